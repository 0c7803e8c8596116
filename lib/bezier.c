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
loft_bezier_split(const double *ctl, int deg, int dim, double t,
    double *left, double *right)
{
	double w[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	int n = deg + 1;

	memcpy(w, ctl, (size_t)n * dim * sizeof *w);
	for (int r = 0; r < n; r++) {
		/* w[0..n-r) is the r-th level of the triangle */
		if (left != NULL)
			vcopy(left + r * dim, w, dim);
		if (right != NULL)
			vcopy(right + (deg - r) * dim, w + (deg - r) * dim, dim);
		for (int i = 0; i < deg - r; i++)
			for (int k = 0; k < dim; k++)
				w[i * dim + k] += t * (w[(i + 1) * dim + k] -
				    w[i * dim + k]);
	}
}

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

/*
 * The Bernstein polynomials of degree n at t and their first and second
 * derivatives (d1, d2 may be NULL): from those of degree n - 2, raised a
 * degree at a time, d B_i^n = n (B_(i-1)^(n-1) - B_i^(n-1)) and d2 B_i^n =
 * n (n - 1) (B_(i-2)^(n-2) - 2 B_(i-1)^(n-2) + B_i^(n-2)).  O(n^2).
 */
static void
bernstein3(int n, double t, double *b, double *d1, double *d2)
{
	double lo[LOFT_BEZIER_MAXPTS + 2] = { 0 };
	double s = 1 - t;
	int k = n >= 2 ? n - 2 : 0;

	loft_bernstein(k, t, lo + 2);   /* lo[2 + i] = B_i^k, zeros before */
	for (int i = 0; i <= n; i++) {
		double a = i <= k ? lo[2 + i] : 0, bb = lo[1 + i], c = lo[i];

		if (d2 != NULL)
			d2[i] = n >= 2 ? (double)n * (n - 1) * (c - 2 * bb + a) : 0;
	}
	for (; k < n; k++) {            /* raise lo to degree k + 1 */
		lo[2 + k + 1] = 0;
		for (int i = k + 1; i >= 0; i--)
			lo[2 + i] = s * lo[2 + i] + t * lo[1 + i];
		if (k + 1 == n - 1 && d1 != NULL)
			for (int i = 0; i <= n; i++)
				d1[i] = n * ((i > 0 ? lo[1 + i] : 0) -
				    (i < n ? lo[2 + i] : 0));
	}
	if (n == 1 && d1 != NULL)
		d1[0] = -1, d1[1] = 1;
	if (n == 0 && d1 != NULL)
		d1[0] = 0;
	memcpy(b, lo + 2, (size_t)(n + 1) * sizeof *b);
}

/*
 * A Bezier surface of degrees m, n (control points u-major, 3 numbers
 * each) at (u, v) with its first and second derivatives (any of them
 * may be NULL), as sums over the Bernstein bases in u and v: O(m n) per
 * point beside the bases' O(m^2 + n^2), where a de Casteljau triangle in
 * v for every row took O(m n^2) (a 63 x 63 net sampled at -n 400 took
 * minutes).
 */
void
loft__bezier_surface_eval2(const double *ctl, int m, int n, double u,
    double v, double *p, double *pu, double *pv, double *puu, double *pvv)
{
	double bu[LOFT_BEZIER_MAXPTS + 1], du[LOFT_BEZIER_MAXPTS + 1],
	    duu[LOFT_BEZIER_MAXPTS + 1], bv[LOFT_BEZIER_MAXPTS + 1],
	    dv[LOFT_BEZIER_MAXPTS + 1], dvv[LOFT_BEZIER_MAXPTS + 1];
	double acc[5][3] = { { 0 } };

	/* the v-derivatives' sums only where asked for: the inner loop */
	int nv = pvv != NULL ? 3 : pv != NULL ? 2 : 1;
	const double *bases[3] = { bv, dv, dvv };

	bernstein3(m, u, bu, du, duu);
	bernstein3(n, v, bv, dv, dvv);
	for (int i = 0; i <= m; i++) {
		/* the row i, summed in v: point, and its v-derivatives */
		double r[3][3] = { { 0 } };
		const double *q = ctl + 3 * (size_t)i * (size_t)(n + 1);

		for (int d = 0; d < nv; d++)
			for (int j = 0; j <= n; j++)
				for (int c = 0; c < 3; c++)
					r[d][c] += bases[d][j] * q[3 * j + c];
		for (int c = 0; c < 3; c++) {
			acc[0][c] += bu[i] * r[0][c];
			acc[1][c] += du[i] * r[0][c];
			acc[2][c] += bu[i] * r[1][c];
			acc[3][c] += duu[i] * r[0][c];
			acc[4][c] += bu[i] * r[2][c];
		}
	}
	{
		double *out[5] = { p, pu, pv, puu, pvv };

		for (int d = 0; d < 5; d++)
			if (out[d] != NULL)
				memcpy(out[d], acc[d], sizeof acc[d]);
	}
}

void
loft_bezier_surface_eval(const double *ctl, int m, int n, double u,
    double v, double *p, double *pu, double *pv)
{
	loft__bezier_surface_eval2(ctl, m, n, u, v, p, pu, pv, NULL, NULL);
}
