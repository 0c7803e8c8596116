/*
 * sparse.c: unit tests of the core's mesh (lib/mesh.c) and sparse
 * solvers (lib/sparse.c) against invariants and hand counts:
 *  - a grid Laplacian plus a diagonal, solved by conjugate gradients and
 *    by the envelope Cholesky factor, gives residuals below 1e-10 of
 *    the right-hand side, and the two solutions agree;
 *  - a matrix that is not positive definite is refused by the factor;
 *  - two bilinear patches side by side, meshed 4 x 4 each and welded,
 *    have 5 * 9 vertices, 64 triangles, and 2 * (4 + 8) = 24 sides on
 *    the boundary; each inner side's two triangles run it opposite ways.
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "loft.h"

/* The n x n grid's Laplacian plus the diagonal d: order n^2. */
static void
grid_matrix(struct loft_sparse *m, size_t n, double d)
{
	memset(m, 0, sizeof *m);
	m->n = n * n;
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < n; j++) {
			size_t k = i * n + j;

			loft_sparse_add(m, k, k, d);
			if (i + 1 < n) {
				loft_sparse_add(m, k, k, 1);
				loft_sparse_add(m, k + n, k + n, 1);
				loft_sparse_add(m, k, k + n, -1);
			}
			if (j + 1 < n) {
				loft_sparse_add(m, k, k, 1);
				loft_sparse_add(m, k + 1, k + 1, 1);
				loft_sparse_add(m, k, k + 1, -1);
			}
		}
	CHECK(loft_sparse_compress(m) == 0, "compress");
}

/* |m x - b| / |b| */
static double
residual(const struct loft_sparse *m, const double *x, const double *b)
{
	double r = 0, s = 0;

	for (size_t i = 0; i < m->n; i++) {
		double y = 0;

		for (size_t k = m->row[i]; k < m->row[i + 1]; k++)
			y += m->a[k] * x[m->col[k]];
		r += (y - b[i]) * (y - b[i]);
		s += b[i] * b[i];
	}
	return sqrt(r / s);
}

static void
solvers(void)
{
	struct loft_sparse m;
	struct loft_sparse_chol c;
	size_t n = 30, N = n * n;
	double *b = malloc(N * sizeof *b), *x = calloc(N, sizeof *x);
	double *y = malloc(N * sizeof *y), *w = malloc(N * sizeof *w), d = 0;
	long it;

	grid_matrix(&m, n, 1e-3);
	for (size_t i = 0; i < N; i++)
		b[i] = sin(0.37 * i) + 0.1 * (i % 7);
	CHECK(loft_sparse_solve(&m, b, x, 1e-12, 100000, &it) == 0,
	    "conjugate gradients converge (%ld steps)", it);
	CHECK(residual(&m, x, b) < 1e-10, "CG residual %g", residual(&m, x, b));
	CHECK(loft_sparse_factor(&m, &c) == 0, "the factor");
	loft_sparse_chol_solve(&c, b, y, w);
	CHECK(residual(&m, y, b) < 1e-10, "Cholesky residual %g",
	    residual(&m, y, b));
	for (size_t i = 0; i < N; i++)
		d = fmax(d, fabs(x[i] - y[i]) / (1 + fabs(y[i])));
	CHECK(d < 1e-8, "CG and Cholesky differ by %g", d);
	loft_sparse_chol_free(&c);
	loft_sparse_free(&m);
	/* indefinite: the diagonal made negative */
	grid_matrix(&m, 4, -5);
	CHECK(loft_sparse_factor(&m, &c) == LOFT_EGEOM, "indefinite refused");
	loft_sparse_free(&m);
	free(b);
	free(x);
	free(y);
	free(w);
}

static void
mesh(void)
{
	double ctl[2][12] = { { 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0 },
	    { 1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0 } };
	struct loft_surface s[2];
	struct loft_mesh me;
	size_t *nb, bound = 0, flip = 0;
	unsigned char *same;

	memset(&me, 0, sizeof me);
	for (int i = 0; i < 2; i++)
		loft_surface_from_bezier(ctl[i], 1, 1, &s[i]);
	CHECK(loft_mesh_surfaces(&me, s, 2, NULL, NULL, 4, 1e-9) == 0, "mesh");
	CHECK(me.nv == 45 && me.nt == 64, "%zu vertices, %zu triangles",
	    me.nv, me.nt);
	nb = malloc(3 * me.nt * sizeof *nb);
	same = malloc(3 * me.nt);
	CHECK(loft_mesh_neighbours(&me, nb, same) == 0, "neighbours");
	for (size_t k = 0; k < 3 * me.nt; k++) {
		bound += nb[k] == (size_t)-1;
		flip += nb[k] != (size_t)-1 && same[k];
	}
	CHECK(bound == 24, "%zu boundary sides, want 24", bound);
	CHECK(flip == 0, "%zu sides run the same way by both", flip);
	free(nb);
	free(same);
	loft_mesh_free(&me);
}

int
main(void)
{
	solvers();
	mesh();
	return check_done("sparse");
}
