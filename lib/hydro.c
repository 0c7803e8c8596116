/*
 * hydro.c: the hydrostatics of a hull given as surfaces, exact to
 * rounding on polynomial ones.
 *
 * The divergence theorem over the solid below the waterline z = Z turns
 * each volume integral into one over its boundary: the hull below Z,
 * the waterplane, and (for a half) the centreplane y = 0.  With N the
 * unnormalised outer normal x_u x x_v of the hull:
 *
 *   V            = int (z - Z) N_z  = int x N_x = int y N_y
 *   int x dV     = int x (z - Z) N_z,   int y dV likewise,
 *   int (z-Z) dV = int (z - Z)^2 / 2 N_z,
 *   int_wp g dA  = -int g(x, y) N_z     (any g, as div (0, 0, g) = 0),
 *   0            = int N_x              (and int N_y for a whole hull),
 *
 * each over the parameters of the hull where z <= Z.  The fields chosen
 * vanish on the waterplane (z = Z) and the centreplane (y = 0, N_x = N_z
 * = 0 there), so those faces need no surface of their own; the three
 * volumes and int N_x agree only when the hull is closed below Z, which
 * is the check that it is.  On polynomial surfaces every integrand is a
 * polynomial in (u, v), integrated by loft_clip_integrate exactly.
 *
 * Every integrand is a linear combination, with powers of Z, of moments
 * that do not depend on Z, so a surface wholly below a waterline adds
 * moments computed once; only the surfaces the waterline crosses are
 * clipped.  Inside, coordinates are (p - o) / scale, o the middle of the
 * hull's box (y not moved: the centreplane stays y = 0) and scale a
 * power of 2, so the results do not depend on the units and a fourth
 * power of a length cannot overflow.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

enum {
	M_NZ, M_ZNZ, M_XNZ, M_XZNZ, M_YNZ, M_YZNZ, M_ZZNZ, M_XXNZ, M_YYNZ,
	M_NX, M_XNX, M_NY, M_YNY, M_AREA, NM
};

/* The error allowed in each integral over a surface, relative to the
 * square of its size (inside, where the hull is about 1): the adaptive
 * quadrature meets it where the integrand is not a polynomial (the
 * wetted area, a curved waterline edge), far below the 1e-9 the
 * hydrostatics are checked to. */
#define HYDRO_TOL 1e-15

/* The hull is closed below the waterline when its three volumes and
 * int N_x agree within this part of its wetted area (inside, lengths
 * are at most 1): exact quadrature leaves rounding, and edges shared by
 * neighbouring patches agree to rounding. */
#define CLOSE_TOL 1e-8

/* A half reaches y < 0 when a point of it lies below this part of the
 * hull's size. */
#define HALF_TOL 1e-9

/* Grid and golden-section steps of a surface's extreme point: the grid
 * finds the basin, and 0.618^60 of its step is below rounding. */
#define EXT_GRID 8

/* The waterline's samples on a surface that come within this part of
 * the surface's size of the sampled extremes make it worth refining:
 * samples 1/16 apart (waterline.c's) miss an extreme by at most 1/8 of
 * their step squared, 1/2048, times the second derivative, about the
 * size. */
#define EXT_MARGIN 1e-3
#define EXT_STEPS 60

struct frame {
	const double *o;
	double scale;
};

/* The moments at a point (loft_clip_fn). */
static void
moments_at(void *ctx, const double *p, const double *pu, const double *pv,
    double w, double *acc)
{
	const struct frame *f = ctx;
	double q[3], a[3], b[3], n[3];

	for (int k = 0; k < 3; k++) {
		q[k] = (p[k] - f->o[k]) / f->scale;
		a[k] = pu[k] / f->scale;
		b[k] = pv[k] / f->scale;
	}
	n[0] = a[1] * b[2] - a[2] * b[1];
	n[1] = a[2] * b[0] - a[0] * b[2];
	n[2] = a[0] * b[1] - a[1] * b[0];
	acc[M_NZ] += w * n[2];
	acc[M_ZNZ] += w * q[2] * n[2];
	acc[M_XNZ] += w * q[0] * n[2];
	acc[M_XZNZ] += w * q[0] * q[2] * n[2];
	acc[M_YNZ] += w * q[1] * n[2];
	acc[M_YZNZ] += w * q[1] * q[2] * n[2];
	acc[M_ZZNZ] += w * q[2] * q[2] * n[2];
	acc[M_XXNZ] += w * q[0] * q[0] * n[2];
	acc[M_YYNZ] += w * q[1] * q[1] * n[2];
	acc[M_NX] += w * n[0];
	acc[M_XNX] += w * q[0] * n[0];
	acc[M_NY] += w * n[1];
	acc[M_YNY] += w * q[1] * n[1];
	acc[M_AREA] += w * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* The moments of surface i where p[axis[k]] <= level[k], k < nc, into
 * acc (added). */
static void
clip_moments(const struct loft_hydro *h, size_t i, int nc, const int *axis,
    const double *level, double *acc)
{
	struct frame f = { h->o, h->scale };
	struct loft_clip c;
	struct loft_error err;
	const double *lo = h->box + 6 * i, *hi = lo + 3;
	double d2 = 0;

	for (int k = 0; k < 3; k++)
		d2 += (hi[k] - lo[k]) / h->scale * ((hi[k] - lo[k]) / h->scale);
	memset(&c, 0, sizeof c);
	c.n = nc;
	for (int k = 0; k < nc; k++) {
		c.axis[k] = axis[k];
		c.level[k] = level[k];
	}
	if (nc == 0) {          /* the whole surface: a plane above it */
		c.n = 1;
		c.axis[0] = 2;
		c.level[0] = HUGE_VAL;
	}
	for (int k = 0; k < NM; k++)
		c.tol[k] = HYDRO_TOL * (d2 > DBL_MIN ? d2 : DBL_MIN);
	loft_clip_integrate(&h->s[i], &c, moments_at, &f, NM, acc, &err);
}

/* The largest of sg * p[axis] over s: the best of a grid, then golden
 * sections along u and v in turn near it; exact where the extreme is at
 * a control point of the net (a keel at a corner or an edge). */
static double
surface_extreme(const struct loft_surface *s, int axis, double sg)
{
	const double g = 0.6180339887498949;
	double lo[3], hi[3], p[3], best = -HUGE_VAL, uv[2] = { 0, 0 };

	for (int i = 0; i <= EXT_GRID; i++)
		for (int j = 0; j <= EXT_GRID; j++) {
			loft_surface_eval(s, (double)i / EXT_GRID,
			    (double)j / EXT_GRID, p, NULL, NULL);
			if (sg * p[axis] > best) {
				best = sg * p[axis];
				uv[0] = (double)i / EXT_GRID;
				uv[1] = (double)j / EXT_GRID;
			}
		}
	loft_surface_box(s, lo, hi);
	if (best >= (sg > 0 ? hi[axis] : -lo[axis]))
		return sg * best;       /* the net's bound is reached */
	for (int round = 0; round < 4; round++)
		for (int d = 0; d < 2; d++) {
			double a = fmax(0, uv[d] - 1.0 / EXT_GRID);
			double b = fmin(1, uv[d] + 1.0 / EXT_GRID), t[2];

			for (int k = 0; k < EXT_STEPS; k++) {
				double f[2];

				t[0] = b - g * (b - a);
				t[1] = a + g * (b - a);
				for (int e = 0; e < 2; e++) {
					double w[2] = { uv[0], uv[1] };

					w[d] = t[e];
					loft_surface_eval(s, w[0], w[1], p, NULL, NULL);
					f[e] = sg * p[axis];
				}
				if (f[0] > f[1])
					b = t[1];
				else
					a = t[0];
				if (fmax(f[0], f[1]) > best) {
					best = fmax(f[0], f[1]);
					uv[d] = f[0] > f[1] ? t[0] : t[1];
				}
			}
		}
	return sg * best;
}

/* The frame: the box of all, its middle, a power of 2 above its size. */
static void
frame_of(struct loft_hydro *h)
{
	double lo[3], hi[3], size = 0;
	int e;

	memcpy(lo, h->box, sizeof lo);          /* ns >= 1 */
	memcpy(hi, h->box + 3, sizeof hi);
	for (size_t i = 1; i < h->ns; i++)
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], h->box[6 * i + k]);
			hi[k] = fmax(hi[k], h->box[6 * i + 3 + k]);
		}
	for (int k = 0; k < 3; k++) {
		h->o[k] = k == 1 ? 0 : lo[k] / 2 + hi[k] / 2;
		size = fmax(size, fmax(fabs(lo[k] - h->o[k]),
		    fabs(hi[k] - h->o[k])));
	}
	frexp(size > 0 ? size : 1, &e);
	h->scale = ldexp(1, e + 1);     /* above twice the size */
}

int
loft_hydro_init(struct loft_hydro *h, const struct loft_surface *s,
    size_t ns, int whole, struct loft_error *err)
{
	double ymin = HUGE_VAL;

	memset(h, 0, sizeof *h);
	for (size_t i = 0; i < ns; i++)
		if (s[i].dim != 3)
			return loft_fail(err, LOFT_EINPUT, -1, "a surface of %d "
			    "coordinates: a hull is in space (x along, y across, "
			    "z up)", s[i].dim);
	if (ns == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "no surfaces: no hull");
	h->s = s;
	h->ns = ns;
	h->whole = whole;
	h->box = malloc(ns * 6 * sizeof *h->box);
	h->full = calloc(ns * NM, sizeof *h->full);
	if (h->box == NULL || h->full == NULL) {
		loft_hydro_free(h);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	for (size_t i = 0; i < ns; i++)
		loft_surface_box(&s[i], h->box + 6 * i, h->box + 6 * i + 3);
	frame_of(h);
	h->zmin = HUGE_VAL;
	h->zmax = -HUGE_VAL;
	for (size_t i = 0; i < ns; i++) {
		h->zmin = fmin(h->zmin, surface_extreme(&s[i], 2, -1));
		h->zmax = fmax(h->zmax, surface_extreme(&s[i], 2, 1));
		if (!whole && h->box[6 * i + 1] < 0)
			ymin = fmin(ymin, surface_extreme(&s[i], 1, -1));
		clip_moments(h, i, 0, NULL, NULL, h->full + NM * i);
	}
	if (ymin < -HALF_TOL * h->scale) {
		loft_hydro_free(h);
		return loft_fail(err, LOFT_EINPUT, -1, "the hull reaches y = %g "
		    "< 0: a half is the starboard side, y >= 0 (-w for a "
		    "whole hull)", ymin);
	}
	return 0;
}

void
loft_hydro_free(struct loft_hydro *h)
{
	free(h->box);
	free(h->full);
	h->box = h->full = NULL;
}

/* The moments of the hull where p[axis[k]] <= level[k] (k < nc) into m. */
static void
hull_moments(const struct loft_hydro *h, int nc, const int *axis,
    const double *level, double *m)
{
	memset(m, 0, NM * sizeof *m);
	for (size_t i = 0; i < h->ns; i++) {
		const double *lo = h->box + 6 * i, *hi = lo + 3;
		int cut[LOFT_CLIP_MAX], ncut = 0, out = 0;
		double lv[LOFT_CLIP_MAX];

		for (int k = 0; k < nc; k++) {
			if (lo[axis[k]] >= level[k])
				out = 1;
			else if (hi[axis[k]] > level[k]) {
				cut[ncut] = axis[k];
				lv[ncut++] = level[k];
			}
		}
		if (out)
			continue;
		if (ncut == 0)
			for (int k = 0; k < NM; k++)
				m[k] += h->full[NM * i + k];
		else
			clip_moments(h, i, ncut, cut, lv, m);
	}
}

/* Whether the waterline wl meets the hull: 0 or LOFT_EGEOM. */
static int
in_range(const struct loft_hydro *h, double wl, struct loft_error *err)
{
	if (!(wl > h->zmin))
		return loft_fail(err, LOFT_EGEOM, -1, "waterline z = %g is at or "
		    "below the hull's lowest point z = %g", wl, h->zmin);
	if (wl > h->zmax)
		return loft_fail(err, LOFT_EGEOM, -1, "waterline z = %g is above "
		    "the hull's top z = %g", wl, h->zmax);
	return 0;
}

/* Points sampled along each side of a surface, to match it with the
 * side of another: sides shared by neighbouring patches pass through
 * the same points, ends first or last. */
#define SIDE_PTS 5
/* Two sides are one, a side lies on the centreplane or a point is
 * above the waterline within this part of the hull's size: sides
 * shared by patches that patchloft or patchjoin made agree to rounding,
 * and a true gap is far wider. */
#define SIDE_TOL 1e-7

struct side {
	double p[SIDE_PTS][3];
	size_t surf;
};

static int
by_middle_x(const void *a, const void *b)
{
	double x = ((const struct side *)a)->p[SIDE_PTS / 2][0],
	    y = ((const struct side *)b)->p[SIDE_PTS / 2][0];

	return (x > y) - (x < y);
}

/* Whether sides a and b pass through the same points, either way. */
static int
same_side(const struct side *a, const struct side *b, double tol)
{
	int fwd = 1, back = 1;

	for (int j = 0; j < SIDE_PTS; j++)
		for (int k = 0; k < 3; k++) {
			fwd &= fabs(a->p[j][k] - b->p[j][k]) <= tol;
			back &= fabs(a->p[j][k] - b->p[SIDE_PTS - 1 - j][k]) <=
			    tol;
		}
	return fwd || back;
}

/* Whether side a matters to the hull's closing below wl: it reaches
 * below the waterline, is not a point or a line of one point (a keel
 * or stem where the side collapses), and for a half does not lie on
 * the centreplane y = 0, where the mirror closes it. */
static int
side_matters(const struct loft_hydro *h, const struct side *a, double wl,
    double tol)
{
	int below = 0, point = 1, centre = 1;

	for (int j = 0; j < SIDE_PTS; j++) {
		below |= a->p[j][2] < wl - tol;
		centre &= fabs(a->p[j][1]) <= tol;
		for (int k = 0; k < 3; k++)
			point &= fabs(a->p[j][k] - a->p[0][k]) <= tol;
	}
	return below && !point && !(centre && !h->whole);
}

/*
 * The first surface of h (in input order) with a side below the
 * waterline wl that no other side shares: where an open hull is open,
 * for its message to name.  -1 when none is found (or memory ran
 * out).  The sides sorted by the x of their middles, so that each is
 * matched against the few near it: n log n for n surfaces.
 */
static long
open_surface(const struct loft_hydro *h, double wl)
{
	size_t n = 4 * h->ns;
	struct side *sd = malloc(n * sizeof *sd);
	double tol = SIDE_TOL * h->scale;
	long first = -1;

	if (sd == NULL)
		return -1;
	for (size_t i = 0; i < h->ns; i++)
		for (int e = 0; e < 4; e++) {
			struct side *a = &sd[4 * i + e];

			a->surf = i;
			for (int j = 0; j < SIDE_PTS; j++) {
				double t = (double)j / (SIDE_PTS - 1),
				    u = e < 2 ? e : t, v = e < 2 ? t : e - 2;

				loft_surface_eval(&h->s[i], u, v, a->p[j], NULL,
				    NULL);
			}
		}
	qsort(sd, n, sizeof *sd, by_middle_x);
	for (size_t k = 0; k < n; k++) {
		int shared = 0;
		double x = sd[k].p[SIDE_PTS / 2][0];

		if ((first >= 0 && sd[k].surf >= (size_t)first) ||
		    !side_matters(h, &sd[k], wl, tol))
			continue;
		for (size_t m = k; !shared && m-- > 0 &&
		    sd[m].p[SIDE_PTS / 2][0] >= x - tol;)
			shared = same_side(&sd[k], &sd[m], tol);
		for (size_t m = k + 1; !shared && m < n &&
		    sd[m].p[SIDE_PTS / 2][0] <= x + tol; m++)
			shared = same_side(&sd[k], &sd[m], tol);
		if (!shared)
			first = (long)sd[k].surf;
	}
	free(sd);
	return first;
}

/* The hull open below wl: the message, and in err->row the surface
 * open_surface finds (-1: none). */
static int
open_hull(const struct loft_hydro *h, double wl, const char *where,
    struct loft_error *err)
{
	loft_fail(err, LOFT_EGEOM, -1, "the hull is open below the waterline "
	    "z = %g: %s", wl, where);
	err->row = open_surface(h, wl);
	return LOFT_EGEOM;
}

/* The waterline's checks, and the moments below it with the hull's
 * normals turned outward (*sg: -1 when they were turned); zn: the
 * waterline inside. */
static int
below(const struct loft_hydro *h, double wl, double *m, double *zn,
    double *sg, struct loft_error *err)
{
	int axis = 2, big;
	double v[3], w;

	if (in_range(h, wl, err) != 0)
		return LOFT_EGEOM;
	hull_moments(h, 1, &axis, &wl, m);
	*zn = (wl - h->o[2]) / h->scale;
	v[0] = m[M_ZNZ] - *zn * m[M_NZ];
	v[1] = m[M_XNX];
	v[2] = m[M_YNY];
	w = m[M_AREA];
	/* the sense of the normals: of the largest of the three volumes */
	big = fabs(v[0]) >= fabs(v[1]) ? 0 : 1;
	big = fabs(v[big]) >= fabs(v[2]) ? big : 2;
	if (!(fabs(v[big]) > CLOSE_TOL * w))
		return loft_fail(err, LOFT_EGEOM, -1, "no volume below the "
		    "waterline z = %g", wl);
	*sg = v[big] < 0 ? -1 : 1;
	for (int k = 0; k < NM; k++)
		if (k != M_AREA)
			m[k] *= *sg;
	for (int k = 0; k < 3; k++)
		v[k] *= *sg;
	if (!(fabs(v[0] - v[big]) <= CLOSE_TOL * w))
		return open_hull(h, wl, "its bottom does not close", err);
	if (!(fabs(m[M_NX]) <= CLOSE_TOL * w && fabs(v[1] - v[0]) <=
	    CLOSE_TOL * w))
		return open_hull(h, wl, "its ends do not close", err);
	if (!(fabs(v[2] - v[0]) <= CLOSE_TOL * w) || (h->whole &&
	    !(fabs(m[M_NY]) <= CLOSE_TOL * w)))
		return open_hull(h, wl, h->whole ? "its sides do not close" :
		    "its sides do not close at the centreplane y = 0", err);
	return 0;
}

/* The waterline's ends and breadth: the extremes of samples along it on
 * every surface it crosses, then refined on the surfaces whose samples
 * come near the extremes of all.  0 when it crosses none, -1 when
 * memory ran out. */
static int
waterline_box(const struct loft_hydro *h, double wl, double *lo, double *hi)
{
	double *c = malloc(h->ns * 6 * sizeof *c), glo[3], ghi[3];
	int found = 0;

	if (c == NULL)
		return -1;
	for (size_t i = 0; i < h->ns; i++) {
		double *a = c + 6 * i, *b = a + 3;

		a[0] = HUGE_VAL;        /* not crossed */
		if (h->box[6 * i + 2] > wl || h->box[6 * i + 5] < wl ||
		    loft_clip_extremes(&h->s[i], 2, wl, 0, a, b) != 0) {
			a[0] = HUGE_VAL;
			continue;
		}
		for (int k = 0; k < 3; k++) {
			glo[k] = found ? fmin(glo[k], a[k]) : a[k];
			ghi[k] = found ? fmax(ghi[k], b[k]) : b[k];
		}
		found = 1;
	}
	for (int k = 0; found && k < 3; k++) {
		lo[k] = glo[k];
		hi[k] = ghi[k];
	}
	for (size_t i = 0; found && i < h->ns; i++) {
		const double *bx = h->box + 6 * i, *a = c + 6 * i, *b = a + 3;
		double ra[3], rb[3], margin = EXT_MARGIN * (fabs(bx[3] - bx[0]) +
		    fabs(bx[4] - bx[1]) + fabs(bx[5] - bx[2]));

		if (a[0] == HUGE_VAL || (a[0] > glo[0] + margin && b[0] <
		    ghi[0] - margin && a[1] > glo[1] + margin && b[1] <
		    ghi[1] - margin))
			continue;       /* far from the extremes */
		if (loft_clip_extremes(&h->s[i], 2, wl, 1, ra, rb) != 0)
			continue;
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], ra[k]);
			hi[k] = fmax(hi[k], rb[k]);
		}
	}
	free(c);
	return found;
}

static double section_area(const struct loft_hydro *h, double wl, double xs,
    double sg);

/* The hydrostatics from the moments m below the waterline zn (inside). */
static void
from_moments(const struct loft_hydro *h, const double *m, double zn,
    struct loft_hydrostatics *o)
{
	double s = h->scale, mult = h->whole ? 1 : 2;
	double v = m[M_ZNZ] - zn * m[M_NZ], a = -m[M_NZ];
	double xf = -m[M_XNZ] / a, yf = h->whole ? -m[M_YNZ] / a : 0;

	o->volume = mult * v * s * s * s;
	o->lcb = h->o[0] + s * ((m[M_XZNZ] - zn * m[M_XNZ]) / v);
	o->tcb = h->whole ? s * ((m[M_YZNZ] - zn * m[M_YNZ]) / v) : 0;
	o->vcb = o->z + s * ((m[M_ZZNZ] - 2 * zn * m[M_ZNZ] + zn * zn *
	    m[M_NZ]) / (2 * v));
	o->awp = mult * a * s * s;
	o->lcf = h->o[0] + s * xf;
	o->bmt = s * ((-m[M_YYNZ] - a * yf * yf) / v);
	o->bml = s * ((-m[M_XXNZ] - a * xf * xf) / v);
	o->t = o->z - h->zmin;
	o->kmt = o->vcb - h->zmin + o->bmt;
	o->kml = o->vcb - h->zmin + o->bml;
	o->wetted = mult * m[M_AREA] * s * s;
}

int
loft_hydro_at(const struct loft_hydro *h, double wl,
    struct loft_hydrostatics *o, struct loft_error *err)
{
	double m[NM], zn, lo[3], hi[3], sg;
	int rc;

	memset(o, 0, sizeof *o);
	o->z = wl;
	if (below(h, wl, m, &zn, &sg, err) != 0)
		return LOFT_EGEOM;
	from_moments(h, m, zn, o);
	if ((rc = waterline_box(h, wl, lo, hi)) < 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (rc == 0)
		return loft_fail(err, LOFT_EGEOM, -1, "waterline z = %g meets "
		    "no surface", wl);
	o->lwl = hi[0] - lo[0];
	o->bwl = h->whole ? hi[1] - lo[1] : 2 * hi[1];
	o->am = section_area(h, wl, lo[0] / 2 + hi[0] / 2, sg);
	o->cb = o->volume / (o->lwl * o->bwl * o->t);
	o->cp = o->volume / (o->am * o->lwl);
	o->cm = o->am / (o->bwl * o->t);
	o->cwp = o->awp / (o->lwl * o->bwl);
	return 0;
}

/* The section's area, the normals' sense sg known. */
static double
section_area(const struct loft_hydro *h, double wl, double xs, double sg)
{
	double m[NM], lv[2] = { wl, xs };
	int axis[2] = { 2, 0 };

	hull_moments(h, 2, axis, lv, m);
	/* at the ends the area is 0 but for rounding, of either sign */
	return fmax(0, -sg * (h->whole ? 1 : 2) * m[M_NX] * h->scale *
	    h->scale);
}

int
loft_hydro_sections(const struct loft_hydro *h, double wl, const double *xs,
    size_t n, double *area, struct loft_error *err)
{
	double m[NM], zn, sg;

	if (below(h, wl, m, &zn, &sg, err) != 0)
		return LOFT_EGEOM;
	for (size_t i = 0; i < n; i++)
		area[i] = section_area(h, wl, xs[i], sg);
	return 0;
}

int
loft_hydro_ends(const struct loft_hydro *h, double wl, double *x0, double *x1,
    struct loft_error *err)
{
	double lo[3], hi[3];
	int rc;

	if (in_range(h, wl, err) != 0)
		return LOFT_EGEOM;
	if ((rc = waterline_box(h, wl, lo, hi)) < 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (rc == 0)
		return loft_fail(err, LOFT_EGEOM, -1, "waterline z = %g meets "
		    "no surface", wl);
	*x0 = lo[0];
	*x1 = hi[0];
	return 0;
}
