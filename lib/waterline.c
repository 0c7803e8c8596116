/*
 * waterline.c: a surface clipped by planes p[k] = level (a waterline, a
 * station), and integrals over the part below them.
 *
 * The part of the parameter square where every clip holds has a curved
 * edge, the level curve of a polynomial.  Integrating over it, one
 * parameter (t) is the inner: at each node of the outer one (s) the
 * inner polynomial's roots are found to rounding, and the inner integral
 * runs over the pieces between them where the clips hold, by
 * Gauss-Legendre quadrature, so a polynomial integrand of degree below
 * 2 GAUSS_N is exact there.  The outer integral is split where the curve
 * meets the edges t = 0 and t = 1 (there the inner integral has a kink)
 * and integrated adaptively: on a piece where the curve is a graph of s
 * the inner integral is smooth in s.  The roles of u and v are chosen
 * per surface so that the curve is as near as can be to a graph of s.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

#define GAUSS_N 10

/* Gauss-Legendre nodes and weights of 10 points on [-1, 1], the positive
 * half (the rule is symmetric): exact for degree 19. */
static const double gauss_x[5] = {
	0.1488743389816312108848260, 0.4333953941292471907992659,
	0.6794095682990244062343274, 0.8650633666889845107320967,
	0.9739065285171717200779640
};
static const double gauss_w[5] = {
	0.2955242247147528701738930, 0.2692667193099963550912269,
	0.2190863625159820439955349, 0.1494513491505805931457763,
	0.0666713443086881375935688
};

/* Halvings of an outer piece before its estimate is taken as it is:
 * 2^-40 of the parameter is far below what the tolerances ask on any
 * integrand that is not singular; the cap only bounds the work.  The
 * inner integrand is smooth between the roots found, and one rule of
 * GAUSS_N points is exact there on polynomials. */
#define OUTER_DEPTH 40

/* Lines of degree up to BERN_MAXDEG have their roots isolated by the
 * signs of their Bernstein coefficients (interpolated at d + 1 points:
 * the collocation matrix is well conditioned that far); a piece narrower
 * than BERN_WIDTH whose coefficients still change sign twice holds a
 * double root, a tangency, kept when the sign changes across it. */
#define BERN_MAXDEG 16
#define BERN_WIDTH 1e-12

/* Steps of the root finder after the bracket (it takes about ten), and
 * the width of bracket that is the root: a parameter's rounding. */
#define ROOT_STEPS 100
#define ROOT_WIDTH (4 * DBL_EPSILON)

#define MAXROOTS (4 * LOFT_BEZIER_MAXPTS + 8)

struct ctx {
	const struct loft_surface *s;
	const struct loft_clip *c;
	loft_clip_fn f;
	void *fctx;
	int nval, swap, tdeg, sdeg;
	int live[LOFT_CLIP_MAX];        /* the plane crosses the net's box */
	double tinv[(BERN_MAXDEG + 1) * (BERN_MAXDEG + 1)];     /* inner */
	double sinv[(BERN_MAXDEG + 1) * (BERN_MAXDEG + 1)];     /* outer */
};

/* The surface at outer s, inner t. */
static void
ev(const struct ctx *x, double s, double t, double *p, double *pu,
    double *pv)
{
	if (x->swap)
		loft_surface_eval(x->s, t, s, p, pu, pv);
	else
		loft_surface_eval(x->s, s, t, p, pu, pv);
}

/* Clip k's function at (s, t): negative where the part is kept. */
static double
gclip(const struct ctx *x, int k, double s, double t)
{
	double p[3];

	ev(x, s, t, p, NULL, NULL);
	return p[x->c->axis[k]] - x->c->level[k];
}

/* Clip k's function along a line: inner (s fixed at `fixed`, q is t)
 * or outer (t fixed, q is s). */
static double
gline(const struct ctx *x, int k, int inner, double fixed, double q)
{
	return inner ? gclip(x, k, fixed, q) : gclip(x, k, q, fixed);
}

/* The root of clip k along a line between a and b where the sign
 * changes (ga, gb the values there), by the Illinois variant of regula
 * falsi: the bracket always holds the root, and shrinks superlinearly. */
static double
bracket_root(const struct ctx *x, int k, int inner, double fixed, double a,
    double b, double ga, double gb)
{
	int side = 0;

	for (int i = 0; i < ROOT_STEPS && b - a > ROOT_WIDTH; i++) {
		double c = (a * gb - b * ga) / (gb - ga), gc;

		if (!(c > a && c < b))
			c = 0.5 * (a + b);
		gc = gline(x, k, inner, fixed, c);
		if (gc == 0)
			return c;
		if ((gc < 0) == (gb < 0)) {
			b = c;
			gb = gc;
			if (side == -1)
				ga *= 0.5;
			side = -1;
		} else {
			a = c;
			ga = gc;
			if (side == 1)
				gb *= 0.5;
			side = 1;
		}
	}
	return fabs(ga) < fabs(gb) ? a : b;
}

/* Whether the Bernstein coefficients c[0..d] change sign more than
 * once (2), once (1) or not (0). */
static int
sign_changes(const double *c, int d)
{
	int n = 0;

	for (int i = 1; i <= d && n < 2; i++)
		n += (c[i] < 0) != (c[i - 1] < 0);
	return n;
}

/* Append to r the roots of clip k in (a, b) of the line, whose function
 * there has Bernstein coefficients c[0..d]: where they change sign once
 * there is one root (variation diminishing), bracketed and found on the
 * surface itself; where more, the halves by de Casteljau's algorithm,
 * down to BERN_WIDTH (a double root: found if the sign changes). */
static int
isolate(const struct ctx *x, int k, int inner, double fixed, const double *c,
    int d, double a, double b, double *r, int nr)
{
	double lc[LOFT_BEZIER_MAXPTS], rc[LOFT_BEZIER_MAXPTS];
	int n = sign_changes(c, d);

	if (n == 0 || nr >= MAXROOTS)
		return nr;
	if (n == 1 || b - a < BERN_WIDTH) {
		double ga = gline(x, k, inner, fixed, a);
		double gb = gline(x, k, inner, fixed, b);

		if ((ga < 0) != (gb < 0))
			r[nr++] = bracket_root(x, k, inner, fixed, a, b, ga, gb);
		return nr;
	}
	loft_bezier_split(c, d, 1, 0.5, lc, rc);
	nr = isolate(x, k, inner, fixed, lc, d, a, 0.5 * (a + b), r, nr);
	return isolate(x, k, inner, fixed, rc, d, 0.5 * (a + b), b, r, nr);
}

/* Samples per degree along a line of degree above BERN_MAXDEG: a sign
 * change between samples brackets a root; two roots closer than the
 * step are missed with the sliver between them. */
#define ROOT_SAMPLES 3

/* Append to r the roots of clip k along a line of degree d by samples. */
static int
sample_roots(const struct ctx *x, int k, int inner, double fixed, int d,
    double *r, int nr)
{
	int ns = ROOT_SAMPLES * d + 4;
	double a = 0, ga = gline(x, k, inner, fixed, 0);

	for (int i = 1; i <= ns && nr < MAXROOTS; i++) {
		double b = (double)i / ns, gb = gline(x, k, inner, fixed, b);

		if ((ga < 0) != (gb < 0))
			r[nr++] = bracket_root(x, k, inner, fixed, a, b, ga, gb);
		a = b;
		ga = gb;
	}
	return nr;
}

/* Append to r the roots of every clip along a line: the clip's function
 * there is a polynomial of the line's degree d, its Bernstein
 * coefficients those that interpolate it at t = j/d (x->inv), its ends
 * the surface's own values. */
static int
line_roots(const struct ctx *x, int inner, double fixed, double *r, int nr)
{
	int d = inner ? x->tdeg : x->sdeg;
	const double *inv = inner ? x->tinv : x->sinv;

	if (d < 1 || d >= LOFT_BEZIER_MAXPTS)   /* a surface type's degrees */
		return nr;
	for (int k = 0; k < x->c->n; k++) {
		double f[LOFT_BEZIER_MAXPTS], c[LOFT_BEZIER_MAXPTS];

		if (!x->live[k])
			continue;
		if (d > BERN_MAXDEG) {
			nr = sample_roots(x, k, inner, fixed, d, r, nr);
			continue;
		}
		for (int j = 0; j <= d; j++)
			f[j] = gline(x, k, inner, fixed, (double)j / d);
		for (int i = 0; i <= d; i++) {
			c[i] = 0;
			for (int j = 0; j <= d; j++)
				c[i] += inv[i * (d + 1) + j] * f[j];
		}
		c[0] = f[0];
		c[d] = f[d];
		nr = isolate(x, k, inner, fixed, c, d, 0, 1, r, nr);
	}
	return nr;
}

/* inv: the inverse of the (d + 1)^2 matrix of B_j^d(i/d) (Bernstein
 * polynomials at equal steps), by Gauss-Jordan elimination with partial
 * pivoting; d <= BERN_MAXDEG, where it is well conditioned. */
static void
bernstein_inverse(int d, double *inv)
{
	double a[BERN_MAXDEG + 1][2 * (BERN_MAXDEG + 1)];
	int n = d + 1;

	for (int i = 0; i < n; i++) {
		double b[LOFT_BEZIER_MAXPTS];

		loft_bernstein(d, (double)i / d, b);
		for (int j = 0; j < n; j++) {
			a[i][j] = b[j];
			a[i][n + j] = i == j;
		}
	}
	for (int col = 0; col < n; col++) {
		int p = col;

		for (int i = col + 1; i < n; i++)
			if (fabs(a[i][col]) > fabs(a[p][col]))
				p = i;
		for (int j = 0; j < 2 * n; j++) {
			double t = a[col][j];

			a[col][j] = a[p][j];
			a[p][j] = t;
		}
		for (int i = 0; i < n; i++) {
			double m = a[i][col] / a[col][col];

			if (i == col)
				continue;
			for (int j = col; j < 2 * n; j++)
				a[i][j] -= m * a[col][j];
		}
	}
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
			inv[i * n + j] = a[i][n + j] / a[i][i];
}

static int
dcmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* Whether (s, t) is kept by every clip. */
static int
kept(const struct ctx *x, double s, double t)
{
	double p[3];

	ev(x, s, t, p, NULL, NULL);
	for (int k = 0; k < x->c->n; k++)
		if (!(p[x->c->axis[k]] <= x->c->level[k]))
			return 0;
	return 1;
}

/* The inner integrand at (s, t), times w, added to out. */
static void
inner_point(const struct ctx *x, double s, double t, double *out)
{
	double p[3], pu[3], pv[3];

	ev(x, s, t, p, pu, pv);
	x->f(x->fctx, p, pu, pv, 1.0, out);
}

static void
outer_point(const struct ctx *x, double unused, double s, double *out);

/* The 10-point rule of the inner (outer) integrand over [a, b]. */
static void
gauss(const struct ctx *x, int inner, double fixed, double a, double b,
    double *out)
{
	double h = 0.5 * (b - a), m = 0.5 * (a + b);

	memset(out, 0, (size_t)x->nval * sizeof *out);
	for (int i = 0; i < GAUSS_N; i++) {
		double tmp[LOFT_CLIP_MAXVAL] = { 0 };
		double q = i < 5 ? m - h * gauss_x[4 - i] : m + h * gauss_x[i - 5];
		double w = h * gauss_w[i < 5 ? 4 - i : i - 5];

		if (inner)
			inner_point(x, fixed, q, tmp);
		else
			outer_point(x, fixed, q, tmp);
		for (int k = 0; k < x->nval; k++)
			out[k] += w * tmp[k];
	}
}

/* Adaptive: the rule over [a, b] (whole) against the sum of its halves;
 * the halves are kept when they agree within tol, else each is halved. */
static void
adapt(const struct ctx *x, int inner, double fixed, double a, double b,
    const double *whole, int depth, double *acc)
{
	double l[LOFT_CLIP_MAXVAL], r[LOFT_CLIP_MAXVAL], m = 0.5 * (a + b);
	int ok = 1;

	gauss(x, inner, fixed, a, m, l);
	gauss(x, inner, fixed, m, b, r);
	for (int k = 0; k < x->nval; k++)
		if (!(fabs(l[k] + r[k] - whole[k]) <= x->c->tol[k]))
			ok = 0;
	if (ok || depth == 0 || !(m > a && m < b)) {
		for (int k = 0; k < x->nval; k++)
			acc[k] += l[k] + r[k];
		return;
	}
	adapt(x, inner, fixed, a, m, l, depth - 1, acc);
	adapt(x, inner, fixed, m, b, r, depth - 1, acc);
}

/* The integral over [a, b], adaptively, added to acc. */
static void
integrate(const struct ctx *x, int inner, double fixed, double a, double b,
    double *acc)
{
	double whole[LOFT_CLIP_MAXVAL];

	if (!(b > a))
		return;
	gauss(x, inner, fixed, a, b, whole);
	if (inner) {            /* smooth between the roots: one rule */
		for (int k = 0; k < x->nval; k++)
			acc[k] += whole[k];
		return;
	}
	adapt(x, inner, fixed, a, b, whole, OUTER_DEPTH, acc);
}

/* The inner integral at s: over the pieces of t in [0, 1] between the
 * clips' roots where the clips hold. */
static void
outer_point(const struct ctx *x, double unused, double s, double *out)
{
	double r[MAXROOTS + 2];
	int nr = 0;

	(void)unused;
	r[nr++] = 0;
	nr = line_roots(x, 1, s, r, nr);
	r[nr++] = 1;
	qsort(r, (size_t)nr, sizeof *r, dcmp);
	for (int i = 0; i + 1 < nr; i++)
		if (r[i + 1] > r[i] && kept(x, s, 0.5 * (r[i] + r[i + 1])))
			integrate(x, 1, s, r[i], r[i + 1], out);
}

static int choose_swap(const struct loft_surface *s, int axis);

/* x's surface, parameters and root finding for a clip of s by c. */
static void
setup(struct ctx *x, const struct loft_surface *s, const struct loft_clip *c)
{
	x->s = s;
	x->c = c;
	x->swap = choose_swap(s, c->axis[0]);
	x->sdeg = x->swap ? s->n : s->m;
	x->tdeg = x->swap ? s->m : s->n;
	if (x->sdeg <= BERN_MAXDEG)
		bernstein_inverse(x->sdeg, x->sinv);
	if (x->tdeg <= BERN_MAXDEG)
		bernstein_inverse(x->tdeg, x->tinv);
}

/* Which parameter is the outer: the one along which the first clip's
 * coordinate changes least, so its level curves are nearest to graphs
 * of it. */
static int
choose_swap(const struct loft_surface *s, int axis)
{
	double su = 0, sv = 0;

	for (int i = 0; i <= 4; i++)
		for (int j = 0; j <= 4; j++) {
			double p[3], pu[3], pv[3];

			loft_surface_eval(s, i / 4.0, j / 4.0, p, pu, pv);
			su += fabs(pu[axis]);
			sv += fabs(pv[axis]);
		}
	return su > sv;
}

int
loft_clip_integrate(const struct loft_surface *s, const struct loft_clip *c,
    loft_clip_fn f, void *fctx, int nval, double *acc,
    struct loft_error *err)
{
	struct ctx x;
	double r[2 * MAXROOTS + 2], lo[3], hi[3];
	int nr = 0;

	int bad = s->dim != 3 || c->n < 1 || c->n > LOFT_CLIP_MAX ||
	    nval < 1 || nval > LOFT_CLIP_MAXVAL;

	for (int k = 0; !bad && k < c->n; k++)
		bad = c->axis[k] < 0 || c->axis[k] > 2;
	if (bad)
		return loft_fail(err, LOFT_EINPUT, -1, "a clip needs a surface "
		    "in space, 1 to %d planes of x, y or z and 1 to %d "
		    "integrands",
		    LOFT_CLIP_MAX, LOFT_CLIP_MAXVAL);
	setup(&x, s, c);
	x.f = f;
	x.fctx = fctx;
	x.nval = nval;
	loft_surface_box(s, lo, hi);
	for (int k = 0; k < c->n; k++) {
		if (lo[c->axis[k]] >= c->level[k])
			return 0;       /* nothing kept */
		x.live[k] = hi[c->axis[k]] > c->level[k];
	}
	/* the outer pieces: split where a clip's curve meets t = 0 or 1 */
	r[nr++] = 0;
	nr = line_roots(&x, 0, 0.0, r, nr);
	nr = line_roots(&x, 0, 1.0, r, nr);
	r[nr++] = 1;
	qsort(r, (size_t)nr, sizeof *r, dcmp);
	for (int i = 0; i + 1 < nr; i++)
		integrate(&x, 0, 0.0, r[i], r[i + 1], acc);
	return 0;
}

/* The point of clip 0's curve on the line of outer s nearest to t0,
 * into p: a bracket widened from t0 until the sign changes, then its
 * root.  0 when none is found within the line. */
static int
curve_point(const struct ctx *x, double s, double t0, double *t, double *p)
{
	double g0 = gline(x, 0, 1, s, t0);

	for (double d = 1.0 / 256; d < 2; d *= 2) {
		double a = fmax(0, t0 - d), b = fmin(1, t0 + d);
		double ga = gline(x, 0, 1, s, a), gb = gline(x, 0, 1, s, b);

		if ((ga < 0) != (g0 < 0) || (gb < 0) != (g0 < 0)) {
			int left = (ga < 0) != (g0 < 0);

			*t = left ? bracket_root(x, 0, 1, s, a, t0, ga, g0) :
			    bracket_root(x, 0, 1, s, t0, b, g0, gb);
			ev(x, s, *t, p, NULL, NULL);
			return 1;
		}
		if (a == 0 && b == 1)
			break;
	}
	return 0;
}

/* Samples of the outer parameter when looking for a curve's extremes. */
#define EXT_SAMPLES 16

/* Golden-section steps refining an extreme: 0.618^40 of a sample step
 * is below rounding in the parameter, and an extreme's value is then
 * right to rounding (it is flat there). */
#define EXT_STEPS 40

/* Refine the largest of sg * p[k] along the curve near outer s0, t0. */
static double
refine_extreme(const struct ctx *x, int k, double sg, double s0, double t0,
    double best)
{
	const double g = 0.6180339887498949;
	double a = fmax(0, s0 - 1.0 / EXT_SAMPLES);
	double b = fmin(1, s0 + 1.0 / EXT_SAMPLES);
	double t = t0, p[3];

	for (int i = 0; i < EXT_STEPS; i++) {
		double s1 = b - g * (b - a), s2 = a + g * (b - a), f1, f2, t1, t2;

		if (!curve_point(x, s1, t, &t1, p))
			break;
		f1 = sg * p[k];
		if (!curve_point(x, s2, t, &t2, p))
			break;
		f2 = sg * p[k];
		best = fmax(best, fmax(f1, f2));
		if (f1 > f2) {
			b = s2;
			t = t1;
		} else {
			a = s1;
			t = t2;
		}
	}
	return best;
}

/* The extremes found so far along a curve: best[0] the largest of
 * -p[k], best[1] of p[k], at outer s, inner t. */
struct ext {
	double best[2][3], s[2][3], t[2][3];
	int found;
};

static void
consider(const struct ctx *x, struct ext *e, double s, double t)
{
	double p[3];

	ev(x, s, t, p, NULL, NULL);
	for (int k = 0; k < 3; k++)
		for (int g = 0; g < 2; g++) {
			double v = g ? p[k] : -p[k];

			if (!e->found || v > e->best[g][k]) {
				e->best[g][k] = v;
				e->s[g][k] = s;
				e->t[g][k] = t;
			}
		}
	e->found = 1;
}

int
loft_clip_extremes(const struct loft_surface *s, int axis, double level,
    int refine, double *lo, double *hi)
{
	struct loft_clip c = { 1, { axis, 0 }, { level, 0 }, { 0 } };
	struct ctx x;
	struct ext e;

	memset(&x, 0, sizeof x);
	setup(&x, s, &c);
	x.live[0] = 1;
	e.found = 0;
	for (int i = 0; i <= EXT_SAMPLES; i++) {
		double sv = (double)i / EXT_SAMPLES, r[MAXROOTS];
		int nr = line_roots(&x, 1, sv, r, 0);

		for (int j = 0; j < nr; j++)
			consider(&x, &e, sv, r[j]);
	}
	/* where the curve meets the edges t = 0 and t = 1 */
	for (int side = 0; side < 2; side++) {
		double r[MAXROOTS];
		int nr = line_roots(&x, 0, (double)side, r, 0);

		for (int j = 0; j < nr; j++)
			consider(&x, &e, r[j], (double)side);
	}
	if (!e.found)
		return LOFT_EGEOM;
	for (int k = 0; refine && k < 3; k++)
		for (int g = 0; k != axis && g < 2; g++)
			e.best[g][k] = refine_extreme(&x, k, g ? 1 : -1,
			    e.s[g][k], e.t[g][k], e.best[g][k]);
	for (int k = 0; k < 3; k++) {
		lo[k] = -e.best[0][k];
		hi[k] = e.best[1][k];
	}
	return 0;
}

/* Seeds per direction of loft_surface_meet's Newton iterations, and its
 * steps: Newton from the nearest seed converges in a few; the rest of
 * the steps polish to rounding or give up on a seed that wanders. */
#define MEET_SEEDS 6
#define MEET_STEPS 40

/* A point meets both planes when it is off them by at most this part
 * of the surface's size: rounding of its coordinates. */
#define MEET_TOL 1e-12

/* Newton's iterations from (u, v) on the two planes' residuals, the
 * parameters kept in [0, 1]; 0 and the point in p when it converged. */
static int
meet_newton(const struct loft_surface *s, int a, double la, int b,
    double lb, double u, double v, double size, double *p)
{
	for (int i = 0; i < MEET_STEPS; i++) {
		double pu[3], pv[3], fa, fb, det, du, dv;

		loft_surface_eval(s, u, v, p, pu, pv);
		fa = p[a] - la;
		fb = p[b] - lb;
		det = pu[a] * pv[b] - pv[a] * pu[b];
		if (!(fabs(det) > 0))
			return -1;
		du = (fa * pv[b] - fb * pv[a]) / det;
		dv = (pu[a] * fb - pu[b] * fa) / det;
		u = fmin(1, fmax(0, u - du));
		v = fmin(1, fmax(0, v - dv));
		if (fabs(du) + fabs(dv) <= 4 * DBL_EPSILON)
			break;
	}
	loft_surface_eval(s, u, v, p, NULL, NULL);
	return fabs(p[a] - la) <= MEET_TOL * size &&
	    fabs(p[b] - lb) <= MEET_TOL * size ? 0 : -1;
}

int
loft_surface_meet(const struct loft_surface *s, int a, double la, int b,
    double lb, int k, double *best)
{
	double lo[3], hi[3], size = 0;
	int found = 0;

	loft_surface_box(s, lo, hi);
	for (int i = 0; i < 3; i++)
		size = fmax(size, hi[i] - lo[i]);
	if (la < lo[a] || la > hi[a] || lb < lo[b] || lb > hi[b])
		return LOFT_EGEOM;
	for (int i = 0; i < MEET_SEEDS; i++)
		for (int j = 0; j < MEET_SEEDS; j++) {
			double p[3];

			if (meet_newton(s, a, la, b, lb, (i + 0.5) / MEET_SEEDS,
			    (j + 0.5) / MEET_SEEDS, size, p) != 0)
				continue;
			if (!found || p[k] > *best)
				*best = p[k];
			found = 1;
		}
	return found ? 0 : LOFT_EGEOM;
}
