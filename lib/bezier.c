/*
 * bezier.c: Bezier curves and surfaces (Carriazo et al., section 2):
 * B(t) = sum B_i^n(t) P_i with the Bernstein polynomials
 * B_i^n(t) = C(n, i) t^i (1 - t)^(n - i).
 */
#include <string.h>

#include "internal.h"

void
loft_bernstein(int n, double t, double *b)
{
	double s = 1 - t;

	/* b holds the degree-k polynomials after step k: B_i^k =
	 * (1 - t) B_i^(k-1) + t B_(i-1)^(k-1), all terms positive. */
	b[0] = 1;
	for (int k = 1; k <= n; k++) {
		b[k] = t * b[k - 1];
		for (int i = k - 1; i > 0; i--)
			b[i] = s * b[i] + t * b[i - 1];
		b[0] *= s;
	}
}

/* C(n, k) as a double: exact while it stays below 2^53. */
static double
binomial(int n, int k)
{
	double c = 1;

	if (k > n - k)
		k = n - k;
	for (int i = 1; i <= k; i++)
		c = c * (n - k + i) / i;
	return c;
}

double
loft_bernstein_gram(int n, int i, int j)
{
	return binomial(n, i) * binomial(n, j) /
	    ((2 * n + 1) * binomial(2 * n, i + j));
}

/*
 * One de Casteljau step on the npts points q (dim numbers each): q_i =
 * (1 - t) q_i + t q_(i+1), leaving npts - 1 points.
 */
static void
casteljau_step(double *q, size_t npts, int dim, double t)
{
	for (size_t i = 0; i + 1 < npts; i++)
		for (int k = 0; k < dim; k++)
			q[i * dim + k] += t * (q[(i + 1) * dim + k] -
			    q[i * dim + k]);
}

/*
 * Reduce to the last three points of de Casteljau's triangle: the second
 * derivative is n (n - 1) (q0 - 2 q1 + q2), the first n (r1 - r0) with
 * r the two points after one more step, and the point the last one.
 */
void
loft_bezier_eval(const double *ctl, size_t npts, int dim, double t,
    double *p, double *d1, double *d2)
{
	double q[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	double n = (double)npts - 1;

	memcpy(q, ctl, npts * dim * sizeof *q);
	for (; npts > 3; npts--)
		casteljau_step(q, npts, dim, t);
	if (d2 != NULL)
		for (int k = 0; k < dim; k++)
			d2[k] = npts < 3 ? 0 :
			    n * (n - 1) * (q[k] - 2 * q[dim + k] + q[2 * dim + k]);
	if (npts == 3)
		casteljau_step(q, npts--, dim, t);
	for (int k = 0; k < dim; k++) {
		if (d1 != NULL)
			d1[k] = npts < 2 ? 0 : n * (q[dim + k] - q[k]);
		if (p != NULL)
			p[k] = npts < 2 ? q[k] : q[k] + t * (q[dim + k] - q[k]);
	}
}

void
loft_bezier_surface_eval(const double *ctl, int m, int n, double u,
    double v, double *p, double *pu, double *pv)
{
	double row[LOFT_BEZIER_MAXPTS * 3], rowv[LOFT_BEZIER_MAXPTS * 3];

	/* each u-row of the net is a Bezier curve in v; their points and
	 * v-derivatives at v are the control points of the curve in u
	 * through (u, v) and of its v-derivative */
	for (int i = 0; i <= m; i++)
		loft_bezier_eval(ctl + 3 * i * (n + 1), (size_t)n + 1, 3, v,
		    row + 3 * i, rowv + 3 * i, NULL);
	loft_bezier_eval(row, (size_t)m + 1, 3, u, p, pu, NULL);
	if (pv != NULL)
		loft_bezier_eval(rowv, (size_t)m + 1, 3, u, pv, NULL, NULL);
}
