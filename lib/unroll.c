/*
 * unroll.c: laying a surface of patches flat.  A developable sheet is
 * developed exactly, patch by patch, by integrating its geodesic
 * curvature (the flat image of a curve on a developable surface is the
 * plane curve of the same arc length whose curvature is the curve's
 * geodesic curvature), and the patches are placed on one another where
 * they share vertices.  A doubly curved sheet starts from that
 * development and is relaxed by the as-rigid-as-possible local/global
 * iteration of Liu, Zhang, Xu, Gotsman and Gortler (2008) on its mesh,
 * the global step a sparse solve (sparse.c).  Core.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/*
 * Quadrature intervals at least along each line of the exact
 * development, of Gauss-Legendre order 5 each: on a cubic patch the
 * integrands are smooth to every order and 16 intervals hold them to
 * 1e-14 of the size.
 */
#define MIN_INTERVALS 16

/* Mesh steps a patch side: at least, at most, and the vertices of the
 * whole mesh at most when the steps come from the tolerance (a 100-patch
 * plate gets 6 steps a side, and unrolls in a fraction of a second). */
#define MIN_STEPS 4
#define MAX_STEPS 64
#define VERTEX_BUDGET 4096.0

/* Vertices nearer than this part of the sheet's size are one (as
 * cad.c's WELD_TOL: shared edges agree to a few rounding errors). */
#define WELD_TOL 1e-9

/* The sparse solve stops at this residual, relative to the right-hand
 * side: well below the strains reported (1e-4 and up). */
#define SOLVE_TOL 1e-10

/* The iteration stops when a round lowers the energy by less than this
 * part of it. */
#define ENERGY_TOL 1e-7

/* Passes of reweighting after the plain iteration (arap). */
#define REWEIGHTS 6

/* A cotangent weight is held to this: a sliver's would swamp the rest. */
#define COT_MAX 1e4

static void
cross(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

/* What the development needs at a point: the speeds |f_u|, |f_v|, the
 * angle gamma from f_u to f_v, and the rates ku, kv at which the flat
 * direction of a u- and a v-line turns (geodesic curvature times speed). */
struct geo {
	double su, sv, gamma, ku, kv;
};

static void
geo_at(const struct loft_surface *s, double u, double v, struct geo *g)
{
	double p[3] = { 0 }, xu[3] = { 0 }, xv[3] = { 0 }, xuu[3] = { 0 };
	double xvv[3] = { 0 }, n[3], c[3], sn;

	loft_surface_eval2(s, u, v, p, xu, xv, xuu, xvv);
	cross(xu, xv, n);
	sn = vunit(n, 3);
	g->su = vnorm(xu, 3);
	g->sv = vnorm(xv, 3);
	g->gamma = atan2(sn, vdot(xu, xv, 3));
	g->ku = g->kv = 0;
	if (!(sn > 0)) {
		g->gamma = M_PI / 2;
		return;
	}
	cross(n, xu, c);
	g->ku = vdot(xuu, c, 3) / (g->su * g->su);
	cross(n, xv, c);
	g->kv = vdot(xvv, c, 3) / (g->sv * g->sv);
}

/*
 * Develop a line of s from t = 0 to 1: the u-line at v = w (dir 0) or
 * the v-line at u = w (dir 1), over M intervals, starting from the flat
 * direction ang[0] and point pos[0..1]; the direction and point after
 * every `every` intervals go to ang[k], pos[2k].
 */
static void
develop_line(const struct loft_surface *s, int dir, double w, long M,
    long every, double *ang, double *pos)
{
	const double *X = loft__gl5_x, *W = loft__gl5_w;
	double a = ang[0], x = pos[0], y = pos[1], h = 1.0 / M;
	struct geo g;

	for (long k = 0; k < M; k++) {
		double t0 = (double)k / M, ra = 0, dx = 0, dy = 0;

		for (int q = 0; q < 5; q++) {
			double in = 0, sp;

			for (int r = 0; r < 5; r++) {
				double t = t0 + h * X[q] * X[r];

				geo_at(s, dir ? w : t, dir ? t : w, &g);
				in += W[r] * (dir ? g.kv : g.ku);
			}
			in *= h * X[q];
			geo_at(s, dir ? w : t0 + h * X[q], dir ? t0 + h * X[q] :
			    w, &g);
			sp = dir ? g.sv : g.su;
			dx += W[q] * sp * cos(a + in);
			dy += W[q] * sp * sin(a + in);
			ra += W[q] * (dir ? g.kv : g.ku);
		}
		a += h * ra;
		x += h * dx;
		y += h * dy;
		if ((k + 1) % every == 0) {
			ang[(k + 1) / every] = a;
			pos[2 * ((k + 1) / every)] = x;
			pos[2 * ((k + 1) / every) + 1] = y;
		}
	}
}

/*
 * Develop patch s on its (N + 1)^2 nodes: the edge u = 0 first, f_u at
 * (0, 0) along the x axis, then each line v = j / N from it.  loc gets
 * the flat points (2 a node, u-major), jac the flat images of f_u and
 * f_v there (4 a node).  Returns 0 or LOFT_ENOMEM.
 */
static int
develop_patch(const struct loft_surface *s, long N, double *loc, double *jac)
{
	long sub = (MIN_INTERVALS + N - 1) / N, M = N * sub;
	double *psi = malloc(((size_t)N + 1) * 6 * sizeof *psi);
	double *p0, *beta, *pos;
	struct geo g;

	if (psi == NULL)
		return LOFT_ENOMEM;
	p0 = psi + N + 1;
	beta = p0 + 2 * (N + 1);
	pos = beta + N + 1;
	geo_at(s, 0, 0, &g);
	psi[0] = g.gamma;
	p0[0] = p0[1] = 0;
	develop_line(s, 1, 0, M, sub, psi, p0);
	for (long j = 0; j <= N; j++) {
		double v = (double)j / N;

		geo_at(s, 0, v, &g);
		beta[0] = psi[j] - g.gamma;
		pos[0] = p0[2 * j];
		pos[1] = p0[2 * j + 1];
		develop_line(s, 0, v, M, sub, beta, pos);
		for (long i = 0; i <= N; i++) {
			size_t k = (size_t)i * (N + 1) + j;

			geo_at(s, (double)i / N, v, &g);
			loc[2 * k] = pos[2 * i];
			loc[2 * k + 1] = pos[2 * i + 1];
			jac[4 * k] = g.su * cos(beta[i]);
			jac[4 * k + 1] = g.su * sin(beta[i]);
			jac[4 * k + 2] = g.sv * cos(beta[i] + g.gamma);
			jac[4 * k + 3] = g.sv * sin(beta[i] + g.gamma);
		}
	}
	free(psi);
	return 0;
}

/* A rigid motion of the plane, a reflection first when flip. */
struct motion {
	double c, s, lc[2], gc[2];
	int flip;
};

static void
move(const struct motion *m, const double *l, double *g, int vector)
{
	double x = l[0] - (vector ? 0 : m->lc[0]);
	double y = (m->flip ? -1 : 1) * (l[1] - (vector ? 0 : m->lc[1]));

	g[0] = m->c * x - m->s * y + (vector ? 0 : m->gc[0]);
	g[1] = m->s * x + m->c * y + (vector ? 0 : m->gc[1]);
}

/* The motion (reflected if flip) taking the n points l nearest to g
 * (least squares); its sum of squared misses. */
static double
fit_motion(const double *l, const double *g, size_t n, int flip,
    struct motion *m)
{
	double sd = 0, sc = 0, e = 0, th;

	memset(m, 0, sizeof *m);
	m->flip = flip;
	for (size_t k = 0; k < n; k++)
		for (int c = 0; c < 2; c++) {
			m->lc[c] += l[2 * k + c] / n;
			m->gc[c] += g[2 * k + c] / n;
		}
	for (size_t k = 0; k < n; k++) {
		double x = l[2 * k] - m->lc[0];
		double y = (flip ? -1 : 1) * (l[2 * k + 1] - m->lc[1]);
		double X = g[2 * k] - m->gc[0], Y = g[2 * k + 1] - m->gc[1];

		sd += x * X + y * Y;
		sc += x * Y - y * X;
	}
	th = atan2(sc, sd);
	m->c = cos(th);
	m->s = sin(th);
	for (size_t k = 0; k < n; k++) {
		double q[2];

		move(m, l + 2 * k, q, 0);
		e += (q[0] - g[2 * k]) * (q[0] - g[2 * k]) +
		    (q[1] - g[2 * k + 1]) * (q[1] - g[2 * k + 1]);
	}
	return e;
}

/*
 * The grid nodes of each welded vertex: node[start[w] .. start[w + 1])
 * (start: nv + 1 entries, node: as many as grid).  0 or LOFT_ENOMEM.
 */
static int
vertex_nodes(const struct loft_unroll *r, size_t **start, size_t **node)
{
	size_t nv = r->mesh.nv, n = (size_t)(r->N + 1) * (r->N + 1) * r->npatch;
	size_t *st = calloc(nv + 2, sizeof *st), *nd = malloc((n + 1) *
	    sizeof *nd);

	*start = st;
	*node = nd;
	if (st == NULL || nd == NULL)
		return LOFT_ENOMEM;
	for (size_t k = 0; k < n; k++)
		st[r->grid[k] + 2]++;
	for (size_t w = 2; w < nv + 2; w++)
		st[w] += st[w - 1];
	for (size_t k = 0; k < n; k++)
		nd[st[r->grid[k] + 1]++] = k;
	return 0;
}

/* After patch p is placed: each vertex it placed counts once more for
 * every patch with a node on it. */
static void
count_placed(const struct loft_unroll *r, const size_t *owner,
    const size_t *start, const size_t *node, size_t p, size_t *count)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1);

	for (size_t k = p * nn; k < (p + 1) * nn; k++) {
		size_t w = r->grid[k];

		if (owner[w] != k)
			continue;
		for (size_t j = start[w]; j < start[w + 1]; j++)
			count[node[j] / nn]++;
	}
}

/* The unit normal f_u x f_v of the patch of grid node k, or 0s. */
static void
node_normal(const struct loft_unroll *r, const struct loft_surface *s,
    size_t k, double *n)
{
	size_t N = r->N > 0 ? (size_t)r->N : 1, w = N + 1, nn = w * w;
	double du[3] = { 0 }, dv[3] = { 0 };

	n[0] = n[1] = n[2] = 0;
	if (nn == 0)            /* N so large its square wrapped: none */
		return;
	loft_surface_eval(&s[k / nn], (double)(k % nn / w) / (double)N,
	    (double)(k % nn % w) / (double)N, NULL, du, dv);
	cross(du, dv, n);
	vunit(n, 3);
}

/*
 * Whether patch p runs the other way from the placed patches it
 * shares vertices with: its normal against theirs (flip says which
 * placed patches were reflected), at the first shared vertex where
 * both are defined.
 */
static int
reflected(const struct loft_unroll *r, const struct loft_surface *s,
    const size_t *owner, const unsigned char *flip, size_t p)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1);

	for (size_t k = p * nn; k < (p + 1) * nn; k++) {
		size_t o = owner[r->grid[k]];
		double a[3], b[3], d;

		if (o == (size_t)-1)
			continue;
		node_normal(r, s, k, a);
		node_normal(r, s, o, b);
		if ((d = vdot(a, b, 3)) != 0)
			return flip[o / nn] ^ (d < 0);
	}
	return 0;
}

/*
 * Place patch p's developed nodes loc (and their jac) on the vertices
 * placed already (owner: the node that placed each, or -1), by the
 * motion that fits them best, reflected where the patch runs the other
 * way (flip[p]); with none placed, to the right of what is (a sheet in
 * pieces).  Then its unplaced vertices are placed.
 */
static int
place_patch(struct loft_unroll *r, size_t *owner, int flip, size_t p,
    double *loc, double *jac, double *right)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1), n = 0;
	double *l = malloc(4 * nn * sizeof *l), *g, lo = INFINITY;
	struct motion m;

	if (l == NULL)
		return LOFT_ENOMEM;
	g = l + 2 * nn;
	for (size_t k = 0; k < nn; k++) {
		size_t w = r->grid[p * nn + k];

		lo = fmin(lo, loc[2 * k]);
		if (owner[w] == (size_t)-1)
			continue;
		vcopy(l + 2 * n, loc + 2 * k, 2);
		vcopy(g + 2 * n++, r->xy + 2 * w, 2);
	}
	if (n >= 2) {
		fit_motion(l, g, n, flip, &m);
	} else {
		memset(&m, 0, sizeof m);
		m.c = 1;
		m.gc[0] = *right - lo;
	}
	for (size_t k = 0; k < nn; k++) {
		size_t w = r->grid[p * nn + k];
		double q[2];

		move(&m, loc + 2 * k, q, 0);
		move(&m, jac + 4 * k, r->jac + 4 * (p * nn + k), 1);
		move(&m, jac + 4 * k + 2, r->jac + 4 * (p * nn + k) + 2, 1);
		if (owner[w] == (size_t)-1) {
			vcopy(r->xy + 2 * w, q, 2);
			owner[w] = p * nn + k;
		}
		*right = fmax(*right, q[0]);
	}
	free(l);
	return 0;
}

/* Develop every patch and place them, the patch with the most
 * vertices placed already first. */
static int
develop(struct loft_unroll *r, const struct loft_surface *s)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1), np = r->npatch;
	double *loc = calloc(6 * nn, sizeof *loc), right = 0;
	size_t *owner = malloc((r->mesh.nv + 1) * sizeof *owner);
	size_t *count = calloc(np + 1, sizeof *count), *start, *node;
	unsigned char *done = calloc(np, 1), *flip = calloc(np, 1);
	int rc = loc == NULL || owner == NULL || done == NULL || flip == NULL ||
	    count == NULL ? LOFT_ENOMEM : 0;

	if (vertex_nodes(r, &start, &node) != 0)
		rc = LOFT_ENOMEM;
	for (size_t i = 0; rc == 0 && i < r->mesh.nv; i++)
		owner[i] = (size_t)-1;
	for (size_t round = 0; rc == 0 && round < np; round++) {
		size_t best = np;

		for (size_t p = 0; p < np; p++)
			if (!done[p] && (best == np || count[p] > count[best]))
				best = p;
		done[best] = 1;
		flip[best] = (unsigned char)reflected(r, s, owner, flip, best);
		rc = develop_patch(&s[best], r->N, loc, loc + 2 * nn);
		if (rc == 0)
			rc = place_patch(r, owner, flip[best], best, loc,
			    loc + 2 * nn, &right);
		if (rc == 0)
			count_placed(r, owner, start, node, best, count);
	}
	free(loc);
	free(owner);
	free(count);
	free(start);
	free(node);
	free(done);
	free(flip);
	return rc;
}

/* The mesh steps a side for tol: from the largest second derivatives
 * on a 5 x 5 grid of each patch, as loft_mesh_steps from a net's. */
static long
steps_for(const struct loft_surface *s, size_t ns, double tol)
{
	double most = 0;
	long N;

	for (size_t i = 0; i < ns; i++)
		for (int a = 0; a <= 4; a++)
			for (int b = 0; b <= 4; b++) {
				double p[3] = { 0 }, du[3] = { 0 }, dv[3] = { 0 };
				double uu[3] = { 0 }, vv[3] = { 0 }, k, h, da;
				double m;

				loft_surface_eval2(&s[i], a / 4.0, b / 4.0, p, du,
				    dv, uu, vv);
				(void)loft_surface_curvature(&s[i], a / 4.0,
				    b / 4.0, &k, &h, &da);
				m = vnorm(uu, 3) + vnorm(vv, 3) + 2 * fabs(h) *
				    (vnorm(du, 3) + vnorm(dv, 3)) *
				    (vnorm(du, 3) + vnorm(dv, 3)) / 4;
				most = fmax(most, m);
			}
	N = !(most / (8 * tol) < 1e12) ? MAX_STEPS :
	    (long)ceil(sqrt(most / (8 * tol)));
	if ((double)N * N * ns > VERTEX_BUDGET)
		N = (long)sqrt(VERTEX_BUDGET / ns);
	return N < MIN_STEPS ? MIN_STEPS : N > MAX_STEPS ? MAX_STEPS : N;
}

/* Mesh the patches on one grid each, keep each node's welded vertex. */
static int
make_mesh(struct loft_unroll *r, const struct loft_surface *s, size_t ns,
    double size, struct loft_error *err)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1);

	r->npatch = ns;
	if (loft_mesh_surfaces(&r->mesh, s, ns, NULL, NULL, r->N, -1) != 0 ||
	    (r->grid = malloc(ns * nn * sizeof *r->grid)) == NULL ||
	    (r->jac = malloc(4 * ns * nn * sizeof *r->jac)) == NULL ||
	    loft_mesh_weld(&r->mesh, WELD_TOL * size, r->grid) != 0 ||
	    (r->xy = calloc(2 * r->mesh.nv + 1, sizeof *r->xy)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < 3 * r->mesh.nv; i++)
		if (!isfinite(r->mesh.v[i]))
			return loft_fail(err, LOFT_EGEOM, -1, "the surface "
			    "overflows: coefficients too large");
	return 0;
}

/* The size of the sheet: the diagonal of its points' box on a 5 x 5
 * grid of each patch. */
static double
sheet_size(const struct loft_surface *s, size_t ns)
{
	double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 }, d = 0;

	for (size_t i = 0; i < ns; i++)
		for (int a = 0; a <= 4; a++)
			for (int b = 0; b <= 4; b++) {
				double p[3] = { 0 };

				loft_surface_eval(&s[i], a / 4.0, b / 4.0, p, NULL,
				    NULL);
				for (int c = 0; c < 3; c++) {
					lo[c] = i + a + b == 0 ? p[c] : fmin(lo[c], p[c]);
					hi[c] = i + a + b == 0 ? p[c] : fmax(hi[c], p[c]);
				}
			}
	for (int c = 0; c < 3; c++)
		d = hypot(d, hi[c] - lo[c]);
	return d;
}

/* ---- as rigid as possible -------------------------------------------- */

/* A triangle of the iteration: its flat shape (x), cotangents, sense. */
struct tri {
	double x[6], cot[3];
	int ok;
};

/* Triangle t laid in its own plane with the sense sign (+1 or -1). */
static void
tri_setup(const struct loft_mesh *me, size_t t, double sign, struct tri *T)
{
	const size_t *v = me->t + 3 * t;
	double e1[3], e2[3], c[3], l;

	memset(T, 0, sizeof *T);
	vsub(e1, me->v + 3 * v[1], me->v + 3 * v[0], 3);
	vsub(e2, me->v + 3 * v[2], me->v + 3 * v[0], 3);
	cross(e1, e2, c);
	l = vnorm(e1, 3);
	if (!(vnorm(c, 3) > 0) || !(l > 0))
		return;
	T->x[2] = l;
	T->x[4] = vdot(e1, e2, 3) / l;
	T->x[5] = sign * vnorm(c, 3) / l;
	for (int k = 0; k < 3; k++) {
		double a[3], b[3], d[3];

		vsub(a, me->v + 3 * v[(k + 1) % 3], me->v + 3 * v[k], 3);
		vsub(b, me->v + 3 * v[(k + 2) % 3], me->v + 3 * v[k], 3);
		cross(a, b, d);
		T->cot[k] = fmax(-COT_MAX, fmin(COT_MAX, vdot(a, b, 3) /
		    vnorm(d, 3)));
	}
	T->ok = 1;
}

/* The Laplacian of the cotangent weights, vertex 0 held. */
static int
laplacian(const struct loft_mesh *me, const struct tri *T,
    struct loft_sparse *L, double *pin)
{
	double sum = 0;

	L->n = me->nv;
	for (size_t t = 0; t < me->nt; t++)
		for (int k = 0; T[t].ok && k < 3; k++) {
			size_t i = me->t[3 * t + (k + 1) % 3];
			size_t j = me->t[3 * t + (k + 2) % 3];
			double c = T[t].cot[k];

			sum += 2 * fabs(c);
			if (loft_sparse_add(L, i, i, c) || loft_sparse_add(L, j, j, c)
			    || loft_sparse_add(L, i, j, -c))
				return LOFT_ENOMEM;
		}
	*pin = sum / (me->nv + 1) + 1;
	if (loft_sparse_add(L, 0, 0, *pin) != 0)
		return LOFT_ENOMEM;
	return loft_sparse_compress(L);
}

/* Side k of triangle t (opposite its vertex k): its own vector X (2
 * numbers) and, when xy is not NULL, its flat vector U. */
static void
side_vectors(const struct loft_mesh *me, const struct tri *T, size_t t,
    int k, const double *xy, double *X, double *U)
{
	int a = (k + 1) % 3, b = (k + 2) % 3;

	X[0] = T[t].x[2 * a] - T[t].x[2 * b];
	X[1] = T[t].x[2 * a + 1] - T[t].x[2 * b + 1];
	if (xy != NULL)
		vsub(U, xy + 2 * me->t[3 * t + a], xy + 2 * me->t[3 * t + b], 2);
}

/* The local step: each triangle's best rotation (its angle in rot);
 * the energy of the flat points xy. */
static double
local_step(const struct loft_mesh *me, const struct tri *T, const double *xy,
    double *rot)
{
	double e = 0;

	for (size_t t = 0; t < me->nt; t++) {
		double sd = 0, sc = 0, c, s, X[2], U[2];

		for (int k = 0; T[t].ok && k < 3; k++) {
			side_vectors(me, T, t, k, xy, X, U);
			sd += T[t].cot[k] * (X[0] * U[0] + X[1] * U[1]);
			sc += T[t].cot[k] * (X[0] * U[1] - X[1] * U[0]);
		}
		rot[t] = atan2(sc, sd);
		c = cos(rot[t]);
		s = sin(rot[t]);
		for (int k = 0; T[t].ok && k < 3; k++) {
			double du, dv;

			side_vectors(me, T, t, k, xy, X, U);
			du = U[0] - (c * X[0] - s * X[1]);
			dv = U[1] - (s * X[0] + c * X[1]);
			e += T[t].cot[k] * (du * du + dv * dv);
		}
	}
	return e;
}

/* The global step's right-hand sides bx, by from the rotations. */
static void
global_rhs(const struct loft_mesh *me, const struct tri *T, const double *rot,
    double pin, const double *xy, double *bx, double *by)
{
	memset(bx, 0, me->nv * sizeof *bx);
	memset(by, 0, me->nv * sizeof *by);
	for (size_t t = 0; t < me->nt; t++) {
		double c = cos(rot[t]), s = sin(rot[t]);

		for (int k = 0; T[t].ok && k < 3; k++) {
			size_t i = me->t[3 * t + (k + 1) % 3];
			size_t j = me->t[3 * t + (k + 2) % 3];
			double w = T[t].cot[k], X[2], rx, ry;

			side_vectors(me, T, t, k, NULL, X, NULL);
			rx = w * (c * X[0] - s * X[1]);
			ry = w * (s * X[0] + c * X[1]);
			bx[i] += rx;
			by[i] += ry;
			bx[j] -= rx;
			by[j] -= ry;
		}
	}
	/* the hold on vertex 0 where it is */
	bx[0] += pin * xy[0];
	by[0] += pin * xy[1];
}

/* The sense of each triangle in the starting development. */
static void
senses(const struct loft_mesh *me, const double *xy, struct tri *T)
{
	for (size_t t = 0; t < me->nt; t++) {
		const double *a = xy + 2 * me->t[3 * t];
		const double *b = xy + 2 * me->t[3 * t + 1];
		const double *c = xy + 2 * me->t[3 * t + 2];
		double s = (b[0] - a[0]) * (c[1] - a[1]) -
		    (b[1] - a[1]) * (c[0] - a[0]);

		tri_setup(me, t, s < 0 ? -1 : 1, &T[t]);
	}
}

/* The rounds of one weighting: the Laplacian factored once. */
static int
arap_rounds(struct loft_unroll *r, struct tri *T, int rounds, double *rot,
    double *b)
{
	struct loft_mesh *me = &r->mesh;
	double e0 = INFINITY, pin = 0, *x = b + 2 * me->nv;
	struct loft_sparse L;
	struct loft_sparse_chol C;
	int rc, direct = 0;

	memset(&L, 0, sizeof L);
	memset(&C, 0, sizeof C);
	rc = laplacian(me, T, &L, &pin);
	/* the factor once for every round; conjugate gradients without it */
	if (rc == 0)
		direct = loft_sparse_factor(&L, &C) == 0;
	for (int round = 0; rc == 0 && round < rounds; round++, r->rounds++) {
		double e = local_step(me, T, r->xy, rot);

		if (!(e < e0 * (1 - ENERGY_TOL)))
			break;
		e0 = e;
		global_rhs(me, T, rot, pin, r->xy, b, b + me->nv);
		for (size_t i = 0; i < me->nv; i++) {
			x[i] = r->xy[2 * i];
			x[me->nv + i] = r->xy[2 * i + 1];
		}
		for (int c = 0; c < 2 && rc != LOFT_ENOMEM; c++)
			if (direct)
				loft_sparse_chol_solve(&C, b + c * me->nv,
				    x + c * me->nv, rot);
			else
				rc = loft_sparse_solve(&L, b + c * me->nv,
				    x + c * me->nv, SOLVE_TOL,
				    10 * (long)me->nv + 100, NULL);
		if (rc == LOFT_ENOMEM)
			break;
		rc = 0;
		for (size_t i = 0; i < me->nv; i++) {
			r->xy[2 * i] = x[i];
			r->xy[2 * i + 1] = x[me->nv + i];
		}
	}
	loft_sparse_free(&L);
	loft_sparse_chol_free(&C);
	return rc;
}

/* The largest edge strain of triangle t. */
static double
tri_strain(const struct loft_mesh *me, const double *xy, size_t t)
{
	double s = 0;

	for (int k = 0; k < 3; k++) {
		size_t a = me->t[3 * t + k], b = me->t[3 * t + (k + 1) % 3];
		double l3 = vdist(me->v + 3 * a, me->v + 3 * b, 3);

		if (l3 > 0)
			s = fmax(s, fabs(vdist(xy + 2 * a, xy + 2 * b, 2) / l3 - 1));
	}
	return s;
}

/*
 * As rigid as possible, then reweighted: the energy's least squares
 * leave the largest strains where the sheet is most curved, so each
 * further pass weighs a triangle by how its strain stands to the
 * mean (iteratively reweighted least squares, towards the least
 * largest strain), and the best of the passes by largest strain is
 * kept.
 */
static int
arap(struct loft_unroll *r, int rounds)
{
	struct loft_mesh *me = &r->mesh;
	struct tri *T = malloc((me->nt + 1) * sizeof *T);
	double *rot = malloc((me->nt + me->nv + 1) * sizeof *rot);
	double *b = malloc((4 * me->nv + 1) * sizeof *b);
	double *best = malloc((2 * me->nv + 1) * sizeof *best), most = INFINITY;
	int rc = T == NULL || rot == NULL || b == NULL || best == NULL ?
	    LOFT_ENOMEM : 0;

	if (rc == 0)
		senses(me, r->xy, T);
	r->rounds = 0;
	for (int pass = 0; rc == 0 && pass < REWEIGHTS; pass++) {
		double mean = 0, worst = 0;

		rc = arap_rounds(r, T, pass == 0 ? rounds : rounds / 2, rot, b);
		for (size_t t = 0; t < me->nt; t++) {
			rot[t] = tri_strain(me, r->xy, t);
			mean += rot[t] / me->nt;
			worst = fmax(worst, rot[t]);
		}
		if (worst < most) {
			most = worst;
			memcpy(best, r->xy, 2 * me->nv * sizeof *best);
		}
		for (size_t t = 0; mean > 0 && t < me->nt; t++)
			for (int k = 0; k < 3; k++)
				T[t].cot[k] *= 1 + rot[t] * rot[t] / (mean * mean);
	}
	if (rc == 0)
		memcpy(r->xy, best, 2 * me->nv * sizeof *best);
	free(T);
	free(rot);
	free(b);
	free(best);
	return rc;
}

/* ---- results ----------------------------------------------------------- */

/* Node jacobians from the flat points by differences along the grid. */
static void
grid_jacobians(struct loft_unroll *r)
{
	long N = r->N;
	size_t nn = (size_t)(N + 1) * (N + 1);

	for (size_t p = 0; p < r->npatch; p++)
		for (long i = 0; i <= N; i++)
			for (long j = 0; j <= N; j++)
				for (int d = 0; d < 2; d++) {
					long a = d ? j : i;
					long lo = a == 0 ? 0 : a == N ? a - 2 : a - 1;
					double w[3] = { -1.5, 2, -0.5 };
					double *J = r->jac + 4 * (p * nn +
					    (size_t)i * (N + 1) + j) + 2 * d;

					if (a == N)
						w[0] = 0.5, w[1] = -2, w[2] = 1.5;
					else if (a > 0)
						w[0] = -0.5, w[1] = 0, w[2] = 0.5;
					J[0] = J[1] = 0;
					for (int q = 0; q < 3 && N >= 2; q++) {
						long b = lo + q;
						size_t k = p * nn + (size_t)(d ? i : b) *
						    (N + 1) + (size_t)(d ? b : j);

						vaxpy(J, w[q] * N, r->xy + 2 *
						    r->grid[k], 2);
					}
				}
}

/* Edge strains and areas of the mesh, flat against space. */
static int
strains(struct loft_unroll *r)
{
	const struct loft_mesh *me = &r->mesh;
	size_t *nb = malloc((3 * me->nt + 1) * sizeof *nb), ne = 0;

	if (nb == NULL || loft_mesh_neighbours(me, nb, NULL) != 0) {
		free(nb);
		return LOFT_ENOMEM;
	}
	r->strain_max = r->strain_mean = r->area3 = r->area2 = 0;
	for (size_t t = 0; t < me->nt; t++) {
		const size_t *v = me->t + 3 * t;
		double e1[3], e2[3], c[3], f1[2], f2[2];

		vsub(e1, me->v + 3 * v[1], me->v + 3 * v[0], 3);
		vsub(e2, me->v + 3 * v[2], me->v + 3 * v[0], 3);
		cross(e1, e2, c);
		r->area3 += vnorm(c, 3) / 2;
		vsub(f1, r->xy + 2 * v[1], r->xy + 2 * v[0], 2);
		vsub(f2, r->xy + 2 * v[2], r->xy + 2 * v[0], 2);
		r->area2 += fabs(f1[0] * f2[1] - f1[1] * f2[0]) / 2;
		for (int k = 0; k < 3; k++) {
			size_t a = v[k], b = v[(k + 1) % 3];
			double l3 = vdist(me->v + 3 * a, me->v + 3 * b, 3), s;

			if ((nb[3 * t + k] != (size_t)-1 && nb[3 * t + k] < t) ||
			    !(l3 > 0))
				continue;
			s = fabs(vdist(r->xy + 2 * a, r->xy + 2 * b, 2) / l3 - 1);
			r->strain_max = fmax(r->strain_max, s);
			r->strain_mean += s;
			ne++;
		}
	}
	r->strain_mean /= ne > 0 ? (double)ne : 1;
	free(nb);
	return 0;
}

/* ---- the outline ------------------------------------------------------ */

/* A side of the sheet's boundary: its welded ends a, b, and the grid
 * nodes na, nb they are on, of the one patch whose triangle has it. */
struct bside {
	size_t a, b, na, nb;
	int used;
};

static int
by_key(const void *x, const void *y)
{
	const struct bside *p = x, *q = y;
	size_t p0 = p->a < p->b ? p->a : p->b, p1 = p->a < p->b ? p->b : p->a;
	size_t q0 = q->a < q->b ? q->a : q->b, q1 = q->a < q->b ? q->b : q->a;

	if (p0 != q0)
		return p0 < q0 ? -1 : 1;
	return p1 < q1 ? -1 : p1 > q1;
}

/* The sides of the patches' grid triangles that no other has. */
static int
boundary_sides(const struct loft_unroll *r, struct bside **out, size_t *n)
{
	long N = r->N;
	size_t nn = (size_t)(N + 1) * (N + 1), ns = 0, nb = 0;
	struct bside *s = malloc((6 * (size_t)N * N * r->npatch + 1) *
	    sizeof *s);

	if (s == NULL)
		return LOFT_ENOMEM;
	for (size_t p = 0; p < r->npatch; p++)
		for (long i = 0; i < N; i++)
			for (long j = 0; j < N; j++) {
				size_t a = p * nn + (size_t)i * (N + 1) + j;
				size_t b = a + N + 1;
				size_t t[2][3] = { { a, b, b + 1 },
				    { a, b + 1, a + 1 } };

				for (int h = 0; h < 2; h++) {
					size_t w[3];

					for (int k = 0; k < 3; k++)
						w[k] = r->grid[t[h][k]];
					if (w[0] == w[1] || w[1] == w[2] ||
					    w[0] == w[2])
						continue;
					for (int k = 0; k < 3; k++) {
						struct bside *e = &s[ns++];

						e->a = w[k];
						e->b = w[(k + 1) % 3];
						e->na = t[h][k];
						e->nb = t[h][(k + 1) % 3];
						e->used = 0;
					}
				}
			}
	qsort(s, ns, sizeof *s, by_key);
	for (size_t i = 0; i < ns; ) {
		size_t j = i + 1;

		while (j < ns && by_key(&s[i], &s[j]) == 0)
			j++;
		if (j == i + 1)
			s[nb++] = s[i];
		i = j;
	}
	*out = s;
	*n = nb;
	return 0;
}

/* The boundary loops as sequences of sides, one after another (dir:
 * the side runs b to a); each loop ends with a side of index nb. */
static int
chain(struct bside *s, size_t nb, size_t nv, size_t *seq, int *dir,
    size_t *nseq)
{
	size_t *at = malloc((2 * nv + 1) * sizeof *at), n = 0;

	if (at == NULL)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < 2 * nv; i++)
		at[i] = (size_t)-1;
	for (size_t k = 0; k < nb; k++)
		for (int e = 0; e < 2; e++) {
			size_t v = e ? s[k].b : s[k].a;

			at[2 * v + (at[2 * v] != (size_t)-1)] = k;
		}
	for (size_t k0 = 0; k0 < nb; k0++) {
		size_t k = k0, end;

		if (s[k0].used)
			continue;
		end = s[k0].a;
		for (int d = 0;;) {
			size_t v = d ? s[k].a : s[k].b, next = (size_t)-1;

			s[k].used = 1;
			seq[n] = k;
			dir[n++] = d;
			if (v == end)
				break;
			for (int q = 0; q < 2; q++)
				if (at[2 * v + q] != (size_t)-1 &&
				    !s[at[2 * v + q]].used)
					next = at[2 * v + q];
			if (next == (size_t)-1)
				break;
			k = next;
			d = s[k].b == v;
		}
		seq[n] = nb;
		dir[n++] = 0;
	}
	*nseq = n;
	free(at);
	return 0;
}

/* The flat image of node k's parameter step to node l, at node k. */
static void
tangent(const struct loft_unroll *r, size_t k, size_t l, double *t)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1), w = (size_t)r->N + 1;
	double du = ((double)(l % nn / w) - (double)(k % nn / w)) / r->N;
	double dv = ((double)(l % nn % w) - (double)(k % nn % w)) / r->N;
	const double *J = r->jac + 4 * k;

	t[0] = J[0] * du + J[2] * dv;
	t[1] = J[1] * du + J[3] * dv;
}

/* Write the loop seq[0..n) as Hermite segments, reversed when rev. */
static int
write_loop(struct loft_unroll *r, const struct bside *s, const size_t *seq,
    const int *dir, size_t n, int rev)
{
	if ((r->seg = malloc((8 * n + 1) * sizeof *r->seg)) == NULL)
		return LOFT_ENOMEM;
	r->nseg = n;
	for (size_t q = 0; q < n; q++) {
		size_t i = rev ? n - 1 - q : q;
		const struct bside *e = &s[seq[i]];
		int d = dir[i] ^ rev;
		size_t A = d ? e->b : e->a, B = d ? e->a : e->b;
		size_t nA = d ? e->nb : e->na, nB = d ? e->na : e->nb;
		double *g = r->seg + 8 * q;

		vcopy(g, r->xy + 2 * A, 2);
		vcopy(g + 2, r->xy + 2 * B, 2);
		tangent(r, nA, nB, g + 4);
		tangent(r, nB, nA, g + 6);
		vscale(g + 6, -1, g + 6, 2);
	}
	return 0;
}

/* The outline: the boundary loop of largest area, counter-clockwise. */
static int
outline(struct loft_unroll *r, struct loft_error *err)
{
	struct bside *s = NULL;
	size_t nb = 0, *seq = NULL, best = 0, bestn = 0, start = 0, nseq = 0;
	int *dir = NULL, rc;
	double most = -1, sign = 1;

	if ((rc = boundary_sides(r, &s, &nb)) == 0 &&
	    ((seq = malloc((2 * nb + 1) * sizeof *seq)) == NULL ||
	    (dir = malloc((2 * nb + 1) * sizeof *dir)) == NULL))
		rc = LOFT_ENOMEM;
	if (rc == 0)
		rc = chain(s, nb, r->mesh.nv, seq, dir, &nseq);
	for (size_t i = 0; rc == 0 && i < nseq; i++) {
		double area = 0;

		if (seq[i] != nb)
			continue;
		for (size_t q = start; q < i; q++) {
			const double *a = r->xy + 2 * s[seq[q]].a;
			const double *b = r->xy + 2 * s[seq[q]].b;

			area += (dir[q] ? -1 : 1) * (a[0] * b[1] - a[1] * b[0]);
		}
		if (fabs(area) > most) {
			most = fabs(area);
			best = start;
			bestn = i - start;
			sign = area;
		}
		start = i + 1;
	}
	if (rc == 0 && bestn < 2)
		rc = loft_fail(err, LOFT_EGEOM, -1, "the sheet has no outline "
		    "(it is closed)");
	if (rc == 0)
		rc = write_loop(r, s, seq + best, dir + best, bestn, sign < 0);
	free(s);
	free(seq);
	free(dir);
	return rc;
}

/* r's lengths (the mesh in space and flat, the flat map's derivatives,
 * the outline) times 2^e and its areas times 4^e: the sheet unrolled
 * near unit size brought back to its own.  0, or LOFT_EGEOM (and err
 * says so) where a number of r is then no double: a length or an area
 * overflows, an area underflows (below DBL_MIN), or a curvature of
 * r->num overflows. */
static int
rescale(struct loft_unroll *r, int e, struct loft_error *err)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1) * r->npatch;
	struct {
		double *x;
		size_t n;
	} len[4] = { { r->mesh.v, 3 * r->mesh.nv }, { r->xy, 2 * r->mesh.nv },
	    { r->jac, 4 * nn }, { r->seg, 8 * r->nseg } };

	for (int k = 0; k < 4; k++)
		vpow2(len[k].x, len[k].n, e);
	r->area3 = ldexp(r->area3, 2 * e);
	r->area2 = ldexp(r->area2, 2 * e);
	for (int k = 0; k < 4; k++)
		for (size_t i = 0; i < len[k].n; i++)
			if (!isfinite(len[k].x[i]))
				return loft_fail(err, LOFT_EGEOM, -1, "the sheet "
				    "overflows: coefficients too large");
	if (isinf(r->area3) || isinf(r->area2))
		return loft_fail(err, LOFT_EGEOM, -1, "the sheet's area "
		    "overflows: coefficients too large");
	if (fpclassify(r->area3) != FP_NORMAL ||
	    fpclassify(r->area2) != FP_NORMAL)
		return loft_fail(err, LOFT_EGEOM, -1, "the sheet's area "
		    "underflows: coefficients too small");
	if (!isfinite(r->num.kmin.value) || !isfinite(r->num.kmax.value) ||
	    !isfinite(r->num.hmin.value) || !isfinite(r->num.hmax.value))
		return loft_fail(err, LOFT_EGEOM, -1, "the sheet's curvature "
		    "overflows: coefficients too small");
	return 0;
}

/* The sheet of the ns surfaces s, which sheet_size says is size units
 * across (> 0), unrolled at 2^-e times its size, near 1 (frexp), so
 * that no product of its lengths overflows or underflows (E G - F^2
 * goes as the fourth power): a sheet 1e-90 or 1e90 units across came
 * out developed wrong, by its curvature read as 0. */
static int
unroll_scaled(const struct loft_unroll_opts *o, const struct loft_surface *s,
    size_t ns, double size, struct loft_unroll *r, struct loft_error *err)
{
	struct loft_surface *ss = malloc(ns * sizeof *ss);
	int e, rc;
	double unit = frexp(size, &e);  /* the size scaled: 0.5 to 1 */

	if (ss == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < ns; i++)
		loft_surface_scaled(&s[i], -e, &ss[i]);
	r->N = o->steps > 0 ? o->steps : steps_for(ss, ns, o->tol > 0 ?
	    ldexp(o->tol, -e) : LOFT_UNROLL_RELTOL * unit);
	if ((rc = make_mesh(r, ss, ns, unit, err)) != 0) {
		free(ss);
		return rc;
	}
	r->exact = r->num.developable && !o->arap;
	rc = develop(r, ss);
	if (rc == 0 && !r->exact) {
		rc = arap(r, o->rounds > 0 ? o->rounds : LOFT_UNROLL_ROUNDS);
		grid_jacobians(r);
	}
	if (rc == 0)
		rc = strains(r);
	if (rc == 0)
		rc = outline(r, err);
	free(ss);
	if (rc == LOFT_ENOMEM)
		return loft_fail(err, rc, -1, "out of memory");
	return rc == 0 ? rescale(r, e, err) : rc;
}

int
loft_unroll(const struct loft_unroll_opts *o, const struct loft_surface *s,
    size_t ns, struct loft_unroll *r, struct loft_error *err)
{
	double size;

	memset(r, 0, sizeof *r);
	if (ns == 0 || !(o->tol >= 0) || !isfinite(o->tol))
		return loft_fail(err, LOFT_EINPUT, -1, ns == 0 ? "no surface" :
		    "the tolerance must be a number from 0");
	size = sheet_size(s, ns);
	if (!(size > 0) || !isfinite(size))
		return loft_fail(err, LOFT_EGEOM, -1, !(size > 0) ? "the "
		    "surface is a point" : "the surface overflows: "
		    "coefficients too large");
	loft_surface_numbers(s, ns, ns > 16 ? 2 : 8, &r->num);
	return unroll_scaled(o, s, ns, size, r, err);
}

void
loft_unroll_hermite(const struct loft_unroll *r, size_t p, const double *a,
    const double *b, double *seg)
{
	size_t nn = (size_t)(r->N + 1) * (r->N + 1), ka, kb;

	ka = p * nn + (size_t)floor(a[0] * r->N + 0.5) * (r->N + 1) +
	    (size_t)floor(a[1] * r->N + 0.5);
	kb = p * nn + (size_t)floor(b[0] * r->N + 0.5) * (r->N + 1) +
	    (size_t)floor(b[1] * r->N + 0.5);
	vcopy(seg, r->xy + 2 * r->grid[ka], 2);
	vcopy(seg + 2, r->xy + 2 * r->grid[kb], 2);
	tangent(r, ka, kb, seg + 4);
	tangent(r, kb, ka, seg + 6);
	vscale(seg + 6, -1, seg + 6, 2);
}

/* The point where the plane cuts side a-b (signed distances da, db),
 * flat. */
static void
cut_point(const struct loft_unroll *r, size_t a, size_t b, double da,
    double db, double *q)
{
	double t;

	if (b < a) {            /* from the lower end: one point for both */
		size_t x = a;   /* triangles of the side */
		double y = da;

		a = b;
		b = x;
		da = db;
		db = y;
	}
	t = da / (da - db);
	q[0] = r->xy[2 * a] + t * (r->xy[2 * b] - r->xy[2 * a]);
	q[1] = r->xy[2 * a + 1] + t * (r->xy[2 * b + 1] - r->xy[2 * a + 1]);
}

/* A piece of a cut: the sides (keys of their ends) it joins, flat. */
struct piece {
	size_t k[2][2];
	double q[4];
	int used;
};

static int
same_key(const size_t *a, const size_t *b)
{
	return a[0] == b[0] && a[1] == b[1];
}

/* Grow curve c by one point q.  0 or LOFT_ENOMEM. */
static int
cut_add(struct loft_cut_curve *c, size_t *cap, const double *q)
{
	if (loft__grow((void **)&c->p, cap, 2 * (c->n + 1), sizeof *c->p))
		return LOFT_ENOMEM;
	vcopy(c->p + 2 * c->n++, q, 2);
	return 0;
}

/* Extend curve c from the end whose side is key by unused pieces. */
static int
extend(struct piece *pc, size_t n, struct loft_cut_curve *c, size_t *cap,
    const size_t *key)
{
	int rc = 0;

	for (int more = 1; rc == 0 && more; ) {
		more = 0;
		for (size_t j = 0; j < n && !more; j++)
			for (int e = 0; e < 2 && !pc[j].used; e++)
				if (same_key(pc[j].k[e], key)) {
					pc[j].used = more = 1;
					rc = cut_add(c, cap, pc[j].q + 2 * (1 - e));
					key = pc[j].k[1 - e];
					break;
				}
	}
	return rc;
}

/* Chain the pieces into curves, appended to out: from each unused
 * piece forward, then the curve turned round and on from its start. */
static int
chain_pieces(struct piece *pc, size_t n, struct loft_cut *out)
{
	for (size_t i = 0; i < n; i++) {
		struct loft_cut_curve c = { NULL, 0, 0 };
		size_t cap = 0, m;
		int rc;

		if (pc[i].used)
			continue;
		pc[i].used = 1;
		rc = cut_add(&c, &cap, pc[i].q) || cut_add(&c, &cap, pc[i].q + 2) ||
		    extend(pc, n, &c, &cap, pc[i].k[1]);
		m = c.n;
		for (size_t k = 0; rc == 0 && k < m / 2; k++)
			for (int d = 0; d < 2; d++) {
				double t = c.p[2 * k + d];

				c.p[2 * k + d] = c.p[2 * (m - 1 - k) + d];
				c.p[2 * (m - 1 - k) + d] = t;
			}
		if (rc == 0)
			rc = extend(pc, n, &c, &cap, pc[i].k[0]);
		c.closed = c.n > 3 && vdist(c.p, c.p + 2 * (c.n - 1), 2) == 0;
		if (c.closed)
			c.n--;
		if (rc != 0 || loft__grow((void **)&out->c, &out->cap, out->n + 1,
		    sizeof *out->c) != 0) {
			free(c.p);
			return LOFT_ENOMEM;
		}
		out->c[out->n++] = c;
	}
	return 0;
}

int
loft_unroll_cut(const struct loft_unroll *r, const double *normal, double d,
    struct loft_cut *out)
{
	const struct loft_mesh *me = &r->mesh;
	struct piece *pc = NULL;
	size_t n = 0, cap = 0;
	int rc = 0;

	out->dim = 2;
	for (size_t t = 0; rc == 0 && t < me->nt; t++) {
		const size_t *v = me->t + 3 * t;
		double s[3];
		int m = 0;
		struct piece x;

		memset(&x, 0, sizeof x);
		for (int k = 0; k < 3; k++)
			s[k] = vdot(me->v + 3 * v[k], normal, 3) - d;
		for (int k = 0; k < 3 && m < 2; k++) {
			size_t a = v[k], b = v[(k + 1) % 3];
			double sa = s[k], sb = s[(k + 1) % 3];

			if ((sa < 0) == (sb < 0))
				continue;
			/* through a vertex: the vertex is the key */
			if (sa == 0 || sb == 0)
				a = b = sa == 0 ? a : b;
			x.k[m][0] = a < b ? a : b;
			x.k[m][1] = a < b ? b : a;
			cut_point(r, v[k], v[(k + 1) % 3], sa, sb, x.q + 2 * m);
			m++;
		}
		if (m < 2 || same_key(x.k[0], x.k[1]))
			continue;
		x.used = 0;
		if (loft__grow((void **)&pc, &cap, n + 1, sizeof *pc) != 0)
			rc = LOFT_ENOMEM;
		else
			pc[n++] = x;
	}
	if (rc == 0)
		rc = chain_pieces(pc, n, out);
	free(pc);
	return rc;
}

void
loft_unroll_free(struct loft_unroll *r)
{
	loft_mesh_free(&r->mesh);
	free(r->xy);
	free(r->grid);
	free(r->jac);
	free(r->seg);
	memset(r, 0, sizeof *r);
}
