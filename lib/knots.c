/*
 * knots.c: what every fitting method (fit.c, cspline.c, fair.c) shares
 * about the knots: the checks no method can fit past, and the unit end
 * tangents of an open curve, given or estimated.  Core.  In its own
 * module so that the methods depend on it and not on each other.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/*
 * Knots closer than COINCIDENT_REL times the size of the knot set are one
 * point: a segment between them has no direction to speak of.  Near the
 * rounding error of coordinates of that size, and far below any spacing a
 * designer means.
 */
#define COINCIDENT_REL 1e-12

/* Knots that stray less than this, relative to the set's size, from a
 * line lie on it. */
#define COLLINEAR_REL 1e-12

/* The largest distance of a knot from p[0]: the size of the set. */
static double
knot_extent(const double *p, size_t n, int dim, size_t *far)
{
	double big = 0;

	*far = 0;
	for (size_t i = 1; i < n; i++) {
		double d = vdist(p + i * dim, p, dim);
		if (d > big) {
			big = d;
			*far = i;
		}
	}
	return big;
}

static int
collinear(const double *p, size_t n, int dim, double size, size_t far)
{
	double e[LOFT_MAXDIM], v[LOFT_MAXDIM];

	vsub(e, p + far * dim, p, dim);
	vunit(e, dim);
	for (size_t i = 1; i < n; i++) {
		vsub(v, p + i * dim, p, dim);
		vaxpy(v, -vdot(v, e, dim), e, dim);
		if (vnorm(v, dim) > COLLINEAR_REL * size)
			return 0;
	}
	return 1;
}

int
loft__check_knots(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, struct loft_error *err)
{
	size_t need = o->closed ? LOFT_MIN_CLOSED : LOFT_MIN_OPEN, far;
	size_t nseg = o->closed ? n : n - 1;
	double size;

	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1,
		    "knots have %d coordinates; 2 or 3 are needed", dim);
	if (n < need)
		return loft_fail(err, LOFT_EGEOM, -1,
		    "%zu knot%s: a%s curve needs at least %zu", n,
		    n == 1 ? "" : "s", o->closed ? " closed" : "n open", need);
	size = knot_extent(p, n, dim, &far);
	for (size_t i = 0; i < nseg; i++) {
		size_t j = (i + 1) % n;

		if (!(vdist(p + j * dim, p + i * dim, dim) > COINCIDENT_REL *
		    size))
			return loft_fail(err, LOFT_EGEOM, (long)j,
			    "knot %zu coincides with knot %zu%s", j + 1, i + 1,
			    j == 0 ? " (closing the curve: drop the repeated "
			    "first knot)" : "");
	}
	if (o->closed && collinear(p, n, dim, size, far))
		return loft_fail(err, LOFT_EGEOM, -1,
		    "all knots lie on one line: no closed curve goes through "
		    "them");
	return 0;
}

int
loft_end_tangent(const double *a, const double *b, const double *c, int dim,
    double *t, struct loft_error *err)
{
	double ab[LOFT_MAXDIM], ac[LOFT_MAXDIM], perp[LOFT_MAXDIM];

	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "a tangent in %d "
		    "dimensions: want 2 or 3", dim);
	vsub(ab, b, a, dim);
	vcopy(t, ab, dim);
	if (c != NULL) {
		vsub(ac, c, a, dim);
		vcopy(perp, ac, dim);
		vaxpy(perp, -vdot(ac, ab, dim) / vdot(ab, ab, dim), ab, dim);
		if (vnorm(perp, dim) > COLLINEAR_REL * vnorm(ac, dim)) {
			/* The tangent at a of the circle through a, b, c:
			 * inversion about a maps the circle to the line
			 * through the images of b and c, whose direction
			 * (b-a)/|b-a|^2 - (c-a)/|c-a|^2 the tangent takes. */
			vscale(t, vdot(ac, ac, dim), ab, dim);
			vaxpy(t, -vdot(ab, ab, dim), ac, dim);
		}
	}
	if (!(vunit(t, dim) > 0) || !isfinite(t[0]))
		return loft_fail(err, LOFT_EGEOM, -1,
		    "cannot estimate an end tangent: knots coincide");
	return 0;
}

/* The unit end tangents of an open curve: given, or estimated. */
int
loft__open_ends(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *t0, double *tn, struct loft_error *err)
{
	const double *last = p + (n - 1) * dim;

	if (o->have_start) {
		vcopy(t0, o->start, dim);
		if (!(vunit(t0, dim) > 0))
			return loft_fail(err, LOFT_EGEOM, -1,
			    "start tangent is zero");
	} else if (loft_end_tangent(p, p + dim, n > 2 ? p + 2 * dim : NULL,
	    dim, t0, err) != 0) {
		return LOFT_EGEOM;
	}
	if (o->have_end) {
		vcopy(tn, o->end, dim);
		if (!(vunit(tn, dim) > 0))
			return loft_fail(err, LOFT_EGEOM, -1,
			    "end tangent is zero");
	} else {
		if (loft_end_tangent(last, last - dim, n > 2 ? last - 2 * dim :
		    NULL, dim, tn, err) != 0)
			return LOFT_EGEOM;
		vscale(tn, -1, tn, dim);
	}
	/* two knots and one tangent given: the free end's is the circular
	 * arc's, the given one mirrored in the chord (as three knots give
	 * the circle's through them) */
	if (n == 2 && o->have_start != o->have_end) {
		double u[LOFT_MAXDIM];
		const double *g = o->have_start ? t0 : tn;
		double *t = o->have_start ? tn : t0;

		vsub(u, last, p, dim);
		if (vunit(u, dim) > 0) {
			vscale(t, -1, g, dim);
			vaxpy(t, 2 * vdot(g, u, dim), u, dim);
			if (!(vunit(t, dim) > 0))
				vcopy(t, u, dim);
		}
	}
	return 0;
}

/* ------------------------------------------------------------------ */
/* Manning's method */
