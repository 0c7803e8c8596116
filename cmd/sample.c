/*
 * sample: evaluate each curve record at equal parameter steps, at equal
 * arc lengths (-s) or at as few points as keep within a tolerance (-t),
 * and write the points, optionally with parameter, unit tangent and
 * curvature; each surface record as a wireframe of iso-parameter lines;
 * or either as a Wavefront OBJ mesh.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"
#include "loftcad.h"

struct opts {
	long per;               /* points per segment */
	int param, tangent, curvature;
	int obj;                /* -f obj */
	int attrs;              /* -a: each record's header as a comment */
	struct loft_cad_doc *doc;       /* -f obj: the OBJ format's, made
	                                   at the first record */
	double spacing;         /* -s: arc length between points, or 0 */
	double tol;             /* -t: chordal tolerance, or 0 */
	double *u;              /* -s, -t: the parameters of a record */
	size_t ucap;
	size_t most;            /* -s, -t: points a record, at most */
	double *pts;            /* -f obj: a curve's points, 3 numbers each */
	size_t npts, ptscap;
};

/* -s and -t write at most this many points of a record (the fuzzing
 * harness sets fewer in opts). */
#define MAX_POINTS 10000000

/*
 * -t refuses a tolerance below this fraction of the curve's size: the
 * points would be millions a segment, and rounding of the size itself.
 */
#define MIN_TOL 1e-9

static const char usage_text[] =
    "usage: sample [-n per-segment | -s spacing | -t tolerance] "
    "[-p digits] [-a] [-u] [-d] [-k]\n"
    "              [-f points|obj] [file ...]\n";

/*
 * -a: the record's header, type and attributes, as a comment line
 * "# TYPE key=value ..." before what it gives: the rows of a point record
 * have no header, and so a graded set's size= would be lost.  loft's
 * reader, GNU graph, gnuplot and OBJ readers all skip it.
 */
static void
put_header_comment(struct loft_run *run, const struct loft_record *rec)
{
	static const char *const none[] = { NULL };
	const struct opts *o = run->ctx;

	if (!o->attrs)
		return;
	loft_put_type(&run->w, "# ");
	loft_put_type(&run->w, rec->type);
	loft_put_attrs_except(&run->w, rec, none);
	loft_end_line(&run->w);
}

/*
 * The end of what one input record gives as points: the blank line that
 * ends the last point record, and a second one, so that gnuplot sees
 * each input record as a data set of its own (plot 'file' index 2 picks
 * the third) and a surface's lines, one blank line apart, as one grid
 * (splot).  loft's reader and GNU graph take any number of blank lines
 * as one.
 */
static void
end_data_set(struct loft_run *run)
{
	loft_end_record(&run->w);
	loft_end_line(&run->w);
}

/*
 * -f obj: a record's object goes through the OBJ format of loftcad.h
 * (lib/obj.c, tocad -f obj's), its callbacks called here record by
 * record into run->w.  obj_begin starts the record's object.
 */
static int
obj_begin(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_cad_item it = { .rec = rec, .name = "" };
	struct loft_cad_opts co = { 0 };

	if (o->doc == NULL) {
		if ((o->doc = malloc(sizeof *o->doc)) == NULL)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		loft_cad_init(o->doc, loft_cad_format_named("obj"), &co);
	}
	loft_cad_attach(o->doc, &run->w);
	if (o->doc->f->begin_record(o->doc, &it) != 0) {
		loft_cad_detach(o->doc, &run->w);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	return 0;
}

/* The record's geometry written by f (its code rc), the object ends. */
static int
obj_end(struct loft_run *run, int rc, struct loft_error *err)
{
	struct opts *o = run->ctx;

	if (rc == 0)
		rc = o->doc->f->end_record(o->doc);
	loft_cad_detach(o->doc, &run->w);
	return rc == 0 ? 0 : loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
}

/* -f obj: keep the point p of a curve for its polyline. */
static int
obj_point(struct opts *o, const double *p, int dim, struct loft_error *err)
{
	if (o->npts == o->ptscap) {
		size_t cap = o->ptscap ? 2 * o->ptscap : 64;
		double *q = cap < o->ptscap ? NULL :
		    realloc(o->pts, 3 * cap * sizeof *q);

		if (q == NULL)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		o->pts = q;
		o->ptscap = cap;
	}
	for (int q = 0; q < 3; q++)
		o->pts[3 * o->npts + q] = q < dim ? p[q] : 0;
	o->npts++;
	return 0;
}

/* What the options hold: the parameters, the OBJ points and format. */
static void
opts_free(struct opts *o)
{
	free(o->u);
	free(o->pts);
	if (o->doc != NULL)
		loft_cad_free(o->doc);
	free(o->doc);
}

/* One output row: the point, then the columns the options ask for. */
static int
put_point(struct loft_run *run, const struct loft_curve *c, size_t i,
    double u, struct loft_error *err)
{
	struct opts *o = run->ctx;
	double p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], k;
	int dim = c->dim;

	loft_curve_eval(c, i, u, p, d1, d2);
	for (int q = 0; q < dim; q++)
		if (!isfinite(p[q]) || !isfinite(d1[q]) || !isfinite(d2[q]))
			return loft_fail(err, LOFT_EGEOM, (long)i, "segment %zu "
			    "overflows at u = %g: coefficients too large", i + 1,
			    u);
	if (o->obj)
		return obj_point(o, p, dim, err);
	for (int q = 0; q < dim; q++)
		loft_put_num(&run->w, p[q]);
	if (o->param)
		loft_put_num(&run->w, (double)i + u);
	if ((o->tangent || o->curvature) &&
	    loft_curvature(d1, d2, dim, &k) != 0)
		return loft_fail(err, LOFT_EGEOM, (long)i, "the tangent "
		    "vanishes in segment %zu at u = %g: no direction or "
		    "curvature there", i + 1, u);
	if (o->tangent) {
		double t[LOFT_MAXDIM];

		(void)loft_unit_tangent(d1, dim, t); /* d1 != 0: checked above */
		for (int q = 0; q < dim; q++)
			loft_put_num(&run->w, t[q]);
	}
	if (o->curvature)
		loft_put_num(&run->w, k);
	loft_end_line(&run->w);
	return 0;
}

/* Room for n parameters in o->u: 0, or LOFT_ENOMEM. */
static int
room(struct opts *o, size_t n, struct loft_error *err)
{
	double *u;

	if (n <= o->ucap)
		return 0;
	if ((u = realloc(o->u, n * sizeof *u)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	o->u = u;
	o->ucap = n;
	return 0;
}

/*
 * -s and -t: the parameters of the points, in o->u; their count in *n.
 */
static int
chosen_params(struct opts *o, const struct loft_curve *c, size_t *n,
    struct loft_error *err)
{
	double len, lo[LOFT_MAXDIM], hi[LOFT_MAXDIM], size = 0;

	if (o->spacing > 0) {
		len = loft_curve_length(c);
		*n = loft_spaced_count(len, o->spacing);
		if (!isfinite(len))
			return loft_fail(err, LOFT_EGEOM, -1, "the length "
			    "overflows: coefficients too large");
		if (*n > o->most)
			return loft_fail(err, LOFT_EINPUT, -1, "-s %g along a "
			    "curve of length %g: more than %zu points",
			    o->spacing, len, o->most);
		if (room(o, *n, err) != 0)
			return LOFT_ENOMEM;
		loft_curve_spaced(c, o->spacing, o->u, *n);
		return 0;
	}
	loft_curve_bbox(c, lo, hi);
	for (int k = 0; k < c->dim; k++)
		size = fmax(size, hi[k] - lo[k]);
	if (loft_tol_check(o->tol, size, MIN_TOL, err) != 0)  /* issue 28 */
		return LOFT_EINPUT;
	while ((*n = loft_curve_flatten(c, o->tol, o->u, o->ucap)) > o->ucap)
		if (*n > o->most)
			return loft_fail(err, LOFT_EINPUT, -1, "-t %g: more "
			    "than %zu points", o->tol, o->most);
		else if (room(o, *n, err) != 0)
			return LOFT_ENOMEM;
	return 0;
}

/* The points at parameters o->u[0..n), curve-wide (piece + local u). */
static int
put_params(struct loft_run *run, const struct loft_curve *c, size_t n,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;

	for (size_t j = 0; j < n; j++) {
		double f = floor(o->u[j]);
		size_t i = f >= (double)c->npieces ? c->npieces - 1 : (size_t)f;

		if (put_point(run, c, i, o->u[j] - (double)i, err) != 0)
			return LOFT_EGEOM;
	}
	return 0;
}

static int
sample_curve(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_curve c;
	size_t n = 0;
	int rc;

	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	if ((o->spacing > 0 || o->tol > 0) &&
	    (rc = chosen_params(o, &c, &n, err)) != 0)
		return rc;
	put_header_comment(run, rec);
	o->npts = 0;
	if (n > 0) {
		if (put_params(run, &c, n, err) != 0)
			return LOFT_EGEOM;
	} else {
		for (size_t i = 0; i < c.npieces; i++)
			for (long j = 0; j < o->per; j++)
				if (put_point(run, &c, i, (double)j / o->per,
				    err) != 0)
					return LOFT_EGEOM;
		/* the last segment's end: the first point again on a
		 * closed curve */
		if (put_point(run, &c, c.npieces - 1, 1, err) != 0)
			return LOFT_EGEOM;
		n = c.npieces * (size_t)o->per + 1;
	}
	if (!o->obj) {
		end_data_set(run);
		return 0;
	}
	if ((rc = obj_begin(run, rec, err)) != 0)
		return rc;
	return obj_end(run, o->doc->f->polyline(o->doc, o->pts, o->npts, 3,
	    0), err);
}

/* The point of s at (u, v), checked: 0, or LOFT_EGEOM on overflow. */
static int
surface_point(const struct loft_surface *s, double u, double v, double *p,
    struct loft_error *err)
{
	loft_surface_eval(s, u, v, p, NULL, NULL);
	for (int q = 0; q < s->dim; q++)
		if (!isfinite(p[q]))
			return loft_fail(err, LOFT_EGEOM, -1, "%s overflows at "
			    "u = %g, v = %g: coefficients too large", s->type,
			    u, v);
	return 0;
}

/*
 * A surface as a wireframe: the lines u = j/n, then v = j/n, j = 0..n,
 * each a point record of n + 1 points, with u and v after the point
 * under -u.
 */
static int
wireframe(struct loft_run *run, const struct loft_surface *s,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	double p[LOFT_MAXDIM];
	long n = o->per;

	for (int dir = 0; dir < 2; dir++)
		for (long j = 0; j <= n; j++) {
			for (long k = 0; k <= n; k++) {
				double a = (double)j / n, b = (double)k / n;
				double u = dir == 0 ? a : b, v = dir == 0 ? b : a;

				if (surface_point(s, u, v, p, err) != 0)
					return LOFT_EGEOM;
				for (int q = 0; q < s->dim; q++)
					loft_put_num(&run->w, p[q]);
				if (o->param) {
					loft_put_num(&run->w, u);
					loft_put_num(&run->w, v);
				}
				loft_end_line(&run->w);
			}
			if (dir == 1 && j == n)
				end_data_set(run);
			else
				loft_end_record(&run->w);
		}
	return 0;
}

/*
 * A surface as an OBJ mesh (mesh.c): (n + 1)^2 vertices, u-major, and
 * two triangles a cell, counter-clockwise in (u, v), so their normals
 * point along f_u x f_v; not welded.
 */
static int
mesh(struct loft_run *run, const struct loft_record *rec,
    const struct loft_surface *s, struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_mesh me;
	int rc = 0;

	memset(&me, 0, sizeof me);
	if (loft_mesh_surfaces(&me, s, 1, NULL, NULL, o->per, -1) != 0)
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < me.nv && rc == 0; i++)
		for (int q = 0; q < 3 && rc == 0; q++)
			if (!isfinite(me.v[3 * i + q]))
				rc = loft_fail(err, LOFT_EGEOM, -1, "%s overflows "
				    "at u = %g, v = %g: coefficients too large",
				    s->type, me.uv[2 * i], me.uv[2 * i + 1]);
	if (rc == 0 && (rc = obj_begin(run, rec, err)) == 0)
		rc = obj_end(run, o->doc->f->mesh(o->doc, me.v, me.nv, me.t,
		    me.nt), err);
	loft_mesh_free(&me);
	return rc;
}

static int
sample_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_surface s;

	if (!loft_is_surface(rec))
		return sample_curve(run, rec, err);
	if (loft_surface_from_record(rec, &s, err) != 0)
		return LOFT_EINPUT;
	if (o->spacing > 0 || o->tol > 0)
		return loft_fail(err, LOFT_EINPUT, -1, "-s and -t need a curve; "
		    "a %s record is a surface", rec->type);
	if (o->tangent || o->curvature)
		return loft_fail(err, LOFT_EINPUT, -1, "-d and -k need a curve; "
		    "a %s record has no tangent or curvature", rec->type);
	put_header_comment(run, rec);
	return o->obj ? mesh(run, rec, &s, err) : wireframe(run, &s, err);
}

/* An option's length: a number greater than 0. */
static int
positive(const char *s, double *x, struct loft_error *err)
{
	if (loft_parse_real(s, 0, DBL_MAX, x, err) != 0)
		return LOFT_EINPUT;
	if (*x == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "'%s': want a number "
		    "greater than 0", s);
	return 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	static const char *const formats[] = { "points", "obj", NULL };
	struct opts o = { 16, 0, 0, 0, 0, 0, NULL, 0, 0, NULL, 0, MAX_POINTS,
	    NULL, 0, 0 };
	struct loft_run run = { .prog = "sample", .out = stdout, .msg = stderr,
	    .handle = sample_record, .ctx = &o };
	struct loft_error err;
	int c, rc, ways = 0;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "n:s:t:p:audkf:h")) != -1) {
		switch (c) {
		case 'n':
			if (loft_parse_int(optarg, 1, 1000000, &o.per, &err))
				loft_usage_error(usage_text, c, err.msg);
			ways |= 1;
			break;
		case 's':
			if (positive(optarg, &o.spacing, &err))
				loft_usage_error(usage_text, c, err.msg);
			ways |= 2;
			break;
		case 't':
			if (positive(optarg, &o.tol, &err))
				loft_usage_error(usage_text, c, err.msg);
			ways |= 4;
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'a': o.attrs = 1; break;
		case 'u': o.param = 1; break;
		case 'd': o.tangent = 1; break;
		case 'k': o.curvature = 1; break;
		case 'f':
			if (loft_parse_word(optarg, formats, &o.obj, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (o.obj && (o.param || o.tangent || o.curvature))
		loft_usage_error(usage_text, 0, "-u, -d and -k add columns "
		    "to points; -f obj has none");
	if (ways != 0 && (ways & (ways - 1)) != 0)
		loft_usage_error(usage_text, 0, "-n, -s and -t are three "
		    "ways of choosing the points: give one");
	rc = loft_run_files(&run, argc - optind, argv + optind);
	opts_free(&o);
	return rc;
}
#endif
