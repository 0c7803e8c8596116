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

/* ---- envelope Cholesky in reverse Cuthill-McKee order ------------------ */

/*
 * The envelope of the factor is held to this many numbers: a mesh of
 * 65536 vertices in RCM order has about 300 a row; beyond it the
 * caller falls back on conjugate gradients.
 */
#define ENVELOPE_MAX ((size_t)1 << 26)

/* Reverse Cuthill-McKee (1969): breadth first from a vertex of least
 * degree in each piece, neighbours by increasing degree; reversed. */
static void
rcm(const struct loft_sparse *m, size_t *perm, unsigned char *seen)
{
	size_t n = m->n, head = 0, tail = 0;

	memset(seen, 0, n);
	while (tail < n) {
		size_t s = n;

		for (size_t i = 0; i < n; i++)
			if (!seen[i] && (s == n || m->row[i + 1] - m->row[i] <
			    m->row[s + 1] - m->row[s]))
				s = i;
		seen[s] = 1;
		perm[tail++] = s;
		while (head < tail) {
			size_t v = perm[head++], first = tail;

			for (size_t k = m->row[v]; k < m->row[v + 1]; k++)
				if (!seen[m->col[k]]) {
					seen[m->col[k]] = 1;
					perm[tail++] = m->col[k];
				}
			/* by degree: insertion sort of the few new ones */
			for (size_t a = first + 1; a < tail; a++)
				for (size_t b = a; b > first && m->row[perm[b] + 1] -
				    m->row[perm[b]] < m->row[perm[b - 1] + 1] -
				    m->row[perm[b - 1]]; b--) {
					size_t t = perm[b];

					perm[b] = perm[b - 1];
					perm[b - 1] = t;
				}
		}
	}
	for (size_t i = 0; i < n / 2; i++) {
		size_t t = perm[i];

		perm[i] = perm[n - 1 - i];
		perm[n - 1 - i] = t;
	}
}

/* The envelope's row starts; 0, or LOFT_ENOMEM when it is too large. */
static int
envelope(const struct loft_sparse *m, struct loft_sparse_chol *c)
{
	size_t n = m->n;

	c->start[0] = 0;
	for (size_t i = 0; i < n; i++) {
		size_t r = c->perm[i], f = i;

		for (size_t k = m->row[r]; k < m->row[r + 1]; k++)
			if (c->inv[m->col[k]] < f)
				f = c->inv[m->col[k]];
		c->first[i] = f;
		c->start[i + 1] = c->start[i] + (i - f + 1);
		if (c->start[i + 1] > ENVELOPE_MAX)
			return LOFT_ENOMEM;
	}
	return 0;
}

/* Row i of the factor, from the rows before it (L L^t = P A P^t). */
static int
factor_row(struct loft_sparse_chol *c, size_t i)
{
	double *li = c->l + c->start[i] - c->first[i];

	for (size_t j = c->first[i]; j <= i; j++) {
		double *lj = c->l + c->start[j] - c->first[j], s = li[j];
		size_t k0 = c->first[i] > c->first[j] ? c->first[i] : c->first[j];

		for (size_t k = k0; k < j; k++)
			s -= li[k] * lj[k];
		if (j < i)
			li[j] = s / lj[j];
		else if (!(s > 0))
			return LOFT_EGEOM;
		else
			li[i] = sqrt(s);
	}
	return 0;
}

int
loft_sparse_factor(const struct loft_sparse *m, struct loft_sparse_chol *c)
{
	size_t n = m->n;
	unsigned char *seen = malloc(n + 1);
	int rc = LOFT_ENOMEM;

	memset(c, 0, sizeof *c);
	c->n = n;
	c->perm = malloc((n + 1) * sizeof *c->perm);
	c->inv = malloc((n + 1) * sizeof *c->inv);
	c->first = malloc((n + 1) * sizeof *c->first);
	c->start = malloc((n + 2) * sizeof *c->start);
	if (seen == NULL || c->perm == NULL || c->inv == NULL ||
	    c->first == NULL || c->start == NULL)
		goto out;
	rcm(m, c->perm, seen);
	for (size_t i = 0; i < n; i++)
		c->inv[c->perm[i]] = i;
	if (envelope(m, c) != 0 ||
	    (c->l = calloc(c->start[n] + 1, sizeof *c->l)) == NULL)
		goto out;
	for (size_t i = 0; i < n; i++) {
		size_t r = c->perm[i];

		for (size_t k = m->row[r]; k < m->row[r + 1]; k++)
			if (c->inv[m->col[k]] <= i)
				c->l[c->start[i] - c->first[i] +
				    c->inv[m->col[k]]] = m->a[k];
	}
	rc = 0;
	for (size_t i = 0; rc == 0 && i < n; i++)
		rc = factor_row(c, i);
out:
	free(seen);
	if (rc != 0)
		loft_sparse_chol_free(c);
	return rc;
}

void
loft_sparse_chol_solve(const struct loft_sparse_chol *c, const double *b,
    double *x, double *work)
{
	size_t n = c->n;

	for (size_t i = 0; i < n; i++) {
		const double *li = c->l + c->start[i] - c->first[i];
		double s = b[c->perm[i]];

		for (size_t k = c->first[i]; k < i; k++)
			s -= li[k] * work[k];
		work[i] = s / li[i];
	}
	for (size_t i = n; i-- > 0; ) {
		const double *li = c->l + c->start[i] - c->first[i];

		work[i] /= li[i];
		for (size_t k = c->first[i]; k < i; k++)
			work[k] -= li[k] * work[i];
	}
	for (size_t i = 0; i < n; i++)
		x[c->perm[i]] = work[i];
}

void
loft_sparse_chol_free(struct loft_sparse_chol *c)
{
	free(c->perm);
	free(c->inv);
	free(c->first);
	free(c->start);
	free(c->l);
	memset(c, 0, sizeof *c);
}
