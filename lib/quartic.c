/*
 * quartic.c: MacCallum's quartic curve (MacCallum 1970, sections 3 and
 * 4): the blending functions H1..H5, evaluation, conversion from a cubic,
 * and dragging a curve of quartic segments.
 */
#include <stdio.h>
#include <string.h>

#include "internal.h"

/*
 * The matrix M of section 4 over the basis [u^4 u^3 u^2 u 1]:
 * H_j(u) = sum_i u^(4-i) M[i][j], for the coefficients (0), (1), (0)_u,
 * (1)_u, (h) in that order.
 */
const double loft_quartic_m[5][5] = {
	{ -8, -8, -2, 2, 16 },
	{ 18, 14, 5, -3, -32 },
	{ -11, -5, -4, 1, 16 },
	{ 0, 0, 1, 0, 0 },
	{ 1, 0, 0, 0, 0 },
};

/*
 * Section 3: H_j = [u^4 u^3 u^2 u 1] M, column j, by Horner's rule, and
 * its first and second derivatives.  At u = 0, 1/2 and 1 every step is
 * exact, so the H take their defining values 0 and 1 exactly there.
 */
void
loft_quartic_h(double u, double *h, double *dh, double *d2h)
{
	const double (*m)[5] = loft_quartic_m;

	for (int j = 0; j < 5; j++) {
		if (h != NULL)
			h[j] = (((m[0][j] * u + m[1][j]) * u + m[2][j]) * u +
			    m[3][j]) * u + m[4][j];
		if (dh != NULL)
			dh[j] = ((4 * m[0][j] * u + 3 * m[1][j]) * u +
			    2 * m[2][j]) * u + m[3][j];
		if (d2h != NULL)
			d2h[j] = (12 * m[0][j] * u + 6 * m[1][j]) * u +
			    2 * m[2][j];
	}
}

void
loft__quartic_combine(const double *const *k, int dim, double u,
    double *p, double *d1, double *d2)
{
	double h[5], dh[5], d2h[5];

	loft_quartic_h(u, h, dh, d2h);
	for (int c = 0; c < dim; c++) {
		double c1 = k[1][c] - k[0][c], ch = k[4][c] - k[0][c];

		/* H1 + H2 + H5 = 1: the value is the plain sum, exact at
		 * u = 0, 1/2, 1; derivatives are taken from differences,
		 * as the cubic's are from its chord, so they stay accurate
		 * far from the origin */
		if (p != NULL)
			p[c] = h[0] * k[0][c] + h[1] * k[1][c] + h[2] * k[2][c] +
			    h[3] * k[3][c] + h[4] * k[4][c];
		if (d1 != NULL)
			d1[c] = dh[1] * c1 + dh[4] * ch + dh[2] * k[2][c] +
			    dh[3] * k[3][c];
		if (d2 != NULL)
			d2[c] = d2h[1] * c1 + d2h[4] * ch + d2h[2] * k[2][c] +
			    d2h[3] * k[3][c];
	}
}

/*
 * Section 4: f(u) = [H1 H2 H3 H4 H5] [(0) (1) (0)_u (1)_u (h)]^t.
 */
void
loft_quartic_eval(const double *q, int dim, double u,
    double *p, double *d1, double *d2)
{
	const double *k[5];

	for (int i = 0; i < 5; i++)
		k[i] = q + i * dim;
	loft__quartic_combine(k, dim, u, p, d1, d2);
}

/*
 * A cubic P_A P_B P'_A P'_B has the same end values and slopes; its (h)
 * is eq. 7 of Manning at u = 1/2: (P_A + P_B)/2 + (P'_A - P'_B)/8.
 * The quartic through these five is the cubic itself (it is unique).
 */
void
loft_cubic_to_quartic(const double *cubic, int dim, double *q)
{
	double h[LOFT_MAXDIM] = { 0 };

	for (int c = 0; c < dim; c++)
		h[c] = (cubic[c] + cubic[dim + c]) / 2 +
		    (cubic[2 * dim + c] - cubic[3 * dim + c]) / 8;
	memmove(q, cubic, 4 * dim * sizeof *q);
	memcpy(q + 4 * dim, h, dim * sizeof *q);
}

double
loft__h5(double u)
{
	double h[5];

	loft_quartic_h(u, h, NULL, NULL);
	return h[4];
}

void
loft__bump(double a, double b, double *coef)
{
	double h[5], dh0[5], dh1[5], hm[5];

	loft_quartic_h(a, h, dh0, NULL);
	coef[0] = h[4];
	coef[2] = b * dh0[4];
	loft_quartic_h(a + b, h, dh1, NULL);
	coef[1] = h[4];
	coef[3] = b * dh1[4];
	loft_quartic_h(a + b / 2, hm, NULL, NULL);
	coef[4] = hm[4];
}

/* ------------------------------------------------------------------ */
/* Dragging a curve of quartic segments */

/*
 * Section 4.  The dragged point lies in segment i at local parameter u.
 * Central rule: delta(h) = delta / H5(u), nothing else changes.  Near an
 * end with a segment beyond it: the two segments act as one quartic in
 * w, the join at w_p = r1/(r1 + r2) (both scale factors 1 here: w_p =
 * 1/2), and each takes the exact restriction of the bump
 * delta H5(w) / H5(w_d), so the common end point moves by
 * delta H_p / H_d and its slope by delta H'_p / H_d.
 */
int
loft_quartic_drag(double *q, size_t nseg, int dim, int closed, double U,
    const double *delta, double edge, struct loft_drag_info *info,
    struct loft_error *err)
{
	size_t i, j, rows = 5 * (size_t)dim;
	double u, rho, wp = 0.5, coef_i[5], coef_j[5], hd;
	int near_end;           /* 0: start of segment i, 1: its end */

	memset(info, 0, sizeof *info);
	if (nseg == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "curve has no segments");
	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "a curve of %d "
		    "coordinates: want 2 or 3", dim);
	if (!(U >= 0 && U <= (double)nseg))
		return loft_fail(err, LOFT_EINPUT, -1, "-u %g is outside the "
		    "curve's parameter range 0 to %zu", U, nseg);
	i = U >= (double)nseg ? nseg - 1 : (size_t)U;
	u = U - (double)i;
	near_end = u > 0.5;
	rho = near_end ? 1 - u : u;
	info->piece = (long)i;
	if (rho < edge) {
		int has = near_end ? (closed || i + 1 < nseg) :
		    (closed || i > 0);

		if (has) {
			j = near_end ? (i + 1) % nseg : (i + nseg - 1) % nseg;
			if (j == i)
				has = 0;        /* closed curve of one segment */
		}
		if (has) {
			/* segment i on [0, wp] with its end at wp, segment
			 * j on [wp, 1]; H5 is symmetric, so which way each
			 * runs only flips the affine map */
			double wd = wp * (1 - rho);

			loft__bump(near_end ? 0 : wp, near_end ? wp : -wp,
			    coef_i);
			loft__bump(near_end ? wp : 1, near_end ? 1 - wp :
			    -(1 - wp), coef_j);
			hd = loft__h5(wd);
			for (int k = 0; k < 5; k++)
				for (int c = 0; c < dim; c++) {
					q[i * rows + k * dim + c] +=
					    delta[c] * coef_i[k] / hd;
					q[j * rows + k * dim + c] +=
					    delta[c] * coef_j[k] / hd;
				}
			info->rule = LOFT_DRAG_EDGE;
			info->other = (long)j;
			info->hd = hd;
			info->hp = coef_i[near_end ? 1 : 0];
			return 0;
		}
		info->rule = LOFT_DRAG_FALLBACK;
		snprintf(info->why, sizeof info->why, "%s",
		    near_end ? "the curve ends there" :
		    "the curve starts there");
	} else {
		info->rule = LOFT_DRAG_CENTRAL;
	}
	hd = loft__h5(u);
	if (!(hd > 0))
		return loft_fail(err, LOFT_EGEOM, (long)i, "the point at u = %g "
		    "is an end of the curve, which dragging keeps fixed", U);
	for (int c = 0; c < dim; c++)
		q[i * rows + 4 * dim + c] += delta[c] / hd;
	info->hd = hd;
	info->other = -1;
	return 0;
}

/*
 * Section 4, the first constraint: the change lies in the plane of the
 * display, delta - (delta . w) w / (w . w).
 */
int
loft_drag_project(double *delta, const double *view, int dim,
    struct loft_error *err)
{
	double ww = vdot(view, view, dim), len = vnorm(delta, dim);
	double unit[LOFT_MAXDIM];

	if (!(ww >= VNORM_LO && ww <= VNORM_HI)) {
		/* w . w overflowed or underflowed: project on w / |w| */
		vcopy(unit, view, dim);
		ww = vunit(unit, dim) > 0 ? 1 : 0;
		view = unit;
	}
	if (!(ww > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "the viewing direction "
		    "is zero");
	vaxpy(delta, -vdot(delta, view, dim) / ww, view, dim);
	if (!(len > 0) || !(vnorm(delta, dim) > LOFT_DRAG_ZERO * len))
		return loft_fail(err, LOFT_EGEOM, -1, "zero displacement%s: "
		    "nothing to drag", len > 0 ? " after projection onto the "
		    "display plane (it is along the viewing direction)" : "");
	return 0;
}
