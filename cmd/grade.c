/*
 * grade: grade each record of insole knots into a set of shoe sizes
 * (Manning 1973, Fig. 16): per size step, the length along the foot (x)
 * grows by one step and the width across it (y) by a smaller step, about
 * a reference point; not a proportional enlargement.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loft.h"

/* One English size, 1/3 inch: the step in length, in millimetres. */
#define LENGTH_STEP 8.46
/* The width step: a last's joint girth grows 1/4 inch (6.35 mm) per
 * English size, and an insole is about 2.5 times narrower at the joint
 * than the girth around it; 1/10 inch. */
#define WIDTH_STEP 2.54
/* Sizes are whole numbers within this many steps of the input's. */
#define MAX_STEPS 1000

struct opts {
	long from, to;
	double lstep, wstep;
	int have_origin;
	double origin[2];
};

static const char usage_text[] =
    "usage: grade -s from:to [-l step] [-w step] [-o x,y] [-p digits] "
    "[file ...]\n";

static void
usage(int status)
{
	fputs(usage_text, status ? stderr : stdout);
	exit(status);
}

/* A whole number with an optional sign, |v| <= MAX_STEPS; 0 or -1. */
static int
parse_step(const char *s, size_t len, long *v)
{
	char buf[32];
	struct loft_error err;
	int neg = len > 0 && s[0] == '-';

	if (len > 0 && (s[0] == '-' || s[0] == '+')) {
		s++;
		len--;
	}
	if (len == 0 || len >= sizeof buf)
		return -1;
	memcpy(buf, s, len);
	buf[len] = '\0';
	if (loft_parse_int(buf, 0, MAX_STEPS, v, &err) != 0)
		return -1;
	if (neg)
		*v = -*v;
	return 0;
}

/* The size attribute: the input's size (0 when it has none) plus k. */
static int
size_attr(const struct loft_record *rec, long k, char *buf, size_t n,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, "size");
	long base = 0;

	if (v != NULL && parse_step(v, strlen(v), &base) != 0)
		return loft_fail(err, LOFT_EINPUT, -1, "attribute size=%s: want "
		    "a whole number from -%d to %d", v, MAX_STEPS, MAX_STEPS);
	snprintf(buf, n, base + k == 0 ? "0" : "%+ld", base + k);
	return 0;
}

/* A start= or end= direction, stretched by the grading: (tx sx, ty sy). */
static int
put_direction(struct loft_writer *w, const struct loft_record *rec,
    const char *key, const double *stretch, struct loft_error *err)
{
	const char *v = loft_attr(rec, key);
	char a[LOFT_NUMBUF], b[LOFT_NUMBUF], buf[2 * LOFT_NUMBUF + 2];
	double t[2];
	int n;

	if (v == NULL)
		return 0;
	if (loft_parse_list(v, t, 2, &n, err) != 0 || n != 2)
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: want 2 "
		    "numbers separated by commas", key, v);
	t[0] *= stretch[0];
	t[1] *= stretch[1];
	if (!isfinite(t[0]) || !isfinite(t[1]))
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: too "
		    "large to grade", key, v);
	loft_format_num(a, t[0], w->digits);
	loft_format_num(b, t[1], w->digits);
	snprintf(buf, sizeof buf, "%s,%s", a, b);
	loft_put_attr(w, key, buf);
	return 0;
}

/*
 * The grading formula.  With L = max x - min x and W = max y - min y the
 * outline's length and width, (ox, oy) the reference point, l and w the
 * steps, size step k moves each knot to
 *   x' = x + (x - ox) k l / L,   y' = y + (y - oy) k w / W,
 * so the outline of size k is exactly L + k l long and W + k w wide.
 */
static int
grade_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	static const char *const consumed[] = { "size", "start", "end", NULL };
	const struct opts *o = run->ctx;
	double lo[2], hi[2], ref[2], len, wid;
	size_t heel = 0;
	char size[32];

	if (rec->type != NULL && strcmp(rec->type, "points") != 0)
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: grade reads "
		    "knots (point records)", rec->type);
	if (rec->nrows == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "record has no knots");
	if (rec->ncols != 2)
		return loft_fail(err, LOFT_EINPUT, 0, "knots have %d "
		    "coordinate%s; grade reads plane outlines (2)", rec->ncols,
		    rec->ncols == 1 ? "" : "s");
	lo[0] = hi[0] = rec->num[0];
	lo[1] = hi[1] = rec->num[1];
	for (size_t i = 1; i < rec->nrows; i++)
		for (int k = 0; k < 2; k++) {
			double v = rec->num[2 * i + k];

			if (v < lo[k]) {
				lo[k] = v;
				if (k == 0)
					heel = i;
			}
			if (v > hi[k])
				hi[k] = v;
		}
	len = hi[0] - lo[0];
	wid = hi[1] - lo[1];
	if (!isfinite(len) || !isfinite(wid))
		return loft_fail(err, LOFT_EINPUT, -1, "the outline is too "
		    "large to grade");
	if (!(len > 0) || !(wid > 0))
		return loft_fail(err, LOFT_EINPUT, -1, "the knots have no "
		    "extent along %s: no outline to grade", len > 0 ? "y" : "x");
	ref[0] = o->have_origin ? o->origin[0] : rec->num[2 * heel];
	ref[1] = o->have_origin ? o->origin[1] : rec->num[2 * heel + 1];
	for (long k = o->from; k <= o->to; k++) {
		double sl = k * o->lstep, sw = k * o->wstep, stretch[2];

		if (!(len + sl > 0) || !(wid + sw > 0))
			return loft_fail(err, LOFT_EINPUT, -1, "size step %ld "
			    "leaves the outline no %s (%g %+g)", k,
			    len + sl > 0 ? "width" : "length",
			    len + sl > 0 ? wid : len, len + sl > 0 ? sw : sl);
		stretch[0] = (len + sl) / len;
		stretch[1] = (wid + sw) / wid;
		if (size_attr(rec, k, size, sizeof size, err) != 0)
			return LOFT_EINPUT;
		loft_put_type(&run->w, "points");
		loft_put_attr(&run->w, "size", size);
		loft_put_attrs_except(&run->w, rec, consumed);
		if (put_direction(&run->w, rec, "start", stretch, err) != 0 ||
		    put_direction(&run->w, rec, "end", stretch, err) != 0)
			return LOFT_EINPUT;
		loft_end_line(&run->w);
		for (size_t i = 0; i < rec->nrows; i++) {
			double x = rec->num[2 * i], y = rec->num[2 * i + 1];

			loft_put_num(&run->w, x + (x - ref[0]) * sl / len);
			loft_put_num(&run->w, y + (y - ref[1]) * sw / wid);
			loft_end_line(&run->w);
		}
		loft_end_record(&run->w);
	}
	return 0;
}

/* -s from:to */
static int
parse_sizes(const char *s, struct opts *o)
{
	const char *colon = strchr(s, ':');

	return colon == NULL || parse_step(s, (size_t)(colon - s), &o->from) ||
	    parse_step(colon + 1, strlen(colon + 1), &o->to) ||
	    o->from > o->to ? -1 : 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .lstep = LENGTH_STEP, .wstep = WIDTH_STEP };
	struct loft_run run = { .prog = "grade", .out = stdout, .msg = stderr,
	    .handle = grade_record, .ctx = &o };
	struct loft_error err;
	int c, rc = 0, n, sizes = 0;
	long digits;

	while ((c = getopt(argc, argv, "s:l:w:o:p:h")) != -1) {
		switch (c) {
		case 's':
			if (parse_sizes(optarg, &o) != 0) {
				rc = loft_fail(&err, LOFT_EINPUT, -1, "'%s': want "
				    "from:to, whole numbers from -%d to %d, from "
				    "<= to", optarg, MAX_STEPS, MAX_STEPS);
			}
			sizes = 1;
			break;
		case 'l': rc = loft_parse_real(optarg, 0, 1e6, &o.lstep, &err);
		    break;
		case 'w': rc = loft_parse_real(optarg, 0, 1e6, &o.wstep, &err);
		    break;
		case 'o':
			rc = loft_parse_list(optarg, o.origin, 2, &n, &err);
			if (rc == 0 && n != 2)
				rc = loft_fail(&err, LOFT_EINPUT, -1, "'%s': want "
				    "2 numbers separated by commas", optarg);
			o.have_origin = 1;
			break;
		case 'p': rc = loft_parse_int(optarg, 1, 17, &digits, &err);
		    run.w.digits = digits; break;
		case 'h': usage(0); break;
		default: usage(2);
		}
		if (rc != 0) {
			fprintf(stderr, "grade: -%c %s\n", c, err.msg);
			usage(2);
		}
	}
	if (!sizes) {
		fputs("grade: -s from:to is needed\n", stderr);
		usage(2);
	}
	return loft_run_files(&run, argc - optind, argv + optind);
}
#endif
