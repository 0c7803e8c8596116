/*
 * arclen.c: arc length of curves of any record type, and its inverse:
 * adaptive Gauss-Kronrod quadrature of the speed |P'(u)| piece by piece,
 * and Newton's method on the length, safeguarded by bisection, for the
 * parameter at a given length (equal spacing along a curve).
 */
#include <math.h>

#include "internal.h"

/*
 * Kronrod's 15-point rule and the 7-point Gauss rule it extends, on
 * [-1, 1]: nodes xk (the Gauss nodes are xk[1], xk[3], xk[5] and 0) and
 * weights, as tabulated by Piessens et al., QUADPACK (1983).  The
 * Gauss rule is exact for degree 13, the Kronrod rule for degree 22;
 * |K15 - G7| estimates G7's error and so bounds K15's generously.
 */
static const double xk[8] = {
	0.991455371120812639206854697526329,
	0.949107912342758524526189684047851,
	0.864864423359769072789712788640926,
	0.741531185599394439863864773280788,
	0.586087235467691130294144845693013,
	0.405845151377397166906606412076961,
	0.207784955007898467600689403773245,
	0,
};
static const double wk[8] = {
	0.022935322010529224963732008058970,
	0.063092092629978553290700663189204,
	0.104790010322250183839876322541518,
	0.140653259715525918745189590510238,
	0.169004726639267902826583426598550,
	0.190350578064785409913256402421014,
	0.204432940075298892414161999234649,
	0.209482141084727828012999174891714,
};
static const double wg[4] = {
	0.129484966168869693270611432679082,
	0.279705391489276667901467771423780,
	0.381830050505118944950369775488975,
	0.417959183673469387755102040816327,
};

/*
 * Halving stops at this depth, intervals 2^-40 of a piece: only a
 * singular integrand (a curvature integral through a cusp) gets there.
 */
#define QUAD_DEPTH 40

/*
 * And at this many halvings in one call: a singular point costs some
 * 40 of them, so only an integrand that rounding keeps from meeting its
 * tolerance everywhere, or that is not finite, gets here.
 */
#define QUAD_BUDGET 4000

/* Newton on the length stops within this fraction of the piece's. */
#define ARC_TOL 1e-13

#define QUAD_MAXF 4

/* Newton's corrections below this fraction of a walk's fine width
 * take 3 points. */
#define SHORT_STEP 1e-3

struct quad {
	const struct loft__piece *pc;
	loft__integrand f;
	void *ctx;
	int failed;
	int deepest;            /* the deepest level accepted */
	long budget;            /* intervals it may still halve */
};

/* K15 and G7 over [a, b], and K15 of |f|: m values each (m goes with
 * the arrays, apart from *q, so that the analyser sees it never change). */
static void
gk15(struct quad *q, int m, double a, double b, double *k, double *g,
    double *kabs)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a);
	double f0[QUAD_MAXF], f1[QUAD_MAXF], f2[QUAD_MAXF];

	q->f(q->pc, c, f0, q->ctx);
	for (int j = 0; j < m; j++) {
		k[j] = wk[7] * f0[j];
		g[j] = wg[3] * f0[j];
		kabs[j] = wk[7] * fabs(f0[j]);
	}
	for (int i = 0; i < 7; i++) {
		q->f(q->pc, c - h * xk[i], f1, q->ctx);
		q->f(q->pc, c + h * xk[i], f2, q->ctx);
		for (int j = 0; j < m; j++) {
			k[j] += wk[i] * (f1[j] + f2[j]);
			kabs[j] += wk[i] * (fabs(f1[j]) + fabs(f2[j]));
			if (i % 2 == 1)
				g[j] += wg[i / 2] * (f1[j] + f2[j]);
		}
	}
	for (int j = 0; j < m; j++) {
		k[j] *= h;
		g[j] *= h;
		kabs[j] *= h;
	}
}

/* Accept [a, b] (K15 in k, G7 in g) or halve it, each half tol / 2. */
static void
adapt(struct quad *q, int m, double a, double b, const double *k,
    const double *g, const double *tol, int depth, double *sum)
{
	double k1[QUAD_MAXF], g1[QUAD_MAXF], k2[QUAD_MAXF], g2[QUAD_MAXF],
	    abs1[QUAD_MAXF], abs2[QUAD_MAXF], half[QUAD_MAXF];
	int ok = 1;

	for (int j = 0; j < m; j++) {
		if (!(fabs(k[j] - g[j]) <= tol[j]))
			ok = 0;
		if (!isfinite(k[j]))
			depth = QUAD_DEPTH;     /* halving cannot help */
	}
	if (!ok && q->budget-- <= 0)
		depth = QUAD_DEPTH;
	if (ok || depth >= QUAD_DEPTH) {
		if (!ok)
			q->failed = 1;
		if (depth > q->deepest)
			q->deepest = depth;
		for (int j = 0; j < m; j++)
			sum[j] += k[j];
		return;
	}
	gk15(q, m, a, 0.5 * (a + b), k1, g1, abs1);
	gk15(q, m, 0.5 * (a + b), b, k2, g2, abs2);
	for (int j = 0; j < m; j++)
		half[j] = 0.5 * tol[j];
	adapt(q, m, a, 0.5 * (a + b), k1, g1, half, depth + 1, sum);
	adapt(q, m, 0.5 * (a + b), b, k2, g2, half, depth + 1, sum);
}

int
loft__quad(const struct loft__piece *pc, double a, double b, int m,
    loft__integrand f, void *ctx, double rel, const double *floor,
    double *sum, int *depth)
{
	struct quad q = { pc, f, ctx, 0, 0, QUAD_BUDGET };
	double k[QUAD_MAXF], g[QUAD_MAXF], kabs[QUAD_MAXF], tol[QUAD_MAXF];

	if (!(b > a))
		return 0;
	gk15(&q, m, a, b, k, g, kabs);
	for (int j = 0; j < m; j++)
		tol[j] = rel * kabs[j] + (floor != NULL ? floor[j] * (b - a) : 0);
	adapt(&q, m, a, b, k, g, tol, 0, sum);
	if (depth != NULL)
		*depth = q.deepest;
	return q.failed ? LOFT_ENOCONV : 0;
}

void
loft__speed(const struct loft__piece *pc, double u, double *f, void *ctx)
{
	double d[LOFT_MAXDIM];

	(void)ctx;
	loft__piece_eval(pc, u, NULL, d, NULL);
	f[0] = vnorm(d, pc->dim);
}

/* The length of piece pc over [a, b]; *depth the deepest halving. */
static double
piece_arc(const struct loft__piece *pc, double a, double b, int *depth)
{
	double s = 0;

	loft__quad(pc, a, b, 1, loft__speed, NULL, LOFT_ARC_REL, NULL, &s,
	    depth);
	return s;
}

double
loft_curve_arc(const struct loft_curve *c, double u0, double u1)
{
	struct loft__piece pc;
	double s = 0, sign = 1, top = (double)c->npieces;

	if (u1 < u0) {
		double t = u0;

		u0 = u1;
		u1 = t;
		sign = -1;
	}
	u0 = fmax(u0, 0);
	u1 = fmin(u1, top);
	for (size_t i = (size_t)u0; i < c->npieces && (double)i < u1; i++) {
		loft__piece(c, i, 0, &pc);
		s += piece_arc(&pc, fmax(u0 - (double)i, 0),
		    fmin(u1 - (double)i, 1), NULL);
	}
	return sign * s;
}

double
loft_curve_length(const struct loft_curve *c)
{
	return loft_curve_arc(c, 0, (double)c->npieces);
}

/*
 * A piece being walked by arc length: its length, and the widest
 * interval fine on which a fixed rule is trusted, 2^-d where the
 * adaptive rule halved the piece d times to reach LOFT_ARC_REL: the
 * speed is as smooth over any interval that narrow as over the
 * intervals the rule accepted, and a Gauss rule's error falls with the
 * width to its order, so G7 there is as good as K15 was (for an
 * analytic speed; near a cusp the halving goes deep and fine with it).
 */
struct walk {
	struct loft__piece pc;
	double len, fine;
};

static void
walk_piece(struct walk *w, const struct loft_curve *c, size_t i)
{
	int depth = 0;

	loft__piece(c, i, 0, &w->pc);
	w->len = piece_arc(&w->pc, 0, 1, &depth);
	w->fine = ldexp(1, -depth);
}

/* The speed and its u-derivative, P'.P'' / |P'|. */
static void
speed2(const struct loft__piece *pc, double u, double *v, double *dv)
{
	double d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], m;
	int e = 0;

	loft__piece_eval(pc, u, NULL, d1, d2);
	*v = vnorm(d1, pc->dim);
	/* P'.P'' of a curve of 1e-200 underflowed to 0, and Newton's step
	 * was then taken as exact (issue 28): by a power of two first */
	m = fmax(vmaxabs(d1, pc->dim), vmaxabs(d2, pc->dim));
	if (m > 0 && m < INFINITY) {
		e = ilogb(m);
		for (int k = 0; k < pc->dim; k++) {
			d1[k] = ldexp(d1[k], -e);
			d2[k] = ldexp(d2[k], -e);
		}
	}
	*dv = *v > 0 ? ldexp(vdot(d1, d2, pc->dim) / vnorm(d1, pc->dim), e) :
	    0;
}

/*
 * The length of w's piece from a to b (either order): Gauss-Legendre's
 * 3 points on an interval below SHORT_STEP of fine (Newton's
 * corrections; their error, the width to the 7th power, is then below
 * the rounding), its 7 on one up to fine, the adaptive rule beyond.
 */
static double
walk_arc(const struct walk *w, double a, double b)
{
	static const double x3 = 0.774596669241483377035853079956480;
	double c = 0.5 * (a + b), h = 0.5 * (b - a), v0, v1, v2, s;

	if (fabs(b - a) < SHORT_STEP * w->fine) {
		loft__speed(&w->pc, c - h * x3, &v0, NULL);
		loft__speed(&w->pc, c, &v1, NULL);
		loft__speed(&w->pc, c + h * x3, &v2, NULL);
		return h * (5 * (v0 + v2) + 8 * v1) / 9;
	}
	if (fabs(b - a) <= w->fine) {
		loft__speed(&w->pc, c, &v1, NULL);
		s = wg[3] * v1;
		for (int i = 1; i < 7; i += 2) {
			loft__speed(&w->pc, c - h * xk[i], &v0, NULL);
			loft__speed(&w->pc, c + h * xk[i], &v2, NULL);
			s += wg[i / 2] * (v0 + v2);
		}
		return h * s;
	}
	return b > a ? piece_arc(&w->pc, a, b, NULL) :
	    -piece_arc(&w->pc, b, a, NULL);
}

/*
 * The local parameter in w's piece where the length from its start is
 * t, given that the length to ub is *sb <= t (on return: the length to
 * the parameter returned) and t <= the piece's length: Newton's method
 * on s(u) - t, s'(u) = |P'(u)|, the length brought up from the last
 * iterate each step, the first step of second order (s'' = P'.P''/|P'|);
 * a step that leaves the bracket, or a zero speed, bisects instead.
 * tol is the length error accepted; a Newton step whose own error
 * estimate, s'' (f / s')^2 / 2, is below tol / 4 is taken without
 * measuring again.
 */
static double
solve_piece(const struct walk *w, double ub, double *sb, double t,
    double tol)
{
	double lo = ub, hi = 1, u = ub, s = *sb, v, dv;

	if (t >= w->len) {
		*sb = w->len;
		return 1;
	}
	for (int it = 0; it < 100 && hi > lo; it++) {
		double f = s - t, next, e;

		*sb = s;
		if (fabs(f) <= tol)
			return u;
		if (f < 0)
			lo = u;
		else
			hi = u;
		speed2(&w->pc, u, &v, &dv);
		e = v > 0 ? -f / v : 0;
		/* the first step solves v h + dv h^2 / 2 = -f */
		if (it == 0 && v > 0 && v * v - 2 * dv * f > 0)
			e = -2 * f / (v + sqrt(v * v - 2 * dv * f));
		next = u + e;
		if (!(v > 0 && next > lo && next < hi))
			next = 0.5 * (lo + hi);
		else if (it > 0 && fabs(dv) * e * e <= 0.5 * tol) {
			*sb = t;
			return next;
		}
		if (next == u)
			return u;
		s += walk_arc(w, u, next);
		u = next;
	}
	*sb = s;
	return u;
}

double
loft_curve_at_length(const struct loft_curve *c, double s)
{
	struct walk w;
	double cum = 0;

	if (s <= 0)
		return 0;
	for (size_t i = 0; i < c->npieces; i++) {
		double sb = 0;

		walk_piece(&w, c, i);
		if (s < cum + w.len)
			return (double)i + solve_piece(&w, 0, &sb, s - cum,
			    ARC_TOL * w.len);
		cum += w.len;
	}
	return (double)c->npieces;
}

size_t
loft_spaced_count(double len, double step)
{
	double k = ceil(len * (1 - LOFT_SPACING_TIE) / step);

	if (!(len > 0) || !(step > 0))
		return 2;
	return k > 1e15 ? (size_t)-1 : (size_t)k + 1;
}

void
loft_curve_spaced(const struct loft_curve *c, double step, double *u,
    size_t n)
{
	struct walk w;
	double cum = 0, ub = 0, sb = 0;
	size_t i = 0, k = 1;

	u[0] = 0;
	walk_piece(&w, c, 0);
	for (; k + 1 < n; k++) {
		double t = (double)k * step;

		/* on to the piece where length t ends */
		while (t >= cum + w.len && i + 1 < c->npieces) {
			cum += w.len;
			walk_piece(&w, c, ++i);
			ub = sb = 0;
		}
		ub = solve_piece(&w, ub, &sb, t - cum, ARC_TOL * w.len);
		u[k] = (double)i + ub;
	}
	if (n > 1)
		u[n - 1] = (double)c->npieces;
}
