/*
 * offsets: tables of offsets in and out.  With -x and -z, the
 * half-breadths of a hull's surfaces at those stations and waterlines,
 * as an offsets record; with -k, each offsets record read back as one
 * station knot record per row, for splinefit -o | patchloft.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	double *x, *z;          /* -x stations, -z waterlines */
	size_t nx, xcap, nz, zcap;
	int knots;              /* -k */
};

/* A half-breadth the table lacks: no point of the hull there. */
#define NONE (-1.0)

/* A half-breadth within this part of the hull's size of 0 is a point on
 * the centreplane, off it by the rounding of the surfaces' evaluation
 * (a stem or keel station lofted through y = 0). */
#define CENTRE_TOL 1e-12

/* The largest extent of the surfaces' boxes. */
static double
hull_size(const struct loft_surface *s, size_t ns)
{
	double size = 0;

	for (size_t k = 0; k < ns; k++) {
		double lo[3], hi[3];

		loft_surface_box(&s[k], lo, hi);
		for (int i = 0; i < 3; i++)
			size = fmax(size, hi[i] - lo[i]);
	}
	return size;
}

static const char usage_text[] =
    "usage: offsets -x x|from:to:step -z z|from:to:step [-p digits] "
    "[file ...]\n"
    "       offsets -k [-p digits] [file ...]\n";

/* The waterlines as the header's z= list, in a new string; NULL out of
 * memory. */
static char *
levels_text(const double *z, size_t n)
{
	char *buf, num[LOFT_NUMBUF];
	size_t len = 0;

	if ((buf = malloc(n * (LOFT_NUMBUF + 1) + 1)) == NULL)
		return NULL;
	buf[0] = '\0';
	for (size_t i = 0; i < n; i++) {
		loft_format_num(num, z[i], 0);
		len += (size_t)sprintf(buf + len, "%s%s", i ? "," : "", num);
	}
	return buf;
}

/* -x, -z: the table of the surfaces' half-breadths. */
static int
tabulate(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_surface *s;
	size_t ns;
	double *row, size;
	char *levels = NULL;

	if (n == 0)
		return 0;
	if (loft_surfaces_from_records(run, recs, n, &s, &ns) != 0)
		return 1;
	size = hull_size(s, ns);
	if ((row = malloc((o->nz + 1) * sizeof *row)) == NULL ||
	    (levels = levels_text(o->z, o->nz)) == NULL) {
		fputs("offsets: out of memory\n", run->msg);
		free(row);
		free(s);
		return 1;
	}
	loft_put_type(&run->w, "offsets");
	loft_put_attr(&run->w, "z", levels);
	free(levels);
	loft_end_line(&run->w);
	for (size_t i = 0; i < o->nx; i++) {
		row[0] = o->x[i];
		for (size_t j = 0; j < o->nz; j++) {
			row[j + 1] = NONE;
			for (size_t k = 0; k < ns; k++) {
				double y;

				if (loft_surface_meet(&s[k], 0, o->x[i], 2, o->z[j],
				    1, &y) == 0 && y > row[j + 1])
					row[j + 1] = fmax(0, y);
			}
			if (row[j + 1] >= 0 && row[j + 1] <= CENTRE_TOL * size)
				row[j + 1] = 0;
		}
		loft_put_row(&run->w, row, (int)o->nz + 1);
	}
	loft_end_record(&run->w);
	free(row);
	free(s);
	return 0;
}

/* The z= list of an offsets record: its count must be the columns - 1. */
static int
read_levels(const struct loft_record *rec, double *z, struct loft_error *err)
{
	const char *a = loft_attr(rec, "z");
	int n;

	if (a == NULL)
		return loft_fail(err, LOFT_EINPUT, -1, "offsets record without "
		    "its waterlines z=");
	if (loft_parse_list(a, z, rec->ncols - 1, &n, err) != 0 ||
	    n != rec->ncols - 1)
		return loft_fail(err, LOFT_EINPUT, 0, "z=%s: want %d "
		    "waterline heights, one per half-breadth column", a,
		    rec->ncols - 1);
	for (int i = 1; i < n; i++)
		if (!(z[i] > z[i - 1]))
			return loft_fail(err, LOFT_EINPUT, -1, "z=%s: the "
			    "waterlines must rise", a);
	return 0;
}

/* -k: one station record per row, its points from the lowest
 * waterline up, where the table has a half-breadth. */
static int
stations(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	double *z;
	char num[LOFT_NUMBUF];

	if (rec->type == NULL || strcmp(rec->type, "offsets") != 0)
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: offsets -k "
		    "reads offsets records", rec->type ? rec->type : "a point");
	if (rec->ncols < 3)
		return loft_fail(err, LOFT_EINPUT, 0, "an offsets row needs a "
		    "station and two half-breadths or more, not %d numbers",
		    rec->ncols);
	if ((z = malloc((size_t)rec->ncols * sizeof *z)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (read_levels(rec, z, err) != 0) {
		free(z);
		return LOFT_EINPUT;
	}
	for (size_t i = 0; i < rec->nrows; i++) {
		const double *r = rec->num + i * (size_t)rec->ncols;
		int have = 0;

		for (int j = 1; j < rec->ncols; j++)
			have += r[j] >= 0;
		if (have < 2) {
			free(z);
			return loft_fail(err, LOFT_EINPUT, (long)i, "station x = "
			    "%g has %d half-breadths; a station needs 2", r[0],
			    have);
		}
		loft_put_type(&run->w, "points");
		loft_format_num(num, r[0], 0);
		loft_put_attr(&run->w, "station", num);
		loft_end_line(&run->w);
		for (int j = 1; j < rec->ncols; j++)
			if (r[j] >= 0) {
				double p[3] = { r[0], r[j], z[j - 1] };

				loft_put_row(&run->w, p, 3);
			}
		loft_end_record(&run->w);
	}
	free(z);
	return 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "offsets", .out = stdout,
	    .msg = stderr, .handle = stations, .ctx = &o };
	struct loft_error err;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "x:z:kp:h")) != -1) {
		switch (c) {
		case 'x':
			loft_opt_range(usage_text, c, optarg, &o.x, &o.nx, &o.xcap);
			break;
		case 'z':
			loft_opt_range(usage_text, c, optarg, &o.z, &o.nz, &o.zcap);
			break;
		case 'k': o.knots = 1; break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.knots && (o.nx > 0 || o.nz > 0))
		loft_usage_error(usage_text, 0, "-k reads a table: no -x or -z");
	if (!o.knots && (o.nx == 0 || o.nz == 0))
		loft_usage_error(usage_text, 0, "give stations -x and "
		    "waterlines -z, or -k");
	if (o.knots)
		c = loft_run_files(&run, argc - optind, argv + optind);
	else
		c = loft_run_design(&run, argc - optind, argv + optind,
		    tabulate);
	free(o.x);
	free(o.z);
	return c;
}
#endif
