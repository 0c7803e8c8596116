/*
 * sample: evaluate each curve record at equal parameter steps and write
 * the points, optionally with parameter, unit tangent and curvature.
 */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "loft.h"

struct opts {
	long per;               /* points per segment */
	int param, tangent, curvature;
};

static const char usage_text[] =
    "usage: sample [-n per-segment] [-p digits] [-u] [-d] [-k] [file ...]\n";

static void
usage(int status)
{
	fputs(usage_text, status ? stderr : stdout);
	exit(status);
}

/* One output row: the point, then the columns the options ask for. */
static int
put_point(struct loft_run *run, const struct loft_curve *c, size_t i,
    double u, struct loft_error *err)
{
	const struct opts *o = run->ctx;
	double p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], k;
	int dim = c->dim;

	loft_curve_eval(c, i, u, p, d1, d2);
	for (int q = 0; q < dim; q++)
		if (!isfinite(p[q]) || !isfinite(d1[q]) || !isfinite(d2[q]))
			return loft_fail(err, LOFT_EGEOM, (long)i, "segment %zu "
			    "overflows at u = %g: coefficients too large", i + 1,
			    u);
	for (int q = 0; q < dim; q++)
		loft_put_num(&run->w, p[q]);
	if (o->param)
		loft_put_num(&run->w, (double)i + u);
	if ((o->tangent || o->curvature) &&
	    loft_curvature(d1, d2, dim, &k) != 0)
		return loft_fail(err, LOFT_EGEOM, (long)i, "the tangent "
		    "vanishes in segment %zu at u = %g: no direction or "
		    "curvature there", i + 1, u);
	if (o->tangent) {
		double len = 0;

		for (int q = 0; q < dim; q++)
			len += d1[q] * d1[q];
		for (int q = 0; q < dim; q++)
			loft_put_num(&run->w, d1[q] / sqrt(len));
	}
	if (o->curvature)
		loft_put_num(&run->w, k);
	loft_end_line(&run->w);
	return 0;
}

static int
sample_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_curve c;

	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	for (size_t i = 0; i < c.npieces; i++)
		for (long j = 0; j < o->per; j++)
			if (put_point(run, &c, i, (double)j / o->per, err) != 0)
				return LOFT_EGEOM;
	/* the last segment's end: the first point again on a closed curve */
	if (put_point(run, &c, c.npieces - 1, 1, err) != 0)
		return LOFT_EGEOM;
	loft_end_record(&run->w);
	return 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { 16, 0, 0, 0 };
	struct loft_run run = { .prog = "sample", .out = stdout, .msg = stderr,
	    .handle = sample_record, .ctx = &o };
	struct loft_error err;
	long digits;
	int c;

	while ((c = getopt(argc, argv, "n:p:udkh")) != -1) {
		switch (c) {
		case 'n':
			if (loft_parse_int(optarg, 1, 1000000, &o.per, &err))
				goto bad;
			break;
		case 'p':
			if (loft_parse_int(optarg, 1, 17, &digits, &err))
				goto bad;
			run.w.digits = digits;
			break;
		case 'u': o.param = 1; break;
		case 'd': o.tangent = 1; break;
		case 'k': o.curvature = 1; break;
		case 'h': usage(0); break;
		default: usage(2);
		}
	}
	return loft_run_files(&run, argc - optind, argv + optind);
bad:
	fprintf(stderr, "sample: -%c %s\n", c, err.msg);
	usage(2);
}
#endif
