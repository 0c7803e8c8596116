/*
 * cut.c: the curves where a plane n.x = d cuts surfaces (patches of a
 * design, or any surface of surface.c's table).  On each surface the
 * zero set of g(u, v) = n.f(u, v) - d (for a patch a polynomial of
 * degree 4 in each variable) is found on a grid of cells: each grid
 * line where g changes sign holds a root, solved in that one parameter
 * with the other fixed, so the point is on the plane to rounding and
 * on the surface exactly as evaluated.  The roots are joined cell by
 * cell (marching squares, a saddle decided by the cell's centre), then
 * points are put between them, each again solved in one parameter,
 * until every chord is within the tolerance of the curve.  Pieces of
 * all the surfaces are joined where their ends meet.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Cells per direction: twice the degree, at least 8.  A loop of the cut
 * smaller than a cell may be missed; a patch's g is a quartic in each
 * variable, with at most 4 roots on a line, so 8 separates them on a
 * fair surface. */
#define GRID_MIN 8
#define GRID_MAX 64

/* An edge lies in the plane where g is this small, relative to the
 * surface's size and its distance from the origin, at 17 points along
 * it: rounding in evaluating a section at its station is 1e-16. */
#define PLANE_REL 1e-12

/* Pieces whose ends are this near, relative to the whole set's size,
 * meet: shared edges give the same roots to rounding. */
#define JOIN_REL 1e-9

/* A chord tolerance below this, relative to the set's size, is taken
 * as this: the points themselves are only on the surface to about
 * 1e-9 of its size (the promise of patchcut(1)), and below it halving
 * chords would multiply points past any use. */
#define TOL_MIN_REL 1e-9

/* Depth of the halving of a chord against the tolerance: 2^24 points
 * between two roots is more than any tolerance above rounding needs. */
#define DEPTH_MAX 24

struct piece {
	double *p;              /* points, dim each */
	size_t n, cap;
	int closed;
	int edge;               /* an edge of a surface in the plane */
};

struct pieces {
	struct piece *v;
	size_t n, cap;
};

/* A root of g on a grid line. */
struct root {
	double u, v;
	double p[LOFT_MAXDIM];
	long nb[2];
	int deg;
};

struct ctx {
	const struct loft_surface *s;
	const double *n;        /* unit normal */
	double d, tol;
	int dim;
};

static double
gval(const struct ctx *c, double u, double v, double *p, double *gu,
    double *gv)
{
	double q[LOFT_MAXDIM], du[LOFT_MAXDIM], dv[LOFT_MAXDIM];

	if (p == NULL)
		p = q;
	loft_surface_eval(c->s, u, v, p, gu ? du : NULL, gv ? dv : NULL);
	if (gu != NULL)
		*gu = vdot(c->n, du, c->dim);
	if (gv != NULL)
		*gv = vdot(c->n, dv, c->dim);
	return vdot(c->n, p, c->dim) - c->d;
}

static int
push_point(struct piece *pc, const double *p, int dim)
{
	if (loft__grow((void **)&pc->p, &pc->cap, (pc->n + 1) * dim,
	    sizeof *pc->p) != 0)
		return LOFT_ENOMEM;
	vcopy(pc->p + pc->n * dim, p, dim);
	pc->n++;
	return 0;
}

static struct piece *
new_piece(struct pieces *ps)
{
	if (loft__grow((void **)&ps->v, &ps->cap, ps->n + 1, sizeof *ps->v))
		return NULL;
	memset(&ps->v[ps->n], 0, sizeof ps->v[ps->n]);
	return &ps->v[ps->n++];
}

/*
 * The root of g on the line through (u, v) with parameter dir (0: u,
 * 1: v) free, between lo and hi where g has opposite signs glo, ghi:
 * Newton's steps kept inside the bracket, else halving, to adjacent
 * doubles.
 */
static void
bracket_root(const struct ctx *c, int dir, double fixed, double lo,
    double hi, double glo, struct root *r)
{
	double x = (lo + hi) / 2;

	for (int it = 0; it < 200; it++) {
		double gu, gv, u = dir == 0 ? x : fixed, v = dir == 0 ? fixed : x;
		double g = gval(c, u, v, NULL, &gu, &gv), gd = dir == 0 ? gu : gv;
		double nx;

		if (g == 0)
			break;
		if ((g < 0) == (glo < 0))
			lo = x;
		else
			hi = x;
		nx = x - g / gd;
		if (!(nx > fmin(lo, hi) && nx < fmax(lo, hi)))
			nx = (lo + hi) / 2;
		if (nx == x || (nx == lo || nx == hi))
			break;
		x = nx;
	}
	r->u = dir == 0 ? x : fixed;
	r->v = dir == 0 ? fixed : x;
	gval(c, r->u, r->v, r->p, NULL, NULL);
	r->nb[0] = r->nb[1] = -1;
	r->deg = 0;
}

/*
 * Project (u, v) onto g = 0 along the parameter in which g changes
 * faster, the other fixed, by Newton's method.  Returns 0 and the point,
 * or -1 when it does not settle within reach of the start.
 */
static int
project(const struct ctx *c, double *u, double *v, double reach, double *p)
{
	double gu, gv, g = gval(c, *u, *v, NULL, &gu, &gv);
	int dir = fabs(gu) >= fabs(gv) ? 0 : 1;
	double x = dir == 0 ? *u : *v, x0 = x;

	for (int it = 0; it < 60; it++) {
		double gd = dir == 0 ? gu : gv, nx;

		if (g == 0)
			break;
		if (!(gd != 0))
			return -1;
		nx = x - g / gd;
		nx = nx < 0 ? 0 : nx > 1 ? 1 : nx;
		if (!(fabs(nx - x0) <= reach))
			return -1;
		if (fabs(nx - x) <= 4e-16)
			break;
		x = nx;
		g = gval(c, dir == 0 ? x : *u, dir == 0 ? *v : x, NULL, &gu, &gv);
	}
	if (dir == 0)
		*u = x;
	else
		*v = x;
	gval(c, *u, *v, p, NULL, NULL);
	return 0;
}

/* Distance of m from the chord a b. */
static double
chord_gap(const double *a, const double *b, const double *m, int dim)
{
	double e[LOFT_MAXDIM], w[LOFT_MAXDIM], len;

	vsub(e, b, a, dim);
	vsub(w, m, a, dim);
	len = vunit(e, dim);
	if (len > 0)
		vaxpy(w, -vdot(w, e, dim), e, dim);
	return vnorm(w, dim);
}

/* Points between roots a and b (b pushed last), halving each chord
 * that strays more than the tolerance from the cut. */
static int
refine(const struct ctx *c, const struct root *a, const struct root *b,
    int depth, struct piece *pc)
{
	struct root m = { 0 };  /* m.p is set by project, before it is read */
	double reach = 2 * (fabs(a->u - b->u) + fabs(a->v - b->v)) + 1e-9;

	m.u = (a->u + b->u) / 2;
	m.v = (a->v + b->v) / 2;
	if (depth < DEPTH_MAX && project(c, &m.u, &m.v, reach, m.p) == 0 &&
	    chord_gap(a->p, b->p, m.p, c->dim) > c->tol) {
		if (refine(c, a, &m, depth + 1, pc) != 0)
			return LOFT_ENOMEM;
		return refine(c, &m, b, depth + 1, pc);
	}
	return push_point(pc, b->p, c->dim);
}

/* The same along an edge of the surface lying in the plane. */
static int
refine_edge(const struct ctx *c, int e, double t0, const double *p0,
    double t1, const double *p1, int depth, struct piece *pc)
{
	double t = (t0 + t1) / 2, p[LOFT_MAXDIM];
	double u = e < 2 ? e : t, v = e < 2 ? t : e - 2;

	loft_surface_eval(c->s, u, v, p, NULL, NULL);
	if (depth < DEPTH_MAX && chord_gap(p0, p1, p, c->dim) > c->tol) {
		if (refine_edge(c, e, t0, p0, t, p, depth + 1, pc) != 0)
			return LOFT_ENOMEM;
		return refine_edge(c, e, t, p, t1, p1, depth + 1, pc);
	}
	return push_point(pc, p1, c->dim);
}

/* The edge e (enum loft_edge) as a piece, at least 4 chords. */
static int
edge_piece(const struct ctx *c, int e, struct pieces *ps)
{
	struct piece *pc = new_piece(ps);
	double p0[LOFT_MAXDIM], p1[LOFT_MAXDIM];

	if (pc == NULL)
		return LOFT_ENOMEM;
	pc->edge = 1;
	for (int i = 0; i <= 4; i++) {
		double t = i / 4.0, u = e < 2 ? e : t, v = e < 2 ? t : e - 2;

		loft_surface_eval(c->s, u, v, p1, NULL, NULL);
		if (i == 0) {
			if (push_point(pc, p1, c->dim) != 0)
				return LOFT_ENOMEM;
		} else if (refine_edge(c, e, (i - 1) / 4.0, p0, t, p1, 0,
		    pc) != 0) {
			return LOFT_ENOMEM;
		}
		vcopy(p0, p1, c->dim);
	}
	return 0;
}

static void
link_roots(struct root *r, long a, long b)
{
	if (a < 0 || b < 0 || r[a].deg == 2 || r[b].deg == 2)
		return;
	r[a].nb[r[a].deg++] = b;
	r[b].nb[r[b].deg++] = a;
}

/* Walk the chain of roots from root i, refining each link into pc. */
static int
walk(const struct ctx *c, struct root *r, char *seen, long i,
    struct piece *pc)
{
	long prev = -1, first = i;

	if (push_point(pc, r[i].p, c->dim) != 0)
		return LOFT_ENOMEM;
	seen[i] = 1;
	for (;;) {
		long nx = -1;

		for (int k = 0; k < r[i].deg; k++)
			if (r[i].nb[k] != prev && !seen[r[i].nb[k]]) {
				nx = r[i].nb[k];
				break;
			}
		if (nx < 0) {
			/* a loop closes on its first root */
			if (r[i].deg == 2 && r[first].deg == 2 && prev >= 0 &&
			    (r[i].nb[0] == first || r[i].nb[1] == first) &&
			    i != first) {
				if (refine(c, &r[i], &r[first], 0, pc) != 0)
					return LOFT_ENOMEM;
				pc->n--;        /* the first again */
				pc->closed = 1;
			}
			return 0;
		}
		if (refine(c, &r[i], &r[nx], 0, pc) != 0)
			return LOFT_ENOMEM;
		seen[nx] = 1;
		prev = i;
		i = nx;
	}
}

/*
 * cut_surface's marching grid: g the plane's function at the (m + 1)^2
 * nodes (a / m, b / m), hx and vx the index in r of the root on each
 * side of a cell along u and along v (or -1), r the nr roots.
 */
struct grid {
	int m;
	double *g;
	long *hx, *vx;
	struct root *r;
	size_t nr;
};
#define G(a, b) gr->g[(size_t)(a) * (gr->m + 1) + (b)]

/* Which edges of the surface lie in the plane (in[e]), each a piece
 * into ps; *ne their count.  0 or LOFT_ENOMEM. */
static int
plane_edges(const struct ctx *c, const double *lo, const double *hi,
    int *in, int *ne, struct pieces *ps)
{
	double size = vdist(lo, hi, c->dim), far = 0;
	int rc;

	for (int k = 0; k < c->dim; k++)
		far = fmax(far, fmax(fabs(lo[k]), fabs(hi[k])));
	for (int e = 0; e < 4; e++) {
		in[e] = 1;
		for (int i = 0; i <= 16 && in[e]; i++) {
			double t = i / 16.0;

			if (!(fabs(gval(c, e < 2 ? e : t, e < 2 ? t : e - 2, NULL,
			    NULL, NULL)) <= PLANE_REL * (size + far)))
				in[e] = 0;
		}
		if (in[e]) {
			++*ne;
			if ((rc = edge_piece(c, e, ps)) != 0)
				return rc;
		}
	}
	return 0;
}

/* The function at the grid's nodes; an edge in the plane takes the
 * signs beside it, so that it has no roots. */
static void
grid_values(const struct ctx *c, struct grid *gr, const int *in)
{
	int m = gr->m;

	for (int a = 0; a <= m; a++)
		for (int b = 0; b <= m; b++)
			G(a, b) = gval(c, (double)a / m, (double)b / m, NULL, NULL,
			    NULL);
	for (int k = 0; k <= m; k++) {
		if (in[LOFT_U0])
			G(0, k) = G(1, k);
		if (in[LOFT_U1])
			G(m, k) = G(m - 1, k);
		if (in[LOFT_V0])
			G(k, 0) = G(k, 1);
		if (in[LOFT_V1])
			G(k, m) = G(k, m - 1);
	}
}

/* The roots on the grid's lines v = b / m, then u = a / m. */
static void
grid_roots(const struct ctx *c, struct grid *gr, const int *in)
{
	int m = gr->m;

	for (int b = 0; b <= m; b++)
		for (int a = 0; a < m; a++) {
			long *x = &gr->hx[(size_t)b * m + a];

			*x = -1;
			if ((G(a, b) < 0) != (G(a + 1, b) < 0) &&
			    !((b == 0 && in[LOFT_V0]) || (b == m && in[LOFT_V1]))) {
				bracket_root(c, 0, (double)b / m, (double)a / m,
				    (double)(a + 1) / m, G(a, b), &gr->r[gr->nr]);
				*x = (long)gr->nr++;
			}
		}
	for (int a = 0; a <= m; a++)
		for (int b = 0; b < m; b++) {
			long *x = &gr->vx[(size_t)a * m + b];

			*x = -1;
			if ((G(a, b) < 0) != (G(a, b + 1) < 0) &&
			    !((a == 0 && in[LOFT_U0]) || (a == m && in[LOFT_U1]))) {
				bracket_root(c, 1, (double)a / m, (double)b / m,
				    (double)(b + 1) / m, G(a, b), &gr->r[gr->nr]);
				*x = (long)gr->nr++;
			}
		}
}

/* The roots on each cell's sides (bottom, right, top, left) linked in
 * pairs; a cell of four by the sign at its centre. */
static void
grid_links(const struct ctx *c, struct grid *gr)
{
	int m = gr->m;
	struct root *r = gr->r;

	for (int a = 0; a < m; a++)
		for (int b = 0; b < m; b++) {
			long e[4] = { gr->hx[(size_t)b * m + a],
			    gr->vx[(size_t)(a + 1) * m + b],
			    gr->hx[(size_t)(b + 1) * m + a],
			    gr->vx[(size_t)a * m + b] };
			long got[4];
			int k = 0;

			for (int i = 0; i < 4; i++)
				if (e[i] >= 0)
					got[k++] = e[i];
			if (k == 2) {
				link_roots(r, got[0], got[1]);
			} else if (k == 4) {
				double gc = gval(c, (a + 0.5) / m, (b + 0.5) / m,
				    NULL, NULL, NULL);

				if ((gc < 0) == (G(a, b) < 0)) {
					link_roots(r, e[0], e[1]);
					link_roots(r, e[2], e[3]);
				} else {
					link_roots(r, e[3], e[0]);
					link_roots(r, e[1], e[2]);
				}
			}
		}
}
#undef G

/* The linked roots into pieces of ps: open pieces from their ends,
 * then loops.  0 or LOFT_ENOMEM. */
static int
grid_walk(const struct ctx *c, struct grid *gr, struct pieces *ps)
{
	char *seen = calloc(gr->nr + 1, 1);
	int rc = 0;

	if (seen == NULL)
		return LOFT_ENOMEM;
	for (int pass = 1; pass <= 2 && rc == 0; pass++)
		for (size_t i = 0; i < gr->nr && rc == 0; i++) {
			struct piece *pc;

			if (seen[i] || gr->r[i].deg != pass)
				continue;
			if ((pc = new_piece(ps)) == NULL)
				rc = LOFT_ENOMEM;
			else
				rc = walk(c, gr->r, seen, (long)i, pc);
		}
	free(seen);
	return rc;
}

/* The cut of one surface, its box lo..hi, into ps: its edges in the
 * plane, then the rest by marching over a grid of its parameters. */
static int
cut_surface(const struct ctx *c, const double *lo, const double *hi,
    struct pieces *ps)
{
	int m = 2 * (c->s->m > c->s->n ? c->s->m : c->s->n), in[4] = { 0 };
	int rc, ne = 0;
	struct grid gr = { 0 };
	size_t cap;

	m = m < GRID_MIN ? GRID_MIN : m > GRID_MAX ? GRID_MAX : m;
	if ((rc = plane_edges(c, lo, hi, in, &ne, ps)) != 0 || ne == 4)
		return rc;
	cap = (size_t)2 * m * (m + 1);
	gr.m = m;
	gr.g = malloc((size_t)(m + 1) * (m + 1) * sizeof *gr.g);
	gr.hx = malloc(cap / 2 * sizeof *gr.hx);
	gr.vx = malloc(cap / 2 * sizeof *gr.vx);
	gr.r = malloc(cap * sizeof *gr.r);
	if (gr.g == NULL || gr.hx == NULL || gr.vx == NULL || gr.r == NULL) {
		rc = LOFT_ENOMEM;
	} else {
		grid_values(c, &gr, in);
		grid_roots(c, &gr, in);
		grid_links(c, &gr);
		rc = grid_walk(c, &gr, ps);
	}
	free(gr.g);
	free(gr.hx);
	free(gr.vx);
	free(gr.r);
	return rc;
}

int
loft_cutter_init(struct loft_cutter *k, const struct loft_surface *s,
    size_t ns, struct loft_error *err)
{
	int dim = ns > 0 ? s[0].dim : 2;
	double lo[LOFT_MAXDIM], hi[LOFT_MAXDIM];

	memset(k, 0, sizeof *k);
	k->s = s;
	k->ns = ns;
	k->dim = dim;
	if (ns > 0 && (k->box = malloc(ns * 2 * dim * sizeof *k->box)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < ns; i++) {
		double *b = k->box + i * 2 * dim;

		loft_surface_box(&s[i], b, b + dim);
		for (int c = 0; c < dim; c++) {
			if (i == 0 || b[c] < lo[c])
				lo[c] = b[c];
			if (i == 0 || b[dim + c] > hi[c])
				hi[c] = b[dim + c];
		}
	}
	if (ns > 0)
		k->size = vdist(lo, hi, dim);
	return 0;
}

void
loft_cutter_free(struct loft_cutter *k)
{
	free(k->box);
	memset(k, 0, sizeof *k);
}

/* Endpoints to join: piece i's end e (0 start, 1 end), its point. */
struct end {
	size_t i;
	int e;
	const double *p;
	long mate;
};

static int
end_cmp(const void *a, const void *b)
{
	const struct end *x = a, *y = b;

	if (x->p[0] != y->p[0])
		return x->p[0] < y->p[0] ? -1 : 1;
	if (x->i != y->i)
		return x->i < y->i ? -1 : 1;
	return x->e - y->e;
}

static const double *
end_point(const struct piece *pc, int e, int dim)
{
	return pc->p + (e ? pc->n - 1 : 0) * dim;
}

/* Edge pieces by the smaller first coordinate of their two ends. */
struct key {
	double x;
	size_t i;
};

static int
key_cmp(const void *a, const void *b)
{
	const struct key *x = a, *y = b;

	if (x->x != y->x)
		return x->x < y->x ? -1 : 1;
	return (x->i > y->i) - (x->i < y->i);
}

/* Whether edge pieces a and b are one: the same ends, either way, and
 * the same point half way. */
static int
same_edge(const struct piece *a, const struct piece *b, int dim, double jt)
{
	int same = vdist(end_point(a, 0, dim), end_point(b, 0, dim), dim) <= jt &&
	    vdist(end_point(a, 1, dim), end_point(b, 1, dim), dim) <= jt;
	int rev = vdist(end_point(a, 0, dim), end_point(b, 1, dim), dim) <= jt &&
	    vdist(end_point(a, 1, dim), end_point(b, 0, dim), dim) <= jt;

	return (same || rev) && vdist(a->p + a->n / 2 * dim, b->p +
	    (same ? b->n / 2 : b->n - 1 - b->n / 2) * dim, dim) <=
	    1e-6 * vdist(end_point(a, 0, dim), end_point(a, 1, dim), dim) + jt;
}

/* Drop each edge piece that another edge piece repeats (the edge
 * shared by two surfaces, both in the plane); sorted, so only pieces
 * whose ends begin alike are compared. */
static int
drop_repeats(struct pieces *ps, int dim, double jt)
{
	struct key *k;
	size_t n = 0;

	if ((k = malloc((ps->n + 1) * sizeof *k)) == NULL)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < ps->n; i++)
		if (ps->v[i].edge && ps->v[i].n > 0)
			k[n++] = (struct key){ fmin(end_point(&ps->v[i], 0, dim)[0],
			    end_point(&ps->v[i], 1, dim)[0]), i };
	qsort(k, n, sizeof *k, key_cmp);
	for (size_t a = 0; a < n; a++) {
		struct piece *pa = &ps->v[k[a].i];

		for (size_t b = a + 1; b < n && k[b].x - k[a].x <= jt &&
		    pa->n > 0; b++) {
			struct piece *pb = &ps->v[k[b].i];

			if (pb->n > 0 && same_edge(pa, pb, dim, jt))
				pb->n = 0;
		}
	}
	free(k);
	return 0;
}

/* Append piece pc to curve out, from its end e, skipping its first
 * point (the join) unless first, and points within jt of the last. */
static int
append(struct loft_cut_curve *out, const struct piece *pc, int e, int first,
    int dim, double jt)
{
	for (size_t k = first ? 0 : 1; k < pc->n; k++) {
		const double *p = pc->p + (e ? pc->n - 1 - k : k) * dim;
		double *q;

		if (out->n > 0 && vdist(p, out->p + (out->n - 1) * dim, dim) <=
		    jt)
			continue;
		if ((q = realloc(out->p, (out->n + 1) * dim * sizeof *q)) == NULL)
			return LOFT_ENOMEM;
		out->p = q;
		vcopy(q + out->n * dim, p, dim);
		out->n++;
	}
	return 0;
}

/* The ends of the open pieces of ps into e, sorted by x, each mated
 * with the first end after it within jt that has no mate yet (not the
 * other end of a piece of fewer than three points); pieces of fewer
 * than two points are marked used.  Returns the count of ends. */
static size_t
mate_ends(struct pieces *ps, int dim, double jt, struct end *e, char *used)
{
	size_t ne = 0;

	for (size_t i = 0; i < ps->n; i++) {
		if (ps->v[i].n < 2) {
			used[i] = 1;
			continue;
		}
		for (int k = 0; k < 2 && !ps->v[i].closed; k++)
			e[ne++] = (struct end){ i, k, end_point(&ps->v[i], k, dim),
			    -1 };
	}
	qsort(e, ne, sizeof *e, end_cmp);
	for (size_t a = 0; a < ne; a++)
		for (size_t b = a + 1; b < ne && e[a].mate < 0 &&
		    e[b].p[0] - e[a].p[0] <= jt; b++)
			if (e[b].mate < 0 && !(e[b].i == e[a].i &&
			    ps->v[e[a].i].n < 3) && vdist(e[a].p, e[b].p, dim) <= jt) {
				e[a].mate = (long)b;
				e[b].mate = (long)a;
			}
	return ne;
}

/* Curve cv from piece i, entered at its end from, then on through the
 * mates of its far ends while they lead to unused pieces; on pass 1 a
 * chain back to piece i closes cv as a ring.  0 or LOFT_ENOMEM. */
static int
chain(struct pieces *ps, const struct end *e, const long *where, char *used,
    size_t i, int from, int pass, struct loft_cut_curve *cv, int dim,
    double jt)
{
	size_t at = i;
	int rc = 0;

	for (int first = 1; rc == 0; first = 0) {
		long m;

		used[at] = 1;
		rc = append(cv, &ps->v[at], from, first, dim, jt);
		m = e[where[2 * at + !from]].mate;
		if (m < 0)
			break;
		if (e[m].i == i && pass == 1) {
			cv->closed = 1;
			break;
		}
		if (used[e[m].i])
			break;
		at = e[m].i;
		from = e[m].e;
	}
	if (cv->closed && cv->n > 1 && vdist(cv->p, cv->p +
	    (cv->n - 1) * dim, dim) <= jt)
		cv->n--;
	return rc;
}

/* Join the pieces ps into out's curves. */
static int
join(struct pieces *ps, int dim, double jt, struct loft_cut *out)
{
	size_t ne = 0;
	struct end *e;
	long *where;
	char *used;
	int rc = 0;

	if (drop_repeats(ps, dim, jt) != 0)
		return LOFT_ENOMEM;
	e = malloc((2 * ps->n + 1) * sizeof *e);
	where = calloc(2 * ps->n + 1, sizeof *where);   /* each end set below */
	used = calloc(ps->n + 1, 1);
	if (e == NULL || where == NULL || used == NULL) {
		rc = LOFT_ENOMEM;
		goto out;
	}
	ne = mate_ends(ps, dim, jt, e, used);
	for (size_t a = 0; a < ne; a++)
		where[2 * e[a].i + e[a].e] = (long)a;
	/* open curves from a free end, then rings, then closed pieces */
	for (int pass = 0; pass < 3 && rc == 0; pass++)
		for (size_t i = 0; i < ps->n && rc == 0; i++) {
			struct loft_cut_curve *cv;
			int from = 0;

			if (used[i] || (pass == 2) != (ps->v[i].closed != 0))
				continue;
			if (pass == 0) {
				if (e[where[2 * i]].mate >= 0 &&
				    e[where[2 * i + 1]].mate >= 0)
					continue;
				from = e[where[2 * i]].mate >= 0;
			}
			if (loft__grow((void **)&out->c, &out->cap, out->n + 1,
			    sizeof *out->c) != 0) {
				rc = LOFT_ENOMEM;
				break;
			}
			cv = &out->c[out->n++];
			memset(cv, 0, sizeof *cv);
			if (pass == 2) {
				used[i] = 1;
				cv->closed = 1;
				rc = append(cv, &ps->v[i], 0, 1, dim, jt);
				continue;
			}
			rc = chain(ps, e, where, used, i, from, pass, cv, dim, jt);
		}
out:
	free(e);
	free(where);
	free(used);
	return rc;
}

int
loft_cut_plane(const struct loft_cutter *k, const double *normal, double d,
    double tol, struct loft_cut *out, struct loft_error *err)
{
	struct pieces ps = { 0 };
	struct ctx c;
	double n[LOFT_MAXDIM], len;
	int dim = k->dim, rc = 0, hit = 0;
	size_t first = out->n;

	vcopy(n, normal, dim);
	len = vunit(n, dim);
	if (!(len > 0))
		return loft_fail(err, LOFT_EINPUT, -1, "the plane's normal has "
		    "no part in the surfaces' %d coordinates", dim);
	c.n = n;
	c.d = d / len;
	c.tol = fmax(tol, TOL_MIN_REL * k->size);
	c.dim = dim;
	out->dim = dim;
	for (size_t i = 0; i < k->ns && rc == 0; i++) {
		const double *b = k->box + i * 2 * dim;
		double glo = 0, ghi = 0;

		/* the plane against the box: n.x over it from glo to ghi */
		for (int q = 0; q < dim; q++) {
			glo += n[q] * (n[q] > 0 ? b[q] : b[dim + q]);
			ghi += n[q] * (n[q] > 0 ? b[dim + q] : b[q]);
		}
		if (c.d < glo - JOIN_REL * k->size || c.d > ghi + JOIN_REL * k->size)
			continue;
		c.s = &k->s[i];
		rc = cut_surface(&c, b, b + dim, &ps);
	}
	if (rc == 0)
		rc = join(&ps, dim, JOIN_REL * k->size, out);
	for (size_t i = 0; i < ps.n; i++)
		free(ps.v[i].p);
	free(ps.v);
	if (rc != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = first; i < out->n; i++)
		hit |= out->c[i].n >= 2;
	if (!hit)
		return loft_fail(err, LOFT_EGEOM, -1, "the plane misses");
	return 0;
}

void
loft_cut_free(struct loft_cut *c)
{
	for (size_t i = 0; i < c->n; i++)
		free(c->c[i].p);
	free(c->c);
	memset(c, 0, sizeof *c);
}
