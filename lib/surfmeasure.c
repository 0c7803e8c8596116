/*
 * surfmeasure.c: the numbers of a surface of patches: its area, its
 * Gaussian and mean curvature and where they are greatest and least,
 * and the integrals of the Gaussian curvature that say how far it is
 * from developable.  By Gauss-Legendre quadrature over each patch's
 * cells.  Core.
 */
#include <string.h>

#include "internal.h"

/* Gauss-Legendre nodes and weights of order 5 on [0, 1]. */
const double loft__gl5_x[5] = {
	0.046910077030668004, 0.23076534494715845, 0.5,
	0.76923465505284155, 0.95308992296933200
};
const double loft__gl5_w[5] = {
	0.11846344252809454, 0.23931433524968324, 0.28444444444444444,
	0.23931433524968324, 0.11846344252809454
};

/*
 * The step of the central difference that gives x_uv from x_u (the
 * surface types give x_uu and x_vv exactly, not the twist): its error
 * is h^2 times the third derivative, its rounding 1e-16 / h of the
 * size, both near 1e-10 at this h in a patch's unit parameter.
 */
#define TWIST_STEP 1e-5

/* The exponent e of the largest coordinate of the first derivatives a
 * and b (3 each), as frexp gives it (that coordinate is at least half
 * of 2^e and below it); 0 where all are 0. */
static int
scale_of(const double *a, const double *b)
{
	double most = 0;
	int e;

	for (int c = 0; c < 3; c++)
		most = fmax(most, fmax(fabs(a[c]), fabs(b[c])));
	if (!(most > 0) || !isfinite(most))
		return 0;
	(void)frexp(most, &e);
	return e;
}

/*
 * loft_surface_curvature of s scaled by 2^-e (*e chosen so that its
 * first derivatives at (u, v) are near 1): *k = K 2^2e, *h = H 2^e,
 * *da = |f_u x f_v| 2^-2e, exactly (the scaling is by a power of two).
 * Unscaled, E G - F^2 goes as the fourth power of the size: past 1e77
 * it overflowed and K read 0, below 1e-77 it underflowed and the point
 * was passed over, so a doubly curved patch measured developable.
 */
static int
curvature_scaled(const struct loft_surface *s, double u, double v,
    double *k, double *h, double *da, int *e)
{
	double p[3] = { 0 }, xu[3] = { 0 }, xv[3] = { 0 }, xuu[3] = { 0 };
	double xvv[3] = { 0 }, a[3] = { 0 }, b[3] = { 0 }, xuv[3], n[3];
	double v0 = fmax(0, v - TWIST_STEP), v1 = fmin(1, v + TWIST_STEP);
	double E, F, G, L, M, N, det;

	loft_surface_eval2(s, u, v, p, xu, xv, xuu, xvv);
	loft_surface_eval(s, u, v0, NULL, a, NULL);
	loft_surface_eval(s, u, v1, NULL, b, NULL);
	for (int c = 0; c < 3; c++)
		xuv[c] = (b[c] - a[c]) / (v1 - v0);
	*e = scale_of(xu, xv);
	vpow2(xu, 3, -*e);
	vpow2(xv, 3, -*e);
	vpow2(xuu, 3, -*e);
	vpow2(xvv, 3, -*e);
	vpow2(xuv, 3, -*e);
	n[0] = xu[1] * xv[2] - xu[2] * xv[1];
	n[1] = xu[2] * xv[0] - xu[0] * xv[2];
	n[2] = xu[0] * xv[1] - xu[1] * xv[0];
	*da = vunit(n, 3);
	*k = *h = 0;
	if (!(*da > 0))
		return LOFT_EGEOM;
	E = vdot(xu, xu, 3);
	F = vdot(xu, xv, 3);
	G = vdot(xv, xv, 3);
	L = vdot(xuu, n, 3);
	M = vdot(xuv, n, 3);
	N = vdot(xvv, n, 3);
	det = E * G - F * F;
	if (!(det > 0))
		return LOFT_EGEOM;
	*k = (L * N - M * M) / det;
	*h = (E * N - 2 * F * M + G * L) / (2 * det);
	return isfinite(*k) && isfinite(*h) ? 0 : LOFT_EGEOM;
}

int
loft_surface_curvature(const struct loft_surface *s, double u, double v,
    double *k, double *h, double *da)
{
	int e, rc = curvature_scaled(s, u, v, k, h, da, &e);

	*k = ldexp(*k, -2 * e);
	*h = ldexp(*h, -e);
	*da = ldexp(*da, 2 * e);
	return rc;
}

static void
extreme(struct loft_surface_where *w, double x, int lower, size_t patch,
    double u, double v, int first)
{
	if (first || (lower ? x < w->value : x > w->value)) {
		w->value = x;
		w->patch = patch;
		w->u = u;
		w->v = v;
	}
}

void
loft_surface_numbers(const struct loft_surface *s, size_t ns, long cells,
    struct loft_surface_numbers *m)
{
	int first = 1;

	memset(m, 0, sizeof *m);
	if (cells < 1)
		cells = 1;
	for (size_t i = 0; i < ns; i++)
		for (long a = 0; a < cells * 5; a++)
			for (long b = 0; b < cells * 5; b++) {
				double u = (a / 5 + loft__gl5_x[a % 5]) / cells;
				double v = (b / 5 + loft__gl5_x[b % 5]) / cells;
				double wt = loft__gl5_w[a % 5] *
				    loft__gl5_w[b % 5] / ((double)cells * cells);
				double k, h, da;
				int e, rc = curvature_scaled(&s[i], u, v, &k,
				    &h, &da, &e);

				/* K dA does not depend on the scale */
				m->area += isfinite(da) ? ldexp(wt * da, 2 * e) :
				    0;
				if (rc != 0)
					continue;
				m->kint += wt * da * k;
				m->kabs += wt * da * fabs(k);
				k = ldexp(k, -2 * e);
				h = ldexp(h, -e);
				extreme(&m->kmin, k, 1, i, u, v, first);
				extreme(&m->kmax, k, 0, i, u, v, first);
				extreme(&m->hmin, h, 1, i, u, v, first);
				extreme(&m->hmax, h, 0, i, u, v, first);
				first = 0;
			}
	m->developable = m->kabs <= LOFT_DEVELOPABLE_TOL;
}
