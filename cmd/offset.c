/*
 * offset: the offset of each plane curve record at one or more
 * distances, as cubic records: outward of a closed curve, to the left
 * of an open one, loops cut away, corners joined.
 */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "loftprog.h"

#define MAXDIST 64              /* -d options in one call */

struct opts {
	double dist[MAXDIST];
	int ndist;
	double tol;             /* -t, or 0: LOFT_OFFSET_TOL of |dist| */
	int join;               /* enum loft_join */
	struct loft_offset off;
};

static const char usage_text[] =
    "usage: offset -d dist [-d dist ...] [-t tol] [-j round|miter|bevel] "
    "[-p digits] [file ...]\n";

/* Attributes of the input that no longer hold for its offset. */
static const char *const dropped[] = { "closed", "offset", "error", "corners",
    "straight", "start", "end", NULL };

/* Write the parts of o->off as cubic records at distance d. */
static void
put_offset(struct loft_run *run, const struct loft_record *rec, double d)
{
	const struct opts *o = run->ctx;
	char buf[LOFT_NUMBUF];

	for (size_t k = 0; k < o->off.npart; k++) {
		const struct loft_offset_part *p = &o->off.part[k];

		loft_put_type(&run->w, "cubic");
		loft_put_attr(&run->w, "closed", p->closed ? "1" : "0");
		loft_put_attrs_except(&run->w, rec, dropped);
		loft_format_num(buf, d, 0);
		loft_put_attr(&run->w, "offset", buf);
		loft_end_line(&run->w);
		for (size_t i = 0; i < p->n; i++)
			loft_put_row(&run->w, o->off.seg + 8 * (p->first + i), 8);
		loft_end_record(&run->w);
	}
}

static int
offset_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_curve c;
	int r;

	if (loft_is_surface(rec))
		return loft_fail(err, LOFT_EINPUT, -1, "a %s record is a "
		    "surface: offset reads plane curves", rec->type);
	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	if (c.dim != 2)
		return loft_fail(err, LOFT_EINPUT, -1, "a space curve (%d "
		    "coordinates) has no one offset: offset reads plane "
		    "curves", c.dim);
	for (int k = 0; k < o->ndist; k++) {
		double d = o->dist[k];

		if ((r = loft_offset_curve(&c, d, o->tol, o->join, &o->off,
		    err)) != 0) {
			if (o->ndist > 1) {
				char msg[sizeof err->msg];

				snprintf(msg, sizeof msg, "%s", err->msg);
				loft_fail(err, r, err->row, "-d %g: %s", d, msg);
			}
			return r;
		}
		put_offset(run, rec, d);
	}
	return 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	static const char *const joins[] = { "round", "miter", "bevel", NULL };
	static struct opts o;
	struct loft_run run = { .prog = "offset", .out = stdout, .msg = stderr,
	    .handle = offset_record, .ctx = &o };
	struct loft_error err;
	int c, status;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "d:t:j:p:h")) != -1) {
		switch (c) {
		case 'd':
			if (o.ndist == MAXDIST) {
				snprintf(err.msg, sizeof err.msg, "%s: at most "
				    "%d distances", optarg, MAXDIST);
				loft_usage_error(usage_text, c, err.msg);
			}
			if (loft_parse_real(optarg, -1e300, 1e300,
			    &o.dist[o.ndist], &err))
				loft_usage_error(usage_text, c, err.msg);
			if (o.dist[o.ndist++] == 0) {
				snprintf(err.msg, sizeof err.msg, "'%s': the "
				    "offset at distance 0 is the curve", optarg);
				loft_usage_error(usage_text, c, err.msg);
			}
			break;
		case 't':
			if (loft_parse_real(optarg, 0, 1e300, &o.tol, &err))
				loft_usage_error(usage_text, c, err.msg);
			if (o.tol == 0) {
				snprintf(err.msg, sizeof err.msg, "'%s': want a "
				    "positive tolerance", optarg);
				loft_usage_error(usage_text, c, err.msg);
			}
			break;
		case 'j':
			if (loft_parse_word(optarg, joins, &o.join, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.ndist == 0)
		loft_usage_error(usage_text, 0, "-d is missing: give the "
		    "distance");
	status = loft_run_files(&run, argc - optind, argv + optind);
	loft_offset_free(&o.off);
	return status;
}
#endif
