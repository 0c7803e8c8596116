/*
 * grid.c: a uniform grid of the plane for finding what lies near a box
 * or along a segment without looking at everything, and the segment
 * tests that go with it (issue 22: loftplot's label placement files its
 * lines and labels here, and fair.c's loft_fit_crosses its curve's edges).
 *
 * An item (a box, or a segment filed by the cells it passes through)
 * is an entry in each cell it covers; a cell's entries are a chain in
 * a hash table of (column, row), so an empty region costs nothing and
 * a query looks at the few cells of its box.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "loft.h"

/* The hash of cell (cx, cy) into nbucket (a power of two) chains. */
static size_t
bucket(const struct loft_grid *g, long cx, long cy)
{
	unsigned long h = (unsigned long)cx * 2654435761UL ^
	    (unsigned long)cy * 40503UL;

	return (size_t)(h ^ h >> 15) & (g->nbucket - 1);
}

int
loft_grid_init(struct loft_grid *g, double cw, double ch, const double *origin,
    size_t n)
{
	g->cw = cw;
	g->ch = ch;
	g->x0 = origin[0];
	g->y0 = origin[1];
	g->e = NULL;
	g->ne = g->ecap = 0;
	for (g->nbucket = 64; g->nbucket < 2 * n && g->nbucket < SIZE_MAX / 4;
	    g->nbucket *= 2)
		;
	if ((g->head = malloc(g->nbucket * sizeof *g->head)) == NULL)
		return LOFT_ENOMEM;
	for (size_t h = 0; h < g->nbucket; h++)
		g->head[h] = (size_t)-1;
	return 0;
}

void
loft_grid_free(struct loft_grid *g)
{
	free(g->head);
	free(g->e);
	g->head = NULL;
	g->e = NULL;
	g->ne = g->ecap = 0;
}

/* The cell range [c0, c1] of the interval lo..hi along axis k. */
static void
cells(const struct loft_grid *g, double lo, double hi, int k, long *c0,
    long *c1)
{
	double o = k ? g->y0 : g->x0, w = k ? g->ch : g->cw;

	*c0 = (long)floor((lo - o) / w);
	*c1 = (long)floor((hi - o) / w);
}

int
loft_grid_add(struct loft_grid *g, const double *lo, const double *hi,
    size_t id)
{
	long x0, x1, y0, y1;

	cells(g, lo[0], hi[0], 0, &x0, &x1);
	cells(g, lo[1], hi[1], 1, &y0, &y1);
	for (long cx = x0; cx <= x1; cx++)
		for (long cy = y0; cy <= y1; cy++) {
			size_t h = bucket(g, cx, cy);

			if (g->ne == g->ecap) {
				size_t cap = g->ecap ? 2 * g->ecap : 256;
				void *v = cap < SIZE_MAX / sizeof *g->e ?
				    realloc(g->e, cap * sizeof *g->e) : NULL;

				if (v == NULL)
					return LOFT_ENOMEM;
				g->e = v;
				g->ecap = cap;
			}
			g->e[g->ne] = (struct loft_grid_entry){ cx, cy, id,
			    g->head[h] };
			g->head[h] = g->ne++;
		}
	return 0;
}

int
loft_grid_each(const struct loft_grid *g, const double *lo, const double *hi,
    int (*visit)(void *ctx, size_t id), void *ctx)
{
	long x0, x1, y0, y1;
	int rc;

	cells(g, lo[0], hi[0], 0, &x0, &x1);
	cells(g, lo[1], hi[1], 1, &y0, &y1);
	for (long cx = x0; cx <= x1; cx++)
		for (long cy = y0; cy <= y1; cy++)
			for (size_t k = g->head[bucket(g, cx, cy)];
			    k != (size_t)-1; k = g->e[k].next)
				if (g->e[k].cx == cx && g->e[k].cy == cy &&
				    (rc = visit(ctx, g->e[k].id)) != 0)
					return rc;
	return 0;
}

/* A segment sg (x0 y0 x1 y1) is taken in n pieces no longer than a
 * cell (pieces), each by its box (piece_box): the cells of those boxes
 * are the cells it passes through. */
static size_t
pieces(const struct loft_grid *g, const double *sg)
{
	double len = fmax(fabs(sg[2] - sg[0]) / g->cw,
	    fabs(sg[3] - sg[1]) / g->ch);

	return len < 1 ? 1 : (size_t)ceil(len);
}

static void
piece_box(const double *sg, size_t i, size_t n, double *lo, double *hi)
{
	for (int k = 0; k < 2; k++) {
		double a = sg[k] + (double)i / (double)n * (sg[2 + k] - sg[k]);
		double b = sg[k] + (double)(i + 1) / (double)n *
		    (sg[2 + k] - sg[k]);

		lo[k] = fmin(a, b);
		hi[k] = fmax(a, b);
	}
}

int
loft_grid_add_segment(struct loft_grid *g, const double *sg, size_t id)
{
	size_t n = pieces(g, sg);
	double lo[2], hi[2];
	int rc;

	for (size_t i = 0; i < n; i++) {
		piece_box(sg, i, n, lo, hi);
		if ((rc = loft_grid_add(g, lo, hi, id)) != 0)
			return rc;
	}
	return 0;
}

int
loft_grid_each_along(const struct loft_grid *g, const double *sg,
    int (*visit)(void *ctx, size_t id), void *ctx)
{
	size_t n = pieces(g, sg);
	double lo[2], hi[2];
	int rc;

	for (size_t i = 0; i < n; i++) {
		piece_box(sg, i, n, lo, hi);
		if ((rc = loft_grid_each(g, lo, hi, visit, ctx)) != 0)
			return rc;
	}
	return 0;
}

/* The sign of the turn a -> b -> c: 1 left, -1 right, 0 in line. */
static int
turn(const double *a, const double *b, const double *c)
{
	double t = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

	return (t > 0) - (t < 0);
}

int
loft_segments_cross(const double *s, const double *t)
{
	return turn(s, s + 2, t) * turn(s, s + 2, t + 2) < 0 &&
	    turn(t, t + 2, s) * turn(t, t + 2, s + 2) < 0;
}

int
loft_fold_crosses(const double *a, const double *b, size_t n)
{
	/* edge i of a polyline is its 4 numbers from point i on */
	for (size_t i = 0; i + 1 < n; i++)
		for (size_t j = i == 0; j + 1 < n; j++)
			if (loft_segments_cross(a + 2 * i, b + 2 * j))
				return 1;
	return 0;
}

double
loft_fold_u(size_t t, size_t m, double reach)
{
	double step = reach / (double)m;

	if (t == 0)
		return 0;
	if (t <= LOFT_FOLD_FINE)
		return ldexp(step, (int)t - 1 - LOFT_FOLD_FINE);
	return (double)(t - LOFT_FOLD_FINE) * step;
}

int
loft_sides_cross(void (*eval)(const void *ctx, size_t s, double u,
    double *p), const void *ctx, size_t pj, size_t j, double reach)
{
	enum { N = LOFT_FOLD_FINE + LOFT_FOLD_STEPS + 1 };
	double a[2 * N], b[2 * N];

	for (size_t t = 0; t < N; t++) {
		double u = loft_fold_u(t, LOFT_FOLD_STEPS, reach);

		eval(ctx, pj, 1 - u, a + 2 * t);
		eval(ctx, j, u, b + 2 * t);
	}
	return loft_fold_crosses(a, b, N);
}

/* Liang and Barsky's clipping: the part of the segment inside each
 * slab of the box, intersected. */
int
loft_segment_meets_box(const double *sg, const double *lo, const double *hi)
{
	double t0 = 0, t1 = 1;

	for (int k = 0; k < 2; k++) {
		double a = sg[k], d = sg[2 + k] - a, l, h;

		if (d == 0) {
			if (a < lo[k] || a > hi[k])
				return 0;
			continue;
		}
		l = (lo[k] - a) / d;
		h = (hi[k] - a) / d;
		if (l > h) {
			double t = l;

			l = h;
			h = t;
		}
		t0 = fmax(t0, l);
		t1 = fmin(t1, h);
		if (t0 > t1)
			return 0;
	}
	return 1;
}
