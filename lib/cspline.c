/*
 * cspline.c: the baselines Manning (1973, section 1) argues against: the
 * cubic spline with continuous tangent vectors and second derivatives
 * (Ferguson's conditions h = 1, k = 0 in eq. 3 and 5), with parameter
 * intervals either uniform (Ferguson 1964) or proportional to the chords.
 */
#include <stdlib.h>

#include "internal.h"

/*
 * Solve the tridiagonal system a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] =
 * d[i] (i = 0..k-1, a[0] and c[k-1] unused) for dim right-hand sides,
 * d row i holding dim numbers; d becomes x.  w: k scratch numbers.  The
 * systems here are diagonally dominant, so no pivoting is needed.
 */
static void
thomas(const double *a, const double *b, const double *c, double *d,
    double *w, size_t k, int dim)
{
	w[0] = c[0] / b[0];
	vscale(d, 1 / b[0], d, dim);
	for (size_t i = 1; i < k; i++) {
		double den = b[i] - a[i] * w[i - 1];

		w[i] = c[i] / den;
		vaxpy(d + i * dim, -a[i], d + (i - 1) * dim, dim);
		vscale(d + i * dim, 1 / den, d + i * dim, dim);
	}
	for (size_t i = k - 1; i-- > 0;)
		vaxpy(d + i * dim, -w[i], d + (i + 1) * dim, dim);
}

/*
 * The cyclic system: as thomas, but a[0] multiplies x[k-1] and c[k-1]
 * multiplies x[0].  Solved as a tridiagonal one plus a rank-one
 * correction (Sherman and Morrison): A = A' + u v^T with u = (g, 0, ..,
 * 0, c[k-1]), v = (1, 0, .., 0, a[0]/g), g = -b[0].  b is modified.
 * w: 2k scratch numbers.
 */
static void
cyclic(const double *a, double *b, const double *c, double *d, double *w,
    size_t k, int dim)
{
	double g = -b[0], alpha = a[0], beta = c[k - 1], *z = w + k;

	b[0] -= g;
	b[k - 1] -= alpha * beta / g;
	thomas(a, b, c, d, w, k, dim);
	for (size_t i = 0; i < k; i++)
		z[i] = 0;
	z[0] = g;
	z[k - 1] = beta;
	thomas(a, b, c, z, w, k, 1);
	for (int q = 0; q < dim; q++) {
		double f = (d[q] + alpha / g * d[(k - 1) * dim + q]) /
		    (1 + z[0] + alpha / g * z[k - 1]);

		for (size_t i = 0; i < k; i++)
			d[i * dim + q] -= f * z[i];
	}
}

/*
 * Row i of the continuity condition for the knot derivatives m (with
 * respect to the global parameter; interval h0 before knot i, h1 after):
 *   h1 m_{i-1} + 2(h0 + h1) m_i + h0 m_{i+1}
 *       = 3 (h1 (P_i - P_{i-1}) / h0 + h0 (P_{i+1} - P_i) / h1).
 */
static void
row(double h0, double h1, const double *pm, const double *p,
    const double *pp, int dim, double *a, double *b, double *c, double *d)
{
	*a = h1;
	*b = 2 * (h0 + h1);
	*c = h0;
	for (int q = 0; q < dim; q++)
		d[q] = 3 * (h1 * (p[q] - pm[q]) / h0 + h0 * (pp[q] - p[q]) / h1);
}

int
loft__fit_cspline(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_error *err)
{
	size_t nseg = o->closed ? n : n - 1;
	double *mem = malloc((6 * n + n * dim) * sizeof *mem);
	double *h, *a, *b, *c, *w, *m;
	int rc = 0;

	if (mem == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	h = mem, a = h + n, b = a + n, c = b + n, w = c + n, m = w + 2 * n;
	for (size_t i = 0; i < nseg; i++)
		h[i] = o->method == LOFT_CHORD ?
		    vdist(p + ((i + 1) % n) * dim, p + i * dim, dim) : 1;
	if (o->closed) {
		for (size_t i = 0; i < n; i++)
			row(h[(i + n - 1) % n], h[i], p + ((i + n - 1) % n) * dim,
			    p + i * dim, p + ((i + 1) % n) * dim, dim, &a[i],
			    &b[i], &c[i], m + i * dim);
		cyclic(a, b, c, m, w, n, dim);
	} else {
		/* End derivatives: the given directions, each as long as
		 * its end chord in the segment's own parameter. */
		rc = loft__open_ends(o, p, n, dim, m, m + (n - 1) * dim, err);
		if (rc == 0) {
			vscale(m, vdist(p + dim, p, dim) / h[0], m, dim);
			vscale(m + (n - 1) * dim, vdist(p + (n - 1) * dim,
			    p + (n - 2) * dim, dim) / h[n - 2],
			    m + (n - 1) * dim, dim);
		}
		if (rc == 0 && n > 2) {
			for (size_t i = 1; i + 1 < n; i++)
				row(h[i - 1], h[i], p + (i - 1) * dim,
				    p + i * dim, p + (i + 1) * dim, dim, &a[i],
				    &b[i], &c[i], m + i * dim);
			/* the known end derivatives move to the right */
			vaxpy(m + dim, -a[1], m, dim);
			vaxpy(m + (n - 2) * dim, -c[n - 2], m + (n - 1) * dim,
			    dim);
			thomas(a + 1, b + 1, c + 1, m + dim, w, n - 2, dim);
		}
	}
	for (size_t i = 0; rc == 0 && i < nseg; i++) {
		size_t j = (i + 1) % n;
		double *s = seg + i * 4 * dim;

		vcopy(s, p + i * dim, dim);
		vcopy(s + dim, p + j * dim, dim);
		vscale(s + 2 * dim, h[i], m + i * dim, dim);
		vscale(s + 3 * dim, h[i], m + j * dim, dim);
	}
	free(mem);
	return rc;
}
