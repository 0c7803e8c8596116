/*
 * patchloft: a design of MacCallum's bi-quartic patches through two or
 * more section curves, slope-continuous across every patch edge, the
 * curves across the sections fitted as splinefit fits its curves.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	struct loft_skin_opts skin;
	int start_dim, end_dim;         /* coordinates given with -S, -E */
};

static const char usage_text[] =
    "usage: patchloft [-c] [-S tx,ty[,tz]] [-E tx,ty[,tz]] [-p digits] "
    "[file ...]\n";

/* The sections' curves, checked one by one; 0, or 1 after reporting. */
static int
read_sections(struct loft_run *run, const struct loft_record *recs, size_t n,
    struct loft_curve *sec)
{
	struct loft_error err;
	int rc = 0;

	for (size_t i = 0; i < n; i++) {
		err.line = 0;
		if (loft_curve_from_record(&recs[i], &sec[i], &err) != 0) {
			loft_report(run, &recs[i], &err);
			rc = 1;
		}
	}
	return rc;
}

static int
skin_sections(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_skin_result r;
	struct loft_design d = { 0 };
	struct loft_curve *sec;
	struct loft_error err;
	int rc;

	if (n == 0) {
		fprintf(run->msg, "patchloft: no sections in the input: a loft "
		    "needs at least %d\n", o->skin.closed ? LOFT_MIN_CLOSED :
		    LOFT_MIN_OPEN);
		return 1;
	}
	if ((sec = calloc(n, sizeof *sec)) == NULL) {
		fprintf(run->msg, "patchloft: out of memory\n");
		return 1;
	}
	if (read_sections(run, recs, n, sec) != 0) {
		free(sec);
		return 1;
	}
	err.line = 0;
	if ((o->skin.have_start && o->start_dim != sec[0].dim) ||
	    (o->skin.have_end && o->end_dim != sec[0].dim)) {
		loft_fail(&err, LOFT_EINPUT, -1, "-%c has %d numbers, the "
		    "sections %d coordinates", o->skin.have_start &&
		    o->start_dim != sec[0].dim ? 'S' : 'E',
		    o->skin.have_start && o->start_dim != sec[0].dim ?
		    o->start_dim : o->end_dim, sec[0].dim);
		loft_report(run, &recs[0], &err);
		free(sec);
		return 1;
	}
	rc = loft_skin(&o->skin, sec, n, &r, &err);
	free(sec);
	if (rc != 0) {
		size_t at = err.row >= 0 && (size_t)err.row < n ?
		    (size_t)err.row : 0;

		err.row = -1;
		loft_report(run, &recs[at], &err);
		return 1;
	}
	rc = loft_skin_design(&r, &d, &err);
	loft_skin_free(&r);
	if (rc != 0) {
		fprintf(run->msg, "patchloft: %s\n", err.msg);
		loft_design_free(&d);
		return 1;
	}
	for (size_t i = 0; i < d.n; i++)
		loft_design_put(&run->w, &d, i);
	loft_design_free(&d);
	return 0;
}

/* -S or -E: a direction of 2 or 3 numbers, not zero. */
static void
parse_slope(int c, const char *arg, double *v, int *have, int *dim)
{
	struct loft_error err;

	if (loft_parse_list(arg, v, LOFT_MAXDIM, dim, &err) != 0)
		loft_usage_error(usage_text, c, err.msg);
	/* the scaled norm: 0,0,1e-300 is a direction (issue 28) */
	if (*dim < 2 || loft_unit_tangent(v, *dim, v) != 0) {
		snprintf(err.msg, sizeof err.msg, "'%s': want a direction of "
		    "2 or 3 numbers, not zero", arg);
		loft_usage_error(usage_text, c, err.msg);
	}
	*have = 1;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o;
	struct loft_run run = { .prog = "patchloft", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c;

	memset(&o, 0, sizeof o);
	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "cS:E:p:h")) != -1) {
		switch (c) {
		case 'c': o.skin.closed = 1; break;
		case 'S': parse_slope(c, optarg, o.skin.start,
		    &o.skin.have_start, &o.start_dim); break;
		case 'E': parse_slope(c, optarg, o.skin.end, &o.skin.have_end,
		    &o.end_dim); break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.skin.closed && (o.skin.have_start || o.skin.have_end)) {
		loft_usage_error(usage_text, 0, "-S and -E are for an open "
		    "loft; -c closes it");
	}
	return loft_run_design(&run, argc - optind, argv + optind,
	    skin_sections);
}
#endif
