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

/* Newton on the length stops within this fraction of the curve's. */
#define ARC_TOL 1e-13

#define QUAD_MAXF 4

struct quad {
	const struct loft__piece *pc;
	loft__integrand f;
	void *ctx;
	int m;
	int failed;
};

/* K15 and G7 over [a, b], and K15 of |f|. */
static void
gk15(struct quad *q, double a, double b, double *k, double *g, double *kabs)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a);
	double f0[QUAD_MAXF], f1[QUAD_MAXF], f2[QUAD_MAXF];

	q->f(q->pc, c, f0, q->ctx);
	for (int j = 0; j < q->m; j++) {
		k[j] = wk[7] * f0[j];
		g[j] = wg[3] * f0[j];
		kabs[j] = wk[7] * fabs(f0[j]);
	}
	for (int i = 0; i < 7; i++) {
		q->f(q->pc, c - h * xk[i], f1, q->ctx);
		q->f(q->pc, c + h * xk[i], f2, q->ctx);
		for (int j = 0; j < q->m; j++) {
			k[j] += wk[i] * (f1[j] + f2[j]);
			kabs[j] += wk[i] * (fabs(f1[j]) + fabs(f2[j]));
			if (i % 2 == 1)
				g[j] += wg[i / 2] * (f1[j] + f2[j]);
		}
	}
	for (int j = 0; j < q->m; j++) {
		k[j] *= h;
		g[j] *= h;
		kabs[j] *= h;
	}
}

/* Accept [a, b] (K15 in k, G7 in g) or halve it, each half tol / 2. */
static void
adapt(struct quad *q, double a, double b, const double *k, const double *g,
    const double *tol, int depth, double *sum)
{
	double k1[QUAD_MAXF], g1[QUAD_MAXF], k2[QUAD_MAXF], g2[QUAD_MAXF],
	    abs1[QUAD_MAXF], abs2[QUAD_MAXF], half[QUAD_MAXF];
	int ok = 1;

	for (int j = 0; j < q->m; j++)
		if (!(fabs(k[j] - g[j]) <= tol[j]))
			ok = 0;
	if (ok || depth >= QUAD_DEPTH) {
		if (!ok)
			q->failed = 1;
		for (int j = 0; j < q->m; j++)
			sum[j] += k[j];
		return;
	}
	gk15(q, a, 0.5 * (a + b), k1, g1, abs1);
	gk15(q, 0.5 * (a + b), b, k2, g2, abs2);
	for (int j = 0; j < q->m; j++)
		half[j] = 0.5 * tol[j];
	adapt(q, a, 0.5 * (a + b), k1, g1, half, depth + 1, sum);
	adapt(q, 0.5 * (a + b), b, k2, g2, half, depth + 1, sum);
}

int
loft__quad(const struct loft__piece *pc, double a, double b, int m,
    loft__integrand f, void *ctx, double rel, const double *floor,
    double *sum)
{
	struct quad q = { pc, f, ctx, m, 0 };
	double k[QUAD_MAXF], g[QUAD_MAXF], kabs[QUAD_MAXF], tol[QUAD_MAXF];

	if (!(b > a))
		return 0;
	gk15(&q, a, b, k, g, kabs);
	for (int j = 0; j < m; j++)
		tol[j] = rel * kabs[j] + (floor != NULL ? floor[j] * (b - a) : 0);
	adapt(&q, a, b, k, g, tol, 0, sum);
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

/* The length of piece pc over [a, b]. */
static double
piece_arc(const struct loft__piece *pc, double a, double b)
{
	double s = 0;

	loft__quad(pc, a, b, 1, loft__speed, NULL, LOFT_ARC_REL, NULL, &s);
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
		loft__piece(c, i, &pc);
		s += piece_arc(&pc, fmax(u0 - (double)i, 0),
		    fmin(u1 - (double)i, 1));
	}
	return sign * s;
}

double
loft_curve_length(const struct loft_curve *c)
{
	return loft_curve_arc(c, 0, (double)c->npieces);
}

/*
 * The local parameter in piece pc where the length from its start is t,
 * given that the length to ub is *sb <= t (on return: the length to the
 * parameter returned) and the piece's whole length is
 * len >= t: Newton's method on s(u) - t, s'(u) = |P'(u)|, the length
 * brought up from the last iterate each step; a step that leaves the
 * bracket, or a zero speed, bisects instead.  tol is the length error
 * accepted.
 */
static double
solve_piece(const struct loft__piece *pc, double ub, double *sb, double t,
    double len, double tol)
{
	double lo = ub, hi = 1, u = ub, s = *sb, v;

	if (t >= len) {
		*sb = len;
		return 1;
	}
	for (int it = 0; it < 100 && hi > lo; it++) {
		double f = s - t, next;

		*sb = s;
		if (fabs(f) <= tol)
			return u;
		if (f < 0)
			lo = u;
		else
			hi = u;
		loft__speed(pc, u, &v, NULL);
		next = v > 0 ? u - f / v : -1;
		if (!(next > lo && next < hi))
			next = 0.5 * (lo + hi);
		if (next == u)
			return u;
		s += next > u ? piece_arc(pc, u, next) : -piece_arc(pc, next, u);
		u = next;
	}
	*sb = s;
	return u;
}

double
loft_curve_at_length(const struct loft_curve *c, double s)
{
	struct loft__piece pc;
	double cum = 0, tol = ARC_TOL * loft_curve_length(c);

	if (s <= 0)
		return 0;
	for (size_t i = 0; i < c->npieces; i++) {
		double len, sb = 0;

		loft__piece(c, i, &pc);
		len = piece_arc(&pc, 0, 1);
		if (s < cum + len)
			return (double)i + solve_piece(&pc, 0, &sb, s - cum, len,
			    tol);
		cum += len;
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
	struct loft__piece pc;
	double cum = 0, len = 0, ub = 0, sb = 0, tol;
	size_t i = 0, k = 1;

	tol = ARC_TOL * loft_curve_length(c);
	u[0] = 0;
	if (c->npieces > 0) {
		loft__piece(c, 0, &pc);
		len = piece_arc(&pc, 0, 1);
	}
	for (; k + 1 < n; k++) {
		double t = (double)k * step;

		/* on to the piece where length t ends */
		while (t >= cum + len && i + 1 < c->npieces) {
			cum += len;
			loft__piece(c, ++i, &pc);
			len = piece_arc(&pc, 0, 1);
			ub = sb = 0;
		}
		ub = solve_piece(&pc, ub, &sb, t - cum, len, tol);
		u[k] = (double)i + ub;
	}
	if (n > 1)
		u[n - 1] = (double)c->npieces;
}
