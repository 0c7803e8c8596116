/*
 * arclen.c: unit tests of the curve measures (lib/arclen.c, measure.c,
 * flatten.c, and curve.c's Bernstein form) against references derived
 * here: Bernstein sums by loft_bernstein, the parabola's closed-form arc
 * length, curvature jumps by hand.
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "loft.h"

/* A curve record of type type, rows x cols numbers num. */
static void
curve(struct loft_record *rec, struct loft_curve *c, const char *type,
    double *num, size_t rows, int cols)
{
	struct loft_error err;

	memset(rec, 0, sizeof *rec);
	rec->type = (char *)type;
	rec->num = num;
	rec->nrows = rows;
	rec->ncols = cols;
	CHECK(loft_curve_from_record(rec, c, &err) == 0, "%s record", type);
}

/*
 * Each piece's Bernstein form, summed by loft_bernstein, is the piece
 * loft_curve_eval evaluates.
 */
static void
test_bezier_form(void)
{
	double cub[] = { 0.5, -1, 3, 2, 4, 1, -2, 5, 3, 2, 1, 0, 1, 1, -1, 0 };
	double qua[] = { 1, 2, 4, -1, 3, 0, 0, -3, 2, 1 };
	double bez[] = { 0, 0, 1, 3, 2, -1, 4, 4, 5, 0 };
	struct { const char *type; double *num; size_t rows; int cols; } t[] = {
		{ "cubic", cub, 2, 8 }, { "quartic", qua, 1, 10 },
		{ "bezier", bez, 5, 2 },
	};

	for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
		struct loft_record rec;
		struct loft_curve c;
		double ctl[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM], b[LOFT_BEZIER_MAXPTS];
		double worst = 0;

		curve(&rec, &c, t[k].type, t[k].num, t[k].rows, t[k].cols);
		for (size_t i = 0; i < c.npieces; i++) {
			int n = loft_curve_bezier(&c, i, ctl);

			for (int j = 0; j <= 8; j++) {
				double u = j / 8.0, p[LOFT_MAXDIM];

				loft_curve_eval(&c, i, u, p, NULL, NULL);
				loft_bernstein(n, u, b);
				for (int q = 0; q < c.dim; q++) {
					double s = 0;

					for (int m = 0; m <= n; m++)
						s += b[m] * ctl[m * c.dim + q];
					worst = fmax(worst, fabs(s - p[q]));
				}
			}
		}
		CHECK(worst < 1e-14, "%s: Bernstein form off by %g", t[k].type,
		    worst);
	}
}

/* y = x^2 from 0 to 2 as x = 2t: s(x) = x w / 2 + asinh(2x) / 4. */
static double
parabola_arc(double x)
{
	double w = sqrt(1 + 4 * x * x);

	return x * w / 2 + log(2 * x + w) / 4;
}

static void
test_arc(void)
{
	double bez[] = { 0, 0, 1, 0, 2, 4 };
	struct loft_record rec;
	struct loft_curve c;
	double len, u[64];
	size_t n;

	curve(&rec, &c, "bezier", bez, 3, 2);
	len = loft_curve_length(&c);
	NEAR(len, parabola_arc(2), 1e-12 * len, "parabola length");
	for (int j = 1; j < 8; j++) {
		double t = j / 8.0, s;

		NEAR(loft_curve_arc(&c, 0, t), parabola_arc(2 * t), 1e-12 * len,
		    "arc to t");
		NEAR(loft_curve_arc(&c, t, 0), -parabola_arc(2 * t), 1e-12 * len,
		    "arc backwards");
		s = parabola_arc(2 * t);
		NEAR(parabola_arc(2 * loft_curve_at_length(&c, s)), s,
		    1e-12 * len, "the parameter at a length");
	}
	CHECK(loft_curve_at_length(&c, -1) == 0, "before the start");
	CHECK(loft_curve_at_length(&c, 2 * len) == 1, "beyond the end");
	/* spacing: 0, 0.5, ... and the end; each point at its length */
	n = loft_spaced_count(len, 0.5);
	CHECK(n == (size_t)floor(len / 0.5) + 2, "%zu spaced points", n);
	loft_curve_spaced(&c, 0.5, u, n);
	CHECK(u[0] == 0 && u[n - 1] == 1, "spacing from start to end");
	for (size_t k = 1; k + 1 < n; k++)
		NEAR(parabola_arc(2 * u[k]), 0.5 * k, 1e-12 * len, "spaced");
	CHECK(loft_spaced_count(10, 2.5) == 5, "a length of 4 steps");
	CHECK(loft_spaced_count(10, 3) == 5, "a short last step");
	CHECK(loft_spaced_count(10, 20) == 2, "a step beyond the end");
	CHECK(loft_spaced_count(10 * (1 + 1e-12), 2.5) == 5, "a near tie");
}

static void
test_flatten(void)
{
	double line[] = { 0, 0, 3, 4, 6, 8, 1.5, 2 };
	double bez[] = { 0, 0, 1, 0, 2, 4 };
	struct loft_record rec;
	struct loft_curve c;
	double u[4096], worst = 0;
	size_t n;

	curve(&rec, &c, "cubic", line, 1, 8);
	CHECK(loft_curve_flatten(&c, 1e-6, u, 4096) == 2, "a line, 2 points");
	curve(&rec, &c, "bezier", bez, 3, 2);
	n = loft_curve_flatten(&c, 1e-4, u, 4096);
	CHECK(n > 2 && n < 4096, "%zu points", n);
	CHECK(loft_curve_flatten(&c, 1e-4, u, 3) == n, "the count, short room");
	n = loft_curve_flatten(&c, 1e-4, u, 4096);
	/* the distance from y = x^2 at x between two points' x to their
	 * chord, largest at the mean x: (b - a)^2 / 4 vertically; the
	 * perpendicular distance is at most that */
	for (size_t k = 0; k + 1 < n; k++) {
		double a = 2 * u[k], b = 2 * u[k + 1];

		CHECK(u[k + 1] > u[k], "increasing");
		worst = fmax(worst, (b - a) * (b - a) / 4 /
		    sqrt(1 + (a + b) * (a + b)));
	}
	CHECK(worst <= 1e-4, "a chord %g from the parabola", worst);
	CHECK(worst > 1e-5, "only %g: too many points", worst);
}

/*
 * A line (0,0)-(1,0) then x = 1 + t, y = t^2 (Hermite ends (1,0) (2,1),
 * tangents (1,0) (1,2)): curvature 0 then 2 at the knot u = 1.
 */
static void
test_jump(void)
{
	double two[] = { 0, 0, 1, 0, 1, 0, 1, 0, 1, 0, 2, 1, 1, 0, 1, 2 };
	struct loft_curve c;
	struct loft_error err;
	double jump, u, r;
	long k;

	loft_curve_cubic(&c, two, 2, 2, 0);
	loft_curve_jump(&c, &jump, &u);
	NEAR(jump, 2, 1e-14, "the jump at the knot");
	CHECK(u == 1, "the jump at u = %g", u);
	CHECK(loft_curve_min_radius(&c, &r, &u, &err) == 0, "min radius");
	NEAR(r, 0.5, 1e-14, "radius 1/2 after the knot");
	CHECK(u == 1, "at u = %g", u);
	CHECK(loft_curve_inflexions(&c, &k, &err) == 0 && k == 0,
	    "a straight stretch is no inflexion on its own: %ld", k);
	NEAR(loft_curve_length(&c), 1 + (sqrt(5) + asinh(2) / 2) / 2, 1e-14,
	    "1 and the arc of y = t^2 to t = 1");
}

/*
 * A curve of no pieces (loft_curve_cubic takes nseg = 0) has no first
 * point to measure from: the centroid is refused, not made of garbage.
 */
static void
test_no_pieces(void)
{
	double none[16] = { 0 };
	struct loft_curve c;
	struct loft_error err;
	double cen[2];

	for (int closed = 0; closed < 2; closed++) {
		loft_curve_cubic(&c, none, 0, 2, closed);
		CHECK(loft_curve_centroid(&c, cen, &err) == LOFT_EINPUT,
		    "no centroid of no pieces (closed=%d)", closed);
	}
}

int
main(void)
{
	test_bezier_form();
	test_arc();
	test_flatten();
	test_jump();
	test_no_pieces();
	return check_done("arclen");
}
