/*
 * cadlimit.c: curves and surfaces of a degree a format cannot take, as
 * cubic pieces and bicubic patches within the record's tolerance
 * (bspline.c's Hermite pieces).  STEP and IGES readers take B-splines
 * of degree 25 at most (OpenCASCADE's Geom_BSplineCurve::MaxDegree):
 * one of degree 26 to 63 is read as nothing at all.
 * Program layer (loftcad.h, on loftprog.h): for the CAD formats.
 */
#include <stdlib.h>

#include "loftcad.h"

/* The most pieces a Bezier piece, patches a side, it is cut into. */
#define LOWER_PIECES 4096
#define LOWER_SIDE 64

int
loft_cad_lower_curve(const struct loft_bcurve *c, double tol,
    struct loft_bcurve *out, double **buf)
{
	size_t per = 4 * (size_t)c->dim, n = 0, k;
	double *b = malloc(c->npieces * LOWER_PIECES * per * sizeof *b);
	struct loft_error err;
	int rc = 0;

	*buf = b;
	if (b == NULL)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < c->npieces && rc == 0; i++) {
		rc = loft_bezier_cubics(c->ctl + i * (size_t)(c->deg + 1) *
		    (size_t)c->dim, c->deg, c->dim, tol, LOWER_PIECES,
		    b + n * per, &k, &err);
		n += k;
	}
	*out = *c;
	out->ctl = b;
	out->deg = 3;
	out->npieces = n;
	return rc;
}

int
loft_cad_lower_surface(const struct loft_bsurf *s, double tol, double **nets,
    size_t *count)
{
	double *b = malloc(48 * LOWER_SIDE * LOWER_SIDE * sizeof *b);
	struct loft_error err;
	size_t ku = 0, kv = 0;
	int rc;

	*nets = b;
	*count = 0;
	if (b == NULL)
		return LOFT_ENOMEM;
	rc = loft_bezier_bicubics(s->ctl, s->m, s->n, tol, LOWER_SIDE, b, &ku,
	    &kv, &err);
	*count = ku * kv;
	return rc;
}
