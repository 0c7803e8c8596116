/*
 * splinefit: fit a fair spline through each record of knots (Manning 1973)
 * and write it as a cubic record.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loft.h"

/* Two fits whose unit tangents differ by less than this at every knot are
 * the same curve; sign-rule alternatives differ by order 1. */
#define SAME_CURVE 1e-6

struct opts {
	struct loft_fit_opts fit;
	int start_dim, end_dim;         /* coordinates given with -S, -E */
	int verbose;
	double *seg, *other;            /* scratch, grown as records need */
	size_t segcap;
};

static const char usage_text[] =
    "usage: splinefit [-o] [-S tx,ty[,tz]] [-E tx,ty[,tz]] [-a alpha] "
    "[-k positive|turn]\n"
    "                 [-m manning|ferguson|chord] [-t tol] [-i maxiter] "
    "[-p digits] [-v]\n"
    "                 [file ...]\n";

static void
usage(int status)
{
	fputs(usage_text, status ? stderr : stdout);
	exit(status);
}

static void
bad_option(int c, const struct loft_error *err)
{
	fprintf(stderr, "splinefit: -%c %s\n", c, err->msg);
	usage(2);
}

/*
 * The end tangent named key ("start" or "end"): the one -S or -E gave,
 * which must have the knots' dim (given_dim) coordinates, or else the
 * record's attribute, if it has one.
 */
static int
record_tangent(const struct loft_record *rec, const char *key, int dim,
    int given_dim, int *have, double *t, struct loft_error *err)
{
	const char *v = loft_attr(rec, key);
	int n;

	if (*have && given_dim != dim)
		return loft_fail(err, LOFT_EINPUT, -1, "the %s tangent has %d "
		    "coordinates but the knots have %d", key, given_dim, dim);
	if (*have || v == NULL)
		return 0;
	if (loft_parse_list(v, t, dim, &n, err) != 0 || n != dim)
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: want "
		    "%d numbers separated by commas", key, v, dim);
	*have = 1;
	return 0;
}

static int
grow_scratch(struct opts *o, size_t need, struct loft_error *err)
{
	double *a, *b;

	if (need <= o->segcap)
		return 0;
	a = realloc(o->seg, need * sizeof *a);
	if (a != NULL)
		o->seg = a;
	b = a ? realloc(o->other, need * sizeof *b) : NULL;
	if (b == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	o->other = b;
	o->segcap = need;
	return 0;
}

/* -v: how the fit went, and whether the other sign rule agrees. */
static void
report(struct loft_run *run, const struct loft_record *rec,
    const struct loft_fit_opts *fit, const struct loft_fit_info *info,
    size_t nseg)
{
	struct opts *o = run->ctx;
	struct loft_fit_opts alt = *fit;
	struct loft_fit_info ainfo;
	struct loft_error aerr;
	int dim = rec->ncols;
	char other[320] = "";

	fprintf(run->msg, "splinefit: %s:%ld: %zu knots, %d iteration%s, "
	    "converged (tangent change %.2g), curvature jump %.2g",
	    rec->file, rec->line, rec->nrows, info->iterations,
	    info->iterations == 1 ? "" : "s", info->change,
	    loft_curvature_jump(o->seg, nseg, dim, fit->closed));
	if (fit->method == LOFT_MANNING) {
		alt.sign = fit->sign == LOFT_SIGN_POSITIVE ?
		    LOFT_SIGN_TURN : LOFT_SIGN_POSITIVE;
		if (loft_fit(&alt, rec->num, rec->nrows, dim, o->other,
		    &ainfo, &aerr) != 0)
			snprintf(other, sizeof other, "fails (%s)", aerr.msg);
		else if (loft_tangent_distance(o->seg, o->other, nseg, dim) >
		    SAME_CURVE)
			snprintf(other, sizeof other, "reaches a DIFFERENT "
			    "curve: the knots do not decide where it goes");
		else
			snprintf(other, sizeof other, "reaches the same curve");
		fprintf(run->msg, "; the other sign rule (-k %s) %s",
		    alt.sign == LOFT_SIGN_TURN ? "turn" : "positive", other);
	}
	fputc('\n', run->msg);
}

static int
fit_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	static const char *const consumed[] = { "start", "end", "closed",
	    NULL };
	struct opts *o = run->ctx;
	struct loft_fit_opts fit = o->fit;
	struct loft_fit_info info;
	int dim = rec->ncols, rc;
	size_t n = rec->nrows, nseg;

	if (rec->type != NULL && strcmp(rec->type, "points") != 0)
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: splinefit "
		    "reads knots (point records)", rec->type);
	if (n == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "record has no knots");
	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, 0, "knots have %d "
		    "coordinate%s; 2 or 3 are needed", dim, dim == 1 ? "" : "s");
	if (!fit.closed &&
	    (record_tangent(rec, "start", dim, o->start_dim, &fit.have_start,
	    fit.start, err) != 0 ||
	    record_tangent(rec, "end", dim, o->end_dim, &fit.have_end,
	    fit.end, err) != 0))
		return LOFT_EINPUT;
	if (grow_scratch(o, 4 * (size_t)dim * n, err) != 0)
		return LOFT_ENOMEM;
	if ((rc = loft_fit(&fit, rec->num, n, dim, o->seg, &info, err)) != 0)
		return rc;
	nseg = fit.closed ? n : n - 1;
	if (o->verbose)
		report(run, rec, &fit, &info, nseg);
	loft_put_type(&run->w, "cubic");
	loft_put_attr(&run->w, "closed", fit.closed ? "1" : "0");
	loft_put_attrs_except(&run->w, rec, consumed);
	loft_end_line(&run->w);
	for (size_t i = 0; i < nseg; i++)
		loft_put_row(&run->w, o->seg + i * 4 * dim, 4 * dim);
	loft_end_record(&run->w);
	return 0;
}

static void
parse_vector(int c, const char *arg, double *v, int *have, int *dim)
{
	struct loft_error err;

	if (loft_parse_list(arg, v, LOFT_MAXDIM, dim, &err) != 0)
		bad_option(c, &err);
	if (*dim >= 2 && v[0] == 0 && v[1] == 0 && (*dim == 2 || v[2] == 0)) {
		snprintf(err.msg, sizeof err.msg, "'%s': a direction cannot be "
		    "zero", arg);
		bad_option(c, &err);
	}
	if (*dim < 2) {
		snprintf(err.msg, sizeof err.msg, "'%s': want 2 or 3 numbers "
		    "separated by commas", arg);
		bad_option(c, &err);
	}
	*have = 1;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	static const char *const methods[] = { "manning", "ferguson", "chord",
	    NULL };
	static const char *const signs[] = { "positive", "turn", NULL };
	struct opts o = { 0 };
	struct loft_run run = { .prog = "splinefit", .out = stdout,
	    .msg = stderr, .handle = fit_record, .ctx = &o };
	struct loft_error err;
	int c, status, rc = 0, word;
	long whole;

	loft_fit_defaults(&o.fit);
	while ((c = getopt(argc, argv, "oS:E:a:k:m:t:i:p:vh")) != -1) {
		switch (c) {
		case 'o': o.fit.closed = 0; break;
		case 'S': parse_vector(c, optarg, o.fit.start,
		    &o.fit.have_start, &o.start_dim); break;
		case 'E': parse_vector(c, optarg, o.fit.end, &o.fit.have_end,
		    &o.end_dim); break;
		case 'a': rc = loft_parse_real(optarg, 0.5, 1, &o.fit.alpha,
		    &err); break;
		case 'k': rc = loft_parse_word(optarg, signs, &word, &err);
		    o.fit.sign = word; break;
		case 'm': rc = loft_parse_word(optarg, methods, &word, &err);
		    o.fit.method = word; break;
		case 't': rc = loft_parse_real(optarg, 1e-15, 1, &o.fit.tol,
		    &err); break;
		case 'i': rc = loft_parse_int(optarg, 1, 1000000, &whole, &err);
		    o.fit.maxiter = whole; break;
		case 'p': rc = loft_parse_int(optarg, 1, 17, &whole, &err);
		    run.w.digits = whole; break;
		case 'v': o.verbose = 1; break;
		case 'h': usage(0); break;
		default: usage(2);
		}
		if (rc != 0)
			bad_option(c, &err);
	}
	if (o.fit.closed && (o.fit.have_start || o.fit.have_end)) {
		fputs("splinefit: -S and -E give the ends of an open curve: "
		    "use them with -o\n", stderr);
		usage(2);
	}
	status = loft_run_files(&run, argc - optind, argv + optind);
	free(o.seg);
	free(o.other);
	return status;
}
#endif
