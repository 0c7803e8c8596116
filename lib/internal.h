/*
 * internal.h: helpers shared by the modules of libloft and not part of
 * its interface (never installed).  Vectors have dim <= LOFT_MAXDIM.
 * It knows only the core (loft.h), so either layer may use it; the CAD
 * readers' own helpers, which write records, are in cadread.h.
 */
#ifndef LOFT_INTERNAL_H
#define LOFT_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "loft.h"

#ifndef M_PI                    /* XSI, not C99 */
#define M_PI 3.14159265358979323846
#endif
#ifndef M_E
#define M_E 2.7182818284590452354
#endif

static inline double
vdot(const double *a, const double *b, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++)
		s += a[k] * b[k];
	return s;
}

/*
 * Plain sums of squares inside [VNORM_LO, VNORM_HI] are exact enough, and
 * vnorm keeps them (figures are compared byte for byte); outside, a
 * square overflowed or lost its digits to underflow, and vnorm scales
 * by a power of two first (exact), so that a length of 1e200 or 1e-200
 * is a length, not infinity or zero: the units of a record never change
 * a result (issue 12).  Both limits leave each square a normal double.
 */
#define VNORM_LO 0x1p-900
#define VNORM_HI 0x1p+900

/* The largest |a[k]|. */
static inline double
vmaxabs(const double *a, int dim)
{
	double m = 0;

	for (int k = 0; k < dim; k++)
		if (fabs(a[k]) > m)
			m = fabs(a[k]);
	return m;
}

/* The power of two that scales the n points p (dimension dim), exactly,
 * into the box [-2, 2) with the largest coordinate's magnitude in
 * [1, 2), so that no square of a distance between them overflows or
 * underflows: into *e.  Returns 0, or -1 (*e untouched) where the points
 * are all 0 or one is not finite. */
static inline int
unit_exponent(const double *p, size_t n, int dim, int *e)
{
	double big = 0;

	for (size_t i = 0; i < n; i++)
		big = fmax(big, vmaxabs(p + i * dim, dim));
	if (!(big > 0) || !isfinite(big))
		return -1;
	*e = ilogb(big);
	return 0;
}

/* |a|: the plain root of the sum of squares, or rescaled where it fails */
static inline double
vnorm(const double *a, int dim)
{
	double s = vdot(a, a, dim), m, t = 0;
	int e;

	if ((s >= VNORM_LO && s <= VNORM_HI) || s != s)
		return sqrt(s);
	m = vmaxabs(a, dim);
	if (m == 0 || isinf(m))
		return m;
	e = ilogb(m);
	for (int k = 0; k < dim; k++) {
		double x = ldexp(a[k], -e);     /* |x| < 2: no overflow */

		t += x * x;
	}
	return ldexp(sqrt(t), e);
}

/* d = a - b */
static inline void
vsub(double *d, const double *a, const double *b, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = a[k] - b[k];
}

/* d += s * a */
static inline void
vaxpy(double *d, double s, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] += s * a[k];
}

static inline void
vscale(double *d, double s, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = s * a[k];
}

/* x[0..n) times 2^e, exactly where no number over- or underflows (as
 * ldexp); nothing where x is NULL */
static inline void
vpow2(double *x, size_t n, int e)
{
	for (size_t k = 0; x != NULL && k < n; k++)
		x[k] = ldexp(x[k], e);
}

static inline void
vcopy(double *d, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = a[k];
}

/* |a - b| */
static inline double
vdist(const double *a, const double *b, int dim)
{
	double d[LOFT_MAXDIM];

	vsub(d, a, b, dim);
	return vnorm(d, dim);
}

/* The square of the distance from q to the segment a b. */
static inline double
vsegdist2(const double *a, const double *b, const double *q, int dim)
{
	double d[LOFT_MAXDIM], e[LOFT_MAXDIM], dd, t;

	vsub(d, b, a, dim);
	vsub(e, q, a, dim);
	dd = vdot(d, d, dim);
	t = dd > 0 ? vdot(e, d, dim) / dd : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	vaxpy(e, -t, d, dim);
	return vdot(e, e, dim);
}

/*
 * Scale a to unit length; returns its former length (0: left alone).
 * A length whose reciprocal would overflow or be subnormal is scaled by
 * a power of two first, exactly.  Each coordinate is divided by the
 * length, correctly rounded, not multiplied by its rounded reciprocal:
 * a direction along an axis is then exactly that axis whatever its
 * length (issue 28: -S 1e-320,0 was not -S 1,0 to the last digit).
 */
static inline double
vunit(double *a, int dim)
{
	double n = vnorm(a, dim);

	if (n > 0 && (n < VNORM_LO || n > VNORM_HI) &&
	    vmaxabs(a, dim) < INFINITY) {       /* n may overflow, a not */
		double m[LOFT_MAXDIM], l;
		int e = ilogb(vmaxabs(a, dim));

		for (int k = 0; k < dim; k++)
			m[k] = ldexp(a[k], -e);
		l = vnorm(m, dim);
		for (int k = 0; k < dim; k++)
			a[k] = m[k] / l;
	} else if (n > 0) {
		for (int k = 0; k < dim; k++)
			a[k] /= n;
	}
	return n;
}

/* cubic.c: eq. 9 from the chord's length w and the cosines ca, cb of the
 * angles the unit tangents at A and B make with it; as loft_normalise. */
int loft__normalise_cos(double w, double ca, double cb, double alpha,
    double *ma, double *mb);

/* knots.c: 0, or LOFT_E* with err filled, for knots no method can fit. */
int loft__check_knots(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, struct loft_error *err);

/* knots.c: unit end tangents t0, tn of an open curve, given or
 * estimated. */
int loft__open_ends(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *t0, double *tn, struct loft_error *err);

/* fair.c: the fair default of loft_fit, from the chord-length spline. */
int loft__fit_fair(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_fit_info *info, struct loft_error *err);

/* fit.c: Manning's spline (sections 5, 6, 9) through knots already in
 * the unit box, as loft_fit's LOFT_MANNING; also a start of fair.c. */
int loft__fit_manning(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, double *seg, struct loft_fit_info *info,
    struct loft_error *err);

/* cspline.c: the Ferguson and chord-length baselines of loft_fit. */
int loft__fit_cspline(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, double *seg, struct loft_error *err);

/* No tangent vector of a fit longer than this many times its chord: a
 * curve's energy falls as it grows (a circle's is 2 pi / R), so a fair
 * descent left free would swell loops out of the knots' reach, and a
 * flat join past it would swell as far. */
#define LOFT__MAXMAG 3.0

/*
 * cspline.c: a span alone between a straight run (its tangent given,
 * o->flat_start or o->flat_end) and a free end (a corner's), n 2, met
 * G2 at the run, as Spiro's `[' `]' points meet theirs.  The chord
 * spline has there the given unit tangent g times the chord c, and at
 * the free end g's mirror in the chord r = 2 (g.u) u - g times c, u the
 * unit chord: G1.  Here the free end's is r times 3 c / (2 g.u), which
 * turns P''(0) = 6 c u - 4 c g - 2 |P'(1)| r along g: curvature 0 at
 * the run.  Its Bezier points are A, A + c g / 3, the meeting of the
 * two end tangents' lines, and B: a convex polygon turning by twice the
 * angle of g from the chord, so the curve never loops.  Only where g
 * is within 60 degrees of the chord (that magnitude at most
 * LOFT__MAXMAG chords); past it the join stays G1.  The segment into
 * seg; 0, or 1 where it does not apply (then seg is untouched).
 */
int loft__flat_join(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, double *seg);

/*
 * cspline.c: the spline of continuous first derivatives with parameter
 * intervals h (one per segment, positive) whose second derivative at
 * knot i jumps along the tangent so that the system's diagonal is
 * (h0 + h1)(1 + e^y_i) (y NULL: continuous second derivatives; on an
 * open curve e^y_0 and e^y_{n-1} scale the end derivatives), into seg
 * as loft_fit writes it; the curvature is continuous whatever h and y.
 * work: 7n + 2n dim numbers, which keep the system for
 * loft__cspline_adjoint.  Returns 0 or an error of the end tangents.
 */
int loft__cspline_h(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, const double *h, const double *y, double *seg, double *work,
    struct loft_error *err);

/*
 * cspline.c: the gradient gh (one per segment) with respect to the
 * intervals h of a function of the segments, given its gradient gseg
 * with respect to each segment's P'_A and P'_B (2 dim numbers per
 * segment), by the adjoint of the system, and with respect to y into gy
 * (n numbers) unless NULL; work as loft__cspline_h left it for the same
 * h and y.
 */
void loft__cspline_adjoint(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, const double *h, const double *y, const double *gseg,
    double *gh, double *gy, double *work);

/*
 * dtoa.c: exact decimal conversion.  Each returns 0, or -1 in a rare
 * case its 128-bit arithmetic cannot decide; the caller then asks the C
 * library.  x is finite and positive.
 * loft__shortest: the fewest significant digits d (maybe with trailing
 * zeros) with d 10^e reading back to x, the nearest such to x.
 * loft__round_digits: x rounded to p (1..17) significant digits, ties to
 * even, as printf rounds: d has p digits.
 * loft__decimal_to_double: w 10^e rounded to the nearest double, normal
 * doubles only (-1 for subnormal or overflowing results).
 * loft__decimal_text: d 10^e (d > 0) laid out as printf's %.{prec}g lays
 * out those digits, trailing zeros dropped; returns the length written.
 */
int loft__shortest(double x, uint64_t *d, int *e);
int loft__round_digits(double x, int p, uint64_t *d, int *e);
int loft__decimal_to_double(uint64_t w, int e, double *x);
int loft__decimal_text(char *buf, uint64_t d, int e, int prec);
/* floor(log10(2^q)) and floor(log10(3/4 2^q)), for |q| <= 1200 */
int loft__floor_log10_pow2(int q);
int loft__floor_log10_3q_pow2(int q);

/*
 * cholesky.c: solve A x = b in place of b, A the symmetric positive
 * definite n x n matrix a (row-major, overwritten by its Cholesky
 * factor).  Returns 0, or -1 when a pivot is not above rel times A's
 * largest diagonal (rel 0: not positive), with its index in *at and its
 * ratio to that diagonal in *pivot (either may be NULL); b is then
 * unchanged.
 */
int loft__cholesky_solve(double *a, double *b, size_t n, double rel,
    size_t *at, double *pivot);
/* grow.c: grow *buf to hold at least need elements of size sz; 0 or -1. */
int loft__grow(void **buf, size_t *cap, size_t need, size_t sz);

/*
 * The operations of a curve type, which its row of types.c's table
 * names (curve.c has the built-in ones).  A piecewise type has a row
 * per piece, rows_per_point numbers a coordinate in a row, and eval; a
 * control-point type (eval NULL) is one piece of a point per row,
 * evaluated by eval_ctl, and is its own Bezier form (bezier NULL).
 * bezier: a piece's Bernstein control points, returning its degree.
 * quartic: a piece as MacCallum's quartic (0) (1) (0)_u (1)_u (h),
 * 5 dim numbers, exactly; NULL for a type of no such form (degree above
 * four, or no Hermite segments): programs that work on quartic segments
 * (patchnew -b, patchdrag, patchloft) then refuse it with a message.
 */
struct loft__curve_type {
	const char *name;
	int rows_per_point;     /* numbers in a row, per coordinate */
	void (*eval)(const double *piece, int dim, double u,
	    double *p, double *d1, double *d2);
	void (*eval_ctl)(const double *ctl, size_t npts, int dim, double u,
	    double *p, double *d1, double *d2);
	int (*bezier)(const double *piece, int dim, double *ctl);
	void (*quartic)(const double *piece, int dim, double *q);
};

/*
 * The operations of a surface type (surface.c has the built-in ones).
 * bezier: its control net in space (loft_surface_bezier).
 */
struct loft__surface_type {
	const char *name;
	/* check rec's rows and attributes; set s->dim, s->m, s->n */
	int (*check)(const struct loft_record *rec, struct loft_surface *s,
	    struct loft_error *err);
	void (*eval)(const struct loft_surface *s, double u, double v,
	    double *p, double *du, double *dv);
	void (*eval2)(const struct loft_surface *s, double u, double v,
	    double *p, double *du, double *dv, double *duu, double *dvv);
	/* the box of a set of points around the surface (its hull) */
	void (*box)(const struct loft_surface *s, double *lo, double *hi);
	void (*bezier)(const struct loft_surface *s, double *ctl);
};

/* curve.c and surface.c: the operations of each curve and surface type,
 * which types.c's table names. */
extern const struct loft__curve_type loft__cubic_type, loft__quartic_type,
    loft__bezier_type;
extern const struct loft__surface_type loft__patch_type,
    loft__bezier_surface_type;

/* surfmeasure.c: Gauss-Legendre nodes and weights of order 5 on [0, 1]. */
extern const double loft__gl5_x[5], loft__gl5_w[5];

/* quartic.c: the quartic with coefficient vectors k[0..4] at u (any of
 * p, d1, d2 may be NULL); loft_quartic_eval over pointers. */
void loft__quartic_combine(const double *const *k, int dim, double u,
    double *p, double *d1, double *d2);

/* quartic.c: H5(u) = 16 u^2 (1 - u)^2, the bump of section 4. */
double loft__h5(double u);

/* quartic.c: the quartic coefficients, over x in [0, 1], of
 * H5(a + b x): the restriction of the bump to a piece of it. */
void loft__bump(double a, double b, double *coef);

/* bezier.c: loft_bezier_surface_eval with second derivatives too. */
void loft__bezier_surface_eval2(const double *ctl, int m, int n, double u,
    double v, double *p, double *pu, double *pv, double *puu, double *pvv);

/* patch.c: 0, or LOFT_EINPUT with err filled, unless rec has the five
 * rows of 10 or 15 numbers of a patch. */
int loft__patch_shape(const struct loft_record *rec, struct loft_error *err);

/*
 * bernstein.c: polynomials on [0, 1] in the Bernstein basis, as
 * coefficient arrays c[0..n] of degree n <= LOFT__BMAX - 1.  The degree
 * 6 n - 9 of the curvature-derivative numerator of a space Bezier curve
 * with LOFT_BEZIER_MAXPTS points fits.
 */
#define LOFT__BMAX (6 * LOFT_BEZIER_MAXPTS)
/* The value at t, by de Casteljau's algorithm. */
double loft__bern_eval(const double *c, int n, double t);
/* h[0..m+n] = f g, f of degree m and g of degree n. */
void loft__bern_mul(const double *f, int m, const double *g, int n, double *h);
/* f[0..n] += s g, g of degree m <= n raised to degree n. */
void loft__bern_addto(double *f, int n, double s, const double *g, int m);
/* The largest |c[i]|: a bound on |f| over [0, 1]. */
double loft__bern_max(const double *c, int n);
/*
 * The roots of c in (0, 1), increasing, at most max of them, written to
 * r; returns their count.  Coefficients within zero of 0 count as 0: a
 * stretch where the polynomial stays within zero has no roots.  Roots
 * are isolated by subdivision (a polynomial whose coefficients do not
 * change sign has no root) and refined to the last bits by bisection.
 */
int loft__bern_roots(const double *c, int n, double zero, double *r, int max);

/*
 * A piece of a curve as a Bezier curve: degree n, dim, and per
 * coordinate k its control values b[k][0..n] and those of its first,
 * second and third derivatives (degree max(n - j, 0), zero where the
 * piece has none).
 */
struct loft__piece {
	int n, dim;
	double b[LOFT_MAXDIM][LOFT_BEZIER_MAXPTS];
	double d1[LOFT_MAXDIM][LOFT_BEZIER_MAXPTS];
	double d2[LOFT_MAXDIM][LOFT_BEZIER_MAXPTS];
	double d3[LOFT_MAXDIM][LOFT_BEZIER_MAXPTS];
	double p1[LOFT_MAXDIM][8], p2[LOFT_MAXDIM][8]; /* low degrees: P'
	                           and P'' in powers of u, for speed */
};
/* The degree of the j-th derivative's coefficients in a piece. */
#define LOFT__DEG(pc, j) ((pc)->n > (j) ? (pc)->n - (j) : 0)
/* Piece i of c, every coefficient times 2^-e: exact, but for overflow
 * and subnormals; a piece of any size brought near 1 (issue 28). */
void loft__piece(const struct loft_curve *c, size_t i, int e,
    struct loft__piece *pc);
/* Point, first and second derivatives at u (any may be NULL). */
void loft__piece_eval(const struct loft__piece *pc, double u, double *p,
    double *d1, double *d2);
/* The diagonal of the box around all control points of c: its size. */
double loft__curve_extent(const struct loft_curve *c);

/*
 * arclen.c: adaptive Gauss-Kronrod (7, 15) quadrature of the m <= 4
 * integrands f writes at u, over [a, b] of piece pc.  An interval is
 * accepted when every component's |K15 - G7| is at most rel times the
 * K15 of its absolute value plus floor[k] (b - a) (floor may be NULL),
 * else it is halved, the tolerance with it.  Adds the integrals to
 * sum[0..m) and, if depth is not NULL, stores the deepest halving.
 * Returns 0, or LOFT_ENOCONV when an interval was accepted
 * at the depth limit without meeting its tolerance.
 */
typedef void (*loft__integrand)(const struct loft__piece *pc, double u,
    double *f, void *ctx);
int loft__quad(const struct loft__piece *pc, double a, double b, int m,
    loft__integrand f, void *ctx, double rel, const double *floor,
    double *sum, int *depth);
/* The speed |P'(u)|: the integrand of arc length. */
void loft__speed(const struct loft__piece *pc, double u, double *f, void *ctx);

#endif
