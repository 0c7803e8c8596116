/*
 * unroll: lay a surface flat, for plate development and the forme of a
 * last.  The patch records of the input are one sheet (a design); each
 * other surface record is a sheet of its own.  Each sheet's pattern is
 * written as one closed plane cubic curve, in the input's units; with
 * -e the images of the patch edges, with -x, -y, -z those of plane cuts
 * (stations, buttocks, waterlines), with -m the strain of every mesh
 * edge, coloured for loftplot.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

/* More cuts than this is a mistake of units. */
#define MAX_CUTS 1000

struct cut {
	int axis;               /* 0, 1, 2: x, y, z */
	double at;
};

struct opts {
	struct loft_unroll_opts u;
	int verbose;            /* -v */
	int edges;              /* -e */
	int map;                /* -m */
	struct cut cut[MAX_CUTS];
	size_t ncut;
};

static const char usage_text[] =
    "usage: unroll [-aemv] [-n steps] [-t tol] [-x v] [-y v] [-z v] "
    "[-p digits]\n              [file ...]\n";

/* Write the plane cubic segments seg[0..n) as one record. */
static void
put_cubic(struct loft_writer *w, const double *seg, size_t n, int closed,
    const char *key, const char *val, const char *colour)
{
	loft_put_type(w, "cubic");
	loft_put_attr(w, "closed", closed ? "1" : "0");
	if (key != NULL)
		loft_put_attr(w, key, val);
	if (colour != NULL)
		loft_put_attr(w, "colour", colour);
	loft_end_line(w);
	for (size_t i = 0; i < n; i++)
		loft_put_row(w, seg + 8 * i, 8);
	loft_end_record(w);
}

/* -e: each patch's four edges, Hermite segments on its grid nodes. */
static int
put_edges(struct loft_writer *w, const struct loft_unroll *r,
    const long *id)
{
	long N = r->N;
	double *seg = malloc(8 * (size_t)N * sizeof *seg);
	char name[64];

	if (seg == NULL)
		return LOFT_ENOMEM;
	for (size_t p = 0; p < r->npatch; p++)
		for (int e = 0; e < 4; e++) {
			for (long k = 0; k < N; k++) {
				double a[2] = { e < 2 ? e : (double)k / N,
				    e < 2 ? (double)k / N : e - 2 };
				double b[2] = { e < 2 ? e : (double)(k + 1) / N,
				    e < 2 ? (double)(k + 1) / N : e - 2 };

				loft_unroll_hermite(r, p, a, b, seg + 8 * k);
			}
			snprintf(name, sizeof name, "%ld:%s", id[p],
			    loft_edge_name[e]);
			put_cubic(w, seg, (size_t)N, 0, "edge", name, NULL);
		}
	free(seg);
	return 0;
}

/* A colour for a strain s of the largest smax: from pale grey, red
 * where the flat edge is longer, blue where shorter. */
static void
strain_colour(double s, double smax, char *buf)
{
	double f = smax > 0 ? fmin(1, fabs(s) / smax) : 0;
	int hi = (int)(225 - 25 * f + 0.5), lo = (int)(225 - 200 * f + 0.5);

	snprintf(buf, 7, "%02x%02x%02x", s < 0 ? lo : hi, lo, s < 0 ? hi : lo);
}

/* -m: every mesh edge, a straight segment coloured by its strain. */
static int
put_map(struct loft_writer *w, const struct loft_unroll *r)
{
	const struct loft_mesh *me = &r->mesh;
	size_t *nb = malloc((3 * me->nt + 1) * sizeof *nb);
	char val[LOFT_NUMBUF], col[7];

	if (nb == NULL || loft_mesh_neighbours(me, nb, NULL) != 0) {
		free(nb);
		return LOFT_ENOMEM;
	}
	for (size_t t = 0; t < me->nt; t++)
		for (int k = 0; k < 3; k++) {
			size_t a = me->t[3 * t + k], b = me->t[3 * t + (k + 1) % 3];
			double seg[8], l3 = 0, l2, s;

			if (nb[3 * t + k] != (size_t)-1 && nb[3 * t + k] < t)
				continue;
			for (int c = 0; c < 3; c++)
				l3 = hypot(l3, me->v[3 * a + c] - me->v[3 * b + c]);
			memcpy(seg, r->xy + 2 * a, 2 * sizeof *seg);
			memcpy(seg + 2, r->xy + 2 * b, 2 * sizeof *seg);
			for (int c = 0; c < 2; c++)
				seg[4 + c] = seg[6 + c] = seg[2 + c] - seg[c];
			l2 = hypot(seg[4], seg[5]);
			s = l3 > 0 ? l2 / l3 - 1 : 0;
			loft_format_num(val, s, 3);
			strain_colour(s, r->strain_max, col);
			put_cubic(w, seg, 1, 0, "strain", val, col);
		}
	free(nb);
	return 0;
}

/* -x, -y, -z: the flat images of the cuts, as point records. */
static int
put_cuts(struct loft_writer *w, const struct opts *o,
    const struct loft_unroll *r)
{
	static const char *const axis[3] = { "x", "y", "z" };

	for (size_t i = 0; i < o->ncut; i++) {
		struct loft_cut cut = { 0 };
		double n[3] = { 0, 0, 0 };
		char val[LOFT_NUMBUF + 4];

		n[o->cut[i].axis] = 1;
		if (loft_unroll_cut(r, n, o->cut[i].at, &cut) != 0)
			return LOFT_ENOMEM;
		snprintf(val, sizeof val, "%s=", axis[o->cut[i].axis]);
		loft_format_num(val + 2, o->cut[i].at, 0);
		for (size_t c = 0; c < cut.n; c++) {
			if (cut.c[c].n == 0)
				continue;
			loft_put_type(w, "points");
			loft_put_attr(w, "cut", val);
			loft_end_line(w);
			for (size_t k = 0; k <= cut.c[c].n; k++)
				if (k < cut.c[c].n || cut.c[c].closed)
					loft_put_row(w, cut.c[c].p + 2 *
					    (k % cut.c[c].n), 2);
			loft_end_record(w);
		}
		loft_cut_free(&cut);
	}
	return 0;
}

/* -v: what the unrolling cost, on standard error. */
static void
report(const struct loft_run *run, const struct loft_record *rec,
    const struct loft_unroll *r)
{
	const struct loft_surface_numbers *m = &r->num;

	fprintf(run->msg, "%s: %s:%ld: %s", run->prog, rec->file, rec->line,
	    r->exact ? "developable, developed exactly" : "doubly curved, "
	    "least strain");
	if (!r->exact)
		fprintf(run->msg, " (%ld rounds)", r->rounds);
	fprintf(run->msg, "; mesh %ld steps a side: edge strain largest %.3g "
	    "mean %.3g, area %.9g flat %.9g (change %.3g%%); Gaussian "
	    "curvature integral %.3g, of |K| %.3g, from %.3g to %.3g\n",
	    r->N, r->strain_max, r->strain_mean, r->area3, r->area2,
	    100 * (r->area2 / r->area3 - 1), m->kint, m->kabs, m->kmin.value,
	    m->kmax.value);
}

/* Unroll the n surfaces s (ids id, for -e) as one sheet. */
static int
unroll_sheet(struct loft_run *run, const struct loft_record *rec,
    const struct loft_surface *s, size_t n, const long *id)
{
	const struct opts *o = run->ctx;
	struct loft_unroll r;
	struct loft_error err;
	int rc;

	err.line = 0;
	rc = loft_unroll(&o->u, s, n, &r, &err);
	if (rc == 0) {
		put_cubic(&run->w, r.seg, r.nseg, 1, NULL, NULL, NULL);
		if (o->edges)
			rc = put_edges(&run->w, &r, id);
		if (rc == 0)
			rc = put_cuts(&run->w, o, &r);
		if (rc == 0 && o->map)
			rc = put_map(&run->w, &r);
		if (rc != 0)
			loft_fail(&err, rc, -1, "out of memory");
		else if (o->verbose)
			report(run, rec, &r);
	}
	if (rc != 0)
		loft_report(run, rec, &err);
	loft_unroll_free(&r);
	return rc;
}

static int
unroll_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	struct loft_design d = { 0 };
	struct loft_surface *s = calloc(n + 1, sizeof *s);
	long *id = calloc(n + 1, sizeof *id);
	struct loft_error err;
	size_t np = 0;
	int rc = s == NULL || id == NULL;

	for (size_t i = 0; rc == 0 && i < n; i++) {
		if (loft_record_is(&recs[i], LOFT_KIND_MEMBER))
			np++;
		else if (!loft_is_surface(&recs[i])) {
			err.line = 0;
			loft_fail(&err, LOFT_EINPUT, -1, "%s record: unroll "
			    "lays surface records flat", recs[i].type ?
			    recs[i].type : "a point");
			loft_report(run, &recs[i], &err);
			rc = 1;
		}
	}
	if (rc == 0 && np > 0 && loft_design_from_records(run, recs, n, &d) == 0) {
		for (size_t i = 0; i < d.n; i++) {
			loft_surface_from_patch(d.p[i].b, d.p[i].dim, &s[i]);
			id[i] = d.p[i].id;
		}
		rc = unroll_sheet(run, d.p[0].rec, s, d.n, id) != 0;
	} else if (np > 0)
		rc = 1;
	for (size_t i = 0; rc == 0 && i < n; i++) {
		if (loft_record_is(&recs[i], LOFT_KIND_MEMBER))
			continue;
		err.line = 0;
		id[0] = 0;
		if (loft_surface_from_record(&recs[i], &s[0], &err) != 0) {
			loft_report(run, &recs[i], &err);
			rc = 1;
		} else
			rc = unroll_sheet(run, &recs[i], s, 1, id) != 0;
	}
	if (s == NULL || id == NULL)
		fputs("unroll: out of memory\n", run->msg);
	loft_design_free(&d);
	free(s);
	free(id);
	return rc;
}

/* -x, -y, -z v: a cut at v. */
static void
add_cut(struct opts *o, int c, const char *arg)
{
	struct loft_error err;

	if (o->ncut == MAX_CUTS)
		loft_usage_error(usage_text, c, "too many cuts");
	if (loft_parse_real(arg, -1e300, 1e300, &o->cut[o->ncut].at, &err))
		loft_usage_error(usage_text, c, err.msg);
	o->cut[o->ncut++].axis = c - 'x';
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	static struct opts o;
	struct loft_run run = { .prog = "unroll", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "aemvn:t:x:y:z:p:h")) != -1) {
		switch (c) {
		case 'a': o.u.arap = 1; break;
		case 'e': o.edges = 1; break;
		case 'm': o.map = 1; break;
		case 'v': o.verbose = 1; break;
		case 'n':
			if (loft_parse_int(optarg, 1, 1024, &o.u.steps, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 't':
			if (loft_parse_real(optarg, 0, 1e300, &o.u.tol, &err) ||
			    !(o.u.tol > 0))
				loft_usage_error(usage_text, c, "want a "
				    "tolerance above 0");
			break;
		case 'x': case 'y': case 'z': add_cut(&o, c, optarg); break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	return loft_run_design(&run, argc - optind, argv + optind,
	    unroll_design);
}
#endif
