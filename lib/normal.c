/*
 * normal.c: normal approximation of regular curves and surfaces by
 * Bezier ones, after A. Carriazo, M. C. Marquez and H. Ugail, "Normal
 * approximations of regular curves and surfaces", Filomat 29(3), 2015.
 *
 * Every control point but the ends lies on the normal line of the curve
 * (eq. 1) or surface at an equally spaced parameter, and the distances
 * lambda along those lines minimise the squared L2 distance between the
 * curve and the Bezier curve (eq. 3).  F is quadratic in the lambdas, so
 * dF/dlambda_j = 0 is a linear system; its matrix is the Bernstein Gram
 * matrix weighted by the normals' dot products, which is exact, and only
 * its right-hand side needs quadrature.
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/*
 * Quadrature: Gauss-Legendre with QUAD_NODES nodes on each of at least
 * QUAD_MIN_PANELS equal panels, panels aligned with the curve's pieces.
 * 16 nodes integrate polynomials of degree 31 exactly, so a piecewise
 * cubic or quartic input is integrated exactly for every degree the
 * program allows; on the papers' smooth examples (trigonometric in t)
 * doubling the panels changes F by less than 1e-15 relative, which the
 * tests check.
 */
#define QUAD_NODES      16
#define QUAD_MIN_PANELS 16

/*
 * A space curve has no principal normal where alpha'' is parallel to
 * alpha' (zero curvature).  Parallel within rounding: the sine of the
 * angle between them below this.
 */
#define NORMAL_TOL 1e-10

/*
 * The derivative vanishes (the curve or surface is not regular) when its
 * length is below this fraction of the average over the parameter range.
 */
#define SPEED_TOL 1e-12

/* A pivot of the Cholesky factorisation below this fraction of the
 * largest diagonal entry: the system is singular to working precision. */
#define SINGULAR_TOL 1e-13

/*
 * F and the normal equations hold squares of lengths, which overflow for
 * a curve larger than about 1e150 and lose their digits to underflow
 * below 1e-150.  A curve or surface whose size lies outside [SCALE_LO,
 * SCALE_HI] is therefore solved scaled by a power of two (exactly) and
 * the results scaled back, so that they scale with the units; inside,
 * far from both ends, nothing changes, to the last bit.
 */
#define SCALE_LO 1e-50
#define SCALE_HI 1e50

/* A curve or surface, its coordinates multiplied by 2^-e. */
struct scaled {
	const struct loft_pcurve *a;
	const struct loft_psurface *x;
	int e;
};

static void
unscale(double *v, int n, int e)
{
	for (int k = 0; v != NULL && k < n; k++)
		v[k] = ldexp(v[k], e);
}

static void
scaled_curve_eval(void *ctx, double t, double *p, double *d1, double *d2)
{
	const struct scaled *c = ctx;

	c->a->eval(c->a->ctx, t, p, d1, d2);
	unscale(p, c->a->dim, -c->e);
	unscale(d1, c->a->dim, -c->e);
	unscale(d2, c->a->dim, -c->e);
}

static void
scaled_surface_eval(void *ctx, double u, double v, double *p, double *pu,
    double *pv, double *puu, double *pvv)
{
	const struct scaled *c = ctx;

	c->x->eval(c->x->ctx, u, v, p, pu, pv, puu, pvv);
	unscale(p, 3, -c->e);
	unscale(pu, 3, -c->e);
	unscale(pv, 3, -c->e);
	unscale(puu, 3, -c->e);
	unscale(pvv, 3, -c->e);
}

/*
 * The power of two to scale by: 0 for a size (the largest coordinate at
 * a few parameters) inside [SCALE_LO, SCALE_HI], or not finite, or 0;
 * those are for the method to judge.
 */
static int
scale_of(const double *pts, int n)
{
	double m = 0;

	for (int k = 0; k < n; k++)
		m = fmax(m, fabs(pts[k]));
	return m > 0 && isfinite(m) && (m < SCALE_LO || m > SCALE_HI) ?
	    ilogb(m) : 0;
}

/*
 * F of the scaled curve (of size 1 to 2) below this is rounding, its
 * points' 1e-16 squared and summed: written as it comes, 0 when it
 * underflows, it is as true as its digits.  Above it, F must survive
 * the scaling back.
 */
#define F_ROUNDING 1e-28

/* F scaled back by 2^(2e): 0, or LOFT_EGEOM where it overflows, or
 * underflows while it is more than rounding (issue 28: a curve of size
 * 1e-200 had error=0). */
static int
unscale_error(double *error, int e, const char *what, struct loft_error *err)
{
	double f = *error;

	*error = ldexp(f, 2 * e);
	if (!isfinite(*error))
		return loft_fail(err, LOFT_EGEOM, -1, "the %s is too large: "
		    "F, in its units squared, overflows", what);
	if (f > F_ROUNDING && !(*error >= DBL_MIN))
		return loft_fail(err, LOFT_EGEOM, -1, "the %s is too small: "
		    "F, in its units squared, underflows", what);
	return 0;
}

#define SCALE_PROBES 9  /* t = 0, 1/8, ..., 1 (and that squared) */

struct rule {
	double *t, *w;
	size_t count;
	double *ends;           /* the panels' ends: panels + 1 of them */
	size_t panels;
};

/*
 * The QUAD_NODES-point Gauss-Legendre rule on [0, 1]: the roots of the
 * Legendre polynomial P_q by Newton's method from Tricomi's estimate,
 * the weights 2 / ((1 - x^2) P_q'(x)^2) halved for the unit interval.
 */
static void
gauss_legendre(double *x, double *w)
{
	const int q = QUAD_NODES;

	for (int i = 0; i < q; i++) {
		double z = cos(M_PI * (i + 0.75) / (q + 0.5)), dp = 1;

		for (int it = 0; it < 100; it++) {
			double p0 = 1, p1 = z, dz;

			for (int k = 2; k <= q; k++) {
				double p2 = ((2 * k - 1) * z * p1 -
				    (k - 1) * p0) / k;

				p0 = p1;
				p1 = p2;
			}
			dp = q * (z * p1 - p0) / (z * z - 1);
			dz = p1 / dp;
			z -= dz;
			if (fabs(dz) <= 1e-16)
				break;
		}
		x[i] = (1 - z) / 2;
		w[i] = 1 / ((1 - z * z) * dp * dp);
	}
}

static void
rule_free(struct rule *r)
{
	free(r->t);
	free(r->w);
	free(r->ends);
	/* a second free, by squad_free after a failed rule_make, is none */
	r->t = r->w = r->ends = NULL;
}

static int
rule_make(struct rule *r, size_t npieces, struct loft_error *err)
{
	double gx[QUAD_NODES], gw[QUAD_NODES];
	size_t per, panels;

	r->t = r->w = r->ends = NULL;
	if (npieces == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "a curve or surface of "
		    "no pieces");
	per = npieces >= QUAD_MIN_PANELS ? 1 :
	    (QUAD_MIN_PANELS + npieces - 1) / npieces;
	panels = npieces * per;
	if (panels > (size_t)-1 / QUAD_NODES / sizeof(double))
		return loft_fail(err, LOFT_ENOMEM, -1, "too many pieces");
	r->count = panels * QUAD_NODES;
	r->panels = panels;
	r->t = malloc(r->count * sizeof *r->t);
	r->w = malloc(r->count * sizeof *r->w);
	r->ends = malloc((panels + 1) * sizeof *r->ends);
	if (r->t == NULL || r->w == NULL || r->ends == NULL) {
		rule_free(r);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	gauss_legendre(gx, gw);
	for (size_t p = 0; p < panels; p++) {
		/* panel p of piece p / per, so its ends are the pieces' */
		double a = (double)(p / per) / npieces +
		    (double)(p % per) / (double)panels;
		double h = 1.0 / (double)panels;

		if (p % per == per - 1)
			h = (double)(p / per + 1) / npieces - a;
		r->ends[p] = a;
		for (int i = 0; i < QUAD_NODES; i++) {
			r->t[p * QUAD_NODES + i] = a + h * gx[i];
			r->w[p * QUAD_NODES + i] = h * gw[i];
		}
	}
	r->ends[panels] = 1;
	return 0;
}

static int
all_finite(const double *v, int n)
{
	for (int k = 0; k < n; k++)
		if (!isfinite(v[k]))
			return 0;
	return 1;
}

/*
 * A system singular to working precision is solved again with its
 * diagonal loaded by this fraction of itself (ridge regression).  The
 * matrix is positive definite in exact arithmetic (a Schur product of
 * the positive definite Bernstein Gram matrices and the normals' Gram
 * matrix, whose diagonal is 1), so a negative or tiny pivot is rounding
 * of the order of n 1e-16 of the diagonal; 1e-12 lies above that for
 * every n allowed, and moves lambda only along directions F hardly
 * sees (high degrees, issue 28: 24,24 on a saddle was "singular").
 */
#define RIDGE 1e-12

/* loft__cholesky_solve, ridged where it must be, with the message of a
 * system that is singular even so.  a is overwritten. */
static int
cholesky_solve(double *a, double *b, size_t n, struct loft_error *err)
{
	size_t j;
	double pivot, *a0 = malloc(n * n * sizeof *a0),
	    *b0 = malloc(n * sizeof *b0);

	if (a0 == NULL || b0 == NULL) {
		free(a0);
		free(b0);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	memcpy(a0, a, n * n * sizeof *a0);
	memcpy(b0, b, n * sizeof *b0);
	if (loft__cholesky_solve(a, b, n, SINGULAR_TOL, &j, &pivot) != 0) {
		memcpy(a, a0, n * n * sizeof *a0);
		for (size_t i = 0; i < n; i++)
			a[i * n + i] += RIDGE * a0[i * n + i];
		memcpy(b, b0, n * sizeof *b0);
		if (loft__cholesky_solve(a, b, n, SINGULAR_TOL, &j, &pivot) !=
		    0) {
			free(a0);
			free(b0);
			return loft_fail(err, LOFT_EGEOM, -1, "the system for the "
			    "control points is singular (pivot %zu of %zu is "
			    "%.3g of the largest)", j + 1, n, pivot);
		}
	}
	free(a0);
	free(b0);
	return 0;
}

/* 3-D cross product */
static void
cross(double *c, const double *a, const double *b)
{
	double x = a[1] * b[2] - a[2] * b[1];
	double y = a[2] * b[0] - a[0] * b[2];
	double z = a[0] * b[1] - a[1] * b[0];

	c[0] = x;
	c[1] = y;
	c[2] = z;
}

/* ------------------------------------------------------------------ */
/* Curves                                                              */

/* What the curve method needs of the curve at one t_i. */
struct station {
	double p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM];
	double n[LOFT_MAXDIM];  /* unit normal, or zero where there is none */
	int has_normal;
};

/*
 * The normal at t: in the plane the unit normal (-y', x') / |alpha'| of
 * section 2; in space the principal normal b x t, which is the unit
 * vector along (alpha' x alpha'') x alpha'.  speed is the curve's mean
 * speed, for SPEED_TOL.
 */
static int
normal_at(struct station *s, int dim, double t, double speed,
    struct loft_error *err)
{
	double len = vnorm(s->d1, dim);

	s->has_normal = 0;
	memset(s->n, 0, sizeof s->n);
	if (!(len > SPEED_TOL * speed))
		return loft_fail(err, LOFT_EGEOM, -1, "the curve's derivative "
		    "vanishes at t = %.17g: no normal there", t);
	if (dim == 2) {
		s->n[0] = -s->d1[1] / len;
		s->n[1] = s->d1[0] / len;
		s->has_normal = 1;
		return 0;
	}
	double b[3], acc = vnorm(s->d2, 3);

	cross(b, s->d1, s->d2);
	if (!(vnorm(b, 3) > NORMAL_TOL * len * acc))
		return 0;               /* zero curvature: no principal normal */
	cross(s->n, b, s->d1);
	vunit(s->n, 3);
	s->has_normal = 1;
	return 0;
}

/*
 * Evaluate the curve at every quadrature node into ap (count * dim) and
 * store its mean speed: the length of the polyline from t = 0 through
 * the nodes.  The panels' ends are checked finite too, so a pole at
 * a simple fraction (1/2, 1/4, ...) is caught; one strictly between
 * sample points is not.
 */
static int
sample_curve(const struct loft_pcurve *a, const struct rule *r, double *ap,
    double *speed, struct loft_error *err)
{
	int dim = a->dim;
	double p[LOFT_MAXDIM], len = 0;

	for (size_t k = 0; k <= r->panels; k++) {
		a->eval(a->ctx, r->ends[k], p, NULL, NULL);
		if (!all_finite(p, dim))
			return loft_fail(err, LOFT_EINPUT, -1, "the curve is "
			    "not finite at t = %.17g", r->ends[k]);
		if (k == 0)
			vcopy(ap, p, dim);      /* for the polyline's start */
	}
	vcopy(p, ap, dim);
	for (size_t q = 0; q < r->count; q++) {
		a->eval(a->ctx, r->t[q], ap + q * dim, NULL, NULL);
		if (!all_finite(ap + q * dim, dim))
			return loft_fail(err, LOFT_EINPUT, -1, "the curve is "
			    "not finite at t = %.17g", r->t[q]);
		len += vdist(ap + q * dim, p, dim);
		vcopy(p, ap + q * dim, dim);
	}
	if (!(len > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "the curve is a single "
		    "point");
	if (!isfinite(len))     /* else every derivative would seem to vanish */
		return loft_fail(err, LOFT_EINPUT, -1, "the curve is too "
		    "large: its length overflows");
	*speed = len;
	return 0;
}

/*
 * Point, derivatives and normal at t_i = i / n, checked finite; the
 * normal only where the method needs it (need_normal).
 */
static int
station_at(const struct loft_pcurve *a, struct station *s, double t,
    double speed, int need_normal, struct loft_error *err)
{
	int dim = a->dim;

	a->eval(a->ctx, t, s->p, s->d1, s->d2);
	s->has_normal = 0;
	memset(s->n, 0, sizeof s->n);
	if (!all_finite(s->p, dim))
		return loft_fail(err, LOFT_EINPUT, -1, "the curve is not "
		    "finite at t = %.17g", t);
	if (!need_normal)
		return 0;
	if (!all_finite(s->d1, dim) || (dim == 3 && !all_finite(s->d2, dim)))
		return loft_fail(err, LOFT_EINPUT, -1, "the curve or its "
		    "derivatives are not finite at t = %.17g", t);
	return normal_at(s, dim, t, speed, err);
}

/*
 * Eq. 4: B'(0) . n(0) = 0 gives n (alpha(t_1) + lambda_1 n(t_1) -
 * alpha(0)) . n(0) = 0, and likewise at the far end.
 */
static int
clamp_end(const struct station *end, const struct station *next, int dim,
    double *lambda, const char *which, struct loft_error *err)
{
	double c[LOFT_MAXDIM], nn;

	if (!end->has_normal || !next->has_normal)
		return loft_fail(err, LOFT_EGEOM, -1, "cannot clamp at t = %s: "
		    "the curve has no normal there or at the next t_i (zero "
		    "curvature)", which);
	nn = vdot(next->n, end->n, dim);
	if (!(fabs(nn) > NORMAL_TOL))
		return loft_fail(err, LOFT_EGEOM, -1, "cannot clamp at t = %s: "
		    "the normal at the next t_i is perpendicular to the end's",
		    which);
	vsub(c, next->p, end->p, dim);
	*lambda = -vdot(c, end->n, dim) / nn;
	return 0;
}

/*
 * The right-hand side of dF/dlambda_j = 0 (section 3): with Q the
 * control points for lambda = 0 on the free stations, r(t) = alpha(t) -
 * sum Q_i B_i(t) and b_j = n_j . integral r B_j dt.
 */
static void
curve_rhs(const struct rule *r, const double *ap, int dim, int n,
    const double *q, const struct station *st, const int *freeidx,
    int nfree, double *b)
{
	double bern[LOFT_NORMAL_MAXDEG + 1];

	memset(b, 0, nfree * sizeof *b);
	for (size_t k = 0; k < r->count; k++) {
		double res[LOFT_MAXDIM];

		loft_bernstein(n, r->t[k], bern);
		vcopy(res, ap + k * dim, dim);
		for (int i = 0; i <= n; i++)
			vaxpy(res, -bern[i], q + i * dim, dim);
		for (int f = 0; f < nfree; f++) {
			int j = freeidx[f];

			b[f] += r->w[k] * bern[j] * vdot(st[j].n, res, dim);
		}
	}
}

/* F = integral |alpha - B|^2 (eq. 3) for the control points ctl. */
static double
curve_error(const struct rule *r, const double *ap, int dim, int n,
    const double *ctl)
{
	double f = 0;

	for (size_t k = 0; k < r->count; k++) {
		double b[LOFT_MAXDIM];

		loft_bezier_eval(ctl, (size_t)n + 1, dim, r->t[k], b, NULL,
		    NULL);
		f += r->w[k] * vdist(b, ap + k * dim, dim) *
		    vdist(b, ap + k * dim, dim);
	}
	return f;
}

/* Solve for the free lambdas and place every control point. */
static int
curve_solve(const struct rule *r, const double *ap, int dim, int n,
    const struct station *st, double *lam, const int *fixed, double *ctl,
    struct loft_error *err)
{
	int freeidx[LOFT_NORMAL_MAXDEG], nfree = 0, rc;
	double a[LOFT_NORMAL_MAXDEG * LOFT_NORMAL_MAXDEG];
	double b[LOFT_NORMAL_MAXDEG];

	for (int i = 0; i <= n; i++) {
		vcopy(ctl + i * dim, st[i].p, dim);
		vaxpy(ctl + i * dim, lam[i], st[i].n, dim);
		if (!fixed[i])
			freeidx[nfree++] = i;
	}
	if (nfree == 0)
		return 0;
	for (int f = 0; f < nfree; f++)
		for (int g = 0; g < nfree; g++)
			a[f * nfree + g] = vdot(st[freeidx[f]].n,
			    st[freeidx[g]].n, dim) *
			    loft_bernstein_gram(n, freeidx[f], freeidx[g]);
	curve_rhs(r, ap, dim, n, ctl, st, freeidx, nfree, b);
	if ((rc = cholesky_solve(a, b, (size_t)nfree, err)) != 0)
		return rc;
	for (int f = 0; f < nfree; f++) {
		int j = freeidx[f];

		lam[j] = b[f];
		vaxpy(ctl + j * dim, lam[j], st[j].n, dim);
	}
	return 0;
}

static int normal_curve(const struct loft_pcurve *a, int n, int clamp,
    double *ctl, double *lambda, int *nonormal, double *error,
    struct loft_error *err);

int
loft_normal_curve(const struct loft_pcurve *a, int n, int clamp,
    double *ctl, double *lambda, int *nonormal, double *error,
    struct loft_error *err)
{
	double pts[SCALE_PROBES * LOFT_MAXDIM];
	struct scaled c = { a, NULL, 0 };
	struct loft_pcurve sa = *a;
	int rc;

	if (a->dim < 2 || a->dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "a curve of dimension "
		    "%d: want 2 or 3", a->dim);
	for (int k = 0; k < SCALE_PROBES; k++)
		a->eval(a->ctx, (double)k / (SCALE_PROBES - 1),
		    pts + k * a->dim, NULL, NULL);
	if ((c.e = scale_of(pts, SCALE_PROBES * a->dim)) != 0) {
		sa.eval = scaled_curve_eval;
		sa.ctx = &c;
	}
	rc = normal_curve(&sa, n, clamp, ctl, lambda, nonormal, error, err);
	if (rc != 0 || c.e == 0)
		return rc;
	unscale(ctl, (n + 1) * a->dim, c.e);
	unscale(lambda, lambda != NULL ? n + 1 : 0, c.e);
	return unscale_error(error, c.e, "curve", err);
}

static int
normal_curve(const struct loft_pcurve *a, int n, int clamp,
    double *ctl, double *lambda, int *nonormal, double *error,
    struct loft_error *err)
{
	struct station st[LOFT_NORMAL_MAXDEG + 1];
	double lam[LOFT_NORMAL_MAXDEG + 1] = { 0 }, speed = 0, *ap;
	int fixed[LOFT_NORMAL_MAXDEG + 1], dim = a->dim, rc;
	struct rule r;

	if (n < (clamp ? 3 : 1) || n > LOFT_NORMAL_MAXDEG)
		return loft_fail(err, LOFT_EINPUT, -1, "degree %d: want %d to "
		    "%d", n, clamp ? 3 : 1, LOFT_NORMAL_MAXDEG);
	if ((rc = rule_make(&r, a->npieces, err)) != 0)
		return rc;
	ap = malloc(r.count * dim * sizeof *ap);
	if (ap == NULL) {
		rule_free(&r);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	rc = sample_curve(a, &r, ap, &speed, err);
	for (int i = 0; i <= n && rc == 0; i++) {
		rc = station_at(a, &st[i], (double)i / n, speed,
		    clamp || (i > 0 && i < n), err);
		/* the ends are the curve's own: no lambda there */
		fixed[i] = i == 0 || i == n || !st[i].has_normal;
	}
	if (rc == 0 && clamp)
		rc = clamp_end(&st[0], &st[1], dim, &lam[1], "0", err);
	if (rc == 0 && clamp)
		rc = clamp_end(&st[n], &st[n - 1], dim, &lam[n - 1], "1", err);
	if (clamp)
		fixed[1] = fixed[n - 1] = 1;
	if (rc == 0)
		rc = curve_solve(&r, ap, dim, n, st, lam, fixed, ctl, err);
	if (rc == 0) {
		*error = curve_error(&r, ap, dim, n, ctl);
		for (int i = 0; i <= n; i++) {
			if (lambda != NULL)
				lambda[i] = lam[i];
			if (nonormal != NULL)
				nonormal[i] = i > 0 && i < n &&
				    !st[i].has_normal;
		}
	}
	free(ap);
	rule_free(&r);
	return rc;
}

/* ------------------------------------------------------------------ */
/* Surfaces                                                            */

/* A boundary curve of a surface: x(t, 0), x(0, t), x(t, 1), x(1, t). */
struct edge {
	const struct loft_psurface *x;
	int along_u;            /* t is u (edges v = 0, 1) or v */
	double fixed;           /* the other parameter's value */
};

static void
edge_eval(void *ctx, double t, double *p, double *d1, double *d2)
{
	const struct edge *e = ctx;

	if (e->along_u)
		e->x->eval(e->x->ctx, t, e->fixed, p, d1, NULL, d2, NULL);
	else
		e->x->eval(e->x->ctx, e->fixed, t, p, NULL, d1, NULL, d2);
}

/*
 * Step 1 of section 4: the four boundary curves by the curve method,
 * their control points into the border of the net.
 */
static int
surface_border(const struct loft_psurface *x, int m, int n, int clamp,
    double *ctl, struct loft_error *err)
{
	static const char *const names[] = { "v = 0", "u = 0", "v = 1",
	    "u = 1" };
	double pts[(LOFT_NORMAL_MAXDEG + 1) * 3], f;
	int rc;

	for (int e = 0; e < 4; e++) {
		struct edge ed = { x, e % 2 == 0, e < 2 ? 0 : 1 };
		struct loft_pcurve c = { 3, ed.along_u ? x->npu : x->npv,
		    edge_eval, &ed };
		int deg = ed.along_u ? m : n;

		if ((rc = loft_normal_curve(&c, deg, clamp, pts, NULL, NULL, &f,
		    err)) != 0) {
			char msg[sizeof err->msg];

			memcpy(msg, err->msg, sizeof msg);
			return loft_fail(err, rc, -1, "boundary %s: %s",
			    names[e], msg);
		}
		for (int k = 0; k <= deg; k++) {
			int i = ed.along_u ? k : (e < 2 ? 0 : m);
			int j = ed.along_u ? (e < 2 ? 0 : n) : k;

			vcopy(ctl + 3 * (i * (n + 1) + j), pts + 3 * k, 3);
		}
	}
	return 0;
}

/*
 * The interior stations: x(u_i, v_j) into the net, the unit normal
 * x_u x x_v / |x_u x x_v| into nrm (index (i - 1)(n - 1) + j - 1).
 */
static int
surface_stations(const struct loft_psurface *x, int m, int n, double *ctl,
    double *nrm, struct loft_error *err)
{
	for (int i = 1; i < m; i++)
		for (int j = 1; j < n; j++) {
			double u = (double)i / m, v = (double)j / n;
			double *p = ctl + 3 * (i * (n + 1) + j), pu[3], pv[3];
			double *nn = nrm + 3 * ((i - 1) * (n - 1) + j - 1);

			x->eval(x->ctx, u, v, p, pu, pv, NULL, NULL);
			if (!all_finite(p, 3) || !all_finite(pu, 3) ||
			    !all_finite(pv, 3))
				return loft_fail(err, LOFT_EINPUT, -1, "the "
				    "surface or its derivatives are not finite "
				    "at (u, v) = (%.17g, %.17g)", u, v);
			cross(nn, pu, pv);
			if (!(vnorm(nn, 3) > NORMAL_TOL * vnorm(pu, 3) *
			    vnorm(pv, 3)) || !(vnorm(nn, 3) > 0))
				return loft_fail(err, LOFT_EGEOM, -1, "the "
				    "surface is not regular at (u, v) = "
				    "(%.17g, %.17g): x_u x x_v = 0, no normal",
				    u, v);
			vunit(nn, 3);
		}
	return 0;
}

/* The surface at every pair of quadrature nodes, u-major, checked. */
static int
sample_surface(const struct loft_psurface *x, const struct rule *ru,
    const struct rule *rv, double *xp, struct loft_error *err)
{
	double p[3];

	/* the grid of panel ends, for poles at simple fractions */
	for (size_t a = 0; a <= ru->panels; a++)
		for (size_t b = 0; b <= rv->panels; b++) {
			x->eval(x->ctx, ru->ends[a], rv->ends[b], p, NULL, NULL,
			    NULL, NULL);
			if (!all_finite(p, 3))
				return loft_fail(err, LOFT_EINPUT, -1, "the "
				    "surface is not finite at (u, v) = "
				    "(%.17g, %.17g)", ru->ends[a], rv->ends[b]);
		}
	for (size_t a = 0; a < ru->count; a++)
		for (size_t b = 0; b < rv->count; b++) {
			double *q = xp + 3 * (a * rv->count + b);

			x->eval(x->ctx, ru->t[a], rv->t[b], q, NULL, NULL,
			    NULL, NULL);
			if (!all_finite(q, 3))
				return loft_fail(err, LOFT_EINPUT, -1, "the "
				    "surface is not finite at (u, v) = "
				    "(%.17g, %.17g)", ru->t[a], rv->t[b]);
		}
	return 0;
}

/* Bernstein values of degree deg at every node of r, node-major. */
static double *
bernstein_table(const struct rule *r, int deg)
{
	double *t = malloc(r->count * (deg + 1) * sizeof *t);

	if (t != NULL)
		for (size_t k = 0; k < r->count; k++)
			loft_bernstein(deg, r->t[k], t + k * (deg + 1));
	return t;
}

/* The surface quadrature's state, so the helpers below stay short. */
struct squad {
	struct rule ru, rv;
	double *xp, *bu, *bv;   /* x at the nodes; Bernstein tables */
	int m, n;
};

/* B(u, v) at node pair (a, b) for the net ctl. */
static void
net_at(const struct squad *s, const double *ctl, size_t a, size_t b,
    double *p)
{
	const double *bu = s->bu + a * (s->m + 1), *bv = s->bv + b * (s->n + 1);

	p[0] = p[1] = p[2] = 0;
	for (int i = 0; i <= s->m; i++)
		for (int j = 0; j <= s->n; j++)
			vaxpy(p, bu[i] * bv[j], ctl + 3 * (i * (s->n + 1) + j),
			    3);
}

/* The double integral of |x - B|^2 for the net ctl. */
static double
surface_error(const struct squad *s, const double *ctl)
{
	double f = 0;

	for (size_t a = 0; a < s->ru.count; a++)
		for (size_t b = 0; b < s->rv.count; b++) {
			double p[3], d;

			net_at(s, ctl, a, b, p);
			d = vdist(p, s->xp + 3 * (a * s->rv.count + b), 3);
			f += s->ru.w[a] * s->rv.w[b] * d * d;
		}
	return f;
}

/*
 * Steps 2 to 4 of section 4: dF/dlambda_ij = 0 is A lambda = b with
 * A_(ij)(kl) = (N_ij . N_kl) G^m_ik G^n_jl, G the Bernstein Gram
 * matrices, and b_ij = N_ij . double integral of r B_i(u) B_j(v), r = x
 * minus the surface of the net with every lambda zero.
 */
static int
surface_solve(const struct squad *s, const double *nrm, double *ctl,
    struct loft_error *err)
{
	int m = s->m, n = s->n;
	size_t dim = (size_t)(m - 1) * (n - 1);
	double *a = malloc(dim * dim * sizeof *a), *b = calloc(dim, sizeof *b);
	int rc = 0;

	if (a == NULL || b == NULL) {
		free(a);
		free(b);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	for (size_t f = 0; f < dim; f++)
		for (size_t g = 0; g < dim; g++)
			a[f * dim + g] = vdot(nrm + 3 * f, nrm + 3 * g, 3) *
			    loft_bernstein_gram(m, (int)(f / (n - 1)) + 1,
			    (int)(g / (n - 1)) + 1) *
			    loft_bernstein_gram(n, (int)(f % (n - 1)) + 1,
			    (int)(g % (n - 1)) + 1);
	for (size_t qa = 0; qa < s->ru.count; qa++)
		for (size_t qb = 0; qb < s->rv.count; qb++) {
			const double *bu = s->bu + qa * (m + 1);
			const double *bv = s->bv + qb * (n + 1);
			double r[3], w = s->ru.w[qa] * s->rv.w[qb];

			net_at(s, ctl, qa, qb, r);
			vsub(r, s->xp + 3 * (qa * s->rv.count + qb), r, 3);
			for (size_t f = 0; f < dim; f++)
				b[f] += w * bu[f / (n - 1) + 1] *
				    bv[f % (n - 1) + 1] * vdot(nrm + 3 * f, r, 3);
		}
	rc = cholesky_solve(a, b, dim, err);
	for (size_t f = 0; f < dim && rc == 0; f++) {
		size_t i = f / (n - 1) + 1, j = f % (n - 1) + 1;

		vaxpy(ctl + 3 * (i * (n + 1) + j), b[f], nrm + 3 * f, 3);
	}
	free(a);
	free(b);
	return rc;
}

static void
squad_free(struct squad *s)
{
	rule_free(&s->ru);
	rule_free(&s->rv);
	free(s->xp);
	free(s->bu);
	free(s->bv);
}

static int
squad_make(struct squad *s, const struct loft_psurface *x, int m, int n,
    struct loft_error *err)
{
	memset(s, 0, sizeof *s);
	s->m = m;
	s->n = n;
	if (rule_make(&s->ru, x->npu, err) != 0 ||
	    rule_make(&s->rv, x->npv, err) != 0)
		return LOFT_ENOMEM;
	s->xp = malloc(s->ru.count * s->rv.count * 3 * sizeof *s->xp);
	s->bu = bernstein_table(&s->ru, m);
	s->bv = bernstein_table(&s->rv, n);
	if (s->xp == NULL || s->bu == NULL || s->bv == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	return sample_surface(x, &s->ru, &s->rv, s->xp, err);
}

static int normal_surface(const struct loft_psurface *x, int m, int n,
    int clamp, double *ctl, double *error, struct loft_error *err);

int
loft_normal_surface(const struct loft_psurface *x, int m, int n, int clamp,
    double *ctl, double *error, struct loft_error *err)
{
	double pts[SCALE_PROBES * SCALE_PROBES * 3];
	struct scaled c = { NULL, x, 0 };
	struct loft_psurface sx = *x;
	int rc;

	for (int i = 0; i < SCALE_PROBES; i++)
		for (int j = 0; j < SCALE_PROBES; j++)
			x->eval(x->ctx, (double)i / (SCALE_PROBES - 1),
			    (double)j / (SCALE_PROBES - 1),
			    pts + 3 * (i * SCALE_PROBES + j), NULL, NULL, NULL,
			    NULL);
	if ((c.e = scale_of(pts, SCALE_PROBES * SCALE_PROBES * 3)) != 0) {
		sx.eval = scaled_surface_eval;
		sx.ctx = &c;
	}
	rc = normal_surface(&sx, m, n, clamp, ctl, error, err);
	if (rc != 0 || c.e == 0)
		return rc;
	unscale(ctl, (m + 1) * (n + 1) * 3, c.e);
	return unscale_error(error, c.e, "surface", err);
}

static int
normal_surface(const struct loft_psurface *x, int m, int n, int clamp,
    double *ctl, double *error, struct loft_error *err)
{
	struct squad s;
	double *nrm;
	int rc;

	if (m < (clamp ? 3 : 1) || n < (clamp ? 3 : 1) ||
	    m > LOFT_NORMAL_MAXDEG || n > LOFT_NORMAL_MAXDEG)
		return loft_fail(err, LOFT_EINPUT, -1, "degrees %d,%d: want %d "
		    "to %d each", m, n, clamp ? 3 : 1, LOFT_NORMAL_MAXDEG);
	/* zeroed: surface_stations sets the (m - 1)(n - 1) surface_solve
	 * reads, and no entry is ever left unset */
	nrm = calloc((size_t)m * n * 3, sizeof *nrm);
	if (nrm == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	rc = squad_make(&s, x, m, n, err);
	if (rc == 0)
		rc = surface_border(x, m, n, clamp, ctl, err);
	if (rc == 0)
		rc = surface_stations(x, m, n, ctl, nrm, err);
	if (rc == 0 && m > 1 && n > 1)
		rc = surface_solve(&s, nrm, ctl, err);
	if (rc == 0)
		*error = surface_error(&s, ctl);
	squad_free(&s);
	free(nrm);
	return rc;
}
