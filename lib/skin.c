/*
 * skin.c: lofting, a design of MacCallum's bi-quartic patches (1970,
 * section 4) through a family of section curves.  v runs along the
 * sections, u across them: patch (k, j) lies between sections k and
 * k + 1 over segment j of the common segmentation.
 *
 * The edges along the sections are the sections' own segments.  The
 * curves across them, at each breakpoint, go through the sections'
 * points with loft_fit's tangent directions (Manning's fair spline).
 * Across every edge the surface is tangent-plane continuous by
 * construction: the derivative across an edge on one side is, as a
 * polynomial, a multiple of the other side's plus a multiple of the
 * derivative along the edge,
 *   across a section edge:   R(v) = sigma L(v) + c v (1 - v) E'(v),
 *   across a breakpoint edge: R(u) = lambda(u) L(u), lambda linear,
 * with L of the degree that keeps R a quartic.  The twists at a corner
 * of four patches are tied by those relations; the c of each section
 * edge are chosen (least squares, smallest) so the four agree.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Breakpoints of the sections' normalised parameters closer than this
 * are one: i/m computed for different m rounds by 1e-16. */
#define BREAK_EPS 1e-12

/* A split point within this of a segment's end, in the segment's own
 * parameter, is that end (i/m times m rounds by a few 1e-16). */
#define SNAP_EPS 1e-9

/* Tangents on either side of a section's knot are one direction when
 * their cross product is this small against their lengths: splinefit's
 * are parallel to rounding; a corner turns by far more. */
#define PARALLEL_REL 1e-9

/* A quartic segment is of cubic form when its (h) is the cubic's point
 * at 1/2 within this of the segment's extent (rounding only). */
#define CUBIC_REL 1e-9

/* Entry (i, j) of patch b. */
#define BIJ(b, i, j, dim) ((b) + (5 * (i) + (j)) * (dim))

struct skin {
	int dim, cs, cl;        /* dimension, closed sections, closed loft */
	size_t ns, nseg, nodes; /* sections, segments, breakpoints a section */
	size_t nstrip;
	double *seg;            /* ns * nseg quartics, 5 * dim each */
	double *t;              /* ns * nodes cross derivatives, design u */
	double *rho;            /* ns * nodes: ratio A / B at a knot, 0: corner */
	double *su;             /* nstrip */
	double *c;              /* ns * nseg */
	double *tw;             /* twists: nstrip * nseg * 4 * dim */
	double *b;              /* patches */
};

static double *
SEG(const struct skin *s, size_t k, size_t j)
{
	return s->seg + (k * s->nseg + j) * 5 * s->dim;
}

/* Node j of section k (its start point, or the last segment's end). */
static const double *
NODE(const struct skin *s, size_t k, size_t j)
{
	if (j < s->nseg)
		return SEG(s, k, j);
	return SEG(s, k, s->nseg - 1) + s->dim;
}

static double *
TAN(const struct skin *s, size_t k, size_t j)
{
	return s->t + (k * s->nodes + j % s->nodes) * s->dim;
}

/* Twist of patch (k, j) at corner (a, b). */
static double *
TW(const struct skin *s, size_t k, size_t j, int a, int b)
{
	return s->tw + ((k * s->nseg + j) * 4 + 2 * a + b) * s->dim;
}

static double *
PATCH(const struct skin *s, size_t k, size_t j)
{
	return s->b + (k * s->nseg + j) * 25 * s->dim;
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The piece [lo, hi] of piece i of c as a quartic q: exact for curves
 * of degree four or less; a whole piece is its type's quartic form. */
static void
piece(const struct loft_curve *c, size_t i, double lo, double hi, double *q)
{
	int dim = c->dim;
	double len = hi - lo;

	if (lo == 0 && hi == 1) {
		loft_curve_quartic(c, i, q);
		return;
	}
	loft_curve_eval(c, i, lo, q, q + 2 * dim, NULL);
	loft_curve_eval(c, i, hi, q + dim, q + 3 * dim, NULL);
	loft_curve_eval(c, i, lo + len / 2, q + 4 * dim, NULL, NULL);
	vscale(q + 2 * dim, len, q + 2 * dim, dim);
	vscale(q + 3 * dim, len, q + 3 * dim, dim);
}

/*
 * The common segmentation: the union of every section's breakpoints
 * i / m in its normalised parameter; with closed sections (cs), a count
 * that is even or below 3 is made odd by halving the longest interval
 * (the ring of conditions on c, below, is then solvable, and no patch
 * is its own neighbour).  Returns them (malloc'd, *count of them, from
 * 0 to 1), or NULL without memory.
 */
static double *
breakpoints(const struct loft_curve *sec, size_t ns, int cs, size_t *count)
{
	size_t total = 0, n = 0;
	double *t;

	for (size_t k = 0; k < ns; k++)
		total += sec[k].npieces + 1;
	if ((t = malloc((total + 1) * sizeof *t)) == NULL)
		return NULL;
	for (size_t k = 0; k < ns; k++)
		for (size_t i = 0; i <= sec[k].npieces; i++)
			t[n++] = (double)i / (double)sec[k].npieces;
	qsort(t, n, sizeof *t, cmp_double);
	total = 1;
	for (size_t i = 1; i < n; i++)
		if (t[i] - t[total - 1] > BREAK_EPS)
			t[total++] = t[i];
	t[total - 1] = 1;
	while (cs && ((total - 1) % 2 == 0 || total - 1 < 3)) {
		size_t big = 0;

		for (size_t i = 1; i + 1 < total; i++)
			if (t[i + 1] - t[i] > t[big + 1] - t[big])
				big = i;
		memmove(t + big + 2, t + big + 1, (total - big - 1) * sizeof *t);
		t[big + 1] = (t[big] + t[big + 2]) / 2;
		total++;
	}
	*count = total;
	return t;
}

/* Split the sections at the common breakpoints t (nseg + 1 of them):
 * ns * nseg quartics in s->seg. */
static void
refine(const struct skin *s, const struct loft_curve *sec, const double *t)
{
	for (size_t k = 0; k < s->ns; k++) {
		double m = (double)sec[k].npieces;

		for (size_t j = 0; j < s->nseg; j++) {
			double mid = (t[j] + t[j + 1]) / 2 * m;
			size_t i = (size_t)mid;
			double lo, hi;

			if (i >= sec[k].npieces)
				i = sec[k].npieces - 1;
			lo = t[j] * m - (double)i;
			hi = t[j + 1] * m - (double)i;
			lo = lo < SNAP_EPS ? 0 : lo;
			hi = hi > 1 - SNAP_EPS ? 1 : hi;
			piece(&sec[k], i, lo, hi, SEG(s, k, j));
		}
	}
}

/* The patch strip k lies between sections k and k + 1 (mod ns). */
static size_t
next(const struct skin *s, size_t k)
{
	return k + 1 == s->ns ? 0 : k + 1;
}

/* The sign of a . b, of unit copies: products of sections of 1e-300 or
 * 1e300 underflow or overflow (issue 28). */
static double
same_way(const double *a, const double *b, int dim)
{
	double ua[LOFT_MAXDIM], ub[LOFT_MAXDIM];

	vcopy(ua, a, dim);
	vcopy(ub, b, dim);
	vunit(ua, dim);
	vunit(ub, dim);
	return vdot(ua, ub, dim);
}

/*
 * Sections that cross: in strip k the chord from section k to k + 1
 * at some breakpoint points against the strip's mean chord, or against
 * the chord at the breakpoint before (the strip turns over between).
 */
static int
check_order(const struct skin *s, struct loft_error *err)
{
	int dim = s->dim;

	for (size_t k = 0; k < s->nstrip; k++) {
		double mean[LOFT_MAXDIM] = { 0 }, d[LOFT_MAXDIM];
		double prior[LOFT_MAXDIM] = { 0 };

		for (size_t j = 0; j < s->nodes; j++) {
			vsub(d, NODE(s, next(s, k), j), NODE(s, k, j), dim);
			vaxpy(mean, 1, d, dim);
		}
		for (size_t j = 0; j < s->nodes; j++) {
			double dot;

			vcopy(prior, d, dim);
			vsub(d, NODE(s, next(s, k), j), NODE(s, k, j), dim);
			dot = j > 0 ? same_way(d, prior, dim) : 1;
			if (!(same_way(d, mean, dim) > 0) || !(dot > 0))
				return loft_fail(err, LOFT_EGEOM, (long)next(s, k),
				    "section %zu crosses section %zu (at its "
				    "breakpoint %zu of %zu): the sections must "
				    "follow one another", next(s, k) + 1, k + 1,
				    j + 1, s->nodes);
		}
	}
	return 0;
}

/*
 * The curves across: loft_fit through the sections' points at each
 * breakpoint; the scale factors su (each strip's mean chord over the
 * mean of all); one cross derivative per knot, in the design's u: the
 * fit's direction, the mean of its two sides' magnitudes.
 */
static int
cross(const struct skin *s, const struct loft_skin_opts *o,
    struct loft_error *err)
{
	struct loft_fit_opts fo;
	size_t ns = s->ns;
	int dim = s->dim, rc = 0;
	double *p, *cs, wsum = 0;

	p = malloc(ns * dim * sizeof *p);
	cs = malloc(4 * dim * ns * sizeof *cs);
	if (p == NULL || cs == NULL) {
		free(p);
		free(cs);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	for (size_t k = 0; k < s->nstrip; k++) {
		double w = 0;

		for (size_t j = 0; j < s->nodes; j++)
			w += vdist(NODE(s, next(s, k), j), NODE(s, k, j), dim);
		s->su[k] = w / (double)s->nodes;
		wsum += s->su[k];
	}
	for (size_t k = 0; k < s->nstrip; k++)
		s->su[k] /= wsum / (double)s->nstrip;
	loft_fit_defaults(&fo);
	fo.closed = s->cl;
	fo.have_start = o->have_start;
	fo.have_end = o->have_end;
	vcopy(fo.start, o->start, dim);
	vcopy(fo.end, o->end, dim);
	for (size_t j = 0; j < s->nodes && rc == 0; j++) {
		for (size_t k = 0; k < ns; k++)
			vcopy(p + k * dim, NODE(s, k, j), dim);
		if ((rc = loft_fit(&fo, p, ns, dim, cs, NULL, err)) != 0) {
			char msg[sizeof err->msg];

			memcpy(msg, err->msg, sizeof msg);
			loft_fail(err, rc, err->row, "the curve across the "
			    "sections at their breakpoint %zu of %zu (the "
			    "knots are the sections): %s", j + 1, s->nodes, msg);
			break;
		}
		for (size_t k = 0; k < ns; k++) {
			/* leaving section k in strip k, arriving from k - 1
			 * (from ns - 1 when closed), where the strip is */
			size_t kl = k > 0 ? k - 1 : ns - 1;
			int hr = k < s->nstrip, hl = kl < s->nstrip;
			const double *ca = cs + 4 * dim * k + 2 * dim;
			const double *cb = cs + 4 * dim * kl + 3 * dim;
			double dir[LOFT_MAXDIM] = { 0 }, u[LOFT_MAXDIM], mag = 0;

			if (hr) {
				vcopy(u, ca, dim);
				mag += vunit(u, dim) / s->su[k];
				vaxpy(dir, 1, u, dim);
			}
			if (hl) {
				vcopy(u, cb, dim);
				mag += vunit(u, dim) / s->su[kl];
				vaxpy(dir, 1, u, dim);
			}
			vunit(dir, dim);
			vscale(TAN(s, k, j), mag / (hr + hl), dir, dim);
		}
	}
	free(p);
	free(cs);
	return rc;
}

/* Knot j of section k: rho = |A| / |B| of the tangents after and
 * before it where they are one direction, else 0 (a corner, or an end
 * of an open section). */
static void
ratios(const struct skin *s)
{
	int dim = s->dim;

	for (size_t k = 0; k < s->ns; k++)
		for (size_t j = 0; j < s->nodes; j++) {
			double *r = &s->rho[k * s->nodes + j];
			double a[LOFT_MAXDIM], b[LOFT_MAXDIM], ab, bb,
			    e[LOFT_MAXDIM], m;

			*r = 0;
			if (!s->cs && (j == 0 || j == s->nseg))
				continue;
			vcopy(a, SEG(s, k, j) + 2 * dim, dim);
			vcopy(b, SEG(s, k, j > 0 ? j - 1 : s->nseg - 1) + 3 * dim,
			    dim);
			/* both by one power of two, exactly: the products of
			 * sections of 1e+-160 over- or underflowed (issue 28) */
			m = fmax(vmaxabs(a, dim), vmaxabs(b, dim));
			if (m > 0 && m < INFINITY)
				for (int q = 0, x = ilogb(m); q < dim; q++) {
					a[q] = ldexp(a[q], -x);
					b[q] = ldexp(b[q], -x);
				}
			ab = vdot(a, b, dim);
			bb = vdot(b, b, dim);
			if (!(ab > 0 && bb > 0))
				continue;
			/* what of a is not along b */
			vcopy(e, a, dim);
			vaxpy(e, -ab / bb, b, dim);
			if (vnorm(e, dim) <= PARALLEL_REL * vnorm(a, dim))
				*r = ab / bb;
		}
}

static double
RHO(const struct skin *s, size_t k, size_t j)
{
	return s->rho[k * s->nodes + j % s->nodes];
}

/* Section k is an edge between two strips. */
static int
interior(const struct skin *s, size_t k)
{
	return s->cl || (k > 0 && k + 1 < s->ns);
}

static size_t
prev(const struct skin *s, size_t k)
{
	return k > 0 ? k - 1 : s->ns - 1;
}

/* The breakpoint edge at j in strip k is smooth: both its knots are. */
static int
vsmooth(const struct skin *s, size_t k, size_t j)
{
	return RHO(s, k, j) > 0 && RHO(s, next(s, k), j) > 0;
}

/* Segment j of section k is a cubic written as a quartic. */
static int
cubic_form(const struct skin *s, size_t k, size_t j)
{
	const double *q = SEG(s, k, j);
	int dim = s->dim;
	double ext = vdist(q, q + dim, dim), h[5 * LOFT_MAXDIM];

	ext = fmax(ext, fmax(vnorm(q + 2 * dim, dim), vnorm(q + 3 * dim, dim)));
	loft_cubic_to_quartic(q, dim, h);
	return vdist(h + 4 * dim, q + 4 * dim, dim) <= CUBIC_REL * ext;
}

/*
 * The c of section k's edges: where the corner at knot j has four
 * patches tied into a ring, c[j] + c[j - 1] = m[j] (see the top of the
 * file).  Runs of such knots are solved each with the smallest sum of
 * squares; a closed section tied at every knot (an odd count, by
 * refine) exactly.  A section with a segment of true quartic form has
 * no such term (c = 0): the corners' twists then cannot all agree.
 */
static void
solve_c(const struct skin *s, size_t k, double *m, int *eq)
{
	size_t n = s->nseg, nn = s->cs ? n : n + 1, start = 0;
	double *c = s->c + k * n, sig = s->su[k] / s->su[prev(s, k)];
	int all = 1;

	memset(c, 0, n * sizeof *c);
	for (size_t j = 0; j < n; j++)
		if (!cubic_form(s, k, j))
			return;
	for (size_t j = 0; j < nn; j++) {
		eq[j] = RHO(s, k, j) > 0 && vsmooth(s, prev(s, k), j) &&
		    vsmooth(s, k, j);
		if (eq[j]) {
			double d0 = RHO(s, next(s, k), j) - RHO(s, k, j);
			double d1 = RHO(s, k, j) - RHO(s, prev(s, k), j);

			m[j] = (d0 - sig * d1) / RHO(s, k, j);
		}
		all &= eq[j];
	}
	if (s->cs && all && n % 2 == 0)
		return;         /* refine makes n odd: not reached */
	if (s->cs && all) {
		/* c[j] = p + (-1)^j x from c[0] = x; knot 0 closes it */
		double p = 0;

		for (size_t j = 1; j < n; j++)
			p = m[j] - p;
		c[0] = (m[0] - p) / 2;
		for (size_t j = 1; j < n; j++)
			c[j] = m[j] - c[j - 1];
		return;
	}
	if (s->cs) {
		/* start after a knot with no condition */
		for (start = 0; start < nn && eq[start]; start++)
			;
		if (start == nn)
			start = 0;
	}
	for (size_t r = 0; r < nn; ) {
		size_t a = (start + r) % nn, len = 0, first;
		double sp = 0, x;

		if (!eq[a]) {
			r++;
			continue;
		}
		/* the run of knots a .. a + len - 1 ties segments a - 1 .. */
		while (r + len < nn && eq[(start + r + len) % nn])
			len++;
		first = (a + n - 1) % n;
		c[first] = 0;
		for (size_t i = 0; i < len; i++) {
			size_t jn = (a + i) % nn, sn = jn % n, sp0 = (jn + n - 1) % n;

			c[sn] = m[jn] - c[sp0];
			sp += (i % 2 == 0 ? -1 : 1) * c[sn];
		}
		/* c_i = p_i + s_i x, s alternating from +1 at first */
		x = -sp / (double)(len + 1);
		c[first] = x;
		for (size_t i = 0; i < len; i++) {
			size_t jn = (a + i) % nn, sn = jn % n, sp0 = (jn + n - 1) % n;

			c[sn] = m[jn] - c[sp0];
		}
		r += len;
	}
}

/* The relation q[b] = mul q[a] + add vec, used to find whichever of
 * q[a], q[b] is not known yet from the other. */
static void
tie(double *const *q, int *known, int a, int b, double mul, double add,
    const double *vec, int dim)
{
	if (known[a] && !known[b]) {
		vscale(q[b], mul, q[a], dim);
		vaxpy(q[b], add, vec, dim);
		known[b] = 1;
	} else if (known[b] && !known[a]) {
		vcopy(q[a], q[b], dim);
		vaxpy(q[a], -add, vec, dim);
		vscale(q[a], 1 / mul, q[a], dim);
		known[a] = 1;
	}
}

/*
 * The twists at knot j of section k, in the patches around it:
 * q[0] (k-1, j-1) at (1,1), q[1] (k, j-1) at (0,1), q[2] (k-1, j) at
 * (1,0), q[3] (k, j) at (0,0).  One is estimated (the change of the
 * cross derivative along the segment), the others follow by the
 * relations across the edges between them.
 */
static void
corner(const struct skin *s, size_t k, size_t j)
{
	int dim = s->dim, known[4] = { 0 }, have[4];
	size_t kk[4], jj[4];
	double *q[4];
	int ca[4] = { 1, 0, 1, 0 }, cb[4] = { 1, 1, 0, 0 };
	size_t n = s->nseg, jm = j > 0 ? j - 1 : n - 1;
	int left = s->cl || k > 0, right = s->cl || k + 1 < s->ns;
	int below = s->cs || j > 0, above = s->cs || j < n;
	double sig = 0, rho = RHO(s, k, j);
	const double *a = NULL, *bv = NULL;

	have[0] = left && below;
	have[1] = right && below;
	have[2] = left && above;
	have[3] = right && above;
	for (int i = 0; i < 4; i++) {
		kk[i] = ca[i] ? prev(s, k) : k;
		jj[i] = cb[i] ? jm : j % n;
		q[i] = have[i] ? TW(s, kk[i], jj[i], ca[i], cb[i]) : NULL;
	}
	if (left && right)
		sig = s->su[k] / s->su[prev(s, k)];
	if (below)
		bv = SEG(s, k, jm) + 3 * dim;
	if (above)
		a = SEG(s, k, j % n) + 2 * dim;
	for (int pass = 0; pass < 4; pass++) {
		int start = -1;

		for (int i = 0; i < 4 && start < 0; i++)
			if (have[i] && !known[i])
				start = i;
		if (start < 0)
			break;
		{
			size_t t = kk[start], sj = jj[start];
			int ea = ca[start];

			vsub(q[start], TAN(s, t + ea == s->ns ? 0 : t + ea,
			    sj + 1), TAN(s, t + ea == s->ns ? 0 : t + ea, sj), dim);
			vscale(q[start], s->su[t], q[start], dim);
		}
		known[start] = 1;
		for (int round = 0; round < 4; round++) {
			/* R1: q1 = sig q0 - c[k][j-1] B; R2: q3 = sig q2 + c[k][j] A;
			 * R3: q2 = d(k-1) B + rho q0; R4: q3 = d(k) B + rho q1 */
			int r1 = have[0] && have[1], r2 = have[2] && have[3];
			int r3 = have[0] && have[2] && vsmooth(s, prev(s, k), j);
			int r4 = have[1] && have[3] && vsmooth(s, k, j);
			double c1 = r1 ? s->c[k * n + jm] : 0;
			double c2 = r2 ? s->c[k * n + j % n] : 0;
			double d3 = r3 ? rho - RHO(s, prev(s, k), j) : 0;
			double d4 = r4 ? RHO(s, next(s, k), j) - rho : 0;

			if (r1)
				tie(q, known, 0, 1, sig, -c1, bv, dim);
			if (r3)
				tie(q, known, 0, 2, rho, d3, bv, dim);
			if (r2)
				tie(q, known, 2, 3, sig, c2, a, dim);
			if (r4)
				tie(q, known, 1, 3, rho, d4, bv, dim);
		}
	}
}

/* The cubic's (h) of a quartic row or column x0 x1 d0 d1: its point at
 * 1/2, (x0 + x1) / 2 + (d0 - d1) / 8. */
static void
cubic_mid(const double *x0, const double *x1, const double *d0,
    const double *d1, int dim, double *h)
{
	for (int c = 0; c < dim; c++)
		h[c] = (x0[c] + x1[c]) / 2 + (d0[c] - d1[c]) / 8;
}

/* Everything of patch (k, j) but (0h)_u, (h0)_v and (hh). */
static void
fill(const struct skin *s, size_t k, size_t j)
{
	int dim = s->dim;
	size_t k1 = next(s, k);
	double *b = PATCH(s, k, j);

	memcpy(BIJ(b, 0, 0, dim), SEG(s, k, j), 5 * dim * sizeof *b);
	memcpy(BIJ(b, 1, 0, dim), SEG(s, k1, j), 5 * dim * sizeof *b);
	for (int e = 0; e < 2; e++) {
		vscale(BIJ(b, 2, e, dim), s->su[k], TAN(s, k, j + e), dim);
		vscale(BIJ(b, 3, e, dim), s->su[k], TAN(s, k1, j + e), dim);
		cubic_mid(BIJ(b, 0, e, dim), BIJ(b, 1, e, dim),
		    BIJ(b, 2, e, dim), BIJ(b, 3, e, dim), dim,
		    BIJ(b, 4, e, dim));
	}
	for (int a = 0; a < 2; a++)
		for (int e = 0; e < 2; e++)
			vcopy(BIJ(b, 2 + a, 2 + e, dim), TW(s, k, j, a, e), dim);
	/* (1h)_u and (h1)_v: row 3 and column 3 cubic */
	cubic_mid(BIJ(b, 3, 0, dim), BIJ(b, 3, 1, dim), BIJ(b, 3, 2, dim),
	    BIJ(b, 3, 3, dim), dim, BIJ(b, 3, 4, dim));
	cubic_mid(BIJ(b, 0, 3, dim), BIJ(b, 1, 3, dim), BIJ(b, 2, 3, dim),
	    BIJ(b, 3, 3, dim), dim, BIJ(b, 4, 3, dim));
}

/* (0h)_u, (h0)_v and (hh) of patch (k, j), from its neighbours below
 * and to the left where the relations tie them. */
static void
finish(const struct skin *s, size_t k, size_t j)
{
	int dim = s->dim;
	size_t n = s->nseg;
	double *b = PATCH(s, k, j);

	if (interior(s, k)) {
		const double *l = PATCH(s, prev(s, k), j);
		double d[LOFT_MAXDIM], sig = s->su[k] / s->su[prev(s, k)];

		loft_quartic_eval(SEG(s, k, j), dim, 0.5, NULL, d, NULL);
		vscale(BIJ(b, 2, 4, dim), sig, BIJ(l, 3, 4, dim), dim);
		vaxpy(BIJ(b, 2, 4, dim), s->c[k * n + j] / 4, d, dim);
	} else {
		cubic_mid(BIJ(b, 2, 0, dim), BIJ(b, 2, 1, dim),
		    BIJ(b, 2, 2, dim), BIJ(b, 2, 3, dim), dim,
		    BIJ(b, 2, 4, dim));
	}
	if ((s->cs || j > 0) && vsmooth(s, k, j)) {
		const double *l = PATCH(s, k, j > 0 ? j - 1 : n - 1);

		vscale(BIJ(b, 4, 2, dim), (RHO(s, k, j) +
		    RHO(s, next(s, k), j)) / 2, BIJ(l, 4, 3, dim), dim);
	} else {
		cubic_mid(BIJ(b, 0, 2, dim), BIJ(b, 1, 2, dim),
		    BIJ(b, 2, 2, dim), BIJ(b, 3, 2, dim), dim,
		    BIJ(b, 4, 2, dim));
	}
	cubic_mid(BIJ(b, 0, 4, dim), BIJ(b, 1, 4, dim), BIJ(b, 2, 4, dim),
	    BIJ(b, 3, 4, dim), dim, BIJ(b, 4, 4, dim));
}

static void
skin_free(struct skin *s)
{
	free(s->seg);
	free(s->t);
	free(s->rho);
	free(s->su);
	free(s->c);
	free(s->tw);
	free(s->b);
}

/* Check section k against the first: curve type, dimension, open or
 * closed. */
static int
check_section(const struct loft_curve *sec, size_t k, struct loft_error *err)
{
	if (sec[k].quartic == NULL)
		return loft_fail(err, LOFT_EINPUT, (long)k, "a %s record: "
		    "a section is a cubic or quartic curve", sec[k].type);
	if (sec[k].npieces == 0)
		return loft_fail(err, LOFT_EINPUT, (long)k, "section %zu "
		    "has no segment", k + 1);
	if (sec[k].dim != sec[0].dim)
		return loft_fail(err, LOFT_EINPUT, (long)k, "section %zu "
		    "has %d coordinates, section 1 %d", k + 1,
		    sec[k].dim, sec[0].dim);
	if (sec[k].closed != sec[0].closed)
		return loft_fail(err, LOFT_EINPUT, (long)k, "section %zu "
		    "is %s, section 1 %s: sections are all open or all "
		    "closed", k + 1, sec[k].closed ? "closed" : "open",
		    sec[0].closed ? "closed" : "open");
	return 0;
}

/* Check the sections, each (check_section), then their count. */
static int
check_sections(const struct loft_skin_opts *o, const struct loft_curve *sec,
    size_t ns, struct loft_error *err)
{
	size_t need = o->closed ? LOFT_MIN_CLOSED : LOFT_MIN_OPEN;
	int rc;

	for (size_t k = 0; k < ns; k++)
		if ((rc = check_section(sec, k, err)) != 0)
			return rc;
	if (ns < need)
		return loft_fail(err, LOFT_EINPUT, ns > 0 ? 0 : -1, "%zu "
		    "section%s: a%s loft needs at least %zu", ns,
		    ns == 1 ? "" : "s", o->closed ? " closed" : "n open", need);
	return 0;
}

int
loft_skin(const struct loft_skin_opts *o, const struct loft_curve *sec,
    size_t ns, struct loft_skin_result *out, struct loft_error *err)
{
	struct skin s;
	double *m = NULL, *t;
	int *eq = NULL, rc;
	size_t nbreak;

	memset(out, 0, sizeof *out);
	memset(&s, 0, sizeof s);
	if ((rc = check_sections(o, sec, ns, err)) != 0)
		return rc;
	s.dim = sec[0].dim;
	s.cs = sec[0].closed;
	s.cl = o->closed;
	s.ns = ns;
	s.nstrip = s.cl ? ns : ns - 1;
	if ((t = breakpoints(sec, ns, s.cs, &nbreak)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (nbreak < 2) {       /* never: each section has 0 and 1 */
		free(t);
		return loft_fail(err, LOFT_EINPUT, -1, "no segment to loft");
	}
	/* the helpers below take the skin const, so that what is set here
	 * stays plainly set; they fill the arrays */
	s.nseg = nbreak - 1;
	s.nodes = s.cs ? s.nseg : s.nseg + 1;
	s.seg = malloc(ns * s.nseg * 5 * s.dim * sizeof *s.seg);
	s.su = malloc(s.nstrip * sizeof *s.su);
	s.t = malloc(ns * s.nodes * s.dim * sizeof *s.t);
	if (s.seg == NULL || s.su == NULL || s.t == NULL) {
		free(t);
		skin_free(&s);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	refine(&s, sec, t);
	free(t);
	if ((rc = check_order(&s, err)) != 0 || (rc = cross(&s, o, err)) != 0) {
		skin_free(&s);
		return rc;
	}
	s.rho = malloc(ns * s.nodes * sizeof *s.rho);
	s.c = calloc(ns * s.nseg, sizeof *s.c);
	s.tw = malloc(s.nstrip * s.nseg * 4 * s.dim * sizeof *s.tw);
	s.b = malloc(s.nstrip * s.nseg * 25 * s.dim * sizeof *s.b);
	m = malloc((s.nseg + 1) * sizeof *m);
	eq = malloc((s.nseg + 1) * sizeof *eq);
	if (s.rho == NULL || s.c == NULL || s.tw == NULL || s.b == NULL ||
	    m == NULL || eq == NULL) {
		skin_free(&s);
		free(m);
		free(eq);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	ratios(&s);
	for (size_t k = 0; k < s.ns; k++)
		if (interior(&s, k))
			solve_c(&s, k, m, eq);
	free(m);
	free(eq);
	for (size_t k = 0; k < s.ns; k++)
		for (size_t j = 0; j <= s.nseg; j++)
			if (j < s.nseg || !s.cs)
				corner(&s, k, j);
	for (size_t k = 0; k < s.nstrip; k++)
		for (size_t j = 0; j < s.nseg; j++)
			fill(&s, k, j);
	for (size_t k = 0; k < s.nstrip; k++)
		for (size_t j = 0; j < s.nseg; j++)
			finish(&s, k, j);
	out->dim = s.dim;
	out->nu = s.nstrip;
	out->nv = s.nseg;
	out->closed_u = s.cl;
	out->closed_v = s.cs;
	out->b = s.b;
	out->su = s.su;
	s.b = NULL;
	s.su = NULL;
	skin_free(&s);
	return 0;
}

void
loft_skin_free(struct loft_skin_result *r)
{
	free(r->b);
	free(r->su);
	memset(r, 0, sizeof *r);
}

/* A link list of one neighbour, the whole edge, the same way. */
static int
link_one(struct loft_patch *p, int e, long id)
{
	if ((p->link[e] = malloc(sizeof *p->link[e])) == NULL)
		return LOFT_ENOMEM;
	p->link[e][0].id = id;
	p->link[e][0].a = 0;
	p->link[e][0].b = 1;
	p->nlink[e] = p->linkcap[e] = 1;
	return 0;
}

int
loft_skin_design(const struct loft_skin_result *r, struct loft_design *d,
    struct loft_error *err)
{
	size_t nu = r->nu, nv = r->nv;

	if (nu * nv > (size_t)1000000000)
		return loft_fail(err, LOFT_EINPUT, -1, "%zu patches: more "
		    "than ids can name", nu * nv);
	for (size_t k = 0; k < nu; k++)
		for (size_t j = 0; j < nv; j++) {
			long id = (long)(k * nv + j + 1);
			struct loft_patch *p;
			/* neighbours u0 u1 v0 v1, or 0 */
			long nb[4] = { 0, 0, 0, 0 };

			if (loft_design_new(d, r->b + (k * nv + j) * 25 * r->dim,
			    r->dim, id, err) != 0)
				return LOFT_ENOMEM;
			p = &d->p[d->n - 1];
			p->scale[0] = r->su[k];
			if (k > 0 || (r->closed_u && nu > 1))
				nb[0] = (long)((k > 0 ? k - 1 : nu - 1) * nv + j + 1);
			if (k + 1 < nu || (r->closed_u && nu > 1))
				nb[1] = (long)((k + 1 < nu ? k + 1 : 0) * nv + j + 1);
			if (j > 0 || (r->closed_v && nv > 1))
				nb[2] = (long)(k * nv + (j > 0 ? j - 1 : nv - 1) + 1);
			if (j + 1 < nv || (r->closed_v && nv > 1))
				nb[3] = (long)(k * nv + (j + 1 < nv ? j + 1 : 0) + 1);
			/* a ring of two names one neighbour across both edges:
			 * loft.5 allows a neighbour once; keep the first */
			if (nb[0] != 0 && nb[0] == nb[1])
				nb[1] = 0;
			if (nb[2] != 0 && nb[2] == nb[3])
				nb[3] = 0;
			for (int e = 0; e < 4; e++)
				if (nb[e] != 0 && link_one(p, e, nb[e]) != 0)
					return loft_fail(err, LOFT_ENOMEM, -1,
					    "out of memory");
		}
	return 0;
}
