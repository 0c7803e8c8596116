/*
 * bernstein.c: arithmetic and roots of polynomials on [0, 1] in the
 * Bernstein basis, sum c_i C(n, i) t^i (1 - t)^(n - i), and curve pieces
 * in that basis.  The basis suits root finding: the polynomial lies in
 * the convex hull of its coefficients, so coefficients of one sign prove
 * there is no root, and subdividing at t = 1/2 (de Casteljau) narrows
 * the hull quickly.  Measuring (measure.c), arc length (arclen.c) and
 * flattening (flatten.c) work on pieces in this form.
 */
#include <math.h>
#include <string.h>

#include "internal.h"

/*
 * Pieces of degree up to this also keep their derivatives' power
 * coefficients, for speed: converting a Bernstein polynomial of low
 * degree on [0, 1] to powers loses only a few bits (the conversion's
 * coefficients are at most C(n, j) C(j, i), 20 at degree 4).
 */
#define POWER_DEG 4

/*
 * Subdivision stops at intervals this narrow: a cluster of roots closer
 * than this (in a piece's parameter) is reported as one root.
 */
#define ROOT_WIDTH 1e-13

double
loft__bern_eval(const double *c, int n, double t)
{
	double q[LOFT__BMAX];

	memcpy(q, c, (size_t)(n + 1) * sizeof *q);
	for (int k = n; k > 0; k--)
		for (int i = 0; i < k; i++)
			q[i] += t * (q[i + 1] - q[i]);
	return q[0];
}

/* C(n, k) for k = 0..n into b, by the multiplicative rule. */
static void
binomials(int n, double *b)
{
	b[0] = 1;
	for (int k = 1; k <= n; k++)
		b[k] = b[k - 1] * (n - k + 1) / k;
}

/*
 * (f g)_k = sum over i + j = k of C(m, i) C(n, j) / C(m + n, k) f_i g_j:
 * the product of the two expansions, gathered by powers.
 */
void
loft__bern_mul(const double *f, int m, const double *g, int n, double *h)
{
	double bm[LOFT__BMAX], bn[LOFT__BMAX], bmn[LOFT__BMAX];

	binomials(m, bm);
	binomials(n, bn);
	binomials(m + n, bmn);
	for (int k = 0; k <= m + n; k++)
		h[k] = 0;
	for (int i = 0; i <= m; i++)
		for (int j = 0; j <= n; j++)
			h[i + j] += bm[i] * bn[j] * f[i] * g[j];
	for (int k = 0; k <= m + n; k++)
		h[k] /= bmn[k];
}

/*
 * Degree elevation from m to m + 1: c'_i = i / (m + 1) c_(i-1) +
 * (1 - i / (m + 1)) c_i, repeated up to n.
 */
void
loft__bern_addto(double *f, int n, double s, const double *g, int m)
{
	double e[LOFT__BMAX];

	memcpy(e, g, (size_t)(m + 1) * sizeof *e);
	for (; m < n; m++) {
		e[m + 1] = e[m];
		for (int i = m; i > 0; i--)
			e[i] = (i * e[i - 1] + (m + 1 - i) * e[i]) / (m + 1);
	}
	for (int i = 0; i <= n; i++)
		f[i] += s * e[i];
}

double
loft__bern_max(const double *c, int n)
{
	double most = 0;

	for (int i = 0; i <= n; i++)
		most = fmax(most, fabs(c[i]));
	return most;
}

/* -1, 0 or 1: the sign of x, 0 within zero of 0. */
static int
sign_of(double x, double zero)
{
	return x > zero ? 1 : x < -zero ? -1 : 0;
}

/*
 * The one root in (0, 1) of c, whose end values have opposite signs:
 * bisection to the last bits, each step a de Casteljau evaluation.
 */
static double
refine(const double *c, int n)
{
	double lo = 0, hi = 1, mid = 0.5;
	int up = c[0] < 0;

	while (mid > lo && mid < hi) {
		double v = loft__bern_eval(c, n, mid);

		if (v == 0)
			return mid;
		if ((v < 0) == up)
			lo = mid;
		else
			hi = mid;
		mid = 0.5 * (lo + hi);
	}
	return mid;
}

struct roots {
	double zero;
	double *r;
	int n, max;
};

/* The roots of c (degree n) over [a, b] of the original parameter. */
static void
roots_in(struct roots *rs, const double *c, int n, double a, double b)
{
	double left[LOFT__BMAX], right[LOFT__BMAX];
	int changes = 0, last = 0, nz = 0;

	for (int i = 0; i <= n; i++) {
		int s = sign_of(c[i], rs->zero);

		if (s == 0)
			continue;
		nz++;
		if (last != 0 && s != last)
			changes++;
		last = s;
	}
	if (nz == 0 || changes == 0 || rs->n >= rs->max)
		return;
	if (changes == 1 && sign_of(c[0], rs->zero) != 0 &&
	    sign_of(c[n], rs->zero) != 0) {
		/* one sign change between nonzero ends: exactly one root */
		rs->r[rs->n++] = a + (b - a) * refine(c, n);
		return;
	}
	if (b - a < ROOT_WIDTH) {
		rs->r[rs->n++] = 0.5 * (a + b);
		return;
	}
	/* de Casteljau at 1/2: the left edge of the triangle is the left
	 * half's coefficients, the right edge the right half's */
	memcpy(right, c, (size_t)(n + 1) * sizeof *right);
	left[0] = right[0];
	for (int k = n; k > 0; k--) {
		for (int i = 0; i < k; i++)
			right[i] = 0.5 * (right[i] + right[i + 1]);
		left[n - k + 1] = right[0];
	}
	roots_in(rs, left, n, a, 0.5 * (a + b));
	/* a root at the split point is an end of both halves, which count
	 * it as neither's: it is the halves' common coefficient */
	if (sign_of(right[0], rs->zero) == 0 && rs->n < rs->max)
		rs->r[rs->n++] = 0.5 * (a + b);
	roots_in(rs, right, n, 0.5 * (a + b), b);
}

int
loft__bern_roots(const double *c, int n, double zero, double *r, int max)
{
	struct roots rs = { zero, r, 0, max };

	roots_in(&rs, c, n, 0, 1);
	return rs.n;
}

/*
 * The power coefficients a[0..n] of the Bernstein coefficients c[0..n]:
 * a_j = C(n, j) sum over i <= j of (-1)^(j - i) C(j, i) c_i.
 */
static void
to_power(const double *c, int n, double *a)
{
	double bn[LOFT__BMAX], bj[LOFT__BMAX];

	binomials(n, bn);
	for (int j = 0; j <= n; j++) {
		double s = 0;

		binomials(j, bj);
		for (int i = 0; i <= j; i++)
			s += ((j - i) % 2 ? -bj[i] : bj[i]) * c[i];
		a[j] = bn[j] * s;
	}
}

void
loft__piece(const struct loft_curve *c, size_t i, int e,
    struct loft__piece *pc)
{
	double ctl[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	int n = loft_curve_bezier(c, i, ctl), dim = c->dim;

	pc->n = n;
	pc->dim = dim;
	for (int k = 0; k < dim; k++) {
		/* scaled before the differences, which would overflow
		 * first for control values near the largest double */
		for (int j = 0; j <= n; j++)
			pc->b[k][j] = ldexp(ctl[j * dim + k], -e);
		/* the derivative of a degree-m expansion: m (c_(j+1) - c_j) */
		for (int j = 0; j <= n; j++)
			pc->d1[k][j] = pc->d2[k][j] = pc->d3[k][j] = 0;
		for (int j = 0; j < n; j++)
			pc->d1[k][j] = n * (pc->b[k][j + 1] - pc->b[k][j]);
		for (int j = 0; j + 1 < n; j++)
			pc->d2[k][j] = (n - 1) * (pc->d1[k][j + 1] -
			    pc->d1[k][j]);
		for (int j = 0; j + 2 < n; j++)
			pc->d3[k][j] = (n - 2) * (pc->d2[k][j + 1] -
			    pc->d2[k][j]);
		if (n <= POWER_DEG) {
			to_power(pc->d1[k], n - 1, pc->p1[k]);
			to_power(pc->d2[k], LOFT__DEG(pc, 2), pc->p2[k]);
		}
	}
}

/* Horner's rule on the power coefficients a[0..n] at u. */
static double
horner(const double *a, int n, double u)
{
	double v = a[n];

	for (int j = n - 1; j >= 0; j--)
		v = v * u + a[j];
	return v;
}

void
loft__piece_eval(const struct loft__piece *pc, double u, double *p,
    double *d1, double *d2)
{
	if (pc->n <= POWER_DEG && p == NULL) {
		for (int k = 0; k < pc->dim; k++) {
			if (d1 != NULL)
				d1[k] = horner(pc->p1[k], pc->n - 1, u);
			if (d2 != NULL)
				d2[k] = horner(pc->p2[k], LOFT__DEG(pc, 2), u);
		}
		return;
	}
	for (int k = 0; k < pc->dim; k++) {
		if (p != NULL)
			p[k] = u == 1 ? pc->b[k][pc->n] :
			    loft__bern_eval(pc->b[k], pc->n, u);
		if (d1 != NULL)
			d1[k] = loft__bern_eval(pc->d1[k], LOFT__DEG(pc, 1), u);
		if (d2 != NULL)
			d2[k] = loft__bern_eval(pc->d2[k], LOFT__DEG(pc, 2), u);
	}
}

double
loft__curve_extent(const struct loft_curve *c)
{
	double ctl[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	/* zero, not unset, for a curve of no pieces (cppcheck, scan-build) */
	double lo[LOFT_MAXDIM] = { 0 }, hi[LOFT_MAXDIM] = { 0 };

	for (size_t i = 0; i < c->npieces; i++) {
		int n = loft_curve_bezier(c, i, ctl);

		for (int j = 0; j <= n; j++)
			for (int k = 0; k < c->dim; k++) {
				double x = ctl[j * c->dim + k];

				if ((i == 0 && j == 0) || x < lo[k])
					lo[k] = x;
				if ((i == 0 && j == 0) || x > hi[k])
					hi[k] = x;
			}
	}
	for (int k = 0; k < c->dim; k++)
		lo[k] = hi[k] - lo[k];
	return vnorm(lo, c->dim);       /* no square overflows (issue 28) */
}
