/*
 * paper.c: Manning (1973)'s results as assertions.  Usage: paper INSOLE,
 * INSOLE the 22-knot outline.  Derivatives at segment ends are computed
 * here from the formulas of section 5, not by the library's evaluator,
 * and curvature by the cross-product form of eq. 2.
 */
#include <stdlib.h>
#include <string.h>

#include "loftprog.h"
#include "check.h"

#define MAXKNOTS 100000

static double seg[4 * 3 * MAXKNOTS], seg2[4 * 3 * MAXKNOTS];

/* ------------------------------------------------------------------ */
/* independent measures of a fitted curve */

static double
dot(const double *a, const double *b, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++)
		s += a[k] * b[k];
	return s;
}

static double
norm(const double *a, int dim)
{
	return sqrt(dot(a, a, dim));
}

/* P'' at u = 0 and u = 1 of a segment (section 5, from eq. 7):
 * 6(P_B - P_A) - 4P'_A - 2P'_B and -6(P_B - P_A) + 2P'_A + 4P'_B. */
static void
second_derivs(const double *s, int dim, double *d0, double *d1)
{
	for (int k = 0; k < dim; k++) {
		double c = s[dim + k] - s[k];

		d0[k] = 6 * c - 4 * s[2 * dim + k] - 2 * s[3 * dim + k];
		d1[k] = -6 * c + 2 * s[2 * dim + k] + 4 * s[3 * dim + k];
	}
}

/* Curvature vector P' x (P'' x P') / |P'|^4, in 3-D (2-D padded). */
static void
kappa_n(const double *d1, const double *d2, int dim, double *kn)
{
	double a[3] = { 0, 0, 0 }, b[3] = { 0, 0, 0 }, c[3], aa;

	memcpy(a, d1, dim * sizeof *a);
	memcpy(b, d2, dim * sizeof *b);
	aa = dot(a, a, 3);
	c[0] = b[1] * a[2] - b[2] * a[1];
	c[1] = b[2] * a[0] - b[0] * a[2];
	c[2] = b[0] * a[1] - b[1] * a[0];
	kn[0] = (a[1] * c[2] - a[2] * c[1]) / (aa * aa);
	kn[1] = (a[2] * c[0] - a[0] * c[2]) / (aa * aa);
	kn[2] = (a[0] * c[1] - a[1] * c[0]) / (aa * aa);
}

struct joins {
	double pos, dir, curv;  /* largest jumps: |dP|/size, |dT|, |d kn|/max */
};

/* Continuity at every knot where segment i ends and segment i+1 begins. */
static struct joins
continuity(const double *s, size_t nseg, int dim, int closed)
{
	struct joins j = { 0, 0, 0 };
	double big = 0, size = 0;
	size_t njoin = closed ? nseg : nseg - 1;

	for (size_t i = 0; i < nseg; i++)
		if (norm(s + 4 * dim * i, dim) > size)
			size = norm(s + 4 * dim * i, dim);
	for (size_t i = 0; i < njoin; i++) {
		const double *a = s + 4 * dim * i, *b = s + 4 * dim *
		    ((i + 1) % nseg);
		double a0[3], a1[3], b0[3], b1[3], ka[3], kb[3], ta[3], tb[3],
		    d[3];

		second_derivs(a, dim, a0, a1);
		second_derivs(b, dim, b0, b1);
		kappa_n(a + 3 * dim, a1, dim, ka);
		kappa_n(b + 2 * dim, b0, dim, kb);
		for (int k = 0; k < 3; k++)
			d[k] = ka[k] - kb[k];
		if (norm(d, 3) > j.curv)
			j.curv = norm(d, 3);
		if (norm(ka, 3) > big)
			big = norm(ka, 3);
		if (norm(kb, 3) > big)
			big = norm(kb, 3);
		for (int k = 0; k < dim; k++) {
			ta[k] = a[3 * dim + k] / norm(a + 3 * dim, dim);
			tb[k] = b[2 * dim + k] / norm(b + 2 * dim, dim);
			d[k] = a[dim + k] - b[k];
		}
		if (norm(d, dim) / size > j.pos)
			j.pos = norm(d, dim) / size;
		for (int k = 0; k < dim; k++)
			d[k] = ta[k] - tb[k];
		if (norm(d, dim) > j.dir)
			j.dir = norm(d, dim);
	}
	j.curv = big > 0 ? j.curv / big : 0;
	return j;
}

/* Eq. 9 with alpha = 2/3 holds for every segment's tangent magnitudes;
 * returns the largest relative error. */
static double
normalisation_error(const double *s, size_t nseg, int dim)
{
	double worst = 0;

	for (size_t i = 0; i < nseg; i++) {
		const double *a = s + 4 * dim * i;
		double c[3], w, ca, cb, ma, mb;

		for (int k = 0; k < dim; k++)
			c[k] = a[dim + k] - a[k];
		w = norm(c, dim);
		ca = dot(a + 2 * dim, c, dim) / (norm(a + 2 * dim, dim) * w);
		cb = dot(a + 3 * dim, c, dim) / (norm(a + 3 * dim, dim) * w);
		ma = 2 * w / (1 + 2.0 / 3 * cb + 1.0 / 3 * ca);
		mb = 2 * w / (1 + 2.0 / 3 * ca + 1.0 / 3 * cb);
		worst = fmax(worst, fabs(norm(a + 2 * dim, dim) - ma) / ma);
		worst = fmax(worst, fabs(norm(a + 3 * dim, dim) - mb) / mb);
	}
	return worst;
}

/* Turns of the tangent of a closed plane curve, sampled finely. */
static double
turning(const double *s, size_t nseg)
{
	double total = 0, prev = 0;

	for (size_t i = 0; i < nseg; i++)
		for (int j = 0; j <= 200; j++) {
			double d[2], a, step;

			loft_cubic_eval(s + 8 * i, 2, j / 200.0, NULL, d, NULL);
			a = atan2(d[1], d[0]);
			if (i + j > 0) {
				step = a - prev;
				step -= 2 * M_PI * floor((step + M_PI) /
				    (2 * M_PI));
				total += step;
			}
			prev = a;
		}
	return total / (2 * M_PI);
}

/* Sign changes of the curvature x'y'' - y'x'' of a closed plane curve. */
static int
inflexions(const double *s, size_t nseg)
{
	int count = 0, prev = 0;

	for (size_t i = 0; i < nseg; i++)
		for (int j = 0; j < 200; j++) {
			double d[2], e[2], c;

			loft_cubic_eval(s + 8 * i, 2, j / 200.0, NULL, d, e);
			c = d[0] * e[1] - d[1] * e[0];
			if (prev != 0 && (c > 0 ? 1 : -1) != prev)
				count++;
			prev = c > 0 ? 1 : -1;
		}
	return count;
}

/* K_i of eq. 10 at knot i, from the fitted tangents and magnitudes. */
static double
k_coefficient(const double *p, const double *s, size_t n, size_t i)
{
	size_t h = (i + n - 1) % n, j = (i + 1) % n;
	const double *sh = s + 8 * h, *si = s + 8 * i;
	double ri = norm(si + 4, 2), li = norm(sh + 6, 2);
	double rh = norm(sh + 4, 2), lj = norm(si + 6, 2);
	double t[2], v[2];

	for (int k = 0; k < 2; k++) {
		double th = sh[4 + k] / rh, tj = si[6 + k] / lj;

		t[k] = si[4 + k] / ri;
		v[k] = 3 * (ri * ri * (p[2 * i + k] - p[2 * h + k]) + li * li *
		    (p[2 * j + k] - p[2 * i + k])) - rh * ri * ri * th -
		    li * li * lj * tj;
	}
	return dot(v, t, 2);
}

static void
fit_ok(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    double *s, struct loft_fit_info *info, const char *what)
{
	struct loft_error err;
	int rc = loft_fit(o, p, n, dim, s, info, &err);

	CHECK(rc == 0, "%s: fit fails: %s", what, rc ? err.msg : "");
}

/* Every fit: continuous position, direction and curvature vector at each
 * knot, and normalised magnitudes. */
static void
check_fair(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    const char *what)
{
	size_t nseg = o->closed ? n : n - 1;
	struct joins j;

	fit_ok(o, p, n, dim, seg, NULL, what);
	j = continuity(seg, nseg, dim, o->closed);
	CHECK(j.pos < 1e-15, "%s: position jump %g", what, j.pos);
	CHECK(j.dir < 1e-12, "%s: direction jump %g", what, j.dir);
	CHECK(j.curv < 1e-9, "%s: curvature jump %g", what, j.curv);
	CHECK(normalisation_error(seg, nseg, dim) < 1e-12,
	    "%s: eq. 11 off by %g", what, normalisation_error(seg, nseg, dim));
}

/* ------------------------------------------------------------------ */
/* the knot sets */

static const double square[] = { 1, 1, -1, 1, -1, -1, 1, -1 };
static const double rect[] = { 2, 1, -2, 1, -2, -1, 2, -1 };
/* Fig. 8 and 9: the rectangle with knots added on the major or the
 * minor axis */
static const double quasi_ellipse[] = { 3, 0, 2, 1, -2, 1, -3, 0, -2, -1,
    2, -1 };
static const double oblate[] = { 2, 1, 0, 1.6, -2, 1, -2, -1, 0, -1.6,
    2, -1 };
/* Fig. 15-like: a circle of radius 10 with knot 3 pulled in to (0, 2). */
static const double ambiguous[] = { 10, 0, 3.5, 9.4, 0, 2, -3.5, 9.4,
    -10, 0, -7, -7, 0, -10, 7, -7 };
/* A quarter circle, clockwise from (0, 1) to (1, 0). */
static const double arc[] = { 0, 1, 0.5, 0.8660254037844386,
    0.8660254037844386, 0.5, 1, 0 };

/* Section 7: the tennis-ball seam, b/a = 55/24, r^2 = a^2 + b^2. */
static void
tennis(double *p, int eight)
{
	double a = 24, b = 55, r = hypot(a, b), q = r / sqrt(2);
	double four[4][3] = { { a, 0, b }, { -a, b, 0 }, { a, 0, -b },
	    { -a, -b, 0 } };
	double mid[4][3] = { { 0, q, q }, { 0, q, -q }, { 0, -q, -q },
	    { 0, -q, q } };

	for (int i = 0; i < 4; i++) {
		memcpy(p + (eight ? 6 : 3) * i, four[i], sizeof four[i]);
		if (eight)
			memcpy(p + 6 * i + 3, mid[i], sizeof mid[i]);
	}
}

/* Largest |distance from centre - r| / r over the sampled curve. */
static double
radial_error(const double *s, size_t nseg, int dim, double r)
{
	double worst = 0, x[3];

	for (size_t i = 0; i < nseg; i++)
		for (int j = 0; j < 400; j++) {
			loft_cubic_eval(s + 4 * dim * i, dim, j / 400.0, x, NULL,
			    NULL);
			worst = fmax(worst, fabs(norm(x, dim) - r) / r);
		}
	return worst;
}

/* Fig. 7: four knots at a square's corners give a near-circle. */
static void
test_fig7(void)
{
	struct loft_fit_opts o;

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	fit_ok(&o, square, 4, 2, seg, NULL, "square");
	CHECK(radial_error(seg, 4, 2, sqrt(2)) < 5e-4,
	    "square: radius off by %g of the circumradius",
	    radial_error(seg, 4, 2, sqrt(2)));
}

/* Section 7: the eight-knot seam stays within 0.003 r of the sphere; the
 * four-knot curve of Fig. 13 does not. */
static void
test_tennis(void)
{
	struct loft_fit_opts o;
	double p[24], r = hypot(24, 55);

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	tennis(p, 1);
	fit_ok(&o, p, 8, 3, seg, NULL, "tennis 8");
	CHECK(radial_error(seg, 8, 3, r) < 0.003, "tennis 8: %g r from the "
	    "sphere", radial_error(seg, 8, 3, r));
	tennis(p, 0);
	fit_ok(&o, p, 4, 3, seg, NULL, "tennis 4");
	CHECK(radial_error(seg, 4, 3, r) > 0.003, "tennis 4 lies on the "
	    "sphere? %g r", radial_error(seg, 4, 3, r));
}

static void
test_continuity(const double *insole)
{
	struct loft_fit_opts o;
	double p[24];

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	for (int sign = LOFT_SIGN_POSITIVE; sign <= LOFT_SIGN_TURN; sign++) {
		o.sign = sign;
		check_fair(&o, square, 4, 2, "square");
		check_fair(&o, rect, 4, 2, "rectangle");
		check_fair(&o, quasi_ellipse, 6, 2, "quasi-ellipse");
		check_fair(&o, oblate, 6, 2, "oblate");
		check_fair(&o, ambiguous, 8, 2, "Fig. 15 knots");
		check_fair(&o, insole, 22, 2, "insole");
		tennis(p, 1);
		check_fair(&o, p, 8, 3, "tennis 8");
		tennis(p, 0);
		check_fair(&o, p, 4, 3, "tennis 4");
	}
	o.closed = 0;
	check_fair(&o, arc, 4, 2, "open arc, estimated ends");
	check_fair(&o, insole, 22, 2, "open insole");
	o.have_start = o.have_end = 1;
	o.start[0] = 2, o.start[1] = 0.5, o.end[0] = 0.5, o.end[1] = -1;
	check_fair(&o, arc, 4, 2, "open arc, given ends");
}

/*
 * Section 8, Fig. 15: two sign rules, two curves through the same knots.
 * As in the paper, K_i > 0 makes a loop (the tangent turns twice, no
 * inflexion) and the turn rule an inlet (turns once, two inflexions).
 * Unlike the paper's knots, whose coordinates it does not give, at this
 * inlet every K_i is positive too: it is a solution of both rules, and
 * the rule decides which one the iteration of section 6 reaches.
 */
static void
test_fig15(void)
{
	struct loft_fit_opts o;
	struct loft_fit_info a, b;

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	fit_ok(&o, ambiguous, 8, 2, seg, &a, "positive rule");
	o.sign = LOFT_SIGN_TURN;
	fit_ok(&o, ambiguous, 8, 2, seg2, &b, "turn rule");
	CHECK(a.converged && b.converged, "both converge");
	CHECK(loft_tangent_distance(seg, seg2, 8, 2) > 0.5,
	    "two different curves: tangents differ by %g",
	    loft_tangent_distance(seg, seg2, 8, 2));
	NEAR(turning(seg, 8), 2, 1e-6, "positive rule: a loop");
	NEAR(turning(seg2, 8), 1, 1e-6, "turn rule: an inlet");
	CHECK(inflexions(seg, 8) == 0, "loop: %d inflexions",
	    inflexions(seg, 8));
	CHECK(inflexions(seg2, 8) == 2, "inlet: %d inflexions",
	    inflexions(seg2, 8));
	for (size_t i = 0; i < 8; i++)
		CHECK(k_coefficient(ambiguous, seg, 8, i) > 0 &&
		    k_coefficient(ambiguous, seg2, 8, i) > 0, "K_%zu > 0", i + 1);
}

/* Section 9: open curves leave and arrive along the given directions. */
static void
test_open_ends(void)
{
	struct loft_fit_opts o;
	const double *last = seg + 8 * 2;

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	o.closed = 0;
	o.have_start = o.have_end = 1;
	o.start[0] = 3, o.start[1] = 0;         /* only the direction counts */
	o.end[0] = 0, o.end[1] = -1;
	fit_ok(&o, arc, 4, 2, seg, NULL, "arc");
	CHECK(seg[4] > 0 && seg[5] == 0, "leaves along +x: %g %g", seg[4],
	    seg[5]);
	CHECK(last[6] == 0 && last[7] < 0, "arrives along -y: %g %g",
	    last[6], last[7]);
	CHECK(radial_error(seg, 3, 2, 1) < 1e-6, "on the unit circle: %g",
	    radial_error(seg, 3, 2, 1));
	/* estimated: the tangent of the circle through the end knots */
	o.have_start = o.have_end = 0;
	fit_ok(&o, arc, 4, 2, seg, NULL, "arc, estimated ends");
	NEAR(seg[5] / norm(seg + 4, 2), 0, 1e-15, "estimated start along +x");
	NEAR(last[6] / norm(last + 6, 2), 0, 1e-15, "estimated end along -y");
}

/* The iteration count does not grow with the number of knots: the same
 * smooth outline through 22 and through 100000 knots. */
static int
outline_iterations(size_t n, double *p)
{
	struct loft_fit_opts o;
	struct loft_fit_info info;

	for (size_t i = 0; i < n; i++) {
		double t = 2 * M_PI * (i + 0.3 * sin(14 * M_PI * i / n) / 7) / n;
		double r = 1 + 0.2 * cos(3 * t);

		p[2 * i] = 130 * r * cos(t);
		p[2 * i + 1] = 45 * r * sin(t);
	}
	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	fit_ok(&o, p, n, 2, seg, &info, "outline");
	return info.iterations;
}

static void
test_iterations(void)
{
	double *p = malloc(2 * MAXKNOTS * sizeof *p);
	int few = outline_iterations(22, p), many = outline_iterations(MAXKNOTS,
	    p);

	CHECK(many <= few + 10, "100000 knots: %d iterations, 22 knots: %d",
	    many, few);
	/* segments 1/100000 of the curve long still join in curvature to
	 * within rounding of their second derivatives (about 1e-16 of the
	 * coordinates over h^2 kappa, here near 1e-9) */
	CHECK(continuity(seg, MAXKNOTS, 2, 1).curv < 5e-8,
	    "100000 knots: curvature jump %g",
	    continuity(seg, MAXKNOTS, 2, 1).curv);
	free(p);
}

/* The same knots in other units, or far from the origin, give the same
 * curve in those units: scale by 1e-6, 1e6, 1e100, or translate by 1e6. */
static void
test_units(const double *insole)
{
	static const double scale[] = { 1e-6, 1e6, 1e100, 1 }, shift[] = {
	    0, 0, 0, 1e6 };
	struct loft_fit_opts o;
	double p[44];

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	fit_ok(&o, insole, 22, 2, seg, NULL, "insole");
	for (int c = 0; c < 4; c++) {
		double worst = 0;

		for (int i = 0; i < 44; i++)
			p[i] = scale[c] * insole[i] + shift[c];
		fit_ok(&o, p, 22, 2, seg2, NULL, "insole in other units");
		for (int i = 0; i < 22; i++)
			for (int k = 4; k < 8; k++)
				worst = fmax(worst, fabs(seg2[8 * i + k] /
				    scale[c] - seg[8 * i + k]) /
				    norm(seg + 8 * i + (k < 6 ? 4 : 6), 2));
		CHECK(worst < 1e-9, "units %g, shift %g: tangents differ by "
		    "%g relative", scale[c], shift[c], worst);
	}
}

/* No convergence within -i is an error that says how far it got. */
static void
test_noconv(void)
{
	struct loft_fit_opts o;
	struct loft_fit_info info;
	struct loft_error err;

	loft_fit_defaults(&o);
	o.method = LOFT_MANNING;
	o.maxiter = 3;
	CHECK(loft_fit(&o, ambiguous, 8, 2, seg, &info, &err) == LOFT_ENOCONV,
	    "3 iterations are not enough");
	CHECK(info.change > o.tol && strstr(err.msg, "3 iterations") != NULL,
	    "residual %g, message %s", info.change, err.msg);
}

static int
read_knots(const char *path, double *p, size_t max)
{
	FILE *fp = fopen(path, "r");
	struct loft_reader *rd;
	struct loft_record rec = { 0 };
	struct loft_error err;
	int n = -1;

	if (fp == NULL)
		return -1;
	rd = loft_reader_new(fp, path);
	if (loft_read(rd, &rec, &err) == 1 && rec.ncols == 2 &&
	    rec.nrows <= max) {
		memcpy(p, rec.num, 2 * rec.nrows * sizeof *p);
		n = (int)rec.nrows;
	}
	loft_record_free(&rec);
	loft_reader_free(rd);
	fclose(fp);
	return n;
}

int
main(int argc, char *argv[])
{
	double insole[44];

	if (argc != 2 || read_knots(argv[1], insole, 22) != 22) {
		fprintf(stderr, "usage: paper INSOLE (22 knots)\n");
		return 2;
	}
	test_fig7();
	test_tennis();
	test_continuity(insole);
	test_fig15();
	test_open_ends();
	test_iterations();
	test_noconv();
	test_units(insole);
	return check_done("paper");
}
