/*
 * optrange.c: an option's list of levels, "v" or "from:to:step", or a
 * comma-separated list of those, as
 * hydro -z and offsets -x and -z take them.
 */
#include <stdlib.h>
#include <string.h>

#include "loftprog.h"

/* More levels than this from one FROM:TO:STEP is a mistake of units. */
#define RANGE_MAX 100000

static int
push(double **v, size_t *n, size_t *cap, double x, struct loft_error *err)
{
	if (loft_grow((void **)v, cap, *n + 1, sizeof **v) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	(*v)[(*n)++] = x;
	return 0;
}

/* One item of the list: v or from:to:step, ending at end. */
static int
item(const char *s, const char *end, double **v, size_t *n, size_t *cap,
    struct loft_error *err)
{
	double a[3];
	int k = 0;
	long count;

	for (;;) {
		size_t len = strcspn(s, ":,");

		if (s + len > end)
			len = (size_t)(end - s);

		if (k == 3 || loft_parse_num(s, len, &a[k], err) != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "want a value or "
			    "from:to:step");
		k++;
		if (s + len >= end)
			break;
		s += len + 1;
	}
	if (k == 1)
		return push(v, n, cap, a[0], err);
	if (k != 3 || !(a[2] > 0) || !(a[0] <= a[1]))
		return loft_fail(err, LOFT_EINPUT, -1, "want from:to:step, from "
		    "up to to, step above 0");
	if (!((a[1] - a[0]) / a[2] < RANGE_MAX))
		return loft_fail(err, LOFT_EINPUT, -1, "more than %d levels",
		    RANGE_MAX);
	/* to itself where the steps reach it within rounding */
	count = (long)((a[1] - a[0]) / a[2] * (1 + 1e-12) + 1e-9) + 1;
	for (long i = 0; i < count; i++) {
		/* 0.3 + 3 * 0.1 is 0.6000000000000001: the steps are meant
		 * in decimals, so 15 digits of them */
		char buf[LOFT_NUMBUF];
		double x;

		loft_format_num(buf, a[0] + (double)i * a[2], 15);
		if (loft_parse_num(buf, strlen(buf), &x, err) != 0)
			x = a[0] + (double)i * a[2];
		if (push(v, n, cap, x, err) != 0)
			return LOFT_ENOMEM;
	}
	return 0;
}

/* Parse arg into the levels, or 0 and a code with err. */
static int
parse(const char *arg, double **v, size_t *n, size_t *cap,
    struct loft_error *err)
{
	for (const char *s = arg;; ) {
		const char *end = s + strcspn(s, ",");
		int rc = item(s, end, v, n, cap, err);

		if (rc != 0)
			return rc;
		if (*end == '\0')
			return 0;
		s = end + 1;
	}
}

void
loft_opt_range(const char *usage, int opt, const char *arg, double **v,
    size_t *n, size_t *cap)
{
	struct loft_error err;
	int rc = parse(arg, v, n, cap, &err);

	if (rc == LOFT_ENOMEM) {
		/* the program's name: the usage's word after "usage: " */
		const char *prog = usage + strlen("usage: ");

		fprintf(stderr, "%.*s: out of memory\n",
		    (int)strcspn(prog, " \n"), prog);
		exit(1);
	}
	if (rc != 0)
		loft_usage_error(usage, opt, err.msg);
}
