/*
 * loftplot: draw every record of the input as one SVG picture: curves as
 * paths (exact cubic Bezier segments for cubic records, sampled
 * polylines for other curve types), surfaces as wireframes of
 * iso-parameter lines, point records as polylines, knots as markers,
 * and on request curvature combs, end tangents and Bezier control
 * polygons.
 *
 * loftplot reads all its input before it writes: the picture's frame depends
 * on every record.  Bad records are reported and left out; the picture
 * of the good ones is written whole, and loftplot exits 1.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftcad.h"
#include "internal.h"       /* vnorm: a comb of any units (issue 28) */
#include "wasm/page.h"

/* The picture's larger side, in pixels (the width and height written). */
#define PICTURE_PX 640
/* Sizes in pixels of that picture, so that they do not depend on the
 * drawing's units: thin strokes (curves are LOFT_PLOT_CURVE_PX, labels
 * LOFT_PLOT_FONT_PX high, markers as svgplot.c draws them). */
#define THIN_PX 0.6
/* -t tangents: dashed, so heavier than the thin lines to be seen. */
#define TANGENT_PX 1.1
/* An estimate of a label's advance per character, as a fraction of the
 * font size, generous for digits and signs in a sans-serif face. */
#define CHAR_EM 0.62
/* A curve of another type than cubic is drawn as a polyline within this
 * many pixels of it: a quarter pixel, below what antialiasing shows. */
#define FLAT_PX 0.25
/* ...with at most this many points: far more than a picture of 640
 * pixels can show, so only a pathological record reaches it. */
#define MAX_FLAT 4000000
/* The margin around the drawing, a fraction of its larger side. */
#define MARGIN 0.04
/* Without -C, the longest comb tooth is this fraction of the larger side
 * of the curves' extent: long enough to read, short enough not to hide
 * the drawing. */
#define COMB_LENGTH 0.15
/* With a -C of the user's, no tooth is longer than this fraction of the
 * larger side of the curves' extent (longer teeth are cut to it): a
 * sharp corner must not shrink the curve to a speck in a frame the comb
 * fills. */
#define COMB_CAP 0.5

/* Kinds of stroke, in the order they are drawn (later on top). */
enum kind {
	K_COMB,         /* pairs: base point, projected curvature vector */
	K_MESH,         /* a surface's inner iso-parameter line, thin */
	K_LINE,         /* a polyline */
	K_BEZIER,       /* four control points per cubic piece */
	K_HANDLE,       /* pairs: end of a piece, end of its tangent / 3 */
	K_NET,          /* a line of a Bezier control polygon or net (-b) */
	K_MARKS,        /* knot markers of a point record (-m) */
	K_CONTROL,      /* Bezier control point markers (-b) */
	K_KNOTS,        /* knot markers from -K */
	NKIND
};

enum view { V_XY, V_YZ, V_XZ, V_ISO };

struct stroke {
	enum kind kind;
	int rec;                /* record number, from 0; -1 for -K knots */
	int closed;             /* close the path (Z) where it ends at its start */
	size_t first, n;        /* its points in pic.pt */
};

/* A label tries these many points of its record's curve. */
#define NANCHOR LOFT_LABEL_ANCHORS

/* A label: where it goes (labels.c), what it says.  One on its curve
 * (p.oncurve) stands on a ground of the background's colour. */
struct label {
	struct loft_label p;
	int numbered;           /* the text is the record's number */
	char *text;
};

/* A box in the plane: lo[0..1], hi[0..1]; empty while lo > hi. */
struct box {
	double lo[2], hi[2];
};

/* A record drawn: its extent, and where it came from. */
struct drawn {
	struct box box;
	double kmax;            /* its comb's largest curvature */
	const char *file;
	long line;
	char colour[8];         /* its colour=rrggbb as #rrggbb (unroll -m), */
	                        /* or "" */
};

struct pic {
	/* options */
	enum view view;
	long steps;             /* samples per piece for polylines and combs */
	int steps_set;          /* -n given: a surface's lines take it too */
	long grid;              /* a surface's parameter intervals each way */
	int comb, handles, marks, control;
	double comb_scale;      /* 0: automatic */
	double comb_div;        /* teeth are scale * curvature / comb_div */
	double comb_cap;        /* the longest tooth, in the drawing's units */
	const char *background; /* -B, or NULL */
	const char *label_key;
	struct loft_page *page; /* -i: the records the page holds, or NULL */
	/* the picture */
	double *pt;             /* projected points, 2 numbers each */
	size_t npt, ptcap;
	struct stroke *st;
	size_t nst, stcap;
	struct label *lb;
	size_t nlb, lbcap;
	struct box box;         /* of the curves, points and knots */
	struct box kbox;        /* of the knots of -K */
	double kmax;            /* largest curvature of any comb tooth */
	int nrec;               /* records drawn */
	int dim;                /* the first record's dimension; 0: none yet */
	struct drawn *rec;      /* each of them */
	size_t reccap;
	int failed;             /* out of memory */
};

static const char usage_text[] =
    "usage: loftplot [-bcimt] [-B colour] [-C scale] [-g lines] [-K file] "
    "[-l key]\n            [-n steps] [-v xy|yz|xz|iso] [file ...]\n";

/* Colours of records 0, 1, ... in turn; the -K knots are black. */
static const char *const colours[] = {
	"#1f4e9c", "#c0392b", "#2e7d32", "#7b3fa0", "#d35400", "#00838f",
	"#6d4c41", "#ad1457",
};
#define NCOLOURS (sizeof colours / sizeof colours[0])

/* ------------------------------------------------------------------ */
/* Collecting the picture */

static void
box_empty(struct box *b)
{
	b->lo[0] = b->lo[1] = HUGE_VAL;
	b->hi[0] = b->hi[1] = -HUGE_VAL;
}

static void
box_add(struct box *b, const double *q)
{
	for (int k = 0; k < 2; k++) {
		if (q[k] < b->lo[k])
			b->lo[k] = q[k];
		if (q[k] > b->hi[k])
			b->hi[k] = q[k];
	}
}

static void
box_join(struct box *b, const struct box *c)
{
	if (c->lo[0] <= c->hi[0]) {
		box_add(b, c->lo);
		box_add(b, c->hi);
	}
}

/*
 * The view -v: a linear map of a point or vector of dim coordinates to
 * the plane (so it maps cubic pieces to cubic pieces).  iso is the
 * orthographic view from the direction (1, 1, 1): z up, x to the lower
 * left, y to the lower right.  Coordinates beyond dim are 0 (a
 * record's are 2 or 3; p[k] for k >= dim is not read).
 */
static void
project(enum view v, const double *p, int dim, double *q)
{
	double x = dim > 0 ? p[0] : 0, y = dim > 1 ? p[1] : 0,
	    z = dim > 2 ? p[2] : 0;

	switch (v) {
	default: q[0] = x; q[1] = y; break;     /* V_XY */
	case V_YZ: q[0] = y; q[1] = z; break;
	case V_XZ: q[0] = x; q[1] = z; break;
	case V_ISO:
		q[0] = (y - x) / sqrt(2);
		q[1] = (2 * z - x - y) / sqrt(6);
		break;
	}
}

/* Start a stroke of kind for the current record; NULL: out of memory. */
static struct stroke *
new_stroke(struct pic *pc, enum kind kind, int rec)
{
	struct stroke *s;

	if (loft_grow((void **)&pc->st, &pc->stcap, pc->nst + 1, sizeof *pc->st))
		return NULL;
	s = &pc->st[pc->nst++];
	s->kind = kind;
	s->rec = rec;
	s->closed = 0;
	s->first = pc->npt;
	s->n = 0;
	return s;
}

/* Append a plane point to stroke s (the last one started). */
static int
add_point(struct pic *pc, struct stroke *s, const double *q,
    struct loft_error *err)
{
	if (!isfinite(q[0]) || !isfinite(q[1]))
		return loft_fail(err, LOFT_EGEOM, -1, "coordinates too large "
		    "to draw");
	if (loft_grow((void **)&pc->pt, &pc->ptcap, pc->npt + 1, 2 * sizeof *pc->pt))
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	pc->pt[2 * pc->npt] = q[0];
	pc->pt[2 * pc->npt + 1] = q[1];
	pc->npt++;
	s->n++;
	return 0;
}

/* What one record adds beside its strokes: its extent, and the point
 * furthest right, where its label goes. */
struct extent {
	struct box box;
	double right[2];
};

/* No point seen yet. */
static void
extent_empty(struct extent *e)
{
	box_empty(&e->box);
	e->right[0] = -HUGE_VAL;
	e->right[1] = 0;
}

static void
see(struct extent *e, const double *q)
{
	if (e->box.lo[0] > e->box.hi[0] || q[0] > e->right[0]) {
		e->right[0] = q[0];
		e->right[1] = q[1];
	}
	box_add(&e->box, q);
}

/* Add the point p (dim coordinates) to stroke s, projected, and see it. */
static int
add_seen(struct pic *pc, struct stroke *s, struct extent *e, const double *p,
    int dim, struct loft_error *err)
{
	double q[2];

	project(pc->view, p, dim, q);
	if (add_point(pc, s, q, err) != 0)
		return -1;
	see(e, q);
	return 0;
}

/* Knot markers at the rows of a point record. */
static int
add_marks(struct pic *pc, const struct loft_record *rec, enum kind kind,
    int recno, struct extent *e, struct loft_error *err)
{
	struct stroke *s = new_stroke(pc, kind, recno);

	if (s == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < rec->nrows; i++)
		if (add_seen(pc, s, e, rec->num + i * rec->ncols, rec->ncols,
		    err) != 0)
			return (err->row = i), -1;
	return 0;
}

static int
check_points(const struct loft_record *rec, struct loft_error *err)
{
	if (rec->nrows == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "record has no points");
	if (rec->ncols < 2 || rec->ncols > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, 0, "points have %d number%s; "
		    "loftplot reads 2 or 3 coordinates (no extra columns)",
		    rec->ncols, rec->ncols == 1 ? "" : "s");
	return 0;
}

/* A point record's closed=1 (loft(5)): its outline is closed. */
static int
closed_points(const struct loft_record *rec)
{
	const char *v = loft_attr(rec, "closed");

	return v != NULL && strcmp(v, "1") == 0 && rec->nrows > 2;
}

/* A point record: a polyline through its rows, closed where the record
 * says closed=1, and markers with -m. */
static int
draw_points(struct pic *pc, const struct loft_record *rec, struct extent *e,
    struct loft_error *err)
{
	struct stroke *s;

	if (check_points(rec, err) != 0)
		return -1;
	if ((s = new_stroke(pc, K_LINE, pc->nrec)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < rec->nrows; i++)
		if (add_seen(pc, s, e, rec->num + i * rec->ncols, rec->ncols,
		    err) != 0)
			return (err->row = i), -1;
	if (closed_points(rec)) {       /* back to the first point, and Z */
		s->closed = 1;
		if (memcmp(rec->num, rec->num + (rec->nrows - 1) * rec->ncols,
		    rec->ncols * sizeof *rec->num) != 0 && add_seen(pc, s, e,
		    rec->num, rec->ncols, err) != 0)
			return -1;
	}
	return pc->marks ? add_marks(pc, rec, K_MARKS, pc->nrec, e, err) : 0;
}

/*
 * The extremes of one coordinate of a cubic Bezier piece with control
 * values b[0..3] (stride 2 in a plane point array): the roots in (0, 1)
 * of its derivative, the quadratic 3(a t^2 + 2 b t + c) with
 * a = b3 - 3b2 + 3b1 - b0, b = b2 - 2b1 + b0, c = b1 - b0.  Stores the
 * roots in t, returns their count.
 */
static int
extreme_params(const double *cp, int k, double *t)
{
	double b0 = cp[k], b1 = cp[2 + k], b2 = cp[4 + k], b3 = cp[6 + k];
	double a = b3 - 3 * b2 + 3 * b1 - b0, b = b2 - 2 * b1 + b0, c = b1 - b0;
	double r[2], disc, big = fmax(fabs(a), fmax(fabs(b), fabs(c)));
	int n = 0, m = 0;

	/* the roots are those of the coefficients over a power of two near
	 * their largest (exact): b * b - a * c neither overflows for a
	 * drawing of 1e160 nor underflows for one of 1e-160 (issue 28) */
	if (big > 0 && isfinite(big)) {
		int e = ilogb(big);

		a = ldexp(a, -e);
		b = ldexp(b, -e);
		c = ldexp(c, -e);
	}
	if (a == 0) {
		if (b != 0)
			r[n++] = -c / (2 * b);
	} else if ((disc = b * b - a * c) >= 0) {
		/* the stable form of the two roots */
		double q = -(b + copysign(sqrt(disc), b));

		r[n++] = q / a;
		if (q != 0)
			r[n++] = c / q;
	}
	for (int i = 0; i < n; i++)
		if (r[i] > 0 && r[i] < 1)
			t[m++] = r[i];
	return m;
}

/* The point at t of the cubic Bezier piece cp (4 plane points). */
static void
bezier_at(const double *cp, double t, double *q)
{
	double s = 1 - t;

	for (int k = 0; k < 2; k++)
		q[k] = s * s * s * cp[k] + 3 * s * s * t * cp[2 + k] +
		    3 * s * t * t * cp[4 + k] + t * t * t * cp[6 + k];
}

/* See the whole of the Bezier piece cp (4 plane points): its ends and
 * its extremes in x and y, so the frame fits the curve, not its control
 * polygon. */
static void
see_bezier(struct extent *e, const double *cp)
{
	double t[2], q[2];

	see(e, cp);
	see(e, cp + 6);
	for (int k = 0; k < 2; k++) {
		int n = extreme_params(cp, k, t);

		for (int i = 0; i < n; i++) {
			double s = 1 - t[i];

			for (int j = 0; j < 2; j++)
				q[j] = s * s * s * cp[j] +
				    3 * s * s * t[i] * cp[2 + j] +
				    3 * s * t[i] * t[i] * cp[4 + j] +
				    t[i] * t[i] * t[i] * cp[6 + j];
			see(e, q);
		}
	}
}

/*
 * A cubic piece as a Bezier segment, exactly: with P and P' its point
 * and u-derivative at the ends, the control points are
 *   B0 = P(0), B1 = P(0) + P'(0)/3, B2 = P(1) - P'(1)/3, B3 = P(1)
 * (the Bernstein form of eq. 7 of Manning's paper).  The view is linear,
 * so the projected control points are those of the projected piece.
 */
static int
add_bezier_piece(struct pic *pc, struct stroke *s, struct extent *e,
    const struct loft_curve *c, size_t i, struct loft_error *err)
{
	double p0[LOFT_MAXDIM], d0[LOFT_MAXDIM], p1[LOFT_MAXDIM],
	    d1[LOFT_MAXDIM], b[4][LOFT_MAXDIM];

	loft_curve_eval(c, i, 0, p0, d0, NULL);
	loft_curve_eval(c, i, 1, p1, d1, NULL);
	for (int k = 0; k < c->dim; k++) {
		b[0][k] = p0[k];
		b[1][k] = p0[k] + d0[k] / 3;
		b[2][k] = p1[k] - d1[k] / 3;
		b[3][k] = p1[k];
	}
	for (int j = 0; j < 4; j++) {
		double q[2];

		project(pc->view, b[j], c->dim, q);
		if (add_point(pc, s, q, err) != 0)
			return (err->row = i), -1;
	}
	see_bezier(e, pc->pt + 2 * (pc->npt - 4));
	return 0;
}

/* Evaluate piece i at u into p, d1, d2; an error where it overflows. */
static int
eval_finite(const struct loft_curve *c, size_t i, double u, double *p,
    double *d1, double *d2, struct loft_error *err)
{
	loft_curve_eval(c, i, u, p, d1, d2);
	for (int k = 0; k < c->dim; k++)
		if (!isfinite(p[k]) || !isfinite(d1[k]) || !isfinite(d2[k]))
			return loft_fail(err, LOFT_EGEOM, (long)i, "segment %zu "
			    "overflows at u = %g: coefficients too large",
			    i + 1, u);
	return 0;
}

/*
 * Curves of other types: a polyline through the fewest points that keep
 * it within FLAT_PX pixels of the curve (loft_curve_flatten).  The
 * tolerance is taken from the record's own projected extent, which is at
 * most the picture's, so it is at most FLAT_PX of the picture's pixels
 * however the record is framed.  The views are orthogonal projections,
 * which shorten no distance less than the curve's own 3-D distance, so a
 * polyline within tol in space is within tol on the page.
 */
static int
add_flattened(struct pic *pc, struct stroke *s, struct extent *e,
    const struct loft_curve *c, struct loft_error *err)
{
	double ctl[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM], p[LOFT_MAXDIM],
	    d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], q[2], tol, size = 0, *u;
	struct box b;
	size_t n;

	box_empty(&b);
	for (size_t i = 0; i < c->npieces; i++) {
		int deg = loft_curve_bezier(c, i, ctl);

		for (int j = 0; j <= deg; j++) {
			project(pc->view, ctl + j * c->dim, c->dim, q);
			box_add(&b, q);
		}
	}
	size = fmax(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
	if (!isfinite(size))
		return loft_fail(err, LOFT_EGEOM, -1, "coordinates too large "
		    "to draw");
	/* a curve seen end on: any tolerance draws its one point */
	tol = size > 0 ? FLAT_PX * size / PICTURE_PX : 1;
	n = loft_curve_flatten(c, tol, NULL, 0);
	if (n > MAX_FLAT)
		return loft_fail(err, LOFT_EGEOM, -1, "curve needs %zu points "
		    "to draw smooth (more than %d): too wiggly", n, MAX_FLAT);
	if ((u = malloc(n * sizeof *u)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	loft_curve_flatten(c, tol, u, n);
	for (size_t j = 0; j < n; j++) {
		size_t i = u[j] >= (double)c->npieces ? c->npieces - 1 :
		    (size_t)u[j];

		if (eval_finite(c, i, u[j] - (double)i, p, d1, d2, err) != 0 ||
		    add_seen(pc, s, e, p, c->dim, err) != 0) {
			free(u);
			return (err->row = (long)i), -1;
		}
	}
	free(u);
	return 0;
}

/*
 * The comb: at steps + 1 points of every piece, both ends included, so
 * that a jump of curvature at a join shows as two teeth, the point and
 * its curvature vector d2P/ds2 (eq. 2 of Manning's paper), projected.
 * The teeth are drawn later, when the scale is known.
 */
static int
add_comb(struct pic *pc, const struct loft_curve *c, struct loft_error *err)
{
	double p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM],
	    kn[LOFT_MAXDIM], q[2], len;
	struct stroke *s = new_stroke(pc, K_COMB, pc->nrec);

	if (s == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < c->npieces; i++)
		for (long j = 0; j <= pc->steps; j++) {
			double u = (double)j / pc->steps;

			if (eval_finite(c, i, u, p, d1, d2, err) != 0)
				return -1;
			if (loft_curvature_vector(d1, d2, c->dim, kn) != 0)
				return loft_fail(err, LOFT_EGEOM, (long)i, "the "
				    "tangent vanishes in segment %zu at u = %g: "
				    "no curvature for the comb", i + 1, u);
			len = vnorm(kn, c->dim);
			if (!isfinite(len))
				return loft_fail(err, LOFT_EGEOM, (long)i,
				    "curvature too large to draw in segment %zu",
				    i + 1);
			if (len > pc->kmax)
				pc->kmax = len;
			project(pc->view, p, c->dim, q);
			if (add_point(pc, s, q, err) != 0)
				return -1;
			project(pc->view, kn, c->dim, q);
			if (add_point(pc, s, q, err) != 0)
				return -1;
		}
	return 0;
}

/* -t: each piece's end tangents, a third of dP/du long (for a cubic
 * piece, the legs of its Bezier control polygon). */
static int
add_handles(struct pic *pc, const struct loft_curve *c, struct extent *e,
    struct loft_error *err)
{
	double p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM],
	    tip[LOFT_MAXDIM];
	struct stroke *s = new_stroke(pc, K_HANDLE, pc->nrec);

	if (s == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < c->npieces; i++)
		for (int end = 0; end < 2; end++) {
			if (eval_finite(c, i, end, p, d1, d2, err) != 0)
				return -1;
			for (int k = 0; k < c->dim; k++)
				tip[k] = p[k] + (end ? -d1[k] : d1[k]) / 3;
			if (add_seen(pc, s, e, p, c->dim, err) != 0 ||
			    add_seen(pc, s, e, tip, c->dim, err) != 0)
				return (err->row = i), -1;
		}
	return 0;
}

/*
 * A curve record of any type lib/curve.c knows: exact Bezier segments
 * for cubic records, a polyline within FLAT_PX of the curve for the
 * others.
 */
static int
draw_curve(struct pic *pc, const struct loft_curve *c, struct extent *e,
    struct loft_error *err)
{
	int exact = loft_type_named(c->type)->degree == 3;
	struct stroke *s = new_stroke(pc, exact ? K_BEZIER : K_LINE, pc->nrec);

	if (s == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	s->closed = c->closed;
	if (!exact && add_flattened(pc, s, e, c, err) != 0)
		return -1;
	for (size_t i = 0; exact && i < c->npieces; i++)
		if (add_bezier_piece(pc, s, e, c, i, err) != 0)
			return -1;
	if (pc->comb && add_comb(pc, c, err) != 0)
		return -1;
	if (pc->handles && add_handles(pc, c, e, err) != 0)
		return -1;
	return 0;
}

/*
 * Without -n, each line of a wireframe gets as many equal steps as keep
 * its chords within FLAT_PX pixels of it.  A chord over a parameter
 * step h lies within h^2/8 max|c''| of its arc, c'' the line's second
 * derivative (x_vv along a line u = const, x_uu along v = const; the
 * view shortens it, never lengthens it).  max|c''| is taken at
 * LINE_PROBES + 1 points along the line and widened by LINE_MARGIN for
 * what lies between them: the lines are polynomials of low degree (4
 * for a patch), so c'' varies slowly between probes.  The tolerance is
 * FLAT_PX of the surface's own extent at those probes (at most the
 * picture's).
 */
#define LINE_PROBES 64
#define LINE_MARGIN 1.5
/* ...and no line takes more steps than this (a 640-pixel picture
 * shows none of them). */
#define MAX_LINE_STEPS 20000

/* The point of sf at parameter t along line a of direction dir (u = a
 * for dir 0, v = a for dir 1), in uv; its second derivative along the
 * line in d2 if not NULL. */
static void
line_point(const struct loft_surface *sf, int dir, double a, double t,
    double *p, double *d2)
{
	double duu[LOFT_MAXDIM], dvv[LOFT_MAXDIM], u = dir ? t : a,
	    v = dir ? a : t;

	if (d2 == NULL) {
		loft_surface_eval(sf, u, v, p, NULL, NULL);
		return;
	}
	loft_surface_eval2(sf, u, v, p, NULL, NULL, duu, dvv);
	memcpy(d2, dir ? duu : dvv, (size_t)sf->dim * sizeof *d2);
}

/* The steps line a of direction dir takes (see above) for the
 * tolerance tol. */
static long
line_steps(const struct pic *pc, const struct loft_surface *sf, int dir,
    double a, double tol)
{
	double p[LOFT_MAXDIM], d2[LOFT_MAXDIM], most = 0, n;

	if (pc->steps_set)
		return pc->steps;
	for (int k = 0; k <= LINE_PROBES; k++) {
		line_point(sf, dir, a, (double)k / LINE_PROBES, p, d2);
		most = fmax(most, vnorm(d2, sf->dim));  /* of any units */
	}
	n = ceil(sqrt(LINE_MARGIN * (most / tol) / 8));
	return !(n < MAX_LINE_STEPS) ? MAX_LINE_STEPS : n < 1 ? 1 : (long)n;
}

/* FLAT_PX of the extent of sf's lines in the view, seen at the probes;
 * 1 for a surface seen as a point. */
static double
lines_tolerance(const struct pic *pc, const struct loft_surface *sf)
{
	double p[LOFT_MAXDIM], q[2], size;
	struct box b;

	box_empty(&b);
	for (int dir = 0; dir < 2; dir++)
		for (long j = 0; j <= pc->grid; j++)
			for (int k = 0; k <= LINE_PROBES; k++) {
				line_point(sf, dir, (double)j / pc->grid,
				    (double)k / LINE_PROBES, p, NULL);
				project(pc->view, p, sf->dim, q);
				box_add(&b, q);
			}
	size = fmax(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
	return size > 0 ? FLAT_PX * size / PICTURE_PX : 1;
}

/*
 * A surface record as a wireframe: the iso-parameter lines u = j/g, then
 * v = j/g, for j = 0..g (g of -g), each a polyline through steps + 1
 * points at equal steps of the other parameter: with -n, steps is its
 * value, and with g = steps these are the points sample -n steps
 * writes; without, as many as the line's bending needs (line_steps).
 * The lines on the four edges are drawn as curves, those inside thin,
 * so that in a design the patch boundaries stand out, as in MacCallum's
 * Fig. 4.
 */
static int
draw_surface(struct pic *pc, const struct loft_surface *sf, struct extent *e,
    struct loft_error *err)
{
	double p[LOFT_MAXDIM], uv[2], tol = pc->steps_set ? 0 :
	    lines_tolerance(pc, sf);

	if (!isfinite(tol))
		return loft_fail(err, LOFT_EGEOM, -1, "coordinates too large "
		    "to draw");
	for (int dir = 0; dir < 2; dir++)
		for (long j = 0; j <= pc->grid; j++) {
			int edge = j == 0 || j == pc->grid;
			struct stroke *s = new_stroke(pc, edge ? K_LINE : K_MESH,
			    pc->nrec);
			long steps;

			if (s == NULL)
				return loft_fail(err, LOFT_ENOMEM, -1,
				    "out of memory");
			uv[dir] = (double)j / pc->grid;
			steps = line_steps(pc, sf, dir, uv[dir], tol);
			for (long k = 0; k <= steps; k++) {
				uv[1 - dir] = (double)k / steps;
				loft_surface_eval(sf, uv[0], uv[1], p, NULL, NULL);
				if (add_seen(pc, s, e, p, sf->dim, err) != 0)
					return -1;
			}
		}
	return 0;
}

/*
 * -b: the control points of a record, nu rows of nv points, u-major (a
 * bezier record is one row, a bezier-surface m + 1 rows of n + 1): the
 * lines through them along each direction, its control polygon or net,
 * and a marker at each.  They lie off the curve, so they widen the
 * frame.
 */
static int
add_control(struct pic *pc, const struct loft_record *rec, size_t nu,
    size_t nv, struct extent *e, struct loft_error *err)
{
	for (int dir = 0; dir < 2; dir++) {
		size_t nlines = dir ? nv : nu, npts = dir ? nu : nv;

		for (size_t l = 0; npts > 1 && l < nlines; l++) {
			struct stroke *s = new_stroke(pc, K_NET, pc->nrec);

			if (s == NULL)
				return loft_fail(err, LOFT_ENOMEM, -1,
				    "out of memory");
			for (size_t k = 0; k < npts; k++) {
				size_t row = dir ? k * nv + l : l * nv + k;

				if (add_seen(pc, s, e, rec->num +
				    row * rec->ncols, rec->ncols, err) != 0)
					return (err->row = (long)row), -1;
			}
		}
	}
	return add_marks(pc, rec, K_CONTROL, pc->nrec, e, err);
}

/* Points of stroke s spread along it, for a label to stand by:
 * NANCHOR - 1 of them at even steps of its parameter (of its cubic
 * pieces) or of its points. */
static void
label_anchors(const struct pic *pc, const struct stroke *s, struct label *l)
{
	const double *p = pc->pt + 2 * s->first;
	size_t n = s->kind == K_BEZIER ? s->n / 4 : s->n;

	for (int k = 0; n > 0 && k < NANCHOR - 1; k++) {
		double t = ((double)k + 0.5) * (double)n / (NANCHOR - 1);
		size_t i = (size_t)t < n ? (size_t)t : n - 1;
		double *q = l->p.anc[l->p.nanc++];

		if (s->kind == K_BEZIER) {
			bezier_at(p + 8 * i, t - (double)i, q);
		} else {
			q[0] = p[2 * i];
			q[1] = p[2 * i + 1];
		}
	}
}

static int
add_label(struct pic *pc, const struct loft_record *rec,
    const struct extent *e, const double *centre, size_t nst,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, pc->label_key);
	char num[24];
	struct label *l;

	if (v == NULL) {
		snprintf(num, sizeof num, "%d", pc->nrec + 1);
		v = num;
	}
	if (loft_grow((void **)&pc->lb, &pc->lbcap, pc->nlb + 1, sizeof *pc->lb) ||
	    (pc->lb[pc->nlb].text = strdup(v)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	l = &pc->lb[pc->nlb++];
	memset(&l->p, 0, sizeof l->p);
	l->p.rec = pc->nrec;
	l->numbered = v == num;
	l->p.centred = centre != NULL;
	l->p.at[0] = l->p.anchor[0] = centre ? centre[0] : e->right[0];
	l->p.at[1] = l->p.anchor[1] = centre ? centre[1] : e->right[1];
	l->p.anc[0][0] = l->p.anchor[0];
	l->p.anc[0][1] = l->p.anchor[1];
	l->p.nanc = 1;
	if (!l->p.centred && nst < pc->nst)
		label_anchors(pc, &pc->st[nst], l);
	return 0;
}

/*
 * Rows of sample -k, -d, -s or -t of a plane curve have 3 or more
 * numbers, and drawn with plane curves they would be taken for 3-D
 * points without a word: a point record (points true) of more
 * coordinates than the picture's first good record is refused.  Plane
 * curves and surfaces may still be drawn with space ones (at z = 0).
 */
static int
check_dim(struct pic *pc, int dim, int points, struct loft_error *err)
{
	if (pc->dim == 0)
		pc->dim = dim;
	else if (points && dim > pc->dim)
		return loft_fail(err, LOFT_EINPUT, -1, "%d coordinates, where "
		    "the first record has %d: rows of sample -k, -d, -s or -t? "
		    "loftplot draws coordinates alone", dim, pc->dim);
	return 0;
}

/*
 * The handler: add what rec draws to the picture.  A record that fails
 * takes back everything it added, so the picture holds good records
 * only.
 */
static int
keep_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct pic *pc = run->ctx;
	size_t npt = pc->npt, nst = pc->nst, nlb = pc->nlb;
	double kmax = pc->kmax;
	struct loft_curve c;
	struct loft_surface sf;
	struct extent e;
	double mid[LOFT_MAXDIM], centre[2];
	int rc, surface = 0, dim = pc->dim;
	const char *c0;

	extent_empty(&e);
	pc->kmax = 0;           /* this record's own, for pc->rec */
	if (loft_record_is(rec, LOFT_KIND_KNOTS)) {
		if ((rc = draw_points(pc, rec, &e, err)) == 0)
			rc = check_dim(pc, rec->ncols, 1, err);
	} else if (loft_is_surface(rec)) {
		if ((rc = loft_surface_from_record(rec, &sf, err)) == 0 &&
		    (rc = check_dim(pc, sf.dim, 0, err)) == 0)
			rc = draw_surface(pc, &sf, &e, err);
		/* a patch's label (its id) at its middle, f(1/2, 1/2): a
		 * corner is shared by up to four patches */
		if (rc == 0) {
			loft_surface_eval(&sf, 0.5, 0.5, mid, NULL, NULL);
			project(pc->view, mid, sf.dim, centre);
			surface = 1;
		}
		if (rc == 0 && pc->control &&
		    loft_record_is(rec, LOFT_KIND_CONTROL))
			rc = add_control(pc, rec, (size_t)sf.m + 1,
			    (size_t)sf.n + 1, &e, err);
	} else if ((rc = loft_curve_from_record(rec, &c, err)) == 0 &&
	    (rc = check_dim(pc, c.dim, 0, err)) == 0) {
		rc = draw_curve(pc, &c, &e, err);
		if (rc == 0 && pc->control &&
		    loft_record_is(rec, LOFT_KIND_CONTROL))
			rc = add_control(pc, rec, 1, rec->nrows, &e, err);
	}
	if (rc == 0 && pc->label_key != NULL)
		rc = add_label(pc, rec, &e, surface ? centre : NULL, nst, err);
	if (rc == 0 && loft_grow((void **)&pc->rec, &pc->reccap,
	    (size_t)pc->nrec + 1, sizeof *pc->rec) != 0)
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (rc != 0) {
		pc->dim = dim;
		pc->npt = npt;
		pc->nst = nst;
		while (pc->nlb > nlb)
			free(pc->lb[--pc->nlb].text);
		pc->kmax = kmax;
		return LOFT_EINPUT;
	}
	box_join(&pc->box, &e.box);
	if (pc->page != NULL)
		loft_put_record(loft_record_is(rec, LOFT_KIND_KNOTS) ?
		    &pc->page->points : surface ? &pc->page->design :
		    &pc->page->curves, rec);
	pc->rec[pc->nrec] = (struct drawn){ e.box, pc->kmax, rec->file,
	    rec->line, "" };
	if ((c0 = loft_attr(rec, "colour")) != NULL && strlen(c0) == 6 &&
	    strspn(c0, "0123456789abcdefABCDEF") == 6)
		snprintf(pc->rec[pc->nrec].colour, 8, "#%s", c0);
	pc->kmax = fmax(kmax, pc->kmax);
	pc->nrec++;
	return 0;
}

/* The handler for -K: knot markers from point records. */
static int
keep_knots(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct pic *pc = run->ctx;
	size_t npt = pc->npt, nst = pc->nst;
	struct extent e;

	extent_empty(&e);
	if (!loft_record_is(rec, LOFT_KIND_KNOTS))
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: -K reads "
		    "knots (point records)", rec->type);
	if (check_points(rec, err) != 0 ||
	    check_dim(pc, rec->ncols, 1, err) != 0 ||
	    add_marks(pc, rec, K_KNOTS, -1, &e, err) != 0) {
		pc->npt = npt;
		pc->nst = nst;
		return LOFT_EINPUT;
	}
	box_join(&pc->box, &e.box);
	box_join(&pc->kbox, &e.box);
	if (pc->page != NULL)
		loft_put_record(&pc->page->knots, rec);
	return 0;
}

/* ------------------------------------------------------------------ */
/* Writing the picture */

static const struct drawn *drawn_colour;      /* the records' own */

static const char *
colour(int rec)
{
	if (rec >= 0 && drawn_colour != NULL && drawn_colour[rec].colour[0])
		return drawn_colour[rec].colour;
	return rec < 0 ? "#000" : colours[rec % NCOLOURS];
}

/* The comb tooth of point pair j of s: from the curve, away from the
 * centre of curvature, scale times the curvature long. */
static void
tooth_tip(const struct pic *pc, const struct stroke *s, size_t j,
    double scale, double *tip)
{
	const double *base = pc->pt + 2 * (s->first + 2 * j), *kn = base + 2;
	/* kn / comb_div first: an automatic scale of a drawing of 1e160 or
	 * 1e-160 units would overflow, the curvatures relative to the
	 * largest do not */
	double k[2] = { kn[0] / pc->comb_div, kn[1] / pc->comb_div };
	double len = hypot(k[0], k[1]);

	if (scale * len > pc->comb_cap)         /* cut to the cap */
		scale = pc->comb_cap / len;
	tip[0] = base[0] - scale * k[0];
	tip[1] = base[1] - scale * k[1];
}

/* Begin a record of the picture, of style class cls, colour and stroke
 * width width_px pixels (0: the picture's), in it. */
static int
begin(struct loft_cad_doc *d, struct loft_cad_item *it, const char *cls,
    const char *colour, double width_px)
{
	memset(it, 0, sizeof *it);
	it->name = "";
	it->cls = cls;
	it->colour = colour;
	it->width_px = width_px;
	return d->f->begin_record(d, it);
}

/* A comb: its teeth, then the line through their tips. */
static int
draw_comb(struct loft_cad_doc *d, const struct pic *pc,
    const struct stroke *s, double scale)
{
	struct loft_cad_item it;
	size_t n = s->n / 2;
	double *tip = malloc(2 * n * sizeof *tip), seg[4];
	int rc;

	if (tip == NULL)
		return LOFT_ENOMEM;
	rc = begin(d, &it, "comb", colour(s->rec), THIN_PX);
	for (size_t j = 0; j < n && rc == 0; j++) {
		tooth_tip(pc, s, j, scale, tip + 2 * j);
		memcpy(seg, pc->pt + 2 * (s->first + 2 * j), 2 * sizeof *seg);
		memcpy(seg + 2, tip + 2 * j, 2 * sizeof *seg);
		rc = d->f->polyline(d, seg, 2, 2, 0);
	}
	if (rc == 0)
		rc = d->f->end_record(d);
	if (rc == 0)
		rc = begin(d, &it, "comb-envelope", colour(s->rec), THIN_PX);
	if (rc == 0)
		rc = d->f->polyline(d, tip, n, 2, 0);
	if (rc == 0)
		rc = d->f->end_record(d);
	free(tip);
	return rc;
}

/*
 * A record's curve width in pixels: LOFT_PLOT_CURVE_PX for the last
 * record, and up to HEAVIER times that more for the first, so that
 * where two records' curves run together (a fitted segment and the arc it
 * approximates) the later, drawn on top and thinner, leaves the earlier
 * showing at both sides: a rim of 1.1 pixels each side, which a screen
 * shows in its colour (a rim of 0.75 blended into one purple line).
 */
#define HEAVIER 1.5
static double
curve_px(const struct pic *pc, int rec)
{
	if (pc->nrec < 2 || rec < 0)
		return LOFT_PLOT_CURVE_PX;
	return LOFT_PLOT_CURVE_PX * (1 + HEAVIER *
	    (double)(pc->nrec - 1 - rec) /
	    (pc->nrec - 1));
}

/* A curve (exact cubic pieces) or a polyline. */
static int
draw_path(struct loft_cad_doc *d, const struct pic *pc,
    const struct stroke *s)
{
	const double *p = pc->pt + 2 * s->first;
	struct loft_bcurve c = { p, s->n / 4, 3, 2, s->closed };
	struct loft_cad_item it;
	int rc;

	if (s->kind == K_MESH || s->kind == K_NET)
		rc = begin(d, &it, s->kind == K_MESH ? "mesh" :
		    "control-polygon", colour(s->rec), THIN_PX);
	else
		rc = begin(d, &it, "curve", colour(s->rec),
		    curve_px(pc, s->rec));
	if (rc == 0)
		rc = s->kind == K_BEZIER ? d->f->curve(d, &c) :
		    d->f->polyline(d, p, s->n, 2, s->closed);
	return rc == 0 ? d->f->end_record(d) : rc;
}

/* -t: pairs of points, a tangent each. */
static int
draw_handles(struct loft_cad_doc *d, const struct pic *pc,
    const struct stroke *s)
{
	const double *p = pc->pt + 2 * s->first;
	struct loft_cad_item it;
	int rc = begin(d, &it, "tangents", colour(s->rec), TANGENT_PX);

	for (size_t j = 0; j + 1 < s->n && rc == 0; j += 2)
		rc = d->f->polyline(d, p + 2 * j, 2, 2, 0);
	return rc == 0 ? d->f->end_record(d) : rc;
}

/* Markers; control points are open, white inside, so they are not taken
 * for points on the curve. */
static int
draw_marks(struct loft_cad_doc *d, const struct pic *pc,
    const struct stroke *s)
{
	struct loft_cad_item it;
	int rc = s->kind == K_CONTROL ? begin(d, &it, "control-points",
	    colour(s->rec), THIN_PX) : begin(d, &it, s->kind == K_KNOTS ?
	    "knots" : "points", colour(s->rec), 0);

	if (rc == 0)
		rc = d->f->points(d, pc->pt + 2 * s->first, s->n, 2);
	return rc == 0 ? d->f->end_record(d) : rc;
}

/* What the labels keep clear of: the lines drawn, as segments (a
 * marker is a segment of no length), each with its record. */
struct obstacles {
	double (*seg)[4];
	int *rec;
	size_t n, cap, reccap;
};

static int
add_segment(struct obstacles *o, const double *a, const double *b, int rec)
{
	if (loft_grow((void **)&o->seg, &o->cap, o->n + 1, sizeof *o->seg) != 0 ||
	    loft_grow((void **)&o->rec, &o->reccap, o->n + 1, sizeof *o->rec) != 0)
		return -1;
	o->rec[o->n] = rec;
	o->seg[o->n][0] = a[0];
	o->seg[o->n][1] = a[1];
	o->seg[o->n][2] = b[0];
	o->seg[o->n][3] = b[1];
	o->n++;
	return 0;
}

/* The segments of a stroke of a line (mesh, polyline, net), closed or
 * not, and of a marker stroke (segments of no length). */
static int
line_segments(const struct stroke *s, const double *p, struct obstacles *o)
{
	int rc = 0;

	if (s->kind != K_MESH && s->kind != K_LINE && s->kind != K_NET) {
		for (size_t j = 0; rc == 0 && j < s->n; j++)
			rc = add_segment(o, p + 2 * j, p + 2 * j, s->rec);
		return rc;
	}
	for (size_t j = 0; rc == 0 && j + 1 < s->n; j++)
		rc = add_segment(o, p + 2 * j, p + 2 * j + 2, s->rec);
	if (rc == 0 && s->closed && s->n > 2)
		rc = add_segment(o, p + 2 * (s->n - 1), p, s->rec);
	return rc;
}

/*
 * The segments of every stroke drawn, but the comb's teeth (a comb's
 * envelope is a line to keep clear of; its teeth fill an area a label
 * may sit on).  A cubic piece is cut into BEZIER_CHORDS chords: its
 * distance from them is far below the gap a label keeps.
 */
#define BEZIER_CHORDS 16
static int
collect_segments(const struct pic *pc, double scale, struct obstacles *o)
{
	for (size_t i = 0; i < pc->nst; i++) {
		const struct stroke *s = &pc->st[i];
		const double *p = pc->pt + 2 * s->first;
		double a[2], b[2];
		int rc = 0;

		switch (s->kind) {
		case K_COMB:
			for (size_t j = 0; rc == 0 && j + 1 < s->n / 2; j++) {
				tooth_tip(pc, s, j, scale, a);
				tooth_tip(pc, s, j + 1, scale, b);
				rc = add_segment(o, a, b, s->rec);
			}
			break;
		case K_BEZIER:
			for (size_t j = 0; rc == 0 && j < s->n / 4; j++)
				for (int k = 0; rc == 0 && k < BEZIER_CHORDS;
				    k++) {
					bezier_at(p + 8 * j,
					    (double)k / BEZIER_CHORDS, a);
					bezier_at(p + 8 * j,
					    (double)(k + 1) / BEZIER_CHORDS, b);
					rc = add_segment(o, a, b, s->rec);
				}
			break;
		case K_HANDLE:
			for (size_t j = 0; rc == 0 && j + 1 < s->n; j += 2)
				rc = add_segment(o, p + 2 * j, p + 2 * j + 2, s->rec);
			break;
		default:
			rc = line_segments(s, p, o);
		}
		if (rc != 0)
			return -1;
	}
	return 0;
}

/*
 * Place the labels (loft_place_labels, labels.c) of height font, clear
 * of the lines drawn, the comb's teeth scale times the curvature long.
 * Adds the labels' boxes to frame.  0, or -1: out of memory.
 */
static int
place_labels(struct pic *pc, double font, double scale, struct box *frame)
{
	struct obstacles o = { 0 };
	struct loft_label *p = malloc(pc->nlb * sizeof *p);
	int rc = -1;

	if (p != NULL && collect_segments(pc, scale, &o) == 0) {
		for (size_t i = 0; i < pc->nlb; i++) {
			p[i] = pc->lb[i].p;
			p[i].width = CHAR_EM * font *
			    (double)strlen(pc->lb[i].text);
		}
		rc = loft_place_labels(p, pc->nlb, o.n ? o.seg[0] : NULL,
		    o.rec, o.n, font, frame->lo, frame->hi) != 0 ? -1 : 0;
		for (size_t i = 0; rc == 0 && i < pc->nlb; i++)
			pc->lb[i].p = p[i];
	}
	free(o.seg);
	free(o.rec);
	free(p);
	return rc;
}

/* The comb's scale, from the extent b of the curves (-C's, or teeth
 * COMB_LENGTH of it at the largest curvature), and its teeth's tips
 * added to b. */
static double
comb_scale(struct pic *pc, struct box *b)
{
	double big = fmax(b->hi[0] - b->lo[0], b->hi[1] - b->lo[1]), tip[2],
	    scale = pc->comb_scale;

	pc->comb_div = 1;
	if (scale == 0 && pc->kmax > 0) {
		scale = COMB_LENGTH * big;
		pc->comb_div = pc->kmax;
	}
	pc->comb_cap = COMB_CAP * big;
	for (size_t i = 0; i < pc->nst; i++)
		for (size_t j = 0; pc->st[i].kind == K_COMB &&
		    j < pc->st[i].n / 2; j++) {
			tooth_tip(pc, &pc->st[i], j, scale, tip);
			box_add(b, tip);
		}
	return scale;
}

/* Curves and polylines in one pass, in the order of their records, so
 * that a later record lies on an earlier one, drawn thinner. */
static int
draw_strokes(struct loft_cad_doc *d, const struct pic *pc, double scale)
{
	int rc = 0;

	for (int kind = 0; kind < NKIND && rc == 0; kind++)
		for (size_t i = 0; i < pc->nst && rc == 0; i++) {
			const struct stroke *s = &pc->st[i];
			int k = s->kind == K_BEZIER ? K_LINE : (int)s->kind;

			if (k != kind || s->n == 0)
				continue;
			switch (s->kind) {
			case K_COMB: rc = draw_comb(d, pc, s, scale); break;
			case K_MESH:
			case K_LINE:
			case K_NET:
			case K_BEZIER: rc = draw_path(d, pc, s); break;
			case K_HANDLE: rc = draw_handles(d, pc, s); break;
			default: rc = draw_marks(d, pc, s); break;
			}
		}
	return rc;
}

/* The labels placed, of height font: leaders, the grounds of those on
 * their curves (of the background's colour, hiding the line under
 * them), then the texts. */
static int
draw_labels(struct loft_cad_doc *d, const struct pic *pc, double font)
{
	struct loft_cad_item it;
	int rc = 0;

	for (size_t i = 0; i < pc->nlb && rc == 0; i++) {
		const struct loft_label *l = &pc->lb[i].p;
		double sg[4];

		if (!l->leader)
			continue;
		loft_label_leader(l, sg);
		if ((rc = begin(d, &it, "leader", colour(l->rec), THIN_PX)) ==
		    0 && (rc = d->f->polyline(d, sg, 2, 2, 0)) == 0)
			rc = d->f->end_record(d);
	}
	for (size_t i = 0; i < pc->nlb && rc == 0; i++) {
		const struct loft_label *l = &pc->lb[i].p;

		if (!l->oncurve)
			continue;
		if ((rc = begin(d, &it, "label-ground", pc->background ?
		    pc->background : "#fff", 0)) == 0 &&
		    (rc = d->f->box(d, l->lo, l->hi)) == 0)
			rc = d->f->end_record(d);
	}
	for (size_t i = 0; i < pc->nlb && rc == 0; i++) {
		const struct loft_label *l = &pc->lb[i].p;
		double q[2] = { l->at[0] + font / 2, l->at[1] - 0.35 * font };
		int middle = l->centred || l->oncurve;

		/* a patch's id, or a label on its curve: centred on its
		 * point, exactly */
		if (middle) {
			q[0] = l->at[0];
			q[1] = l->at[1];
		}
		if ((rc = begin(d, &it, l->oncurve ? "label on-curve" :
		    "label", colour(l->rec), 0)) == 0 &&
		    (rc = d->f->label(d, q, font, middle, pc->lb[i].text)) == 0)
			rc = d->f->end_record(d);
	}
	return rc;
}

/*
 * The picture's frame (the viewBox of d), from the drawing's extent b:
 * a margin, and room for the labels, placed here; their height in
 * *font.  0, or LOFT_EGEOM (too large to frame) or LOFT_ENOMEM.
 */
static int
frame(struct loft_cad_doc *d, struct pic *pc, struct box *b, double scale,
    double *font)
{
	const struct loft_cad_opts o = { .picture_px = PICTURE_PX,
	    .background = pc->background };
	double w = b->hi[0] - b->lo[0], h = b->hi[1] - b->lo[1], big, margin,
	    *vb;

	if (!isfinite(w) || !isfinite(h))
		return LOFT_EGEOM;
	big = fmax(w, h);
	if (big == 0)   /* one point: a frame of unit size around it */
		big = fmax(1, fmax(fabs(b->lo[0]), fabs(b->lo[1])));
	margin = MARGIN * big;
	*font = 0;
	if (pc->nlb > 0) {
		*font = LOFT_PLOT_FONT_PX * (big + 2 * margin) / PICTURE_PX;
		if (place_labels(pc, *font, scale, b) != 0)
			return LOFT_ENOMEM;
	}
	loft_cad_free(d);
	loft_cad_init(d, &loft_cad_svgplot, &o);
	vb = d->o.frame;
	vb[0] = b->lo[0] - margin;
	vb[1] = -(b->hi[1] + margin);
	vb[2] = b->hi[0] - b->lo[0] + 2 * margin;
	vb[3] = b->hi[1] - b->lo[1] + 2 * margin;
	big = fmax(vb[2], vb[3]);
	/* the corner too: a drawing near the largest double has its margin
	 * beyond it */
	if (!isfinite(big) || !(big > 0) || !isfinite(vb[0]) ||
	    !isfinite(vb[1]))
		return LOFT_EGEOM;
	return 0;
}

/*
 * Write the whole picture into d (loftplot's SVG picture, svgplot.c),
 * made anew: the picture in d->out.  0, or LOFT_EGEOM (it cannot be
 * framed) or LOFT_ENOMEM with err filled.  d is the caller's, zeroed or
 * made by write_svg before, to be freed with loft_cad_free.
 */
static int
write_svg(struct loft_cad_doc *d, struct pic *pc, struct loft_error *err)
{
	struct box b = pc->box;
	double scale = comb_scale(pc, &b), font;
	int rc = frame(d, pc, &b, scale, &font);

	drawn_colour = pc->rec;
	if (rc == 0 && (rc = d->f->begin(d)) == 0 &&
	    (rc = draw_strokes(d, pc, scale)) == 0 &&
	    (rc = draw_labels(d, pc, font)) == 0)
		rc = d->f->end(d);
	if (rc == LOFT_ENOMEM || d->out.bad == LOFT_ENOMEM)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (rc != 0 || d->out.bad != 0)
		return loft_fail(err, LOFT_EGEOM, -1, "the drawing is too large "
		    "to frame");
	return 0;
}

static void
free_pic(struct pic *pc)
{
	for (size_t i = 0; i < pc->nlb; i++)
		free(pc->lb[i].text);
	free(pc->lb);
	free(pc->pt);
	free(pc->st);
	free(pc->rec);
}

/*
 * A picture that cannot be framed: take out the record farthest from the
 * origin (the largest coordinate of its extent), naming it, as if it had
 * failed when it was read, so that the others are still drawn (one
 * far-out record emptied the whole picture, naming none).
 */
static void
take_out_farthest(struct pic *pc)
{
	int far = 0;
	double most = -1;
	size_t k = 0;

	for (int r = 0; r < pc->nrec; r++) {
		const struct box *b = &pc->rec[r].box;
		double m = fmax(fmax(fabs(b->lo[0]), fabs(b->hi[0])),
		    fmax(fabs(b->lo[1]), fabs(b->hi[1])));

		if (m > most) {
			most = m;
			far = r;
		}
	}
	fprintf(stderr, "loftplot: %s:%ld: too far out to be framed with the "
	    "other records: left out\n", pc->rec[far].file,
	    pc->rec[far].line);
	/* its strokes and label go; those after it move up a number */
	for (size_t i = 0; i < pc->nst; i++)
		if (pc->st[i].rec != far) {
			pc->st[k] = pc->st[i];
			pc->st[k].rec -= pc->st[k].rec > far;
			k++;
		}
	pc->nst = k;
	k = 0;
	for (size_t i = 0; i < pc->nlb; i++) {
		struct label *l = &pc->lb[i];

		if (l->p.rec == far) {
			free(l->text);
			continue;
		}
		if (l->p.rec > far && l->numbered)      /* fewer digits */
			snprintf(l->text, strlen(l->text) + 1, "%d", l->p.rec);
		l->p.rec -= l->p.rec > far;
		pc->lb[k++] = *l;
	}
	pc->nlb = k;
	memmove(pc->rec + far, pc->rec + far + 1,
	    (size_t)(pc->nrec - far - 1) * sizeof *pc->rec);
	pc->nrec--;
	pc->box = pc->kbox;
	pc->kmax = 0;
	for (int r = 0; r < pc->nrec; r++) {
		box_join(&pc->box, &pc->rec[r].box);
		pc->kmax = fmax(pc->kmax, pc->rec[r].kmax);
	}
}

/* -B: a colour name of letters, or # and 3 or 6 hexadecimal digits:
 * nothing that could end the attribute it is written into. */
static int
colour_ok(const char *s)
{
	size_t n = strlen(s);

	if (s[0] == '#')
		return (n == 4 || n == 7) && strspn(s + 1,
		    "0123456789abcdefABCDEF") == n - 1;
	return n > 0 && n < 40 && strspn(s, "abcdefghijklmnopqrstuvwxyz"
	    "ABCDEFGHIJKLMNOPQRSTUVWXYZ") == n;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
/* -i: option c (with arg, when it takes one) for the page's picture
 * too, but for those the page sets itself (-v, -c) or has no use for
 * (-i, -K). */
static void
page_option(struct loft_page *pg, int c, const char *arg)
{
	static const char *const opts[] = { "-b", "-m", "-t", "-B", "-C",
	    "-g", "-l", "-n" };
	static const char letters[] = "bmtBCgln";
	const char *f = strchr(letters, c);

	if (c == 0 || f == NULL || pg->nargs + 2 >= (int)(sizeof pg->args /
	    sizeof pg->args[0]))
		return;
	pg->args[pg->nargs++] = opts[f - letters];
	if (f - letters >= 3)           /* -B -C -g -l -n take an argument */
		pg->args[pg->nargs++] = arg;
}

/* -i: the page of the records kept (lib/wasm/pageout.c); exit status 1
 * when a record was bad or no module was built, as the page says. */
static int
write_page(struct loft_run *run, struct pic *pc, const char *view)
{
	struct loft_page *pg = pc->page;
	int status = run->status;

	pg->view = view;
	pg->comb = pc->comb;
	if (pc->nst == 0) {
		fputs("loftplot: nothing to draw\n", stderr);
		status = 1;
	} else if (loft_page_wasm_bytes == 0) {
		fputs("loftplot: -i: the page's WebAssembly module was not "
		    "built: install clang, lld, wasi-libc and "
		    "libclang-rt-14-dev-wasm32, then make again\n", stderr);
		status = 1;
	} else if (loft_page_write(stdout, pg) != 0) {
		fputs("loftplot: cannot write the page\n", stderr);
		status = 1;
	}
	loft_writer_free(&pg->knots);
	loft_writer_free(&pg->curves);
	loft_writer_free(&pg->points);
	loft_writer_free(&pg->design);
	return status;
}

int
main(int argc, char *argv[])
{
	static const char *const views[] = { "xy", "yz", "xz", "iso", NULL };
	struct pic pc = { .steps = 16, .grid = 8 };
	struct loft_run run = { .prog = "loftplot", .out = stdout, .msg = stderr,
	    .handle = keep_record, .ctx = &pc };
	struct loft_cad_doc d = { 0 };
	struct loft_page page = { 0 };
	struct loft_error err;
	char *knots = NULL;
	int c, rc = 0, word, status;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "bcimtB:C:g:K:l:n:v:h")) != -1) {
		switch (c) {
		case 'b': pc.control = 1; break;
		case 'B': pc.background = optarg;
		    if (!colour_ok(optarg))
			    rc = loft_fail(&err, LOFT_EINPUT, -1, "'%s': a colour "
				"is a name (white) or #rgb or #rrggbb",
				optarg);
		    break;
		case 'c': pc.comb = 1; break;
		case 'i': pc.page = &page; break;
		case 'm': pc.marks = 1; break;
		case 't': pc.handles = 1; break;
		case 'C': rc = loft_parse_real(optarg, 1e-300, 1e300,
		    &pc.comb_scale, &err); pc.comb = 1; break;
		case 'g': rc = loft_parse_int(optarg, 1, 10000, &pc.grid, &err);
		    break;
		case 'K': knots = optarg; break;
		case 'l': pc.label_key = optarg; break;
		case 'n': rc = loft_parse_int(optarg, 1, 10000, &pc.steps, &err);
		    pc.steps_set = 1; break;
		case 'v': rc = loft_parse_word(optarg, views, &word, &err);
		    pc.view = word; break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
		if (rc != 0)
			loft_usage_error(usage_text, c, err.msg);
		page_option(&page, c, optarg);
	}
	box_empty(&pc.box);
	box_empty(&pc.kbox);
	if (knots != NULL) {
		run.handle = keep_knots;
		loft_run_files(&run, 1, &knots);
		run.handle = keep_record;
	}
	loft_run_files(&run, argc - optind, argv + optind);
	if (pc.page != NULL)
		status = write_page(&run, &pc, views[pc.view]);
	else if (pc.nst == 0) {
		fputs("loftplot: nothing to draw\n", stderr);
		status = 1;
	} else if ((rc = write_svg(&d, &pc, &err)) != 0) {
		/* one far-out record must not empty the whole picture */
		while (rc == LOFT_EGEOM && pc.nrec > 1) {
			take_out_farthest(&pc);
			rc = write_svg(&d, &pc, &err);
		}
		if (rc != 0)
			fprintf(stderr, "loftplot: %s\n", err.msg);
		else
			loft_run_write(&run, d.out.buf, d.out.len);
		status = 1;     /* a record was left out, or nothing drawn */
	} else {
		status = loft_run_write(&run, d.out.buf, d.out.len);
	}
	loft_cad_free(&d);
	free_pic(&pc);
	return status;
}
#endif
