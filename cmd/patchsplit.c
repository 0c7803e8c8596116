/*
 * patchsplit: split patches of a design along a line of constant u or v
 * (MacCallum 1970, section 5); the two halves are identical to the
 * patch they replace.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	int dir;                /* 0: -u, 1: -v, -1: not given */
	double t;
	long id;                /* -i */
	int have_id;            /* 0: every patch */
};

static const char usage_text[] =
    "usage: patchsplit -u t | -v t [-i id] [-p digits] [file ...]\n";

static int
split_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_design d = { 0 };
	struct loft_error err;
	size_t count;
	long at = -1;           /* -i: the index of the patch split */
	int rc = 0;

	if (loft_design_only_patches(run, recs, n) != 0 ||
	    loft_design_from_records(run, recs, n, &d) != 0)
		rc = 1;
	count = d.n;
	err.line = 0;           /* loft_fail sets the row, not the line */
	if (rc == 0 && o->have_id) {
		long i = at = loft_design_find(&d, o->id);

		if (i < 0) {
			fprintf(run->msg, "patchsplit: no patch with id %ld in "
			    "the input\n", o->id);
			rc = 1;
		} else if (loft_design_split(&d, (size_t)i, o->dir, o->t,
		    &err) != 0) {
			loft_report(run, d.p[i].rec, &err);
			rc = 1;
		}
	} else if (rc == 0) {
		for (size_t i = 0; i < count && rc == 0; i++)
			if (loft_design_split(&d, i, o->dir, o->t, &err) != 0) {
				loft_report(run, d.p[i].rec, &err);
				rc = 1;
			}
	}
	/* input order, each split patch's second half (appended to d, in
	 * the order of the splits) after its first */
	for (size_t i = 0, j = count; rc == 0 && i < count; i++) {
		loft_design_put(&run->w, &d, i);
		if (j < d.n && (!o->have_id || (long)i == at))
			loft_design_put(&run->w, &d, j++);
	}
	loft_design_free(&d);
	return rc;
}

/* t of -u or -v: strictly between 0 and 1. */
static void
parse_t(int c, const char *arg, struct opts *o)
{
	struct loft_error err;

	if (o->dir >= 0)
		loft_usage_error(usage_text, 0, "give one of -u and -v");
	if (loft_parse_num(arg, strlen(arg), &o->t, &err) != 0) {
		loft_usage_error(usage_text, c, err.msg);
	}
	if (!(o->t > 0 && o->t < 1)) {
		/* a number splitting cannot use: bad input, not usage */
		fprintf(stderr, "patchsplit: -%c %s: want a number between 0 "
		    "and 1, both excluded\n", c, arg);
		exit(1);
	}
	o->dir = c == 'u' ? 0 : 1;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .dir = -1 };
	struct loft_run run = { .prog = "patchsplit", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "u:v:i:p:h")) != -1) {
		switch (c) {
		case 'u':
		case 'v': parse_t(c, optarg, &o); break;
		case 'i':
			if (loft_parse_int(optarg, 0, LONG_MAX, &o.id, &err))
				loft_usage_error(usage_text, c, err.msg);
			o.have_id = 1;
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.dir < 0)
		loft_usage_error(usage_text, 0, "give -u t or -v t");
	return loft_run_design(&run, argc - optind, argv + optind,
	    split_design);
}
#endif
