/*
 * bspline.c: tests of lib/bspline.c, B-splines as Bezier pieces, against
 * independent evaluations written here: de Boor's algorithm for curves,
 * and for surfaces the Cox-de Boor recursion of the basis functions
 * (de Boor 1972) summed directly; compared with the pieces evaluated in
 * their Bernstein form at the same parameters.
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "loft.h"

/* N_i,p(u) by the Cox-de Boor recursion, spans half open. */
static double
basis(const double *t, size_t nk, size_t i, int p, double u)
{
	double a = 0, b = 0;

	if (p == 0)
		return t[i] <= u && u < t[i + 1];
	if (t[i + p] > t[i])
		a = (u - t[i]) / (t[i + p] - t[i]) * basis(t, nk, i, p - 1, u);
	if (t[i + p + 1] > t[i + 1])
		b = (t[i + p + 1] - u) / (t[i + p + 1] - t[i + 1]) *
		    basis(t, nk, i + 1, p - 1, u);
	return a + b;
}

/* The curve at u in [t[p], t[n]) by de Boor's algorithm, into x. */
static void
deboor(const double *t, size_t n, int p, const double *P, int dim, double u,
    double *x)
{
	double d[64 * 4];
	size_t k = (size_t)p;

	while (k + 1 < n && !(u < t[k + 1]))
		k++;
	memcpy(d, P + (k - p) * dim, (size_t)(p + 1) * dim * sizeof *d);
	for (int r = 1; r <= p; r++)
		for (int j = p; j >= r; j--) {
			double a = (u - t[j + k - p]) / (t[j + 1 + k - r] -
			    t[j + k - p]);

			for (int q = 0; q < dim; q++)
				d[j * dim + q] = (1 - a) * d[(j - 1) * dim + q] +
				    a * d[j * dim + q];
		}
	memcpy(x, d + p * dim, (size_t)dim * sizeof *x);
}

/* A Bezier piece at s by Bernstein sums (loft_bernstein). */
static void
bez(const double *c, int deg, int dim, double s, double *x)
{
	double b[64];

	loft_bernstein(deg, s, b);
	for (int k = 0; k < dim; k++) {
		x[k] = 0;
		for (int i = 0; i <= deg; i++)
			x[k] += b[i] * c[i * dim + k];
	}
}

static double
rnd(void)
{
	return (double)rand() / RAND_MAX * 2 - 1;
}

/* A curve of degree p, n points, knots t: every piece at 7 parameters. */
static void
check_curve(const double *t, size_t n, int p, int dim, const char *what)
{
	double *P = malloc(n * dim * sizeof *P), *out, *range;
	size_t ns = loft_bspline_spans(t, n, p);
	struct loft_error err;
	double worst = 0, size = 0;

	for (size_t i = 0; i < n * dim; i++)
		size = fmax(size, fabs(P[i] = 100 * rnd()));
	out = malloc(ns * (p + 1) * dim * sizeof *out);
	range = malloc(2 * ns * sizeof *range);
	CHECK(loft_bspline_bezier(t, n, p, P, dim, out, range, &err) == 0,
	    "%s: %s", what, err.msg);
	for (size_t k = 0; k < ns; k++)
		for (int j = 0; j <= 6; j++) {
			double s = j / 6.0, u = range[2 * k] + s * (range[2 * k +
			    1] - range[2 * k]), x[4], y[4];

			if (j == 6)
				s = 1 - 1e-12, u = range[2 * k] + s * (range[2 *
				    k + 1] - range[2 * k]);
			deboor(t, n, p, P, dim, u, x);
			bez(out + k * (p + 1) * dim, p, dim, s, y);
			for (int q = 0; q < dim; q++)
				worst = fmax(worst, fabs(x[q] - y[q]));
		}
	CHECK(worst <= 1e-11 * size, "%s: pieces off de Boor by %g", what,
	    worst);
	free(P);
	free(out);
	free(range);
}

static void
test_curves(void)
{
	double clamped[] = { 0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4 };
	double open[] = { -1, 0.5, 1, 1.5, 2.25, 3, 3.5, 5, 6, 7.5 };
	double line[] = { 0, 0, 1, 3, 3 };
	double *t = malloc(80 * sizeof *t);

	check_curve(clamped, 8, 3, 3, "clamped cubic, a double knot");
	check_curve(open, 6, 3, 2, "unclamped cubic");
	check_curve(open, 7, 2, 4, "unclamped quadratic in 4-D");
	check_curve(line, 3, 1, 3, "polyline");
	for (int p = 4; p <= 30; p += 13) {     /* degrees 4, 17, 30 */
		size_t n = (size_t)p + 10;

		for (size_t i = 0; i < n + p + 1; i++)
			t[i] = i <= (size_t)p ? 0 : i >= n ? 9 :
			    0.9 * (double)(i - p) + 0.3 * rnd();
		check_curve(t, n, p, 3, "high degree, clamped");
	}
	free(t);
}

/* A surface: every patch at a 5 x 5 grid against the tensor sum. */
static void
test_surface(void)
{
	double tu[] = { 0, 0, 0, 1, 2.5, 4, 4, 4 };      /* p 2, 5 points */
	double tv[] = { 0, 1, 2, 3, 4, 5, 6, 7, 8 };      /* q 3, 5, open */
	double P[5 * 5 * 4], *out;
	size_t su = loft_bspline_spans(tu, 5, 2), sv = loft_bspline_spans(tv,
	    5, 3);
	struct loft_error err;
	double worst = 0;

	for (int i = 0; i < 100; i++)
		P[i] = 10 * rnd() + (i % 4 == 3 ? 20 : 0);
	out = malloc(su * sv * 12 * 4 * sizeof *out);
	CHECK(su == 3 && sv == 2, "spans %zu %zu", su, sv);
	CHECK(loft_bspline_surface_bezier(tu, 5, 2, tv, 5, 3, P, 4, out,
	    &err) == 0, "surface: %s", err.msg);
	for (size_t a = 0; a < su; a++)
	    for (size_t sb = 0; sb < sv; sb++)
		for (int gi = 0; gi <= 4; gi++)
			for (int gj = 0; gj <= 4; gj++) {
				double s = gi / 4.0 * 0.999, r = gj / 4.0 * 0.999;
				double u0[] = { 0, 1, 2.5, 4 };
				double u = u0[a] + s * (u0[a + 1] - u0[a]);
				double v = 3 + (double)sb + r, x[4] = { 0 }, y[4] = { 0 };
				double bu[3], bv[4];
				const double *c = out + (a * sv + sb) * 48;

				for (int i = 0; i < 5; i++)
					for (int j = 0; j < 5; j++) {
						double b = basis(tu, 8, i, 2, u) *
						    basis(tv, 9, j, 3, v);

						for (int k = 0; k < 4; k++)
							x[k] += b * P[4 * (5 * i + j) + k];
					}
				loft_bernstein(2, s, bu);
				loft_bernstein(3, r, bv);
				for (int i = 0; i <= 2; i++)
					for (int j = 0; j <= 3; j++)
						for (int k = 0; k < 4; k++)
							y[k] += bu[i] * bv[j] *
							    c[4 * (4 * i + j) + k];
				for (int k = 0; k < 4; k++)
					worst = fmax(worst, fabs(x[k] - y[k]));
			}
	CHECK(worst < 1e-12, "surface patches off the tensor sum by %g", worst);
	free(out);
}

/* A quarter circle, rational quadratic (1,0), (1,1) w 1/sqrt2, (0,1):
 * its cubics stay within tol of the unit circle. */
static void
test_rational(void)
{
	double w = sqrt(0.5), hw[] = { 1, 0, 1, w, w, w, 0, 1, 1 };
	double out[4 * 256 * 2], worst = 0;
	size_t n = 0;
	struct loft_error err;

	CHECK(loft_rational_cubics(hw, 2, 2, 1e-7, 256, out, &n, &err) == 0,
	    "quarter circle: %s", err.msg);
	for (size_t i = 0; i < n; i++)
		for (int j = 0; j <= 40; j++) {
			double x[2];

			bez(out + 8 * i, 3, 2, j / 40.0, x);
			worst = fmax(worst, fabs(hypot(x[0], x[1]) - 1));
		}
	CHECK(n > 1 && worst <= 1e-7, "quarter circle: %zu cubics, off the "
	    "circle by %g", n, worst);
	/* a negative weight is refused */
	hw[5] = -1;
	CHECK(loft_rational_cubics(hw, 2, 2, 1e-7, 256, out, &n, &err) ==
	    LOFT_EGEOM, "a negative weight is taken");
	/* a bad knot vector is refused */
	{
		double t[] = { 0, 0, 1, 0.5, 1, 1 };

		CHECK(loft_bspline_check(t, 3, 2, &err) == LOFT_EINPUT,
		    "decreasing knots taken");
		CHECK(loft_bspline_check(t, 3, 64, &err) == LOFT_EINPUT,
		    "degree 64 taken");
	}
}

/* An eighth of a sphere, degrees 2 x 2 rational (octant patch): every
 * point of its bicubics is at distance 1 from the centre within tol. */
static void
test_rational_surface(void)
{
	double r = sqrt(0.5), hw[9 * 4], *out = malloc(48 * 64 * 64 *
	    sizeof *out), worst = 0;
	/* circle arcs: meridian (x,z) quarter times equator (x,y) quarter */
	double m[3][3] = { { 1, 0, 1 }, { r, r, r }, { 0, 1, 1 } };
	double e[3][3] = { { 1, 0, 1 }, { r, r, r }, { 0, 1, 1 } };
	size_t k = 0, kv = 0;
	struct loft_error err;

	for (int i = 0; i < 3; i++)             /* u: the meridian */
		for (int j = 0; j < 3; j++) {   /* v: the equator */
			double *h = hw + 4 * (3 * i + j);

			h[0] = m[i][0] * e[j][0];
			h[1] = m[i][0] * e[j][1];
			h[2] = m[i][1] * e[j][2];
			h[3] = m[i][2] * e[j][2];
		}
	CHECK(loft_rational_bicubics(hw, 2, 2, 1e-7, 64, out, &k, &kv, &err) == 0,
	    "octant: %s", err.msg);
	for (size_t c = 0; c < k * kv; c++)
		for (int a = 0; a <= 8; a++)
			for (int b = 0; b <= 8; b++) {
				double x[3];

				loft_bezier_surface_eval(out + 48 * c, 3, 3, a / 8.0,
				    b / 8.0, x, NULL, NULL);
				worst = fmax(worst, fabs(sqrt(x[0] * x[0] + x[1] *
				    x[1] + x[2] * x[2]) - 1));
			}
	CHECK(k * kv > 1 && worst <= 1e-7, "octant: %zu by %zu patches, off "
	    "the sphere by %g", k, kv, worst);
	free(out);
}

int
main(void)
{
	srand(7);
	test_curves();
	test_surface();
	test_rational();
	test_rational_surface();
	return check_done("bspline");
}
