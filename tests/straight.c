/*
 * straight.c: loft_straight_spans on outlines built here, whose straight
 * runs are known by construction: a stadium (two lines, two half
 * circles of two cubic arcs each), turned and lifted into space; a
 * rectangle (lines meeting lines); the stadium with its arcs turned
 * off the line's direction by 0.01 rad (kinks, not runs); an open curve.
 */
#include <string.h>

#include "../lib/loft.h"
#include "check.h"

/* A quarter arc of the circle about (cx, cy), radius r, from angle a
 * counter-clockwise: the usual cubic, arms 4/3 tan(pi/8) r, as a row. */
static void
arc(double *s, double cx, double cy, double r, double a)
{
	double k = 3 * 4.0 / 3 * tan(M_PI / 8) * r, b = a + M_PI / 2;
	double row[8] = { cx + r * cos(a), cy + r * sin(a), cx + r * cos(b),
	    cy + r * sin(b), -k * sin(a), k * cos(a), -k * sin(b), k * cos(b) };

	memcpy(s, row, sizeof row);
}

static void
line(double *s, double x0, double y0, double x1, double y1)
{
	double row[8] = { x0, y0, x1, y1, x1 - x0, y1 - y0, x1 - x0, y1 - y0 };

	memcpy(s, row, sizeof row);
}

/* The stadium: line 0, arcs 1 and 2, line 3, arcs 4 and 5. */
static void
stadium(double *s)
{
	line(s, 0, 0, 4, 0);
	arc(s + 8, 4, 1, 1, -M_PI / 2);
	arc(s + 16, 4, 1, 1, 0);
	line(s + 24, 4, 2, 0, 2);
	arc(s + 32, 0, 1, 1, M_PI / 2);
	arc(s + 40, 0, 1, 1, M_PI);
}

/* Turn the vector v (2 numbers) by angle a. */
static void
turn(double *v, double a)
{
	double x = v[0], y = v[1];

	v[0] = x * cos(a) - y * sin(a);
	v[1] = x * sin(a) + y * cos(a);
}

int
main(void)
{
	double s[48], sp[72];
	size_t out[12], n;

	stadium(s);
	n = loft_straight_spans(s, 6, 2, 1, out);
	CHECK(n == 2 && out[0] == 0 && out[1] == 3, "stadium: %zu runs", n);
	/* turned by 0.7 rad and lifted to z = 5: the same runs */
	for (int i = 0; i < 6; i++) {
		for (int j = 0; j < 4; j++) {
			double v[2] = { s[8 * i + 2 * j], s[8 * i + 2 * j + 1] };

			turn(v, 0.7);
			sp[12 * i + 3 * j] = v[0];
			sp[12 * i + 3 * j + 1] = v[1];
			sp[12 * i + 3 * j + 2] = j < 2 ? 5 : 0;
		}
	}
	n = loft_straight_spans(sp, 6, 3, 1, out);
	CHECK(n == 2 && out[0] == 0 && out[1] == 3, "turned stadium: %zu", n);
	/* a rectangle: lines meet lines, no curve, no run */
	line(s, 0, 0, 4, 0);
	line(s + 8, 4, 0, 4, 2);
	line(s + 16, 4, 2, 0, 2);
	line(s + 24, 0, 2, 0, 0);
	n = loft_straight_spans(s, 4, 2, 1, out);
	CHECK(n == 0, "rectangle: %zu runs", n);
	/* kinks: the arcs beside line 0 turned 0.01 rad at its ends */
	stadium(s);
	turn(s + 8 + 4, 0.01);
	turn(s + 40 + 6, -0.01);
	n = loft_straight_spans(s, 6, 2, 1, out);
	CHECK(n == 1 && out[0] == 3, "kinked stadium: %zu runs", n);
	/* open: the first 4 segments, line 0 and line 3 each beside an arc;
	 * without the closing join line 0 still meets arc 1 */
	stadium(s);
	n = loft_straight_spans(s + 8, 3, 2, 0, out);
	CHECK(n == 1 && out[0] == 2, "open arcs then line: %zu runs", n);
	n = loft_straight_spans(s, 1, 2, 0, out);
	CHECK(n == 0, "a lone line: %zu runs", n);
	n = loft_straight_spans(s, 6, 1, 1, out);
	CHECK(n == 0, "dimension 1: %zu runs", n);
	return check_done("straight");
}
