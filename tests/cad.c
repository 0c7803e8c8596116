/*
 * cad.c: the exact Bezier forms of bezform.c against the record types'
 * own evaluators (Manning's eq. 7 in cubic.c, MacCallum's u M B M^t v^t
 * in quartic.c and patch.c, which use the paper's matrix M and share no
 * code with the Bezier forms), and the helpers the CAD writers share.
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "loft.h"
#include "loftcad.h"

/* A deterministic sequence in [-1, 1]. */
static double
rnd(void)
{
	static unsigned long s = 12345;

	s = s * 6364136223846793005UL + 1442695040888963407UL;
	return (double)((s >> 11) & ((1UL << 52) - 1)) / (double)(1UL << 51) - 1;
}

/* The Bezier surface of the net b (u-major, dim each) at (u, v), by
 * Bernstein sums written out here. */
static void
bezier_sum(const double *b, int m, int n, int dim, double u, double v,
    double *p)
{
	double bu[LOFT_BEZIER_MAXPTS], bv[LOFT_BEZIER_MAXPTS];

	loft_bernstein(m, u, bu);
	loft_bernstein(n, v, bv);
	for (int k = 0; k < dim; k++) {
		p[k] = 0;
		for (int i = 0; i <= m; i++)
			for (int j = 0; j <= n; j++)
				p[k] += bu[i] * bv[j] * b[(i * (n + 1) + j) * dim + k];
	}
}

/* |a - b|, dim <= 3, by hypot (no overflow for large coordinates) */
static double
dist(const double *a, const double *b, int dim)
{
	double d[3] = { 0, 0, 0 };

	for (int k = 0; k < dim; k++)
		d[k] = a[k] - b[k];
	return hypot(hypot(d[0], d[1]), d[2]);
}

/* A patch's Bezier net gives loft_patch_eval's points to 1e-12 of its size. */
static void
test_patch(void)
{
	for (int trial = 0; trial < 20; trial++) {
		int dim = 2 + trial % 2;
		double b[LOFT_PATCH_NUMS], net[LOFT_PATCH_NUMS], worst = 0;
		double scale = pow(10, trial % 7 - 3);

		for (int i = 0; i < 25 * dim; i++)
			b[i] = scale * rnd();
		loft_patch_bezier(b, dim, net);
		for (int k = 0; k < 400; k++) {
			double u = (rnd() + 1) / 2, v = (rnd() + 1) / 2;
			double p[3], q[3];

			if (k < 9) {            /* the corners and mid-edges too */
				u = (k % 3) / 2.0;
				v = (k / 3) / 2.0;
			}
			loft_patch_eval(b, dim, u, v, p, NULL, NULL);
			bezier_sum(net, 4, 4, dim, u, v, q);
			if (dist(p, q, dim) > worst)
				worst = dist(p, q, dim);
		}
		CHECK(worst <= 1e-12 * scale * 5, "patch %d (dim %d, scale %g): "
		    "Bezier net off by %g", trial, dim, scale, worst);
	}
}

/* The Bezier points of a one-segment record of type with ncols numbers. */
static void
bezier_form(const char *type, double *row, int ncols, double *ctl)
{
	struct loft_record rec;
	struct loft_curve c;
	struct loft_error err;

	memset(&rec, 0, sizeof rec);
	rec.type = (char *)type;
	rec.num = row;
	rec.nrows = 1;
	rec.ncols = ncols;
	CHECK(loft_curve_from_record(&rec, &c, &err) == 0, "%s: %s", type,
	    err.msg);
	(void)loft_curve_bezier(&c, 0, ctl);
}

/* Cubic and quartic segments: the Bezier points give the same curve. */
static void
test_curves(void)
{
	for (int trial = 0; trial < 20; trial++) {
		int dim = 2 + trial % 2;
		double c[4 * 3], q[5 * 3], cb[4 * 3], qb[5 * 3];
		double wc = 0, wq = 0;

		for (int i = 0; i < 5 * dim; i++)
			q[i] = 100 * rnd();
		memcpy(c, q, 4 * dim * sizeof *c);
		bezier_form("cubic", c, 4 * dim, cb);
		bezier_form("quartic", q, 5 * dim, qb);
		for (int k = 0; k <= 64; k++) {
			double u = k / 64.0, p[3], r[3];

			loft_cubic_eval(c, dim, u, p, NULL, NULL);
			loft_bezier_eval(cb, 4, dim, u, r, NULL, NULL);
			wc = fmax(wc, dist(p, r, dim));
			loft_quartic_eval(q, dim, u, p, NULL, NULL);
			loft_bezier_eval(qb, 5, dim, u, r, NULL, NULL);
			wq = fmax(wq, dist(p, r, dim));
		}
		CHECK(wc <= 1e-12 * 100, "cubic %d: off by %g", trial, wc);
		CHECK(wq <= 1e-12 * 100, "quartic %d: off by %g", trial, wq);
	}
	/* by hand: the cubic 0 0 1 0 0 2 0 -2 has Bezier points (0,0),
	 * (0,2/3), (1,2/3), (1,0) */
	{
		double seg[8] = { 0, 0, 1, 0, 0, 2, 0, -2 }, b[8];
		double want[8] = { 0, 0, 0, 2.0 / 3, 1, 2.0 / 3, 1, 0 };

		bezier_form("cubic", seg, 8, b);
		for (int i = 0; i < 8; i++)
			NEAR(b[i], want[i], 1e-15, "cubic 0 0 1 0 0 2 0 -2");
	}
}

/* Splitting, and the steps of a polyline within a tolerance. */
static void
test_split(void)
{
	for (int trial = 0; trial < 10; trial++) {
		int deg = 1 + trial, dim = 3;
		double c[12 * 3], l[12 * 3], r[12 * 3], t = 0.3 + 0.04 * trial;
		double worst = 0, tol, far = 0;
		long steps;

		for (int i = 0; i < (deg + 1) * dim; i++)
			c[i] = rnd();
		loft_bezier_split(c, deg, dim, t, l, r);
		for (int k = 0; k <= 32; k++) {
			double s = k / 32.0, p[3], q[3];

			loft_bezier_eval(l, deg + 1, dim, s, p, NULL, NULL);
			loft_bezier_eval(c, deg + 1, dim, s * t, q, NULL, NULL);
			worst = fmax(worst, dist(p, q, dim));
			loft_bezier_eval(r, deg + 1, dim, s, p, NULL, NULL);
			loft_bezier_eval(c, deg + 1, dim, t + s * (1 - t), q, NULL,
			    NULL);
			worst = fmax(worst, dist(p, q, dim));
		}
		CHECK(worst <= 1e-14, "split of degree %d: off by %g", deg, worst);
		/* the polyline of loft_bezier_steps' steps is within the
		 * tolerance at every parameter, sampled 20 times a step */
		tol = 1e-3 * (trial + 1);
		steps = loft_bezier_steps(c, deg, dim, tol, 100000);
		for (long j = 0; j < steps; j++) {
			double a[3], b[3];

			loft_bezier_eval(c, deg + 1, dim, (double)j / steps, a,
			    NULL, NULL);
			loft_bezier_eval(c, deg + 1, dim, (double)(j + 1) / steps,
			    b, NULL, NULL);
			for (int k = 0; k <= 20; k++) {
				double s = k / 20.0, p[3], q[3];

				loft_bezier_eval(c, deg + 1, dim, (j + s) / steps, p,
				    NULL, NULL);
				for (int i = 0; i < dim; i++)
					q[i] = a[i] + s * (b[i] - a[i]);
				far = fmax(far, dist(p, q, dim));
			}
		}
		CHECK(steps >= 1 && far <= tol, "%ld steps of degree %d: %g "
		    "from the curve, over the tolerance %g", steps, deg, far, tol);
	}
	/* by hand: the parabola of (0,0) (1,2) (2,0) has C'' = (0,-8), and
	 * steps h err by h^2 (8/8) at their middles: h = 0.1 for 0.01, not
	 * enough for 0.0099 */
	{
		double p[6] = { 0, 0, 1, 2, 2, 0 };

		CHECK(loft_bezier_steps(p, 2, 2, 0.01, 1000) == 10 &&
		    loft_bezier_steps(p, 2, 2, 0.0099, 1000) == 11 &&
		    loft_bezier_steps(p, 2, 2, 1e-9, 1000) == 0,
		    "steps of a parabola: %ld %ld %ld, want 10 11 0",
		    loft_bezier_steps(p, 2, 2, 0.01, 1000),
		    loft_bezier_steps(p, 2, 2, 0.0099, 1000),
		    loft_bezier_steps(p, 2, 2, 1e-9, 1000));
	}
}

/* STEP and IGES reals: a '.', E for the exponent, lossless. */
static void
test_real(void)
{
	static const struct { double x; const char *s; } cases[] = {
		{ 1, "1." }, { 0, "0." }, { -0.0, "0." }, { 0.5, "0.5" },
		{ 1e-5, "1.E-05" }, { -2.5e-300, "-2.5E-300" }, { 1e21, "1.E+21" },
		{ 123456, "123456." }, { 0.1, "0.1" },
	};
	char buf[LOFT_NUMBUF + 2];

	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		loft_cad_real(buf, cases[i].x);
		CHECK(strcmp(buf, cases[i].s) == 0, "real %g: '%s', want '%s'",
		    cases[i].x, buf, cases[i].s);
	}
}

/* Knots: 0 .. n with multiplicities d+1, d, ..., d, d+1. */
static void
test_knots(void)
{
	double k[4];
	int m[4];

	loft_cad_knots(3, 3, k, m);
	CHECK(k[0] == 0 && k[3] == 3 && m[0] == 4 && m[1] == 3 && m[2] == 3 &&
	    m[3] == 4, "knots of 3 cubic pieces");
}

int
main(void)
{
	test_patch();
	test_curves();
	test_split();
	test_real();
	test_knots();
	return check_done("cad");
}
