/*
 * floor: the input and output work of sample (or of splinefit | sample)
 * with no geometry, so that the benchmark can tell the two apart.
 *
 *   floor [-n per] [-p digits] [-f] [file ...]
 *
 * It reads loft records with loft's reader and, for a record of n rows,
 * writes n * per + 1 points as sample -n per does for n segments: of
 * the record's dimension, or a quarter of it for a cubic record.  The
 * numbers are the record's own, scaled by a factor that changes from
 * point to point, so that they carry as many digits as sample's.  They
 * go out through loft's writer (and formatter), or with -f through
 * printf("%.17g") (or "%.{digits}g"), one point to a line.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	long per;
	int printf_, digits;
};

static int
floor_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	int cubic = rec->type != NULL && strcmp(rec->type, "cubic") == 0;
	int dim = cubic ? rec->ncols / 4 : rec->ncols;
	long npts = (long)rec->nrows * o->per + 1;

	if (rec->nrows == 0 || dim < 1)
		return loft_fail(err, LOFT_EINPUT, -1, "no rows");
	for (long j = 0; j < npts; j++) {
		const double *row = rec->num + (j % rec->nrows) * rec->ncols;
		double f = 1 + (double)(j % o->per) / (3.0 * o->per);

		for (int q = 0; q < dim; q++) {
			if (o->printf_)
				printf("%s%.*g", q ? " " : "", o->digits ?
				    o->digits : 17, row[q] * f);
			else
				loft_put_num(&run->w, row[q] * f);
		}
		if (o->printf_)
			putchar('\n');
		else
			loft_end_line(&run->w);
	}
	if (o->printf_)
		putchar('\n');
	else
		loft_end_record(&run->w);
	return 0;
}

int
main(int argc, char *argv[])
{
	struct opts o = { 20, 0, 0 };
	struct loft_run run = { .prog = "floor", .out = stdout, .msg = stderr,
	    .handle = floor_record, .ctx = &o };
	int c;

	while ((c = getopt(argc, argv, "n:p:f")) != -1) {
		switch (c) {
		case 'n': o.per = atol(optarg); break;
		case 'p': o.digits = atoi(optarg); break;
		case 'f': o.printf_ = 1; break;
		default:
			fputs("usage: floor [-n per] [-p digits] [-f] "
			    "[file ...]\n", stderr);
			return 2;
		}
	}
	if (o.per < 1 || o.digits < 0 || o.digits > 17)
		return 2;
	run.w.digits = o.digits;
	return loft_run_files(&run, argc - optind, argv + optind);
}
