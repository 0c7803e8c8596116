/*
 * fair.c: the fair default of loft_fit.  Of the cubic splines with
 * continuous first and second derivatives (so continuous tangent and
 * curvature: G2) through the knots, with any positive parameter
 * intervals h_i, the one of least bending energy E, the integral of
 * curvature squared along the curve, that descent from the chord-length
 * intervals reaches.
 *
 * Every h gives a G2 curve through the knots from one tridiagonal
 * system, so no step can break continuity or fail.  E and its gradient
 * with respect to log h cost O(n): E by Gauss quadrature per segment,
 * dE/dP' in closed form, dE/dh by the adjoint of the system (cspline.c).
 * The descent takes L-BFGS steps, each kept only when it lowers E enough
 * (Armijo) and keeps every curvature within the chord spline's largest;
 * the result must be fairer than the chord-length spline by a finer
 * quadrature, no more sharply bent, and (in the plane) cross itself only
 * where the chord spline does, or the chord spline is written instead.
 *
 * The free second-derivative jumps make the family every G2 cubic curve
 * through the knots with those end tangents: the tangent magnitudes at a
 * knot may differ (h) and the curvature is matched without matching
 * P'' (y), the two freedoms Manning's normalisation fixes one way.
 *
 * Sparse closed records are searched thoroughly (thorough): five starts,
 * one of them a direction estimate in Spiro's manner (spiral_solve: the
 * knots' tangent angles at which Euler spirals through consecutive knots
 * meet with equal curvature, by Newton), each run to convergence, and
 * the spirals' own G2 cubics: one a span, and, where the caller has
 * room (loft_fit_opts.split), a span split into cubics of at most 45
 * degrees' turning each, which follow a spiral that one cubic cannot
 * (a far-out knot's).  The measure they are kept by is the
 * scale-free E L (energy times length), not E: E falls as a curve grows,
 * so its least rewards swelling, where E L is least for the circle
 * (4 pi^2) and does not depend on the units.  This differs from the
 * paper (Manning's normalisation minimises nothing) and from a batten's
 * least E alike; but the spirals' cubics are kept over a curve of less
 * E L where their E is less and their E L not much more
 * (FAIR_SPIRAL_SLACK).  An open curve, as a piece between corners is, is
 * further kept from swelling past the chord spline span by span
 * (unswell).  Every result is judged against the chord spline: no more
 * energy (exactly where the Gauss parts do not resolve a segment's:
 * costlier), no sharper bend (by the exact least radius; in the quick
 * descent where a segment slows), no crossing it has not; else the
 * chord spline is written.  Last, a plane piece beside a straight run
 * has the segments next to the run made again to meet it with
 * curvature 0 (flat_ends), where that passes the same judgement: the
 * family's end tangents are given, and its least energy meets a line
 * G1 only.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Steps at most: L-BFGS takes the insole within 1e-4 of its settled
 * energy in 6; each costs a few O(n) passes, and the bench's 10^4
 * insoles must stay within half GNU spline's time. */
#define FAIR_STEPS 6

/* No step changes a log interval by more than this: a factor e, so a
 * step cannot jump across a fold of the energy into a worse valley. */
#define FAIR_MAXSTEP 1.0

/* Stop once a step lowers E by less than this fraction of it: the
 * steps after gain less than the eye can tell, and cost as much. */
#define FAIR_SETTLED 1e-4

/* Nowhere slower than this fraction of the chord (at the quadrature
 * points), or than the chord spline where it is slower: a cubic that
 * nearly stops bends sharply there, in a spike the quadrature can miss. */
#define FAIR_SLOW 0.25

/* The pairs of steps L-BFGS remembers. */
#define FAIR_MEMORY 4

/* Records of more knots keep the chord-length spline, the descent's
 * start: each step costs about a microsecond a knot, and on knots that
 * dense the chord spline is within rounding of fair wherever they are
 * even; a 10^6-knot outline must fit in under 2 s. */
#define FAIR_MAXKNOTS 100000

/* A step is quartered at most this many times before the descent
 * settles: each try costs a whole spline. */
#define FAIR_HALVINGS 4

/* Armijo's fraction of the first-order decrease a step must achieve. */
#define FAIR_ARMIJO 1e-4

/* 4-point Gauss-Legendre on [0, 1], on each of 1, 2 or FAIR_CHECK equal
 * parts of a segment: within 1e-5 relative of the energy of the
 * segments of a fair curve at 2.  Each segment of the start takes 1
 * part where 1 agrees with 2 to 1e-4 of its energy (4-point Gauss on
 * 2 parts is some 2^8 times closer than on 1, so the difference is the
 * error of 1), else 2 where 2 agree so with FAIR_CHECK, else FAIR_CHECK
 * (a segment that turns sharply in a small part of it); most of an
 * outline's take 1.  The descent's result is checked against the start
 * by the next finer rule of each segment, 2 parts or FAIR_CHECK, the
 * same for both (see loft__fit_fair). */
#define FAIR_CHECK 8
#define GAUSS 4
static const double gauss_u[GAUSS] = {
	0.069431844202973712, 0.33000947820757187, 0.66999052179242813,
	0.93056815579702629 };
static const double gauss_w[GAUSS] = {
	0.17392742256872693, 0.32607257743127307, 0.32607257743127307,
	0.17392742256872693 };

/*
 * The bending energy of segment s (a row P_A P_B P'_A P'_B) and, unless g
 * is NULL, its gradient with respect to P'_A and P'_B into g (2 dim); the
 * largest squared curvature at the quadrature points raises *k2max, the
 * least (|P'| / chord)^2 there lowers *slow.  With V = |P'|^2, W =
 * |P''|^2, U = P'.P'', the integrand k^2 |P'| is (VW - U^2) V^-5/2.
 * HUGE_VAL where the tangent vanishes.  P' = D0 + u (B + u C) and P'' =
 * B + 2 u C in powers of u: fewer products a point than the Hermite
 * basis, and one root and one quotient a point.
 */
/* energy_body is written once for any dim and compiled into
 * segment_energy twice, once with dim = 2; GCC and Clang are told to
 * (others may call it, the same numbers either way). */
#if defined(__GNUC__)
#define FAIR_INLINE inline __attribute__((always_inline))
#else
#define FAIR_INLINE inline
#endif
static FAIR_INLINE double
energy_body(const double *s, int dim, int pieces, double *g, double *k2max,
    double *slow, double *len)
{
	const double *d0 = s + 2 * dim, *d1 = s + 3 * dim;
	double bq[LOFT_MAXDIM], cq[LOFT_MAXDIM], e = 0, cc = 0, vmin = HUGE_VAL;
	double kk = *k2max, step = 1.0 / pieces, ell = 0;
	double *gl = g != NULL ? g + 2 * dim : NULL;

	for (int k = 0; k < dim; k++) {
		double c = s[dim + k] - s[k];

		cc += c * c;
		bq[k] = 6 * c - 4 * d0[k] - 2 * d1[k];
		cq[k] = 3 * (d0[k] + d1[k]) - 6 * c;
	}
	if (g != NULL)
		memset(g, 0, 4 * dim * sizeof *g);
	for (int part = 0; part < pieces; part++)
		for (int j = 0; j < GAUSS; j++) {
			double u = (part + gauss_u[j]) * step, wq = gauss_w[j] * step;
			double p1[LOFT_MAXDIM], p2[LOFT_MAXDIM], v = 0, w = 0, x = 0;
			double num, sv, t, r, k2;

			for (int k = 0; k < dim; k++) {
				p2[k] = bq[k] + 2 * u * cq[k];
				p1[k] = d0[k] + u * (bq[k] + u * cq[k]);
				v += p1[k] * p1[k];
				w += p2[k] * p2[k];
				x += p1[k] * p2[k];
			}
			if (!(v > 0))
				return HUGE_VAL;
			num = v * w - x * x;
			if (num < 0)
				num = 0;
			sv = sqrt(v);
			t = 1 / (v * sv);               /* V^-3/2 */
			r = t * t * sv;                 /* V^-5/2 */
			k2 = num * t * t;
			e += wq * num * r;
			ell += wq * sv;
			if (k2 > kk)
				kk = k2;
			if (v < vmin)
				vmin = v;
			if (g == NULL)
				continue;
			{
				double a0 = 1 - 4 * u + 3 * u * u, a1 = -2 * u +
				    3 * u * u, b0 = -4 + 6 * u, b1 = -2 + 6 * u;
				double c5 = 5 * num * r * t * sv;       /* 5 num V^-7/2 */

				for (int k = 0; k < dim; k++) {
					double f1 = 2 * (w * p1[k] - x * p2[k]) * r -
					    c5 * p1[k];
					double f2 = 2 * (v * p2[k] - x * p1[k]) * r;

					g[k] += wq * (f1 * a0 + f2 * b0);
					g[dim + k] += wq * (f1 * a1 + f2 * b1);
					gl[k] += wq * p1[k] / sv * a0;
					gl[dim + k] += wq * p1[k] / sv * a1;
				}
			}
		}
	*k2max = kk;
	if (slow != NULL && vmin / cc < *slow)
		*slow = vmin / cc;
	*len += ell;
	return e;
}

/* energy_body, compiled apart for the plane, where the loops over the
 * coordinates unroll: most records are plane outlines. */
static double
segment_energy(const double *s, int dim, int pieces, double *g, double *k2max,
    double *slow, double *len)
{
	return dim == 2 ? energy_body(s, 2, pieces, g, k2max, slow, len) :
	    energy_body(s, dim, pieces, g, k2max, slow, len);
}

/* Whether every tangent vector of the segments is within LOFT__MAXMAG
 * chords. */
static int
tame(const double *seg, size_t nseg, int dim)
{
	for (size_t s = 0; s < nseg; s++) {
		const double *q = seg + s * 4 * dim;
		double w = LOFT__MAXMAG * vdist(q + dim, q, dim);

		if (!(vnorm(q + 2 * dim, dim) <= w && vnorm(q + 3 * dim, dim) <= w))
			return 0;
	}
	return 1;
}

/*
 * The largest curvature of the segments at FAIR_KSAMPLES + 1 even
 * points of each, ends included: the cap of the descent (which checks
 * it at the quadrature points) and the final check of its result.
 * Squares are compared, one root at the end.
 */
#define FAIR_KSAMPLES 8
static FAIR_INLINE double
curvature_body(const double *seg, size_t nseg, int dim)
{
	double big = 0;

	for (size_t s = 0; s < nseg; s++) {
		const double *q = seg + s * 4 * dim, *d0 = q + 2 * dim;
		double bq[LOFT_MAXDIM], cq[LOFT_MAXDIM];

		for (int k = 0; k < dim; k++) {
			double c = q[dim + k] - q[k];

			bq[k] = 6 * c - 4 * d0[k] - 2 * q[3 * dim + k];
			cq[k] = 3 * (d0[k] + q[3 * dim + k]) - 6 * c;
		}
		for (int j = 0; j <= FAIR_KSAMPLES; j++) {
			double u = (double)j / FAIR_KSAMPLES, v = 0, w = 0, x = 0;
			double num, k2;

			for (int k = 0; k < dim; k++) {
				double p1 = d0[k] + u * (bq[k] + u * cq[k]);
				double p2 = bq[k] + 2 * u * cq[k];

				v += p1 * p1;
				w += p2 * p2;
				x += p1 * p2;
			}
			if (!(v > 0))
				return HUGE_VAL;
			num = v * w - x * x;
			k2 = num / (v * v * v);
			if (k2 > big)
				big = k2;
		}
	}
	return sqrt(big);
}

/* curvature_body, compiled apart for the plane as energy_body is. */
static double
max_curvature(const double *seg, size_t nseg, int dim)
{
	return dim == 2 ? curvature_body(seg, nseg, 2) :
	    curvature_body(seg, nseg, dim);
}

/* The energy of all nseg segments, each in parts[s] parts, or pieces
 * where parts is NULL; their length into *len.  Unless g is NULL, each
 * segment's gradients of its energy and of its length with respect to
 * its P'_A and P'_B into g, 4 dim numbers a segment.  *kmax: the largest
 * curvature at the quadrature points; *slow as segment_energy's. */
static double
curve_energy(const double *seg, size_t nseg, int dim, int pieces,
    const unsigned char *parts, double *g, double *kmax, double *slow,
    double *len)
{
	double e = 0, k2 = 0;

	if (slow != NULL)
		*slow = HUGE_VAL;
	*len = 0;
	for (size_t s = 0; s < nseg; s++)
		e += segment_energy(seg + s * 4 * dim, dim, parts ? parts[s] :
		    pieces, g ? g + s * 4 * dim : NULL, &k2, slow, len);
	*kmax = sqrt(k2);
	return e;
}

/*
 * The parts of each segment of a start into parts, and those of the
 * final check into check (see FAIR_CHECK).  Returns the start's energy
 * by the check's parts, its length by them into *flen; its energy and
 * length by the parts chosen into *e and *len, the largest curvature
 * and least speed by them into *kmax and *slow (as curve_energy).
 */
static double
choose_parts(const double *seg, size_t nseg, int dim, unsigned char *parts,
    unsigned char *check, double *e, double *len, double *flen, double *kmax,
    double *slow)
{
	double fine = 0, kk = 0;

	*e = *len = *flen = 0;
	*slow = HUGE_VAL;
	for (size_t s = 0; s < nseg; s++) {
		const double *q = seg + s * 4 * dim;
		double k1 = 0, k2 = 0, k8 = 0, s1 = HUGE_VAL, s2 = HUGE_VAL;
		double s8 = HUGE_VAL, l1 = 0, l2 = 0, l8 = 0;
		double a1 = segment_energy(q, dim, 1, NULL, &k1, &s1, &l1);
		double a2 = segment_energy(q, dim, 2, NULL, &k2, &s2, &l2), b = a2;
		double lb = l2;

		parts[s] = 1;
		check[s] = 2;
		if (!(fabs(a1 - a2) <= 1e-4 * a2)) {
			b = segment_energy(q, dim, FAIR_CHECK, NULL, &k8, &s8, &l8);
			lb = l8;
			check[s] = FAIR_CHECK;
			parts[s] = fabs(a2 - b) <= 1e-4 * b ? 2 : FAIR_CHECK;
		}
		*e += parts[s] == 1 ? a1 : parts[s] == 2 ? a2 : b;
		*len += parts[s] == 1 ? l1 : parts[s] == 2 ? l2 : l8;
		kk = fmax(kk, parts[s] == 1 ? k1 : parts[s] == 2 ? k2 : k8);
		*slow = fmin(*slow, parts[s] == 1 ? s1 : parts[s] == 2 ? s2 : s8);
		fine += b;
		*flen += lb;
	}
	*kmax = sqrt(kk);
	return fine;
}

struct fair {
	const struct loft_fit_opts *o;
	const double *p;
	size_t n, nseg;
	int dim;
	double *seg, *work, *gseg;
	double *gboth;          /* dE and dL of each segment (curve_energy) */
	double kcap;
	double slow;            /* the least (|P'| / chord)^2 allowed */
	unsigned char *parts;   /* the quadrature's parts of each segment */
	unsigned char *check;   /* and the final check's */
	int scalefree;          /* descend E L (thorough), else E */
	double base;            /* the last try's E L / e0 */
	double e0;              /* the start's E L: E L / e0 is descended,
	                         * so steps do not depend on the units */
	int steps;              /* steps at most */
	double settled;         /* stop when a step gains less (relative) */
};

/* Of two curves of nearly equal E L, the one nearer continuous second
 * derivatives (y = 0): E L is nearly flat along some y (an open curve's
 * end magnitudes), and a descent stopped anywhere along such a valley
 * would give a curve that moved with the rounding of the knots. */
#define FAIR_PREFER_C2 1e-2

/* The sum of the squares of the k numbers y. */
static double
sumsq(const double *y, size_t k)
{
	double s = 0;

	for (size_t i = 0; i < k; i++)
		s += y[i] * y[i];
	return s;
}

/* The least (|P'| / chord)^2 of segment q (a row P_A P_B P'_A P'_B),
 * where the quadrature's points may straddle a near-cusp that a long
 * descent would slip into: |P'|^2 is a quartic in u, sampled at
 * FAIR_KSAMPLES + 1 points and its least sample refined by Newton on
 * P'.P'' = 0 (the third derivative 2 C is constant). */
static double
segment_least_speed(const double *q, int dim)
{
	double bq[LOFT_MAXDIM], cq[LOFT_MAXDIM], cc = 0, best = HUGE_VAL, ub = 0;
	const double *d0 = q + 2 * dim;

	for (int k = 0; k < dim; k++) {
		double c = q[dim + k] - q[k];

		cc += c * c;
		bq[k] = 6 * c - 4 * d0[k] - 2 * q[3 * dim + k];
		cq[k] = 3 * (d0[k] + q[3 * dim + k]) - 6 * c;
	}
	for (int j = 0; j <= FAIR_KSAMPLES; j++) {
		double u = (double)j / FAIR_KSAMPLES, v = 0;

		for (int k = 0; k < dim; k++) {
			double p1 = d0[k] + u * (bq[k] + u * cq[k]);

			v += p1 * p1;
		}
		if (v < best)
			best = v, ub = u;
	}
	for (int it = 0; it < 4; it++) {
		double g = 0, dg = 0, v = 0;

		for (int k = 0; k < dim; k++) {
			double p1 = d0[k] + ub * (bq[k] + ub * cq[k]);
			double p2 = bq[k] + 2 * ub * cq[k];

			g += p1 * p2;
			dg += p2 * p2 + 2 * p1 * cq[k];
		}
		if (!(dg > 0))
			break;
		ub = fmax(0, fmin(1, ub - g / dg));
		for (int k = 0; k < dim; k++) {
			double p1 = d0[k] + ub * (bq[k] + ub * cq[k]);

			v += p1 * p1;
		}
		best = fmin(best, v);
	}
	return cc > 0 ? best / cc : 0;
}

/* The spline of intervals h = exp(x) and diagonal factors y = x + nseg
 * into f->seg, its scale-free energy E L / e0 (HUGE_VAL where a
 * curvature passes the cap), and d(E L)/dP' into f->gseg in the same
 * pass: most tries are kept, and the gradient then needs only the
 * adjoint. */
static double
try_intervals(struct fair *f, const double *x, double *h)
{
	double e, kmax, slow, len;
	struct loft_error err;
	int dim = f->dim;

	for (size_t s = 0; s < f->nseg; s++)
		h[s] = exp(x[s]);
	if (loft__cspline_h(f->o, f->p, f->n, dim, h, x + f->nseg, f->seg,
	    f->work, &err) != 0)
		return HUGE_VAL;
	if (!tame(f->seg, f->nseg, dim))
		return HUGE_VAL;
	e = curve_energy(f->seg, f->nseg, dim, 0, f->parts, f->gboth, &kmax,
	    &slow, &len);
	if (!(kmax <= f->kcap) || !(slow >= f->slow))
		return HUGE_VAL;
	for (size_t s = 0; f->scalefree && s < f->nseg; s++)
		if (!(segment_least_speed(f->seg + s * 4 * dim, dim) >= f->slow))
			return HUGE_VAL;
	if (!f->scalefree) {    /* E alone: its gradient as it is */
		for (size_t s = 0; s < f->nseg; s++)
			memcpy(f->gseg + s * 2 * dim, f->gboth + s * 4 * dim,
			    2 * dim * sizeof *f->gseg);
		e /= f->e0;
		return isfinite(e) ? e : HUGE_VAL;
	}
	/* d(E L) = L dE + E dL, segment by segment */
	for (size_t s = 0; s < f->nseg; s++)
		for (int k = 0; k < 2 * dim; k++)
			f->gseg[s * 2 * dim + k] = len * f->gboth[s * 4 * dim + k] +
			    e * f->gboth[s * 4 * dim + 2 * dim + k];
	e *= len / f->e0;
	f->base = e;
	e *= 1 + FAIR_PREFER_C2 * sumsq(x + f->nseg, f->n) / f->n;
	return isfinite(e) ? e : HUGE_VAL;
}

/* dE/dx at the x last tried (h = exp(x)), into g, from the f->gseg of
 * the try. */
static void
gradient(struct fair *f, const double *x, const double *h, double *g)
{
	loft__cspline_adjoint(f->o, f->p, f->n, f->dim, h, x + f->nseg,
	    f->gseg, g, g + f->nseg, f->work);
	for (size_t s = 0; s < f->nseg; s++)
		g[s] *= h[s] / f->e0;
	if (!f->scalefree) {
		for (size_t i = 0; i < f->n; i++)
			g[f->nseg + i] /= f->e0;
		return;
	}
	for (size_t i = 0; i < f->n; i++) {
		const double *y = x + f->nseg;

		g[f->nseg + i] = g[f->nseg + i] / f->e0 * (1 + FAIR_PREFER_C2 *
		    sumsq(y, f->n) / f->n) + f->base * 2 * FAIR_PREFER_C2 *
		    y[i] / f->n;
	}
	for (size_t s = 0; s < f->nseg; s++)
		g[s] *= 1 + FAIR_PREFER_C2 * sumsq(x + f->nseg, f->n) / f->n;
}

/*
 * The L-BFGS direction -H g into d from the last k of FAIR_MEMORY pairs
 * (s, y) of steps and gradient changes, stored round from slot k0.
 */
static void
direction(size_t m, const double *g, double *d, double *const *sv,
    double *const *yv, const double *rho, int k, int k0)
{
	double al[FAIR_MEMORY] = { 0 }, gamma = 1;     /* al[0..k) is set */

	memcpy(d, g, m * sizeof *d);
	for (int j = k - 1; j >= 0; j--) {
		int q = (k0 + j) % FAIR_MEMORY;
		double a = 0;

		for (size_t i = 0; i < m; i++)
			a += sv[q][i] * d[i];
		al[j] = a *= rho[q];
		for (size_t i = 0; i < m; i++)
			d[i] -= a * yv[q][i];
	}
	if (k > 0) {
		int q = (k0 + k - 1) % FAIR_MEMORY;
		double yy = 0;

		for (size_t i = 0; i < m; i++)
			yy += yv[q][i] * yv[q][i];
		gamma = 1 / (rho[q] * yy);
	}
	for (size_t i = 0; i < m; i++)
		d[i] *= gamma;
	for (int j = 0; j < k; j++) {
		int q = (k0 + j) % FAIR_MEMORY;
		double b = 0;

		for (size_t i = 0; i < m; i++)
			b += yv[q][i] * d[i];
		b *= rho[q];
		for (size_t i = 0; i < m; i++)
			d[i] += (al[j] - b) * sv[q][i];
	}
	for (size_t i = 0; i < m; i++)
		d[i] = -d[i];
}

/* The memory of L-BFGS: FAIR_MEMORY pairs (s, y) of steps and gradient
 * changes, k of them stored round from slot k0. */
struct memory {
	double *sv[FAIR_MEMORY], *yv[FAIR_MEMORY], rho[FAIR_MEMORY];
	int k, k0;
};

/* Remember the step from xp to x, whose gradient g is replaced by the
 * one at x: the pair (x - xp, g(x) - g(xp)), or forget all where it
 * shows no curvature. */
static void
remember(struct fair *f, struct memory *mm, const double *xp, const double *x,
    const double *h, double *g)
{
	size_t m = f->nseg + f->n;
	int q = mm->k < FAIR_MEMORY ? (mm->k0 + mm->k) % FAIR_MEMORY : mm->k0;
	double sy = 0;

	if (mm->k == FAIR_MEMORY)
		mm->k0 = (mm->k0 + 1) % FAIR_MEMORY;
	else
		mm->k++;
	for (size_t i = 0; i < m; i++) {
		mm->sv[q][i] = x[i] - xp[i];
		mm->yv[q][i] = -g[i];
	}
	gradient(f, x, h, g);
	for (size_t i = 0; i < m; i++) {
		mm->yv[q][i] += g[i];
		sy += mm->yv[q][i] * mm->sv[q][i];
	}
	if (sy > 0) {
		mm->rho[q] = 1 / sy;
	} else {
		mm->k = 0;
		mm->k0 = 0;
	}
}

/* Along d from xp (objective e, slope gd < 0) to x, a step no longer
 * than FAIR_MAXSTEP in any coordinate, quartered until Armijo's rule
 * holds; returns the new objective, or HUGE_VAL with x = xp. */
static double
line_search(struct fair *f, const double *xp, const double *d, double big,
    double e, double gd, double *x, double *h)
{
	size_t m = f->nseg + f->n;
	double t = fmin(1, FAIR_MAXSTEP / big);

	for (int half = 0; half < FAIR_HALVINGS; half++, t *= 0.25) {
		double en;

		for (size_t i = 0; i < m; i++)
			x[i] = xp[i] + t * d[i];
		en = try_intervals(f, x, h);
		if (en <= e + FAIR_ARMIJO * t * gd)
			return en;
	}
	memcpy(x, xp, m * sizeof *x);
	return HUGE_VAL;
}

/* The descent; returns the steps taken and the objective reached into
 * *e (HUGE_VAL where the start passes a cap).  x: log h and y, the best
 * on return, whose spline f->seg holds.  v: room for 2 FAIR_MEMORY + 3
 * vectors of nseg + n. */
static int
descend(struct fair *f, double *x, double *h, double *v, double *e)
{
	size_t m = f->nseg + f->n;
	double *g = v, *d = g + m, *xp = d + m;
	struct memory mm;
	int it, stale = 0;

	mm.k = mm.k0 = 0;
	for (int j = 0; j < FAIR_MEMORY; j++) {
		mm.sv[j] = xp + m + 2 * j * m;
		mm.yv[j] = mm.sv[j] + m;
	}
	if (!((*e = try_intervals(f, x, h)) < HUGE_VAL))
		return 0;
	gradient(f, x, h, g);
	for (it = 0; it < f->steps; it++) {
		double gd = 0, big = 0, en;

		direction(m, g, d, mm.sv, mm.yv, mm.rho, mm.k, mm.k0);
		for (size_t i = 0; i < m; i++) {
			gd += g[i] * d[i];
			big = fmax(big, fabs(d[i]));
		}
		if (!(gd < 0) || !isfinite(gd)) {       /* start afresh */
			if (mm.k == 0)
				break;
			mm.k = 0;
			it--;
			continue;
		}
		memcpy(xp, x, m * sizeof *x);
		if (!((en = line_search(f, xp, d, big, *e, gd, x, h)) < HUGE_VAL)) {
			stale = 1;
			break;
		}
		if (*e - en < f->settled * *e || it + 1 == f->steps) {
			*e = en;
			it++;
			break;
		}
		remember(f, &mm, xp, x, h, g);
		*e = en;
	}
	/* the spline of the best x, in f->seg (already, unless the last
	 * try failed) */
	if (stale)
		try_intervals(f, x, h);
	return it;
}

/* Points a segment of the polyline the crossing test follows. */
#define FAIR_POLY 6

/*
 * Whether the closed polyline of the np points pt is shown simple by
 * being star-shaped: seen from the mean of its points every edge turns
 * the same way, by less than half a turn, and the edges cross the ray
 * to the right of that centre once, so the polyline goes round it once
 * with its angle always rising: each ray from the centre meets it once.
 * 0 when not shown (it may still be simple): the grid decides then.  An
 * outline's is nearly always shown, in one pass.
 */
static int
star_simple(const double *pt, size_t np)
{
	double c[2] = { 0, 0 };
	size_t up = 0, down = 0;
	int turn = 0;

	for (size_t i = 0; i < np; i++) {
		c[0] += pt[2 * i];
		c[1] += pt[2 * i + 1];
	}
	c[0] /= np;
	c[1] /= np;
	for (size_t i = 0; i < np; i++) {
		const double *a = pt + 2 * i, *b = pt + 2 * (i + 1 == np ? 0 : i + 1);
		double ax = a[0] - c[0], ay = a[1] - c[1], bx = b[0] - c[0];
		double by = b[1] - c[1], cr = ax * by - ay * bx;
		int t = cr > 0 ? 1 : cr < 0 ? -1 : 0;

		if (t == 0 || (turn != 0 && t != turn))
			return 0;
		turn = t;
		up += ay < 0 && by >= 0;
		down += ay >= 0 && by < 0;
	}
	/* rising (falling) angles cross y = c upwards (downwards) only to
	 * the right of c: once for one turn */
	return turn > 0 ? up == 1 : down == 1;
}

/* The polyline the crossing test follows, and the edge being tested. */
struct poly {
	const double *pt;
	size_t np, ne, e;
	double sg[4];           /* edge e */
	int closed;
};

/* Edge e of p as a segment x0 y0 x1 y1. */
static void
poly_edge(const struct poly *p, size_t e, double *sg)
{
	const double *a = p->pt + 2 * e;
	const double *b = p->pt + 2 * (e + 1 == p->np ? 0 : e + 1);

	sg[0] = a[0];
	sg[1] = a[1];
	sg[2] = b[0];
	sg[3] = b[1];
}

/* Make edge e of p the one tested, and its box lo..hi. */
static void
poly_take(struct poly *p, size_t e, double *lo, double *hi)
{
	p->e = e;
	poly_edge(p, e, p->sg);
	for (int k = 0; k < 2; k++) {
		lo[k] = fmin(p->sg[k], p->sg[2 + k]);
		hi[k] = fmax(p->sg[k], p->sg[2 + k]);
	}
}

/* loft_grid_each's visit: whether edge id, after p->e and not its
 * neighbour, crosses it. */
static int
edge_meets(void *ctx, size_t id)
{
	const struct poly *p = ctx;
	double t[4];

	if (id <= p->e + 1 || (p->closed && p->e == 0 && id == p->ne - 1))
		return 0;
	poly_edge(p, id, t);
	return loft_segments_cross(p->sg, t);
}

/* Where the curve turns back at a joint (its tangents, or the
 * polyline's edges, either side point against each other), the
 * FAIR_FOLD_EDGES edges either side are sampled again, finer and
 * finer still towards the joint (loft_sides_cross), and tested against
 * each other: the test of the whole polyline skips the two edges at the
 * joint as neighbours, and a side that leaves it nearly reversed can
 * cross the other within them.  (A corner after a straight span, its
 * next side leaving at 179.7 degrees, crossed the straight one 0.0025
 * of a segment from the joint.) */
#define FAIR_FOLD_EDGES 4

/* loft_sides_cross's eval: the point of segment s of the rows ctx. */
static void
segment_point(const void *ctx, size_t s, double u, double *p)
{
	loft_cubic_eval((const double *)ctx + 8 * s, 2, u, p, NULL, NULL);
}

/* Whether the nseg segments seg cross at a fold (above); pt: the np
 * points of their polyline. */
static int
folds_cross(const double *seg, size_t nseg, int closed, const double *pt,
    size_t np)
{
	double in[2], out[2];

	for (size_t j = !closed; j < nseg; j++) {
		size_t pj = (j + nseg - 1) % nseg, k = j * FAIR_POLY;

		vsub(in, pt + 2 * k, pt + 2 * ((k + np - 1) % np), 2);
		vsub(out, pt + 2 * k + 2, pt + 2 * k, 2);
		if ((vdot(in, out, 2) < 0 ||
		    vdot(seg + 8 * pj + 6, seg + 8 * j + 4, 2) < 0) &&
		    loft_sides_cross(segment_point, seg, pj, j,
		    (double)FAIR_FOLD_EDGES / FAIR_POLY))
			return 1;
	}
	return 0;
}

/* Edges filed by their boxes in a grid (grid.c) of about one cell an
 * edge, each tested against those after it in its cells: O(n) for a
 * curve of even speed.  Two edges that cross share the cell of the
 * crossing, so none is missed; nor is a crossing at a fold
 * (folds_cross). */
int
loft_fit_crosses(const double *seg, size_t nseg, int closed)
{
	size_t np = nseg * FAIR_POLY + !closed, ne = closed ? np : np - 1;
	size_t g = (size_t)sqrt((double)ne) + 1;
	double *pt = calloc(2 * np, sizeof *pt), lo[2], hi[2], w;
	struct loft_grid grid;
	struct poly p;
	int found = 0;

	if (nseg == 0) {        /* no segment crosses */
		free(pt);
		return 0;
	}
	if (pt == NULL)
		return -1;
	for (size_t i = 0; i < np; i++) {
		size_t s = i / FAIR_POLY < nseg ? i / FAIR_POLY : nseg - 1;

		loft_cubic_eval(seg + 8 * s, 2, (double)(i - s * FAIR_POLY) /
		    FAIR_POLY, pt + 2 * i, NULL, NULL);
	}
	found = folds_cross(seg, nseg, closed, pt, np);
	if (found || (closed && star_simple(pt, np))) {
		free(pt);
		return found;
	}
	lo[0] = hi[0] = pt[0];
	lo[1] = hi[1] = pt[1];
	for (size_t i = 1; i < np; i++)
		for (int k = 0; k < 2; k++) {
			double z = pt[2 * i + k];

			lo[k] = z < lo[k] ? z : lo[k];
			hi[k] = z > hi[k] ? z : hi[k];
		}
	w = fmax(hi[0] - lo[0], hi[1] - lo[1]) / g * (1 + 1e-9);
	if (!(w > 0) || loft_grid_init(&grid, w, w, lo, ne) != 0) {
		free(pt);
		return w > 0 ? -1 : 0;  /* 0: all at one point */
	}
	p = (struct poly){ .pt = pt, .np = np, .ne = ne, .closed = closed };
	for (size_t e = 0; e < ne && found == 0; e++) {
		poly_take(&p, e, lo, hi);
		if (loft_grid_add(&grid, lo, hi, e) != 0)
			found = -1;
	}
	for (size_t e = 0; e < ne && found == 0; e++) {
		poly_take(&p, e, lo, hi);
		found = loft_grid_each(&grid, lo, hi, edge_meets, &p);
	}
	loft_grid_free(&grid);
	free(pt);
	return found;
}

/* Closed records of at most this many knots have every start run to
 * convergence: sparse knots are where the chord spline's start lies
 * farthest from the fairest curve, and a handful of knots costs
 * microseconds a step.  (Not open ones: E L is nearly flat along their
 * end magnitudes, and where a long descent stops along that valley
 * moves with the rounding of the knots.) */
#define FAIR_FEW 16

/* Records of more have it too where the quick descent from the chord
 * spline leaves a bend of radius under this fraction of the mean chord:
 * a knot that sticks out, which the chord spline nearly cusps; up to
 * FAIR_THOROUGH knots, for the thorough search costs some 100 quick
 * descents (4 starts, 24 steps, 8 times the quadrature). */
#define FAIR_SHARP 0.125
#define FAIR_THOROUGH 2000

/* A thorough descent's steps at most, and the relative gain of a step
 * below which it stops: enough to take co-circular knots to within a
 * few times the error of the best cubic arc over the widest gap, and
 * few enough that a descent's path, and so its end, moves with the
 * knots' rounding by no more than 1e-9 of their size (a longer one
 * wanders along the nearly flat valleys of E L: bad.sh's units). */
#define FAIR_CONVERGE 24
#define FAIR_SETTLED_FINE 1e-6

/* The starts of a thorough search, in order (see start_intervals). */
enum { START_CHORD, START_CENTRIPETAL, START_ARC, START_MANNING, START_SPIRAL,
    STARTS };

/* The unit chord of segment s into u; returns its length. */
static double
unit_chord(const struct fair *f, size_t s, double *u)
{
	size_t t = f->n > 0 ? (s + 1) % f->n : s;      /* n > 0: a record */

	vsub(u, f->p + t * f->dim, f->p + s * f->dim, f->dim);
	return vunit(u, f->dim);
}

/*
 * A direction estimate of our own at knot i, in Hobby's manner (each
 * tangent from the knot's two chords alone, no system): the chords'
 * unit vectors weighted each by the other's length, which is the
 * tangent of the circle through three knots where they are even.  The
 * ends of an open curve take their chord.
 */
static void
estimate_tangent(const struct fair *f, size_t i, double *t)
{
	double u0[LOFT_MAXDIM], u1[LOFT_MAXDIM], w0, w1;

	if (!f->o->closed && (i == 0 || i + 1 == f->n)) {
		unit_chord(f, i == 0 ? 0 : i - 1, t);
		return;
	}
	w0 = unit_chord(f, (i + f->n - 1) % f->n, u0);
	w1 = unit_chord(f, i, u1);
	vscale(t, w1, u0, f->dim);
	vaxpy(t, w0, u1, f->dim);
	if (!(vunit(t, f->dim) > 0))
		vcopy(t, u1, f->dim);
}

/* ---- a direction estimate in Spiro's manner ------------------------- */

/* Records of at most this many knots get the start below: its Newton
 * step solves a dense system, n^3, which at 64 knots costs about what a
 * thorough descent does. */
#define SPIRAL_MAXKNOTS LOFT_FIT_SPLIT_KNOTS

/* Newton's iterations at most, and the residual that ends them: the
 * curvature jump over the knots' mean curvature 1 / chord, and the
 * chord equation of a spiral, both to near rounding. */
#define SPIRAL_ITER 40
#define SPIRAL_TOL 1e-11

/* No end angle of a spiral beyond this from its chord: past it the
 * spiral curls, and no cubic of tame tangents follows it. */
#define SPIRAL_MAXANGLE 6.0

/*
 * The Euler spiral (curvature linear in arc length) that leaves its
 * chord at angle psi0 and meets it at psi1 (radians, from the chord,
 * anticlockwise): its end curvatures times its length into k[0], k[1],
 * its length over its chord into *len.  Along it, the angle from the
 * chord is psi0 + (psi1 - psi0) t + d/2 (t^2 - t), t the arc length
 * over the length, and d, its change of curvature times the length, is
 * the root of the chord's condition: the integral of the sine of that
 * angle is 0.  Newton from d = 6 (psi0 + psi1), the small-angle root.
 * 0, or -1 where it does not converge.
 */
static int
spiral(double psi0, double psi1, double *k, double *len)
{
	double d = 6 * (psi0 + psi1), turn = psi1 - psi0;

	if (!(fabs(psi0) < SPIRAL_MAXANGLE && fabs(psi1) < SPIRAL_MAXANGLE))
		return -1;
	for (int it = 0; it < SPIRAL_ITER; it++) {
		double g = 0, dg = 0, c = 0;

		for (int part = 0; part < 4; part++)
			for (int j = 0; j < GAUSS; j++) {
				double t = (part + gauss_u[j]) / 4, w = gauss_w[j] / 4;
				double a = psi0 + turn * t + d / 2 * (t * t - t);

				g += w * sin(a);
				c += w * cos(a);
				dg += w * cos(a) * (t * t - t) / 2;
			}
		if (fabs(g) < SPIRAL_TOL) {
			k[0] = turn - d / 2;
			k[1] = turn + d / 2;
			*len = 1 / c;
			return c > 0 ? 0 : -1;
		}
		if (!(dg < 0))
			return -1;
		d -= fmax(-2, fmin(2, g / dg));
	}
	return -1;
}

/* The state of the angle solve: knot i's tangent angle is ref[i] +
 * x[i]; segment s leaves knot s at psi0[s] from its chord, of angle
 * phi[s] and length c[s], and meets knot s + 1 at psi1[s]. */
struct angles {
	size_t n, nseg;
	int closed;
	int end[2];             /* an open curve's ends: 1 where the tangent
	                         * is given (ref), 0 where free (an arc) */
	double *ref, *phi, *c, *x, *k0, *k1, *len, *r, *jac, *dx, *xn;
	double scale;           /* the mean chord */
};

/* a - b wrapped into (-pi, pi]. */
static double
angle_diff(double a, double b)
{
	double d = a - b;

	return atan2(sin(d), cos(d));
}

/* The spirals of x and the curvature jumps at the knots, times the mean
 * chord, into a->r; the largest jump, or HUGE_VAL where a spiral fails.
 * An open curve's end knot has instead its tangent's turn from the one
 * given, or where none is, its span's change of curvature along it
 * times its length (Spiro's manner: the span beside a free end is a
 * circular arc). */
static double
residuals(struct angles *a, const double *x)
{
	size_t n = a->n;
	double big = 0, k[2], len;

	for (size_t s = 0; s < a->nseg; s++) {
		size_t t = s + 1 < n ? s + 1 : 0;       /* nseg <= n */
		double p0 = angle_diff(a->ref[s], a->phi[s]) + x[s];
		double p1 = angle_diff(a->ref[t], a->phi[s]) + x[t];

		if (spiral(p0, p1, k, &len) != 0)
			return HUGE_VAL;
		a->len[s] = len * a->c[s];
		a->k0[s] = k[0] / a->len[s];
		a->k1[s] = k[1] / a->len[s];
	}
	for (size_t i = 0; i < n; i++) {
		size_t e = i == 0 ? 0 : n - 1, s = i == 0 ? 0 : n - 2;

		if (a->closed || (i > 0 && i + 1 < n))
			a->r[i] = (a->k1[(i + n - 1) % n] - a->k0[i]) * a->scale;
		else if (a->end[i > 0])
			a->r[i] = x[e];
		else
			a->r[i] = (a->k1[s] - a->k0[s]) * a->len[s];
		big = fmax(big, fabs(a->r[i]));
	}
	return big;
}

/* Gaussian elimination with partial pivoting of the n x n system m z =
 * r (m row-major, spoiled; r becomes z); 0, or -1 when singular. */
static int
dense_solve(double *m, double *r, size_t n)
{
	for (size_t c = 0; c < n; c++) {
		size_t p = c;

		for (size_t i = c + 1; i < n; i++)
			if (fabs(m[i * n + c]) > fabs(m[p * n + c]))
				p = i;
		if (!(fabs(m[p * n + c]) > 1e-300))
			return -1;
		for (size_t j = 0; j < n; j++) {
			double t = m[c * n + j];

			m[c * n + j] = m[p * n + j];
			m[p * n + j] = t;
		}
		{
			double t = r[c];

			r[c] = r[p];
			r[p] = t;
		}
		for (size_t i = c + 1; i < n; i++) {
			double q = m[i * n + c] / m[c * n + c];

			for (size_t j = c; j < n; j++)
				m[i * n + j] -= q * m[c * n + j];
			r[i] -= q * r[c];
		}
	}
	for (size_t i = n; i-- > 0;) {
		for (size_t j = i + 1; j < n; j++)
			r[i] -= m[i * n + j] * r[j];
		r[i] /= m[i * n + i];
	}
	return 0;
}

/* A Newton step of the knots' angles: the Jacobian by differences of
 * 1e-7 radian, the step capped at 0.3 radian and halved until the
 * largest jump falls.  Returns the new largest jump, HUGE_VAL where
 * none falls. */
static double
newton_step(struct angles *a, double big)
{
	size_t n = a->n;
	double step = 1e-7, most = 0, t = 1;

	for (size_t j = 0; j < n; j++) {
		memcpy(a->xn, a->x, n * sizeof *a->xn);
		a->xn[j] += step;
		if (!(residuals(a, a->xn) < HUGE_VAL))
			return HUGE_VAL;
		for (size_t i = 0; i < n; i++)
			a->jac[i * n + j] = a->r[i];
	}
	residuals(a, a->x);
	for (size_t i = 0; i < n; i++) {
		for (size_t j = 0; j < n; j++)
			a->jac[i * n + j] = (a->jac[i * n + j] - a->r[i]) / step;
		a->dx[i] = -a->r[i];
	}
	if (dense_solve(a->jac, a->dx, n) != 0)
		return HUGE_VAL;
	for (size_t i = 0; i < n; i++)
		most = fmax(most, fabs(a->dx[i]));
	if (most > 0.3)
		t = 0.3 / most;
	for (int half = 0; half < 12; half++, t /= 2) {
		double e;

		for (size_t i = 0; i < n; i++)
			a->xn[i] = a->x[i] + t * a->dx[i];
		if ((e = residuals(a, a->xn)) < big) {
			memcpy(a->x, a->xn, n * sizeof *a->x);
			return e;
		}
	}
	return HUGE_VAL;
}

/* The samples of the scan for g2_magnitudes' roots, over tangent
 * magnitudes from 0 to LOFT__MAXMAG chords: fine enough to part the
 * roots of the quartic a cubic's two ends make. */
#define SPIRAL_SCAN 256

/* g2_magnitudes' second condition at a, b its first's: b into *b. */
static double
g2_rest(double a, double c, double psi0, double psi1, double k0, double k1,
    double s01, double *b)
{
	*b = -(k0 * a * a + 6 * c * sin(psi0)) / (2 * s01);
	return k1 * *b * *b - 6 * c * sin(psi1) + 2 * a * s01;
}

/*
 * The tangent magnitudes a, b of the cubic from 0 to the chord (c, 0)
 * that leaves at angle psi0 with curvature k0 and arrives at psi1 with
 * k1 (de Boor, Hollig and Sabin's G2 Hermite conditions): with the
 * second derivative 6 C - 4 a T0 - 2 b T1 at the start and -6 C + 2 a
 * T0 + 4 b T1 at the end, k0 a^2 + 6 c sin psi0 + 2 b sin(psi1 - psi0)
 * = 0 and k1 b^2 - 6 c sin psi1 + 2 a sin(psi1 - psi0) = 0.  The first
 * gives b of a; the roots of the second in a are scanned for and
 * bisected, and of those with both magnitudes positive and tame, the
 * one nearest a = b = len (the spiral's length) is taken.  0, or -1
 * where there is none.
 */
static int
g2_magnitudes(double c, double psi0, double psi1, double k0, double k1,
    double len, double *a, double *b)
{
	double s01 = sin(psi1 - psi0), top = LOFT__MAXMAG * c, best = HUGE_VAL;
	double a0 = 0, b0, g0;

	if (!(fabs(s01) > 1e-6))
		return -1;
	g0 = g2_rest(a0, c, psi0, psi1, k0, k1, s01, &b0);
	for (int j = 1; j <= SPIRAL_SCAN; j++) {
		double a1 = top * j / SPIRAL_SCAN, b1, g1, lo = a0, hi = a1, gl = g0;

		g1 = g2_rest(a1, c, psi0, psi1, k0, k1, s01, &b1);
		if ((g0 < 0) != (g1 < 0)) {
			for (int it = 0; it < 60; it++) {
				double mid = (lo + hi) / 2, bm, gm;

				gm = g2_rest(mid, c, psi0, psi1, k0, k1, s01, &bm);
				if ((gm < 0) == (gl < 0))
					lo = mid, gl = gm;
				else
					hi = mid;
			}
			g2_rest(lo, c, psi0, psi1, k0, k1, s01, &b0);
			if (lo > 0 && b0 > 0 && b0 <= top && fabs(lo - len) +
			    fabs(b0 - len) < best) {
				best = fabs(lo - len) + fabs(b0 - len);
				*a = lo;
				*b = b0;
			}
		}
		a0 = a1, g0 = g1;
	}
	return best < HUGE_VAL ? 0 : -1;
}

/*
 * Spiro's manner (Levien 2009: a curve of clothoid pieces, G2 at the
 * knots, by Newton on the knots' tangent angles): the angles at which
 * the Euler spirals through consecutive knots meet with equal
 * curvature, Newton from estimate_tangent's, into a (its room in *mem,
 * for the caller to free).  Closed plane records of at most
 * SPIRAL_MAXKNOTS knots.  0, 1 where it is not to be had (*mem NULL),
 * -1 out of memory.
 */
static int
spiral_solve(const struct fair *f, struct angles *a, double **mem)
{
	size_t n = f->n;
	double big;

	*mem = NULL;
	if (f->dim != 2 || n < (f->o->closed ? 3 : 2) || n > SPIRAL_MAXKNOTS)
		return 1;
	if ((*mem = malloc((10 * n + n * n) * sizeof **mem)) == NULL)
		return -1;
	a->n = n;
	a->nseg = f->nseg;
	a->closed = f->o->closed;
	a->end[0] = f->o->have_start;
	a->end[1] = f->o->have_end;
	a->scale = 0;
	a->ref = *mem, a->phi = a->ref + n, a->c = a->phi + n;
	a->x = a->c + n, a->k0 = a->x + n, a->k1 = a->k0 + n;
	a->len = a->k1 + n, a->r = a->len + n, a->dx = a->r + n;
	a->xn = a->dx + n, a->jac = a->xn + n;
	for (size_t i = 0; i < a->nseg; i++) {
		double u[2];

		a->c[i] = unit_chord(f, i, u);
		a->phi[i] = atan2(u[1], u[0]);
		a->scale += a->c[i] / a->nseg;
	}
	for (size_t i = 0; i < n; i++) {
		double p = a->phi[(i + n - 1) % n];

		if (a->closed || (i > 0 && i + 1 < n))
			a->ref[i] = p + angle_diff(a->phi[i], p) / 2;
		else if (a->end[i > 0])
			a->ref[i] = i == 0 ? atan2(f->o->start[1], f->o->start[0]) :
			    atan2(f->o->end[1], f->o->end[0]);
		else
			a->ref[i] = a->phi[i == 0 ? 0 : n - 2];
		a->x[i] = 0;
	}
	big = residuals(a, a->x);
	for (int it = 0; it < SPIRAL_ITER && big < HUGE_VAL &&
	    big > SPIRAL_TOL; it++)
		big = newton_step(a, big);
	if (big <= SPIRAL_TOL)
		return 0;
	free(*mem);
	*mem = NULL;
	return 1;
}

/* A span whose spiral turns through more than this (radians, along
 * it) is split, where the caller has room (loft_fit_opts.split), into
 * cubics that turn this much at most: a G2 cubic follows a quarter
 * circle to about 1e-4 of its radius, an eighth to some 1e-6, and a
 * spiral past half a turn not at all.  LOFT_FIT_SPLIT a span at most. */
#define SPIRAL_PIECE_TURN (M_PI / 4)

/* A split span's cubic whose tangent magnitude is farther than this
 * factor (a log) from its piece's length follows its spiral badly
 * (nearly stopping at one end): the span is split finer. */
#define SPIRAL_PIECE_MAG 0.6931471805599453

/* The parts of 4-point Gauss along a piece when its points are placed:
 * a piece's angle is a quadratic of at most SPIRAL_PIECE_TURN's change,
 * which 4 parts integrate to rounding. */
#define SPIRAL_QUAD 4

/* How far span s's spiral turns, the integral of |angle'| along it:
 * its angle's rate is alpha + d t, t from 0 to 1. */
static double
spiral_turning(const struct angles *a, size_t s)
{
	double turn = (a->k0[s] + a->k1[s]) / 2 * a->len[s];
	double d = (a->k1[s] - a->k0[s]) * a->len[s], al = turn - d / 2;
	double be = al + d, r;

	if ((al >= 0) == (be >= 0))
		return fabs(turn);
	r = al / (al - be);
	return (fabs(al) * r + fabs(be) * (1 - r)) / 2;
}

/* The angle of span s's spiral at t (0 to 1 along it), absolute. */
static double
spiral_angle(const struct angles *a, size_t s, double t)
{
	double psi0 = angle_diff(a->ref[s], a->phi[s]) + a->x[s];
	double turn = (a->k0[s] + a->k1[s]) / 2 * a->len[s];
	double d = (a->k1[s] - a->k0[s]) * a->len[s];

	return a->phi[s] + psi0 + turn * t + d / 2 * (t * t - t);
}

/* The point of span s's spiral at tb into pb, from its point pa at ta:
 * the integral of its unit tangent times its length. */
static void
spiral_point(const struct angles *a, size_t s, double ta, double tb,
    const double *pa, double *pb)
{
	double w = (tb - ta) / SPIRAL_QUAD;

	pb[0] = pa[0], pb[1] = pa[1];
	for (int part = 0; part < SPIRAL_QUAD; part++)
		for (int j = 0; j < GAUSS; j++) {
			double th = spiral_angle(a, s, ta + w * (part +
			    gauss_u[j]));

			pb[0] += a->len[s] * w * gauss_w[j] * cos(th);
			pb[1] += a->len[s] * w * gauss_w[j] * sin(th);
		}
}

/*
 * Span s of the spirals of a as m cubics into q (8 m numbers), G2
 * Hermite each (g2_magnitudes) to the spiral's points, angles and
 * curvatures at t = j / m; the last ends on the knot itself.  0, or 1
 * where a piece has no such cubic.
 */
static int
spiral_span(const struct fair *f, const struct angles *a, size_t s, int m,
    double *q)
{
	size_t t = (s + 1) % f->n;
	double pa[2], tha = spiral_angle(a, s, 0), ka = a->k0[s];

	memcpy(pa, f->p + 2 * s, sizeof pa);
	for (int j = 1; j <= m; j++, q += 8) {
		double tb = (double)j / m, pb[2], thb = spiral_angle(a, s, tb);
		double kb = j == m ? a->k1[s] : (a->k0[s] * (1 - tb) + a->k1[s] *
		    tb), c, ph, ma = 0, mb = 0;

		if (j == m)
			memcpy(pb, f->p + 2 * t, sizeof pb);
		else
			spiral_point(a, s, (j - 1.0) / m, tb, pa, pb);
		c = hypot(pb[0] - pa[0], pb[1] - pa[1]);
		ph = atan2(pb[1] - pa[1], pb[0] - pa[0]);
		if (g2_magnitudes(c, angle_diff(tha, ph), angle_diff(thb, ph),
		    ka, kb, a->len[s] / m, &ma, &mb) != 0 || (m > 1 &&
		    !(fabs(log(ma * m / a->len[s])) <= SPIRAL_PIECE_MAG &&
		    fabs(log(mb * m / a->len[s])) <= SPIRAL_PIECE_MAG)))
			return 1;
		memcpy(q, pa, sizeof pa);
		memcpy(q + 2, pb, sizeof pb);
		q[4] = ma * cos(tha), q[5] = ma * sin(tha);
		q[6] = mb * cos(thb), q[7] = mb * sin(thb);
		memcpy(pa, pb, sizeof pa);
		tha = thb, ka = kb;
	}
	return 0;
}

/*
 * The spirals of spiral_solve as cubics into seg, each span one cubic
 * (split 0) or as many as keep each within SPIRAL_PIECE_TURN (split 1;
 * seg then has room for LOFT_FIT_SPLIT a span), each with its spiral's
 * end tangents and curvatures: a G2 curve that is the circle, to the
 * error of a cubic arc, where the knots are on one.  The segments into
 * *nseg; 0, 1 where it is not to be had, -1 out of memory.
 */
static int
spiral_start(struct fair *f, int split, double *seg, size_t *nseg)
{
	struct angles a;
	double *mem;
	int rc = spiral_solve(f, &a, &mem);

	*nseg = 0;
	for (size_t s = 0; s < f->nseg && rc == 0; s++) {
		/* a quarter turn is two pieces, whatever its rounding */
		int m = split ? (int)ceil(spiral_turning(&a, s) /
		    SPIRAL_PIECE_TURN * (1 - 1e-9)) : 1;

		m = m < 1 ? 1 : m;
		while (m <= LOFT_FIT_SPLIT && spiral_span(f, &a, s, m, seg +
		    8 * *nseg) != 0)
			m = split ? m + 1 : LOFT_FIT_SPLIT + 1;
		if (m > LOFT_FIT_SPLIT)
			rc = 1;
		else
			*nseg += m;
	}
	free(mem);
	return rc;
}

/*
 * The start of the spirals' angles and lengths in the descent's terms,
 * into x: each interval its spiral's length, and each diagonal factor
 * the one that makes row i of cspline.c's system hold, along the
 * tangent, for knot derivatives the spirals' unit tangents (the
 * least-squares fit of the one number to the row's two).  0, 1 where
 * it is not to be had, -1 out of memory.
 */
static int
spiral_intervals(const struct fair *f, double *x)
{
	struct angles a;
	double *mem = NULL;
	size_t n = f->n;
	int rc = f->o->closed ? spiral_solve(f, &a, &mem) : 1;

	for (size_t i = 0; i < n && rc == 0; i++)
		x[i] = log(a.len[i]);
	for (size_t i = 0; i < n && rc == 0; i++) {
		size_t hm = (i + n - 1) % n, j = (i + 1) % n;
		double h0 = a.len[hm], h1 = a.len[i], d = 0, q;

		for (int k = 0; k < 2; k++) {
			double tk = k == 0 ? cos(a.ref[i] + a.x[i]) :
			    sin(a.ref[i] + a.x[i]);
			double tm = k == 0 ? cos(a.ref[hm] + a.x[hm]) :
			    sin(a.ref[hm] + a.x[hm]);
			double tp = k == 0 ? cos(a.ref[j] + a.x[j]) :
			    sin(a.ref[j] + a.x[j]);
			double rhs = 3 * (h1 * (f->p[2 * i + k] - f->p[2 * hm +
			    k]) / h0 + h0 * (f->p[2 * j + k] - f->p[2 * i + k]) /
			    h1);

			d += tk * (rhs - h1 * tm - h0 * tp);
		}
		q = d / (h0 + h1) - 1;
		x[n + i] = log(fmax(q, 1e-3));
	}
	free(mem);
	return rc;
}

/* Manning's solution's intervals: each segment's mean tangent magnitude
 * (its length, nearly, in the paper's normalisation).  1 where Manning's
 * iteration fails on these knots, -1 out of memory. */
static int
manning_intervals(const struct fair *f, double *x)
{
	struct loft_fit_opts mo = *f->o;
	struct loft_fit_info info;
	struct loft_error err;
	double *seg = malloc(4 * f->dim * f->n * sizeof *seg);
	int rc = 1;

	if (seg == NULL)
		return -1;
	mo.method = LOFT_MANNING;
	memset(&info, 0, sizeof info);
	if (loft__fit_manning(&mo, f->p, f->n, f->dim, seg, &info, &err) ==
	    0) {
		rc = 0;
		for (size_t s = 0; s < f->nseg; s++) {
			const double *q = seg + s * 4 * f->dim;
			double a = vnorm(q + 2 * f->dim, f->dim) +
			    vnorm(q + 3 * f->dim, f->dim);

			if (!(a > 0))
				rc = 1;
			x[s] = log(a / 2);
		}
	}
	free(seg);
	return rc;
}

/*
 * The start `which' into x: log intervals and diagonal factors 0.
 * The chord lengths; their square roots (centripetal, which never
 * cusps a Catmull-Rom curve); each chord lengthened to the circular arc
 * that turns by the mean of the angles estimate_tangent's directions
 * make with it (arc length, the parameter of a fair curve); Manning's.
 * Returns 1 where a start is not to be had, -1 out of memory.
 */
static int
start_intervals(const struct fair *f, int which, double *x)
{
	for (size_t i = 0; i < f->n; i++)
		x[f->nseg + i] = 0;
	if (which == START_MANNING)
		return manning_intervals(f, x);
	if (which == START_SPIRAL)
		return spiral_intervals(f, x);
	for (size_t s = 0; s < f->nseg; s++) {
		double u[LOFT_MAXDIM], t0[LOFT_MAXDIM], t1[LOFT_MAXDIM];
		double w = unit_chord(f, s, u), a;

		if (which == START_CHORD) {
			x[s] = log(w);
			continue;
		}
		if (which == START_CENTRIPETAL) {
			x[s] = 0.5 * log(w);
			continue;
		}
		estimate_tangent(f, s, t0);
		estimate_tangent(f, (s + 1) % f->n, t1);
		a = (acos(fmax(-1, fmin(1, vdot(t0, u, f->dim)))) +
		    acos(fmax(-1, fmin(1, vdot(t1, u, f->dim))))) / 2;
		a = fmin(a, 1.5);       /* a half turn at most */
		x[s] = log(w * (a > 1e-8 ? a / sin(a) : 1));
	}
	return 0;
}

/* Samples a segment of the speed check of a thorough search's result,
 * and the least (|P'| / chord)^2 it allows: a descent from another start
 * than the chord spline may slip a cusp between the quadrature points,
 * where the chord spline's own near-cusp let the speed cap down. */
#define FAIR_SPEED_SAMPLES 64
#define FAIR_CUSP 1e-3

/* The least (|P'| / chord)^2 of the segments at FAIR_SPEED_SAMPLES + 1
 * even points of each, and their largest curvature into *kmax. */
static double
least_speed(const double *seg, size_t nseg, int dim, double *kmax)
{
	double least = HUGE_VAL, k2 = 0;

	for (size_t s = 0; s < nseg; s++) {
		const double *q = seg + s * 4 * dim;
		double cc = 0;

		for (int k = 0; k < dim; k++)
			cc += (q[dim + k] - q[k]) * (q[dim + k] - q[k]);
		for (int j = 0; j <= FAIR_SPEED_SAMPLES; j++) {
			double d[LOFT_MAXDIM], dd[LOFT_MAXDIM], v, x;

			loft_cubic_eval(q, dim, (double)j / FAIR_SPEED_SAMPLES,
			    NULL, d, dd);
			v = vdot(d, d, dim);
			x = vdot(d, dd, dim);
			least = fmin(least, v / cc);
			if (v > 0)
				k2 = fmax(k2, (v * vdot(dd, dd, dim) - x * x) /
				    (v * v * v));
		}
	}
	*kmax = sqrt(k2);
	return least;
}

/* The relative rounding of the root finder's least radius: a curve
 * whose least radius is the chord spline's to this is not sharper. */
#define FAIR_RADIUS_EPS 1e-9

/* The best curve found so far and what it is judged against. */
struct best {
	double *x;              /* its log intervals and factors */
	double score;           /* E L by the check's parts */
	double e;               /* its E */
	double least;           /* the least E L kept yet */
	double echord;          /* the chord spline's E by them: no more */
	int chord_loops;        /* whether the chord spline crosses itself:
	                         * -1 not yet known */
	double *cseg;           /* room for the chord spline's segments */
	int found;              /* 0 the chord spline's, 1 x a descent's, 2
	                         * sseg the spiral start's */
	double *sseg;           /* room for the spiral start's segments */
	size_t nsseg;           /* and their number */
	double *pseg;           /* room for split spirals, or NULL */
	int have_cseg;          /* whether cseg holds it (0 where it fails) */
	double rchord;          /* its least radius, exactly: -1 unknown */
	double echord_exact;    /* its E by adaptive quadrature: -1 unknown,
	                         * HUGE_VAL unbounded */
	int chord_resolved;     /* whether the check's parts resolve its E */
};

/* The chord spline into b->cseg, once; 0, or 1 where it fails. */
static int
chord_spline(struct fair *f, struct best *b, double *h)
{
	struct loft_error err;

	if (b->have_cseg == 0) {
		for (size_t s = 0; s < f->nseg; s++)
			h[s] = vdist(f->p + ((s + 1) % f->n) * f->dim,
			    f->p + s * f->dim, f->dim);
		b->have_cseg = loft__cspline_h(f->o, f->p, f->n, f->dim, h,
		    NULL, b->cseg, f->work, &err) != 0 ? -1 : 1;
	}
	return b->have_cseg < 0;
}

/* The least radius of the nseg segments seg by measure.c's root finder
 * (exact, where the samples of max_curvature and least_speed may step
 * over a cusp); 0 at a cusp or a retracted handle. */
static double
least_radius(const struct fair *f, const double *seg, size_t nseg)
{
	struct loft_curve c;
	struct loft_error err;
	double r, u;

	loft_curve_cubic(&c, seg, nseg, f->dim, f->o->closed);
	return loft_curve_min_radius(&c, &r, &u, &err) == 0 && r > 0 ? r : 0;
}

/* Whether the nseg segments seg bend more sharply anywhere than the
 * chord spline does, by the exact least radius of both (0 where the
 * chord spline cannot be made). */
static int
sharper_exact(struct fair *f, struct best *b, double *h, const double *seg,
    size_t nseg)
{
	if (chord_spline(f, b, h) != 0)
		return 0;
	if (b->rchord < 0)
		b->rchord = least_radius(f, b->cseg, f->nseg);
	return least_radius(f, seg, nseg) < b->rchord * (1 - FAIR_RADIUS_EPS);
}

/* The relative accuracy of measure.c's energy (1e-10) and some: two
 * curves whose exact energies agree to this are as fair. */
#define FAIR_ENERGY_EPS 1e-9

/* The bending energy of the nseg segments seg by measure.c's adaptive
 * quadrature; HUGE_VAL where it is unbounded (a cusp). */
static double
exact_energy(const struct fair *f, const double *seg, size_t nseg)
{
	struct loft_curve c;
	struct loft_error err;
	double e;

	loft_curve_cubic(&c, seg, nseg, f->dim, f->o->closed);
	return loft_curve_energy(&c, &e, &err) == 0 ? e : HUGE_VAL;
}

/* Whether parts Gauss parts resolve the energy of segment q: twice as
 * many agree to 1e-4. */
static int
segment_resolved(const double *q, int dim, int parts)
{
	double k = 0, slow = HUGE_VAL, len = 0;
	double a = segment_energy(q, dim, parts, NULL, &k, &slow, &len);
	double a2 = segment_energy(q, dim, 2 * parts, NULL, &k, &slow, &len);

	return fabs(a - a2) <= 1e-4 * a2;
}

/* Whether the judge's parts resolve the energy of every segment of seg
 * (nseg) that turns sharply: those the check gives FAIR_CHECK parts
 * (all where nseg is not the knots' spans).  The others the check
 * resolves as it does the chord spline's there (choose_parts). */
static int
resolved(const struct fair *f, const double *seg, size_t nseg)
{
	for (size_t s = 0; s < nseg; s++)
		if ((nseg != f->nseg || f->check[s] == FAIR_CHECK) &&
		    !segment_resolved(seg + s * 4 * f->dim, f->dim, FAIR_CHECK))
			return 0;
	return 1;
}

/* Whether the nseg segments seg have more bending energy than the
 * chord spline (the guarantee) where the judge's Gauss parts may not
 * see it: a segment that turns back in a hairpin spends most of its
 * energy between their points (tests/fit.sh's closed knots on a line
 * with a spike: 12350 against the chord spline's 12100, judged the
 * less; so were 8 of 4900 fuzzed sets).  There, by the exact energies. */
static int
costlier(struct fair *f, struct best *b, double *h, const double *seg,
    size_t nseg)
{
	if ((b->chord_resolved && resolved(f, seg, nseg)) ||
	    chord_spline(f, b, h) != 0)
		return 0;
	if (b->echord_exact < 0)
		b->echord_exact = exact_energy(f, b->cseg, f->nseg);
	return !(exact_energy(f, seg, nseg) <= b->echord_exact * (1 +
	    FAIR_ENERGY_EPS));
}

/* Whether the nseg segments seg bend more sharply anywhere than the
 * chord spline does (the guarantee), by the exact least radius of
 * both: a descent may slip a cusp between the points of the sampled
 * caps, whose energy is then unbounded. */
static int
sharper(struct fair *f, struct best *b, double *h, const double *seg,
    size_t nseg)
{
	double least = HUGE_VAL;

	/* the quick descent keeps every segment's speed above its floor,
	 * where the samples see a bend: the root finder (which took the
	 * bench's 10^4 insoles from 0.47 to 0.63 of GNU spline's time)
	 * only where some segment slows below it */
	for (size_t s = 0; !f->scalefree && s < nseg; s++)
		least = fmin(least, segment_least_speed(seg + s * 4 * f->dim,
		    f->dim));
	if (!f->scalefree && least >= FAIR_SLOW * FAIR_SLOW)
		return 0;
	return sharper_exact(f, b, h, seg, nseg);
}

/* Whether the chord spline crosses itself (plane curves; once); -1 out
 * of memory. */
static int
chord_loops(struct fair *f, struct best *b, double *h)
{
	if (b->chord_loops < 0)
		b->chord_loops = chord_spline(f, b, h) != 0 ? 0 :
		    loft_fit_crosses(b->cseg, f->nseg, f->o->closed);
	return b->chord_loops;
}

/* The spirals' cubics (Spiro's manner: the batten's shape, Levien
 * 2009) are kept over a descent's curve of less E L where their E is
 * less and their E L no more than this factor above the least: the
 * least E L hugs a far-out knot in a sharper bend than a batten makes
 * (make compare: at 1.0, 3 of 300 sets bend more than twice as sharply
 * as Spiro's curve). */
#define FAIR_SPIRAL_SLACK 1.1

/*
 * Judge the nseg segments seg, of x (NULL: the spirals' cubics): kept
 * as the best where, by the check's parts (FAIR_CHECK a segment where
 * nseg is not the knots' spans), its E L is below the best's, its E no
 * more than the chord spline's, no curvature past the chord spline's
 * largest, and (in the plane) no crossing unless the chord spline
 * crosses too.  Returns 0, or -1 out of memory.
 */
static int
judge_segs(struct fair *f, struct best *b, const double *x, double *h,
    const double *seg, size_t nseg)
{
	const unsigned char *parts = nseg == f->nseg ? f->check : NULL;
	double e, el, len, kmax;
	int loops;

	e = curve_energy(seg, nseg, f->dim, FAIR_CHECK, parts, NULL, &kmax,
	    NULL, &len);
	el = f->scalefree ? e * len : e;
	if (!(el < b->score || (x == NULL && el <= FAIR_SPIRAL_SLACK *
	    b->least && e < b->e)) || !(e <= b->echord) ||
	    !(max_curvature(seg, nseg, f->dim) <= f->kcap) ||
	    (f->scalefree && (!(least_speed(seg, nseg, f->dim, &kmax) >=
	    FAIR_CUSP) || !(kmax <= f->kcap))) || sharper(f, b, h, seg, nseg) ||
	    costlier(f, b, h, seg, nseg))
		return 0;
	loops = f->dim == 2 ? loft_fit_crosses(seg, nseg, f->o->closed) : 0;
	if (loops == 1)
		loops = chord_loops(f, b, h) == 0 ? 2 : chord_loops(f, b, h);
	if (loops < 0)
		return -1;
	if (loops == 2)
		return 0;
	b->score = el;
	b->e = e;
	b->least = fmin(b->least, el);
	b->found = x != NULL ? 1 : 2;
	if (x != NULL)
		memcpy(b->x, x, (f->nseg + f->n) * sizeof *x);
	else
		memcpy(b->sseg, seg, 4 * f->dim * nseg * sizeof *seg);
	b->nsseg = x != NULL ? b->nsseg : nseg;
	return 0;
}

/* judge_segs of the curve of x in f->seg. */
static int
judge(struct fair *f, struct best *b, const double *x, double *h)
{
	return judge_segs(f, b, x, h, f->seg, f->nseg);
}

/* How much farther than swell_allowed a span of an open curve may
 * swell: 5% more lets the open insole keep an energy below Manning's
 * (fit.sh), and glyph contours' pieces between corners stay nearer
 * their outline than at 2% or 25% (make compare: median 16.4, against
 * 17.0 and 18.1). */
#define FAIR_SWELL 1.05

/* The points of each span at which its swell is sampled. */
#define FAIR_SWELL_SAMPLES 16

/* The swell of segment q (a row P_A P_B P'_A P'_B): its greatest
 * distance from the line of its chord, at FAIR_SWELL_SAMPLES points. */
static double
span_swell(const double *q, int dim)
{
	double c[LOFT_MAXDIM], most = 0;

	vsub(c, q + dim, q, dim);
	if (!(vunit(c, dim) > 0))
		return 0;
	for (int j = 1; j < FAIR_SWELL_SAMPLES; j++) {
		double pt[LOFT_MAXDIM], a;

		loft_cubic_eval(q, dim, (double)j / FAIR_SWELL_SAMPLES, pt,
		    NULL, NULL);
		vsub(pt, pt, q, dim);
		a = vdot(pt, c, dim);
		vaxpy(pt, -a, c, dim);
		most = fmax(most, vnorm(pt, dim));
	}
	return most;
}

/* The sagitta over the chord from knot a to knot b of the circle
 * through them and knot q (the minor arc's); 0 where the three are
 * in a line. */
static double
sagitta(const struct fair *f, size_t a, size_t b, size_t q)
{
	const double *pa = f->p + a * f->dim, *pb = f->p + b * f->dim;
	const double *pq = f->p + q * f->dim;
	double ab = vdist(pa, pb, f->dim), aq = vdist(pa, pq, f->dim);
	double bq = vdist(pb, pq, f->dim), s = (ab + aq + bq) / 2, area, r;

	/* Heron's area, then the circumradius ab aq bq / (4 area) */
	area = s * (s - ab) * (s - aq) * (s - bq);
	if (!(area > 0))
		return 0;
	r = ab * aq * bq / (4 * sqrt(area));
	return r - sqrt(fmax(0, r * r - ab * ab / 4));
}

/* The swell span s may have: the chord spline's, or the sagitta of a
 * circle through its knots and a neighbour where that is more (so that
 * knots on a circle still give the circle). */
static double
swell_allowed(const struct fair *f, const struct best *b, size_t s)
{
	double most = span_swell(b->cseg + s * 4 * f->dim, f->dim);

	if (s > 0)
		most = fmax(most, sagitta(f, s, s + 1, s - 1));
	if (s + 2 < f->n)
		most = fmax(most, sagitta(f, s, s + 1, s + 2));
	return most;
}

/* Whether some span of f->seg (open) swells farther from its chord
 * than swell_allowed, past rounding. */
static int
swells(const struct fair *f, const struct best *b)
{
	for (size_t s = 0; s < f->nseg; s++) {
		const double *q = f->seg + s * 4 * f->dim;

		if (span_swell(q, f->dim) > swell_allowed(f, b, s) * FAIR_SWELL + 1e-9 *
		    vdist(q + f->dim, q, f->dim))
			return 1;
	}
	return 0;
}

/* The halvings of the way back to the chord spline tried. */
#define FAIR_UNSWELL 6

/*
 * An open curve (a piece between corners, or a curve with free ends)
 * never swells past the chord spline, span by span (issue 23: least
 * energy alone rewards a curve that bulges beside a corner): where the
 * best does, the curve of t times its log intervals and diagonal
 * factors and 1 - t times the chord spline's, for t = 1/2, 1/4, ..
 * (FAIR_UNSWELL of them), the first that does not and passes judge;
 * else the chord spline.
 * xt: room for nseg + n numbers.  0, or -1 out of memory.
 */
static int
unswell(struct fair *f, struct best *b, double *xt, double *h)
{
	struct loft_error err;

	if (b->found != 1 || chord_spline(f, b, h) != 0)
		return 0;
	for (size_t s = 0; s < f->nseg; s++)
		h[s] = exp(b->x[s]);
	if (loft__cspline_h(f->o, f->p, f->n, f->dim, h, b->x + f->nseg,
	    f->seg, f->work, &err) != 0 || !swells(f, b))
		return 0;
	memcpy(xt, b->x, (f->nseg + f->n) * sizeof *xt);
	b->found = 0;
	b->score = b->least = b->e = HUGE_VAL;
	for (int k = 0; k < FAIR_UNSWELL && !b->found; k++) {
		for (size_t s = 0; s < f->nseg; s++) {
			double c = log(vdist(f->p + ((s + 1) % f->n) * f->dim,
			    f->p + s * f->dim, f->dim));

			xt[s] = c + (xt[s] - c) / 2;
			h[s] = exp(xt[s]);
		}
		for (size_t i = 0; i < f->n; i++)
			xt[f->nseg + i] /= 2;
		if (loft__cspline_h(f->o, f->p, f->n, f->dim, h, xt + f->nseg,
		    f->seg, f->work, &err) != 0 || swells(f, b))
			continue;
		if (judge(f, b, xt, h) != 0)
			return -1;
	}
	return 0;
}

/* A start past the chord spline's curvature cap by at most this
 * factor descends under a cap this factor beyond its own (a cap at its
 * own value would be met at once and held); one farther past nearly
 * cusps, and its long descent moves with the knots' rounding by more
 * than bad.sh's units allow: it is no start. */
#define FAIR_START_CAP 2.0

/*
 * Every start run to convergence, each judged: the check's parts are
 * FAIR_CHECK everywhere, the chord spline judged again by them first.
 * Returns the steps taken, or -1 out of memory.
 */
static int
thorough(struct fair *f, struct best *b, double *x, double *h, double *v)
{
	double e, len, k, slow, kcap, slow0 = f->slow;
	int steps = 0, rc;
	struct loft_error err;

	if (chord_spline(f, b, h) == 0 && b->rchord < 0)
		b->rchord = least_radius(f, b->cseg, f->nseg);
	/* the chord spline's largest curvature, exactly where the samples
	 * of its cap missed its peak */
	if (b->rchord > 0)
		f->kcap = fmax(f->kcap, (1 + 1e-9) / b->rchord);
	kcap = f->kcap;
	f->steps = FAIR_CONVERGE;
	f->settled = FAIR_SETTLED_FINE;
	f->scalefree = 1;
	memset(f->check, FAIR_CHECK, f->nseg);
	memset(f->parts, FAIR_CHECK, f->nseg);
	start_intervals(f, START_CHORD, x);
	for (size_t s = 0; s < f->nseg; s++)
		h[s] = exp(x[s]);
	if (loft__cspline_h(f->o, f->p, f->n, f->dim, h, NULL, f->seg,
	    f->work, &err) != 0)
		return 0;
	b->echord = curve_energy(f->seg, f->nseg, f->dim, 0, f->check, NULL,
	    &k, NULL, &len) * (1 + 1e-12);
	b->score = b->least = b->echord * len;
	b->e = b->echord;
	b->found = 0;
	f->e0 = b->score;
	memcpy(b->x, x, (f->nseg + f->n) * sizeof *x);
	for (int which = 0; which < STARTS; which++) {
		rc = start_intervals(f, which, x);

		if (rc < 0)
			return -1;
		if (rc > 0)
			continue;
		for (size_t s = 0; s < f->nseg; s++)
			h[s] = exp(x[s]);
		if (loft__cspline_h(f->o, f->p, f->n, f->dim, h, x + f->nseg,
		    f->seg, f->work, &err) != 0)
			continue;
		/* a start past the caps descends under its own (see
		 * FAIR_START_CAP), and is judged by the chord spline's */
		curve_energy(f->seg, f->nseg, f->dim, 0, f->parts, NULL, &k,
		    &slow, &len);
		f->kcap = k > kcap && k <= FAIR_START_CAP * kcap ? FAIR_START_CAP * k : kcap;
		for (size_t s = 0; s < f->nseg; s++)
			slow = fmin(slow, segment_least_speed(f->seg + s * 4 *
			    f->dim, f->dim));
		f->slow = fmin(slow0, slow * (1 - 1e-9));
		steps += descend(f, x, h, v, &e);
		f->kcap = kcap;
		f->slow = slow0;
		if (e < HUGE_VAL && judge(f, b, x, h) != 0)
			return -1;
	}
	/* the spirals, a cubic a span, and split where the caller allows */
	for (int split = 0; split < (b->pseg != NULL ? 2 : 1); split++) {
		size_t ns;
		double *q = split ? b->pseg : f->seg;

		rc = spiral_start(f, split, q, &ns);
		if (rc < 0 || (rc == 0 && judge_segs(f, b, NULL, h, q, ns) != 0))
			return -1;
	}
	return steps;
}

/* An open curve's spirals (Spiro's manner, a cubic a span: the span
 * beside a free end a circular arc), where an end is free (a corner's),
 * judged against the best yet after unswell: kept where their E is
 * less and no span swells past what unswell allows.  Between two given
 * tangents they add nothing to the descent's (splinefit -e's fits,
 * between straight runs, came out farther from the truth).  0, or -1
 * out of memory. */
static int
open_spiral(struct fair *f, struct best *b, double *h)
{
	size_t ns;
	int rc = f->o->have_start && f->o->have_end ? 1 :
	    spiral_start(f, 0, f->seg, &ns);

	if (rc != 0)
		return rc < 0 ? -1 : 0;
	if (chord_spline(f, b, h) != 0 || swells(f, b))
		return 0;
	return judge_segs(f, b, NULL, h, f->seg, ns);
}

/* Whether the best curve found crosses itself (plane curves); -1 out
 * of memory.  Its segments are left in f->seg. */
static int
best_crosses(struct fair *f, struct best *b, double *h)
{
	struct loft_error err;
	const double *seg = f->seg;
	size_t nseg = f->nseg;

	if (b->found == 2) {
		seg = b->sseg;
		nseg = b->nsseg;
	} else if (b->found == 0) {
		if (chord_spline(f, b, h) != 0)
			return 0;
		seg = b->cseg;
	} else {
		for (size_t s = 0; s < f->nseg; s++)
			h[s] = exp(b->x[s]);
		if (loft__cspline_h(f->o, f->p, f->n, f->dim, h, b->x +
		    f->nseg, f->seg, f->work, &err) != 0)
			return 0;
	}
	return loft_fit_crosses(seg, nseg, f->o->closed);
}

/*
 * Where the best open curve (a piece of an outline between corners or
 * straight runs) crosses itself, as it may where the chord spline does
 * (a glyph's thin stem between sparse knots beside a dense serif: each
 * long span's tangents lean to the short span beside it, and the two
 * sides of the stem bulge into each other): the descent from the
 * centripetal spline's intervals (the square roots of the chords, which
 * lean them less), and then that spline itself, each kept if it does
 * not cross itself, passes judge's other tests and, beside a corner (a
 * free end), swells nowhere past what unswell allows, whatever its E L
 * (between two straight runs a stem may swell from its chord where the
 * chord spline's crossed it).
 * With o->untangle (the pieces of a curve cross one another, each
 * uncrossed) every open piece has them tried so.
 * Not on closed records: on make compare's 300 sets, where a curve
 * crosses itself only where the chord spline does, the curves it kept
 * had up to 2.72 times the energy of the fairest peer's, and on 4 sets
 * a bend more than twice as sharp as Spiro's.  0, or -1 out of memory.
 */
static int
uncross(struct fair *f, struct best *b, double *x, double *h, double *v)
{
	int cross = f->dim != 2 ? 0 : f->o->untangle ? 1 : best_crosses(f,
	    b, h), loops;
	double score = b->score, e = b->e, least = b->least;
	struct loft_error err;

	if (cross <= 0)
		return cross;
	loops = b->chord_loops;
	b->chord_loops = 0;             /* no crossing passes */
	for (int pass = 0; pass < 2 && b->score == score; pass++) {
		double en = 0;          /* pass 1: the start as it is */

		start_intervals(f, START_CENTRIPETAL, x);
		if (pass == 0)
			descend(f, x, h, v, &en);
		for (size_t s = 0; s < f->nseg; s++)
			h[s] = exp(x[s]);
		if (!(en < HUGE_VAL) || loft__cspline_h(f->o, f->p, f->n,
		    f->dim, h, x + f->nseg, f->seg, f->work, &err) != 0 ||
		    (!(f->o->have_start && f->o->have_end) && swells(f, b)))
			continue;
		b->score = b->e = HUGE_VAL;
		if (judge(f, b, x, h) != 0)
			return -1;
		if (b->score == HUGE_VAL)       /* not kept */
			b->score = score, b->e = e, b->least = least;
	}
	b->chord_loops = loops;
	return 0;
}

/*
 * From the chord spline in f->seg (its E in f->e0), the quick descent,
 * judged; then a closed record few or sharp enough searched thoroughly,
 * an open one kept from swelling and given Spiro's spirals' chance
 * (unless o->quick: splinefit -e's trial fits, many, where the spirals'
 * Newton made -K -e on noisy glyphs up to 9 times slower).
 * The steps into info->iterations; 0, or -1 out of memory.
 */
static int
search(struct fair *f, struct best *b, double *x, double *h, double *v,
    double chords, struct loft_fit_info *info)
{
	const struct loft_fit_opts *o = f->o;
	double e;
	int more = 0;

	info->iterations = descend(f, x, h, v, &e);
	if (info->iterations > 0 && e < HUGE_VAL)
		more = judge(f, b, x, h);
	if (more == 0 && o->closed && !o->quick && (f->n <= FAIR_FEW ||
	    (f->n <= FAIR_THOROUGH && max_curvature(f->seg, f->nseg, f->dim) *
	    chords * FAIR_SHARP > 1)))
		more = thorough(f, b, x, h, v);
	if (more >= 0 && !o->closed && (unswell(f, b, v, h) < 0 ||
	    (!o->quick && open_spiral(f, b, h) < 0)))
		more = -1;
	if (more >= 0 && !o->closed && !o->quick && uncross(f, b, x, h, v) <
	    0)
		more = -1;
	if (more >= 0)
		info->iterations += more;
	return more < 0 ? -1 : 0;
}

/* The signed curvature of the plane segment q (a row P_A P_B P'_A
 * P'_B) at its end (0 start, 1 end); 0 where its tangent vanishes. */
static double
end_curvature(const double *q, int end)
{
	double d1[2], d2[2], k;

	loft_cubic_eval(q, 2, end, NULL, d1, d2);
	return loft_curvature(d1, d2, 2, &k) == 0 ? k : 0;
}

static double
cross2(const double *a, const double *b)
{
	return a[0] * b[1] - a[1] * b[0];
}

/* Newton's steps at most for a segment with both end curvatures given,
 * and its residual, relative to the chord, at which it stops. */
#define FLAT_NEWTON 30
#define FLAT_SOLVED 1e-13

/*
 * Segment q of a plane curve, its end directions d0 and d1 kept, made
 * to have the curvature k[e] at each end e, 0 where flat[e] (meeting a
 * straight run there).  With Bezier points A, A + a d0, B - b d1, B and
 * chord c the curvature is (2/3)(d0 x c - b d0 x d1) / a^2 at A and
 * (2/3)(c x d1 - a d0 x d1) / b^2 at B: a flat end fixes the other
 * end's arm, and that arm the first's where its curvature is given;
 * where both are given, Newton's method from q's own arms solves the
 * two.  Returns 1 where an arm would be shorter than 1 / LOFT__MAXMAG
 * or longer than LOFT__MAXMAG thirds of the chord (not positive, or
 * lopsided: a span from a run nearly along its chord would turn at
 * once), or Newton fails, q untouched; else 0.
 */
static int
flat_segment(double *q, const int *flat, const double *k)
{
	double c[2], d0[2], d1[2], w, a, b, len, x, y;
	int it = 0;

	vsub(c, q + 2, q, 2);
	vcopy(d0, q + 4, 2);
	vcopy(d1, q + 6, 2);
	a = vunit(d0, 2) / 3;
	b = vunit(d1, 2) / 3;
	len = vnorm(c, 2);
	if (!(a > 0) || !(b > 0) || !(len > 0) || (w = cross2(d0, d1)) == 0)
		return 1;
	x = cross2(d0, c);
	y = cross2(c, d1);
	if (flat[0] || flat[1]) {
		a = flat[1] ? y / w : (y - 1.5 * k[1] * (x / w) * (x / w)) / w;
		b = flat[0] ? x / w : (x - 1.5 * k[0] * a * a) / w;
	}
	for (; !flat[0] && !flat[1] && it < FLAT_NEWTON; it++) {
		/* F = x - b w - 1.5 k0 a^2, G = y - a w - 1.5 k1 b^2 */
		double f = x - b * w - 1.5 * k[0] * a * a;
		double g = y - a * w - 1.5 * k[1] * b * b;
		double fa = -3 * k[0] * a, gb = -3 * k[1] * b, det = fa * gb -
		    w * w;

		if (fabs(f) + fabs(g) <= FLAT_SOLVED * len)
			break;
		if (!(fabs(det) > 0))
			return 1;
		a -= (f * gb + w * g) / det;
		b -= (fa * g + w * f) / det;
	}
	if (it == FLAT_NEWTON || !(3 * a * LOFT__MAXMAG >= len && 3 * b *
	    LOFT__MAXMAG >= len && 3 * a <= LOFT__MAXMAG * len && 3 * b <=
	    LOFT__MAXMAG * len))
		return 1;
	vscale(q + 4, 3 * a, d0, 2);
	vscale(q + 6, 3 * b, d1, 2);
	return 0;
}

/* The curvatures tried at the knot between two segments made anew
 * (flat_pair): FLAT_STEPS + 1 fractions of the fit's, 0 to FLAT_MOST. */
#define FLAT_STEPS 16
#define FLAT_MOST 1.5

/*
 * Segments q and q + 8 of a plane curve made anew (flat_segment), the
 * end at a straight run given by side (0: q's start, 1: the end of q +
 * 8) flat, the far end of the pair with the curvature kfar (or flat
 * where far_flat), and the knot between them with the fraction of its
 * own curvature nearest 1 that both can take: for where the segment
 * beside the run cannot meet its neighbour G2 alone, as beside a knot
 * the fit rounds tightly, whose bend must ease.  1 where no fraction
 * does (q untouched), else 0.
 */
static int
flat_pair(double *q, int side, double kfar, int far_flat)
{
	double km = end_curvature(q, 1), best = HUGE_VAL, t[16], keep[16];

	for (int i = 0; i <= FLAT_STEPS; i++) {
		double k0[2], k1[2], frac = FLAT_MOST * i / FLAT_STEPS;
		int f0[2] = { side == 0 || far_flat, 0 };
		int f1[2] = { 0, side == 1 || far_flat };

		k0[0] = side == 0 ? 0 : kfar;
		k0[1] = k1[0] = km * frac;
		k1[1] = side == 1 ? 0 : kfar;
		memcpy(t, q, sizeof t);
		if (fabs(frac - 1) >= best || flat_segment(t, f0, k0) != 0 ||
		    flat_segment(t + 8, f1, k1) != 0)
			continue;
		best = fabs(frac - 1);
		memcpy(keep, t, sizeof t);
	}
	if (!(best < HUGE_VAL))
		return 1;
	memcpy(q, keep, sizeof keep);
	return 0;
}

/*
 * The curve seg (f->nseg segments) met G2 at a straight run before its
 * first segment where ends & 1, after its last where ends & 2, into t:
 * each such end's segment made anew (flat_segment), its other end with
 * its neighbour's curvature, or else with that neighbour too
 * (flat_pair).  1 where not every such end could be, else 0.
 */
static int
flat_try(const struct fair *f, const double *seg, int ends, double *t)
{
	size_t ns = f->nseg, last = 8 * (ns - 1);
	int fl[2] = { ends & 1, (ends & 2) != 0 }, one[2] = { 1, 0 };
	double k[2];

	memcpy(t, seg, 8 * ns * sizeof *t);
	k[0] = end_curvature(t, 0);
	k[1] = end_curvature(t, 1);
	if (ns == 1)
		return flat_segment(t, fl, k);
	if (ns == 2 && fl[0] && fl[1])          /* an arch */
		return flat_pair(t, 0, 0, 1);
	if (fl[0]) {
		k[1] = end_curvature(t + 8, 0);
		if (flat_segment(t, one, k) != 0 && (ns < 3 || flat_pair(t, 0,
		    end_curvature(t + 16, 0), 0) != 0))
			return 1;
	}
	if (fl[1]) {
		one[0] = 0;
		one[1] = 1;
		k[0] = end_curvature(t + last - 8, 1);
		if (flat_segment(t + last, one, k) != 0 && (ns < 3 ||
		    flat_pair(t + last - 8, 1, end_curvature(t + last - 16, 1),
		    0) != 0))
			return 1;
	}
	return 0;
}

/* Whether a segment of t (f->nseg of them, open) made anew, not as in
 * seg, swells farther from its chord than unswell lets the fit's
 * (swell_allowed, FAIR_SWELL). */
static int
flat_swells(const struct fair *f, const struct best *b, const double *seg,
    const double *t)
{
	for (size_t s = 0; s < f->nseg; s++)
		if (memcmp(t + 8 * s, seg + 8 * s, 8 * sizeof *t) != 0 &&
		    span_swell(t + 8 * s, 2) > swell_allowed(f, b, s) *
		    FAIR_SWELL + 1e-9 * vdist(t + 8 * s + 2, t + 8 * s, 2))
			return 1;
	return 0;
}

/*
 * The open plane curve seg (f->nseg segments, the fit's) met G2 at its
 * ends beside straight runs (o->flat_start, o->flat_end), as Spiro's
 * `[' `]' points meet theirs: both ends, else either, by flat_try,
 * where the curve so made keeps the guarantees (no more energy than
 * the chord spline, no sharper bend, no crossing it has not) and
 * unswell's limit.  b->sseg, free by then, holds the tries.  0, or -1
 * out of memory.
 */
static int
flat_ends(struct fair *f, struct best *b, double *h, double *seg)
{
	size_t ns = f->nseg;
	double *t = b->sseg, e, len, kmax;
	int want = (f->o->flat_start ? 1 : 0) | (f->o->flat_end ? 2 : 0);
	const int tries[3] = { 3, 1, 2 };

	if (f->dim != 2 || f->o->closed || want == 0)
		return 0;
	for (int i = 0; i < 3; i++) {
		int loops;

		if ((tries[i] & want) != tries[i] || flat_try(f, seg, tries[i],
		    t) != 0)
			continue;
		e = curve_energy(t, ns, 2, FAIR_CHECK, f->check, NULL, &kmax,
		    NULL, &len);
		/* by the exact least radius: the segments made again keep no
		 * speed floor, and may nearly cusp between the samples */
		if (chord_spline(f, b, h) != 0 || flat_swells(f, b, seg, t) ||
		    !(e <= b->echord) || !(max_curvature(t, ns, 2) <= f->kcap) ||
		    sharper_exact(f, b, h, t, ns) || costlier(f, b, h, t, ns))
			continue;
		loops = loft_fit_crosses(t, ns, 0);
		if (loops == 1) {       /* kept where the chord spline loops */
			int c = chord_loops(f, b, h);

			loops = c < 0 ? -1 : !c;
		}
		if (loops < 0)
			return -1;
		if (loops == 0) {
			memcpy(seg, t, 8 * ns * sizeof *t);
			return 0;
		}
	}
	return 0;
}

int
loft__fit_fair(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	size_t nseg = o->closed ? n : n - 1, m = 2 * n;
	/* split spirals' room: LOFT_FIT_SPLIT segments a span */
	size_t room = o->split && dim == 2 && o->closed && n <=
	    SPIRAL_MAXKNOTS ? LOFT_FIT_SPLIT : 1;
	struct fair f = { o, p, n, nseg, dim, seg, NULL, NULL, NULL, 0, 0, NULL,
	    NULL, 0, 0, 1, FAIR_STEPS, FAIR_SETTLED };
	struct best b = { NULL, 0, 0, 0, 0, -1, NULL, 0, NULL, 0, NULL, 0, -1,
	    -1, 1 };
	double *mem, *x, *h, *v, e, len, flen, kmax, slow, fine, chords = 0;
	int rc;

	if (n > FAIR_MAXKNOTS) {        /* the chord spline, in its memory */
		struct loft_fit_opts co = *o;

		co.method = LOFT_CHORD;
		info->converged = 1;
		return loft__fit_cspline(&co, p, n, dim, seg, err);
	}
	mem = calloc((7 + 2 * dim) * n + 2 * dim * n + 4 * dim * n + 2 * m +
	    n + m * (2 * FAIR_MEMORY + 3) + 4 * dim * n * (1 + room + (room > 1 ?
	    room : 0)) + 2 * n / sizeof *mem +
	    1, sizeof *mem);
	if (mem == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	f.work = mem;
	f.gseg = f.work + (7 + 2 * dim) * n;
	f.gboth = f.gseg + 2 * dim * n;
	x = f.gboth + 4 * dim * n;
	b.x = x + m;
	h = b.x + m;
	v = h + n;
	b.cseg = v + m * (2 * FAIR_MEMORY + 3);
	b.sseg = b.cseg + 4 * dim * n;
	b.pseg = room > 1 ? b.sseg + 4 * dim * n * room : NULL;
	f.parts = (unsigned char *)(b.sseg + 4 * dim * n * (room > 1 ? 2 *
	    room : 1));
	f.check = f.parts + n;
	start_intervals(&f, START_CHORD, x);
	for (size_t s = 0; s < nseg; s++)
		chords += (h[s] = exp(x[s])) / nseg;
	rc = loft__cspline_h(o, p, n, dim, h, x + nseg, seg, f.work, err);
	if (rc == 0) {
		fine = choose_parts(seg, nseg, dim, f.parts, f.check, &e, &len,
		    &flen, &kmax, &slow);
		for (size_t s = 0; s < nseg; s++)
			b.chord_resolved &= f.parts[s] < FAIR_CHECK ||
			    segment_resolved(seg + s * 4 * dim, dim, FAIR_CHECK);
		/* the chord spline's largest curvature, less rounding */
		f.kcap = fmax(kmax, max_curvature(seg, nseg, dim)) * (1 + 1e-9);
		f.slow = fmin(FAIR_SLOW * FAIR_SLOW, slow);
		f.e0 = e;
		b.echord = fine * (1 - 1e-15);
		b.score = b.least = b.e = fine;
		memcpy(b.x, x, m * sizeof *x);
		if (isfinite(f.e0) && f.e0 > 0 && search(&f, &b, x, h, v,
		    chords, info) < 0) {
			free(mem);
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		}
		/* the best: the chord spline unless a descent or the spiral
		 * start beat it */
		if (b.found == 2) {
			memcpy(seg, b.sseg, 4 * dim * b.nsseg * sizeof *seg);
			info->nseg = b.nsseg;
		} else {
			for (size_t s = 0; s < nseg; s++)
				h[s] = b.found ? exp(b.x[s]) : vdist(p + ((s + 1) %
				    n) * dim, p + s * dim, dim);
			rc = loft__cspline_h(o, p, n, dim, h, b.found ? b.x +
			    nseg : NULL, seg, f.work, err);
		}
		if (rc == 0 && (b.found != 2 || b.nsseg == nseg) &&
		    flat_ends(&f, &b, h, seg) < 0)
			rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		info->converged = 1;
	}
	free(mem);
	return rc;
}
