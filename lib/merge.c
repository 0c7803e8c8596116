/*
 * merge.c: knots that are one knot.  A digitiser's double click, a CAD
 * system's repeated closing point or its rounding leave knots a few
 * micrometres apart that no designer meant; a spline through them must
 * turn in that space, and dents or hooks the curve.
 */
#include "internal.h"

/*
 * The default merge distance, relative to the size of the knot set (the
 * largest distance of a knot from the first).  On a 265 mm outline it is
 * 26.5 micrometres: above a CAD export's rounding (0.5 micrometre) and a
 * digitiser's double click (11 micrometres), and ten times below the
 * closest spacing a designer means (a few tenths of a millimetre at a
 * toe or a heel).
 */
#define MERGE_REL 1e-4

double
loft_merge_distance(const double *p, size_t n, int dim)
{
	double big = 0;

	for (size_t i = 1; i < n; i++)
		big = fmax(big, vdist(p + i * dim, p, dim));
	return MERGE_REL * big;
}

/*
 * With the default distance, a knot is merged only where the chord to it
 * is also shorter than this fraction of a chord beside it: a double
 * click is a thousandth of its neighbours, while a dense even spacing
 * (10^6 knots on a circle) is the spacing meant.
 */
#define MERGE_LOCAL 0.1

/* The chord from knot i to knot j (i + 1 or i - 1 mod n), or infinity
 * past the ends of an open curve. */
static double
chord(const double *p, size_t n, int dim, int closed, size_t i, long step)
{
	size_t j = (i + n + step) % n;

	if (!closed && ((step < 0 && i == 0) || (step > 0 && i + 1 == n)))
		return HUGE_VAL;
	return vdist(p + i * dim, p + j * dim, dim);
}

/* Whether knots a (before) and b are one: nearer than dist and, with
 * local, short beside the longer chord around them. */
static int
one_knot(const double *p, size_t n, int dim, int closed, double dist,
    int local, size_t a, size_t b)
{
	double d = vdist(p + a * dim, p + b * dim, dim);

	if (!(d < dist))
		return 0;
	return !local || d < MERGE_LOCAL * fmax(chord(p, n, dim, closed, a, -1),
	    chord(p, n, dim, closed, b, 1));
}

size_t
loft_merge_knots(const double *p, size_t n, int dim, int closed, double dist,
    int local, size_t *keep, size_t *into)
{
	size_t m = 0;

	for (size_t i = 0; i < n; i++) {
		if (m == 0 || !one_knot(p, n, dim, closed, dist, local,
		    keep[m - 1], i))
			keep[m++] = i;
		if (into != NULL)
			into[i] = m - 1;
	}
	/* the last kept knot of a closed curve against the first: drop
	 * the last (the repeated first knot), and what merged into it */
	while (closed && m > 1 && one_knot(p, n, dim, closed, dist, local,
	    keep[m - 1], 0)) {
		for (size_t i = keep[--m]; into != NULL && i < n; i++)
			into[i] = 0;
	}
	return m;
}
