/*
 * curve.c: curve records of every type behind one interface, so that the
 * programs that evaluate curves (sample, loftplot) learn a new type in
 * one place: its operations below, named from its row of types.c's
 * table.
 */
#include <string.h>

#include "internal.h"

/*
 * Manning's eq. 7 in the Bernstein basis: the inner control points are
 * one third of the end tangents in from the ends, as P'(0) = 3 (b1 - b0).
 */
static int
cubic_bezier(const double *seg, int dim, double *ctl)
{
	for (int k = 0; k < dim; k++) {
		ctl[k] = seg[k];
		ctl[dim + k] = seg[k] + seg[2 * dim + k] / 3;
		ctl[2 * dim + k] = seg[dim + k] - seg[3 * dim + k] / 3;
		ctl[3 * dim + k] = seg[dim + k];
	}
	return 3;
}

/* MacCallum's quartic in the Bernstein basis of degree 4
 * (loft_quartic_bezier). */
static int
quartic_bezier(const double *q, int dim, double *ctl)
{
	loft_quartic_bezier(q, (size_t)dim, ctl, (size_t)dim, dim);
	return 4;
}

/* A quartic segment is its own quartic form. */
static void
quartic_copy(const double *q, int dim, double *out)
{
	memcpy(out, q, 5 * (size_t)dim * sizeof *out);
}

const struct loft__curve_type loft__cubic_type =
	{ "cubic", 4, loft_cubic_eval, NULL, cubic_bezier,
	    loft_cubic_to_quartic };
const struct loft__curve_type loft__quartic_type =
	{ "quartic", 5, loft_quartic_eval, NULL, quartic_bezier,
	    quartic_copy };
const struct loft__curve_type loft__bezier_type =
	{ "bezier", 1, NULL, loft_bezier_eval, NULL, NULL };

/* Parse an optional 0/1 attribute; -1 when it is something else. */
static int
flag_attr(const struct loft_record *rec, const char *key)
{
	const char *v = loft_attr(rec, key);

	if (v == NULL || strcmp(v, "0") == 0)
		return 0;
	return strcmp(v, "1") == 0 ? 1 : -1;
}

int
loft_curve_from_record(const struct loft_record *rec, struct loft_curve *c,
    struct loft_error *err)
{
	const struct loft_type *rt = loft_record_type(rec);
	const struct loft__curve_type *t = rt != NULL ? rt->curve : NULL;

	if (loft_record_is(rec, LOFT_KIND_KNOTS))
		return loft_fail(err, LOFT_EINPUT, -1, "a point record is no "
		    "curve to evaluate (fit one with splinefit first)");
	if (t == NULL)
		return loft_fail(err, LOFT_EINPUT, -1,
		    "unknown record type '%s'", rec->type);
	if (rec->nrows == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "%s record has no rows",
		    t->name);
	if (rec->ncols % t->rows_per_point != 0 ||
	    rec->ncols / t->rows_per_point < 2 ||
	    rec->ncols / t->rows_per_point > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, 0, "%s rows need %d or %d "
		    "numbers, not %d", t->name, 2 * t->rows_per_point,
		    3 * t->rows_per_point, rec->ncols);
	if (t->eval == NULL && (rec->nrows < 2 ||
	    rec->nrows > LOFT_BEZIER_MAXPTS))
		return loft_fail(err, LOFT_EINPUT, -1, "%s record of %zu "
		    "control points: want 2 to %d", t->name, rec->nrows,
		    LOFT_BEZIER_MAXPTS);
	c->type = t->name;
	c->coef = rec->num;
	c->npieces = t->eval != NULL ? rec->nrows : 1;
	c->npts = t->eval != NULL ? 0 : rec->nrows;
	c->dim = rec->ncols / t->rows_per_point;
	c->rowlen = rec->ncols;
	c->eval = t->eval;
	c->eval_ctl = t->eval_ctl;
	c->bezier = t->bezier;
	c->quartic = t->quartic;
	c->degree = t->eval != NULL ? rt->degree : (int)rec->nrows - 1;
	c->closed = flag_attr(rec, "closed");
	if (c->closed < 0)
		return loft_fail(err, LOFT_EINPUT, -1,
		    "attribute closed=%s: want 0 or 1", loft_attr(rec, "closed"));
	return 0;
}

void
loft_curve_eval(const struct loft_curve *c, size_t i, double u,
    double *p, double *d1, double *d2)
{
	if (c->eval_ctl != NULL)
		c->eval_ctl(c->coef, c->npts, c->dim, u, p, d1, d2);
	else
		c->eval(c->coef + i * c->rowlen, c->dim, u, p, d1, d2);
}

void
loft_curve_cubic(struct loft_curve *c, const double *seg, size_t nseg, int dim,
    int closed)
{
	const struct loft__curve_type *t = &loft__cubic_type;

	c->type = t->name;
	c->coef = seg;
	c->npieces = nseg;
	c->npts = 0;
	c->dim = dim;
	c->rowlen = t->rows_per_point * dim;
	c->eval = t->eval;
	c->eval_ctl = NULL;
	c->bezier = t->bezier;
	c->quartic = t->quartic;
	c->degree = loft_type_named(t->name)->degree;
	c->closed = closed != 0;
}

int
loft_curve_bezier(const struct loft_curve *c, size_t i, double *ctl)
{
	if (c->bezier == NULL) {
		memcpy(ctl, c->coef, c->npts * c->dim * sizeof *ctl);
		return (int)c->npts - 1;
	}
	return c->bezier(c->coef + i * c->rowlen, c->dim, ctl);
}

void
loft_curve_quartic(const struct loft_curve *c, size_t i, double *q)
{
	c->quartic(c->coef + i * (size_t)c->rowlen, c->dim, q);
}

int
loft_curvature(const double *d1, const double *d2, int dim, double *k)
{
	double kn[LOFT_MAXDIM];

	if (loft_curvature_vector(d1, d2, dim, kn) != 0)
		return LOFT_EGEOM;
	*k = vnorm(kn, dim);
	/* the sign of d1 x kn is that of d1 x d2, which may underflow */
	if (dim == 2 && d1[0] * kn[1] - d1[1] * kn[0] < 0)
		*k = -*k;
	return 0;
}

int
loft_unit_tangent(const double *d1, int dim, double *t)
{
	double a[LOFT_MAXDIM];

	for (int q = 0; q < dim; q++)
		a[q] = d1[q];
	if (vunit(a, dim) == 0)
		return LOFT_EGEOM;
	for (int q = 0; q < dim; q++)
		t[q] = a[q];
	return 0;
}

double
loft_joint_turn(const double *seg, size_t nseg, int dim, int closed, size_t j)
{
	double u[LOFT_MAXDIM], v[LOFT_MAXDIM], s[LOFT_MAXDIM];
	size_t i = j > 0 ? j - 1 : nseg - 1;

	if (j >= nseg || (j == 0 && !closed) ||
	    loft_unit_tangent(seg + i * 4 * dim + 3 * dim, dim, u) != 0 ||
	    loft_unit_tangent(seg + j * 4 * dim + 2 * dim, dim, v) != 0)
		return 0;
	/* half the angle from the chord and the sum of the unit vectors:
	 * accurate at every angle, where acos of the dot is not near 0 */
	for (int q = 0; q < dim; q++)
		s[q] = u[q] + v[q];
	return 2 * atan2(vdist(u, v, dim), vnorm(s, dim));
}
