/*
 * hydro: the hydrostatics of a hull given as surface records, one row
 * per waterline (a hydrostatic table), or with -s its curve of
 * sectional areas.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

enum field {
	F_Z, F_VOLUME, F_DISPLACEMENT, F_LCB, F_TCB, F_VCB, F_AWP, F_LCF,
	F_BMT, F_BML, F_KMT, F_KML, F_LWL, F_BWL, F_T, F_CB, F_CP, F_CM,
	F_CWP, F_WETTED, F_AM
};

static const char *const field_names[] = {
	"z", "volume", "displacement", "lcb", "tcb", "vcb", "awp", "lcf",
	"bmt", "bml", "kmt", "kml", "lwl", "bwl", "t", "cb", "cp", "cm",
	"cwp", "wetted", "am", NULL
};

#define MAXFIELDS 64

struct opts {
	int whole;              /* -w */
	double *z;              /* -z: the waterlines */
	size_t nz, zcap;
	int field[MAXFIELDS], nfield;   /* -f; 0: every field */
	double rho;             /* -r, or 0 */
	long stations;          /* -s, or 0 */
};

/* More stations than this in a curve of sectional areas is a mistake. */
#define STATIONS_MAX 100000

static const char usage_text[] =
    "usage: hydro [-w] [-z z|from:to:step] [-f field,...] [-r density]\n"
    "             [-s stations] [-p digits] [file ...]\n";

/* The value of field f of the waterline's hydrostatics. */
static double
field_value(const struct opts *o, const struct loft_hydrostatics *h, int f)
{
	const double v[] = {
		h->z, h->volume, o->rho * h->volume, h->lcb, h->tcb, h->vcb,
		h->awp, h->lcf, h->bmt, h->bml, h->kmt, h->kml, h->lwl, h->bwl,
		h->t, h->cb, h->cp, h->cm, h->cwp, h->wetted, h->am
	};

	return v[f];
}

/* Report err of the hull of recs[0..n): at the record of the surface
 * err->row names where the hull is open (loft_hydro_at), else at the
 * first. */
static void
report(struct loft_run *run, const struct loft_record *recs, size_t n,
    struct loft_error *err)
{
	const struct loft_record *rec = &recs[0];

	if (err->row >= 0 && (size_t)err->row < n)
		rec = &recs[err->row];
	err->row = -1;
	loft_report(run, rec, err);
}

/* One row per waterline. */
static int
table(struct loft_run *run, const struct loft_hydro *h,
    const struct loft_record *recs, size_t nrec)
{
	const struct opts *o = run->ctx;
	int all[F_AM + 1], n = o->nfield, k = 0;
	const int *fields = o->field;

	if (n == 0) {
		for (int f = 0; f <= F_AM; f++)
			if (f != F_DISPLACEMENT || o->rho > 0)
				all[k++] = f;
		fields = all;
		n = k;
	}
	for (size_t i = 0; i < o->nz; i++) {
		struct loft_hydrostatics hs;
		struct loft_error err;

		err.line = 0;
		if (loft_hydro_at(h, o->z[i], &hs, &err) != 0) {
			report(run, recs, nrec, &err);
			return 1;
		}
		for (int j = 0; j < n; j++)
			loft_put_num(&run->w, field_value(o, &hs, fields[j]));
		loft_end_line(&run->w);
	}
	loft_end_record(&run->w);
	return 0;
}

/* -s: per waterline, station x against immersed area. */
static int
sections(struct loft_run *run, const struct loft_hydro *h,
    const struct loft_record *recs, size_t nrec)
{
	const struct opts *o = run->ctx;
	char num[LOFT_NUMBUF];
	double *x = malloc(2 * (size_t)o->stations * sizeof *x), *a;
	struct loft_error err;
	int rc = 0;

	if (x == NULL) {
		fputs("hydro: out of memory\n", run->msg);
		return 1;
	}
	a = x + o->stations;
	for (size_t i = 0; i < o->nz; i++) {
		double x0, x1;

		err.line = 0;
		if ((rc = loft_hydro_ends(h, o->z[i], &x0, &x1, &err)) == 0) {
			for (long j = 0; j < o->stations; j++)
				x[j] = o->stations == 1 ? x0 / 2 + x1 / 2 : x0 +
				    (x1 - x0) * ((double)j /
				    (double)(o->stations - 1));
			rc = loft_hydro_sections(h, o->z[i], x,
			    (size_t)o->stations, a, &err);
		}
		if (rc != 0) {
			report(run, recs, nrec, &err);
			break;
		}
		loft_put_type(&run->w, "points");
		loft_put_attr(&run->w, "name", "sectional-area");
		loft_format_num(num, o->z[i], 0);
		loft_put_attr(&run->w, "z", num);
		loft_end_line(&run->w);
		for (long j = 0; j < o->stations; j++) {
			double row[2] = { x[j], a[j] };

			loft_put_row(&run->w, row, 2);
		}
		loft_end_record(&run->w);
	}
	free(x);
	return rc != 0;
}

static int
hydro_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_surface *s;
	struct loft_hydro h;
	struct loft_error err;
	size_t ns;
	int rc;

	if (n == 0)
		return 0;
	if (loft_surfaces_from_records(run, recs, n, &s, &ns) != 0)
		return 1;
	err.line = 0;
	if (loft_hydro_init(&h, s, ns, o->whole, &err) != 0) {
		loft_report(run, &recs[0], &err);
		free(s);
		return 1;
	}
	rc = o->stations > 0 ? sections(run, &h, recs, n) :
	    table(run, &h, recs, n);
	loft_hydro_free(&h);
	free(s);
	return rc;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "hydro", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	double st;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "wz:f:r:s:p:h")) != -1) {
		switch (c) {
		case 'w': o.whole = 1; break;
		case 'z':
			loft_opt_range(usage_text, c, optarg, &o.z, &o.nz, &o.zcap);
			break;
		case 'f':
			if (loft_opt_fields(optarg, field_names, o.field,
			    MAXFIELDS, &o.nfield, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'r':
			if (loft_parse_real(optarg, 0, 1e300, &o.rho, &err) != 0 ||
			    !(o.rho > 0))
				loft_usage_error(usage_text, c, "want a density "
				    "above 0");
			break;
		case 's':
			if (loft_parse_real(optarg, 1, STATIONS_MAX, &st, &err) !=
			    0 || st != floor(st))
				loft_usage_error(usage_text, c, "want a whole "
				    "number of stations from 1 to 100000");
			o.stations = (long)st;
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	for (int i = 0; i < o.nfield; i++)
		if (o.field[i] == F_DISPLACEMENT && !(o.rho > 0))
			loft_usage_error(usage_text, 'f', "displacement needs "
			    "a density, -r");
	if (o.nz == 0)
		loft_opt_range(usage_text, 'z', "0", &o.z, &o.nz, &o.zcap);
	c = loft_run_design(&run, argc - optind, argv + optind, hydro_design);
	free(o.z);
	return c;
}
#endif
