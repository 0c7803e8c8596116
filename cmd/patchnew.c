/*
 * patchnew: a first bi-quartic patch (MacCallum 1970), from four corner
 * points or from four boundary curves, written as a `patch` record.
 */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	long id;
	int ncorner, dim;
	double corner[4 * LOFT_MAXDIM];
	int boundary;           /* -b: read four curves */
};

static const char usage_text[] =
    "usage: patchnew -c x,y[,z] -c x,y[,z] -c x,y[,z] -c x,y[,z] "
    "[-i id] [-p digits]\n"
    "       patchnew -b [-i id] [-p digits] [file ...]\n";

/* Write the one patch b to w. */
static int
put_patch(struct loft_writer *w, const double *b, int dim, long id,
    struct loft_error *err)
{
	struct loft_design d = { 0 };

	if (loft_design_new(&d, b, dim, id, err) != 0)
		return LOFT_ENOMEM;
	loft_design_put(w, &d, 0);
	loft_design_free(&d);
	return 0;
}

/*
 * -b: the input holds four one-segment curves, v = 0 and v = 1 running
 * in u, then u = 0 and u = 1 running in v; Coons' patch through them.
 */
static int
from_curves(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	double q[4][5 * LOFT_MAXDIM], b[LOFT_PATCH_NUMS];
	const double *qp[4];
	struct loft_error err;
	struct loft_curve c;
	int dim = 0;

	for (size_t i = 0; i < n; i++) {
		/* a bad curve gets its line before the count is judged */
		err.line = 0;
		if (loft_curve_from_record(&recs[i], &c, &err) != 0) {
			loft_report(run, &recs[i], &err);
			return 1;
		}
	}
	if (n != 4) {
		fprintf(run->msg, "patchnew: -b wants 4 curve records (v=0, "
		    "v=1, u=0, u=1), not %zu\n", n);
		return 1;
	}
	for (size_t i = 0; i < 4; i++) {
		err.line = 0;
		if (loft_curve_segments(&recs[i], &c, &err) != 0) {
			loft_report(run, &recs[i], &err);
			return 1;
		}
		if (c.npieces != 1 || (i > 0 && c.dim != dim)) {
			if (c.npieces != 1)
				loft_fail(&err, LOFT_EINPUT, -1, "a boundary is "
				    "one segment, not %zu", c.npieces);
			else
				loft_fail(&err, LOFT_EINPUT, -1, "boundary has %d "
				    "coordinates, the first %d", c.dim, dim);
			loft_report(run, &recs[i], &err);
			return 1;
		}
		dim = c.dim;
		loft_curve_quartic(&c, 0, q[i]);
		qp[i] = q[i];
	}
	err.line = 0;
	if (loft_patch_coons(qp, dim, b, &err) != 0) {
		size_t i = (size_t)err.row;

		err.row = -1;
		loft_report(run, &recs[i], &err);
		return 1;
	}
	if (put_patch(&run->w, b, dim, o->id, &err) != 0) {
		loft_report(run, &recs[0], &err);     /* out of memory */
		return 1;
	}
	return 0;
}

/* -c: the bilinear patch through the corners, written to standard output. */
static int
from_corners(struct loft_run *run)
{
	const struct opts *o = run->ctx;
	double b[LOFT_PATCH_NUMS];
	struct loft_error err;
	int status = 0;

	loft_patch_bilinear(o->corner, o->dim, b);
	if (put_patch(&run->w, b, o->dim, o->id, &err) != 0 || run->w.bad) {
		fprintf(stderr, "patchnew: %s\n", run->w.bad == LOFT_EGEOM ?
		    "result is not finite (the input is too extreme)" :
		    "out of memory");
		status = 1;
	} else {
		errno = 0;
		if (fwrite(run->w.buf, 1, run->w.len, stdout) != run->w.len ||
		    fflush(stdout) != 0) {
			if (errno != EPIPE)
				fprintf(stderr, "patchnew: write error: %s\n",
				    strerror(errno ? errno : EIO));
			status = 1;
		}
	}
	loft_writer_free(&run->w);
	return status;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .id = 1 };
	struct loft_run run = { .prog = "patchnew", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c, rc = 0, n;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "c:bi:p:h")) != -1) {
		switch (c) {
		case 'c':
			if (o.ncorner == 4) {
				snprintf(err.msg, sizeof err.msg, "given more "
				    "than four times");
				loft_usage_error(usage_text, c, err.msg);
			}
			rc = loft_parse_list(optarg, o.corner + o.ncorner *
			    LOFT_MAXDIM, LOFT_MAXDIM, &n, &err);
			if (rc == 0 && (n < 2 || (o.ncorner > 0 && n != o.dim))) {
				snprintf(err.msg, sizeof err.msg, "'%s': want %s "
				    "numbers separated by commas", optarg,
				    o.ncorner > 0 ? (o.dim == 2 ? "2" : "3") :
				    "2 or 3");
				rc = LOFT_EINPUT;
			}
			o.dim = n;
			o.ncorner++;
			break;
		case 'b': o.boundary = 1; break;
		case 'i':
			rc = loft_parse_int(optarg, 0, LONG_MAX, &o.id, &err);
			if (rc == 0 && !(o.id >= 1 && o.id <= 1000000000)) {
				/* a number no patch can have: bad input */
				fprintf(stderr, "patchnew: -i %s: want an id from "
				    "1 to 1000000000\n", optarg);
				exit(1);
			}
			break;
		case 'p': rc = loft_opt_digits(optarg, &run.w, &err); break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
		if (rc != 0)
			loft_usage_error(usage_text, c, err.msg);
	}
	if (o.boundary == (o.ncorner > 0) || (!o.boundary && o.ncorner != 4) ||
	    (!o.boundary && optind < argc))
		loft_usage_error(usage_text, 0, "give four corners with -c, "
		    "or -b and the curves");
	if (!o.boundary) {
		/* corners were stored LOFT_MAXDIM apart; pack them */
		for (int k = 1; k < 4; k++)
			memmove(o.corner + k * o.dim, o.corner + k * LOFT_MAXDIM,
			    o.dim * sizeof *o.corner);
		return from_corners(&run);
	}
	return loft_run_design(&run, argc - optind, argv + optind,
	    from_curves);
}
#endif
