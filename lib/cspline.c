/*
 * cspline.c: the baselines Manning (1973, section 1) argues against: the
 * cubic spline with continuous tangent vectors and second derivatives
 * (Ferguson's conditions h = 1, k = 0 in eq. 3 and 5), with parameter
 * intervals either uniform (Ferguson 1964) or proportional to the chords.
 */
#include <stdlib.h>
#include <string.h>

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
	/* (the fair fit's free diagonal replaces b: see diagonal) */
	*c = h0;
	for (int q = 0; q < dim; q++)
		d[q] = 3 * (h1 * (p[q] - pm[q]) / h0 + h0 * (pp[q] - p[q]) / h1);
}

/*
 * The knot derivatives m (n * dim) of the spline with intervals h (nseg
 * of them), and the system's rows a, b, c (n each; w: 2n scratch).  On
 * an open curve m's ends are the given or estimated end directions, each
 * as long as its end chord in the segment's own parameter.
 */
/*
 * The diagonal of row i with the free factors y (NULL: all 0): (h0 + h1)
 * (1 + e^y_i), which is 2 (h0 + h1), continuous second derivatives, at
 * y_i = 0, and always more than the row's other two entries.  Otherwise
 * the second derivative jumps by a multiple of the tangent, which
 * leaves the curvature continuous (Nielson's nu-splines).
 */
static double
diagonal(double h0, double h1, const double *y, size_t i)
{
	return y == NULL ? 2 * (h0 + h1) : (h0 + h1) * (1 + exp(y[i]));
}

static int
solve(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    const double *h, const double *y, double *m, double *a, double *b,
    double *c, double *w, struct loft_error *err)
{
	int rc = 0;

	if (o->closed) {
		for (size_t i = 0; i < n; i++)
			row(h[(i + n - 1) % n], h[i], p + ((i + n - 1) % n) * dim,
			    p + i * dim, p + ((i + 1) % n) * dim, dim, &a[i],
			    &b[i], &c[i], m + i * dim);
		for (size_t i = 0; i < n; i++)
			b[i] = diagonal(h[(i + n - 1) % n], h[i], y, i);
		cyclic(a, b, c, m, w, n, dim);
		/* cyclic spoils b: the rows again, for the adjoint */
		for (size_t i = 0; i < n; i++)
			b[i] = diagonal(h[(i + n - 1) % n], h[i], y, i);
		return 0;
	}
	rc = loft__open_ends(o, p, n, dim, m, m + (n - 1) * dim, err);
	if (rc == 0) {
		/* with y, e^y_0 and e^y_{n-1} times as long */
		double s0 = y == NULL ? 1 : exp(y[0]);
		double s1 = y == NULL ? 1 : exp(y[n - 1]);

		vscale(m, s0 * vdist(p + dim, p, dim) / h[0], m, dim);
		vscale(m + (n - 1) * dim, s1 * vdist(p + (n - 1) * dim,
		    p + (n - 2) * dim, dim) / h[n - 2], m + (n - 1) * dim, dim);
	}
	if (rc == 0 && n > 2) {
		for (size_t i = 1; i + 1 < n; i++)
			row(h[i - 1], h[i], p + (i - 1) * dim, p + i * dim,
			    p + (i + 1) * dim, dim, &a[i], &b[i], &c[i],
			    m + i * dim);
		for (size_t i = 1; i + 1 < n; i++)
			b[i] = diagonal(h[i - 1], h[i], y, i);
		/* the known end derivatives move to the right */
		vaxpy(m + dim, -a[1], m, dim);
		vaxpy(m + (n - 2) * dim, -c[n - 2], m + (n - 1) * dim, dim);
		thomas(a + 1, b + 1, c + 1, m + dim, w, n - 2, dim);
	}
	return rc;
}

static void
segments(const double *p, size_t n, int dim, size_t nseg, const double *h,
    const double *m, double *seg)
{
	for (size_t i = 0; i < nseg; i++) {
		size_t j = (i + 1) % n;
		double *s = seg + i * 4 * dim;

		vcopy(s, p + i * dim, dim);
		vcopy(s + dim, p + j * dim, dim);
		vscale(s + 2 * dim, h[i], m + i * dim, dim);
		vscale(s + 3 * dim, h[i], m + j * dim, dim);
	}
}

int
loft__cspline_h(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, const double *h, const double *y, double *seg, double *work,
    struct loft_error *err)
{
	double *a = work, *b = a + n, *c = b + n, *w = c + n, *m = w + 2 * n;
	int rc = solve(o, p, n, dim, h, y, m, a, b, c, w, err);

	if (rc == 0)
		segments(p, n, dim, o->closed ? n : n - 1, h, m, seg);
	return rc;
}

void
loft__cspline_adjoint(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, const double *h, const double *y, const double *gseg,
    double *gh, double *gy, double *work)
{
	double *a = work, *b = a + n, *c = b + n, *w = c + n, *m = w + 2 * n;
	double *lam = m + n * dim, *at = lam + n * dim, *ct = at + n;
	size_t nseg = o->closed ? n : n - 1, lo = o->closed ? 0 : 1;
	size_t hi = o->closed ? n : n - 1;

	/* explicit: D0 = h_s m_s, D1 = h_s m_{s+1}; dE/dm into lam */
	memset(lam, 0, n * dim * sizeof *lam);
	for (size_t s = 0; s < nseg; s++) {
		const double *g0 = gseg + s * 2 * dim, *g1 = g0 + dim;
		size_t j = (s + 1) % n;

		gh[s] = vdot(g0, m + s * dim, dim) + vdot(g1, m + j * dim, dim);
		vaxpy(lam + s * dim, h[s], g0, dim);
		vaxpy(lam + j * dim, h[s], g1, dim);
	}
	/* on an open curve D0 of the first segment and D1 of the last are
	 * given: they do not change with h, so their terms go */
	if (!o->closed) {
		gh[0] -= vdot(gseg, m, dim);
		gh[nseg - 1] -= vdot(gseg + (nseg - 1) * 2 * dim + dim,
		    m + (n - 1) * dim, dim);
	}
	for (size_t i = 0; gy != NULL && i < n; i++)
		gy[i] = 0;
	/* an open curve's end derivatives, e^y times their own: directly
	 * through the end segments, and through the rows they enter */
	if (!o->closed && gy != NULL && y != NULL) {
		gy[0] = h[0] * vdot(gseg, m, dim);
		gy[n - 1] = h[nseg - 1] * vdot(gseg + (nseg - 1) * 2 * dim + dim,
		    m + (n - 1) * dim, dim);
	}
	if (hi <= lo)
		return;
	/* the transposed system: A^T lam = dE/dm over the unknowns */
	for (size_t i = lo; i < hi; i++) {
		at[i] = o->closed ? c[(i + n - 1) % n] : i > lo ? c[i - 1] : 0;
		ct[i] = o->closed ? a[(i + 1) % n] : i + 1 < hi ? a[i + 1] : 0;
	}
	if (o->closed) {
		cyclic(at, b, ct, lam, w, n, dim);
		for (size_t i = 0; i < n; i++)
			b[i] = 2 * (h[(i + n - 1) % n] + h[i]);
	} else {
		thomas(at + 1, b + 1, ct + 1, lam + dim, w, n - 2, dim);
		if (gy != NULL && y != NULL) {
			gy[0] -= a[1] * vdot(lam + dim, m, dim);
			gy[n - 1] -= c[n - 2] * vdot(lam + (n - 2) * dim,
			    m + (n - 1) * dim, dim);
		}
	}
	/* minus lam . dR/dh, R_i = a_i m_{i-1} + b_i m_i + c_i m_{i+1} - d_i */
	for (size_t i = lo; i < hi; i++) {
		size_t s0 = (i + n - 1) % n, s1 = i;   /* h0 = h[s0], h1 = h[s1] */
		const double *pm = p + s0 * dim, *pi = p + i * dim;
		const double *pp = p + ((i + 1) % n) * dim;
		const double *mm = m + s0 * dim, *mi = m + i * dim;
		const double *mp = m + ((i + 1) % n) * dim, *l = lam + i * dim;
		double h0 = h[s0], h1 = h[s1], r0 = 0, r1 = 0;
		double db = y == NULL ? 2 : 1 + exp(y[i]);      /* db/dh0,1 */

		if (gy != NULL && y != NULL)    /* db/dy = (h0 + h1) e^y */
			gy[i] = -(h0 + h1) * exp(y[i]) * vdot(l, mi, dim);
		for (int q = 0; q < dim; q++) {
			double d0 = pi[q] - pm[q], d1 = pp[q] - pi[q];
			double dh0 = db * mi[q] + mp[q] -
			    3 * (-h1 * d0 / (h0 * h0) + d1 / h1);
			double dh1 = mm[q] + db * mi[q] -
			    3 * (d0 / h0 - h0 * d1 / (h1 * h1));

			if (!o->closed && i == 1)       /* m_0 = e0 / h_0 */
				dh0 -= h1 * mm[q] / h0;
			if (!o->closed && i + 2 == n)   /* m_{n-1} = e1 / h_{n-2} */
				dh1 -= h0 * mp[q] / h1;
			r0 += l[q] * dh0;
			r1 += l[q] * dh1;
		}
		gh[s0] -= r0;
		gh[s1] -= r1;
	}
}

int
loft__flat_join(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg)
{
	const double *t = o->have_start ? o->start : o->end;
	double u[LOFT_MAXDIM], g[LOFT_MAXDIM], r[LOFT_MAXDIM], c, cs;

	if (o->closed || n != 2 || o->have_start == o->have_end ||
	    !(o->have_start ? o->flat_start : o->flat_end))
		return 1;
	vsub(u, p + dim, p, dim);
	vcopy(g, t, dim);
	c = vunit(u, dim);
	if (!(c > 0) || !(vunit(g, dim) > 0))
		return 1;
	cs = vdot(g, u, dim);
	if (!(2 * cs * LOFT__MAXMAG >= 3))    /* also g away from u */
		return 1;
	vscale(r, 2 * cs, u, dim);
	vaxpy(r, -1, g, dim);
	vcopy(seg, p, 2 * dim);
	vscale(seg + (o->have_start ? 2 : 3) * dim, c, g, dim);
	vscale(seg + (o->have_start ? 3 : 2) * dim, 3 * c / (2 * cs), r, dim);
	return 0;
}

int
loft__fit_cspline(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_error *err)
{
	size_t nseg = o->closed ? n : n - 1;
	double *mem = malloc((6 * n + n * dim) * sizeof *mem);
	double *h;
	int rc;

	if (mem == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	h = mem + 5 * n + n * dim;
	for (size_t i = 0; i < nseg; i++)
		h[i] = o->method == LOFT_CHORD ?
		    vdist(p + ((i + 1) % n) * dim, p + i * dim, dim) : 1;
	rc = loft__cspline_h(o, p, n, dim, h, NULL, seg, mem, err);
	free(mem);
	return rc;
}
