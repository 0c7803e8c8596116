/*
 * sparse.c: sparse symmetric positive definite systems, stored as
 * compressed rows and solved by conjugate gradients with a Jacobi
 * (diagonal) preconditioner (Hestenes and Stiefel 1952), for the
 * surface work: unroll's least-squares conformal start and its
 * as-rigid-as-possible steps.  Core.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

int
loft_sparse_add(struct loft_sparse *m, size_t i, size_t j, double a)
{
	if (m->compressed || i >= m->n || j >= m->n)
		return LOFT_EINPUT;
	for (int k = 0; k < (i == j ? 1 : 2); k++) {
		size_t cap = m->cap;

		if (loft__grow((void **)&m->row, &cap, m->nnz + 1,
		    sizeof *m->row) != 0)
			return LOFT_ENOMEM;
		cap = m->cap;
		if (loft__grow((void **)&m->col, &cap, m->nnz + 1,
		    sizeof *m->col) != 0)
			return LOFT_ENOMEM;
		if (loft__grow((void **)&m->a, &m->cap, m->nnz + 1,
		    sizeof *m->a) != 0)
			return LOFT_ENOMEM;
		m->row[m->nnz] = k ? j : i;
		m->col[m->nnz] = k ? i : j;
		m->a[m->nnz++] = a;
	}
	return 0;
}

int
loft_sparse_compress(struct loft_sparse *m)
{
	size_t *start = calloc(m->n + 2, sizeof *start), *col, nz = 0;
	double *a;

	if (start != NULL && m->cap < m->n + 1) {
		size_t cap = m->cap;

		if (loft__grow((void **)&m->row, &cap, m->n + 1,
		    sizeof *m->row) != 0) {
			free(start);
			return LOFT_ENOMEM;
		}
	}

	col = malloc((m->nnz + 1) * sizeof *col);
	a = malloc((m->nnz + 1) * sizeof *a);
	if (start == NULL || col == NULL || a == NULL) {
		free(start);
		free(col);
		free(a);
		return LOFT_ENOMEM;
	}
	/* bucket the triplets by row, then sum equal columns in each */
	for (size_t k = 0; k < m->nnz; k++)
		start[m->row[k] + 2]++;
	for (size_t i = 2; i < m->n + 2; i++)
		start[i] += start[i - 1];
	for (size_t k = 0; k < m->nnz; k++) {
		size_t at = start[m->row[k] + 1]++;

		col[at] = m->col[k];
		a[at] = m->a[k];
	}
	for (size_t i = 0; i < m->n; i++) {
		size_t lo = start[i], hi = start[i + 1], first = nz;

		for (size_t k = lo; k < hi; k++) {
			size_t q = first;

			while (q < nz && m->col[q] != col[k])
				q++;
			if (q == nz) {
				m->col[nz] = col[k];
				m->a[nz++] = a[k];
			} else
				m->a[q] += a[k];
		}
		m->row[i] = first;
	}
	m->row[m->n] = nz;
	m->nnz = nz;
	m->compressed = 1;
	free(start);
	free(col);
	free(a);
	return 0;
}

/* y = m x */
static void
multiply(const struct loft_sparse *m, const double *x, double *y)
{
	for (size_t i = 0; i < m->n; i++) {
		double s = 0;

		for (size_t k = m->row[i]; k < m->row[i + 1]; k++)
			s += m->a[k] * x[m->col[k]];
		y[i] = s;
	}
}

static double
dot(const double *a, const double *b, size_t n)
{
	double s = 0;

	for (size_t i = 0; i < n; i++)
		s += a[i] * b[i];
	return s;
}

int
loft_sparse_solve(const struct loft_sparse *m, const double *b, double *x,
    double tol, long maxit, long *iters)
{
	size_t n = m->n;
	double *w = malloc((4 * n + 1) * sizeof *w), *r, *z, *p, *q;
	double rz, bn = sqrt(dot(b, b, n)), rn;
	long it = 0;
	int rc = LOFT_ENOCONV;

	if (w == NULL)
		return LOFT_ENOMEM;
	r = w;
	z = w + n;
	p = w + 2 * n;
	q = w + 3 * n;
	multiply(m, x, q);
	for (size_t i = 0; i < n; i++)
		r[i] = b[i] - q[i];
	/* the preconditioner: z = r / diag */
	for (size_t i = 0; i < n; i++) {
		double d = 0;

		for (size_t k = m->row[i]; k < m->row[i + 1]; k++)
			if (m->col[k] == i)
				d = m->a[k];
		q[i] = d > 0 ? 1 / d : 1;
		z[i] = q[i] * r[i];
		p[i] = z[i];
	}
	rz = dot(r, z, n);
	for (;;) {
		double alpha, pq, rz1;

		rn = sqrt(dot(r, r, n));
		if (rn <= tol * bn || rn == 0) {
			rc = 0;
			break;
		}
		if (it >= maxit || !(rn < INFINITY))
			break;
		it++;
		/* q holds the preconditioner; use z for m p */
		multiply(m, p, z);
		pq = dot(p, z, n);
		if (!(pq > 0))
			break;
		alpha = rz / pq;
		for (size_t i = 0; i < n; i++) {
			x[i] += alpha * p[i];
			r[i] -= alpha * z[i];
			z[i] = q[i] * r[i];
		}
		rz1 = dot(r, z, n);
		for (size_t i = 0; i < n; i++)
			p[i] = z[i] + rz1 / rz * p[i];
		rz = rz1;
	}
	if (iters != NULL)
		*iters = it;
	free(w);
	return rc;
}

void
loft_sparse_free(struct loft_sparse *m)
{
	free(m->row);
	free(m->col);
	free(m->a);
	memset(m, 0, sizeof *m);
}
