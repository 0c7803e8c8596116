/*
 * measure: for each curve record one row of numbers: its length, area,
 * centroid, bounding box, smallest radius of curvature and where it is,
 * inflexions, curvature extrema, bending energy and largest curvature
 * jump at a knot, or the fields -f names, in its order; for each surface
 * record its area, curvature extremes and distance from developable.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

enum field {
	F_LENGTH, F_AREA, F_CX, F_CY, F_CZ, F_XMIN, F_YMIN, F_ZMIN, F_XMAX,
	F_YMAX, F_ZMAX, F_MINRADIUS, F_MINRADIUS_U, F_INFLEXIONS, F_EXTREMA,
	F_ENERGY, F_JUMP
};

static const char *const field_names[] = {
	"length", "area", "cx", "cy", "cz", "xmin", "ymin", "zmin", "xmax",
	"ymax", "zmax", "minradius", "minradius_u", "inflexions", "extrema",
	"energy", "jump", NULL
};

#define MAXFIELDS 64

struct opts {
	int field[MAXFIELDS];
	int nfield;             /* 0: the default fields for the dimension */
};

/* The default rows of plane and space curves. */
static const int plane_fields[] = {
	F_LENGTH, F_AREA, F_CX, F_CY, F_XMIN, F_YMIN, F_XMAX, F_YMAX,
	F_MINRADIUS, F_MINRADIUS_U, F_INFLEXIONS, F_EXTREMA, F_ENERGY, F_JUMP
};
static const int space_fields[] = {
	F_LENGTH, F_CX, F_CY, F_CZ, F_XMIN, F_YMIN, F_ZMIN, F_XMAX, F_YMAX,
	F_ZMAX, F_MINRADIUS, F_MINRADIUS_U, F_EXTREMA, F_ENERGY, F_JUMP
};

static const char usage_text[] =
    "usage: measure [-f field,...] [-p digits] [file ...]\n";

/* What one record's row needs, computed once when first asked. */
struct sums {
	const struct loft_curve *c;
	int have_box, have_cen, have_radius, have_jump;
	double lo[LOFT_MAXDIM], hi[LOFT_MAXDIM], cen[LOFT_MAXDIM];
	double radius, radius_u, jump, jump_u;
};

/* The value of field f of the record, or a failure naming why not. */
static int
field_value(struct sums *s, int f, double *v, struct loft_error *err)
{
	const struct loft_curve *c = s->c;
	long count;
	int axis = -1;

	switch (f) {
	case F_CZ: case F_ZMIN: case F_ZMAX:
		axis = 2;
		break;
	case F_CY: case F_YMIN: case F_YMAX:
		axis = 1;
		break;
	case F_CX: case F_XMIN: case F_XMAX:
		axis = 0;
		break;
	}
	if (axis >= c->dim)
		return loft_fail(err, LOFT_EINPUT, -1, "field %s: a plane "
		    "curve has no z", field_names[f]);
	switch (f) {
	case F_LENGTH:
		*v = loft_curve_length(c);
		return 0;
	case F_AREA:
		return loft_curve_area(c, v, err);
	case F_CX: case F_CY: case F_CZ:
		if (!s->have_cen && loft_curve_centroid(c, s->cen, err) != 0)
			return LOFT_EGEOM;
		s->have_cen = 1;
		*v = s->cen[axis];
		return 0;
	case F_XMIN: case F_YMIN: case F_ZMIN:
	case F_XMAX: case F_YMAX: case F_ZMAX:
		if (!s->have_box)
			loft_curve_bbox(c, s->lo, s->hi);
		s->have_box = 1;
		*v = f == F_XMIN || f == F_YMIN || f == F_ZMIN ?
		    s->lo[axis] : s->hi[axis];
		return 0;
	case F_MINRADIUS: case F_MINRADIUS_U:
		if (!s->have_radius && loft_curve_min_radius(c, &s->radius,
		    &s->radius_u, err) != 0)
			return LOFT_EGEOM;
		s->have_radius = 1;
		*v = f == F_MINRADIUS ? s->radius : s->radius_u;
		return 0;
	case F_INFLEXIONS:
		if (loft_curve_inflexions(c, &count, err) != 0)
			return LOFT_EINPUT;
		*v = (double)count;
		return 0;
	case F_EXTREMA:
		if (loft_curve_extrema(c, &count, err) != 0)
			return LOFT_EINPUT;
		*v = (double)count;
		return 0;
	case F_ENERGY:
		return loft_curve_energy(c, v, err);
	default:
		if (!s->have_jump)
			loft_curve_jump(c, &s->jump, &s->jump_u);
		s->have_jump = 1;
		*v = s->jump;
		return 0;
	}
}

/*
 * Quadrature cells a side of a surface for its numbers: Gauss-Legendre
 * of order 5 on 8 x 8 cells holds a bi-quartic patch's area to 1e-12.
 */
#define SURFACE_CELLS 8

/*
 * A surface record's row: area; least and greatest Gaussian curvature
 * and mean curvature, each with the u and v where it falls; the
 * integrals of K dA and |K| dA; 1 when developable (surfmeasure.c).
 */
static int
measure_surface(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_surface s;
	struct loft_surface_numbers m;
	const struct loft_surface_where *w[4] = { &m.kmin, &m.kmax, &m.hmin,
	    &m.hmax };
	double v[16];
	int n = 0;

	if (o->nfield > 0)
		return loft_fail(err, LOFT_EINPUT, -1, "-f names curve fields; "
		    "a %s record is a surface, whose row is fixed", rec->type);
	if (loft_surface_from_record(rec, &s, err) != 0)
		return LOFT_EINPUT;
	loft_surface_numbers(&s, 1, SURFACE_CELLS, &m);
	v[n++] = m.area;
	for (int i = 0; i < 4; i++) {
		v[n++] = w[i]->value;
		v[n++] = w[i]->u;
		v[n++] = w[i]->v;
	}
	v[n++] = m.kint;
	v[n++] = m.kabs;
	v[n++] = m.developable;
	for (int i = 0; i < n; i++)
		if (!isfinite(v[i]))
			return loft_fail(err, LOFT_EGEOM, -1, isinf(m.area) ?
			    "the surface's numbers overflow: coefficients too "
			    "large" : "the surface's curvature overflows: "
			    "coefficients too small");
	if (fpclassify(m.area) == FP_SUBNORMAL)
		return loft_fail(err, LOFT_EGEOM, -1, "the surface's area "
		    "underflows: coefficients too small");
	loft_put_row(&run->w, v, n);
	loft_end_record(&run->w);
	return 0;
}

static int
measure_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	const struct opts *o = run->ctx;
	struct loft_curve c;
	struct sums s;
	const int *fields = o->field;
	int n = o->nfield;

	if (loft_is_surface(rec))
		return measure_surface(run, rec, err);
	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	if (n == 0) {
		fields = c.dim == 2 ? plane_fields : space_fields;
		n = c.dim == 2 ? (int)(sizeof plane_fields / sizeof *fields) :
		    (int)(sizeof space_fields / sizeof *fields);
	}
	memset(&s, 0, sizeof s);
	s.c = &c;
	for (int i = 0; i < n; i++) {
		double v;
		int rc = field_value(&s, fields[i], &v, err);

		if (rc != 0)
			return rc;
		if (!isfinite(v))
			return loft_fail(err, LOFT_EGEOM, -1, "%s overflows: "
			    "coefficients too large", field_names[fields[i]]);
		loft_put_num(&run->w, v);
	}
	loft_end_line(&run->w);
	loft_end_record(&run->w);
	return 0;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { { 0 }, 0 };
	struct loft_run run = { .prog = "measure", .out = stdout,
	    .msg = stderr, .handle = measure_record, .ctx = &o };
	struct loft_error err;
	int c;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "f:p:h")) != -1) {
		switch (c) {
		case 'f':
			if (loft_opt_fields(optarg, field_names, o.field,
			    MAXFIELDS, &o.nfield, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	return loft_run_files(&run, argc - optind, argv + optind);
}
#endif
