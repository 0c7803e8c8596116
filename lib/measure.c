/*
 * measure.c: the shape of a curve record of any type in numbers: area
 * and centroid, exact bounding box, curvature (smallest radius,
 * inflexions, extrema, bending energy, jumps at knots).  Each piece is
 * taken in the Bernstein basis (bernstein.c), where the polynomials
 * whose roots matter (a coordinate's derivative, the cross product
 * P' x P'', the numerator of dk/du) are exact products of the control
 * values and their roots are isolated by subdivision, never sampled.
 */
#include <float.h>
#include <math.h>

#include "internal.h"

/*
 * A polynomial whose coefficients stay within this fraction of the
 * products it is made of is taken as zero: the rounding of those
 * products is some 1e-16 of them, so 1e-10 leaves a wide margin, and a
 * curve whose curvature changes by less than that relative amount over
 * a piece is, for a designer, of constant curvature there.
 */
#define CURV_ZERO 1e-10

/*
 * A coordinate's derivative within this fraction of the piece's largest
 * derivative has no extremum worth finding: the coordinate moves by less
 * than that fraction of the piece's size.
 */
#define BOX_ZERO 1e-14

/*
 * A curve whose largest curvature times its size is below this does not
 * bend: straight, to rounding.
 */
#define FLAT 1e-10

/* Relative accuracy of the bending energy's quadrature. */
#define ENERGY_REL 1e-10

/* A closed curve encloses no area below this fraction of its size^2. */
#define AREA_ZERO 1e-12

/*
 * The products below (a coordinate cubed, a speed to the sixth) leave
 * the doubles for curves of 1e+-60 and beyond, so every piece is taken
 * scaled by 2^-e, e the exponent of the curve's size: exact, and the
 * same e for every piece, so that the results of pieces compare; each
 * result is scaled back by the power of e it has (issue 28).
 */
static int
curve_exp(const struct loft_curve *c)
{
	double size = loft__curve_extent(c);

	return size > 0 && size < INFINITY ? ilogb(size) : 0;
}

/* Piece i of c scaled by 2^-e. */
static void
piece_at(const struct loft_curve *c, size_t i, int e, struct loft__piece *pc)
{
	loft__piece(c, i, e, pc);
}

void
loft_curve_bbox(const struct loft_curve *c, double *lo, double *hi)
{
	struct loft__piece pc;
	double r[LOFT__BMAX];
	int e = curve_exp(c);

	for (size_t i = 0; i < c->npieces; i++) {
		double big = 0;

		piece_at(c, i, e, &pc);
		for (int k = 0; k < c->dim; k++)
			big = fmax(big, loft__bern_max(pc.d1[k], pc.n - 1));
		for (int k = 0; k < c->dim; k++) {
			int nr = loft__bern_roots(pc.d1[k], pc.n - 1,
			    BOX_ZERO * big, r, LOFT__BMAX);

			if (i == 0)
				lo[k] = hi[k] = pc.b[k][0];
			lo[k] = fmin(lo[k], fmin(pc.b[k][0], pc.b[k][pc.n]));
			hi[k] = fmax(hi[k], fmax(pc.b[k][0], pc.b[k][pc.n]));
			for (int j = 0; j < nr; j++) {
				double x = loft__bern_eval(pc.b[k], pc.n, r[j]);

				lo[k] = fmin(lo[k], x);
				hi[k] = fmax(hi[k], x);
			}
		}
	}
	for (int k = 0; k < c->dim && c->npieces > 0; k++) {
		lo[k] = ldexp(lo[k], e);
		hi[k] = ldexp(hi[k], e);
	}
}

/*
 * Green's theorem over piece pc, coordinates relative to o: the
 * integrals of X Y', X^2 Y' and Y^2 X' over [0, 1], exact: each is a
 * Bernstein product whose integral is the mean of its coefficients.
 */
static void
green(const struct loft__piece *pc, const double *o, double *m)
{
	double x[LOFT_BEZIER_MAXPTS], y[LOFT_BEZIER_MAXPTS];
	double t[LOFT__BMAX], u[LOFT__BMAX];
	int n = pc->n;

	for (int j = 0; j <= n; j++) {
		x[j] = pc->b[0][j] - o[0];
		y[j] = pc->b[1][j] - o[1];
	}
	m[0] = m[1] = m[2] = 0;
	/* X Y' - Y X', degree 2n - 1 */
	loft__bern_mul(x, n, pc->d1[1], n - 1, t);
	loft__bern_mul(y, n, pc->d1[0], n - 1, u);
	for (int j = 0; j < 2 * n; j++)
		m[0] += (t[j] - u[j]) / (2 * n);
	/* X^2 Y' and Y^2 X', degree 3n - 1 */
	loft__bern_mul(x, n, x, n, u);
	loft__bern_mul(u, 2 * n, pc->d1[1], n - 1, t);
	for (int j = 0; j < 3 * n; j++)
		m[1] += t[j] / (3 * n);
	loft__bern_mul(y, n, y, n, u);
	loft__bern_mul(u, 2 * n, pc->d1[0], n - 1, t);
	for (int j = 0; j < 3 * n; j++)
		m[2] += t[j] / (3 * n);
}

/* Area and first moments of a plane curve, about its first point o, of
 * the curve scaled by 2^-e. */
static void
plane_moments(const struct loft_curve *c, int e, double *o, double *area,
    double *mx, double *my)
{
	struct loft__piece pc;
	double m[3];

	*area = *mx = *my = 0;
	for (size_t i = 0; i < c->npieces; i++) {
		piece_at(c, i, e, &pc);
		if (i == 0) {
			o[0] = pc.b[0][0];
			o[1] = pc.b[1][0];
		}
		green(&pc, o, m);
		*area += 0.5 * m[0];
		*mx += 0.5 * m[1];
		*my -= 0.5 * m[2];
	}
}

int
loft_curve_area(const struct loft_curve *c, double *area,
    struct loft_error *err)
{
	double o[2], mx, my;
	int e = curve_exp(c);

	if (c->dim != 2)
		return loft_fail(err, LOFT_EINPUT, -1, "a space curve bounds no "
		    "plane area");
	plane_moments(c, e, o, area, &mx, &my);
	mx = *area;
	*area = ldexp(*area, 2 * e);
	if (mx != 0 && !(fabs(*area) >= DBL_MIN))
		return loft_fail(err, LOFT_EGEOM, -1, "the area, of the "
		    "order of %g^2, underflows: no double holds it",
		    ldexp(1, e));
	return 0;
}

/* The speed and the moments (P - o) |P'| of the curve's length. */
static void
length_moments(const struct loft__piece *pc, double u, double *f, void *ctx)
{
	const double *o = ctx;
	double p[LOFT_MAXDIM];

	loft__speed(pc, u, f, NULL);
	loft__piece_eval(pc, u, p, NULL, NULL);
	for (int k = 0; k < pc->dim; k++)
		f[k + 1] = (p[k] - o[k]) * f[0];
}

int
loft_curve_centroid(const struct loft_curve *c, double *cen,
    struct loft_error *err)
{
	struct loft__piece pc;
	double o[LOFT_MAXDIM], sum[LOFT_MAXDIM + 1] = { 0 };
	int e = curve_exp(c);

	if (c->npieces == 0)    /* o below is the first piece's start */
		return loft_fail(err, LOFT_EINPUT, -1, "a curve of no pieces "
		    "has no centroid");
	if (c->closed && c->dim == 2) {
		double area, mx, my, size;

		plane_moments(c, e, o, &area, &mx, &my);
		size = ldexp(loft__curve_extent(c), -e);
		if (!(fabs(area) > AREA_ZERO * size * size))
			return loft_fail(err, LOFT_EGEOM, -1, "the closed curve "
			    "encloses no area: its centroid is undefined");
		cen[0] = ldexp(o[0] + mx / area, e);
		cen[1] = ldexp(o[1] + my / area, e);
		return 0;
	}
	for (size_t i = 0; i < c->npieces; i++) {
		piece_at(c, i, e, &pc);
		if (i == 0)
			for (int k = 0; k < c->dim; k++)
				o[k] = pc.b[k][0];
		loft__quad(&pc, 0, 1, c->dim + 1, length_moments, o,
		    LOFT_ARC_REL, NULL, sum, NULL);
	}
	if (!(sum[0] > 0)) {
		for (int k = 0; k < c->dim; k++)
			cen[k] = ldexp(o[k], e);
		return 0;
	}
	for (int k = 0; k < c->dim; k++)
		cen[k] = ldexp(o[k] + sum[k + 1] / sum[0], e);
	return 0;
}

/* a x b - a' x b' for the plane parts of coordinates (i, j). */
static int
cross_poly(const double (*a)[LOFT_BEZIER_MAXPTS], int na,
    const double (*b)[LOFT_BEZIER_MAXPTS], int nb, int i, int j, double *out)
{
	double t[LOFT__BMAX];

	loft__bern_mul(a[i], na, b[j], nb, out);
	loft__bern_mul(a[j], na, b[i], nb, t);
	for (int q = 0; q <= na + nb; q++)
		out[q] -= t[q];
	return na + nb;
}

/* sum over k of a_k b_k, degree na + nb. */
static int
dot_poly(const double (*a)[LOFT_BEZIER_MAXPTS], int na,
    const double (*b)[LOFT_BEZIER_MAXPTS], int nb, int dim, double *out)
{
	double t[LOFT__BMAX];

	for (int q = 0; q <= na + nb; q++)
		out[q] = 0;
	for (int k = 0; k < dim; k++) {
		loft__bern_mul(a[k], na, b[k], nb, t);
		for (int q = 0; q <= na + nb; q++)
			out[q] += t[q];
	}
	return na + nb;
}

/*
 * The speed scale of piece pc: its largest first-derivative coefficient,
 * a bound on |P'|.  The thresholds below are made of it alone: a
 * piece's higher derivatives' coefficients can be far larger than the
 * derivatives (a Bezier curve of high degree), and a straight piece's
 * are rounding.
 */
static double
speed_scale(const struct loft__piece *pc)
{
	double m = 0;

	for (int k = 0; k < pc->dim; k++)
		m = fmax(m, loft__bern_max(pc->d1[k], LOFT__DEG(pc, 1)));
	return m;
}

/*
 * The plane cross product C = x' y'' - y' x'' of piece pc, whose sign
 * is the curvature's; returns its degree and sets *zero, the size below
 * which its values are rounding: C = k |P'|^3, and a curvature below
 * CURV_ZERO over the piece's length (of the order of the speed scale m)
 * is none, so zero = CURV_ZERO m^2.
 */
static int
plane_cross(const struct loft__piece *pc, double *out, double *zero)
{
	int n1 = LOFT__DEG(pc, 1), n2 = LOFT__DEG(pc, 2);
	double m = speed_scale(pc);

	*zero = CURV_ZERO * m * m;
	return cross_poly(pc->d1, n1, pc->d2, n2, 0, 1, out);
}

/*
 * The numerator N of dk/du, whose sign is that of the derivative of the
 * curvature: with Q = P'.P', D = P'.P'' (Manning's eq. 2 differentiated),
 * in the plane k = C Q^(-3/2), N = C' Q - 3 C D, C' = x' y''' - y' x''';
 * in space k^2 = |c|^2 Q^-3 with c = P' x P'', N = (c.c') Q - 3 (c.c) D,
 * c' = P' x P''' (the sign of d|k|/du where k > 0).  Returns the degree
 * and sets *zero as plane_cross does.
 */
static int
curvature_slope(const struct loft__piece *pc, double *out, double *zero)
{
	int n1 = LOFT__DEG(pc, 1), n2 = LOFT__DEG(pc, 2), n3 = LOFT__DEG(pc, 3);
	double q[LOFT__BMAX], d[LOFT__BMAX], a[LOFT__BMAX], b[LOFT__BMAX],
	    t[LOFT__BMAX], m;
	int nq, nd, na, nb, deg;

	nq = dot_poly(pc->d1, n1, pc->d1, n1, pc->dim, q);
	nd = dot_poly(pc->d1, n1, pc->d2, n2, pc->dim, d);
	if (pc->dim == 2) {
		/* a = C', b = C */
		na = cross_poly(pc->d1, n1, pc->d3, n3, 0, 1, a);
		nb = cross_poly(pc->d1, n1, pc->d2, n2, 0, 1, b);
	} else {
		double c[3][LOFT__BMAX], e[3][LOFT__BMAX];
		int nc = 0, ne = 0;

		for (int k = 0; k < 3; k++) {
			nc = cross_poly(pc->d1, n1, pc->d2, n2, (k + 1) % 3,
			    (k + 2) % 3, c[k]);
			ne = cross_poly(pc->d1, n1, pc->d3, n3, (k + 1) % 3,
			    (k + 2) % 3, e[k]);
		}
		/* a = c.c', b = c.c */
		na = nc + ne;
		nb = 2 * nc;
		for (int j = 0; j <= na; j++)
			a[j] = 0;
		for (int j = 0; j <= nb; j++)
			b[j] = 0;
		for (int k = 0; k < 3; k++) {
			loft__bern_mul(c[k], nc, e[k], ne, t);
			for (int j = 0; j <= na; j++)
				a[j] += t[j];
			loft__bern_mul(c[k], nc, c[k], nc, t);
			for (int j = 0; j <= nb; j++)
				b[j] += t[j];
		}
	}
	/* N = dk/ds |P'|^6 in the plane and k dk/ds |P'|^9 in space:
	 * below a change of CURV_ZERO of the curvature over the piece's
	 * length, of the order of m, N is rounding */
	m = speed_scale(pc);
	*zero = CURV_ZERO * (pc->dim == 2 ? m * m * m * m :
	    m * m * m * m * m * m);
	deg = na + nq > nb + nd ? na + nq : nb + nd;
	for (int j = 0; j <= deg; j++)
		out[j] = 0;
	loft__bern_mul(a, na, q, nq, t);
	loft__bern_addto(out, deg, 1, t, na + nq);
	loft__bern_mul(b, nb, d, nd, t);
	loft__bern_addto(out, deg, -3, t, nb + nd);
	return deg;
}

/* Sign changes along a curve, cyclically on a closed one. */
struct signs {
	int first, last;
	long changes;
};

static void
feed(struct signs *s, int sign)
{
	if (sign == 0)
		return;
	if (s->first == 0)
		s->first = sign;
	else if (sign != s->last)
		s->changes++;
	s->last = sign;
}

/* The signs of poly between its roots r[0..nr) in a piece, in order. */
static void
feed_piece(struct signs *s, const double *poly, int deg, double zero,
    const double *r, int nr)
{
	for (int j = 0; j <= nr; j++) {
		double a = j == 0 ? 0 : r[j - 1], b = j == nr ? 1 : r[j];
		double v = loft__bern_eval(poly, deg, 0.5 * (a + b));

		if (b > a)
			feed(s, v > zero ? 1 : v < -zero ? -1 : 0);
	}
}

static long
sign_changes(const struct signs *s, int closed)
{
	return s->changes + (closed && s->first != 0 && s->first != s->last);
}

/*
 * The sign changes along c of the polynomial poly makes of each piece
 * (plane_cross or curvature_slope).
 */
static long
count_changes(const struct loft_curve *c,
    int (*poly)(const struct loft__piece *, double *, double *))
{
	struct loft__piece pc;
	struct signs s = { 0, 0, 0 };
	double p[LOFT__BMAX], r[LOFT__BMAX], zero;
	int e = curve_exp(c);

	for (size_t i = 0; i < c->npieces; i++) {
		int deg, nr;

		piece_at(c, i, e, &pc);
		deg = poly(&pc, p, &zero);
		nr = loft__bern_roots(p, deg, zero, r, LOFT__BMAX);
		feed_piece(&s, p, deg, zero, r, nr);
	}
	return sign_changes(&s, c->closed);
}

int
loft_curve_inflexions(const struct loft_curve *c, long *count,
    struct loft_error *err)
{
	if (c->dim != 2)
		return loft_fail(err, LOFT_EINPUT, -1, "a space curve's "
		    "curvature has no sign: inflexions are for plane curves");
	*count = count_changes(c, plane_cross);
	return 0;
}

int
loft_curve_extrema(const struct loft_curve *c, long *count,
    struct loft_error *err)
{
	(void)err;
	*count = count_changes(c, curvature_slope);
	return 0;
}

/* |a x b| in the plane or in space. */
static double
cross_norm(const double *a, const double *b, int dim)
{
	double c[3];

	if (dim < 3)            /* in the plane (dim is 2 or 3) */
		return fabs(a[0] * b[1] - a[1] * b[0]);
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
	return vnorm(c, 3);
}

/* Whether piece pc is straight: P' x P'' within rounding throughout. */
static int
piece_straight(const struct loft__piece *pc)
{
	static const int pair[3][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };
	double t[LOFT__BMAX], m = speed_scale(pc), zero = CURV_ZERO * m * m;

	for (int k = 0; k < (pc->dim == 2 ? 1 : 3); k++) {
		int deg = cross_poly(pc->d1, LOFT__DEG(pc, 1), pc->d2,
		    LOFT__DEG(pc, 2), pair[k][0], pair[k][1], t);

		if (loft__bern_max(t, deg) > zero)
			return 0;
	}
	return 1;
}

/*
 * |k| at the end `end` (0 or 1) of piece pc where P' vanishes, as a
 * retracted Bezier handle makes it: the limit from inside the piece.
 * With h the distance in u from that end, P' = h P'' + h^2/2 P''' +
 * h^3/6 P'''' + ..., so P' x P'' = h^2/2 P'' x P''' + h^3/3 P'' x P''''
 * + ... and |P'|^3 = |h|^3 |P''|^3: |k| grows without bound unless
 * P'' x P''' = 0, and is then |P'' x P''''| / (3 |P''|^3).  A straight
 * piece has k = 0 whatever its speed.  Returns 0 with *k set, 1 when k
 * grows without bound, or -1 when P'' vanishes too (no limit taken).
 */
static int
end_limit(const struct loft__piece *pc, int end, double *k)
{
	int n2 = LOFT__DEG(pc, 2), n3 = LOFT__DEG(pc, 3);
	double a[LOFT_MAXDIM] = { 0 }, b[LOFT_MAXDIM] = { 0 },
	    d[LOFT_MAXDIM] = { 0 }, na, nb;

	if (!(speed_scale(pc) > 0))
		return -1;      /* the piece is a point: no tangent anywhere */
	if (piece_straight(pc)) {
		*k = 0;
		return 0;
	}
	for (int q = 0; q < pc->dim; q++) {
		a[q] = pc->d2[q][end ? n2 : 0];
		b[q] = pc->d3[q][end ? n3 : 0];
		d[q] = n3 == 0 ? 0 : end ? n3 * (pc->d3[q][n3] -
		    pc->d3[q][n3 - 1]) : n3 * (pc->d3[q][1] - pc->d3[q][0]);
	}
	na = vnorm(a, pc->dim);
	nb = vnorm(b, pc->dim);
	if (!(na > CURV_ZERO * speed_scale(pc)))
		return -1;
	if (cross_norm(a, b, pc->dim) > CURV_ZERO * na * nb)
		return 1;
	*k = cross_norm(a, d, pc->dim) / (3 * na * na * na);
	return 0;
}

/* |k| of piece pc at u into *k: 0, or as end_limit where P' = 0. */
static int
piece_curvature(const struct loft__piece *pc, double u, double *k)
{
	double d1[LOFT_MAXDIM], d2[LOFT_MAXDIM];

	loft__piece_eval(pc, u, NULL, d1, d2);
	if (loft_curvature(d1, d2, pc->dim, k) == 0) {
		*k = fabs(*k);
		return 0;
	}
	return u == 0 || u == 1 ? end_limit(pc, u == 1, k) : -1;
}

int
loft_curve_min_radius(const struct loft_curve *c, double *radius, double *u,
    struct loft_error *err)
{
	struct loft__piece pc;
	double poly[LOFT__BMAX], r[LOFT__BMAX + 2], zero, most = 0, where = 0;
	int e = curve_exp(c);

	for (size_t i = 0; i < c->npieces; i++) {
		int deg, nr;

		piece_at(c, i, e, &pc);
		deg = curvature_slope(&pc, poly, &zero);
		nr = loft__bern_roots(poly, deg, zero, r + 1, LOFT__BMAX);
		r[0] = 0;
		r[nr + 1] = 1;
		for (int j = 0; j < nr + 2; j++) {
			double k;
			int rc = piece_curvature(&pc, r[j], &k);

			if (rc < 0)
				return loft_fail(err, LOFT_EGEOM, (long)i, "the "
				    "tangent vanishes in piece %zu at u = %.17g: "
				    "a cusp, of radius 0", i + 1, r[j]);
			if (rc > 0)
				return loft_fail(err, LOFT_EGEOM, (long)i, "the "
				    "curvature grows without bound toward u = "
				    "%.17g of piece %zu, where a handle is "
				    "retracted and the curve bends (as y = "
				    "x^1.5): no smallest radius", r[j], i + 1);
			if (k > most) {
				most = k;
				where = (double)i + r[j];
			}
		}
	}
	if (!isfinite(most))
		return loft_fail(err, LOFT_EGEOM, -1, "the curvature "
		    "overflows: coefficients too large");
	if (!(most * ldexp(loft__curve_extent(c), -e) > FLAT)) {
		*radius = 0;
		*u = 0;
		return 0;
	}
	*radius = ldexp(1 / most, e);
	*u = where;
	return 0;
}

/*
 * k^2 |P'| = |P' x P''|^2 / |P'|^5, the integrand of bending energy,
 * from the derivatives divided by their largest component m (k scales
 * as 1/m, |P'| as m), so that neither overflows nor underflows.
 */
static void
bending(const struct loft__piece *pc, double u, double *f, void *ctx)
{
	double d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], q, cc, m = 0;

	(void)ctx;
	loft__piece_eval(pc, u, NULL, d1, d2);
	for (int k = 0; k < pc->dim; k++)
		m = fmax(m, fmax(fabs(d1[k]), fabs(d2[k])));
	if (!(m > 0)) {
		f[0] = 0;
		return;
	}
	for (int k = 0; k < pc->dim; k++) {
		d1[k] /= m;
		d2[k] /= m;
	}
	q = vdot(d1, d1, pc->dim);
	if (pc->dim == 2) {
		cc = d1[0] * d2[1] - d1[1] * d2[0];
		cc *= cc;
	} else {
		double a = d1[1] * d2[2] - d1[2] * d2[1],
		    b = d1[2] * d2[0] - d1[0] * d2[2],
		    e = d1[0] * d2[1] - d1[1] * d2[0];

		cc = a * a + b * b + e * e;
	}
	/* a curvature below CURV_ZERO over the piece's length is none, as
	 * for inflexions: a straight piece has energy 0, not rounding */
	f[0] = cc <= CURV_ZERO * CURV_ZERO * q * q ? 0 :
	    cc / (q * q * sqrt(q)) / m;
}

int
loft_curve_energy(const struct loft_curve *c, double *energy,
    struct loft_error *err)
{
	struct loft__piece pc;
	int x = curve_exp(c);
	double floor = ENERGY_REL / ldexp(loft__curve_extent(c), -x), e = 0;

	for (size_t i = 0; i < c->npieces; i++) {
		piece_at(c, i, x, &pc);
		if (loft__quad(&pc, 0, 1, 1, bending, NULL, ENERGY_REL, &floor,
		    &e, NULL) != 0 || !isfinite(e))
			return loft_fail(err, LOFT_EGEOM, (long)i, "the bending "
			    "energy of piece %zu is unbounded: its tangent "
			    "vanishes (a cusp) or its curvature grows without "
			    "bound at an end (a retracted handle)", i + 1);
	}
	*energy = ldexp(e, -x);
	return 0;
}

void
loft_curve_jump(const struct loft_curve *c, double *jump, double *u)
{
	*jump = 0;
	*u = 0;
	for (size_t i = 0; i < c->npieces; i++) {
		size_t next = i + 1 == c->npieces ? 0 : i + 1;
		double d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], ka[LOFT_MAXDIM],
		    kb[LOFT_MAXDIM];

		if (next == 0 && !c->closed)
			break;
		loft_curve_eval(c, i, 1, NULL, d1, d2);
		if (loft_curvature_vector(d1, d2, c->dim, ka) != 0)
			continue;
		loft_curve_eval(c, next, 0, NULL, d1, d2);
		if (loft_curvature_vector(d1, d2, c->dim, kb) != 0)
			continue;
		if (vdist(ka, kb, c->dim) > *jump) {
			*jump = vdist(ka, kb, c->dim);
			*u = next == 0 ? 0 : (double)next;
		}
	}
}
