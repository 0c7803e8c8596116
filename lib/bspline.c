/*
 * bspline.c: B-spline curves and surfaces, rational or not, as Bezier
 * pieces by knot insertion (Boehm 1980: a knot inserted into a span
 * replaces p - 1 control points by convex combinations of their
 * neighbours); and rational or high-degree Bezier pieces as cubic ones
 * within a distance, for the records and formats that take only
 * polynomials of bounded degree.  Core (loft.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

int
loft_bspline_check(const double *t, size_t nctl, int deg,
    struct loft_error *err)
{
	size_t nk;

	if (deg < 1 || deg > LOFT_BSPLINE_MAXDEG)
		return loft_fail(err, LOFT_EINPUT, -1, "degree %d is not from "
		    "1 to %d", deg, LOFT_BSPLINE_MAXDEG);
	if (nctl < (size_t)deg + 1 || nctl > LOFT_BSPLINE_MAXCTL)
		return loft_fail(err, LOFT_EINPUT, -1, "%zu control points "
		    "for degree %d (%d to %ld)", nctl, deg, deg + 1,
		    (long)LOFT_BSPLINE_MAXCTL);
	nk = nctl + (size_t)deg + 1;
	for (size_t i = 0; i < nk; i++) {
		if (!isfinite(t[i]))
			return loft_fail(err, LOFT_EINPUT, (long)i,
			    "knot %zu is not finite", i + 1);
		if (i > 0 && t[i] < t[i - 1])
			return loft_fail(err, LOFT_EINPUT, (long)i,
			    "knot %zu decreases", i + 1);
	}
	if (loft_bspline_spans(t, nctl, deg) == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "the knots leave no "
		    "span of positive length");
	return 0;
}

size_t
loft_bspline_spans(const double *t, size_t nctl, int deg)
{
	size_t n = 0;

	for (size_t i = (size_t)deg; i < nctl; i++)
		n += t[i] < t[i + 1];
	return n;
}

/*
 * Span [a, c) = [t[i], t[i+1]) by knot insertion in O(p^2): with u the
 * span's 2p knots t[i-p+1 .. i+p] and the blossom f, the control points
 * are P_k = f(u[k .. k+p-1]), k = 0..p.  First every u before the span
 * becomes a, R_k = f(a^(p-k), u[p .. p+k-1]); then every u after it
 * becomes c, b_j = f(a^(p-j), c^j).  Each step is Boehm's affine
 * interpolation of two blossom values that differ in one argument.
 */
void
loft_bspline_span(const double *t, const double *ctl, int p, size_t i,
    int dim, double *b)
{
	const double *u = t + i + 1 - (size_t)p;
	double a = t[i], c = t[i + 1];

	memcpy(b, ctl + (i - (size_t)p) * (size_t)dim, (size_t)((p + 1) *
	    dim) * sizeof *b);
	for (int r = 1; r <= p; r++)            /* u[k+r-1] -> a */
		for (int k = 0; k <= p - r; k++) {
			double al = (a - u[k + r - 1]) / (u[k + p] -
			    u[k + r - 1]);

			for (int q = 0; q < dim; q++)
				b[k * dim + q] += al * (b[(k + 1) * dim + q] -
				    b[k * dim + q]);
		}
	for (int r = 1; r <= p; r++)            /* u[p+k-r] -> c */
		for (int k = p; k >= r; k--) {
			double be = (c - a) / (u[p + k - r] - a);

			for (int q = 0; q < dim; q++)
				b[k * dim + q] = b[(k - 1) * dim + q] + be *
				    (b[k * dim + q] - b[(k - 1) * dim + q]);
		}
}

int
loft_bspline_bezier(const double *t, size_t nctl, int deg, const double *ctl,
    int dim, double *out, double *range, struct loft_error *err)
{
	size_t piece = 0, stride = (size_t)(deg + 1) * (size_t)dim;
	int rc;

	if (dim < 1 || dim > LOFT_BSPLINE_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "dimension %d is not "
		    "from 1 to %d", dim, LOFT_BSPLINE_MAXDIM);
	if ((rc = loft_bspline_check(t, nctl, deg, err)) != 0)
		return rc;
	for (size_t i = (size_t)deg; i < nctl; i++) {
		if (!(t[i] < t[i + 1]))
			continue;
		loft_bspline_span(t, ctl, deg, i, dim, out + piece * stride);
		if (range != NULL) {
			range[2 * piece] = t[i];
			range[2 * piece + 1] = t[i + 1];
		}
		piece++;
	}
	return 0;
}

int
loft_bspline_surface_bezier(const double *tu, size_t nu, int p,
    const double *tv, size_t nv, int q, const double *ctl, int dim,
    double *out, struct loft_error *err)
{
	size_t su, sv, rows;
	double *col = NULL, *colb = NULL, *mid = NULL;
	int rc;

	if ((rc = loft_bspline_check(tu, nu, p, err)) != 0 ||
	    (rc = loft_bspline_check(tv, nv, q, err)) != 0)
		return rc;
	if (dim < 1 || dim > LOFT_BSPLINE_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "dimension %d is not "
		    "from 1 to %d", dim, LOFT_BSPLINE_MAXDIM);
	su = loft_bspline_spans(tu, nu, p);
	sv = loft_bspline_spans(tv, nv, q);
	rows = su * (size_t)(p + 1);    /* rows of the net after the u pass */
	col = malloc(nu * (size_t)dim * sizeof *col);
	colb = malloc(rows * (size_t)dim * sizeof *colb);
	mid = malloc(rows * nv * (size_t)dim * sizeof *mid);
	if (col == NULL || colb == NULL || mid == NULL) {
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		goto done;
	}
	/* along u, column j at a time: mid row r (of rows), column j */
	for (size_t j = 0; j < nv; j++) {
		for (size_t i = 0; i < nu; i++)
			memcpy(col + i * dim, ctl + (i * nv + j) * dim,
			    (size_t)dim * sizeof *col);
		(void)loft_bspline_bezier(tu, nu, p, col, dim, colb, NULL, err);
		for (size_t r = 0; r < rows; r++)
			memcpy(mid + (r * nv + j) * dim, colb + r * dim,
			    (size_t)dim * sizeof *mid);
	}
	free(colb);
	colb = malloc(sv * (size_t)(q + 1) * (size_t)dim * sizeof *colb);
	if (colb == NULL) {
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		goto done;
	}
	/* along v, row r at a time, into patch (r / (p+1), s), row r % (p+1) */
	for (size_t r = 0; r < rows; r++) {
		size_t a = r / (size_t)(p + 1), i = r % (size_t)(p + 1);

		(void)loft_bspline_bezier(tv, nv, q, mid + r * nv * dim, dim,
		    colb, NULL, err);
		for (size_t s = 0; s < sv; s++) {
			double *patch = out + (a * sv + s) * (size_t)(p + 1) *
			    (size_t)(q + 1) * (size_t)dim;

			memcpy(patch + i * (size_t)(q + 1) * dim, colb + s *
			    (size_t)(q + 1) * dim, (size_t)(q + 1) * dim *
			    sizeof *patch);
		}
	}
done:
	free(col);
	free(colb);
	free(mid);
	return rc;
}

/* ---- rational and high-degree pieces as cubics ------------------------ */

/*
 * Sample points a cubic piece is checked at, beside its ends, against
 * the piece it stands for.  A cubic Hermite piece's error over a short
 * interval is a smooth function with few extrema (its leading term is
 * a multiple of s^2 (1 - s)^2), so 15 inner samples see its peak within
 * a few per cent; the pieces are made within half the tolerance to
 * cover that.
 */
#define CHECK_SAMPLES 16
#define CHECK_MARGIN 0.5

/*
 * The point (out) and first derivative (d1) at t of the rational
 * Bezier curve hw of degree deg whose points are homogeneous (dim
 * weighted coordinates, then the weight); or -1 where the weight is not
 * positive.
 */
static int
rational_eval(const double *hw, int deg, int dim, double t, double *out,
    double *d1)
{
	double b[LOFT_BSPLINE_MAXDEG + 1], db[LOFT_BSPLINE_MAXDEG + 1];
	double a[LOFT_BSPLINE_MAXDIM + 1] = { 0 };
	double da[LOFT_BSPLINE_MAXDIM + 1] = { 0 };
	int h = dim + 1;

	loft_bernstein(deg, t, b);
	db[0] = 0;
	if (deg > 0) {
		double c[LOFT_BSPLINE_MAXDEG + 1];

		loft_bernstein(deg - 1, t, c);
		for (int i = 0; i <= deg; i++)
			db[i] = deg * ((i > 0 ? c[i - 1] : 0) -
			    (i < deg ? c[i] : 0));
	}
	for (int i = 0; i <= deg; i++)
		for (int k = 0; k < h; k++) {
			a[k] += b[i] * hw[i * h + k];
			da[k] += db[i] * hw[i * h + k];
		}
	if (!(a[dim] > 0))
		return -1;
	for (int k = 0; k < dim; k++) {
		out[k] = a[k] / a[dim];
		if (d1 != NULL)
			d1[k] = (da[k] - out[k] * da[dim]) / a[dim];
	}
	return 0;
}

int
loft_rational_cubics(const double *hw, int deg, int dim, double tol,
    size_t max, double *out, size_t *n, struct loft_error *err)
{
	if (deg < 1 || deg > LOFT_BSPLINE_MAXDEG || dim < 1 ||
	    dim > LOFT_BSPLINE_MAXDIM - 1 || !(tol > 0) || max < 1)
		return loft_fail(err, LOFT_EINPUT, -1, "bad degree, dimension, "
		    "tolerance or count");
	for (size_t k = 1; k <= max; k *= 2) {
		double worst = 0;

		for (size_t i = 0; i < k && worst <= CHECK_MARGIN * tol; i++) {
			double t0 = (double)i / (double)k, h = 1.0 / (double)k;
			double p0[4], p1[4], d0[4], dd[4], *c = out + 4 * i * dim;

			if (rational_eval(hw, deg, dim, t0, p0, d0) ||
			    rational_eval(hw, deg, dim, t0 + h, p1, dd))
				return loft_fail(err, LOFT_EGEOM, -1, "a weight "
				    "is not positive");
			for (int q = 0; q < dim; q++) {
				c[q] = p0[q];
				c[dim + q] = p0[q] + h * d0[q] / 3;
				c[2 * dim + q] = p1[q] - h * dd[q] / 3;
				c[3 * dim + q] = p1[q];
			}
			for (int s = 1; s < CHECK_SAMPLES; s++) {
				double u = (double)s / CHECK_SAMPLES, x[4], y[4];
				double b3[4], e = 0;

				(void)rational_eval(hw, deg, dim, t0 + u * h, x,
				    NULL);
				loft_bernstein(3, u, b3);
				for (int q = 0; q < dim; q++) {
					y[q] = 0;
					for (int r = 0; r < 4; r++)
						y[q] += b3[r] * c[r * dim + q];
					e = hypot(e, y[q] - x[q]);
				}
				if (!(e <= worst))
					worst = isnan(e) ? INFINITY : e;
			}
		}
		if (worst <= CHECK_MARGIN * tol) {
			*n = k;
			return 0;
		}
	}
	return loft_fail(err, LOFT_ENOCONV, -1, "more than %zu cubic pieces "
	    "would be needed for the tolerance", max);
}

/* The Bernstein polynomials of degree d at t into b[0..d], and their
 * derivatives into db[0..d]. */
static void
basis_and_slope(int d, double t, double *b, double *db)
{
	double c[LOFT_BSPLINE_MAXDEG + 1];

	loft_bernstein(d, t, b);
	loft_bernstein(d - 1, t, c);
	for (int i = 0; i <= d; i++)
		db[i] = d * ((i > 0 ? c[i - 1] : 0) - (i < d ? c[i] : 0));
}

/*
 * The rational tensor Bezier surface hw (homogeneous, 4 numbers a point,
 * u-major, degrees m, n) at (u, v): the point and its derivatives in u,
 * v and u and v (into x[0..3), xu, xv, xuv); -1 where the weight is not
 * positive.  R = A / w, so R_u = (A_u - R w_u) / w and
 * R_uv = (A_uv - R_u w_v - R_v w_u - R w_uv) / w.
 */
static int
rsurf_eval(const double *hw, int m, int n, double u, double v, double *x,
    double *xu, double *xv, double *xuv)
{
	double bu[2][LOFT_BSPLINE_MAXDEG + 1], bv[2][LOFT_BSPLINE_MAXDEG + 1];
	double A[4][4] = { { 0 } };

	basis_and_slope(m, u, bu[0], bu[1]);
	basis_and_slope(n, v, bv[0], bv[1]);
	/* A[0]: A, A[1]: A_u, A[2]: A_v, A[3]: A_uv */
	for (int i = 0; i <= m; i++)
		for (int j = 0; j <= n; j++)
			for (int k = 0; k < 4; k++) {
				double h = hw[4 * (i * (n + 1) + j) + k];

				A[0][k] += bu[0][i] * bv[0][j] * h;
				A[1][k] += bu[1][i] * bv[0][j] * h;
				A[2][k] += bu[0][i] * bv[1][j] * h;
				A[3][k] += bu[1][i] * bv[1][j] * h;
			}
	if (!(A[0][3] > 0))
		return -1;
	for (int k = 0; k < 3; k++) {
		double w = A[0][3];

		x[k] = A[0][k] / w;
		xu[k] = (A[1][k] - x[k] * A[1][3]) / w;
		xv[k] = (A[2][k] - x[k] * A[2][3]) / w;
		xuv[k] = (A[3][k] - xu[k] * A[2][3] - xv[k] * A[1][3] -
		    x[k] * A[3][3]) / w;
	}
	return 0;
}

/*
 * The bicubic Bezier net (16 points, u-major) of cell [u0, u0 + h] x
 * [v0, v0 + g] of hw, by Hermite interpolation of the corners' points,
 * first derivatives and twists; -1 where a weight is not positive.
 */
static int
bicubic_cell(const double *hw, int m, int n, double u0, double h, double v0,
    double g, double *net)
{
	for (int a = 0; a < 2; a++)
		for (int b = 0; b < 2; b++) {
			double x[3], xu[3], xv[3], xuv[3];
			int i = 3 * a, j = 3 * b, si = a ? -1 : 1, sj = b ? -1 : 1;

			if (rsurf_eval(hw, m, n, u0 + a * h, v0 + b * g, x, xu,
			    xv, xuv) != 0)
				return -1;
			for (int k = 0; k < 3; k++) {
				double pu = h * xu[k] / 3, pv = g * xv[k] / 3;

				net[3 * (4 * i + j) + k] = x[k];
				net[3 * (4 * (i + si) + j) + k] = x[k] + si * pu;
				net[3 * (4 * i + j + sj) + k] = x[k] + sj * pv;
				net[3 * (4 * (i + si) + j + sj) + k] = x[k] +
				    si * pu + sj * pv + si * sj * h * g *
				    xuv[k] / 9;
			}
		}
	return 0;
}

/* The largest distance between cell net and hw over the cell's samples. */
static double
cell_error(const double *hw, int m, int n, double u0, double h, double v0,
    double g, const double *net)
{
	double worst = 0;

	for (int s = 0; s <= CHECK_SAMPLES / 2; s++)
		for (int r = 0; r <= CHECK_SAMPLES / 2; r++) {
			double a = 2.0 * s / CHECK_SAMPLES, b = 2.0 * r /
			    CHECK_SAMPLES, x[3], du[3], dv[3], duv[3], y[3], e;

			(void)rsurf_eval(hw, m, n, u0 + a * h, v0 + b * g, x, du,
			    dv, duv);
			loft_bezier_surface_eval(net, 3, 3, a, b, y, NULL, NULL);
			e = hypot(hypot(y[0] - x[0], y[1] - x[1]), y[2] - x[2]);
			if (!(e <= worst))
				worst = isnan(e) ? INFINITY : e;
		}
	return worst;
}

/*
 * The bicubic cells of an cu by cv grid of hw into out (cell (a, b) at
 * 48 (a cv + b)) and their largest error, stopping once it is above
 * stop; -1 where a weight is not positive.
 */
static double
grid(const double *hw, int m, int n, size_t cu, size_t cv, double *out,
    double stop)
{
	double worst = 0, h = 1.0 / (double)cu, g = 1.0 / (double)cv;

	for (size_t i = 0; i < cu * cv && worst <= stop; i++) {
		double *net = out + 48 * i, u0 = (double)(i / cv) * h;
		double v0 = (double)(i % cv) * g;

		if (bicubic_cell(hw, m, n, u0, h, v0, g, net) != 0)
			return -1;
		worst = fmax(worst, cell_error(hw, m, n, u0, h, v0, g, net));
	}
	return worst;
}

/*
 * Halve the cells in u or in v, whichever brings the error down more,
 * until it is within the tolerance: a surface of high degree in one
 * direction only is cut in that direction only.
 */
int
loft_rational_bicubics(const double *hw, int m, int n, double tol,
    size_t max, double *out, size_t *ku, size_t *kv, struct loft_error *err)
{
	size_t cu = 1, cv = 1;

	if (m < 1 || n < 1 || m > LOFT_BSPLINE_MAXDEG ||
	    n > LOFT_BSPLINE_MAXDEG || !(tol > 0) || max < 1)
		return loft_fail(err, LOFT_EINPUT, -1, "bad degrees, tolerance "
		    "or count");
	for (;;) {
		double e = grid(hw, m, n, cu, cv, out, CHECK_MARGIN * tol);
		double eu = INFINITY, ev = INFINITY;

		if (e >= 0 && e <= CHECK_MARGIN * tol) {
			*ku = cu;
			*kv = cv;
			return 0;
		}
		if (e >= 0 && 2 * cu * cv <= max * max)
			eu = grid(hw, m, n, 2 * cu, cv, out, INFINITY);
		if (e >= 0 && eu >= 0 && 2 * cu * cv <= max * max)
			ev = grid(hw, m, n, cu, 2 * cv, out, INFINITY);
		if (e < 0 || eu < 0 || ev < 0)
			return loft_fail(err, LOFT_EGEOM, -1, "a weight is not "
			    "positive");
		if (2 * cu * cv > max * max)
			return loft_fail(err, LOFT_ENOCONV, -1, "more than %zu "
			    "bicubic patches would be needed for the "
			    "tolerance", max * max);
		if (eu <= ev)
			cu *= 2;
		else
			cv *= 2;
	}
}

/* The polynomial Bezier ctl (dim each, dim 1 to 3) with weights 1. */
static double *
homogeneous(const double *ctl, size_t npts, int dim)
{
	double *h = malloc(npts * (size_t)(dim + 1) * sizeof *h);

	for (size_t i = 0; h != NULL && i < npts; i++) {
		memcpy(h + i * (dim + 1), ctl + i * dim, (size_t)dim * sizeof *h);
		h[i * (dim + 1) + dim] = 1;
	}
	return h;
}

int
loft_bezier_cubics(const double *ctl, int deg, int dim, double tol,
    size_t max, double *out, size_t *n, struct loft_error *err)
{
	double *h;
	int rc;

	if (deg < 1 || deg > LOFT_BSPLINE_MAXDEG || dim < 1 || dim > 3)
		return loft_fail(err, LOFT_EINPUT, -1, "bad degree or "
		    "dimension");
	if ((h = homogeneous(ctl, (size_t)deg + 1, dim)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	rc = loft_rational_cubics(h, deg, dim, tol, max, out, n, err);
	free(h);
	return rc;
}

int
loft_bezier_bicubics(const double *ctl, int m, int n, double tol,
    size_t max, double *out, size_t *ku, size_t *kv, struct loft_error *err)
{
	double *h;
	int rc;

	if (m < 1 || n < 1 || m > LOFT_BSPLINE_MAXDEG ||
	    n > LOFT_BSPLINE_MAXDEG)
		return loft_fail(err, LOFT_EINPUT, -1, "bad degrees");
	if ((h = homogeneous(ctl, (size_t)(m + 1) * (size_t)(n + 1), 3)) ==
	    NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	rc = loft_rational_bicubics(h, m, n, tol, max, out, ku, kv, err);
	free(h);
	return rc;
}
