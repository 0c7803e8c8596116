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

/* c as cubic pieces into *out, its points in *buf (the caller frees). */
static int
lower_curve(const struct loft_bcurve *c, double tol, struct loft_bcurve *out,
    double **buf)
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

/* s as *count bicubic nets in *nets (the caller frees). */
static int
lower_surface(const struct loft_bsurf *s, double tol, double **nets,
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

int
loft_cad_curve_limited(struct loft_cad_doc *d, const struct loft_bcurve *c,
    double tol, int (*write)(struct loft_cad_doc *, const struct loft_bcurve *))
{
	struct loft_bcurve low;
	double *buf = NULL;
	int rc;

	if (c->deg <= LOFT_CAD_MAXDEG)
		return write(d, c);
	if ((rc = lower_curve(c, tol, &low, &buf)) == 0)
		rc = write(d, &low);
	else if (rc != LOFT_ENOMEM)
		d->out.bad = LOFT_EGEOM, rc = 0;
	free(buf);
	return rc;
}

int
loft_cad_surface_limited(struct loft_cad_doc *d, const struct loft_bsurf *s,
    double tol, int (*write)(struct loft_cad_doc *, const struct loft_bsurf *))
{
	double *nets = NULL;
	size_t n = 0;
	int rc;

	if (s->m <= LOFT_CAD_MAXDEG && s->n <= LOFT_CAD_MAXDEG)
		return write(d, s);
	if ((rc = lower_surface(s, tol, &nets, &n)) == 0)
		for (size_t i = 0; i < n && rc == 0; i++) {
			struct loft_bsurf c = { nets + 48 * i, 3, 3 };

			rc = write(d, &c);
		}
	else if (rc != LOFT_ENOMEM)
		d->out.bad = LOFT_EGEOM, rc = 0;
	free(nets);
	return rc;
}
