/*
 * bezform.c: the exact Bezier forms of loft's polynomial record types,
 * the form every CAD format takes (B-splines are Bezier pieces joined at
 * knots), and the two Bezier operations the writers need.
 * Program layer (loftcad.h, on loftprog.h): part of the CAD writers.
 */
#include "loftcad.h"
#include "internal.h"

/*
 * A quartic's Bezier points from its five conditions (the patch net
 * below maps each row and column so; a quartic curve record's own form
 * is loft_curve_bezier's, in curve.c): Q0 = (0), Q4 = (1);
 * the end derivatives are 4 (Q1 - Q0) and 4 (Q4 - Q3); and the point at
 * u = 1/2 is (Q0 + 4 Q1 + 6 Q2 + 4 Q3 + Q4) / 16, so
 * Q2 = (16 (h) - 5 (0) - 5 (1) - (0)_u + (1)_u) / 6.
 */
static void
quartic_row(const double *c0, const double *c1, const double *d0,
    const double *d1, const double *h, size_t stride, double *q)
{
	q[0] = *c0;
	q[stride] = *c0 + *d0 / 4;
	q[2 * stride] = (16 * *h - 5 * *c0 - 5 * *c1 - *d0 + *d1) / 6;
	q[3 * stride] = *c1 - *d1 / 4;
	q[4 * stride] = *c1;
}

/*
 * MacCallum's f(u, v) = u M B M^t v^t is H(u)^t B H(v) with H the five
 * blending functions; H(u)^t c is the quartic of conditions c, whose
 * Bezier points are T c with T the map of quartic_row.  So f(u, v) =
 * b(u)^t (T B T^t) b(v) with b the Bernstein basis: the net is T applied
 * to B's columns (the u conditions), then to its rows (the v ones).
 */
void
loft_patch_bezier(const double *b, int dim, double *ctl)
{
	double t[25 * LOFT_MAXDIM];
	size_t s = (size_t)dim, row = 5 * s;

	for (int j = 0; j < 5; j++)     /* column j: B[0..4][j] in u */
		for (int k = 0; k < dim; k++) {
			const double *c = b + j * s + k;

			quartic_row(c, c + row, c + 2 * row, c + 3 * row,
			    c + 4 * row, row, t + j * s + k);
		}
	for (int i = 0; i < 5; i++)     /* row i: T[i][0..4] in v */
		for (int k = 0; k < dim; k++) {
			const double *c = t + i * row + k;

			quartic_row(c, c + s, c + 2 * s, c + 3 * s, c + 4 * s, s,
			    ctl + i * row + k);
		}
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
