/*
 * grade: grade each record of insole knots into a set of shoe sizes
 * (Manning 1973, Fig. 16) of a size system: per size, the length along
 * the outline's long axis grows by the system's step and the width
 * across it by a smaller step, about a reference point; not a
 * proportional enlargement.  Optionally the mirror image for the other
 * foot, and one file per size.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

/* Sizes and steps are whole or half numbers no larger than this. */
#define MAX_SIZE 1000
/* No more sizes than this from one outline. */
#define MAX_SIZES 1000

struct opts {
	const struct loft_size_system *sys;
	int absolute;           /* -s: sizes; -r: steps relative to the base */
	double from, to, step;  /* step 0: the system's interval */
	int have_base;
	double base;            /* -b */
	int have_lstep, have_wstep;
	double lstep, wstep;    /* per size number, in the knots' units */
	double unit;            /* the knots' unit in millimetres (-u) */
	int axis;               /* -a: 0 x, 1 y, -1 the longer */
	int have_origin;
	double origin[2];
	int mirror;             /* -m */
	const char *pattern;    /* -O, or NULL: standard output */
	struct loft_outfiles files;
	double *q;              /* graded knots, 2 * qcap numbers */
	size_t qcap;
};

static const char usage_text[] =
    "usage: grade -s sizes | -r steps [-S english|paris|mondopoint] "
    "[-b base] [-l step] [-w step] [-u mm|cm|m|in] [-a x|y] [-o x,y] [-m] "
    "[-O pattern] [-p digits] [file ...]\n";

/* A whole or half number, |v| <= MAX_SIZE, from s[0..len): 0 or -1. */
static int
parse_half(const char *s, size_t len, double *v)
{
	struct loft_error err;

	if (loft_parse_num(s, len, v, &err) != 0 || !(fabs(*v) <= MAX_SIZE) ||
	    2 * *v != floor(2 * *v))
		return -1;
	return 0;
}

/* -s or -r: SIZE, or FROM:TO[:STEP], STEP > 0, FROM <= TO. */
static int
parse_sizes(const char *s, struct opts *o)
{
	const char *c1 = strchr(s, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;

	o->step = 0;
	if (c1 == NULL) {
		if (parse_half(s, strlen(s), &o->from) != 0)
			return -1;
		o->to = o->from;
		return 0;
	}
	if (parse_half(s, (size_t)(c1 - s), &o->from) != 0 ||
	    parse_half(c1 + 1, c2 ? (size_t)(c2 - c1 - 1) : strlen(c1 + 1),
	    &o->to) != 0 || o->from > o->to)
		return -1;
	if (c2 != NULL && (parse_half(c2 + 1, strlen(c2 + 1), &o->step) != 0 ||
	    !(o->step > 0)))
		return -1;
	return 0;
}

/* -O: exactly one %s and no other %. */
static int
check_pattern(const char *p)
{
	const char *s = strstr(p, "%s");

	return s == NULL || strchr(s + 2, '%') != NULL ||
	    strchr(p, '%') != s ? -1 : 0;
}

/* A size as size= writes it: 7, 7.5; a relative step with its sign. */
static void
format_size(char *buf, double v, int relative)
{
	if (relative && v > 0)
		*buf++ = '+';
	loft_format_num(buf, v, 0);
}

/*
 * The record's size= attribute: 0 and *size unset when it has none, 1
 * with *size an absolute size, 2 with *size a relative step (signed, or
 * 0, as -r writes where no size is known); LOFT_EINPUT when bad.
 */
static int
size_attr(const struct loft_record *rec, double *size, struct loft_error *err)
{
	const char *v = loft_attr(rec, "size");

	if (v == NULL)
		return 0;
	if (parse_half(v, strlen(v), size) != 0)
		return -loft_fail(err, LOFT_EINPUT, -1, "attribute size=%s: "
		    "want a whole or half number from -%d to %d", v, MAX_SIZE,
		    MAX_SIZE);
	return v[0] == '+' || v[0] == '-' || *size == 0 ? 2 : 1;
}

/* 0, or LOFT_EINPUT unless size is in the system's range. */
static int
in_range(const struct opts *o, double size, struct loft_error *err)
{
	char buf[LOFT_NUMBUF];

	if (size >= o->sys->lo && size <= o->sys->hi)
		return 0;
	format_size(buf, size, 0);
	return loft_fail(err, LOFT_EINPUT, -1, "size %s is outside the %s "
	    "range, %g to %g", buf, o->sys->name, o->sys->lo, o->sys->hi);
}

/* A start= or end= attribute into t: 1, 0 when absent, or -LOFT_EINPUT. */
static int
direction_attr(const struct loft_record *rec, const char *key, double *t,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, key);
	int n;

	if (v == NULL)
		return 0;
	if (loft_parse_list(v, t, 2, &n, err) != 0 || n != 2)
		return -loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: want "
		    "2 numbers separated by commas", key, v);
	return 1;
}

/* key=tx,ty; LOFT_EINPUT when the grading made it overflow. */
static int
put_direction(struct loft_writer *w, const char *key, const double *t,
    struct loft_error *err)
{
	char a[LOFT_NUMBUF], b[LOFT_NUMBUF], buf[2 * LOFT_NUMBUF + 2];

	if (!isfinite(t[0]) || !isfinite(t[1]))
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s: too large "
		    "to grade", key);
	loft_format_num(a, t[0], w->digits);
	loft_format_num(b, t[1], w->digits);
	snprintf(buf, sizeof buf, "%s,%s", a, b);
	loft_put_attr(w, key, buf);
	return 0;
}

/* What one record brings to its graded sizes besides its knots. */
struct outline {
	const struct loft_record *rec;
	struct loft_grade_frame f;
	int have[2];            /* start=, end= */
	double dir[2][2];
	const char *side[2];    /* -m: the outline's side= and its mirror's */
};

/* One size (mirror 1: its mirror image), its change dl, dw, to run->w. */
static int
put_size(struct loft_run *run, const struct outline *ol, const char *size,
    double dl, double dw, int mirror, struct loft_error *err)
{
	static const char *const consumed[] = { "size", "side", "start", "end",
	    NULL };
	static const char *const keys[2] = { "start", "end" };
	struct opts *o = run->ctx;
	const struct loft_record *rec = ol->rec;
	double t[2];
	char why[sizeof err->msg];

	if (loft_grade_outline(&ol->f, rec->num, rec->nrows, dl, dw, mirror,
	    o->q, err) != 0) {
		memcpy(why, err->msg, sizeof why);
		return loft_fail(err, LOFT_EGEOM, -1, "size %s %s", size, why);
	}
	loft_put_type(&run->w, "points");
	loft_put_attr(&run->w, "size", size);
	if (o->mirror)
		loft_put_attr(&run->w, "side", ol->side[mirror]);
	else if (loft_attr(rec, "side") != NULL)
		loft_put_attr(&run->w, "side", loft_attr(rec, "side"));
	loft_put_attrs_except(&run->w, rec, consumed);
	/* the mirror runs the other way: its start is the end mirrored */
	for (int k = 0; k < 2; k++) {
		int from = mirror ? 1 - k : k;

		if (!ol->have[from])
			continue;
		loft_grade_direction(&ol->f, dl, dw, mirror, ol->dir[from], t);
		if (put_direction(&run->w, keys[k], t, err) != 0)
			return LOFT_EINPUT;
	}
	loft_end_line(&run->w);
	for (size_t i = 0; i < rec->nrows; i++)
		loft_put_row(&run->w, o->q + 2 * i, 2);
	loft_end_record(&run->w);
	return 0;
}

/* -m: the outline's side and its mirror's, from side= (left if none). */
static int
sides(const struct loft_record *rec, const char **side,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, "side");

	if (v == NULL || strcmp(v, "left") == 0) {
		side[0] = "left";
		side[1] = "right";
	} else if (strcmp(v, "right") == 0) {
		side[0] = "right";
		side[1] = "left";
	} else {
		return loft_fail(err, LOFT_EINPUT, -1, "attribute side=%s: want "
		    "left or right", v);
	}
	return 0;
}

/* -O: move what run->w holds for each size into that size's file. */
static int
to_files(struct loft_run *run, char sizes[][LOFT_NUMBUF + 1],
    const size_t *off, long n, struct loft_error *err)
{
	struct opts *o = run->ctx;
	const char *hole = strstr(o->pattern, "%s");
	size_t pre = (size_t)(hole - o->pattern);

	for (long k = 0; k < n; k++) {
		size_t len = strlen(o->pattern) + strlen(sizes[k]);
		char *name = malloc(len);
		int rc;

		if (name == NULL)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		memcpy(name, o->pattern, pre);
		strcpy(name + pre, sizes[k]);
		strcat(name, hole + 2);
		rc = loft_outfiles_add(&o->files, name, run->w.buf + off[k],
		    off[k + 1] - off[k], err);
		free(name);
		if (rc != 0)
			return rc;
	}
	loft_writer_cut(&run->w, 0);
	return 0;
}

/* The record's knots, its size, and the steps' sanity: into ol. */
static int
outline_of(struct loft_run *run, const struct loft_record *rec,
    struct outline *ol, double *base, int *known, struct loft_error *err)
{
	struct opts *o = run->ctx;
	double *q;
	int r;

	if (!loft_record_is(rec, LOFT_KIND_KNOTS))
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: grade reads "
		    "knots (point records)", rec->type);
	if (rec->nrows > 0 && rec->ncols != 2)
		return loft_fail(err, LOFT_EINPUT, 0, "knots have %d "
		    "coordinate%s; grade reads plane outlines (2)", rec->ncols,
		    rec->ncols == 1 ? "" : "s");
	if ((r = size_attr(rec, base, err)) < 0)
		return LOFT_EINPUT;
	*known = r;
	if (r == 0 && o->have_base) {
		*base = o->base;
		*known = 1;
	}
	if (o->absolute && *known == 2)
		return loft_fail(err, LOFT_EINPUT, -1, "size=%s is a step from "
		    "an unknown size, not a size: grade it by steps (-r)",
		    loft_attr(rec, "size"));
	if (o->absolute && *known == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "no base size: absolute "
		    "sizes (-s) need the outline's own, from size= or -b");
	if (*known == 1 && in_range(o, *base, err) != 0)
		return LOFT_EINPUT;
	ol->rec = rec;
	if (loft_grade_frame(rec->num, rec->nrows, o->axis,
	    o->have_origin ? o->origin : NULL, &ol->f, err) != 0 ||
	    loft_grade_steps_fit(&ol->f, o->lstep * o->sys->interval,
	    o->wstep * o->sys->interval, err) != 0)
		return LOFT_EINPUT;
	if ((r = direction_attr(rec, "start", ol->dir[0], err)) < 0)
		return LOFT_EINPUT;
	ol->have[0] = r;
	if ((r = direction_attr(rec, "end", ol->dir[1], err)) < 0)
		return LOFT_EINPUT;
	ol->have[1] = r;
	if (o->mirror && sides(rec, ol->side, err) != 0)
		return LOFT_EINPUT;
	if (rec->nrows > o->qcap) {
		if ((q = realloc(o->q, 2 * rec->nrows * sizeof *q)) == NULL)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		o->q = q;
		o->qcap = rec->nrows;
	}
	return 0;
}

static int
grade_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct outline ol;
	double base = 0, step = o->step > 0 ? o->step : o->sys->interval;
	long n = (long)floor((o->to - o->from) / step) + 1;
	char (*sizes)[LOFT_NUMBUF + 1];
	size_t *off;
	int known = 0, rc = 0;

	if (outline_of(run, rec, &ol, &base, &known, err) != 0)
		return LOFT_EINPUT;
	sizes = malloc((size_t)n * sizeof *sizes);
	off = malloc((size_t)(n + 1) * sizeof *off);
	if (sizes == NULL || off == NULL)
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (long k = 0; rc == 0 && k < n; k++) {
		double v = o->from + (double)k * step;
		double d = o->absolute ? v - base : v;
		double size = o->absolute ? v : base + v;

		off[k] = run->w.len;
		if (known == 1 && (rc = in_range(o, size, err)) != 0)
			break;
		if (!(fabs(size) <= MAX_SIZE)) {     /* size= could not say it
			                                and be read back */
			format_size(sizes[k], size, known != 1);
			rc = loft_fail(err, LOFT_EINPUT, -1, "size %s is beyond "
			    "what size= holds, -%d to %d", sizes[k], MAX_SIZE,
			    MAX_SIZE);
			break;
		}
		format_size(sizes[k], size, known != 1);
		rc = put_size(run, &ol, sizes[k], d * o->lstep, d * o->wstep, 0,
		    err);
		if (rc == 0 && o->mirror)
			rc = put_size(run, &ol, sizes[k], d * o->lstep,
			    d * o->wstep, 1, err);
	}
	if (rc == 0 && o->pattern != NULL && !run->w.bad) {
		off[n] = run->w.len;
		rc = to_files(run, sizes, off, n, err);
	}
	free(sizes);
	free(off);
	return rc;
}

/*
 * One option c with argument arg into o (and run's digits): 0, or -1
 * with err saying what is wrong; *sizes counts -s and -r.
 */
static int
set_option(int c, const char *arg, struct opts *o, struct loft_run *run,
    int *sizes, struct loft_error *err)
{
	static const char *const systems[] = { "english", "paris",
	    "mondopoint", NULL };
	static const char *const units[] = { "mm", "cm", "m", "in", NULL };
	static const double unit_mm[] = { 1, 10, 1000, 25.4 };
	static const char *const axes[] = { "x", "y", NULL };
	long digits;
	int i, n;

	switch (c) {
	case 's':
	case 'r':
		o->absolute = c == 's';
		if ((*sizes)++)
			return loft_fail(err, LOFT_EINPUT, -1, "'%s': give -s or "
			    "-r once", arg);
		if (parse_sizes(arg, o) != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "'%s': want SIZE "
			    "or FROM:TO[:STEP], whole or half numbers from -%d "
			    "to %d, FROM <= TO, STEP > 0", arg, MAX_SIZE,
			    MAX_SIZE);
		return 0;
	case 'S':
		if (loft_parse_word(arg, systems, &i, err))
			return -1;
		o->sys = &loft_size_systems[i];
		return 0;
	case 'b':
		o->have_base = 1;
		return parse_half(arg, strlen(arg), &o->base) == 0 ? 0 :
		    loft_fail(err, LOFT_EINPUT, -1, "'%s': want a whole or half "
		    "number", arg);
	case 'l':
		o->have_lstep = 1;
		return loft_parse_real(arg, 0, HUGE_VAL, &o->lstep, err);
	case 'w':
		o->have_wstep = 1;
		return loft_parse_real(arg, 0, HUGE_VAL, &o->wstep, err);
	case 'u':
		if (loft_parse_word(arg, units, &i, err))
			return -1;
		o->unit = unit_mm[i];
		return 0;
	case 'a':
		return loft_parse_word(arg, axes, &o->axis, err);
	case 'o':
		o->have_origin = 1;
		if (loft_parse_list(arg, o->origin, 2, &n, err))
			return -1;
		return n == 2 ? 0 : loft_fail(err, LOFT_EINPUT, -1, "'%s': want "
		    "2 numbers separated by commas", arg);
	case 'm':
		o->mirror = 1;
		return 0;
	case 'O':
		o->pattern = arg;
		return check_pattern(arg) == 0 ? 0 : loft_fail(err, LOFT_EINPUT,
		    -1, "'%s': want a file name with one %%s and no other %%",
		    arg);
	default:                /* 'p' */
		if (loft_parse_int(arg, 1, 17, &digits, err))
			return -1;
		run->w.digits = digits;
		return 0;
	}
}

/* After the options: the sizes' count and the steps in the knots' units. */
static void
finish_options(struct opts *o, int sizes)
{
	if (!sizes)
		loft_usage_error(usage_text, 0, "-s sizes or -r steps is "
		    "needed");
	if ((o->to - o->from) / (o->step > 0 ? o->step : o->sys->interval) >=
	    MAX_SIZES) {
		char msg[32];

		snprintf(msg, sizeof msg, "more than %d sizes", MAX_SIZES);
		loft_usage_error(usage_text, 0, msg);
	}
	if (!o->have_lstep)
		o->lstep = o->sys->length / o->unit;
	if (!o->have_wstep)
		o->wstep = o->sys->width / o->unit;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { .sys = loft_size_systems, .axis = -1, .unit = 1 };
	struct loft_run run = { .prog = "grade", .out = stdout, .msg = stderr,
	    .handle = grade_record, .ctx = &o };
	struct loft_error err;
	int c, status, sizes = 0;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "s:r:S:b:l:w:u:a:o:mO:p:h")) != -1) {
		if (c == 'h')
			loft_usage(usage_text, 0);
		if (c == '?')
			loft_usage(usage_text, 2);
		if (set_option(c, optarg, &o, &run, &sizes, &err) != 0)
			loft_usage_error(usage_text, c, err.msg);
	}
	finish_options(&o, sizes);
	status = loft_run_files(&run, argc - optind, argv + optind);
	for (size_t k = 0; k < o.files.n; k++)
		if (loft_outfile_write(&o.files.f[k], &err) != 0) {
			fprintf(stderr, "grade: %s\n", err.msg);
			status = 1;
		}
	loft_outfiles_free(&o.files);
	free(o.q);
	return status;
}
#endif
