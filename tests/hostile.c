/*
 * hostile.c: the library's public functions called against their
 * preconditions (issue 12).  A precondition broken is an error code,
 * never undefined behaviour: each case here crashed, divided by zero or
 * wrote out of bounds before.  The references are the contracts in
 * loft.h (the code each call must return) and hand-made values.
 */
#include <limits.h>
#include <string.h>
#include <math.h>

#include "internal.h"             /* vnorm, vunit: the scaled norm */

#include "check.h"

static void
line_eval(void *ctx, double t, double *p, double *d1, double *d2)
{
	(void)ctx;
	p[0] = t, p[1] = 0;
	if (d1 != NULL)
		d1[0] = 1, d1[1] = 0;
	if (d2 != NULL)
		d2[0] = d2[1] = 0;
}

/* loft_normal_curve of a curve of no pieces: it divided by npieces. */
static void
test_normal_no_pieces(void)
{
	struct loft_pcurve a = { 2, 0, line_eval, NULL };
	struct loft_error err;
	double ctl[2 * 4], error = -1;

	CHECK(loft_normal_curve(&a, 3, 0, ctl, NULL, NULL, &error, &err) ==
	    LOFT_EINPUT, "a curve of 0 pieces is not LOFT_EINPUT");
	a.npieces = 1;                  /* and the same curve of one piece */
	CHECK(loft_normal_curve(&a, 3, 0, ctl, NULL, NULL, &error, &err) == 0,
	    "a straight line of one piece: %s", err.msg);
	NEAR(error, 0, 1e-20, "a line's own normal approximation is exact");
}

/*
 * loft_design_split of a patch naming a neighbour the design lacks: it
 * renamed the link in d->p[-1].  Now LOFT_EINPUT, the design unchanged.
 */
static void
test_split_missing_neighbour(void)
{
	static const double corner[8] = { 0, 0, 1, 0, 0, 1, 1, 1 };
	struct loft_attr attr[2] = { { "id", "1" }, { "u1", "2" } };
	struct loft_record rec;
	struct loft_design d = { 0 };
	struct loft_error err;
	double b[50];

	loft_patch_bilinear(corner, 2, b);
	memset(&rec, 0, sizeof rec);
	rec.type = "patch";
	rec.attr = attr;
	rec.nattr = 2;
	rec.num = b;
	rec.nrows = 5;
	rec.ncols = 10;
	rec.line = 1;
	rec.file = "test";
	CHECK(loft_design_add(&d, &rec, &err) == 0, "add: %s", err.msg);
	for (int dir = 0; dir < 2; dir++) {
		CHECK(loft_design_split(&d, 0, dir, 0.5, &err) == LOFT_EINPUT,
		    "split %d with neighbour 2 missing is not LOFT_EINPUT", dir);
		CHECK(d.n == 1 && d.maxid == 1, "the design changed: %zu "
		    "patches, largest id %ld", d.n, d.maxid);
	}
	CHECK(loft_design_split(&d, 1, 0, 0.5, &err) == LOFT_EINPUT,
	    "split of patch 1 of 1 is not LOFT_EINPUT");
	CHECK(loft_design_split(&d, 0, 2, 0.5, &err) == LOFT_EINPUT,
	    "split in direction 2 is not LOFT_EINPUT");
	CHECK(loft_design_split(&d, 0, 0, 1, &err) == LOFT_EINPUT,
	    "split at t = 1 is not LOFT_EINPUT");
	loft_design_free(&d);
}

/*
 * The preconditions of loft_design_new, loft_design_drag and
 * loft_design_join, broken one at a time: each an error code, the
 * design unchanged, where they read past d->p or took any dim and id.
 */
static void
test_design_preconditions(void)
{
	static const double corner[8] = { 0, 0, 1, 0, 0, 1, 1, 1 };
	static const double delta[2] = { 0.1, 0 }, nan_delta[2] = { NAN, 0 };
	struct loft_design d = { 0 };
	struct loft_drag_info info;
	struct loft_join_info jinfo;
	struct loft_error err;
	double b[75], before[75];

	loft_patch_bilinear(corner, 2, b);
	CHECK(loft_design_new(&d, b, 4, 1, &err) == LOFT_EINPUT && d.n == 0,
	    "a patch of 4 coordinates was added");
	CHECK(loft_design_new(&d, b, 2, 0, &err) == LOFT_EINPUT && d.n == 0,
	    "a patch of id 0 was added");
	CHECK(loft_design_new(&d, b, 2, 1000000001L, &err) == LOFT_EINPUT &&
	    d.n == 0, "a patch of id 1000000001 was added");
	CHECK(loft_design_new(&d, b, 2, 1, &err) == 0, "new: %s", err.msg);
	memcpy(before, d.p[0].b, 50 * sizeof *b);
	CHECK(loft_design_drag(&d, 1, 0.5, 0.5, delta, 0.1, &info, &err) ==
	    LOFT_EINPUT, "drag of patch 1 of 1 is not LOFT_EINPUT");
	CHECK(loft_design_drag(&d, 0, 1.5, 0.5, delta, 0.1, &info, &err) ==
	    LOFT_EINPUT, "drag at u = 1.5 is not LOFT_EINPUT");
	CHECK(loft_design_drag(&d, 0, 0.5, NAN, delta, 0.1, &info, &err) ==
	    LOFT_EINPUT, "drag at v = NaN is not LOFT_EINPUT");
	CHECK(loft_design_drag(&d, 0, 0.5, 0.5, nan_delta, 0.1, &info, &err) ==
	    LOFT_EINPUT, "a drag by NaN is not LOFT_EINPUT");
	CHECK(memcmp(before, d.p[0].b, 50 * sizeof *b) == 0,
	    "a refused drag changed the patch");
	CHECK(loft_design_join(&d, 0, 1, &jinfo, &err) == LOFT_EINPUT,
	    "join with patch 1 of 1 is not LOFT_EINPUT");
	for (int k = 24; k >= 0; k--) {         /* the patch in space */
		b[3 * k + 2] = 0;
		b[3 * k + 1] = b[2 * k + 1];
		b[3 * k] = b[2 * k];
	}
	CHECK(loft_design_new(&d, b, 3, 2, &err) == 0, "new: %s", err.msg);
	CHECK(loft_design_join(&d, 0, 1, &jinfo, &err) == LOFT_EINPUT,
	    "join of a plane and a space patch is not LOFT_EINPUT");
	loft_design_free(&d);
}

/*
 * Preconditions of the core checked where they were not: a dim other
 * than 2 or 3 (arrays of LOFT_MAXDIM overrun), an expression of three
 * variables (x[2] read), grading into the knots' own array (each knot
 * read after it was overwritten), digits outside 0..17.
 */
static void
test_core_preconditions(void)
{
	static const double a[4] = { 0, 0, 0, 0 }, b[4] = { 1, 0, 0, 0 };
	static const double knots[6] = { 0, 0, 10, 0, 10, 3 };
	const double *cv[4] = { a, a, a, a };
	struct loft_grade_frame f;
	struct loft_drag_info info;
	struct loft_error err;
	double t[4], q[5 * 4] = { 0 }, same[6];
	char buf[LOFT_NUMBUF];
	int col;

	CHECK(loft_end_tangent(a, b, NULL, 4, t, &err) == LOFT_EINPUT,
	    "a tangent in 4 dimensions is not LOFT_EINPUT");
	CHECK(loft_patch_coons(cv, 4, q, &err) == LOFT_EINPUT,
	    "a Coons patch in 4 dimensions is not LOFT_EINPUT");
	CHECK(loft_quartic_drag(q, 1, 4, 0, 0.5, b, 0.1, &info, &err) ==
	    LOFT_EINPUT, "a quartic drag in 4 dimensions is not LOFT_EINPUT");
	CHECK(loft_expr_parse("u", "uvw", &col, &err) == NULL && col == 0,
	    "an expression of three variables compiled");
	CHECK(loft_expr_parse("u", "", &col, &err) == NULL && col == 0,
	    "an expression of no variables compiled");
	memcpy(same, knots, sizeof same);
	CHECK(loft_grade_frame(same, 3, 0, NULL, &f, &err) == 0, "frame: %s",
	    err.msg);
	CHECK(loft_grade_outline(&f, same, 3, 1, 1, 0, same, &err) ==
	    LOFT_EINPUT && memcmp(same, knots, sizeof same) == 0,
	    "grading in place is not LOFT_EINPUT, the knots unchanged");
	loft_format_num(buf, 0.1, 18);
	CHECK(strcmp(buf, "0.1") == 0, "digits 18: '%s', want 0.1", buf);
	loft_format_num(buf, 0.1, -1);
	CHECK(strcmp(buf, "0.1") == 0, "digits -1: '%s', want 0.1", buf);
}

/* loft_parse_int near and past LONG_MAX: it wrapped (num.c, UBSan). */
static void
test_parse_int_wrap(void)
{
	static const struct { const char *s; long hi, want; } t[] = {
		{ "9223372036854775807", LONG_MAX, 9223372036854775807L },
		{ "9223372036854775808", LONG_MAX, -1 },
		{ "99999999999999999999", LONG_MAX, -1 },
		{ "999999999999999999999999999999999999999", LONG_MAX, -1 },
		{ "00000000000000000000000000000000000000012", LONG_MAX, 12 },
		{ "1000000001", 1000000000, -1 },
		{ "1000000000", 1000000000, 1000000000 },
		{ "10000000000000000001", 17, -1 },
	};
	struct loft_error err;

	for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
		long v = -7;
		int rc = loft_parse_int(t[i].s, 0, t[i].hi, &v, &err);

		if (LONG_MAX < 9223372036854775807L && t[i].hi == LONG_MAX)
			continue;       /* a 32-bit long: other limits */
		if (t[i].want < 0)
			CHECK(rc == LOFT_EINPUT && v == -7, "'%s' up to %ld: "
			    "rc %d, value %ld", t[i].s, t[i].hi, rc, v);
		else
			CHECK(rc == 0 && v == t[i].want, "'%s': rc %d, value "
			    "%ld", t[i].s, rc, v);
	}
}

/*
 * The scaled norm: exact on powers of two far out (3-4-5 triangles, the
 * reference by hand), and to the bit the plain root of the sum of
 * squares inside the range where that works (the figures depend on it).
 */
static void
test_scaled_norm(void)
{
	static const int ex[] = { 1000, 700, 600, 0, -600, -1000, -1060 };
	unsigned long long rng = 0x2545F4914F6CDD1DULL;

	for (size_t i = 0; i < sizeof ex / sizeof ex[0]; i++) {
		double a[3] = { ldexp(3, ex[i]), ldexp(-4, ex[i]), 0 };
		double n = vnorm(a, 3), m = vunit(a, 3);

		CHECK(n == ldexp(5, ex[i]) && m == n, "|(3, -4, 0) 2^%d| = "
		    "%.17g, %.17g, not 5 2^%d", ex[i], n, m, ex[i]);
		/* 3 (1 / 5) is 0.6 within an ulp, not to the bit */
		CHECK(fabs(a[0] - 0.6) < 2e-16 && fabs(a[1] + 0.8) < 2e-16 &&
		    a[2] == 0, "unit (3, -4, 0) 2^%d: %.17g %.17g", ex[i], a[0],
		    a[1]);
	}
	for (int i = 0; i < 10000; i++) {
		double a[3], plain = 0;

		for (int k = 0; k < 3; k++) {
			rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
			/* magnitudes 2^-400 to 2^400 */
			a[k] = ldexp((double)(rng >> 11) / 9007199254740992.0 -
			    0.5, (int)(rng % 801) - 400);
			plain += a[k] * a[k];
		}
		if (plain < 0x1p-900)
			continue;
		if (vnorm(a, 3) != sqrt(plain)) {
			CHECK(0, "|(%a, %a, %a)| differs from the plain root",
			    a[0], a[1], a[2]);
			break;
		}
	}
	{
		double big[2] = { 1.7e308, 1.7e308 }, zero[2] = { 0, -0.0 };

		double n = vnorm(big, 2), m = vunit(big, 2);

		CHECK(isinf(n) && isinf(m), "|(1.7e308, 1.7e308)| is %g, %g, "
		    "not above the largest double", n, m);
		CHECK(fabs(big[0] - sqrt(0.5)) < 2e-16 && big[0] == big[1],
		    "unit (1.7e308, 1.7e308): %g %g", big[0], big[1]);
		CHECK(vunit(zero, 2) == 0 && zero[0] == 0, "unit (0, 0)");
	}
}

/* t^i (1 - t)^(n - i) and its first and second derivatives in t, by
 * the product rule on the power form */
static void
monomial(int n, int i, double t, double *f)
{
	double a = i, b = n - i, s = 1 - t;

	f[0] = pow(t, a) * pow(s, b);
	f[1] = (a > 0 ? a * pow(t, a - 1) * pow(s, b) : 0) -
	    (b > 0 ? b * pow(t, a) * pow(s, b - 1) : 0);
	f[2] = (a > 1 ? a * (a - 1) * pow(t, a - 2) * pow(s, b) : 0) -
	    (a > 0 && b > 0 ? 2 * a * b * pow(t, a - 1) * pow(s, b - 1) : 0) +
	    (b > 1 ? b * (b - 1) * pow(t, a) * pow(s, b - 2) : 0);
}

static double
choose(int n, int k)
{
	return exp(lgamma(n + 1.0) - lgamma(k + 1.0) - lgamma(n - k + 1.0));
}

/*
 * A Bezier surface of degrees 63 x 63 (and 1 x 5, 2 x 2) against the
 * sum of its definition, C(m, i) C(n, j) u^i (1-u)^(m-i) v^j (1-v)^(n-j)
 * P_ij, differentiated by hand; and 10,000 points of the 63 x 63 net in
 * well under a second of processor time: its evaluation is O(m n) per
 * point (a de Casteljau triangle per row, O(m n^2), took 4 s).
 */
static void
test_bezier_surface(void)
{
	static const int deg[][2] = { { 63, 63 }, { 1, 5 }, { 2, 2 } };
	static double ctl[64 * 64 * 3];
	struct loft_surface sf = { 0 };
	struct loft_record rec;
	struct loft_error err;
	struct loft_attr attr[2] = { { "m", "63" }, { "n", "63" } };

	for (size_t k = 0; k < sizeof ctl / sizeof ctl[0]; k++)
		ctl[k] = sin(0.37 * (double)k) + (double)(k % 3);
	for (size_t d = 0; d < sizeof deg / sizeof deg[0]; d++) {
		int m = deg[d][0], n = deg[d][1];
		char ms[8], ns[8];

		snprintf(ms, sizeof ms, "%d", m);
		snprintf(ns, sizeof ns, "%d", n);
		attr[0].val = ms;
		attr[1].val = ns;
		memset(&rec, 0, sizeof rec);
		rec.type = "bezier-surface";
		rec.attr = attr;
		rec.nattr = 2;
		rec.num = ctl;
		rec.nrows = (size_t)(m + 1) * (size_t)(n + 1);
		rec.ncols = 3;
		CHECK(loft_surface_from_record(&rec, &sf, &err) == 0, "%s",
		    err.msg);
		for (int q = 0; q < 7; q++) {
			double u = q / 6.0, v = fmod(0.3 + q * 0.29, 1);
			double got[5][3], want[5][3] = { { 0 } }, most = 0;

			loft_surface_eval2(&sf, u, v, got[0], got[1], got[2],
			    got[3], got[4]);
			for (int i = 0; i <= m; i++)
				for (int j = 0; j <= n; j++) {
					double fu[3], fv[3], c = choose(m, i) *
					    choose(n, j);
					const double *pij = ctl + 3 * (i * (n + 1) + j);

					monomial(m, i, u, fu);
					monomial(n, j, v, fv);
					for (int k = 0; k < 3; k++) {
						want[0][k] += c * fu[0] * fv[0] * pij[k];
						want[1][k] += c * fu[1] * fv[0] * pij[k];
						want[2][k] += c * fu[0] * fv[1] * pij[k];
						want[3][k] += c * fu[2] * fv[0] * pij[k];
						want[4][k] += c * fu[0] * fv[2] * pij[k];
					}
				}
			for (int e = 0; e < 5; e++)
				for (int k = 0; k < 3; k++)
					most = fmax(most, fabs(got[e][k] - want[e][k]) /
					    fmax(1, fabs(want[e][k])));
			/* the sum of 4096 terms, some 1e17 before they cancel
			 * in the derivatives: 1e-9 is a few hundred ulps */
			CHECK(most < 1e-9, "%dx%d at (%g, %g): off by %g", m, n,
			    u, v, most);
		}
	}
	attr[0].val = "63";
	attr[1].val = "63";
	rec.nrows = 64 * 64;
	CHECK(loft_surface_from_record(&rec, &sf, &err) == 0, "%s", err.msg);
	/* every point finite (its speed: make bench, case surface-63) */
	int bad = 0;

	for (int q = 0; q < 10000; q++) {
		double p[3], pu[3], pv[3];

		loft_surface_eval(&sf, (q % 100) / 99.0, (q / 100) / 99.0, p, pu,
		    pv);
		bad += !isfinite(p[0] + p[1] + p[2] + pu[0] + pv[2]);
	}
	CHECK(bad == 0, "63 x 63 net: %d of 10,000 points not finite", bad);
}

int
main(void)
{
	test_normal_no_pieces();
	test_split_missing_neighbour();
	test_design_preconditions();
	test_core_preconditions();
	test_parse_int_wrap();
	test_scaled_norm();
	test_bezier_surface();
	return check_done("hostile");
}
