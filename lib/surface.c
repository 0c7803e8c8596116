/*
 * surface.c: surface records of every type behind one interface, so
 * that the programs that evaluate surfaces (sample, loftplot) learn a
 * new type in one place: its operations below, named from its row of
 * types.c's table.
 */
#include <string.h>

#include "internal.h"

/* Widen lo, hi (dim numbers each) to hold p; first: start with p. */
static void
widen(const double *p, int dim, int first, double *lo, double *hi)
{
	for (int c = 0; c < dim; c++) {
		if (first || p[c] < lo[c])
			lo[c] = p[c];
		if (first || p[c] > hi[c])
			hi[c] = p[c];
	}
}

/* patch: the box of its bi-quartic Bezier net, which holds it (the
 * Bernstein polynomials are positive and sum to 1). */
static void
box_patch(const struct loft_surface *s, double *lo, double *hi)
{
	double net[25 * LOFT_MAXDIM];
	int dim = s->dim;

	loft_patch_bezier(s->coef, dim, net);
	for (int i = 0; i < 25; i++)
		widen(net + i * dim, dim, i == 0, lo, hi);
}

/* patch: its net (loft_patch_bezier), in space. */
static void
bezier_patch(const struct loft_surface *s, double *ctl)
{
	double b[25 * LOFT_MAXDIM];

	loft_patch_bezier(s->coef, s->dim, b);
	for (size_t i = 0; i < 25; i++)
		for (int k = 0; k < 3; k++)
			ctl[3 * i + k] = k < s->dim ? b[i * s->dim + k] : 0;
}

/* bezier-surface: its own control points. */
static void
bezier_bezier_surface(const struct loft_surface *s, double *ctl)
{
	memcpy(ctl, s->coef, 3 * (size_t)(s->m + 1) * (s->n + 1) *
	    sizeof *ctl);
}

/* bezier-surface: the box of its control points. */
static void
box_bezier_surface(const struct loft_surface *s, double *lo, double *hi)
{
	size_t n = (size_t)(s->m + 1) * (s->n + 1);

	for (size_t i = 0; i < n; i++)
		widen(s->coef + 3 * i, 3, i == 0, lo, hi);
}

/* patch: five rows of five vectors (MacCallum's B, loft.5). */
static int
check_patch(const struct loft_record *rec, struct loft_surface *s,
    struct loft_error *err)
{
	if (loft__patch_shape(rec, err) != 0)
		return LOFT_EINPUT;
	s->dim = rec->ncols / 5;
	s->m = s->n = 4;
	return 0;
}

static void
eval_patch(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv)
{
	loft_patch_eval(s->coef, s->dim, u, v, p, du, dv);
}

/* A degree attribute of a bezier-surface: 1 to LOFT_BEZIER_MAXPTS - 1. */
static int
degree_attr(const struct loft_record *rec, const char *key, int *deg,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, key);
	long d;

	if (v == NULL)
		return loft_fail(err, LOFT_EINPUT, -1, "bezier-surface record "
		    "without its degree %s=", key);
	if (loft_parse_int(v, 1, LOFT_BEZIER_MAXPTS - 1, &d, err) != 0) {
		char msg[sizeof err->msg];

		memcpy(msg, err->msg, sizeof msg);
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: %s",
		    key, v, msg);
	}
	*deg = (int)d;
	return 0;
}

/* bezier-surface: (m + 1)(n + 1) control points in space, u-major. */
static int
check_bezier_surface(const struct loft_record *rec, struct loft_surface *s,
    struct loft_error *err)
{
	if (degree_attr(rec, "m", &s->m, err) != 0 ||
	    degree_attr(rec, "n", &s->n, err) != 0)
		return LOFT_EINPUT;
	if (rec->nrows != (size_t)(s->m + 1) * (s->n + 1))
		return loft_fail(err, LOFT_EINPUT, -1, "bezier-surface record "
		    "has %zu rows; m=%d n=%d needs %d", rec->nrows, s->m, s->n,
		    (s->m + 1) * (s->n + 1));
	if (rec->ncols != 3)
		return loft_fail(err, LOFT_EINPUT, 0, "bezier-surface rows need "
		    "3 numbers, not %d", rec->ncols);
	s->dim = 3;
	return 0;
}

static void
eval_bezier_surface(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv)
{
	loft_bezier_surface_eval(s->coef, s->m, s->n, u, v, p, du, dv);
}

/*
 * With second derivatives: the rows of the patch as quartics in v give,
 * at v, the coefficients of the quartics in u through the point (and of
 * its v-derivatives); combining those at u gives every derivative.
 */
static void
eval2_patch(const struct loft_surface *s, double u, double v, double *p,
    double *du, double *dv, double *duu, double *dvv)
{
	double g[3][5][LOFT_MAXDIM];
	const double *k[5];
	int dim = s->dim;

	for (int i = 0; i < 5; i++) {
		for (int j = 0; j < 5; j++)
			k[j] = s->coef + (5 * i + j) * dim;
		loft__quartic_combine(k, dim, v, g[0][i], g[1][i], g[2][i]);
	}
	for (int d = 0; d < 3; d++) {
		for (int i = 0; i < 5; i++)
			k[i] = g[d][i];
		loft__quartic_combine(k, dim, u, d == 0 ? p : d == 1 ? dv : dvv,
		    d == 0 ? du : NULL, d == 0 ? duu : NULL);
	}
}

/* The same for a Bezier net. */
static void
eval2_bezier_surface(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv, double *duu, double *dvv)
{
	loft__bezier_surface_eval2(s->coef, s->m, s->n, u, v, p, du, dv, duu,
	    dvv);
}

const struct loft__surface_type loft__patch_type =
	{ "patch", check_patch, eval_patch, eval2_patch, box_patch,
	    bezier_patch };
const struct loft__surface_type loft__bezier_surface_type =
	{ "bezier-surface", check_bezier_surface, eval_bezier_surface,
	    eval2_bezier_surface, box_bezier_surface, bezier_bezier_surface };

/* The surface operations of rec's type, or NULL: it is no surface. */
static const struct loft__surface_type *
find_type(const struct loft_record *rec)
{
	const struct loft_type *t = loft_record_type(rec);

	return t != NULL ? t->surface : NULL;
}

int
loft_is_surface(const struct loft_record *rec)
{
	return find_type(rec) != NULL;
}

int
loft_surface_from_record(const struct loft_record *rec,
    struct loft_surface *s, struct loft_error *err)
{
	const struct loft__surface_type *t = find_type(rec);

	if (t == NULL)
		return loft_fail(err, LOFT_EINPUT, -1, "%s record is no "
		    "surface", rec->type ? rec->type : "a point");
	memset(s, 0, sizeof *s);
	if (t->check(rec, s, err) != 0)
		return LOFT_EINPUT;
	s->type = t->name;
	s->coef = rec->num;
	s->eval = t->eval;
	s->eval2 = t->eval2;
	s->box = t->box;
	s->bezier = t->bezier;
	return 0;
}

void
loft_surface_from_patch(const double *b, int dim, struct loft_surface *s)
{
	const struct loft__surface_type *t = &loft__patch_type;

	memset(s, 0, sizeof *s);
	s->type = t->name;
	s->coef = b;
	s->dim = dim;
	s->m = s->n = 4;
	s->eval = t->eval;
	s->eval2 = t->eval2;
	s->box = t->box;
	s->bezier = t->bezier;
}

void
loft_surface_box(const struct loft_surface *s, double *lo, double *hi)
{
	s->box(s, lo, hi);
}

void
loft_surface_eval(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv)
{
	s->eval(s, u, v, p, du, dv);
}

void
loft_surface_eval2(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv, double *duu, double *dvv)
{
	s->eval2(s, u, v, p, du, dv, duu, dvv);
}

void
loft_surface_bezier(const struct loft_surface *s, double *ctl)
{
	s->bezier(s, ctl);
}

void
loft_surface_from_bezier(const double *ctl, int m, int n,
    struct loft_surface *s)
{
	const struct loft__surface_type *t = &loft__bezier_surface_type;

	memset(s, 0, sizeof *s);
	s->type = t->name;
	s->coef = ctl;
	s->dim = 3;
	s->m = m;
	s->n = n;
	s->eval = t->eval;
	s->eval2 = t->eval2;
	s->box = t->box;
	s->bezier = t->bezier;
}

static void
eval_scaled(const struct loft_surface *s, double u, double v, double *p,
    double *du, double *dv)
{
	loft_surface_eval(s->of, u, v, p, du, dv);
	vpow2(p, s->dim, s->scale);
	vpow2(du, s->dim, s->scale);
	vpow2(dv, s->dim, s->scale);
}

static void
eval2_scaled(const struct loft_surface *s, double u, double v, double *p,
    double *du, double *dv, double *duu, double *dvv)
{
	loft_surface_eval2(s->of, u, v, p, du, dv, duu, dvv);
	vpow2(p, s->dim, s->scale);
	vpow2(du, s->dim, s->scale);
	vpow2(dv, s->dim, s->scale);
	vpow2(duu, s->dim, s->scale);
	vpow2(dvv, s->dim, s->scale);
}

static void
box_scaled(const struct loft_surface *s, double *lo, double *hi)
{
	loft_surface_box(s->of, lo, hi);
	vpow2(lo, s->dim, s->scale);
	vpow2(hi, s->dim, s->scale);
}

static void
bezier_scaled(const struct loft_surface *s, double *ctl)
{
	loft_surface_bezier(s->of, ctl);
	vpow2(ctl, 3 * (size_t)(s->m + 1) * (s->n + 1), s->scale);
}

void
loft_surface_scaled(const struct loft_surface *s, int e,
    struct loft_surface *out)
{
	*out = *s;
	out->of = s;
	out->scale = e;
	out->eval = eval_scaled;
	out->eval2 = eval2_scaled;
	out->box = box_scaled;
	out->bezier = bezier_scaled;
}
