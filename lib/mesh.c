/*
 * mesh.c: surfaces into one triangle mesh (loft.h's struct loft_mesh):
 * each patch on a grid of N x N cells, T-junctions of a design's links
 * closed by fans, vertices of shared edges welded, the triangles
 * oriented one way, and the adjacency of their sides.  Moved here from
 * cad.c so that tocad, sample and unroll mesh alike.  Core.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Most mesh steps along a patch side: 256^2 cells a patch. */
#define MAX_STEPS 256

/* Edge parameters nearer than this are one place (loft.5's links). */
#define EDGE_TOL 1e-9

/*
 * The steps along each side of the Bezier patch (m, n, ctl) for a mesh
 * within tol: linear interpolation over cells of h = 1/N errs by at most
 * h^2 (M_uu + 2 M_uv + M_vv) / 8, M the bounds of the second derivatives
 * that the net's second differences give (times m (m - 1), m n, n (n - 1)).
 */
long
loft_mesh_steps(const double *ctl, int m, int n, double tol)
{
	double muu = 0, muv = 0, mvv = 0, t;
	const double *p = ctl;

#define P(i, j) (p + 3 * ((size_t)(i) * (n + 1) + (j)))
	for (int i = 0; i <= m; i++)
		for (int j = 0; j <= n; j++) {
			double a[3];

			if (i + 2 <= m) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i + 2, j)[k] -
					    2 * P(i + 1, j)[k] + P(i, j)[k];
				if ((t = m * (m - 1) * vnorm(a, 3)) > muu)
					muu = t;
			}
			if (j + 2 <= n) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i, j + 2)[k] -
					    2 * P(i, j + 1)[k] + P(i, j)[k];
				if ((t = n * (n - 1) * vnorm(a, 3)) > mvv)
					mvv = t;
			}
			if (i + 1 <= m && j + 1 <= n) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i + 1, j + 1)[k] -
					    P(i + 1, j)[k] - P(i, j + 1)[k] +
					    P(i, j)[k];
				if ((t = m * n * vnorm(a, 3)) > muv)
					muv = t;
			}
		}
#undef P
	t = ceil(sqrt((muu + 2 * muv + mvv) / (8 * tol)));
	return !(t >= 1) ? 1 : t > MAX_STEPS ? MAX_STEPS : (long)t;
}

/* The points of an edge beyond its N steps: parameters, sorted. */
struct extra {
	double *t;
	size_t n, cap;
};

static int
by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

/*
 * The extra points of edge e of design patch ip: the steps k/N of each
 * neighbour across it that fall between this edge's own steps (a
 * T-junction: the neighbour covers part of the edge), mapped into this
 * edge's parameter by the two links; sorted, each once.
 */
static int
edge_extras(const struct loft_design *dz, size_t ip, int e, long N,
    struct extra *x)
{
	const struct loft_patch *p = &dz->p[ip];

	x->n = 0;
	for (size_t l = 0; l < p->nlink[e]; l++) {
		const struct loft_link *L = &p->link[e][l];
		long iq = loft_design_find(dz, L->id);
		const struct loft_link *B = NULL;

		if (iq < 0)
			continue;
		for (int f = 0; f < 4 && B == NULL; f++)
			for (size_t k = 0; k < dz->p[iq].nlink[f]; k++)
				if (dz->p[iq].link[f][k].id == p->id)
					B = &dz->p[iq].link[f][k];
		if (B == NULL || fabs(B->b - B->a) < EDGE_TOL)
			continue;
		for (long k = 0; k <= N; k++) {
			double s = (double)k / N, lo = fmin(B->a, B->b);
			double hi = fmax(B->a, B->b), t, r;

			if (s < lo - EDGE_TOL || s > hi + EDGE_TOL)
				continue;
			t = L->a + (s - B->a) * (L->b - L->a) / (B->b - B->a);
			r = t * N - floor(t * N + 0.5);
			if (t <= EDGE_TOL || t >= 1 - EDGE_TOL ||
			    fabs(r) <= EDGE_TOL * N)
				continue;       /* one of this edge's own steps */
			if (loft__grow((void **)&x->t, &x->cap, x->n + 1,
			    sizeof *x->t) != 0)
				return LOFT_ENOMEM;
			x->t[x->n++] = t;
		}
	}
	if (x->n > 1)
		qsort(x->t, x->n, sizeof *x->t, by_value);
	return 0;
}

/* The patch being meshed: its surface and its index among the patches. */
struct at {
	const struct loft_surface *s;
	size_t ip;
};

static int
add_vertex(struct loft_mesh *me, const struct at *s, double u, double v,
    size_t *at)
{
	double p[LOFT_MAXDIM] = { 0, 0, 0 };

	if (loft__grow((void **)&me->v, &me->vcap, 3 * (me->nv + 1),
	    sizeof *me->v) != 0 ||
	    loft__grow((void **)&me->uv, &me->uvcap, 2 * (me->nv + 1),
	    sizeof *me->uv) != 0 ||
	    loft__grow((void **)&me->patch, &me->pcap, me->nv + 1,
	    sizeof *me->patch) != 0)
		return LOFT_ENOMEM;
	loft_surface_eval(s->s, u, v, p, NULL, NULL);
	vcopy(me->v + 3 * me->nv, p, 3);
	me->uv[2 * me->nv] = u;
	me->uv[2 * me->nv + 1] = v;
	me->patch[me->nv] = s->ip;
	*at = me->nv++;
	return 0;
}

static int
add_triangle(struct loft_mesh *me, size_t a, size_t b, size_t c)
{
	if (loft__grow((void **)&me->t, &me->tcap, 3 * (me->nt + 1),
	    sizeof *me->t) != 0)
		return LOFT_ENOMEM;
	me->t[3 * me->nt] = a;
	me->t[3 * me->nt + 1] = b;
	me->t[3 * me->nt + 2] = c;
	me->nt++;
	return 0;
}

/* The extras of x strictly between lo and hi, from lo's end: "rev" from hi's. */
static int
side(struct loft_mesh *me, const struct at *s, const struct extra *x,
    double lo, double hi, int rev, int dir, double fixed, size_t *poly,
    size_t *np)
{
	for (size_t k = 0; k < x->n; k++) {
		double t = x->t[rev ? x->n - 1 - k : k];
		int rc;

		if (t <= lo || t >= hi)
			continue;
		rc = dir == 0 ? add_vertex(me, s, t, fixed, &poly[*np]) :
		    add_vertex(me, s, fixed, t, &poly[*np]);
		if (rc != 0)
			return rc;
		++*np;
	}
	return 0;
}

/* A cell's corners and extra points counter-clockwise, a fan around its
 * centre: v = v0, u = u1, v = v1, u = u0. */
static int
fan_cell(struct loft_mesh *me, const struct at *s, const struct extra *x,
    size_t base, size_t i, size_t j, size_t w, size_t *poly)
{
	size_t a = base + i * w + j, b = a + w, np = 0, c;
	long N = (long)w - 1;
	double u0 = (double)i / N, u1 = (double)(i + 1) / N;
	double v0 = (double)j / N, v1 = (double)(j + 1) / N;
	int rc = 0;

	poly[np++] = a;
	if (j == 0)
		rc = side(me, s, &x[LOFT_V0], u0, u1, 0, 0, 0, poly, &np);
	poly[np++] = b;
	if (rc == 0 && i + 2 == w)
		rc = side(me, s, &x[LOFT_U1], v0, v1, 0, 1, 1, poly, &np);
	poly[np++] = b + 1;
	if (rc == 0 && j + 2 == w)
		rc = side(me, s, &x[LOFT_V1], u0, u1, 1, 0, 1, poly, &np);
	poly[np++] = a + 1;
	if (rc == 0 && i == 0)
		rc = side(me, s, &x[LOFT_U0], v0, v1, 1, 1, 0, poly, &np);
	if (rc == 0)
		rc = add_vertex(me, s, (u0 + u1) / 2, (v0 + v1) / 2, &c);
	for (size_t k = 0; rc == 0 && k < np; k++)
		rc = add_triangle(me, c, poly[k], poly[(k + 1) % np]);
	return rc;
}

/*
 * Patch s on an N x N grid: two triangles a cell, counter-clockwise in
 * (u, v); a cell with extra points on its sides (x[edge], by enum
 * loft_edge) a fan around its centre through all its points.
 */
static int
mesh_patch(struct loft_mesh *me, const struct at *s, long N,
    const struct extra *x)
{
	size_t w = (size_t)N + 1, at, base = me->nv;
	size_t *poly = NULL;
	int rc = 0;

	for (size_t i = 0; rc == 0 && i < w; i++)
		for (size_t j = 0; rc == 0 && j < w; j++)
			rc = add_vertex(me, s, (double)i / N, (double)j / N, &at);
	for (size_t i = 0; rc == 0 && i + 1 < w; i++)
		for (size_t j = 0; rc == 0 && j + 1 < w; j++) {
			size_t a = base + i * w + j, b = a + w;
			size_t cap = 4 + (j == 0 ? x[LOFT_V0].n : 0) +
			    (i + 2 == w ? x[LOFT_U1].n : 0) +
			    (j + 2 == w ? x[LOFT_V1].n : 0) +
			    (i == 0 ? x[LOFT_U0].n : 0);

			if (cap == 4) {
				rc = add_triangle(me, a, b, b + 1) ||
				    add_triangle(me, a, b + 1, a + 1);
				continue;
			}
			free(poly);
			if ((poly = malloc(cap * sizeof *poly)) == NULL)
				return LOFT_ENOMEM;
			rc = fan_cell(me, s, x, base, i, j, w, poly);
		}
	free(poly);
	return rc ? LOFT_ENOMEM : 0;
}

static const double *weld_v;

static int
by_x(const void *a, const void *b)
{
	double xa = weld_v[3 * *(const size_t *)a];
	double xb = weld_v[3 * *(const size_t *)b];

	return xa < xb ? -1 : xa > xb;
}

/* Keep the vertices with to[i] == i, renumbered densely in their order
 * (ord gets the new numbers), and the triangles that keep three. */
static void
renumber(struct loft_mesh *me, const size_t *to, size_t *ord)
{
	size_t nv = 0, nt = 0;

	for (size_t i = 0; i < me->nv; i++)
		if (to[i] == i) {
			vcopy(me->v + 3 * nv, me->v + 3 * i, 3);
			me->uv[2 * nv] = me->uv[2 * i];
			me->uv[2 * nv + 1] = me->uv[2 * i + 1];
			me->patch[nv] = me->patch[i];
			ord[i] = nv++;
		}
	for (size_t k = 0; k < me->nt; k++) {
		size_t a = ord[to[me->t[3 * k]]], b = ord[to[me->t[3 * k + 1]]];
		size_t c = ord[to[me->t[3 * k + 2]]];

		if (a == b || b == c || a == c)
			continue;
		me->t[3 * nt] = a;
		me->t[3 * nt + 1] = b;
		me->t[3 * nt + 2] = c;
		nt++;
	}
	me->nv = nv;
	me->nt = nt;
}

/*
 * Weld: vertices within tol are one (the first of them by x), triangles
 * that lose a side to it dropped, the vertices renumbered densely.
 */
int
loft_mesh_weld(struct loft_mesh *me, double tol, size_t *map)
{
	size_t *ord = malloc((me->nv + 1) * sizeof *ord);
	size_t *to = malloc((me->nv + 1) * sizeof *to), nv = me->nv;

	if (ord == NULL || to == NULL) {
		free(ord);
		free(to);
		return LOFT_ENOMEM;
	}
	for (size_t i = 0; i < me->nv; i++) {
		ord[i] = i;
		to[i] = (size_t)-1;
	}
	weld_v = me->v;
	qsort(ord, me->nv, sizeof *ord, by_x);
	for (size_t a = 0; a < me->nv; a++) {
		size_t i = ord[a];

		if (to[i] != (size_t)-1)
			continue;
		to[i] = i;
		for (size_t b = a + 1; b < me->nv &&
		    me->v[3 * ord[b]] - me->v[3 * i] <= tol; b++)
			if (to[ord[b]] == (size_t)-1 &&
			    vdist(me->v + 3 * ord[b], me->v + 3 * i, 3) <= tol)
				to[ord[b]] = i;
	}
	renumber(me, to, ord);
	for (size_t i = 0; map != NULL && i < nv; i++)
		map[i] = ord[to[i]];
	free(ord);
	free(to);
	return 0;
}

/* A triangle's side: its ends (lower first), the triangle, its sense. */
struct side {
	size_t a, b, t;
	int k;                  /* which side of t */
	int up;                 /* the triangle runs from a to b */
};

static int
by_ends(const void *x, const void *y)
{
	const struct side *p = x, *q = y;

	if (p->a != q->a)
		return p->a < q->a ? -1 : 1;
	return p->b < q->b ? -1 : p->b > q->b;
}

int
loft_mesh_neighbours(const struct loft_mesh *me, size_t *nb,
    unsigned char *same)
{
	size_t ns = 3 * me->nt;
	struct side *s = malloc((ns + 1) * sizeof *s);

	if (s == NULL)
		return LOFT_ENOMEM;
	for (size_t t = 0; t < me->nt; t++)
		for (int k = 0; k < 3; k++) {
			size_t a = me->t[3 * t + k], b = me->t[3 * t + (k + 1) % 3];
			struct side *e = &s[3 * t + k];

			e->a = a < b ? a : b;
			e->b = a < b ? b : a;
			e->t = t;
			e->k = k;
			e->up = a < b;
			nb[3 * t + k] = (size_t)-1;
		}
	qsort(s, ns, sizeof *s, by_ends);
	/* a side of exactly two triangles links them */
	for (size_t i = 0; i + 1 < ns; i++) {
		size_t j = i + 1;

		if (by_ends(&s[i], &s[j]) != 0 || (j + 1 < ns &&
		    by_ends(&s[j], &s[j + 1]) == 0))
			continue;
		nb[3 * s[i].t + s[i].k] = s[j].t;
		nb[3 * s[j].t + s[j].k] = s[i].t;
		if (same != NULL)
			same[3 * s[i].t + s[i].k] = same[3 * s[j].t + s[j].k] =
			    s[i].up == s[j].up;
		i = j;
	}
	free(s);
	return 0;
}

/*
 * Orient the welded mesh consistently: across each side two triangles
 * share, they must run it opposite ways.  Each connected piece keeps the
 * orientation of its first triangle (its first patch's f_u x f_v) and the
 * rest follow by a breadth-first walk; a piece that cannot be oriented
 * (a Moebius band) keeps what the walk gave it.
 */
static int
orient(struct loft_mesh *me)
{
	size_t ns = 3 * me->nt, head = 0, tail = 0;
	size_t *nb = malloc((ns + 1) * sizeof *nb);
	size_t *queue = malloc((me->nt + 1) * sizeof *queue);
	unsigned char *same = malloc(ns + 1), *flip = calloc(me->nt + 1, 1);
	unsigned char *seen = calloc(me->nt + 1, 1);
	int rc = LOFT_ENOMEM;

	if (nb == NULL || queue == NULL || same == NULL || flip == NULL ||
	    seen == NULL || loft_mesh_neighbours(me, nb, same) != 0)
		goto out;
	for (size_t t0 = 0; t0 < me->nt; t0++) {
		if (seen[t0])
			continue;
		seen[t0] = 1;
		queue[tail++] = t0;
		while (head < tail) {
			size_t t = queue[head++];

			for (size_t k = 3 * t; k < 3 * t + 3; k++) {
				size_t n = nb[k];

				if (n == (size_t)-1 || seen[n])
					continue;
				seen[n] = 1;
				flip[n] = flip[t] ^ same[k];
				queue[tail++] = n;
			}
		}
	}
	for (size_t t = 0; t < me->nt; t++)
		if (flip[t]) {
			size_t x = me->t[3 * t + 1];

			me->t[3 * t + 1] = me->t[3 * t + 2];
			me->t[3 * t + 2] = x;
		}
	rc = 0;
out:
	free(nb);
	free(queue);
	free(same);
	free(flip);
	free(seen);
	return rc;
}

int
loft_mesh_surfaces(struct loft_mesh *me, const struct loft_surface *s,
    size_t ns, const long *ip, const struct loft_design *dz, long N,
    double weld_tol)
{
	struct extra x[4];
	int rc = 0;

	memset(x, 0, sizeof x);
	if (N < 1)
		N = 1;
	for (size_t i = 0; rc == 0 && i < ns; i++) {
		struct at a = { &s[i], i };

		for (int e = 0; e < 4; e++) {
			x[e].n = 0;
			if (rc == 0 && dz != NULL && ip != NULL && ip[i] >= 0)
				rc = edge_extras(dz, (size_t)ip[i], e, N, &x[e]);
		}
		if (rc == 0)
			rc = mesh_patch(me, &a, N, x);
	}
	for (int e = 0; e < 4; e++)
		free(x[e].t);
	if (rc == 0 && weld_tol >= 0)
		rc = loft_mesh_weld(me, weld_tol, NULL);
	if (rc == 0 && weld_tol >= 0)
		rc = orient(me);
	return rc;
}

void
loft_mesh_free(struct loft_mesh *me)
{
	free(me->v);
	free(me->t);
	free(me->uv);
	free(me->patch);
	memset(me, 0, sizeof *me);
}
