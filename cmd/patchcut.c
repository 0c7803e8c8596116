/*
 * patchcut: cut a design (and any other surface records) by planes, and
 * write each cut as one curve per connected piece: stations, waterlines
 * and buttocks of a lofted hull.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

/* A plane n.x = d, and how its header names it. */
struct plane {
	double n[3], d;
	int axis;               /* 0, 1, 2: -x -y -z; -1: -p */
};

struct opts {
	struct plane *pl;
	size_t npl, cap;
	double tol;             /* -t, or 0: relative */
	int cubic;              /* -c */
};

/* Without -t: the chord tolerance relative to the design's size. */
#define TOL_REL 1e-3

/* More planes than this from one FROM:TO:STEP is a mistake of units. */
#define PLANES_MAX 100000

static const char usage_text[] =
    "usage: patchcut [-x v|from:to:step] [-y v|from:to:step] "
    "[-z v|from:to:step]\n"
    "                [-p a,b,c,d] [-t tol] [-c] [-P digits] [file ...]\n";

static void
add_plane(struct opts *o, const double *n, double d, int axis)
{
	struct plane *p;

	if (o->npl == o->cap) {
		size_t cap = o->cap ? 2 * o->cap : 8;

		if ((p = realloc(o->pl, cap * sizeof *p)) == NULL) {
			fputs("patchcut: out of memory\n", stderr);
			exit(1);
		}
		o->pl = p;
		o->cap = cap;
	}
	p = &o->pl[o->npl++];
	memcpy(p->n, n, sizeof p->n);
	p->d = d;
	p->axis = axis;
}

/* -x, -y, -z: a value, or FROM:TO:STEP (FROM <= TO, STEP > 0). */
static void
parse_axis(struct opts *o, int c, const char *arg)
{
	double n[3] = { 0, 0, 0 }, v[3];
	struct loft_error err;
	const char *s = arg;
	int axis = c - 'x', k = 0;
	long count;

	n[axis] = 1;
	for (;;) {
		size_t len = strcspn(s, ":");

		if (k == 3 || loft_parse_num(s, len, &v[k], &err) != 0)
			loft_usage_error(usage_text, c, "want a value or "
			    "from:to:step");
		k++;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	if (k == 1) {
		add_plane(o, n, v[0], axis);
		return;
	}
	if (k != 3 || !(v[2] > 0) || !(v[0] <= v[1]))
		loft_usage_error(usage_text, c, "want from:to:step, from up "
		    "to to, step above 0");
	if (!((v[1] - v[0]) / v[2] < PLANES_MAX)) {
		fprintf(stderr, "patchcut: -%c %s: more than %d planes\n", c, arg,
		    PLANES_MAX);
		exit(1);
	}
	/* to itself where the steps reach it within rounding */
	count = (long)((v[1] - v[0]) / v[2] * (1 + 1e-12) + 1e-9) + 1;
	for (long i = 0; i < count; i++) {
		/* 0.3 + 3 * 0.1 is 0.6000000000000001: the steps are meant
		 * in decimals, so 15 digits of them */
		char buf[LOFT_NUMBUF];
		double x;

		loft_format_num(buf, v[0] + (double)i * v[2], 15);
		if (loft_parse_num(buf, strlen(buf), &x, &err) != 0)
			x = v[0] + (double)i * v[2];
		add_plane(o, n, x, axis);
	}
}

/* The header's attributes: plane=x value=V, or plane=a,b,c value=d. */
static void
put_header(struct loft_writer *w, const char *type, const struct plane *p,
    int dim, int closed, int cubic)
{
	static const char *const axis[3] = { "x", "y", "z" };
	char buf[4 * LOFT_NUMBUF], num[LOFT_NUMBUF];
	size_t len = 0;

	loft_put_type(w, type);
	if (cubic)
		loft_put_attr(w, "closed", closed ? "1" : "0");
	if (p->axis >= 0) {
		loft_put_attr(w, "plane", axis[p->axis]);
	} else {
		for (int k = 0; k < dim; k++) {
			loft_format_num(num, p->n[k], 0);
			len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%s",
			    k ? "," : "", num);
		}
		loft_put_attr(w, "plane", buf);
	}
	loft_format_num(num, p->d, 0);
	loft_put_attr(w, "value", num);
	if (!cubic && closed)
		loft_put_attr(w, "closed", "1");
	loft_end_line(w);
}

/* One curve: its points (a closed one ends on its first again), or
 * with -c the cubic fitted through them. */
static int
put_curve(struct loft_run *run, const struct plane *p,
    const struct loft_cut_curve *cv, int dim, struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_fit_opts fo;
	size_t nseg;
	double *seg;

	if (cv->n == 0)         /* loft_cut makes none, but nothing to write */
		return 0;
	if (!o->cubic) {
		put_header(&run->w, "points", p, dim, cv->closed, 0);
		for (size_t i = 0; i <= cv->n; i++)
			if (i < cv->n || cv->closed)
				loft_put_row(&run->w, cv->p + (i % cv->n) * dim, dim);
		loft_end_record(&run->w);
		return 0;
	}
	loft_fit_defaults(&fo);
	fo.closed = cv->closed && cv->n >= LOFT_MIN_CLOSED;
	nseg = fo.closed ? cv->n : cv->n - 1;
	if ((seg = malloc(4 * dim * cv->n * sizeof *seg)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (loft_fit(&fo, cv->p, cv->n, dim, seg, NULL, err) != 0) {
		free(seg);
		return LOFT_EGEOM;
	}
	put_header(&run->w, "cubic", p, dim, fo.closed, 1);
	for (size_t i = 0; i < nseg; i++)
		loft_put_row(&run->w, seg + 4 * dim * i, 4 * dim);
	loft_end_record(&run->w);
	free(seg);
	return 0;
}

/* The surfaces of the input: the design's patches, then the others. */
static int
gather(struct loft_run *run, const struct loft_record *recs, size_t n,
    struct loft_design *d, struct loft_surface **out, size_t *ns)
{
	struct loft_surface *s;
	struct loft_error err;
	char *mine;
	size_t k = 0;
	int rc = 0;

	for (size_t i = 0; i < n; i++)
		if (!loft_is_surface(&recs[i])) {
			err.line = 0;
			loft_fail(&err, LOFT_EINPUT, -1, "%s record: patchcut "
			    "cuts surface records", recs[i].type ? recs[i].type :
			    "a point");
			loft_report(run, &recs[i], &err);
			rc = 1;
		}
	if (rc != 0 || loft_design_from_records(run, recs, n, d) != 0)
		return 1;
	s = calloc(n + 1, sizeof *s);
	mine = calloc(n + 1, 1);
	if (s == NULL || mine == NULL) {
		fputs("patchcut: out of memory\n", run->msg);
		free(s);
		free(mine);
		return 1;
	}
	/* the design's patches, and which records they were */
	for (size_t i = 0; i < d->n; i++) {
		loft_surface_from_patch(d->p[i].b, d->p[i].dim, &s[k++]);
		mine[d->p[i].rec - recs] = 1;
	}
	for (size_t i = 0; i < n; i++) {
		if (mine[i])
			continue;
		err.line = 0;
		if (loft_surface_from_record(&recs[i], &s[k], &err) != 0) {
			loft_report(run, &recs[i], &err);
			rc = 1;
		} else if (k > 0 && s[k].dim != s[0].dim) {
			loft_fail(&err, LOFT_EINPUT, -1, "a surface of %d "
			    "coordinates among surfaces of %d", s[k].dim,
			    s[0].dim);
			loft_report(run, &recs[i], &err);
			rc = 1;
		} else {
			k++;
		}
	}
	free(mine);
	*out = s;
	*ns = k;
	return rc;
}

static int
cut_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_design d = { 0 };
	struct loft_surface *s = NULL;
	struct loft_cutter k = { 0 };
	struct loft_error err;
	size_t ns = 0;
	int rc;

	if (n == 0) {   /* every plane misses: exit 1, as patchcut(1) says */
		fprintf(run->msg, "patchcut: no surfaces in the input: every "
		    "plane misses\n");
		return 1;
	}
	rc = gather(run, recs, n, &d, &s, &ns);
	err.line = 0;
	if (rc == 0 && loft_cutter_init(&k, s, ns, &err) != 0) {
		loft_report(run, &recs[0], &err);
		rc = 1;
	}
	if (rc == 0 && o->tol > 0 && loft_tol_check(o->tol, k.size, 0,
	    &err) != 0) {
		loft_report(run, &recs[0], &err);
		rc = 1;
	}
	for (size_t i = 0; rc == 0 && i < o->npl; i++) {
		const struct plane *p = &o->pl[i];
		struct loft_cut cut = { 0 };
		double tol = o->tol > 0 ? o->tol : TOL_REL * k.size;

		err.line = 0;
		rc = loft_cut_plane(&k, p->n, p->d, tol, &cut, &err);
		if (rc == LOFT_EGEOM) {
			/* a plane that misses: said, and the others cut; one
			 * that meets the surfaces in points only (an all-zero
			 * patch) cuts no curve, and nothing of it is written */
			static const char *const axis[3] = { "x", "y", "z" };
			const char *what = d.n > 0 ? "design" : "surfaces",
			    *how = cut.n > 0 ? " (it meets it in single points,"
			    " no curve)" : "";

			if (p->axis >= 0)
				loft_fail(&err, LOFT_EGEOM, -1, "plane %s = %g "
				    "misses the %s%s", axis[p->axis], p->d, what,
				    how);
			else
				loft_fail(&err, LOFT_EGEOM, -1, "plane %gx + %gy + "
				    "%gz = %g misses the %s%s", p->n[0], p->n[1],
				    p->n[2], p->d, what, how);
			loft_report(run, &recs[0], &err);
			loft_cut_free(&cut);
			rc = 0;
			continue;
		} else if (rc != 0) {
			loft_report(run, &recs[0], &err);
		}
		for (size_t c = 0; rc == 0 && c < cut.n; c++)
			if ((rc = put_curve(run, p, &cut.c[c], cut.dim, &err)) != 0)
				loft_report(run, &recs[0], &err);
		loft_cut_free(&cut);
	}
	loft_cutter_free(&k);
	free(s);
	loft_design_free(&d);
	return rc;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "patchcut", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	double v[4];
	int c, nv;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "x:y:z:p:t:cP:h")) != -1) {
		switch (c) {
		case 'x':
		case 'y':
		case 'z': parse_axis(&o, c, optarg); break;
		case 'p':
			if (loft_parse_list(optarg, v, 4, &nv, &err) != 0 ||
			    nv != 4 || (v[0] == 0 && v[1] == 0 && v[2] == 0))
				loft_usage_error(usage_text, c, "want a,b,c,d: "
				    "the plane ax + by + cz = d, a, b, c not all "
				    "zero");
			add_plane(&o, v, v[3], -1);
			break;
		case 't':
			if (loft_parse_real(optarg, 0, 1e300, &o.tol, &err) != 0 ||
			    !(o.tol > 0))
				loft_usage_error(usage_text, c, "want a "
				    "tolerance above 0");
			break;
		case 'c': o.cubic = 1; break;
		case 'P':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.npl == 0)
		loft_usage_error(usage_text, 0, "give a plane: -x, -y, -z or -p");
	c = loft_run_design(&run, argc - optind, argv + optind, cut_design);
	free(o.pl);
	return c;
}
#endif
