/*
 * sewing.c: Bezier patches sewn into one shell for the B-rep writers
 * (STEP's step.c, IGES's iges.c): corners at one point, or put together
 * by the patches' links, become one vertex; a side that two patches
 * share becomes one edge, named by both faces' loops with their senses;
 * a side that is all one point (a pole) is no edge.  The writers only
 * write what this finds.
 * Program layer (loftcad.h): the geometry of the CAD formats.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

/*
 * A patch's sides, in the order its loop runs them, counterclockwise
 * in (u, v), so that the face's normal is f_u x f_v: side 0 is v = 0,
 * 1 is u = 1, 2 is v = 1 and 3 is u = 0.  Each side's curve is kept in
 * the direction of its surface parameter (u on sides 0 and 2, v on 1
 * and 3), from corner sfrom to corner sto (corners 0 (0,0), 1 (1,0),
 * 2 (1,1), 3 (0,1)); the loop runs sides 2 and 3 backwards.
 */
static const int sfrom[4] = { 0, 1, 3, 0 }, sto[4] = { 1, 2, 2, 3 };
/* The side of each loft_edge (u0, u1, v0, v1). */
static const int side_of[4] = { 3, 1, 0, 2 };

int
loft_sew_add(struct loft_sew *w, const struct loft_bsurf *b,
    const struct loft_record *rec, const char *name, long surf)
{
	struct loft_sew_face *f;
	struct loft_error err;
	int m = b->m, n = b->n;

	if (loft__grow((void **)&w->face, &w->facecap, w->nface + 1,
	    sizeof *w->face) != 0)
		return LOFT_ENOMEM;
	f = memset(w->face + w->nface, 0, sizeof *w->face);
	f->surf = surf;
	f->patch = -1;
	f->m = m;
	f->n = n;
	w->nface++;
	if ((f->name = malloc(strlen(name) + 1)) == NULL || (f->ctl =
	    malloc(3 * (size_t)(m + 1) * (size_t)(n + 1) * sizeof *f->ctl)) ==
	    NULL)
		return LOFT_ENOMEM;
	strcpy(f->name, name);
	memcpy(f->ctl, b->ctl, 3 * (size_t)(m + 1) * (size_t)(n + 1) *
	    sizeof *f->ctl);
	for (int e = 0; e < 4; e++) {
		int deg = e % 2 ? n : m;

		f->deg[e] = deg;
		if ((f->side[e] = malloc(3 * (size_t)(deg + 1) *
		    sizeof *f->side[e])) == NULL)
			return LOFT_ENOMEM;
		for (int k = 0; k <= deg; k++) {
			int i = e == 0 || e == 2 ? k : e == 1 ? m : 0;
			int j = e == 1 || e == 3 ? k : e == 2 ? n : 0;

			memcpy(f->side[e] + 3 * k, b->ctl + 3 * (i * (n + 1) +
			    j), 3 * sizeof *b->ctl);
		}
	}
	/* a patch with an id: its links say which sides are shared */
	if (rec != NULL && loft_record_is(rec, LOFT_KIND_MEMBER) &&
	    loft_attr(rec, "id") != NULL &&
	    loft_design_add(&w->design, rec, &err) == 0) {
		w->design.p[w->design.n - 1].rec = NULL;
		f->patch = (long)w->design.n - 1;
	}
	return 0;
}

/* The point of corner c of face f: the first or last of a side. */
static const double *
corner_pt(const struct loft_sew_face *f, int c)
{
	return c == 0 ? f->side[0] : c == 1 ? f->side[1] : c == 2 ?
	    f->side[1] + 3 * f->deg[1] : f->side[3] + 3 * f->deg[3];
}

static long
root(long *up, long v)
{
	while (up[v] != v)
		v = up[v] = up[up[v]];
	return v;
}

static void
join(long *up, long a, long b)
{
	a = root(up, a);
	b = root(up, b);
	if (a != b)
		up[a > b ? a : b] = a < b ? a : b;
}

/* Order of corners by their points, for welding equal ones. */
static const struct loft_sew *sort_w;
static int
cmp_corner(const void *a, const void *b)
{
	long x = *(const long *)a, y = *(const long *)b;
	const double *p = corner_pt(sort_w->face + x / 4, (int)(x % 4));
	const double *q = corner_pt(sort_w->face + y / 4, (int)(y % 4));

	for (int k = 0; k < 3; k++)
		if (p[k] != q[k])
			return p[k] < q[k] ? -1 : 1;
	return 0;
}

/* The face of design patch index ip, or -1. */
static long
face_of_patch(const struct loft_sew *w, long ip)
{
	for (size_t i = 0; i < w->nface; i++)
		if (w->face[i].patch == ip)
			return (long)i;
	return -1;
}

/*
 * Weld corners: those at the same point, and those that the patches'
 * links put together (a link over a whole side: its ends meet the
 * neighbour's side's ends, the same way round when it runs from 0 to
 * 1).  force[4 f + e] is then 4 g + e' + 1 for the side it is shared
 * with, so that the sides are one edge even where rounding made their
 * points differ; 0 otherwise.
 */
static void
weld(const struct loft_sew *w, long *up, long *force)
{
	size_t nc = 4 * w->nface;
	long *ord = malloc(nc * sizeof *ord);

	for (size_t i = 0; i < nc; i++)
		up[i] = (long)i, force[i] = 0;
	if (ord != NULL) {
		for (size_t i = 0; i < nc; i++)
			ord[i] = (long)i;
		sort_w = w;
		qsort(ord, nc, sizeof *ord, cmp_corner);
		for (size_t i = 1; i < nc; i++)
			if (cmp_corner(ord + i - 1, ord + i) == 0)
				join(up, ord[i - 1], ord[i]);
		free(ord);
	}
	for (size_t f = 0; f < w->nface; f++) {
		const struct loft_patch *p;

		if (w->face[f].patch < 0)
			continue;
		p = w->design.p + w->face[f].patch;
		for (int le = 0; le < 4; le++) {
			const struct loft_link *L = p->link[le];
			long g, ip;
			int e = side_of[le], ge = -1;

			if (p->nlink[le] != 1 || fmin(L->a, L->b) != 0 ||
			    fmax(L->a, L->b) != 1 || (ip = loft_design_find(
			    &w->design, L->id)) < 0 || (g = face_of_patch(w,
			    ip)) < 0)
				continue;
			for (int k = 0; k < 4; k++)
				if (w->design.p[ip].nlink[k] == 1 &&
				    w->design.p[ip].link[k]->id == p->id)
					ge = side_of[k];
			if (ge < 0)
				continue;
			join(up, 4 * (long)f + sfrom[e], 4 * g + (L->a == 0 ?
			    sfrom[ge] : sto[ge]));
			join(up, 4 * (long)f + sto[e], 4 * g + (L->a == 0 ?
			    sto[ge] : sfrom[ge]));
			force[4 * f + (size_t)e] = 4 * g + ge + 1;
		}
	}
}

/* Whether side e of f has all its points at one place (a pole). */
static int
degenerate(const struct loft_sew_face *f, int e)
{
	for (int k = 1; k <= f->deg[e]; k++)
		if (memcmp(f->side[e], f->side[e] + 3 * k, 3 * sizeof(double)))
			return 0;
	return 1;
}

/* Whether sides (f, e) and (g, h) have the same points, the same way
 * round (same 1) or the other (same 0). */
static int
same_points(const struct loft_sew_face *f, int e,
    const struct loft_sew_face *g, int h, int same)
{
	int d = f->deg[e];

	if (g->deg[h] != d)
		return 0;
	for (int k = 0; k <= d; k++)
		if (memcmp(f->side[e] + 3 * k, g->side[h] + 3 * (same ? k :
		    d - k), 3 * sizeof(double)))
			return 0;
	return 1;
}

/* The edge side (f, e) is, its ends the welded corners a and b: an
 * earlier one it is forced (fz: 4 g + e') or found to be, or a new one;
 * -1 when out of memory.  Sets the face's fwd[e]. */
static long
edge_for(struct loft_sew *w, long a, long b, long fz, size_t f, int e)
{
	struct loft_sew_face *F = w->face + f;

	for (size_t k = 0; k < w->nedge; k++) {
		struct loft_sew_edge *x = w->edge + k;
		const struct loft_sew_face *G = w->face + x->face;
		int same;

		if (!((x->from == a && x->to == b) || (x->from == b &&
		    x->to == a)) || x->uses >= 2)
			continue;
		same = x->from == a && (a != b || same_points(F, e, G, x->side,
		    1));
		if ((fz >= 0 && fz / 4 == x->face && fz % 4 == x->side) ||
		    same_points(F, e, G, x->side, same)) {
			x->uses++;
			F->fwd[e] = same == (e < 2);
			return (long)k;
		}
	}
	if (loft__grow((void **)&w->edge, &w->edgecap, w->nedge + 1,
	    sizeof *w->edge) != 0)
		return -1;
	w->edge[w->nedge] = (struct loft_sew_edge){ a, b, (long)f, e, 1, 0 };
	F->fwd[e] = e < 2;
	return (long)w->nedge++;
}

/* Number the welded corners that end an edge, in the order the edges
 * first name them, and keep their points; the edges' ends become those
 * numbers.  -1 when out of memory. */
static int
number_vertices(struct loft_sew *w)
{
	size_t nc = 4 * w->nface;
	long *num;

	if (nc == 0)            /* no faces: no corners to number */
		return 0;
	num = malloc(nc * sizeof *num);
	if (num == NULL || (w->vert = malloc(3 * nc * sizeof *w->vert)) ==
	    NULL) {
		free(num);
		return -1;
	}
	for (size_t i = 0; i < nc; i++)
		num[i] = -1;
	for (size_t k = 0; k < w->nedge; k++) {
		long *c[2] = { &w->edge[k].from, &w->edge[k].to };

		for (int j = 0; j < 2; j++) {
			if (num[*c[j]] < 0) {
				memcpy(w->vert + 3 * w->nvert, corner_pt(w->face +
				    *c[j] / 4, (int)(*c[j] % 4)), 3 *
				    sizeof *w->vert);
				num[*c[j]] = (long)w->nvert++;
			}
			*c[j] = num[*c[j]];
		}
	}
	free(num);
	return 0;
}

/*
 * The k-point Gauss-Legendre rule on [0, 1] into x and wt (k <= MAXGAUSS),
 * exact for polynomials of degree 2k - 1: the roots of the Legendre
 * polynomial P_k by Newton's method from cos(pi (i - 1/4) / (k + 1/2)).
 */
#define MAXGAUSS 100
static void
gauss(int k, double *x, double *wt)
{
	for (int i = 0; i < (k + 1) / 2; i++) {
		double t = cos(M_PI * (i + 0.75) / (k + 0.5)), dp = 1;

		for (int it = 0; it < 100; it++) {
			double p0 = 1, p1 = t, step;    /* P_0, P_1 */

			for (int j = 2; j <= k; j++) {
				double p2 = ((2 * j - 1) * t * p1 - (j - 1) * p0) / j;

				p0 = p1;
				p1 = p2;
			}
			/* p1 is P_k(t), p0 P_(k-1)(t); dp P_k'(t) */
			dp = k * (t * p1 - p0) / (t * t - 1);
			step = p1 / dp;
			t -= step;
			if (fabs(step) < 1e-15)
				break;
		}
		x[i] = (1 - t) / 2;
		x[k - 1 - i] = (1 + t) / 2;
		wt[i] = wt[k - 1 - i] = 1 / ((1 - t * t) * dp * dp);
	}
}

/*
 * The volume the faces enclose, by the divergence theorem: a third of
 * the sum over the faces of the integral of F . (F_u x F_v) over the
 * unit square, positive when their normals f_u x f_v point out.  The
 * integrand is of degree 3m - 1 in u and 3n - 1 in v: Gauss's rule of
 * 3 max(m, n) / 2 + 1 points each way is exact.
 */
static double
signed_volume(const struct loft_sew *w)
{
	double x[MAXGAUSS] = { 0 }, wt[MAXGAUSS] = { 0 }, vol = 0;

	for (size_t f = 0; f < w->nface; f++) {
		const struct loft_sew_face *F = w->face + f;
		int k = 3 * (F->m > F->n ? F->m : F->n) / 2 + 1;

		if (k > MAXGAUSS)
			k = MAXGAUSS;
		gauss(k, x, wt);
		for (int i = 0; i < k; i++)
			for (int j = 0; j < k; j++) {
				double p[3], pu[3], pv[3];

				loft_bezier_surface_eval(F->ctl, F->m, F->n, x[i],
				    x[j], p, pu, pv);
				vol += wt[i] * wt[j] * (p[0] * (pu[1] * pv[2] -
				    pu[2] * pv[1]) + p[1] * (pu[2] * pv[0] -
				    pu[0] * pv[2]) + p[2] * (pu[0] * pv[1] -
				    pu[1] * pv[0])) / 3;
			}
	}
	return vol;
}

int
loft_sew_run(struct loft_sew *w)
{
	size_t nc = 4 * w->nface;
	long *up, *force;
	int rc = LOFT_ENOMEM;

	if (nc == 0)
		return 0;
	up = malloc(nc * sizeof *up);
	force = malloc(nc * sizeof *force);
	if (up == NULL || force == NULL)
		goto done;
	weld(w, up, force);
	for (size_t f = 0; f < w->nface; f++)
		for (int e = 0; e < 4; e++) {
			struct loft_sew_face *F = w->face + f;

			F->edge[e] = -1;
			if (degenerate(F, e))
				continue;
			if ((F->edge[e] = edge_for(w, root(up, 4 * (long)f +
			    sfrom[e]), root(up, 4 * (long)f + sto[e]),
			    force[4 * f + (size_t)e] - 1, f, e)) < 0)
				goto done;
		}
	if (number_vertices(w) != 0)
		goto done;
	w->closed = w->nedge > 0;
	for (size_t k = 0; k < w->nedge; k++)
		w->closed &= w->edge[k].uses == 2;
	w->volume = w->closed ? signed_volume(w) : 0;
	rc = 0;
done:
	free(up);
	free(force);
	return rc;
}

void
loft_sew_free(struct loft_sew *w)
{
	for (size_t i = 0; i < w->nface; i++) {
		free(w->face[i].name);
		free(w->face[i].ctl);
		for (int e = 0; e < 4; e++)
			free(w->face[i].side[e]);
	}
	free(w->face);
	free(w->edge);
	free(w->vert);
	loft_design_free(&w->design);
	memset(w, 0, sizeof *w);
}
