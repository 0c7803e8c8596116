/*
 * offset.c: the offset of a plane curve, the curve at a constant
 * distance from it, as cubic segments within a tolerance; its loops cut
 * away, joins made at its corners.
 *
 * The method, in the order of loft_offset_curve:
 *  1. The curve is looked at in its own frame: coordinates less the
 *     centre of its box, divided by its size, so that every tolerance
 *     below is relative and the numbers neither overflow nor underflow.
 *  2. Each piece is cut where its tangent has turned TURN_MAX, and
 *     where the offset has a cusp (1 - D k = 0, k the curvature: the
 *     curve's radius of curvature is |D| on the offset's side).
 *  3. Each part is matched by a cubic Hermite piece with the offset's
 *     end points and end derivatives, o = c + D n and o' = (1 - D k) c'
 *     (n the unit left normal, n' = -k c'), halved until the cubic is
 *     within the tolerance of the exact offset at interior points.  The
 *     curve itself is matched the same way (D = 0), for the distances
 *     of step 6 and for its area.
 *  4. At a corner (the tangent direction jumps) the outer side gets a
 *     join, the inner side a straight piece that step 6 removes: the
 *     two offsets cross there and are trimmed at their crossing.
 *  5. The raw offset's self-intersections are found by a walk down two
 *     trees of bounding boxes over its pieces in their order along the
 *     curve (neighbours along a curve are neighbours in the plane), then
 *     by halving the cubics that still overlap until they are flat.
 *  6. The crossings cut the raw offset into runs (an open curve's also
 *     where the offset passes the curve's ends); a run that runs
 *     backwards, or whose points are nearer the curve than |D| less
 *     half the tolerance, is cut away.  The runs left are chained into
 *     curves: at a crossing the run that arrives turns onto the other
 *     branch if that one is kept.  A closed result that runs the other
 *     way round from the curve is a loop, and goes too.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* The most a fitted piece may turn: half a right angle keeps every
 * Hermite piece convex or nearly straight, so that neighbours
 * along the offset never cross each other and few halvings are needed. */
#define TURN_MAX (M_PI / 4)
/* Samples of a piece to find where it turns and where the offset has
 * cusps; a bezier record of many control points gets more. */
#define NSAMPLE 16
/* Halvings of one part before the fit gives up (2^-48 of a piece). */
#define FIT_DEPTH 48
/* Pieces whose points all lie within this of each other (relative to
 * the curve's size) are points, and are skipped. */
#define TINY_PIECE 1e-13
/* Consecutive pieces must meet within this of the curve's size. */
#define GAP_TOL 1e-9
/* The tolerance is never below this of the curve's size: the rounding
 * of the coordinates themselves. */
#define TOL_FLOOR 1e-12
/* A tangent shorter than this of the second derivative is taken as
 * zero, and the direction is read a parameter NUDGE further in. */
#define ZERO_TANGENT 1e-9
#define NUDGE 1e-7
/* Crossings nearer than this in the parameter of the raw offset (in
 * pieces) are one crossing found twice. */
#define PARAM_EQ 1e-9
/* The self-intersection search gives up after this many box tests per
 * piece: parts of the offset that run along one another. */
#define ISECT_WORK 4000
/* How large a tail of kept runs may be, in tolerances, and be dropped:
 * slivers at shallow crossings are a few tolerances long. */
#define TAIL_MAX 16
/* Halvings of two cubics before their crossing is taken from chords. */
#define ISECT_DEPTH 52

/* The kinds of piece of the raw offset: the offset proper, where it runs
 * backwards (between two cusps: the curve's radius of curvature is less
 * than |D| there, so nearer points of the curve lie round it and none
 * of it is kept), and the joins on the outer and inner side of a corner. */
enum { RAW, BACK, JOIN_OUT, JOIN_IN };

struct bz {
	double p[8];            /* control points b0..b3, x y each */
	int kind;
};

struct node {
	double box[4];          /* xmin ymin xmax ymax */
	size_t lo, hi;          /* pieces [lo, hi) */
	long l, r;              /* children, or -1 at a leaf */
};

struct isect {
	double sa, sb;          /* parameters along the raw offset, sa < sb */
	double pt[2];
	int single;             /* an open curve's end effect: sa alone */
};

struct cut {
	double s;
	size_t is;              /* its crossing */
	long partner;           /* the cut of the other branch */
};

struct run {
	double s0, s1;          /* from cut to cut, s1 > s0 (maybe past N) */
	long c0, c1;            /* cut at each end, or -1 at an open end */
	int good, seen, led;    /* kept; chained; some kept run leads here */
	long next;
};

struct loft_offset_work {
	struct bz *in, *ch, *em;
	size_t nin, incap, nch, chcap, nem, emcap;
	struct node *tin, *tch;
	size_t ntin, tincap, ntch, tchcap;
	struct isect *is;
	size_t nis, iscap;
	struct cut *cut;
	size_t ncut, cutcap;
	struct run *run;
	size_t nrun, runcap;
	long *comp;
	size_t compcap;
	double *brk;
	size_t brkcap;
	signed char *skip, *cutat;
	size_t skipcap, cutatcap;
	double *kap;
	size_t kapcap;
};

struct ctx {
	const struct loft_curve *c;
	struct loft_offset_work *w;
	struct loft_error *err;
	double org[2], size;    /* the frame: (p - org) / size */
	double D;               /* signed distance to the left, in the frame */
	double tol;             /* tolerance of a fit, in the frame */
	size_t work;            /* box tests done */
	int closed;
};

/* |(x, y)|, for numbers of the frame (no overflow to guard against:
 * libm's hypot is several times slower and showed in the profile) */
static double
len2(double x, double y)
{
	return sqrt(x * x + y * y);
}

#define GROW(w, arr, cap, need) \
	loft__grow((void **)&(w)->arr, &(w)->cap, (need), sizeof *(w)->arr)

/* ---- points of the curve and of its offset ------------------------------ */

/* The point, derivatives of piece i at u, in the frame; 0 or -1 if not
 * finite. */
static int
frame_eval(const struct ctx *x, size_t i, double u, double *p, double *d1,
    double *d2)
{
	double q[LOFT_MAXDIM], e1[LOFT_MAXDIM], e2[LOFT_MAXDIM], s = x->size;

	/* divided, not multiplied by 1 / s, which overflows for a
	 * subnormal size */
	loft_curve_eval(x->c, i, u, q, e1, e2);
	for (int k = 0; k < 2; k++) {
		p[k] = q[k] / s - x->org[k] / s;
		d1[k] = e1[k] / s;
		d2[k] = e2[k] / s;
		if (!isfinite(p[k]) || !isfinite(d1[k]) || !isfinite(d2[k]))
			return -1;
	}
	return 0;
}

/*
 * The offset at signed distance D of piece i at u: point o, derivative
 * od = (1 - D k) c', unit tangent t and curvature k of the curve (any
 * of od, t, kp may be NULL).  Where the tangent vanishes (a zero end
 * tangent) the direction is taken a little further in.  Returns 0, or
 * -1 where the values are not finite or there is no direction at all.
 */
static int
offset_eval(const struct ctx *x, size_t i, double u, double D, double *o,
    double *od, double *t, double *kp)
{
	double p[2], d1[2], d2[2], L, k, f, tt[2];

	if (frame_eval(x, i, u, p, d1, d2) != 0)
		return -1;
	L = len2(d1[0], d1[1]);
	if (!(L > ZERO_TANGENT * len2(d2[0], d2[1]))) {
		double p2[2];

		if (frame_eval(x, i, u < 0.5 ? u + NUDGE : u - NUDGE, p2, d1,
		    d2) != 0)
			return -1;
		L = len2(d1[0], d1[1]);
		if (!(L > 0))
			return -1;
	}
	tt[0] = d1[0] / L;
	tt[1] = d1[1] / L;
	k = (d1[0] * d2[1] - d1[1] * d2[0]) / (L * L * L);
	f = 1 - D * k;
	o[0] = p[0] - D * tt[1];
	o[1] = p[1] + D * tt[0];
	if (od != NULL) {
		od[0] = f * d1[0];
		od[1] = f * d1[1];
	}
	if (t != NULL)
		vcopy(t, tt, 2);
	if (kp != NULL)
		*kp = k;
	return isfinite(o[0]) && isfinite(o[1]) && isfinite(f) ? 0 : -1;
}

/* ---- cubic Bezier pieces ------------------------------------------------ */

static void
bz_eval(const double *b, double t, double *p)
{
	double s = 1 - t;
	double w0 = s * s * s, w1 = 3 * s * s * t, w2 = 3 * s * t * t,
	    w3 = t * t * t;

	for (int k = 0; k < 2; k++)
		p[k] = w0 * b[k] + w1 * b[2 + k] + w2 * b[4 + k] + w3 * b[6 + k];
}

/* The part of b from ta to tb. */
static void
bz_sub(const double *b, double ta, double tb, double *out)
{
	double r[8];

	if (ta > 0) {
		loft_bezier_split(b, 3, 2, ta, NULL, r);
		b = r;
		tb = (tb - ta) / (1 - ta);
	}
	if (tb < 1)
		loft_bezier_split(b, 3, 2, tb, out, NULL);
	else
		memcpy(out, b, sizeof r);
}

static void
bz_box(const double *b, double *box)
{
	box[0] = box[2] = b[0];
	box[1] = box[3] = b[1];
	for (int j = 1; j < 4; j++)
		for (int k = 0; k < 2; k++) {
			if (b[2 * j + k] < box[k])
				box[k] = b[2 * j + k];
			if (b[2 * j + k] > box[2 + k])
				box[2 + k] = b[2 * j + k];
		}
}

static int
box_overlap(const double *a, const double *b)
{
	return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
}

/* The squared distance from q to the box (squares: no root to take). */
static double
box_dist2(const double *box, const double *q)
{
	double dx = q[0] < box[0] ? box[0] - q[0] : q[0] > box[2] ? q[0] - box[2] : 0;
	double dy = q[1] < box[1] ? box[1] - q[1] : q[1] > box[3] ? q[1] - box[3] : 0;

	return dx * dx + dy * dy;
}

/* Whether b lies within eps of its chord: its inner control points do. */
static int
bz_flat(const double *b, double eps)
{
	return vsegdist2(b, b + 6, b + 2, 2) <= eps * eps &&
	    vsegdist2(b, b + 6, b + 4, 2) <= eps * eps;
}

/* Twice the area b sweeps about the origin, (x y' - y x') integrated:
 * a polynomial of degree 5, exact by Gauss-Legendre in 3 points. */
static double
bz_area2(const double *b)
{
	static const double gx[3] = { 0.1127016653792583, 0.5,
	    0.8872983346207417 };
	static const double gw[3] = { 5.0 / 18, 8.0 / 18, 5.0 / 18 };
	double a = 0;

	for (int j = 0; j < 3; j++) {
		double t = gx[j], s = 1 - t, p[2], d[2];

		bz_eval(b, t, p);
		for (int k = 0; k < 2; k++)
			d[k] = 3 * (s * s * (b[2 + k] - b[k]) + 2 * s * t *
			    (b[4 + k] - b[2 + k]) + t * t * (b[6 + k] - b[4 + k]));
		a += gw[j] * (p[0] * d[1] - p[1] * d[0]);
	}
	return a;
}

static int
push(struct bz **arr, size_t *n, size_t *cap, const double *p, int kind)
{
	if (loft__grow((void **)arr, cap, *n + 1, sizeof **arr) != 0)
		return -1;
	memcpy((*arr)[*n].p, p, sizeof (*arr)[*n].p);
	(*arr)[*n].kind = kind;
	(*n)++;
	return 0;
}

/* ---- fitting ------------------------------------------------------------ */

/*
 * Append to arr the cubic pieces within x->tol of the offset at D of
 * piece i from a to b, whose ends oa, ob and derivatives da, db are
 * known: the Hermite cubic of those, checked at five interior points
 * against the exact offset, or the two halves.  The curve itself (D =
 * 0) is fitted four times closer, so that the distances measured to it
 * judge within the tolerance: a point kept is at most half the
 * tolerance nearer than |D| to the fit, a sixteenth to the curve's fit,
 * a sixteenth more by the flatness of near_bz.
 */
static int
fit(struct ctx *x, struct bz **arr, size_t *n, size_t *cap, size_t i,
    double a, double b, const double *oa, const double *da, const double *ob,
    const double *db, double D, int depth)
{
	static const double us[5] = { 0.125, 0.25, 0.5, 0.75, 0.875 };
	double h = b - a, bz[8], om[2], dm[2], q[2], e = 0;
	double tol = D != 0 ? x->tol : x->tol / 4;
	int r;

	for (int k = 0; k < 2; k++) {
		bz[k] = oa[k];
		bz[2 + k] = oa[k] + h * da[k] / 3;
		bz[4 + k] = ob[k] - h * db[k] / 3;
		bz[6 + k] = ob[k];
	}
	for (int j = 0; j < 5 && !(e > tol); j++) {
		if (offset_eval(x, i, a + us[j] * h, D, om, NULL, NULL, NULL))
			goto fail;
		bz_eval(bz, us[j], q);
		e = vdist(q, om, 2);
	}
	if (e <= tol)
		return push(arr, n, cap, bz, RAW) ? LOFT_ENOMEM : 0;
	if (depth >= FIT_DEPTH)
		return loft_fail(x->err, LOFT_EGEOM, (long)i, "the offset of "
		    "segment %zu cannot be made near u = %.6g: the tangent "
		    "vanishes or turns back there", i + 1, a + h / 2);
	if (offset_eval(x, i, a + h / 2, D, om, dm, NULL, NULL) != 0)
		goto fail;
	if ((r = fit(x, arr, n, cap, i, a, a + h / 2, oa, da, om, dm, D,
	    depth + 1)) != 0)
		return r;
	return fit(x, arr, n, cap, i, a + h / 2, b, om, dm, ob, db, D, depth + 1);
fail:
	return loft_fail(x->err, LOFT_EGEOM, (long)i, "segment %zu: the "
	    "offset is not finite near u = %.6g", i + 1, a + h / 2);
}

/* The parameter in (a, b) where g = 1 - D k changes sign, by bisection. */
static double
cusp(const struct ctx *x, size_t i, double a, double ga, double b, double D)
{
	double o[2], k;

	for (int j = 0; j < 50 && b - a > 1e-13; j++) {
		double m = (a + b) / 2;

		if (offset_eval(x, i, m, D, o, NULL, NULL, &k) != 0)
			break;
		if ((1 - D * k > 0) == (ga > 0))
			a = m;
		else
			b = m;
	}
	return (a + b) / 2;
}

static size_t
nsample(const struct loft_curve *c)
{
	return c->npts > NSAMPLE / 4 ? 4 * c->npts : NSAMPLE;
}

/*
 * Look at every piece once, at nsample + 1 points: its curvature there
 * (w->kap) and whether the tangent has turned TURN_MAX since the last
 * cut (w->cutat).  The turning is summed as the chords between unit
 * tangents, 2 sin(a/2) for a step of a, close to a for these steps and
 * cheaper than an arc tangent.
 */
static int
survey(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	size_t ns = nsample(x->c), n = x->c->npieces;
	double o[2], t[2], tp[2] = { 0, 0 }, k;

	if (GROW(w, kap, kapcap, n * (ns + 1)) != 0 ||
	    GROW(w, cutat, cutatcap, n * (ns + 1)) != 0)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < n; i++) {
		double turn = 0;

		if (w->skip[i])
			continue;
		for (size_t j = 0; j <= ns; j++) {
			double u = (double)j / ns;

			if (offset_eval(x, i, u, 0, o, NULL, t, &k) != 0)
				return loft_fail(x->err, LOFT_EGEOM, (long)i,
				    "segment %zu has no direction near u = "
				    "%.6g, or overflows there", i + 1, u);
			w->kap[i * (ns + 1) + j] = k;
			if (j > 0)
				turn += len2(t[0] - tp[0], t[1] - tp[1]);
			w->cutat[i * (ns + 1) + j] = j > 0 && j < ns &&
			    turn > TURN_MAX;
			if (w->cutat[i * (ns + 1) + j])
				turn = 0;
			vcopy(tp, t, 2);
		}
	}
	return 0;
}

/*
 * Fit the offset at D of piece i (D = 0: the curve itself), cut where
 * survey cut it and at the offset's cusps, onto arr.
 */
static int
fit_piece(struct ctx *x, struct bz **arr, size_t *n, size_t *cap, size_t i,
    double D)
{
	struct loft_offset_work *w = x->w;
	size_t ns = nsample(x->c), nb = 0;
	const double *kap = w->kap + i * (ns + 1);
	const signed char *cut = w->cutat + i * (ns + 1);
	double oa[2], da[2], ob[2], db[2], o[2], k;
	int r, back = 0;

	if (GROW(w, brk, brkcap, 2 * ns + 2) != 0)
		return LOFT_ENOMEM;
	w->brk[nb++] = 0;
	for (size_t j = 1; j <= ns; j++) {
		double g = 1 - D * kap[j], gp = 1 - D * kap[j - 1];

		if (D != 0 && (g > 0) != (gp > 0) && g != 0 && gp != 0)
			w->brk[nb++] = cusp(x, i, (double)(j - 1) / ns, gp,
			    (double)j / ns, D);
		if (cut[j] || j == ns)
			w->brk[nb++] = (double)j / ns;
		back |= !(g > 0) || !(gp > 0);
	}
	if (offset_eval(x, i, 0, D, oa, da, NULL, NULL) != 0)
		return loft_fail(x->err, LOFT_EGEOM, (long)i, "segment %zu: "
		    "the offset is not finite at its start", i + 1);
	for (size_t j = 1; j < nb; j++) {
		double b = w->brk[j];

		if (!(b > w->brk[j - 1]))
			continue;
		if (offset_eval(x, i, b, D, ob, db, NULL, NULL) != 0)
			return loft_fail(x->err, LOFT_EGEOM, (long)i, "segment "
			    "%zu: the offset is not finite", i + 1);
		size_t n0 = *n;

		r = fit(x, arr, n, cap, i, w->brk[j - 1], b, oa, da, ob, db, D, 0);
		if (r != 0)
			return r;
		/* between cusps the offset runs backwards, or it does not */
		if (D != 0 && back && offset_eval(x, i, (w->brk[j - 1] + b) / 2,
		    D, o, NULL, NULL, &k) == 0 && 1 - D * k < 0)
			for (size_t m = n0; m < *n; m++)
				(*arr)[m].kind = BACK;
		vcopy(oa, ob, 2);
		vcopy(da, db, 2);
	}
	return 0;
}

/* ---- joins at corners --------------------------------------------------- */

static int
push_line(struct ctx *x, const double *a, const double *b, int kind)
{
	struct loft_offset_work *w = x->w;
	double p[8];

	for (int k = 0; k < 2; k++) {
		p[k] = a[k];
		p[2 + k] = a[k] + (b[k] - a[k]) / 3;
		p[4 + k] = a[k] + 2 * (b[k] - a[k]) / 3;
		p[6 + k] = b[k];
	}
	return push(&w->ch, &w->nch, &w->chcap, p, kind);
}

/* The arc of radius r about c from angle a through th, as cubics each
 * within x->tol: the error of a cubic of sweep f is at most
 * r 4/27 sin^6(f/4) / cos^2(f/4). */
static int
push_arc(struct ctx *x, const double *c, double r, double a, double th)
{
	struct loft_offset_work *w = x->w;
	int n = (int)ceil(fabs(th) / (M_PI / 2));
	double f, s, e;

	if (n < 1)
		n = 1;
	for (;;) {
		f = th / n;
		s = sin(f / 4);
		e = r * 4.0 / 27 * s * s * s * s * s * s / (cos(f / 4) * cos(f / 4));
		if (e <= x->tol || n >= 1 << 20)
			break;
		n *= 2;
	}
	for (int j = 0; j < n; j++) {
		double a0 = a + j * f, a1 = a0 + f, k = 4.0 / 3 * tan(f / 4) * r;
		double p[8];

		p[0] = c[0] + r * cos(a0);
		p[1] = c[1] + r * sin(a0);
		p[6] = c[0] + r * cos(a1);
		p[7] = c[1] + r * sin(a1);
		p[2] = p[0] - k * sin(a0);
		p[3] = p[1] + k * cos(a0);
		p[4] = p[6] + k * sin(a1);
		p[5] = p[7] - k * cos(a1);
		if (push(&w->ch, &w->nch, &w->chcap, p, JOIN_OUT) != 0)
			return -1;
	}
	return 0;
}

/*
 * The join between the raw offset of piece i at its end and of piece j
 * at its start: nothing but a snap where the tangent goes on, else the
 * join of kind join on the outer side and a straight piece on the inner.
 * The chain's last point is the end of i's offset; pj is j's start.
 */
static int
join(struct ctx *x, size_t i, size_t j, enum loft_join kind, const double *pj,
    int *snap)
{
	struct loft_offset_work *w = x->w;
	double o[2], t1[2], t2[2], c[2], p1[2], m[2], th, D = x->D, r = fabs(D);
	int e;

	*snap = 0;
	if (offset_eval(x, i, 1, 0, c, NULL, t1, NULL) != 0 ||
	    offset_eval(x, j, 0, 0, o, NULL, t2, NULL) != 0)
		return loft_fail(x->err, LOFT_EGEOM, (long)j, "segment %zu: "
		    "no direction at its start", j + 1);
	c[0] = (c[0] + o[0]) / 2;
	c[1] = (c[1] + o[1]) / 2;
	th = atan2(t1[0] * t2[1] - t1[1] * t2[0], vdot(t1, t2, 2));
	if (fabs(th) <= LOFT_OFFSET_CORNER && r * fabs(th) <= x->tol) {
		*snap = 1;
		return 0;
	}
	vcopy(p1, w->ch[w->nch - 1].p + 6, 2);
	if (fabs(th) > M_PI - 1e-9)     /* turning back: the outer side */
		th = D > 0 ? -M_PI : M_PI;
	if (D * th > 0)
		e = push_line(x, p1, pj, JOIN_IN);
	else if (kind == LOFT_JOIN_ROUND)
		e = push_arc(x, c, r, atan2(p1[1] - c[1], p1[0] - c[0]), th);
	else if (kind == LOFT_JOIN_MITER &&
	    1 / cos(th / 2) <= LOFT_OFFSET_MITER_LIMIT) {
		m[0] = p1[0] + t1[0] * r * tan(fabs(th) / 2);
		m[1] = p1[1] + t1[1] * r * tan(fabs(th) / 2);
		e = push_line(x, p1, m, JOIN_OUT) ||
		    push_line(x, m, pj, JOIN_OUT);
	} else
		e = push_line(x, p1, pj, JOIN_OUT);
	if (e != 0)
		return LOFT_ENOMEM;
	/* the join starts where the offset ended and ends where j's starts */
	vcopy(w->ch[w->nch - 1].p + 6, pj, 2);
	return 0;
}

/* ---- trees of boxes over pieces in their order along the curve --------- */

static long
build(struct node **nd, size_t *nn, size_t *cap, const struct bz *b,
    size_t lo, size_t hi)
{
	long me = (long)*nn, l = -1, r = -1;
	double box[4];

	if (loft__grow((void **)nd, cap, *nn + 1, sizeof **nd) != 0)
		return -2;
	(*nn)++;
	if (hi - lo == 1) {
		bz_box(b[lo].p, box);
	} else {
		size_t mid = lo + (hi - lo) / 2;

		if ((l = build(nd, nn, cap, b, lo, mid)) < 0 ||
		    (r = build(nd, nn, cap, b, mid, hi)) < 0)
			return -2;
		for (int k = 0; k < 2; k++) {
			box[k] = fmin((*nd)[l].box[k], (*nd)[r].box[k]);
			box[2 + k] = fmax((*nd)[l].box[2 + k], (*nd)[r].box[2 + k]);
		}
	}
	memcpy((*nd)[me].box, box, sizeof box);
	(*nd)[me].lo = lo;
	(*nd)[me].hi = hi;
	(*nd)[me].l = l;
	(*nd)[me].r = r;
	return me;
}

/* Whether the cubic b comes nearer q than sqrt(r2) (to within flat). */
static int
near_bz(const double *b, const double *q, double r2, double flat, int depth)
{
	double box[4], l[8], r[8];

	bz_box(b, box);
	if (box_dist2(box, q) >= r2)
		return 0;
	if (depth >= 40 || bz_flat(b, flat))
		return vsegdist2(b, b + 6, q, 2) < r2;
	loft_bezier_split(b, 3, 2, 0.5, l, r);
	return near_bz(l, q, r2, flat, depth + 1) ||
	    near_bz(r, q, r2, flat, depth + 1);
}

/* Whether the curve (x->w->in) comes nearer q than sqrt(r2). */
static int
near_curve(const struct ctx *x, long nd, const double *q, double r2)
{
	const struct node *n = &x->w->tin[nd];

	if (box_dist2(n->box, q) >= r2)
		return 0;
	if (n->l < 0)
		return near_bz(x->w->in[n->lo].p, q, r2, x->tol / 4, 0);
	return near_curve(x, n->l, q, r2) || near_curve(x, n->r, q, r2);
}

/* Record a crossing of chain pieces i < j at their parameters ta, tb. */
static int
add_isect(struct ctx *x, size_t i, double ta, size_t j, double tb,
    const double *pt)
{
	struct loft_offset_work *w = x->w;
	struct isect *s;

	if (GROW(w, is, iscap, w->nis + 1) != 0)
		return -1;
	s = &w->is[w->nis++];
	s->sa = (double)i + ta;
	s->sb = (double)j + tb;
	vcopy(s->pt, pt, 2);
	s->single = 0;
	return 0;
}

/* The crossings of chain pieces i and j, parts a (a0 to a1) and b. */
static int
bz_isect(struct ctx *x, size_t i, const double *a, double a0, double a1,
    size_t j, const double *b, double b0, double b1, int depth)
{
	double ba[4], bb[4], al[8], ar[8], bl[8], br[8], eps = x->tol * 1e-3;

	if (++x->work > ISECT_WORK * (x->w->nch + 16))
		return 1;
	bz_box(a, ba);
	bz_box(b, bb);
	if (!box_overlap(ba, bb))
		return 0;
	if (depth >= ISECT_DEPTH || (bz_flat(a, eps) && bz_flat(b, eps))) {
		double da[2], db[2], e[2], den, s, t, lim = 1e-9;

		vsub(da, a + 6, a, 2);
		vsub(db, b + 6, b, 2);
		vsub(e, b, a, 2);
		den = da[0] * db[1] - da[1] * db[0];
		if (!(fabs(den) > 1e-14 * vnorm(da, 2) * vnorm(db, 2)))
			return 0;
		s = (e[0] * db[1] - e[1] * db[0]) / den;
		t = (e[0] * da[1] - e[1] * da[0]) / den;
		if (s < -lim || s > 1 + lim || t < -lim || t > 1 + lim)
			return 0;
		e[0] = a[0] + s * da[0];
		e[1] = a[1] + s * da[1];
		return add_isect(x, i, a0 + s * (a1 - a0), j,
		    b0 + t * (b1 - b0), e) ? -1 : 0;
	}
	loft_bezier_split(a, 3, 2, 0.5, al, ar);
	loft_bezier_split(b, 3, 2, 0.5, bl, br);
	{
		double am = (a0 + a1) / 2, bm = (b0 + b1) / 2;
		int r;

		if ((r = bz_isect(x, i, al, a0, am, j, bl, b0, bm, depth + 1)) ||
		    (r = bz_isect(x, i, al, a0, am, j, br, bm, b1, depth + 1)) ||
		    (r = bz_isect(x, i, ar, am, a1, j, bl, b0, bm, depth + 1)) ||
		    (r = bz_isect(x, i, ar, am, a1, j, br, bm, b1, depth + 1)))
			return r;
	}
	return 0;
}

/* Chain pieces i and j are neighbours along the offset. */
static int
adjacent(const struct ctx *x, size_t i, size_t j)
{
	size_t n = x->w->nch;

	return i == j || i + 1 == j || j + 1 == i ||
	    (x->closed && ((i == 0 && j == n - 1) || (j == 0 && i == n - 1)));
}

/* The crossings between the pieces under tree nodes p and q. */
static int
pairs(struct ctx *x, long p, long q)
{
	const struct node *a = &x->w->tch[p], *b = &x->w->tch[q];
	int r;

	if (!box_overlap(a->box, b->box))
		return 0;
	if (++x->work > ISECT_WORK * (x->w->nch + 16))
		return 1;
	if (p == q) {
		if (a->l < 0)
			return 0;
		if ((r = pairs(x, a->l, a->l)) || (r = pairs(x, a->r, a->r)))
			return r;
		return pairs(x, a->l, a->r);
	}
	if (a->l < 0 && b->l < 0) {
		size_t i = a->lo, j = b->lo;

		if (adjacent(x, i, j))
			return 0;
		if (i > j)
			return bz_isect(x, j, x->w->ch[j].p, 0, 1, i,
			    x->w->ch[i].p, 0, 1, 0);
		return bz_isect(x, i, x->w->ch[i].p, 0, 1, j, x->w->ch[j].p,
		    0, 1, 0);
	}
	if (b->l < 0 || (a->l >= 0 && a->hi - a->lo >= b->hi - b->lo)) {
		if ((r = pairs(x, a->l, q)))
			return r;
		return pairs(x, a->r, q);
	}
	if ((r = pairs(x, p, b->l)))
		return r;
	return pairs(x, p, b->r);
}

static int
cmp_isect(const void *a, const void *b)
{
	const struct isect *p = a, *q = b;

	if (p->sa != q->sa)
		return p->sa < q->sa ? -1 : 1;
	return (p->sb > q->sb) - (p->sb < q->sb);
}

static int
cmp_cut(const void *a, const void *b)
{
	const struct cut *p = a, *q = b;

	if (p->s != q->s)
		return p->s < q->s ? -1 : 1;
	return (p->is > q->is) - (p->is < q->is);
}

/* ---- runs between crossings --------------------------------------------- */

/*
 * Whether run r is of the offset running forwards, and keeps |D| from
 * the curve (less half the tolerance) at the middle of its parts, joins
 * on the outer side excepted: of every
 * part where it has at most RUN_SAMPLES, else of RUN_SAMPLES spread
 * along it.  Between two crossings the distance to the curve cannot
 * pass |D| (it could only at a crossing, or where the offset touches
 * itself), so a run is kept or cut whole and a few points judge it;
 * more than one guard against a touch that was not found.
 */
#define RUN_SAMPLES 8
static int
run_good(const struct ctx *x, const struct run *r)
{
	const struct loft_offset_work *w = x->w;
	size_t n = w->nch;
	double r0 = fabs(x->D) - 2 * x->tol, q[2], r2 = r0 * r0;
	double step = floor((r->s1 - r->s0) / RUN_SAMPLES);

	for (double g = floor(r->s0); g < r->s1; g++)
		if (fmin(r->s1 - g, 1) - fmax(r->s0 - g, 0) > 1e-12 &&
		    w->ch[(size_t)g % n].kind == BACK)
			return 0;
	if (!(r0 > 0))
		return 1;
	if (step < 1)
		step = 1;
	for (double g = floor(r->s0); g < r->s1; g += step) {
		double ta = fmax(r->s0 - g, 0), tb = fmin(r->s1 - g, 1);
		const struct bz *b = &w->ch[(size_t)g % n];

		if (tb - ta <= 1e-12 || b->kind == JOIN_OUT)
			continue;
		bz_eval(b->p, (ta + tb) / 2, q);
		if (near_curve(x, 0, q, r2))
			return 0;
	}
	return 1;
}

/* The run that follows run k: across the crossing onto the other branch
 * where that is kept, else straight on; -1 where neither is. */
static long
run_next(const struct ctx *x, long k)
{
	const struct loft_offset_work *w = x->w;
	long e = w->run[k].c1, m = (long)w->nrun, cand[2];

	if (e < 0)
		return -1;
	/* the run starting at cut c: c on a closed chain, c + 1 on an open */
	cand[0] = w->cut[e].partner < 0 ? -1 :
	    w->cut[e].partner + (x->closed ? 0 : 1);
	cand[1] = e + (x->closed ? 0 : 1);
	for (int j = 0; j < 2; j++)
		if (cand[j] >= 0 && cand[j] < m && w->run[cand[j]].good)
			return cand[j];
	return -1;
}

/* Append the pieces of run k to w->em, its ends at its crossings. */
static int
emit_run(struct ctx *x, long k)
{
	struct loft_offset_work *w = x->w;
	const struct run *r = &w->run[k];
	size_t n = w->nch, first = w->nem;
	double p[8];

	for (double g = floor(r->s0); g < r->s1; g++) {
		double ta = fmax(r->s0 - g, 0), tb = fmin(r->s1 - g, 1);

		if (tb - ta <= 1e-12)
			continue;
		bz_sub(w->ch[(size_t)g % n].p, ta, tb, p);
		if (push(&w->em, &w->nem, &w->emcap, p, RAW) != 0)
			return -1;
	}
	if (w->nem > first && r->c0 >= 0)
		vcopy(w->em[first].p, w->is[w->cut[r->c0].is].pt, 2);
	if (w->nem > first && r->c1 >= 0)
		vcopy(w->em[w->nem - 1].p + 6, w->is[w->cut[r->c1].is].pt, 2);
	return 0;
}

/* Move the pieces of w->em into out as one part, in the curve's units:
 * tiny pieces dropped, ends joined exactly; closed parts turning the
 * wrong way (loops) dropped.  area: the curve's, for the sense. */
static int
put_part(struct ctx *x, struct loft_offset *out, int closed, double area)
{
	struct loft_offset_work *w = x->w;
	size_t m = 0;
	double a = 0, S = x->size, tiny = TINY_PIECE * 100;

	double all[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };

	for (size_t i = 0; i < w->nem; i++) {
		double box[4];

		bz_box(w->em[i].p, box);
		for (int k = 0; k < 2; k++) {
			all[k] = fmin(all[k], box[k]);
			all[2 + k] = fmax(all[2 + k], box[2 + k]);
		}
		if (box[2] - box[0] <= tiny && box[3] - box[1] <= tiny)
			continue;
		if (m > 0)
			vcopy(w->em[i].p, w->em[m - 1].p + 6, 2);
		w->em[m++] = w->em[i];
	}
	/* a sliver of an open curve's offset, as the tails of chain() */
	if (m == 0 || (!closed && len2(all[2] - all[0], all[3] - all[1]) <=
	    TAIL_MAX * 4 * x->tol))
		return 0;
	if (closed)
		vcopy(w->em[m - 1].p + 6, w->em[0].p, 2);
	if (closed && area != 0) {
		for (size_t i = 0; i < m; i++)
			a += bz_area2(w->em[i].p);
		if (!(a * area > 0))
			return 0;
	}
	if (loft__grow((void **)&out->seg, &out->segcap, 8 * (out->nseg + m),
	    sizeof *out->seg) != 0 || loft__grow((void **)&out->part,
	    &out->partcap, out->npart + 1, sizeof *out->part) != 0)
		return LOFT_ENOMEM;
	out->part[out->npart].first = out->nseg;
	out->part[out->npart].n = m;
	out->part[out->npart].closed = closed;
	out->npart++;
	for (size_t i = 0; i < m; i++) {
		const double *b = w->em[i].p;
		double *s = out->seg + 8 * out->nseg++;

		for (int k = 0; k < 2; k++) {
			s[k] = x->org[k] + S * b[k];
			s[2 + k] = x->org[k] + S * b[6 + k];
			s[4 + k] = 3 * S * (b[2 + k] - b[k]);
			s[6 + k] = 3 * S * (b[6 + k] - b[4 + k]);
		}
		for (int k = 0; k < 8; k++)
			if (!isfinite(s[k]))
				return loft_fail(x->err, LOFT_EGEOM, -1, "the "
				    "offset is too large for a double");
	}
	/* the rows join exactly, as splinefit's do */
	for (size_t i = out->part[out->npart - 1].first + 1; i < out->nseg; i++)
		vcopy(out->seg + 8 * i, out->seg + 8 * (i - 1) + 2, 2);
	if (closed)
		vcopy(out->seg + 8 * (out->nseg - 1) + 2,
		    out->seg + 8 * out->part[out->npart - 1].first, 2);
	return 0;
}

/* ---- the whole ------------------------------------------------------------ */

/* The frame, the pieces that are points, the gaps; 0 or LOFT_E*. */
static int
frame(struct ctx *x)
{
	const struct loft_curve *c = x->c;
	struct loft_offset_work *w = x->w;
	double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
	double p[LOFT_MAXDIM], e[2], q[LOFT_MAXDIM], size;
	/* a polynomial of degree m that takes one value at m + 1 points is
	 * constant: so many samples tell a piece that is a point */
	size_t ns = c->npts > 5 ? c->npts - 1 : 4, n = c->npieces;

	if (GROW(w, skip, skipcap, n) != 0)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j <= ns; j++) {
			loft_curve_eval(c, i, (double)j / ns, p, NULL, NULL);
			for (int k = 0; k < 2; k++) {
				if (!isfinite(p[k]))
					return loft_fail(x->err, LOFT_EGEOM,
					    (long)i, "segment %zu overflows: "
					    "coefficients too large", i + 1);
				lo[k] = fmin(lo[k], p[k]);
				hi[k] = fmax(hi[k], p[k]);
			}
		}
	size = fmax(hi[0] / 2 - lo[0] / 2, hi[1] / 2 - lo[1] / 2) * 2;
	if (!(size > 0) || !isfinite(size))
		return loft_fail(x->err, LOFT_EGEOM, -1, size > 0 ? "the curve "
		    "is too large" : "the curve is a single point: no offset");
	x->size = size;
	x->org[0] = lo[0] / 2 + hi[0] / 2;
	x->org[1] = lo[1] / 2 + hi[1] / 2;
	for (size_t i = 0; i < n; i++) {
		double p0[2], d[2], dd[2], ext = 0;

		w->skip[i] = 0;
		if (frame_eval(x, i, 0, p0, d, dd) != 0)
			return loft_fail(x->err, LOFT_EGEOM, (long)i, "segment "
			    "%zu overflows: coefficients too large", i + 1);
		for (size_t j = 1; j <= ns; j++) {
			if (frame_eval(x, i, (double)j / ns, e, d, dd) != 0)
				return loft_fail(x->err, LOFT_EGEOM, (long)i,
				    "segment %zu overflows: coefficients too "
				    "large", i + 1);
			ext = fmax(ext, vdist(e, p0, 2));
		}
		w->skip[i] = ext <= TINY_PIECE;
		if (i + 1 < n || x->closed) {
			size_t j = (i + 1) % n;

			if (frame_eval(x, j, 0, q, d, dd) != 0)
				return loft_fail(x->err, LOFT_EGEOM, (long)j,
				    "segment %zu overflows: coefficients too "
				    "large", j + 1);
			if (!(vdist(e, q, 2) <= GAP_TOL))
				return loft_fail(x->err, LOFT_EGEOM, (long)j,
				    j == 0 ? "the curve is closed but its last "
				    "segment does not end where the first "
				    "starts" : "segment %zu does not start "
				    "where segment %zu ends: no offset of a "
				    "broken curve", j + 1, i + 1);
		}
	}
	return 0;
}

/* Fit the curve itself into w->in and return twice its area (closed). */
static int
fit_curve(struct ctx *x, double *area)
{
	struct loft_offset_work *w = x->w;
	int r;

	w->nin = 0;
	*area = 0;
	for (size_t i = 0; i < x->c->npieces; i++)
		if (!w->skip[i] &&
		    (r = fit_piece(x, &w->in, &w->nin, &w->incap, i, 0)) != 0)
			return r;
	if (w->nin == 0)
		return loft_fail(x->err, LOFT_EGEOM, -1, "the curve is a "
		    "single point: no offset");
	for (size_t i = 0; i < w->nin; i++)
		*area += bz_area2(w->in[i].p);
	return 0;
}

/* Move the end point a and the start point b to where they meet. */
static void
meet(double *a, double *b)
{
	a[0] = b[0] = (a[0] + b[0]) / 2;
	a[1] = b[1] = (a[1] + b[1]) / 2;
}

/* The raw offset, joins and all, into w->ch. */
static int
raw_offset(struct ctx *x, enum loft_join kind)
{
	struct loft_offset_work *w = x->w;
	size_t n = x->c->npieces, prev = (size_t)-1, first = (size_t)-1;
	size_t start = 0;
	int r, snap;

	w->nch = 0;
	for (size_t i = 0; i < n; i++) {
		if (w->skip[i])
			continue;
		start = w->nch;
		if ((r = fit_piece(x, &w->ch, &w->nch, &w->chcap, i, x->D)) != 0)
			return r;
		if (prev == (size_t)-1) {
			first = i;
		} else {
			/* the join goes between the two, so fit first and
			 * move this piece's offset after it */
			size_t cnt = w->nch - start;
			double pj[2];

			vcopy(pj, w->ch[start].p, 2);
			if (GROW(w, em, emcap, cnt) != 0)
				return LOFT_ENOMEM;
			memcpy(w->em, w->ch + start, cnt * sizeof *w->em);
			w->nch = start;
			if ((r = join(x, prev, i, kind, pj, &snap)) != 0)
				return r;
			if (GROW(w, ch, chcap, w->nch + cnt) != 0)
				return LOFT_ENOMEM;
			memcpy(w->ch + w->nch, w->em, cnt * sizeof *w->em);
			if (snap)
				meet(w->ch[w->nch - 1].p + 6, w->ch[w->nch].p);
			w->nch += cnt;
		}
		prev = i;
	}
	if (x->closed) {
		double pj[2];

		vcopy(pj, w->ch[0].p, 2);
		if ((r = join(x, prev, first, kind, pj, &snap)) != 0)
			return r;
		if (snap)
			meet(w->ch[w->nch - 1].p + 6, w->ch[0].p);
		vcopy(w->ch[0].p, w->ch[w->nch - 1].p + 6, 2);
	}
	return 0;
}

/*
 * Drop each stretch of the raw offset that runs backwards and is no
 * larger than the tolerance, joining the pieces either side where they
 * meet: a swallowtail so small that its fitted pieces need not cross
 * (the fit may stray by a quarter of the tolerance), which would
 * otherwise condemn the whole run it lies in.  A stretch across the
 * closing join of a closed chain is left to the crossings.
 */
static void
drop_small_backs(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	size_t m = 0, n = w->nch;

	for (size_t i = 0; i < n;) {
		size_t j = i;
		double box[4], b[4];

		if (w->ch[i].kind != BACK) {
			w->ch[m++] = w->ch[i++];
			continue;
		}
		bz_box(w->ch[i].p, box);
		for (; j < n && w->ch[j].kind == BACK; j++) {
			bz_box(w->ch[j].p, b);
			for (int k = 0; k < 2; k++) {
				box[k] = fmin(box[k], b[k]);
				box[2 + k] = fmax(box[2 + k], b[2 + k]);
			}
		}
		if (len2(box[2] - box[0], box[3] - box[1]) > 4 * x->tol ||
		    m == 0 || j == n) {
			while (i < j)
				w->ch[m++] = w->ch[i++];
			continue;
		}
		meet(w->ch[m - 1].p + 6, w->ch[j].p);
		i = j;
	}
	w->nch = m;
}

/* The cuts of the crossings in w->is, two each (one for a single), in
 * order along the raw offset, and their partners. */
static int
make_cuts(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	size_t m = w->nis, n = 0;
	long *seen;

	if (GROW(w, cut, cutcap, 2 * m + 1) != 0 ||
	    GROW(w, comp, compcap, m + 1) != 0)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < m; i++) {
		w->cut[n].s = w->is[i].sa;
		w->cut[n].partner = -1;
		w->cut[n++].is = i;
		if (w->is[i].single)
			continue;
		w->cut[n].s = w->is[i].sb;
		w->cut[n].partner = -1;
		w->cut[n++].is = i;
	}
	w->ncut = n;
	if (n > 1)              /* qsort wants an array, even of none */
		qsort(w->cut, n, sizeof *w->cut, cmp_cut);
	seen = w->comp;
	for (size_t i = 0; i < m; i++)
		seen[i] = -1;
	for (size_t c = 0; c < n; c++) {
		size_t i = w->cut[c].is;

		if (seen[i] < 0) {
			seen[i] = (long)c;
		} else {
			w->cut[c].partner = seen[i];
			w->cut[seen[i]].partner = (long)c;
		}
	}
	return 0;
}

/* Whether the raw offset at s keeps |D| from the curve, less half the
 * tolerance (an outer join always does, a backward stretch never). */
static int
keeps(const struct ctx *x, double s)
{
	const struct loft_offset_work *w = x->w;
	size_t k = s >= (double)w->nch ? w->nch - 1 : (size_t)s;
	double r0 = fabs(x->D) - 2 * x->tol, q[2];

	if (w->ch[k].kind == JOIN_OUT)
		return 1;
	if (w->ch[k].kind == BACK)
		return 0;
	bz_eval(w->ch[k].p, s - (double)k, q);
	return !(r0 > 0) || !near_curve(x, 0, q, r0 * r0);
}

/*
 * An open curve has ends, and near its ends the offset may come nearer
 * the curve than |D| without crossing itself: where it passes the end
 * of the curve (an outline whose ends nearly meet).  Within each run
 * between crossings, at its ends and at END_SAMPLES points of each of
 * its pieces, find where the offset starts or stops keeping |D| from
 * the curve, and cut there too (by bisection, to PARAM_EQ): a single cut,
 * without a partner.
 */
#define END_SAMPLES 8
static int
end_cuts(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	size_t K = w->ncut;
	double N = (double)w->nch;

	for (size_t j = 0; j <= K; j++) {
		double a = j > 0 ? w->cut[j - 1].s : 0, b = j < K ? w->cut[j].s : N;
		double h = fmin((b - a) / 4, 1e-6), lo = a + h, q[2];
		int prev;

		if (!(b - a > 4 * PARAM_EQ))
			continue;
		prev = keeps(x, lo);
		for (double g = (floor(lo * END_SAMPLES) + 1) / END_SAMPLES; ;
		    g += 1.0 / END_SAMPLES) {
			double hi = g < b - h ? g : b - h;
			int now = keeps(x, hi);

			if (now != prev) {
				double l = lo, u = hi;

				while (u - l > PARAM_EQ) {
					double mid = (l + u) / 2;

					if (keeps(x, mid) == prev)
						l = mid;
					else
						u = mid;
				}
				if (GROW(w, is, iscap, w->nis + 1) != 0)
					return LOFT_ENOMEM;
				bz_eval(w->ch[(size_t)l].p, l - floor(l), q);
				w->is[w->nis].sa = w->is[w->nis].sb = l;
				vcopy(w->is[w->nis].pt, q, 2);
				w->is[w->nis++].single = 1;
			}
			prev = now;
			lo = hi;
			if (hi >= b - h)
				break;
		}
	}
	return 0;
}

/* The crossings of the raw offset, sorted and each once, and the cuts. */
static int
crossings(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	double N = (double)w->nch;
	size_t m = 0;
	int r;

	w->nis = w->ntch = 0;
	x->work = 0;
	if (build(&w->tch, &w->ntch, &w->tchcap, w->ch, 0, w->nch) < 0)
		return LOFT_ENOMEM;
	if ((r = pairs(x, 0, 0)) < 0)
		return LOFT_ENOMEM;
	if (r > 0)
		return loft_fail(x->err, LOFT_EGEOM, -1, "the offset runs along "
		    "itself (parts of it overlap): it cannot be made at this "
		    "distance");
	for (size_t i = 0; i < w->nis; i++) {
		struct isect *s = &w->is[i];

		if (x->closed && s->sb >= N - PARAM_EQ)
			s->sb -= N;
		if (s->sb < s->sa) {
			double t = s->sa;

			s->sa = s->sb < 0 ? 0 : s->sb;
			s->sb = t;
		}
	}
	if (w->nis > 1)         /* qsort wants an array, even of none */
		qsort(w->is, w->nis, sizeof *w->is, cmp_isect);
	for (size_t i = 0; i < w->nis; i++) {
		int dup = 0;

		for (size_t j = m; j-- > 0 && !dup &&
		    w->is[i].sa - w->is[j].sa <= PARAM_EQ;)
			dup = fabs(w->is[i].sb - w->is[j].sb) <= PARAM_EQ;
		if (!dup)
			w->is[m++] = w->is[i];
	}
	w->nis = m;
	if ((r = make_cuts(x)) != 0 || x->closed)
		return r;
	if ((r = end_cuts(x)) != 0)
		return r;
	return make_cuts(x);
}

/* The runs between the cuts, each judged. */
static int
runs(struct ctx *x)
{
	struct loft_offset_work *w = x->w;
	size_t K = w->ncut, M = x->closed ? (K ? K : 1) : K + 1;
	double N = (double)w->nch;

	if (GROW(w, run, runcap, M) != 0)
		return LOFT_ENOMEM;
	w->nrun = M;
	for (size_t j = 0; j < M; j++) {
		struct run *r = &w->run[j];

		if (x->closed && K == 0) {
			r->s0 = 0;
			r->s1 = N;
			r->c0 = r->c1 = -1;
		} else if (x->closed) {
			r->c0 = (long)j;
			r->c1 = (long)((j + 1) % K);
			r->s0 = w->cut[j].s;
			r->s1 = w->cut[r->c1].s + (j + 1 == K ? N : 0);
		} else {
			r->c0 = j > 0 ? (long)j - 1 : -1;
			r->c1 = j < K ? (long)j : -1;
			r->s0 = j > 0 ? w->cut[j - 1].s : 0;
			r->s1 = j < K ? w->cut[j].s : N;
		}
		r->seen = 0;
		r->good = run_good(x, r);
	}
	for (size_t j = 0; j < M; j++)
		w->run[j].led = 0;
	for (size_t j = 0; j < M; j++) {
		w->run[j].next = x->closed && K == 0 ? (w->run[0].good ? 0 : -1)
		    : run_next(x, (long)j);
		if (w->run[j].good && w->run[j].next >= 0)
			w->run[w->run[j].next].led = 1;
	}
	return 0;
}

/* The size of run k: the diagonal of the box of its pieces' parts. */
static double
run_size(const struct ctx *x, long k)
{
	const struct loft_offset_work *w = x->w;
	const struct run *r = &w->run[k];
	double box[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY }, b[4], p[8];

	for (double g = floor(r->s0); g < r->s1; g++) {
		double ta = fmax(r->s0 - g, 0), tb = fmin(r->s1 - g, 1);

		if (tb - ta <= 1e-12)
			continue;
		bz_sub(w->ch[(size_t)g % w->nch].p, ta, tb, p);
		bz_box(p, b);
		for (int c = 0; c < 2; c++) {
			box[c] = fmin(box[c], b[c]);
			box[2 + c] = fmax(box[2 + c], b[2 + c]);
		}
	}
	return box[2] >= box[0] ? len2(box[2] - box[0], box[3] - box[1]) : 0;
}

/* Emit the runs from k on as one part, until the next is start or is
 * none or already taken. */
static int
emit_from(struct ctx *x, struct loft_offset *out, long k, long stop,
    int closed, double area)
{
	struct loft_offset_work *w = x->w;

	w->nem = 0;
	do {
		w->run[k].seen = -1;
		if (emit_run(x, k) != 0)
			return LOFT_ENOMEM;
		k = w->run[k].next;
	} while (k >= 0 && k != stop && w->run[k].seen != -1);
	return put_part(x, out, closed, area);
}

/*
 * Chain the kept runs into parts and write them to out.  Each kept run
 * leads to one other or none (run_next), so the runs of a closed curve
 * fall into cycles, the parts, and tails that lead into them or end:
 * a tail no larger than TAIL_MAX tolerances is a sliver between
 * crossings that came close together (where three branches of the
 * offset nearly meet, the runs between them are short and stay within
 * the tolerance of the distance), and is dropped; a larger one means
 * the crossings were not all found.  An open curve's parts start at the
 * kept runs that no kept run leads to.
 */
static int
chain(struct ctx *x, struct loft_offset *out, double area)
{
	struct loft_offset_work *w = x->w;
	size_t M = w->nrun;
	long walk = 0;
	int r;

	if (!x->closed) {
		for (size_t j = 0; j < M; j++)
			if (w->run[j].good && !w->run[j].led && !w->run[j].seen &&
			    (r = emit_from(x, out, (long)j, -1, 0, 0)) != 0)
				return r;
		for (size_t j = 0; j < M; j++)  /* loops left over */
			if (w->run[j].good && !w->run[j].seen &&
			    (r = emit_from(x, out, (long)j, (long)j, 1, 0)) != 0)
				return r;
		return 0;
	}
	for (size_t j = 0; j < M; j++) {
		long k = (long)j;

		if (!w->run[j].good || w->run[j].seen)
			continue;
		walk++;
		while (k >= 0 && w->run[k].seen == 0) {
			w->run[k].seen = walk;
			k = w->run[k].next;
		}
		if (k >= 0 && w->run[k].seen == walk &&
		    (r = emit_from(x, out, k, k, 1, area)) != 0)
			return r;
		/* what this walk marked and did not emit is a tail */
		for (long t = (long)j; t >= 0 && w->run[t].seen == walk;
		    t = w->run[t].next)
			if (run_size(x, t) > TAIL_MAX * 4 * x->tol)
				return loft_fail(x->err, LOFT_EGEOM, -1, "the "
				    "offset's pieces do not close up once its "
				    "loops are cut away: it cannot be made at "
				    "this distance");
	}
	return 0;
}

int
loft_offset_curve(const struct loft_curve *c, double dist, double tol,
    enum loft_join kind, struct loft_offset *out, struct loft_error *err)
{
	struct ctx x = { 0 };
	double area;
	int r;

	out->nseg = out->npart = 0;
	if (c->dim != 2)
		return loft_fail(err, LOFT_EINPUT, -1, "a curve of %d "
		    "coordinates: offset works on plane curves", c->dim);
	if (!isfinite(dist) || dist == 0 || !(tol >= 0) || !isfinite(tol))
		return loft_fail(err, LOFT_EINPUT, -1, "the distance must be "
		    "finite and not 0, the tolerance finite and not negative");
	if (out->work == NULL &&
	    (out->work = calloc(1, sizeof *out->work)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	x.c = c;
	x.w = out->work;
	x.err = err;
	x.closed = c->closed;
	if ((r = frame(&x)) != 0)
		return r;
	if ((r = survey(&x)) != 0)
		goto done;
	x.tol = fmax(tol > 0 ? tol / x.size : LOFT_OFFSET_TOL * fabs(dist /
	    x.size), TOL_FLOOR) / 4;
	if ((r = fit_curve(&x, &area)) != 0)
		goto done;
	if (c->closed && !(fabs(area) > 1e-9))
		return loft_fail(err, LOFT_EGEOM, -1, "the closed curve "
		    "encloses no area: it has no outward side");
	/* outward is to the right of a counter-clockwise curve */
	x.D = dist / x.size * (c->closed && area > 0 ? -1 : 1);
	if (!isfinite(x.D) || fabs(x.D) > 1e12)
		return loft_fail(err, LOFT_EINPUT, -1, "the distance is more "
		    "than 1e12 times the curve's size");
	if (x.w->ntin = 0, build(&x.w->tin, &x.w->ntin, &x.w->tincap, x.w->in,
	    0, x.w->nin) < 0) {
		r = LOFT_ENOMEM;
		goto done;
	}
	if ((r = raw_offset(&x, kind)) == 0)
		drop_small_backs(&x);
	if (r != 0 || (r = crossings(&x)) != 0 ||
	    (r = runs(&x)) != 0 || (r = chain(&x, out, area)) != 0)
		goto done;
	if (out->npart == 0 && c->closed && dist < 0)
		return loft_fail(err, LOFT_EGEOM, -1, "the offset vanishes: "
		    "%.6g inward is more than the outline's inradius", -dist);
	if (out->npart == 0)
		return loft_fail(err, LOFT_EGEOM, -1, "the offset vanishes: "
		    "the curve bends more sharply than %.6g everywhere",
		    fabs(dist));
	return 0;
done:
	if (r == LOFT_ENOMEM)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	return r;
}

void
loft_offset_free(struct loft_offset *o)
{
	struct loft_offset_work *w = o->work;

	if (w != NULL) {
		free(w->in); free(w->ch); free(w->em); free(w->tin);
		free(w->tch); free(w->is); free(w->cut); free(w->run);
		free(w->comp); free(w->brk); free(w->skip);
		free(w->cutat); free(w->kap);
		free(w);
	}
	free(o->seg);
	free(o->part);
	memset(o, 0, sizeof *o);
}
