/*
 * patch.c: tests of MacCallum's quartics and bi-quartic patches (1970).
 * References come from outside the code under test: the defining
 * constraints of the H functions (section 3), polynomials written in the
 * power basis and differentiated here, H5(x) = 16 x^2 (1 - x)^2 by hand,
 * the parent patch for its split children, and invariants (positions
 * and scaled cross derivatives equal across every edge).
 */
#include <stdlib.h>
#include <string.h>

#include "loft.h"
#include "check.h"

#define IDX(i, j, dim) ((5 * (i) + (j)) * (dim))

static unsigned long long rng = 0x9E3779B97F4A7C15ULL;

/* A uniform number in [lo, hi) (xorshift64). */
static double
rnd(double lo, double hi)
{
	rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
	return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

static double
h5(double x)
{
	return 16 * x * x * (1 - x) * (1 - x);
}

static double
dist(const double *a, const double *b, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++)
		s += (a[k] - b[k]) * (a[k] - b[k]);
	return sqrt(s);
}

static double
norm(const double *a, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++)
		s += a[k] * a[k];
	return sqrt(s);
}

/* ------------------------------------------------------------------ */
/* H functions and quartic curves */

/* Section 3: d^p H_j / du^p at u_i is 1 when i = j, else 0, for the
 * coefficients (0), (1), (0)_u, (1)_u, (h): exact at these points. */
static void
test_h_constraints(void)
{
	static const double at[5] = { 0, 1, 0, 1, 0.5 };
	static const int slope[5] = { 0, 0, 1, 1, 0 };
	double h[5], dh[5];

	for (int i = 0; i < 5; i++) {
		loft_quartic_h(at[i], h, dh, NULL);
		for (int j = 0; j < 5; j++)
			CHECK((slope[i] ? dh[j] : h[j]) == (i == j),
			    "H%d %s at %g is %g, want %d", j + 1,
			    slope[i] ? "slope" : "value", at[i],
			    slope[i] ? dh[j] : h[j], i == j);
	}
	/* H5 by hand, and the derivatives by central differences */
	for (int k = 0; k <= 20; k++) {
		double u = k / 20.0, d = 1e-5, hp[5], hm[5], d2[5];

		loft_quartic_h(u, h, dh, d2);
		NEAR(h[4], h5(u), 1e-14, "H5 = 16u^2(1-u)^2");
		NEAR(h[0] + h[1] + h[4], 1, 1e-14, "H1 + H2 + H5 = 1");
		loft_quartic_h(u + d, hp, NULL, NULL);
		loft_quartic_h(u - d, hm, NULL, NULL);
		for (int j = 0; j < 5; j++)
			NEAR(dh[j], (hp[j] - hm[j]) / (2 * d), 1e-8, "H'");
		loft_quartic_h(u + d, NULL, hp, NULL);
		loft_quartic_h(u - d, NULL, hm, NULL);
		for (int j = 0; j < 5; j++)
			NEAR(d2[j], (hp[j] - hm[j]) / (2 * d), 1e-7, "H''");
	}
}

/* A quartic p(u) = sum c_a u^a: its five coefficients by hand. */
static void
power_to_quartic(const double *c, double *q)
{
	q[0] = c[0];
	q[1] = c[0] + c[1] + c[2] + c[3] + c[4];
	q[2] = c[1];
	q[3] = c[1] + 2 * c[2] + 3 * c[3] + 4 * c[4];
	q[4] = c[0] + c[1] / 2 + c[2] / 4 + c[3] / 8 + c[4] / 16;
}

static void
test_quartic_eval(void)
{
	double worst = 0;

	for (int n = 0; n < 200; n++) {
		double c[5], q[5], p, d1, d2, u = rnd(0, 1);

		for (int a = 0; a < 5; a++)
			c[a] = rnd(-10, 10);
		power_to_quartic(c, q);
		loft_quartic_eval(q, 1, u, &p, &d1, &d2);
		worst = fmax(worst, fabs(p - ((((c[4] * u + c[3]) * u + c[2]) *
		    u + c[1]) * u + c[0])));
		NEAR(d1, ((4 * c[4] * u + 3 * c[3]) * u + 2 * c[2]) * u + c[1],
		    1e-11, "quartic slope");
		NEAR(d2, (12 * c[4] * u + 6 * c[3]) * u + 2 * c[2], 1e-10,
		    "quartic second derivative");
		loft_quartic_eval(q, 1, 0.5, &p, NULL, NULL);
		CHECK(p == q[4], "exact at u = 1/2");
		loft_quartic_eval(q, 1, 1, &p, NULL, NULL);
		CHECK(p == q[1], "exact at u = 1");
	}
	CHECK(worst < 1e-12, "quartic value: worst %g", worst);
}

/* A cubic is the quartic with (h) its point at 1/2. */
static void
test_cubic_to_quartic(void)
{
	for (int n = 0; n < 50; n++) {
		double cubic[12], q[15], a[3], b[3], da[3], db[3], u = rnd(0, 1);

		for (int k = 0; k < 12; k++)
			cubic[k] = rnd(-5, 5);
		loft_cubic_to_quartic(cubic, 3, q);
		loft_cubic_eval(cubic, 3, u, a, da, NULL);
		loft_quartic_eval(q, 3, u, b, db, NULL);
		CHECK(dist(a, b, 3) < 1e-13 && dist(da, db, 3) < 1e-12,
		    "cubic as quartic at u = %g: %g", u, dist(a, b, 3));
	}
}

/* ------------------------------------------------------------------ */
/* Patches */

/* A bi-quartic sum c[a][b][k] u^a v^b: point and partials. */
static void
power_eval(double c[5][5][3], int dim, double u, double v, int du, int dv,
    double *p)
{
	for (int k = 0; k < dim; k++) {
		p[k] = 0;
		for (int a = du; a < 5; a++)
			for (int b = dv; b < 5; b++) {
				double t = c[a][b][k];

				for (int i = 0; i < du; i++)
					t *= a - i;
				for (int i = 0; i < dv; i++)
					t *= b - i;
				p[k] += t * pow(u, a - du) * pow(v, b - dv);
			}
	}
}

/* B of a power-basis patch, from section 4's definition of its entries. */
static void
power_to_patch(double c[5][5][3], int dim, double *b)
{
	static const double at[5] = { 0, 1, 0, 1, 0.5 };
	static const int der[5] = { 0, 0, 1, 1, 0 };

	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 5; j++)
			power_eval(c, dim, at[i], at[j], der[i], der[j],
			    b + IDX(i, j, dim));
}

static void
test_patch_eval(void)
{
	double c[5][5][3], b[75], p[3], du[3], dv[3], r[3];

	for (int n = 0; n < 20; n++) {
		for (int a = 0; a < 5; a++)
			for (int e = 0; e < 5; e++)
				for (int k = 0; k < 3; k++)
					c[a][e][k] = rnd(-3, 3);
		power_to_patch(c, 3, b);
		for (int m = 0; m < 20; m++) {
			double u = rnd(0, 1), v = rnd(0, 1);

			loft_patch_eval(b, 3, u, v, p, du, dv);
			power_eval(c, 3, u, v, 0, 0, r);
			CHECK(dist(p, r, 3) < 1e-11, "patch point %g", dist(p, r,
			    3));
			power_eval(c, 3, u, v, 1, 0, r);
			CHECK(dist(du, r, 3) < 1e-10, "patch f_u %g", dist(du, r,
			    3));
			power_eval(c, 3, u, v, 0, 1, r);
			CHECK(dist(dv, r, 3) < 1e-10, "patch f_v %g", dist(dv, r,
			    3));
		}
	}
}

static void
random_patch(double *b, int dim, double scale)
{
	for (int k = 0; k < 25 * dim; k++)
		b[k] = rnd(-scale, scale);
}

/* Section 5: the halves are the parent, at random t and points. */
static double split_worst;

static void
test_split_identity(void)
{
	double b[75], b1[75], b2[75], p[3], q[3];

	for (int n = 0; n < 400; n++) {
		int dim = n % 2 ? 3 : 2, dir = (n / 2) % 2;
		double t = rnd(0.01, 0.99), size;

		random_patch(b, dim, n % 3 == 0 ? 1e3 : 1);
		if (n % 5 == 0)         /* far from the origin */
			for (int k = 0; k < 2 * dim; k++)
				b[k] += 1e4;
		size = loft_patch_size(b, dim);
		loft_patch_split_coef(b, dim, dir, t, b1, b2);
		for (int m = 0; m < 50; m++) {
			double s = rnd(0, 1), w = rnd(0, 1);
			double u1 = dir == 0 ? s * t : w, v1 = dir == 0 ? w : s * t;
			double u2 = dir == 0 ? t + s * (1 - t) : w,
			    v2 = dir == 0 ? w : t + s * (1 - t);

			loft_patch_eval(b1, dim, dir == 0 ? s : w,
			    dir == 0 ? w : s, p, NULL, NULL);
			loft_patch_eval(b, dim, u1, v1, q, NULL, NULL);
			split_worst = fmax(split_worst, dist(p, q, dim) / size);
			loft_patch_eval(b2, dim, dir == 0 ? s : w,
			    dir == 0 ? w : s, p, NULL, NULL);
			loft_patch_eval(b, dim, u2, v2, q, NULL, NULL);
			split_worst = fmax(split_worst, dist(p, q, dim) / size);
		}
		/* the common edge: the same numbers in both halves */
		for (int k = 0; k < 5; k++) {
			const double *x = dir == 0 ? b1 + IDX(1, k, dim) :
			    b1 + IDX(k, 1, dim);
			const double *y = dir == 0 ? b2 + IDX(0, k, dim) :
			    b2 + IDX(k, 0, dim);

			CHECK(memcmp(x, y, dim * sizeof *x) == 0,
			    "common edge entry %d differs", k);
		}
	}
	CHECK(split_worst < 1e-12, "split identity: worst %g of the size",
	    split_worst);
	printf("split identity: largest |f_child - f_parent| = %.3g of the "
	    "patch size (400 patches x 100 points)\n", split_worst);
}

/* ------------------------------------------------------------------ */
/* Designs: an independent check of every edge */

static int
normal_of(int e)
{
	return e == LOFT_U0 || e == LOFT_U1 ? 0 : 1;
}

/* The point of p on edge e at edge parameter s, and the derivative
 * across the edge, in the common parameter, pointing out of p. */
static void
edge_point(const struct loft_patch *p, int e, double s, double *x,
    double *out)
{
	double d[2][3], at = e == LOFT_U0 || e == LOFT_V0 ? 0 : 1;
	int n = normal_of(e);

	loft_patch_eval(p->b, p->dim, n == 0 ? at : s, n == 0 ? s : at, x,
	    d[0], d[1]);
	for (int k = 0; k < p->dim; k++)
		out[k] = (at == 0 ? -1 : 1) * d[n][k] / p->scale[n];
}

static double cont_pos, cont_slope;

/* Every link of d: positions equal and slopes continuous along it.
 * Returns the number of links seen. */
static int
check_continuity(const struct loft_design *d, double size, const char *what)
{
	int links = 0, dangling = 0, oneway = 0;
	double pos = 0, slope = 0;

	for (size_t i = 0; i < d->n; i++)
		for (int e = 0; e < 4; e++)
			for (size_t k = 0; k < d->p[i].nlink[e]; k++) {
				const struct loft_patch *p = &d->p[i], *q;
				const struct loft_link *l = &p->link[e][k], *m = NULL;
				long qi = loft_design_find(d, l->id);
				int f = 0;

				if (qi < 0) {
					dangling++;
					continue;
				}
				q = &d->p[qi];
				for (f = 0; f < 4 && m == NULL; f++)
					for (size_t r = 0; r < q->nlink[f]; r++)
						if (q->link[f][r].id == p->id)
							m = &q->link[f][r];
				f--;
				if (m == NULL) {
					oneway++;
					continue;
				}
				links++;
				for (int j = 0; j <= 10; j++) {
					double s = l->a + (l->b - l->a) * j / 10;
					double lo = fmin(m->a, m->b), hi = fmax(m->a,
					    m->b), sq = lo + (hi - lo) * j / 10;
					double x[3], y[3], gx[3], gy[3];

					edge_point(p, e, s, x, gx);
					edge_point(q, f, sq, y, gy);
					pos = fmax(pos, dist(x, y, p->dim) / size);
					/* out of p is into q: gy is negated */
					for (int c = 0; c < p->dim; c++)
						gy[c] = -gy[c];
					slope = fmax(slope, dist(gx, gy, p->dim) /
					    fmax(norm(gx, p->dim), 1e-300));
				}
			}
	CHECK(dangling == 0, "%s: %d links dangle", what, dangling);
	CHECK(oneway == 0, "%s: %d links have none back", what, oneway);
	CHECK(pos < 1e-12, "%s: edges apart by %g of the size", what, pos);
	CHECK(slope < 1e-10, "%s: slopes differ by %g", what, slope);
	cont_pos = fmax(cont_pos, pos);
	cont_slope = fmax(cont_slope, slope);
	return links;
}

/* Where each patch of a design lies in the first patch's parameter
 * square, kept alongside the splits: u0 u1 v0 v1. */
struct region { double r[4]; };

static void
split_tracked(struct loft_design *d, struct region *reg, size_t i, int dir,
    double t)
{
	struct loft_error err;
	struct region a = reg[i], b = reg[i];
	double lo = a.r[2 * dir], hi = a.r[2 * dir + 1];

	CHECK(loft_design_split(d, i, dir, t, &err) == 0, "split: %s",
	    err.msg);
	a.r[2 * dir + 1] = b.r[2 * dir] = lo + t * (hi - lo);
	reg[i] = a;             /* the first half in place, the second last */
	reg[d->n - 1] = b;
}

/* The design against the original patch b0 at points of each region. */
static double
check_identity(const struct loft_design *d, const struct region *reg,
    const double *b0, double size)
{
	double worst = 0, x[3], y[3];

	for (size_t i = 0; i < d->n; i++)
		for (int m = 0; m < 30; m++) {
			double s = rnd(0, 1), w = rnd(0, 1);
			const double *r = reg[i].r;

			loft_patch_eval(d->p[i].b, d->p[i].dim, s, w, x, NULL,
			    NULL);
			loft_patch_eval(b0, d->p[i].dim, r[0] + s * (r[1] - r[0]),
			    r[2] + w * (r[3] - r[2]), y, NULL, NULL);
			worst = fmax(worst, dist(x, y, 3) / size);
		}
	return worst;
}

/* A curved first patch: Coons' patch of four bent boundaries. */
static void
hull_patch(double *b)
{
	static const double c[4][15] = {
		/* v = 0 in u: (0) (1) (0)_u (1)_u (h) */
		{ 0, 0, 0, 6, 0, 0, 6, 0, 1, 6, 0, -1, 3, 0, 0.6 },
		/* v = 1 */
		{ 0, 4, 0.5, 6, 4, 0.5, 6, 0.5, 0, 6, -0.5, 0, 3, 4.2, 1 },
		/* u = 0 in v */
		{ 0, 0, 0, 0, 4, 0.5, 0, 4, -1, 0, 4, 1, 0.3, 2, 0 },
		/* u = 1 */
		{ 6, 0, 0, 6, 4, 0.5, 0, 4, 0, 0, 4, 0, 6.2, 2, 0.4 },
	};
	const double *cp[4] = { c[0], c[1], c[2], c[3] };
	struct loft_error err;

	CHECK(loft_patch_coons(cp, 3, b, &err) == 0, "coons: %s", err.msg);
}

/* Fig. 4: one patch split into six (3 x 2), every edge continuous. */
static void
test_fig4(void)
{
	struct loft_design d = { 0 };
	struct region reg[8] = { { { 0, 1, 0, 1 } } };
	struct loft_error err;
	double b0[75], size, worst;
	int links, full = 1;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	split_tracked(&d, reg, 0, 0, 1.0 / 3);
	split_tracked(&d, reg, 1, 0, 0.5);
	for (size_t i = 0; i < 3; i++)   /* each column; halves go last */
		split_tracked(&d, reg, i, 1, 0.5);
	CHECK(d.n == 6, "Fig. 4: %zu patches", d.n);
	CHECK(loft_design_check(&d, &(size_t){ 0 }, &err) == 0, "Fig. 4: %s",
	    err.msg);
	links = check_continuity(&d, size, "Fig. 4");
	/* 3 x 2 grid: 4 edges across u, 3 across v, each seen from both */
	CHECK(links == 14, "Fig. 4: %d links, want 14", links);
	for (size_t i = 0; i < d.n; i++) {
		NEAR(d.p[i].scale[0], 1.0 / 3, 1e-15, "Fig. 4 su");
		NEAR(d.p[i].scale[1], 0.5, 0, "Fig. 4 sv");
		for (int e = 0; e < 4; e++)
			for (size_t k = 0; k < d.p[i].nlink[e]; k++)
				full &= d.p[i].link[e][k].a == 0 &&
				    d.p[i].link[e][k].b == 1;
	}
	CHECK(full, "Fig. 4: a regular grid has whole-edge links only");
	worst = check_identity(&d, reg, b0, size);
	CHECK(worst < 1e-12, "Fig. 4 identity: %g", worst);
	/* a central drag in one patch moves that patch's (hh) alone */
	{
		struct loft_design e = { 0 };
		struct loft_drag_info info;
		double delta[3] = { 0, 0, 0.2 };

		for (size_t i = 0; i < d.n; i++)
			loft_design_new(&e, d.p[i].b, 3, d.p[i].id, &err);
		CHECK(loft_design_drag(&d, 2, 0.5, 0.5, delta, 0.25, &info,
		    &err) == 0 && info.rule == LOFT_DRAG_CENTRAL,
		    "Fig. 4 central drag");
		for (size_t i = 0; i < d.n; i++)
			for (int k = 0; k < 75; k++)
				if (!(i == 2 && k >= IDX(4, 4, 3)))
					CHECK(d.p[i].b[k] == e.p[i].b[k],
					    "Fig. 4 drag: patch %zu entry %d moved",
					    i, k);
		loft_design_free(&e);
	}
	loft_design_free(&d);
}

/* Fig. 5: irregular splitting, T-junctions, links with parts of edges. */
static void
test_fig5(void)
{
	struct loft_design d = { 0 };
	struct region reg[8] = { { { 0, 1, 0, 1 } } };
	struct loft_error err;
	double b0[75], size;
	const struct loft_patch *p;
	int links;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	split_tracked(&d, reg, 0, 0, 0.4);     /* 2 | 3 */
	split_tracked(&d, reg, 1, 1, 0.5);     /* 3 -> 4 (v < 1/2), 5 */
	split_tracked(&d, reg, 1, 0, 0.3);     /* 4 -> 6, 7 */
	split_tracked(&d, reg, 0, 1, 0.25);    /* 2 -> 8, 9 */
	CHECK(d.n == 5, "Fig. 5: %zu patches", d.n);
	CHECK(loft_design_check(&d, &(size_t){ 0 }, &err) == 0, "Fig. 5: %s",
	    err.msg);
	/* patch 9 (u < 0.4, v > 0.25): across u1 lie 6 (v 0.25..0.5 of
	 * the square) and 5 (0.5..1), on its own edge 0..1/3 and 1/3..1 */
	p = &d.p[loft_design_find(&d, 9)];
	CHECK(p->nlink[LOFT_U1] == 2, "Fig. 5: 9 has %zu neighbours on u1",
	    p->nlink[LOFT_U1]);
	if (p->nlink[LOFT_U1] == 2) {
		CHECK(p->link[LOFT_U1][0].id == 6 && p->link[LOFT_U1][1].id == 5,
		    "Fig. 5: 9's u1 neighbours %ld %ld",
		    p->link[LOFT_U1][0].id, p->link[LOFT_U1][1].id);
		NEAR(p->link[LOFT_U1][0].b, 1.0 / 3, 1e-15, "T-junction at 1/3");
	}
	links = check_continuity(&d, size, "Fig. 5");
	/* 8-9, 8-6, 9-6, 9-5, 6-7, 6-5, 7-5, each seen from both sides */
	CHECK(links == 14, "Fig. 5: %d links, want 14", links);
	NEAR(check_identity(&d, reg, b0, size), 0, 1e-12, "Fig. 5 identity");
	loft_design_free(&d);
}

/* Every patch split in turn, many times: links stay consistent. */
static void
test_split_everywhere(void)
{
	struct loft_design d = { 0 };
	struct region reg[80] = { { { 0, 1, 0, 1 } } };
	struct loft_error err;
	double b0[75], size;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	for (int n = 0; n < 30; n++)
		split_tracked(&d, reg, (size_t)rnd(0, (double)d.n), n % 2,
		    rnd(0.1, 0.9));
	CHECK(loft_design_check(&d, &(size_t){ 0 }, &err) == 0,
	    "30 random splits: %s", err.msg);
	check_continuity(&d, size, "30 random splits");
	NEAR(check_identity(&d, reg, b0, size), 0, 1e-12,
	    "30 random splits: identity");
	loft_design_free(&d);
}

/*
 * A large design: one patch cut into a 160 x 125 grid (20000 patches,
 * 19999 splits), then every patch split again (40000).  Invariants, no
 * timing: the grid's count of links, every link continuous, the design
 * identical to the first patch, every id found where it is, the ids of
 * split patches gone.  Linear lookups made this minutes of work.
 */
static void
test_large_design(void)
{
	enum { NU = 160, NV = 125 };
	struct loft_design d = { 0 };
	struct region *reg = malloc(2 * NU * NV * sizeof *reg);
	struct loft_error err;
	double b0[75], size;
	size_t n0, found = 0, whole = 0;
	double scale_err = 0;
	int links;

	CHECK(reg != NULL, "large design: out of memory");
	if (reg == NULL)
		return;
	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	reg[0] = (struct region){ { 0, 1, 0, 1 } };
	/* columns: cut one off the rest, which goes last, each time */
	for (int k = 0; k < NU - 1; k++)
		split_tracked(&d, reg, d.n - 1, 0, 1.0 / (NU - k));
	/* rows of column c, which is patch c: the same down the rest */
	for (size_t c = 0; c < NU; c++)
		for (int k = 0; k < NV - 1; k++)
			split_tracked(&d, reg, k == 0 ? c : d.n - 1, 1,
			    1.0 / (NV - k));
	CHECK(d.n == NU * NV, "large design: %zu patches", d.n);
	CHECK(loft_design_check(&d, &(size_t){ 0 }, &err) == 0,
	    "large design: %s", err.msg);
	links = check_continuity(&d, size, "large design");
	CHECK(links == 2 * ((NU - 1) * NV + NU * (NV - 1)),
	    "large design: %d links", links);
	for (size_t i = 0; i < d.n; i++) {
		scale_err = fmax(scale_err, fmax(fabs(d.p[i].scale[0] * NU - 1),
		    fabs(d.p[i].scale[1] * NV - 1)));
		for (int e = 0; e < 4; e++)
			for (size_t k = 0; k < d.p[i].nlink[e]; k++)
				whole += d.p[i].link[e][k].a == 0 &&
				    d.p[i].link[e][k].b == 1;
	}
	CHECK(scale_err < 1e-12, "large design: scale factors 1/%d, 1/%d "
	    "within %g", NU, NV, scale_err);
	CHECK(whole == (size_t)links, "large design: %zu of %d links are "
	    "whole edges", whole, links);
	/* every patch split across v: 40000 */
	n0 = d.n;
	for (size_t i = 0; i < n0; i++)
		split_tracked(&d, reg, i, 1, 0.5);
	CHECK(d.n == 2 * n0, "large design split: %zu patches", d.n);
	CHECK(loft_design_check(&d, &(size_t){ 0 }, &err) == 0,
	    "large design split: %s", err.msg);
	links = check_continuity(&d, size, "large design split");
	CHECK(links == 2 * ((NU - 1) * 2 * NV + NU * (2 * NV - 1)),
	    "large design split: %d links", links);
	NEAR(check_identity(&d, reg, b0, size), 0, 1e-12,
	    "large design split: identity");
	for (size_t i = 0; i < d.n; i++)
		found += loft_design_find(&d, d.p[i].id) == (long)i;
	CHECK(found == d.n, "large design: %zu of %zu ids found in place",
	    found, d.n);
	/* ids 1 .. maxid - 2 n0 are the patches split on the way */
	found = 0;
	for (long id = 1; id <= d.maxid - (long)d.n; id++)
		found += loft_design_find(&d, id) >= 0;
	CHECK(found == 0, "large design: %zu split ids still found", found);
	CHECK(d.maxid == 1 + 2 * (long)(NU * NV - 1 + n0),
	    "large design: largest id %ld", d.maxid);
	printf("large design: %zu patches, %d links, all continuous and "
	    "identical to the first patch\n", d.n, links);
	loft_design_free(&d);
	free(reg);
}

/* ------------------------------------------------------------------ */
/* Dragging */

/* Section 4 on one patch, central rule: the point lands, only (hh)
 * changes, and the four conditions hold. */
static void
test_drag_central(void)
{
	struct loft_design d = { 0 };
	struct loft_drag_info info;
	struct loft_error err;
	double b0[75], size, delta[3], x0[3], x1[3], y0[3], y1[3];
	double most = 0, mu = 0, mv = 0, least = 0;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	delta[0] = 0;
	delta[1] = 0.1;
	delta[2] = 1e-3 * size;
	loft_patch_eval(b0, 3, 0.4, 0.6, x0, NULL, NULL);
	CHECK(loft_design_drag(&d, 0, 0.4, 0.6, delta, 0.25, &info, &err) == 0,
	    "central drag: %s", err.msg);
	CHECK(info.rule == LOFT_DRAG_CENTRAL, "central rule");
	NEAR(info.hd, h5(0.4) * h5(0.6), 1e-15, "H_d = H5(u) H5(v)");
	loft_patch_eval(d.p[0].b, 3, 0.4, 0.6, x1, NULL, NULL);
	for (int k = 0; k < 3; k++)
		NEAR(x1[k] - x0[k], delta[k], 1e-14 * size, "lands exactly");
	for (int k = 0; k < 72; k++)
		CHECK(d.p[0].b[k] == b0[k], "central drag changed entry %d", k);
	/* deviation on a grid: (d) one sign, (c) largest at the middle,
	 * (a) small against the size */
	for (int i = 0; i <= 40; i++)
		for (int j = 0; j <= 40; j++) {
			double dev[3], along;

			loft_patch_eval(b0, 3, i / 40.0, j / 40.0, y0, NULL, NULL);
			loft_patch_eval(d.p[0].b, 3, i / 40.0, j / 40.0, y1, NULL,
			    NULL);
			for (int k = 0; k < 3; k++)
				dev[k] = y1[k] - y0[k];
			along = (dev[0] * delta[0] + dev[1] * delta[1] +
			    dev[2] * delta[2]) / norm(delta, 3);
			least = fmin(least, along);
			if (norm(dev, 3) > most) {
				most = norm(dev, 3);
				mu = i / 40.0;
				mv = j / 40.0;
			}
		}
	CHECK(least > -1e-14 * size, "(d) deviation of one sign: %g", least);
	CHECK(mu == 0.5 && mv == 0.5, "(c) largest deviation at the middle, "
	    "(%g, %g)", mu, mv);
	NEAR(most, norm(delta, 3) / (h5(0.4) * h5(0.6)), 1e-12 * size,
	    "(c) the largest is delta / H_d");
	CHECK(most <= 16.0 / 9 * 16.0 / 9 * norm(delta, 3) * (1 + 1e-12),
	    "(c) within (16/9)^2 of the drag");
	CHECK(most < 0.02 * size, "(a) %g small against the size %g", most,
	    size);
	printf("central drag: point landed within %.2g; largest deviation "
	    "%.4g x the drag, at (0.5, 0.5)\n", dist(x1, (double[]){ x0[0] +
	    delta[0], x0[1] + delta[1], x0[2] + delta[2] }, 3),
	    most / norm(delta, 3));
	/* an edge with no neighbour: the point on it cannot move */
	CHECK(loft_design_drag(&d, 0, 0, 0.5, delta, 0.25, &info, &err) ==
	    LOFT_EGEOM, "a boundary point cannot be dragged");
	CHECK(loft_design_drag(&d, 0, 0.1, 0.5, delta, 0.25, &info, &err) ==
	    0 && info.rule == LOFT_DRAG_FALLBACK, "no neighbour: fallback");
	loft_design_free(&d);
}

/* Near an edge: three patches in a row, unequal scale factors; drag the
 * middle one near the last. */
static void
test_drag_edge(void)
{
	struct loft_design d = { 0 }, e = { 0 };
	struct region reg[4] = { { { 0, 1, 0, 1 } } };
	struct loft_drag_info info;
	struct loft_error err;
	double b0[75], size, delta[3] = { 0.05, -0.1, 0.3 }, x0[3], x1[3];
	double wp, hd, least = 0, most = 0;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	split_tracked(&d, reg, 0, 0, 0.3);     /* 2 | 3 */
	split_tracked(&d, reg, 1, 0, 0.6);     /* 2 | 4 | 5: r 0.3 0.42 0.28 */
	for (size_t i = 0; i < d.n; i++)
		loft_design_new(&e, d.p[i].b, 3, d.p[i].id, &err);
	loft_patch_eval(d.p[1].b, 3, 0.85, 0.4, x0, NULL, NULL);
	CHECK(loft_design_drag(&d, 1, 0.85, 0.4, delta, 0.25, &info, &err) == 0,
	    "edge drag: %s", err.msg);
	CHECK(info.rule == LOFT_DRAG_EDGE && info.other == 2,
	    "edge rule with patch 5 (rule %d, other %ld)", info.rule,
	    info.other);
	/* by hand: w_p = 0.42/(0.42 + 0.28) = 0.6, w_d = 0.85 w_p */
	wp = 0.42 / (0.42 + 0.28);
	hd = h5(0.85 * wp) * h5(0.4);
	NEAR(info.hd, hd, 1e-14, "H_d");
	loft_patch_eval(d.p[1].b, 3, 0.85, 0.4, x1, NULL, NULL);
	for (int k = 0; k < 3; k++)
		NEAR(x1[k] - x0[k], delta[k], 1e-14 * size, "edge drag lands");
	/* the common edge moved by delta H_p / H_d, H_p = H5(w_p) H5(v) */
	for (int j = 1; j < 10; j++) {
		double v = j / 10.0, a[3], b[3];

		loft_patch_eval(e.p[1].b, 3, 1, v, a, NULL, NULL);
		loft_patch_eval(d.p[1].b, 3, 1, v, b, NULL, NULL);
		for (int k = 0; k < 3; k++)
			NEAR(b[k] - a[k], delta[k] * h5(wp) * h5(v) / hd,
			    1e-13 * size, "common edge moves by delta H_p/H_d");
	}
	/* (b) nothing outside the effective segment moves, nor its rim */
	for (int k = 0; k < 75; k++)
		CHECK(d.p[0].b[k] == e.p[0].b[k], "patch 2 moved (entry %d)", k);
	for (int r = 0; r < 5; r++)
		for (int c = 0; c < 5; c++)
			for (int k = 0; k < 3; k++) {
				int i = IDX(r, c, 3) + k;

				/* 4's edge u0 (rows 0, 2), 5's edge u1 (rows
				 * 1, 3), and the v edges (columns 0-3) */
				if (r == 0 || r == 2 || c < 4)
					CHECK(d.p[1].b[i] == e.p[1].b[i],
					    "patch 4's rim moved (%d %d)", r, c);
				if (r == 1 || r == 3 || c < 4)
					CHECK(d.p[2].b[i] == e.p[2].b[i],
					    "patch 5's rim moved (%d %d)", r, c);
			}
	check_continuity(&d, size, "edge drag");
	/* (d) one sign over both patches */
	for (int p = 1; p <= 2; p++)
		for (int i = 0; i <= 20; i++)
			for (int j = 0; j <= 20; j++) {
				double a[3], b[3], along = 0;

				loft_patch_eval(e.p[p].b, 3, i / 20.0, j / 20.0, a,
				    NULL, NULL);
				loft_patch_eval(d.p[p].b, 3, i / 20.0, j / 20.0, b,
				    NULL, NULL);
				for (int k = 0; k < 3; k++)
					along += (b[k] - a[k]) * delta[k];
				least = fmin(least, along);
				most = fmax(most, dist(a, b, 3));
			}
	CHECK(least > -1e-14 * size, "(d) edge drag of one sign: %g", least);
	NEAR(most, norm(delta, 3) / hd, 1e-3, "(c) largest deviation is "
	    "delta / H_d, at the middle of the pair");
	printf("edge drag: w_p = %.3g, H_d = %.4g, H_p/H_d = %.4g, largest "
	    "deviation %.4g x the drag\n", wp, hd, h5(wp) * h5(0.4) / hd,
	    most / norm(delta, 3));
	/* at a T-junction the central rule applies */
	split_tracked(&d, reg, 2, 1, 0.5);
	CHECK(loft_design_drag(&d, 1, 0.9, 0.4, delta, 0.25, &info, &err) ==
	    0 && info.rule == LOFT_DRAG_FALLBACK, "T-junction: fallback");
	loft_design_free(&d);
	loft_design_free(&e);
}

/* A curve of three quartic segments: central, end and open-end drags. */
static void
test_drag_curve(void)
{
	double q[3][10], q0[3][10], delta[2] = { 0, 0.5 }, x0[2], x1[2];
	struct loft_drag_info info;
	struct loft_error err;

	for (int i = 0; i < 3; i++) {
		double c[4] = { i, i + 1, 1, 1 }, cy[4] = { 0, 0, 0.5, 0.5 };

		for (int k = 0; k < 2; k++) {
			double *cc = k == 0 ? c : cy, cub[4] = { cc[0], cc[1],
			    cc[2], cc[3] }, qq[5];

			/* a 1-D cubic -> quartic, coordinate k */
			loft_cubic_to_quartic(cub, 1, qq);
			for (int r = 0; r < 5; r++)
				q[i][r * 2 + k] = qq[r];
		}
	}
	memcpy(q0, q, sizeof q);
	loft_quartic_eval(q[1], 2, 0.5, x0, NULL, NULL);
	CHECK(loft_quartic_drag(&q[0][0], 3, 2, 0, 1.5, delta, 0.25, &info,
	    &err) == 0 && info.rule == LOFT_DRAG_CENTRAL, "curve: central");
	loft_quartic_eval(q[1], 2, 0.5, x1, NULL, NULL);
	NEAR(x1[1] - x0[1], 0.5, 1e-15, "curve: lands");
	CHECK(memcmp(q[0], q0[0], sizeof q[0]) == 0 &&
	    memcmp(q[2], q0[2], sizeof q[2]) == 0 &&
	    memcmp(q[1], q0[1], 8 * sizeof q[1][0]) == 0,
	    "curve: only (h) of segment 2 moved");
	memcpy(q, q0, sizeof q);
	CHECK(loft_quartic_drag(&q[0][0], 3, 2, 0, 1.9, delta, 0.25, &info,
	    &err) == 0 && info.rule == LOFT_DRAG_EDGE && info.other == 2,
	    "curve: edge rule");
	/* the common end moved by delta H5(1/2) / H5(0.45): H_p = 1 */
	NEAR(q[1][3] - q0[1][3], 0.5 / h5(0.45), 1e-14, "curve: joint moves");
	CHECK(q[1][2] == q[2][0] && q[1][3] == q[2][1], "curve: joint shared");
	NEAR(q[1][6] - q[2][4], 0, 1e-14, "curve: slope x continuous");
	NEAR(q[1][7] - q[2][5], 0, 1e-14, "curve: slope y continuous");
	CHECK(memcmp(q[0], q0[0], sizeof q[0]) == 0, "curve: segment 1 kept");
	CHECK(loft_quartic_drag(&q[0][0], 3, 2, 0, 0, delta, 0.25, &info,
	    &err) == LOFT_EGEOM, "curve: the open end cannot move");
	CHECK(loft_quartic_drag(&q[0][0], 3, 2, 1, 0, delta, 0.25, &info,
	    &err) == 0 && info.rule == LOFT_DRAG_EDGE && info.other == 2,
	    "closed curve: the first and last segments are neighbours");
}

/*
 * Section 4's conditions on dragging, worded as issue 4 words them, on
 * central drags at random points at least EDGE from the ends:
 * (a) the largest movement is small against the length (at most
 *     delta / H_d, and H_d >= H5(EDGE) per direction);
 * (b) the effective segment keeps its end points and end slopes, and
 *     nothing outside it moves (bit for bit);
 * (c) the largest deviation lies within C_DISTANCE of the dragged point
 *     in each parameter, the distance patchdrag.1 documents;
 * (d) the deviation has one sign: it is a non-negative multiple of delta.
 */
#define EDGE 0.25
#define C_DISTANCE (0.5 - EDGE)
#define SAMPLES 200

/* The deviation dev from a drag delta: 1 when it is lambda delta, with
 * lambda >= 0, to rounding of the size s. */
static int
one_sign(const double *dev, const double *delta, int dim, double s)
{
	double along = 0, dd = 0, off[3];

	for (int k = 0; k < dim; k++) {
		along += dev[k] * delta[k];
		dd += delta[k] * delta[k];
	}
	for (int k = 0; k < dim; k++)
		off[k] = dev[k] - along / dd * delta[k];
	return along >= -1e-14 * s * sqrt(dd) && norm(off, dim) <= 1e-14 * s;
}

/* a[0..n) == b[0..n), as numbers (minus zero is zero) */
static int
same(const double *a, const double *b, int n)
{
	for (int k = 0; k < n; k++)
		if (a[k] != b[k])
			return 0;
	return 1;
}

static void
test_drag_conditions_curve(void)
{
	enum { NSEG = 4 };
	const double r = 10, arc = M_PI / 3;   /* a circular arc */
	double q[NSEG][10], q0[NSEG][10], len = 0, worst_a = 0, worst_c = 0;
	int bad_b = 0, bad_d = 0;

	/* segment i: from angle i arc to (i + 1) arc, slopes r arc
	 * tangent, (h) on the circle (a quartic near the arc) */
	for (int i = 0; i < NSEG; i++) {
		double t0 = i * arc, t1 = t0 + arc, th = t0 + arc / 2;
		double c[10] = { r * cos(t0), r * sin(t0), r * cos(t1),
		    r * sin(t1), -r * arc * sin(t0), r * arc * cos(t0),
		    -r * arc * sin(t1), r * arc * cos(t1), r * cos(th),
		    r * sin(th) };

		memcpy(q0[i], c, sizeof c);
	}
	for (int i = 0; i < NSEG; i++)
		for (int m = 0; m < SAMPLES; m++) {
			double a[2], b[2];

			loft_quartic_eval(q0[i], 2, (double)m / SAMPLES, a, NULL,
			    NULL);
			loft_quartic_eval(q0[i], 2, (double)(m + 1) / SAMPLES, b,
			    NULL, NULL);
			len += dist(a, b, 2);
		}
	NEAR(len, r * arc * NSEG, 1e-3 * len, "the arc's length");
	for (int n = 0; n < 200; n++) {
		struct loft_drag_info info;
		struct loft_error err;
		int i = (int)rnd(0, NSEG), mi = 0;
		double u = rnd(EDGE, 1 - EDGE), ang = rnd(0, 2 * M_PI);
		double delta[2] = { 1e-3 * len * cos(ang), 1e-3 * len * sin(ang) };
		double most = 0, x0[2], x1[2], d0[2], d1[2];

		memcpy(q, q0, sizeof q);
		CHECK(loft_quartic_drag(&q[0][0], NSEG, 2, 0, i + u, delta, EDGE,
		    &info, &err) == 0 && info.rule == LOFT_DRAG_CENTRAL,
		    "curve condition: central drag at %g", i + u);
		for (int j = 0; j < NSEG; j++)
			bad_b += !same(q[j], q0[j], j == i ? 8 : 10);
		for (int e = 0; e <= 1; e++) {
			loft_quartic_eval(q0[i], 2, e, x0, d0, NULL);
			loft_quartic_eval(q[i], 2, e, x1, d1, NULL);
			bad_b += !same(x0, x1, 2) || !same(d0, d1, 2);
		}
		for (int m = 0; m <= SAMPLES; m++) {
			double dev[2];

			loft_quartic_eval(q0[i], 2, (double)m / SAMPLES, x0, NULL,
			    NULL);
			loft_quartic_eval(q[i], 2, (double)m / SAMPLES, x1, NULL,
			    NULL);
			dev[0] = x1[0] - x0[0];
			dev[1] = x1[1] - x0[1];
			bad_d += !one_sign(dev, delta, 2, len);
			if (norm(dev, 2) > most) {
				most = norm(dev, 2);
				mi = m;
			}
		}
		CHECK(most <= norm(delta, 2) / h5(u) * (1 + 1e-12) &&
		    most <= 16.0 / 9 * norm(delta, 2) * (1 + 1e-12),
		    "(a) curve: largest movement %g for a drag of %g", most,
		    norm(delta, 2));
		worst_a = fmax(worst_a, most / len);
		worst_c = fmax(worst_c, fabs((double)mi / SAMPLES - u));
	}
	CHECK(worst_a <= 16.0 / 9 * 1e-3 * (1 + 1e-12), "(a) curve: largest "
	    "movement %g of the length for drags of 1e-3 of it", worst_a);
	CHECK(bad_b == 0, "(b) curve: %d drags moved an end, an end slope or "
	    "another segment", bad_b);
	CHECK(worst_c <= C_DISTANCE + 1.0 / SAMPLES, "(c) curve: largest "
	    "deviation %g from the dragged point", worst_c);
	CHECK(bad_d == 0, "(d) curve: %d samples off one sign", bad_d);
	/* near a join the effective segment is two segments: their outer
	 * ends and slopes stay, the others do not move, one sign over both */
	for (int n = 0; n < 50; n++) {
		struct loft_drag_info info;
		struct loft_error err;
		int i = 1 + (int)rnd(0, NSEG - 2), j, lo, bad = 0;
		double u = n % 2 ? rnd(0.8, 1) : rnd(0.01, 0.2);
		double delta[2] = { rnd(-0.01, 0.01), rnd(-0.01, 0.01) };
		double x0[2], x1[2], d0[2], d1[2];

		memcpy(q, q0, sizeof q);
		CHECK(loft_quartic_drag(&q[0][0], NSEG, 2, 0, i + u, delta, EDGE,
		    &info, &err) == 0 && info.rule == LOFT_DRAG_EDGE,
		    "curve condition: edge drag at %g", i + u);
		j = (int)info.other;
		lo = i < j ? i : j;
		for (int k = 0; k < NSEG; k++)
			if (k != i && k != j)
				bad += !same(q[k], q0[k], 10);
		loft_quartic_eval(q0[lo], 2, 0, x0, d0, NULL);
		loft_quartic_eval(q[lo], 2, 0, x1, d1, NULL);
		bad += !same(x0, x1, 2) || !same(d0, d1, 2);
		loft_quartic_eval(q0[lo + 1], 2, 1, x0, d0, NULL);
		loft_quartic_eval(q[lo + 1], 2, 1, x1, d1, NULL);
		bad += !same(x0, x1, 2) || !same(d0, d1, 2);
		CHECK(bad == 0, "(b) curve edge drag at %g: %d changes outside",
		    i + u, bad);
		for (int k = lo; k <= lo + 1; k++)
			for (int m = 0; m <= SAMPLES; m++) {
				double dev[2];

				loft_quartic_eval(q0[k], 2, (double)m / SAMPLES,
				    x0, NULL, NULL);
				loft_quartic_eval(q[k], 2, (double)m / SAMPLES,
				    x1, NULL, NULL);
				dev[0] = x1[0] - x0[0];
				dev[1] = x1[1] - x0[1];
				bad_d += !one_sign(dev, delta, 2, len);
			}
	}
	CHECK(bad_d == 0, "(d) curve edge drags: %d samples off one sign",
	    bad_d);
	printf("curve drags: largest movement %.3g of the length for drags "
	    "of 1e-3 of it; largest deviation at most %.3g from the dragged "
	    "point\n", worst_a, worst_c);
}

static void
test_drag_conditions_patch(void)
{
	enum { G = 40 };
	struct loft_design d = { 0 };
	struct region reg[4] = { { { 0, 1, 0, 1 } } };
	struct loft_error err;
	double b0[75], size, worst_a = 0, worst_c = 0;
	int bad_b = 0, bad_d = 0;

	hull_patch(b0);
	size = loft_patch_size(b0, 3);
	loft_design_new(&d, b0, 3, 1, &err);
	split_tracked(&d, reg, 0, 0, 0.5);     /* 2 | 3 */
	for (int n = 0; n < 100; n++) {
		struct loft_design e = { 0 };
		struct loft_drag_info info;
		size_t i = (size_t)n % 2;
		double u = rnd(EDGE, 1 - EDGE), v = rnd(EDGE, 1 - EDGE);
		double delta[3], most = 0, mu = 0, mv = 0;

		for (int k = 0; k < 3; k++)
			delta[k] = rnd(-1, 1) * 1e-3 * size;
		for (size_t k = 0; k < d.n; k++)
			loft_design_new(&e, d.p[k].b, 3, d.p[k].id, &err);
		CHECK(loft_design_drag(&e, i, u, v, delta, EDGE, &info, &err) ==
		    0 && info.rule == LOFT_DRAG_CENTRAL,
		    "patch condition: central drag at %g %g", u, v);
		bad_b += !same(e.p[1 - i].b, d.p[1 - i].b, 75);
		for (int m = 0; m <= 10; m++)
			for (int ed = 0; ed < 4; ed++) {
				double s = m / 10.0, x0[3], x1[3], g0[6], g1[6];
				double eu = ed < 2 ? ed : s, ev = ed < 2 ? s : ed - 2;

				loft_patch_eval(d.p[i].b, 3, eu, ev, x0, g0, g0 + 3);
				loft_patch_eval(e.p[i].b, 3, eu, ev, x1, g1, g1 + 3);
				bad_b += !same(x0, x1, 3) || !same(g0, g1, 6);
			}
		for (int a = 0; a <= G; a++)
			for (int c = 0; c <= G; c++) {
				double x0[3], x1[3], dev[3];

				loft_patch_eval(d.p[i].b, 3, (double)a / G,
				    (double)c / G, x0, NULL, NULL);
				loft_patch_eval(e.p[i].b, 3, (double)a / G,
				    (double)c / G, x1, NULL, NULL);
				for (int k = 0; k < 3; k++)
					dev[k] = x1[k] - x0[k];
				bad_d += !one_sign(dev, delta, 3, size);
				if (norm(dev, 3) > most) {
					most = norm(dev, 3);
					mu = (double)a / G;
					mv = (double)c / G;
				}
			}
		CHECK(most <= norm(delta, 3) / (h5(u) * h5(v)) * (1 + 1e-12) &&
		    most <= 16.0 / 9 * 16.0 / 9 * norm(delta, 3) * (1 + 1e-12),
		    "(a) patch: largest movement %g for a drag of %g", most,
		    norm(delta, 3));
		worst_a = fmax(worst_a, most / size);
		worst_c = fmax(worst_c, fmax(fabs(mu - u), fabs(mv - v)));
		loft_design_free(&e);
	}
	CHECK(worst_a <= 256.0 / 81 * sqrt(3) * 1e-3 * (1 + 1e-12),
	    "(a) patch: largest movement %g of the size", worst_a);
	CHECK(bad_b == 0, "(b) patch: %d changes on the rim or in the other "
	    "patch", bad_b);
	CHECK(worst_c <= C_DISTANCE + 1.0 / G, "(c) patch: largest deviation "
	    "%g from the dragged point", worst_c);
	CHECK(bad_d == 0, "(d) patch: %d samples off one sign", bad_d);
	printf("patch drags: largest movement %.3g of the size for drags of "
	    "1e-3 of it per coordinate; largest deviation at most %.3g from "
	    "the dragged point per parameter\n", worst_a, worst_c);
	loft_design_free(&d);
}

static void
test_project(void)
{
	struct loft_error err;
	double d[3] = { 1, 2, 3 }, w[3] = { 0, 0, 2 }, z[3] = { 0, 0, 5 };

	CHECK(loft_drag_project(d, w, 3, &err) == 0 && d[0] == 1 && d[1] == 2 &&
	    d[2] == 0, "projection drops depth");
	CHECK(loft_drag_project(z, w, 3, &err) == LOFT_EGEOM,
	    "a drag along the view is refused");
}

/* ------------------------------------------------------------------ */
/* Joining */

/* A patch with corners about p00 .. p11 and bent, twisted inside. */
static void
rough_patch(double *b, const double *corner)
{
	double c[12];

	for (int k = 0; k < 12; k++)
		c[k] = corner[k] + rnd(-0.02, 0.02);
	loft_patch_bilinear(c, 3, b);
	for (int k = 2 * 5 * 3; k < 75; k++)   /* slopes, twists, (h) */
		b[k] += k / 3 % 5 > 1 ? rnd(-0.3, 0.3) :
		    rnd(-0.02, 0.02);  /* columns 0, 1: the edges v = 0, 1 */
}

static void
test_join(void)
{
	static const double cp[12] = { 0, 0, 0, 4, 0, 0, 0, 3, 0, 4, 3, 1 };
	/* s's u = 0 edge along p's u = 1 edge; the other case runs it the
	 * other way and puts s's v = 1 edge there */
	static const double cs[2][12] = {
		{ 4, 0, 0, 8, 0, 2, 4, 3, 1, 8, 3, 1 },
		{ 8, 3, 1, 8, 0, 2, 4, 3, 1, 4, 0, 0 },
	};
	for (int n = 0; n < 2; n++) {
		struct loft_design d = { 0 };
		struct loft_join_info info;
		struct loft_error err;
		double bp[75], bs[75], size;

		rough_patch(bp, cp);
		rough_patch(bs, cs[n]);
		loft_design_new(&d, bp, 3, 1, &err);
		loft_design_new(&d, bs, 3, 2, &err);
		d.p[0].scale[0] = 0.5;
		d.p[1].scale[n] = 2;
		size = loft_patch_size(bs, 3);
		CHECK(loft_design_join(&d, 0, 1, &info, &err) == 0, "join: %s",
		    err.msg);
		CHECK(info.edge_p == LOFT_U1 && info.edge_s == (n ? LOFT_V1 :
		    LOFT_U0) && info.reversed == n, "join found edges %d %d "
		    "reversed %d", info.edge_p, info.edge_s, info.reversed);
		CHECK(memcmp(d.p[0].b, bp, sizeof bp) == 0, "principal kept");
		CHECK(d.p[0].scale[0] == 0.5 && d.p[1].scale[n] == 2,
		    "scale factors kept");
		CHECK(check_continuity(&d, size, "join") == 2, "join: one link "
		    "each way");
		printf("join %d: gap before %.3g (size %.3g); after: %.3g apart, "
		    "slope mismatch %.3g\n", n, info.gap, info.size,
		    info.pos_after, info.slope_after);
		/* a drag near the joined edge moves both, which stay joined,
		 * whichever way and whichever edges they meet by */
		{
			struct loft_drag_info di;
			double delta[3] = { 0.1, 0.1, -0.2 }, x0[3], x1[3];

			loft_patch_eval(d.p[0].b, 3, 0.95, 0.3, x0, NULL, NULL);
			CHECK(loft_design_drag(&d, 0, 0.95, 0.3, delta, 0.25, &di,
			    &err) == 0 && di.rule == LOFT_DRAG_EDGE &&
			    di.other == 1, "drag across the joined edge");
			loft_patch_eval(d.p[0].b, 3, 0.95, 0.3, x1, NULL, NULL);
			for (int k = 0; k < 3; k++)
				NEAR(x1[k] - x0[k], delta[k], 1e-14 * size,
				    "lands");
			check_continuity(&d, size, "drag after join");
		}
		loft_design_free(&d);
	}
	/* too far apart */
	{
		struct loft_design d = { 0 };
		struct loft_join_info info;
		struct loft_error err;
		double bp[75], bs[75], far[12];

		for (int k = 0; k < 12; k++)
			far[k] = cs[0][k] + (k % 3 == 2 ? 1 : 0);
		rough_patch(bp, cp);
		rough_patch(bs, far);
		loft_design_new(&d, bp, 3, 1, &err);
		loft_design_new(&d, bs, 3, 2, &err);
		CHECK(loft_design_join(&d, 0, 1, &info, &err) == LOFT_EGEOM,
		    "edges 1 apart do not join");
		loft_design_free(&d);
	}
}

/* Coons: the boundaries exact, corners checked. */
static void
test_coons(void)
{
	double b[75], c[4][15], x[3], y[3];
	const double *cp[4] = { c[0], c[1], c[2], c[3] };
	struct loft_error err;

	hull_patch(b);
	memcpy(c[0], (double[]){ 0, 0, 0, 6, 0, 0, 6, 0, 1, 6, 0, -1, 3, 0,
	    0.6 }, sizeof c[0]);
	for (int m = 0; m <= 10; m++) {
		loft_quartic_eval(c[0], 3, m / 10.0, x, NULL, NULL);
		loft_patch_eval(b, 3, m / 10.0, 0, y, NULL, NULL);
		CHECK(dist(x, y, 3) < 1e-14, "Coons: v = 0 edge is the curve");
	}
	for (int q = 0; q < 4; q++)
		for (int k = 0; k < 15; k++)
			c[q][k] = rnd(-1, 1);
	CHECK(loft_patch_coons(cp, 3, b, &err) == LOFT_EGEOM &&
	    strstr(err.msg, "corner (00)") != NULL, "Coons: mismatch named: "
	    "%s", err.msg);
}

/*
 * loft_skin on a section of no segments (loft_curve_cubic takes nseg =
 * 0): refused, with the row naming that section, not read past its end.
 */
static void
test_skin_no_segment(void)
{
	/* the line (0,0)-(1,0) as a cubic: ends, then end tangents */
	double line[] = { 0, 0, 1, 0, 1, 0, 1, 0 };
	double moved[] = { 0, 1, 1, 1, 1, 0, 1, 0 };
	struct loft_skin_opts o = { 0 };
	struct loft_skin_result r;
	struct loft_curve sec[3];
	struct loft_error err;

	loft_curve_cubic(&sec[0], line, 1, 2, 0);
	loft_curve_cubic(&sec[1], moved, 0, 2, 0);
	loft_curve_cubic(&sec[2], moved, 1, 2, 0);
	CHECK(loft_skin(&o, sec, 3, &r, &err) == LOFT_EINPUT && err.row == 1,
	    "a section of no segment is refused at row 1");
}

int
main(void)
{
	test_h_constraints();
	test_quartic_eval();
	test_cubic_to_quartic();
	test_patch_eval();
	test_split_identity();
	test_fig4();
	test_fig5();
	test_split_everywhere();
	test_large_design();
	test_drag_central();
	test_drag_edge();
	test_drag_curve();
	test_drag_conditions_curve();
	test_drag_conditions_patch();
	test_project();
	test_join();
	test_coons();
	test_skin_no_segment();
	printf("continuity over all designs: edges apart %.3g of the size, "
	    "slopes differ by %.3g\n", cont_pos, cont_slope);
	return check_done("patch");
}
