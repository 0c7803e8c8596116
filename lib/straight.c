/*
 * straight.c: straight runs in a curve already drawn.  In an outline of
 * cubic segments (a CAD drawing's lines and arcs, a glyph's contour) a
 * straight segment that a curved one meets with the same tangent is a
 * straight run in Spiro's sense: splinefit's straight= keeps it straight
 * and the join smooth, where a corner would kink it.
 */
#include "internal.h"

/* A direction is the chord's, or two end tangents agree, within this
 * angle (radians): far below any drawn kink, far above the rounding of
 * the coordinates a drawing is written with (6 to 10 digits). */
#define STRAIGHT_ANGLE 1e-5

/* Whether the tangent vector d lies along the unit chord u (or is 0:
 * a Bezier line's control point at its end). */
static int
along(const double *d, const double *u, int dim, double tol)
{
	double n = vnorm(d, dim), dot = vdot(d, u, dim);

	if (n == 0)
		return 1;
	return dot > 0 && dot >= n * cos(tol);
}

/* Whether segment s of seg is a straight line; its unit chord into u. */
static int
is_line(const double *seg, size_t s, int dim, double tol, double *u)
{
	const double *q = seg + s * 4 * dim;

	vsub(u, q + dim, q, dim);
	if (!(vunit(u, dim) > 0))
		return 0;
	return along(q + 2 * dim, u, dim, tol) && along(q + 3 * dim, u, dim,
	    tol);
}

/* Whether segment c, curved, has the unit direction u at its start
 * (end 0) or end (end 1). */
static int
meets(const double *seg, size_t c, int dim, int end, const double *u,
    double tol)
{
	const double *d = seg + (c * 4 + 2 + end) * dim;

	return vnorm(d, dim) > 0 && along(d, u, dim, tol);
}

size_t
loft_straight_spans(const double *seg, size_t nseg, int dim, int closed,
    size_t *out)
{
	size_t k = 0;
	double u[LOFT_MAXDIM], w[LOFT_MAXDIM];

	if (dim < 2 || dim > LOFT_MAXDIM)
		return 0;
	for (size_t s = 0; s < nseg; s++) {
		int before = closed || s > 0, after = closed || s + 1 < nseg;
		size_t p = (s + nseg - 1) % nseg, n = (s + 1) % nseg;

		if (!is_line(seg, s, dim, STRAIGHT_ANGLE, u))
			continue;
		if ((before && p != s && !is_line(seg, p, dim, STRAIGHT_ANGLE,
		    w) && meets(seg, p, dim, 1, u, STRAIGHT_ANGLE)) || (after &&
		    n != s && !is_line(seg, n, dim, STRAIGHT_ANGLE, w) &&
		    meets(seg, n, dim, 0, u, STRAIGHT_ANGLE)))
			out[k++] = s;
	}
	return k;
}
