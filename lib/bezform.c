/*
 * bezform.c: the exact Bezier forms of loft's polynomial record types,
 * the form every CAD format takes (B-splines are Bezier pieces joined at
 * knots): the one quartic-to-Bernstein conversion, the patch's net, and
 * the steps of a Bezier curve's polyline.  Core (loft.h): curve.c,
 * surface.c and the CAD writers all use these.
 */
#include "internal.h"

void
loft_quartic_bezier(const double *k, size_t in_step, double *b,
    size_t out_step, int dim)
{
	for (int c = 0; c < dim; c++) {
		double c0 = k[c], c1 = k[in_step + c], d0 = k[2 * in_step + c],
		    d1 = k[3 * in_step + c], h = k[4 * in_step + c];

		b[c] = c0;
		b[out_step + c] = c0 + d0 / 4;
		b[2 * out_step + c] = (16 * h - 5 * c0 - 5 * c1 - d0 + d1) / 6;
		b[3 * out_step + c] = c1 - d1 / 4;
		b[4 * out_step + c] = c1;
	}
}

/*
 * MacCallum's f(u, v) = u M B M^t v^t is H(u)^t B H(v) with H the five
 * blending functions; H(u)^t c is the quartic of conditions c, whose
 * Bezier points are T c with T the map of loft_quartic_bezier.  So f(u, v) =
 * b(u)^t (T B T^t) b(v) with b the Bernstein basis: the net is T applied
 * to B's columns (the u conditions), then to its rows (the v ones).
 */
void
loft_patch_bezier(const double *b, int dim, double *ctl)
{
	double t[25 * LOFT_MAXDIM];
	size_t s = (size_t)dim, row = 5 * s;

	for (int j = 0; j < 5; j++)     /* column j: B[0..4][j] in u */
		loft_quartic_bezier(b + j * s, row, t + j * s, row, dim);
	for (int i = 0; i < 5; i++)     /* row i: T[i][0..4] in v */
		loft_quartic_bezier(t + i * row, s, ctl + i * row, s, dim);
}

long
loft_bezier_steps(const double *ctl, int deg, int dim, double tol, long max)
{
	double worst = 0, n;

	/* |C''| <= deg (deg - 1) max |P_i+2 - 2 P_i+1 + P_i| */
	for (int i = 0; i + 2 <= deg; i++) {
		double a[LOFT_MAXDIM];

		for (int k = 0; k < dim; k++)
			a[k] = ctl[(i + 2) * dim + k] - 2 * ctl[(i + 1) * dim + k] +
			    ctl[i * dim + k];
		worst = fmax(worst, vnorm(a, dim));
	}
	if (worst == 0)         /* a straight piece (or a point) */
		return 1;
	n = ceil(sqrt(deg * (deg - 1) * worst / (8 * tol)));
	if (!(n <= (double)max))        /* too many, or not a number */
		return 0;
	return n < 1 ? 1 : (long)n;
}
