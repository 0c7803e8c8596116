/*
 * flatten.c: a polyline within a tolerance of a curve of any record
 * type, by halving each piece until the convex hull of each part's
 * Bezier control points lies within the tolerance of the part's chord.
 */
#include <string.h>

#include "internal.h"

/* Halving stops at parts of 2^-FLAT_DEPTH of a piece. */
#define FLAT_DEPTH 30

struct flat {
	int n, dim;
	double tol;
	double *u;
	size_t max, count;
};

/* The distance from p to the segment from a to b. */
static double
segment_distance(const double *p, const double *a, const double *b, int dim)
{
	double ab[LOFT_MAXDIM], ap[LOFT_MAXDIM], l2, t, m;
	int e = 0;

	vsub(ab, b, a, dim);
	vsub(ap, p, a, dim);
	/* by a power of two, exactly, so that no product under- or
	 * overflows for curves of 1e-200 or 1e200 (issue 28) */
	m = fmax(vmaxabs(ab, dim), vmaxabs(ap, dim));
	if (m > 0 && m < INFINITY) {
		e = ilogb(m);
		for (int k = 0; k < dim; k++) {
			ab[k] = ldexp(ab[k], -e);
			ap[k] = ldexp(ap[k], -e);
		}
	}
	l2 = vdot(ab, ab, dim);
	t = l2 > 0 ? vdot(ap, ab, dim) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	vaxpy(ap, -t, ab, dim);
	return ldexp(vnorm(ap, dim), e);
}

/*
 * Split the n + 1 control points q (dim numbers each) at 1/2 into the
 * left half l and the right half r, by de Casteljau's triangle.
 */
static void
halve(const double *q, int n, int dim, double *l, double *r)
{
	memcpy(r, q, (size_t)(n + 1) * dim * sizeof *r);
	vcopy(l, r, dim);
	for (int k = n; k > 0; k--) {
		for (int i = 0; i < k; i++)
			for (int j = 0; j < dim; j++)
				r[i * dim + j] = 0.5 * (r[i * dim + j] +
				    r[(i + 1) * dim + j]);
		vcopy(l + (n - k + 1) * dim, r, dim);
	}
}

/* The part q of a piece over parameters [a, b]: accept it or halve it. */
static void
flatten_part(struct flat *f, const double *q, double a, double b, int depth)
{
	double l[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM],
	    r[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	const double *qa = q, *qb = q + f->n * f->dim;
	double far = 0;

	halve(q, f->n, f->dim, l, r);
	/* the curve lies in the hulls of the halves' control points, and
	 * the distance to a segment is convex: its largest value over the
	 * hulls is at one of those points */
	for (int i = 0; i <= f->n && far <= f->tol; i++) {
		double dl = segment_distance(l + i * f->dim, qa, qb, f->dim),
		    dr = segment_distance(r + i * f->dim, qa, qb, f->dim);

		far = dl > far ? dl : far;
		far = dr > far ? dr : far;
	}
	if (far <= f->tol || depth >= FLAT_DEPTH) {
		if (f->count < f->max)
			f->u[f->count] = b;
		f->count++;
		return;
	}
	flatten_part(f, l, a, 0.5 * (a + b), depth + 1);
	flatten_part(f, r, 0.5 * (a + b), b, depth + 1);
}

size_t
loft_curve_flatten(const struct loft_curve *c, double tol, double *u,
    size_t max)
{
	double ctl[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	struct flat f = { 0, c->dim, tol, u, max, 1 };

	if (max > 0)
		u[0] = 0;
	for (size_t i = 0; i < c->npieces; i++) {
		f.n = loft_curve_bezier(c, i, ctl);
		flatten_part(&f, ctl, (double)i, (double)i + 1, 0);
	}
	return f.count;
}
