/*
 * bezapprox: approximate a curve or surface by a Bezier one whose control
 * points lie on its normal lines (Carriazo, Marquez and Ugail 2015).  The
 * curve is given by expressions in t (or the surface in u and v), or
 * comes as curve records on the input.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	int m, n;               /* degrees: m = 0 for a curve */
	int clamp, verbose;
	const char *src[3];     /* -x, -y, -z */
	struct loft_expr *e[3];
	int dim;
};

static const char usage_text[] =
    "usage: bezapprox [-cv] [-n degree | -n m,n] [-p digits] -x expr -y expr "
    "[-z expr]\n"
    "       bezapprox [-cv] [-n degree | -n m,n] [-p digits] [file ...]\n";

/* ------------------------------------------------------------------ */
/* Where the curve or surface comes from                               */

static void
expr_curve(void *ctx, double t, double *p, double *d1, double *d2)
{
	struct opts *o = ctx;
	struct loft_jet j;

	for (int k = 0; k < o->dim; k++) {
		loft_expr_eval(o->e[k], &t, &j);
		p[k] = j.v;
		if (d1 != NULL)
			d1[k] = j.d[0];
		if (d2 != NULL)
			d2[k] = j.h[0];
	}
}

static void
expr_surface(void *ctx, double u, double v, double *p, double *pu, double *pv,
    double *puu, double *pvv)
{
	struct opts *o = ctx;
	double x[2] = { u, v };
	struct loft_jet j;

	for (int k = 0; k < 3; k++) {
		loft_expr_eval(o->e[k], x, &j);
		p[k] = j.v;
		if (pu != NULL)
			pu[k] = j.d[0];
		if (pv != NULL)
			pv[k] = j.d[1];
		if (puu != NULL)
			puu[k] = j.h[0];
		if (pvv != NULL)
			pvv[k] = j.h[2];
	}
}

/*
 * A curve record over [0, 1]: piece i of N covers [i / N, (i + 1) / N],
 * so the derivatives in t are N and N^2 times those in the piece's u.
 */
static void
record_curve(void *ctx, double t, double *p, double *d1, double *d2)
{
	const struct loft_curve *c = ctx;
	double n = (double)c->npieces, x = t * n;
	size_t i = x >= n ? c->npieces - 1 : (size_t)x;

	loft_curve_eval(c, i, x - (double)i, p, d1, d2);
	for (int k = 0; k < c->dim; k++) {
		if (d1 != NULL)
			d1[k] *= n;
		if (d2 != NULL)
			d2[k] *= n * n;
	}
}

static void
record_surface(void *ctx, double u, double v, double *p, double *pu,
    double *pv, double *puu, double *pvv)
{
	loft_surface_eval2(ctx, u, v, p, pu, pv, puu, pvv);
}

/* ------------------------------------------------------------------ */
/* Output                                                              */

static void
put_header(struct loft_writer *w, const char *type, const struct opts *o,
    double error, const struct loft_record *rec)
{
	/* what belongs to the input's type: a patch's id and links, a
	 * curve's corners (its joints, which one piece does not have) */
	static const char *const consumed[] = { "closed", "error", "m", "n",
	    "id", "su", "sv", "u0", "u1", "v0", "v1", "corners", "straight",
	    NULL };
	char buf[LOFT_NUMBUF];

	loft_put_type(w, type);
	if (o->m > 0) {
		snprintf(buf, sizeof buf, "%d", o->m);
		loft_put_attr(w, "m", buf);
		snprintf(buf, sizeof buf, "%d", o->n);
		loft_put_attr(w, "n", buf);
	}
	loft_format_num(buf, error, w->digits);
	loft_put_attr(w, "error", buf);
	if (rec != NULL)
		loft_put_attrs_except(w, rec, consumed);
	loft_end_line(w);
}

/* -v: the lambdas, and the control points that had no normal. */
static void
report(FILE *msg, const char *where, const struct opts *o,
    const double *lambda, const int *nonormal)
{
	fprintf(msg, "bezapprox: %s", where);
	for (int i = 1; i < o->n; i++)
		fprintf(msg, "%slambda_%d = %.17g", i > 1 ? ", " : "", i,
		    lambda[i]);
	fputc('\n', msg);
	for (int i = 1; i < o->n; i++)
		if (nonormal[i])
			fprintf(msg, "bezapprox: %sno principal normal at t = "
			    "%.17g (zero curvature): P_%d stays on the "
			    "curve\n", where, (double)i / o->n, i);
}

static int
approx_curve(struct loft_writer *w, const struct opts *o,
    const struct loft_pcurve *a, int closed, const struct loft_record *rec,
    const char *where, struct loft_error *err)
{
	double ctl[(LOFT_NORMAL_MAXDEG + 1) * LOFT_MAXDIM];
	double lambda[LOFT_NORMAL_MAXDEG + 1], error;
	int nonormal[LOFT_NORMAL_MAXDEG + 1], rc;

	rc = loft_normal_curve(a, o->n, o->clamp, ctl, lambda, nonormal,
	    &error, err);
	if (rc != 0)
		return rc;
	if (closed)     /* exactly, whatever the last segment's rounding */
		memcpy(ctl + o->n * a->dim, ctl, a->dim * sizeof *ctl);
	if (o->verbose)
		report(stderr, where, o, lambda, nonormal);
	put_header(w, "bezier", o, error, rec);
	for (int i = 0; i <= o->n; i++)
		loft_put_row(w, ctl + i * a->dim, a->dim);
	loft_end_record(w);
	return 0;
}

/* A surface from a record or from expressions, written to w. */
static int
approx_surface(struct loft_writer *w, const struct opts *o,
    const struct loft_psurface *x, const struct loft_record *rec,
    struct loft_error *err)
{
	double ctl[(LOFT_NORMAL_MAXDEG + 1) * (LOFT_NORMAL_MAXDEG + 1) * 3];
	double error;
	int rc;

	if ((rc = loft_normal_surface(x, o->m, o->n, o->clamp, ctl, &error,
	    err)) != 0)
		return rc;
	put_header(w, "bezier-surface", o, error, rec);
	for (int i = 0; i < (o->m + 1) * (o->n + 1); i++)
		loft_put_row(w, ctl + 3 * i, 3);
	loft_end_record(w);
	return 0;
}

static int
approx_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_curve c;
	struct loft_surface s;
	char where[300];

	if (loft_is_surface(rec)) {
		if (o->m == 0)
			return loft_fail(err, LOFT_EINPUT, -1, "a %s record is "
			    "a surface: give its degrees with -n m,n",
			    rec->type);
		if (loft_surface_from_record(rec, &s, err) != 0)
			return LOFT_EINPUT;
		if (s.dim != 3)
			return loft_fail(err, LOFT_EINPUT, -1, "a %s record in "
			    "the plane has no normals: bezapprox needs a "
			    "surface in space", rec->type);
		struct loft_psurface x = { 1, 1, record_surface, &s };

		return approx_surface(&run->w, o, &x, rec, err);
	}
	if (o->m > 0 && !loft_record_is(rec, LOFT_KIND_KNOTS))
		return loft_fail(err, LOFT_EINPUT, -1, "a %s record is a curve: "
		    "-n m,n approximates surfaces", rec->type);
	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	struct loft_pcurve a = { c.dim, c.npieces, record_curve, &c };

	snprintf(where, sizeof where, "%s:%ld: ", rec->file, rec->line);
	return approx_curve(&run->w, o, &a, c.closed, rec, where, err);
}

/* The curve or surface of -x, -y, -z, written to run->w. */
static int
approx_expr(struct loft_run *run, struct opts *o, struct loft_error *err)
{
	if (o->m == 0) {
		struct loft_pcurve a = { o->dim, 1, expr_curve, o };

		return approx_curve(&run->w, o, &a, 0, NULL, "", err);
	}
	struct loft_psurface x = { 1, 1, expr_surface, o };

	return approx_surface(&run->w, o, &x, NULL, err);
}

/* ------------------------------------------------------------------ */
/* Options                                                             */

/* -n degree or -n m,n */
static void
parse_degrees(const char *arg, struct opts *o)
{
	struct loft_error err;
	double v[2];
	int cnt;

	if (loft_parse_list(arg, v, 2, &cnt, &err) != 0)
		loft_usage_error(usage_text, 'n', err.msg);
	for (int k = 0; k < cnt; k++)
		if (v[k] != floor(v[k]) || fabs(v[k]) > 1000) {
			snprintf(err.msg, sizeof err.msg, "%s: want a whole "
			    "number, or two separated by a comma", arg);
			loft_usage_error(usage_text, 'n', err.msg);
		}
	o->m = cnt == 2 ? (int)v[0] : 0;
	o->n = (int)v[cnt - 1];
}

/* A degree the method cannot use is bad input (exit 1), not bad usage. */
static int
check_degrees(const struct opts *o)
{
	int lo = o->clamp ? 3 : 1;

	for (int k = 0; k < 2; k++) {
		int d = k == 0 ? o->m : o->n;

		if (k == 0 && d == 0)
			continue;
		if (d < lo || d > LOFT_NORMAL_MAXDEG) {
			fprintf(stderr, "bezapprox: -n: degree %d: want %d to "
			    "%d%s\n", d, lo, LOFT_NORMAL_MAXDEG, o->clamp && d < 3 ?
			    " (clamping, -c, fixes two lambdas by eq. 4)" : "");
			return 1;
		}
	}
	return 0;
}

/*
 * Compile -x, -y, -z; a syntax error is shown with a caret under its
 * column.  Returns 0, or 1 after the message.
 */
static int
compile(struct opts *o)
{
	static const char opt[] = "xyz";
	const char *vars = o->m > 0 ? "uv" : "t";
	struct loft_error err;
	int col;

	for (int k = 0; k < o->dim; k++) {
		o->e[k] = loft_expr_parse(o->src[k], vars, &col, &err);
		if (o->e[k] == NULL) {
			fprintf(stderr, "bezapprox: -%c: column %d: %s\n"
			    "  %s\n  %*s^\n", opt[k], col, err.msg, o->src[k],
			    col - 1, "");
			return 1;
		}
	}
	return 0;
}

static int
run_expr(struct opts *o, struct loft_run *run)
{
	struct loft_error err;
	int status;

	if (compile(o) != 0)
		status = 1;
	else if (approx_expr(run, o, &err) != 0) {
		fprintf(stderr, "bezapprox: %s\n", err.msg);
		loft_writer_free(&run->w);
		status = 1;
	} else
		status = loft_run_made(run);
	for (int k = 0; k < 3; k++)
		loft_expr_free(o->e[k]);
	return status;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .n = 3 };
	struct loft_run run = { .prog = "bezapprox", .out = stdout,
	    .msg = stderr, .handle = approx_record, .ctx = &o };
	struct loft_error err;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "cvn:p:x:y:z:h")) != -1) {
		switch (c) {
		case 'c': o.clamp = 1; break;
		case 'v': o.verbose = 1; break;
		case 'n': parse_degrees(optarg, &o); break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'x': o.src[0] = optarg; break;
		case 'y': o.src[1] = optarg; break;
		case 'z': o.src[2] = optarg; break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (check_degrees(&o) != 0)
		return 1;
	o.dim = o.src[2] != NULL ? 3 : 2;
	if (o.src[0] == NULL && o.src[1] == NULL && o.src[2] == NULL)
		return loft_run_files(&run, argc - optind, argv + optind);
	if (o.src[0] == NULL || o.src[1] == NULL)
		loft_usage_error(usage_text, o.src[0] == NULL ? 'x' : 'y',
		    "is missing: a curve "
		    "needs -x and -y (and -z in space)");
	if (o.m > 0 && o.src[2] == NULL)
		loft_usage_error(usage_text, 'z', "is missing: a surface "
		    "needs -x, -y and -z");
	if (optind < argc)
		loft_usage_error(usage_text, 0, "give expressions or input "
		    "files, not both");
	return run_expr(&o, &run);
}
#endif
