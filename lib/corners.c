/*
 * corners.c: the corners of an outline given by dense noisy points
 * (splinefit -e finds them where the record names none).  As potrace
 * judges a corner by what a smooth curve could do within the pixel's
 * tube, a corner here is judged at a scale of a few tolerances: the
 * line through the points on either side of a point, each over that
 * length, turns by a sharp angle there.  A smooth bend turns the
 * lines by its length over its radius, so only a bend too tight for a
 * smooth curve to follow within the tolerance reads as a corner; noise
 * of the size of the tolerance tilts a line over that length by little.
 */
#include <stdlib.h>

#include "internal.h"

/* The scale: this many tolerances, or this many spacings of the
 * points, whichever is longer (a line needs a few points to lean on). */
#define CORNER_TOLS 3.0
#define CORNER_SPACINGS 6.0

/* A turn sharper than this (radians, 30 degrees) is a corner: noise
 * tilts a line over the scale by a few degrees at most, a smooth curve
 * turns this much over it only at a radius of twice the scale. */
#define CORNER_TURN 0.52

/* A corner turns about as much over twice the scale as over it; a
 * smooth bend, twice as much: a turn is a corner only where the turn
 * over twice the scale is at most this many times it. */
#define CORNER_CONCENTRATED 1.5

/* A turn is a corner only where it is this many times its standard
 * error, from the scatter of the points about the two lines: noise
 * tilts a line through k points of scatter r over a length L by about
 * r sqrt(12 / k) / L, and the sharpest of hundreds of such tilts
 * reaches three or four of them. */
#define CORNER_SIGMAS 5.0

/* The unit direction, in the order of the points, of the least-squares
 * line through points a..b (b - a + 1 of them, round the end when
 * closed), into d, and the variance of that direction (radians
 * squared) in *var; 0 where they give none. */
static int
direction(const double *p, size_t n, int dim, size_t a, size_t b, double *d,
    double *var)
{
	double ss = 0, lo = HUGE_VAL, hi = -HUGE_VAL;
	size_t k = (b + n - a) % n + 1;
	double c[LOFT_MAXDIM] = { 0 }, m[LOFT_MAXDIM][LOFT_MAXDIM] = { { 0 } };
	double v[LOFT_MAXDIM], chord[LOFT_MAXDIM];

	for (size_t t = 0; t < k; t++)
		vaxpy(c, 1.0 / k, p + ((a + t) % n) * dim, dim);
	for (size_t t = 0; t < k; t++) {
		double r[LOFT_MAXDIM];

		vsub(r, p + ((a + t) % n) * dim, c, dim);
		for (int i = 0; i < dim; i++)
			for (int j = 0; j < dim; j++)
				m[i][j] += r[i] * r[j];
	}
	/* the principal axis by power iteration from the chord */
	vsub(chord, p + b * dim, p + a * dim, dim);
	if (!(vunit(chord, dim) > 0))
		return 0;
	vcopy(d, chord, dim);
	for (int it = 0; it < 32; it++) {
		for (int i = 0; i < dim; i++) {
			v[i] = 0;
			for (int j = 0; j < dim; j++)
				v[i] += m[i][j] * d[j];
		}
		if (!(vunit(v, dim) > 0))
			break;
		vcopy(d, v, dim);
	}
	if (vdot(d, chord, dim) < 0)
		vscale(d, -1, d, dim);
	for (size_t t = 0; t < k; t++) {
		double r[LOFT_MAXDIM], x;

		vsub(r, p + ((a + t) % n) * dim, c, dim);
		x = vdot(r, d, dim);
		lo = fmin(lo, x);
		hi = fmax(hi, x);
		vaxpy(r, -x, d, dim);
		ss += vdot(r, r, dim);
	}
	*var = hi > lo && k > 2 ? ss / (k - 2) * 12 / k / ((hi - lo) * (hi - lo)) : HUGE_VAL;
	return 1;
}

/* The first point at least len from point i (straight, not along the
 * polyline, whose length noise inflates), backward (dir -1) or
 * forward; *ok 0 where an open outline ends first, or none is. */
static size_t
reach(const double *p, size_t n, int dim, int closed, size_t i, int dir,
    double len, int *ok)
{
	size_t j = i;

	for (size_t t = 1; t < n; t++) {
		if (!closed && ((dir < 0 && j == 0) || (dir > 0 && j == n - 1)))
			break;
		j = dir > 0 ? (j + 1) % n : (j + n - 1) % n;
		if (vdist(p + j * dim, p + i * dim, dim) >= len)
			return j;
	}
	*ok = 0;
	return j;
}

/* The turn at point i over the scale len; 0 where none is measured,
 * or (gate) where it is within the noise's reach. */
static double
turn_at(const double *p, size_t n, int dim, int closed,
    size_t i, double len, int gate)
{
	int ok = 1;
	size_t a = reach(p, n, dim, closed, i, -1, len, &ok);
	size_t b = reach(p, n, dim, closed, i, 1, len, &ok);
	double u[LOFT_MAXDIM], v[LOFT_MAXDIM], c, va, vb, t;

	if (!ok || !direction(p, n, dim, a, i, u, &va) ||
	    !direction(p, n, dim, i, b, v, &vb))
		return 0;
	c = vdot(u, v, dim);
	t = acos(c > 1 ? 1 : c < -1 ? -1 : c);
	/* a turn within the noise's reach counts as none */
	return !gate || t >= CORNER_SIGMAS * sqrt(va + vb) ? t : 0;
}

size_t
loft_find_corners(const double *p, size_t n, int dim, int closed, double tol,
    size_t *corner)
{
	double *s = malloc((n + 1) * sizeof *s), *turn = malloc(n * sizeof *turn);
	double len;
	size_t nc = 0;

	if (s == NULL || turn == NULL || n < 5) {
		free(s);
		free(turn);
		return 0;
	}
	s[0] = 0;
	for (size_t i = 1; i <= n; i++)
		s[i] = s[i - 1] + (i < n || closed ?
		    vdist(p + (i % n) * dim, p + (i - 1) * dim, dim) : 0);
	len = fmax(CORNER_TOLS * tol, CORNER_SPACINGS * s[n] / n);
	for (size_t i = 0; i < n; i++)
		if ((turn[i] = turn_at(p, n, dim, closed, i, len, 1)) > 0 &&
		    turn_at(p, n, dim, closed, i, 2 * len, 0) >
		    CORNER_CONCENTRATED * turn[i])
			turn[i] = 0;    /* a bend: twice the length, twice the turn */
	for (size_t i = 0; i < n; i++) {
		int ok = 1, best = turn[i] >= CORNER_TURN;
		size_t a = reach(p, n, dim, closed, i, -1, len / 2, &ok);
		size_t b = reach(p, n, dim, closed, i, 1, len / 2, &ok);

		/* the sharpest within half the scale either side (the first
		 * of equals): the two corners of a stroke's end as thin as
		 * the scale are two */
		for (size_t j = a; best && j != b; j = (j + 1) % n)
			if (j != i && (turn[j] > turn[i] ||
			    (j < i && turn[j] == turn[i])))
				best = 0;
		if (best)
			corner[nc++] = i;
	}
	free(s);
	free(turn);
	return nc;
}
