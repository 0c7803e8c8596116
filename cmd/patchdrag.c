/*
 * patchdrag: move a point of a patch, or of a quartic or cubic curve,
 * by a displacement or to a target, changing as little of the design as
 * the paper allows (MacCallum 1970, section 4).
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

/*
 * The default reach of the edge rule: a point nearer an edge than a
 * quarter of the parameter range drags the neighbour too.  Farther in,
 * the central rule's H5 is at least H5(1/4) = 9/16, so it moves (hh) by
 * at most 16/9 of the drag (per direction) and the largest deviation,
 * at the middle, stays within 16/9 of it.
 */
#define EDGE_DEFAULT 0.25

struct opts {
	long id;                /* -i */
	int have_id;
	double u, v;
	int have_u, have_v;
	double move[LOFT_MAXDIM], view[LOFT_MAXDIM];
	int nmove, nview;       /* coordinates given; nview 0: no -w */
	int target;             /* -t rather than -b */
	double edge;
	int verbose;
};

static const char usage_text[] =
    "usage: patchdrag [-i id] -u U [-v V] (-b dx,dy[,dz] | -t x,y[,z]) "
    "[-w vx,vy[,vz]]\n"
    "                 [-e edge] [-V] [-p digits] [file ...]\n";

/* An option's value that dragging cannot use: bad input, exit 1. */
static void
bad_value(int c, const char *arg, const char *why)
{
	fprintf(stderr, "patchdrag: -%c %s: %s\n", c, arg, why);
	exit(1);
}

/*
 * The displacement for a point now at p of a record of dim coordinates:
 * -b, or -t minus p; projected on the display plane under -w.
 */
static int
displacement(const struct opts *o, const double *p, int dim, double *delta,
    struct loft_error *err)
{
	double len = 0;

	if (o->nmove != dim || (o->nview > 0 && o->nview != dim))
		return loft_fail(err, LOFT_EINPUT, -1, "-%c has %d coordinates "
		    "but the record has %d", o->nmove != dim ?
		    (o->target ? 't' : 'b') : 'w', o->nmove != dim ? o->nmove :
		    o->nview, dim);
	for (int c = 0; c < dim; c++) {
		delta[c] = o->target ? o->move[c] - p[c] : o->move[c];
		len = fmax(len, fabs(delta[c]));  /* no square to underflow */
	}
	if (o->nview > 0)
		return loft_drag_project(delta, o->view, dim, err);
	if (!(len > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "zero displacement: "
		    "nothing to drag");
	return 0;
}

static const char *const rule_name[] = { "central", "edge", "central" };

/* Drag curve record rec and write it as a quartic record. */
static int
drag_curve(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_drag_info info;
	struct loft_curve c;
	double *q, p[LOFT_MAXDIM], delta[LOFT_MAXDIM];
	size_t i;
	int rc;

	if (loft_curve_segments(rec, &c, err) != 0)
		return LOFT_EINPUT;
	if (!(o->u >= 0 && o->u <= (double)c.npieces))
		/* before -t reads the point there: there is none */
		return loft_fail(err, LOFT_EINPUT, -1, "-u %g is outside the "
		    "curve's parameter range 0 to %zu", o->u, c.npieces);
	if ((q = malloc(c.npieces * 5 * c.dim * sizeof *q)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (i = 0; i < c.npieces; i++)
		loft_curve_quartic(&c, i, q + i * 5 * c.dim);
	i = o->u >= (double)c.npieces ? c.npieces - 1 : (size_t)o->u;
	loft_quartic_eval(q + i * 5 * c.dim, c.dim, o->u - (double)i, p, NULL,
	    NULL);
	rc = displacement(o, p, c.dim, delta, err);
	if (rc == 0)
		rc = loft_quartic_drag(q, c.npieces, c.dim, c.closed, o->u,
		    delta, o->edge, &info, err);
	if (rc == 0) {
		if (o->verbose) {
			fprintf(run->msg, "patchdrag: %s:%ld: %s rule%s%s: "
			    "segment%s %ld", rec->file, rec->line,
			    rule_name[info.rule], info.why[0] ? ", as " : "",
			    info.why, info.other >= 0 ? "s" : "", info.piece + 1);
			if (info.other >= 0)
				fprintf(run->msg, " and %ld", info.other + 1);
			fprintf(run->msg, " moved, H_d = %.6g\n", info.hd);
		}
		loft_put_type(&run->w, "quartic");
		loft_put_attrs_except(&run->w, rec, (const char *const[]){
		    NULL });
		loft_end_line(&run->w);
		for (i = 0; i < c.npieces; i++)
			loft_put_row(&run->w, q + i * 5 * c.dim, 5 * c.dim);
		loft_end_record(&run->w);
	}
	free(q);
	return rc;
}

/* Drag patch i of d. */
static int
drag_patch(struct loft_run *run, struct loft_design *d, size_t i,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_drag_info info;
	struct loft_patch *p = &d->p[i];
	double x[LOFT_MAXDIM], delta[LOFT_MAXDIM];

	if (!o->have_v)
		return loft_fail(err, LOFT_EINPUT, -1, "patch %ld: -v V is "
		    "needed to drag a patch", p->id);
	if (!(o->u >= 0 && o->u <= 1 && o->v >= 0 && o->v <= 1))
		return loft_fail(err, LOFT_EINPUT, -1, "-u %g -v %g is outside "
		    "the patch's parameter square 0 to 1", o->u, o->v);
	loft_patch_eval(p->b, p->dim, o->u, o->v, x, NULL, NULL);
	if (displacement(o, x, p->dim, delta, err) != 0 ||
	    loft_design_drag(d, i, o->u, o->v, delta, o->edge, &info,
	    err) != 0)
		return LOFT_EINPUT;
	if (o->verbose) {
		fprintf(run->msg, "patchdrag: %s:%ld: patch %ld: %s rule",
		    p->rec->file, p->rec->line, p->id, rule_name[info.rule]);
		if (info.rule == LOFT_DRAG_EDGE)
			fprintf(run->msg, " across %s: patches %ld and %ld "
			    "moved, H_d = %.6g, H_p/H_d = %.6g\n",
			    loft_edge_name[info.edge], p->id,
			    d->p[info.other].id, info.hd, info.hp / info.hd);
		else
			fprintf(run->msg, "%s%s%s: (hh) moved by %.6g of the "
			    "drag\n", info.why[0] ? " (" : "", info.why,
			    info.why[0] ? ")" : "", 1 / info.hd);
	}
	return 0;
}

static int
is_patch(const struct loft_record *rec)
{
	return loft_record_is(rec, LOFT_KIND_MEMBER);
}

/* The record to drag: the one with id -i, or the only one. */
static long
pick(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	long found = -1;
	struct loft_error err;
	int bad = 0;

	if (!o->have_id && n != 1) {
		fprintf(run->msg, "patchdrag: the input holds %zu records: "
		    "name the one to drag with -i\n", n);
		return -1;
	}
	if (!o->have_id)
		return 0;
	for (size_t i = 0; i < n; i++) {
		const char *v = loft_attr(&recs[i], "id");
		long id;

		err.line = 0;
		if (v == NULL)
			continue;
		if (is_patch(&recs[i]) && loft_patch_id(&recs[i], &id,
		    &err) != 0) {
			/* it may be the one: name it, not "no record" alone */
			loft_report(run, &recs[i], &err);
			bad = 1;
		} else if (loft_parse_int(v, 1, 1000000000, &id, &err) == 0 &&
		    id == o->id)
			found = (long)i;
	}
	if (bad)
		return -1;
	if (found < 0)
		fprintf(run->msg, "patchdrag: no record with id %ld in the "
		    "input\n", o->id);
	return found;
}

/*
 * Records copied through must be records loft(5) accepts: a header with
 * no rows is an error there (found by fuzzing).  Reports each; 0 if none.
 */
static int
check_copied(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	struct loft_error err;
	int rc = 0;

	for (size_t i = 0; i < n; i++)
		if (!is_patch(&recs[i]) && recs[i].nrows == 0) {
			err.line = 0;
			rc = loft_fail(&err, LOFT_EINPUT, -1,
			    "%s record has no rows", recs[i].type);
			loft_report(run, &recs[i], &err);
		}
	return rc;
}

static int
drag_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	struct loft_design d = { 0 };
	struct loft_error err;
	long k = pick(run, recs, n);
	size_t np = 0;
	int rc = 0, bad;

	if (k < 0)
		return 1;
	bad = loft_design_from_records(run, recs, n, &d) != 0;
	bad |= check_copied(run, recs, n) != 0;   /* report both kinds */
	if (bad) {
		loft_design_free(&d);
		return 1;
	}
	err.line = 0;
	if (is_patch(&recs[k])) {
		/* patch records are the design's patches, in order */
		for (long i = 0; i < k; i++)
			np += is_patch(&recs[i]);
		rc = drag_patch(run, &d, np, &err);
		np = 0;
	}
	for (size_t i = 0; rc == 0 && i < n; i++) {
		if (is_patch(&recs[i]))
			loft_design_put(&run->w, &d, np++);
		else if ((long)i == k)
			rc = drag_curve(run, &recs[i], &err);
		else
			loft_put_record(&run->w, &recs[i]);
	}
	if (rc != 0)
		loft_report(run, &recs[k], &err);
	loft_design_free(&d);
	return rc;
}

static void
parse_vector(int c, const char *arg, double *v, int *n)
{
	struct loft_error err;

	if (loft_parse_list(arg, v, LOFT_MAXDIM, n, &err) != 0)
		loft_usage_error(usage_text, c, err.msg);
	if (*n < 2) {
		snprintf(err.msg, sizeof err.msg, "'%s': want 2 or 3 numbers "
		    "separated by commas", arg);
		loft_usage_error(usage_text, c, err.msg);
	}
	if (c == 'w' && v[0] == 0 && v[1] == 0 && (*n == 2 || v[2] == 0))
		bad_value(c, arg, "a direction cannot be zero");
}

/* A number, any: its range is the method's to judge (exit 1, not 2). */
static double
parse_number(int c, const char *arg)
{
	struct loft_error err;
	double x;

	if (loft_parse_num(arg, strlen(arg), &x, &err) != 0)
		loft_usage_error(usage_text, c, err.msg);
	return x;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .edge = EDGE_DEFAULT };
	struct loft_run run = { .prog = "patchdrag", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c, rc = 0, moves = 0;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "i:u:v:b:t:w:e:Vp:h")) != -1) {
		switch (c) {
		case 'i': rc = loft_parse_int(optarg, 0, LONG_MAX, &o.id,
		    &err); o.have_id = 1; break;
		case 'u': o.u = parse_number(c, optarg); o.have_u = 1; break;
		case 'v': o.v = parse_number(c, optarg); o.have_v = 1; break;
		case 'b':
		case 't': parse_vector(c, optarg, o.move, &o.nmove);
		    o.target = c == 't'; moves++; break;
		case 'w': parse_vector(c, optarg, o.view, &o.nview); break;
		case 'e':
			o.edge = parse_number(c, optarg);
			if (!(o.edge >= 0 && o.edge <= 0.5))
				bad_value(c, optarg, "want a reach from 0 to 0.5");
			break;
		case 'V': o.verbose = 1; break;
		case 'p': rc = loft_opt_digits(optarg, &run.w, &err); break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
		if (rc != 0)
			loft_usage_error(usage_text, c, err.msg);
	}
	if (!o.have_u || moves != 1)
		loft_usage_error(usage_text, 0, "give -u, and one of -b and -t");
	return loft_run_design(&run, argc - optind, argv + optind,
	    drag_design);
}
#endif
