/*
 * fit.c: a spline through knots, continuous in tangent direction and in
 * the curvature vector, with normalised tangent magnitudes (Manning 1973,
 * sections 5, 6 and 9), and loft_fit, which hands the other methods to
 * cspline.c and fair.c.  The checks of the knots and the end tangents
 * every method shares are knots.c's, so no method calls back into fit.c.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

void
loft_fit_defaults(struct loft_fit_opts *o)
{
	memset(o, 0, sizeof *o);
	o->method = LOFT_FAIR;
	o->sign = LOFT_SIGN_POSITIVE;
	o->alpha = 2.0 / 3;
	o->tol = 1e-12;
	o->maxiter = 1000;
	o->closed = 1;
}

struct manning {
	const double *p;
	size_t n;               /* knots */
	size_t nseg;
	int dim, closed;
	double alpha;
	double *t;              /* unit tangents, n * dim */
	double *tnew;           /* the next sweep's, for Jacobi sweeps */
	double *u, *w;          /* unit chord of segment i, nseg * dim; length */
	double *r, *l;          /* r[i]: |P'| leaving knot i; l[i]: arriving */
};

static const double *
knot(const struct manning *m, size_t i)
{
	return m->p + (i % m->n) * m->dim;
}

/* The chords' directions and lengths, once: the iteration needs no
 * square root but the one that scales each new tangent. */
static void
chords(struct manning *m)
{
	int dim = m->dim;

	for (size_t i = 0; i < m->nseg; i++) {
		double *u = m->u + i * dim;

		vsub(u, knot(m, i + 1), knot(m, i), dim);
		m->w[i] = vunit(u, dim);
	}
}

/*
 * Step 1 of section 6: T_i parallel to P_{i+1} - P_{i-1}.  (The tangent
 * of the circle through P_{i-1}, P_i, P_{i+1} starts nearer, but saves
 * few sweeps, and on the knots of Fig. 15 leads to the other of the two
 * solutions; the paper's start is kept.)
 */
static int
initial_tangents(struct manning *m, struct loft_error *err)
{
	int dim = m->dim;
	size_t lo = m->closed ? 0 : 1, hi = m->closed ? m->n : m->n - 1;

	for (size_t i = lo; i < hi; i++) {
		double *t = m->t + i * dim;
		size_t h = (i + m->n - 1) % m->n, j = (i + 1) % m->n;

		vsub(t, knot(m, j), knot(m, h), dim);
		if (!(vunit(t, dim) > 0))
			return loft_fail(err, LOFT_EGEOM, (long)i,
			    "knots %zu and %zu on either side of knot %zu "
			    "coincide: the curve would double back on itself",
			    h + 1, j + 1, i + 1);
	}
	return 0;
}

/* Step 2: the magnitudes r_i and l_{i+1} of eq. 11 for segment i. */
static int
segment_magnitudes(struct manning *m, size_t i, struct loft_error *err)
{
	int dim = m->dim;
	size_t j = (i + 1) % m->n;
	const double *u = m->u + i * dim;

	if (loft__normalise_cos(m->w[i], vdot(m->t + i * dim, u, dim),
	    vdot(m->t + j * dim, u, dim), m->alpha, &m->r[i], &m->l[j]) != 0)
		return loft_fail(err, LOFT_EGEOM, (long)j,
		    "tangents at knots %zu and %zu both turn back along "
		    "the chord between them", i + 1, j + 1);
	return 0;
}

static int
magnitudes(struct manning *m, struct loft_error *err)
{
	for (size_t i = 0; i < m->nseg; i++)
		if (segment_magnitudes(m, i, err) != 0)
			return LOFT_EGEOM;
	return 0;
}

/*
 * Step 3: the right-hand side of eq. 10 at knot i,
 *   K_i T_i = 3{r_i^2 (P_i - P_{i-1}) + l_i^2 (P_{i+1} - P_i)}
 *             - r_{i-1} r_i^2 T_{i-1} - l_i^2 l_{i+1} T_{i+1},
 * scaled to a unit vector with the sign of K_i the rule asks for, and
 * stored as the new T_i in out.  The chords are w u.  Returns the squared
 * change |T~_i - T_i|^2, or -1 where the side vanishes.
 */
static double
new_tangent(struct manning *m, size_t i, enum loft_sign sign, double *out)
{
	int dim = m->dim;
	size_t h = (i + m->n - 1) % m->n, j = (i + 1) % m->n;
	double v[LOFT_MAXDIM], d[LOFT_MAXDIM];
	const double *t = m->t + i * dim;
	double ri = m->r[i], li = m->l[i];

	vscale(v, 3 * ri * ri * m->w[h], m->u + h * dim, dim);
	vaxpy(v, 3 * li * li * m->w[i], m->u + i * dim, dim);
	vaxpy(v, -m->r[h] * ri * ri, m->t + h * dim, dim);
	vaxpy(v, -li * li * m->l[j], m->t + j * dim, dim);
	if (!(vunit(v, dim) > 0))
		return -1;
	if (sign == LOFT_SIGN_TURN && vdot(v, t, dim) < 0)
		vscale(v, -1, v, dim);
	vsub(d, v, t, dim);
	vcopy(out, v, dim);
	return vdot(d, d, dim);
}

/*
 * Steps 2 to 5: iterate to the solution of eq. 10 and 11.  The paper
 * makes each sweep from the tangents of the last (Jacobi).  Under the
 * positive rule we sweep Gauss-Seidel instead: each knot from its
 * neighbour's new tangent and the magnitudes that follow from it.  The
 * solution, where no tangent moves, is the same, reached in about two
 * thirds of the sweeps.  The turn rule picks one of several solutions by
 * the path the iteration takes (section 8), so it keeps the paper's.
 */
static int
iterate(struct manning *m, const struct loft_fit_opts *o,
    struct loft_fit_info *info, struct loft_error *err)
{
	size_t lo = m->closed ? 0 : 1, hi = m->closed ? m->n : m->n - 1;
	int seidel = o->sign == LOFT_SIGN_POSITIVE, dim = m->dim, it = 0;
	double change = 0;

	for (;;) {
		double most = 0;
		int done = lo >= hi || (it > 0 && change < o->tol);

		/* a Gauss-Seidel sweep brings the magnitudes up to date as it
		 * goes: the segment behind each knot, and the last */
		if ((!seidel || it == 0 || done) && magnitudes(m, err) != 0)
			return LOFT_EGEOM;
		if (done)
			break;
		if (it == o->maxiter) {
			info->iterations = it;
			info->change = change;
			return loft_fail(err, LOFT_ENOCONV, -1,
			    "no convergence in %d iterations: tangents still "
			    "move by %.3g", it, change);
		}
		for (size_t i = lo; i < hi; i++) {
			double c;

			if (seidel && segment_magnitudes(m, (i + m->n - 1) %
			    m->n, err) != 0)
				return LOFT_EGEOM;
			c = new_tangent(m, i, o->sign,
			    (seidel ? m->t : m->tnew) + i * dim);
			if (c < 0)
				return loft_fail(err, LOFT_EGEOM, (long)i,
				    "eq. 10 gives no tangent at knot %zu", i + 1);
			if (c > most)
				most = c;
		}
		if (!seidel)
			memcpy(m->t + lo * dim, m->tnew + lo * dim,
			    (hi - lo) * dim * sizeof *m->t);
		else if (!m->closed && segment_magnitudes(m, hi - 1, err) != 0)
			return LOFT_EGEOM;
		change = sqrt(most);
		it++;
	}
	info->iterations = it;
	info->change = change;
	info->converged = 1;
	return 0;
}

static void
write_segments(const struct manning *m, double *seg)
{
	int dim = m->dim;

	for (size_t i = 0; i < m->nseg; i++) {
		size_t j = (i + 1) % m->n;
		double *s = seg + i * 4 * dim;

		vcopy(s, knot(m, i), dim);
		vcopy(s + dim, knot(m, j), dim);
		vscale(s + 2 * dim, m->r[i], m->t + i * dim, dim);
		vscale(s + 3 * dim, m->l[j], m->t + j * dim, dim);
	}
}

int
loft__fit_manning(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	struct manning m = { p, n, o->closed ? n : n - 1, dim, o->closed,
	    o->alpha, NULL, NULL, NULL, NULL, NULL, NULL };
	double *mem = malloc((3 * n * dim + 3 * n) * sizeof *mem);
	int rc;

	if (mem == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	m.t = mem;
	m.tnew = m.t + n * dim;
	m.u = m.tnew + n * dim;
	m.w = m.u + n * dim;
	m.r = m.w + n;
	m.l = m.r + n;
	chords(&m);
	rc = initial_tangents(&m, err);
	if (rc == 0 && !o->closed)
		rc = loft__open_ends(o, p, n, dim, m.t, m.t + (n - 1) * dim,
		    err);
	if (rc == 0)
		rc = iterate(&m, o, info, err);
	if (rc == 0)
		write_segments(&m, seg);
	free(mem);
	return rc;
}

/*
 * Scale the knots p into q, inside the box [-1, 1]^dim, so that every
 * length in the fit is of order one whatever the units: eq. 10 holds
 * lengths cubed, which would overflow for knots near 1e100 and underflow
 * near 1e-100.  The factor is a power of two, so q = p / 2^e exactly and
 * the fit is made for exactly the knots it writes.  Returns e.
 */
static int
unit_box(const double *p, size_t n, int dim, double *q)
{
	int e = 0;

	if (unit_exponent(p, n, dim, &e) == 0)
		e++;            /* into [0.5, 1), as frexp's */
	for (size_t i = 0; i < n * dim; i++)
		q[i] = ldexp(p[i], -e);
	return e;
}

/* One curve without corners, by o->method, of knots already scaled: a
 * lone span beside a straight run met G2 (loft__flat_join) by every
 * method but Manning's, the chord spline there being that curve too. */
static int
fit_method(const struct loft_fit_opts *o, const double *q, size_t n, int dim,
    double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	if (o->method == LOFT_MANNING)
		return loft__fit_manning(o, q, n, dim, seg, info, err);
	if (loft__flat_join(o, q, n, dim, seg) == 0) {
		info->converged = 1;
		return 0;
	}
	if (o->method == LOFT_FAIR)
		return loft__fit_fair(o, q, n, dim, seg, info, err);
	info->converged = 1;
	return loft__fit_cspline(o, q, n, dim, seg, err);
}

/* Whether k is one of the n numbers a. */
static int
listed(const size_t *a, size_t n, size_t k)
{
	for (size_t j = 0; j < n; j++)
		if (a[j] == k)
			return 1;
	return 0;
}

/* Whether span s (knot s to s + 1) is one of o's straight ones. */
static int
is_straight(const struct loft_fit_opts *o, size_t s)
{
	return listed(o->straight, o->nstraight, s);
}

/* Whether knot k is one of o's corners. */
static int
is_corner(const struct loft_fit_opts *o, size_t k)
{
	return listed(o->corner, o->ncorner, k);
}

/*
 * The knots a curve breaks at, increasing, into brk; their count: the
 * corners and the ends of the straight spans (not an open curve's end).
 */
static size_t
break_knots(const struct loft_fit_opts *o, size_t n, size_t *brk)
{
	size_t nb = 0;

	for (size_t i = 0; i < n; i++) {
		int at = is_straight(o, i) || (i > 0 && is_straight(o, i - 1)) ||
		    (o->closed && i == 0 && is_straight(o, n - 1)) ||
		    is_corner(o, i);
		if (at && (o->closed || (i > 0 && i + 1 < n) ||
		    o->ncorner > 0))
			brk[nb++] = i;
	}
	return nb;
}

/* The unit direction of span s into t. */
static void
span_direction(const double *q, size_t n, int dim, size_t s, double *t)
{
	vsub(t, q + ((s + 1) % n) * dim, q + (s % n) * dim, dim);
	vunit(t, dim);
}

/*
 * A curve with corners or straight spans: each piece between the knots
 * it breaks at, and on an open curve from an end to its nearest break,
 * an open curve of its own, whose end tangent beside a straight span is
 * the span's direction.  The piece from break a to the next, b, covers
 * segments a .. b-1 (mod n on a closed curve, where one break makes one
 * piece all the way round); a straight span is a piece of its own.
 */
static int
fit_pieces(const struct loft_fit_opts *o, const double *q, size_t n, int dim,
    double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	double *pk = malloc((n + 1) * (size_t)dim * 5 * sizeof *pk), *ps;
	size_t *brk = malloc(n * sizeof *brk), nc, npiece;
	int rc = 0;

	if (pk == NULL || brk == NULL) {
		free(pk);
		free(brk);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	nc = break_knots(o, n, brk);
	npiece = o->closed ? nc : nc + 1;
	ps = pk + (n + 1) * dim;
	for (size_t k = 0; rc == 0 && k < npiece; k++) {
		struct loft_fit_opts po = *o;
		struct loft_fit_info pi = { 0 };
		size_t a, b, len;

		if (o->closed) {
			a = brk[k];
			b = k + 1 < nc ? brk[k + 1] : brk[0] + n;
		} else {
			a = k == 0 ? 0 : brk[k - 1];
			b = k < nc ? brk[k] : n - 1;
		}
		len = b - a + 1;        /* breaks increase */
		if (len < 2)            /* a corner at an end of an open curve */
			continue;
		for (size_t i = 0; i < len; i++)
			vcopy(pk + i * dim, q + ((a + i) % n) * dim, dim);
		po.closed = 0;
		po.split = 0;
		po.ncorner = 0;
		po.nstraight = 0;
		po.have_start = !o->closed && k == 0 && o->have_start;
		po.have_end = !o->closed && k + 1 == npiece && o->have_end;
		po.flat_start = po.have_start && o->flat_start;
		po.flat_end = po.have_end && o->flat_end;
		if (len == 2 && is_straight(o, a % n)) {
			double *s = ps;

			vcopy(s, pk, dim);
			vcopy(s + dim, pk + dim, dim);
			vsub(s + 2 * dim, pk + dim, pk, dim);
			vcopy(s + 3 * dim, s + 2 * dim, dim);
		} else {
			/* a straight neighbour gives its direction, but not
			 * across a corner */
			if ((o->closed || a > 0) && is_straight(o, (a + n - 1) %
			    n) && !is_corner(o, a % n)) {
				po.have_start = po.flat_start = 1;
				span_direction(q, n, dim, a + n - 1, po.start);
			}
			if ((o->closed || b + 1 < n) && is_straight(o, b % n) &&
			    !is_corner(o, b % n)) {
				po.have_end = po.flat_end = 1;
				span_direction(q, n, dim, b, po.end);
			}
			rc = fit_method(&po, pk, len, dim, ps, &pi, err);
		}
		if (rc != 0 && err->row >= 0)
			err->row = (long)((a + (size_t)err->row) % n);
		info->iterations += pi.iterations;
		info->change = fmax(info->change, pi.change);
		for (size_t i = 0; rc == 0 && i + 1 < len; i++)
			memcpy(seg + ((a + i) % n) * 4 * dim, ps + i * 4 * dim,
			    4 * dim * sizeof *seg);
	}
	info->converged = rc == 0;
	free(pk);
	free(brk);
	return rc;
}

/*
 * fit_pieces, and where the default's pieces of a plane curve cross
 * one another (none crosses itself: fair.c's uncross sees to that),
 * fitted again with o->untangle, each piece the centripetal start's
 * curve where that passes fair.c's checks; that curve is written where
 * it does not cross itself.  (EB Garamond Italic's m and n: the sides
 * of a stem, in pieces of their own between straight runs, bulged
 * across each other.)  Not for splinefit -e's trial fits (o->quick).
 */
static int
fit_untangled(const struct loft_fit_opts *o, const double *q, size_t n,
    int dim, double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	size_t nseg = o->closed ? n : n - 1;
	struct loft_fit_opts uo = *o;
	struct loft_fit_info ui = { 0 };
	struct loft_error ue;
	double *alt;
	int rc = fit_pieces(o, q, n, dim, seg, info, err), x;

	if (rc != 0 || o->method != LOFT_FAIR || o->quick || o->untangle ||
	    dim != 2 || (x = loft_fit_crosses(seg, nseg, o->closed)) == 0)
		return rc;
	if (x < 0 || (alt = malloc(4 * dim * n * sizeof *alt)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	uo.untangle = 1;
	x = fit_pieces(&uo, q, n, dim, alt, &ui, &ue) == 0 ?
	    loft_fit_crosses(alt, nseg, o->closed) : 1;
	if (x == 0)
		memcpy(seg, alt, 4 * dim * nseg * sizeof *seg);
	free(alt);
	return x < 0 ? loft_fail(err, LOFT_ENOMEM, -1, "out of memory") : 0;
}

int
loft_fit(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    double *seg, struct loft_fit_info *info, struct loft_error *err)
{
	struct loft_fit_info dummy;
	double *q;
	size_t nseg = o->closed ? n : n - 1;
	int rc, e;

	if (info == NULL)
		info = &dummy;
	memset(info, 0, sizeof *info);
	info->nseg = nseg;
	if (dim < 2 || dim > LOFT_MAXDIM || n == 0)
		return loft__check_knots(o, p, n, dim, err);
	if ((q = malloc(n * dim * sizeof *q)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	e = unit_box(p, n, dim, q);
	rc = loft__check_knots(o, q, n, dim, err);
	if (rc == 0 && (o->ncorner > 0 || o->nstraight > 0))
		rc = fit_untangled(o, q, n, dim, seg, info, err);
	else if (rc == 0)
		rc = fit_method(o, q, n, dim, seg, info, err);
	free(q);
	/* back to the knots' own units, exactly */
	for (size_t i = 0; rc == 0 && i < info->nseg * 4 * dim; i++)
		seg[i] = ldexp(seg[i], e);
	return rc;
}

/* ------------------------------------------------------------------ */
/* Measures of a fit */

/* The largest distance of a knot of the segments from the first knot. */
static double
segment_extent(const double *seg, size_t nseg, int dim)
{
	double big = 0;

	for (size_t i = 0; i < nseg; i++)
		big = fmax(big, vdist(seg + i * 4 * dim + dim, seg, dim));
	return big;
}

double
loft_curvature_jump(const double *seg, size_t nseg, int dim, int closed)
{
	double jump = 0, big = 0;

	for (size_t i = 0; i < nseg; i++) {
		const double *a = seg + i * 4 * dim;
		double d1[LOFT_MAXDIM], d2[LOFT_MAXDIM], ka[LOFT_MAXDIM],
		    kb[LOFT_MAXDIM];

		loft_cubic_eval(a, dim, 0, NULL, d1, d2);
		if (loft_curvature_vector(d1, d2, dim, ka) == 0 &&
		    vnorm(ka, dim) > big)
			big = vnorm(ka, dim);
		if (i + 1 == nseg && !closed)
			break;
		/* the end of this segment against the start of the next */
		loft_cubic_eval(a, dim, 1, NULL, d1, d2);
		if (loft_curvature_vector(d1, d2, dim, ka) != 0)
			continue;
		if (vnorm(ka, dim) > big)
			big = vnorm(ka, dim);
		loft_cubic_eval(seg + ((i + 1) % nseg) * 4 * dim, dim, 0,
		    NULL, d1, d2);
		if (loft_curvature_vector(d1, d2, dim, kb) == 0 &&
		    vdist(ka, kb, dim) > jump)
			jump = vdist(ka, kb, dim);
	}
	/* a curve no more curved than a circle its own size is measured
	 * against that circle, so rounding on a straight line reads 0 */
	big = fmax(big, 1 / segment_extent(seg, nseg, dim));
	return big > 0 && isfinite(big) ? jump / big : 0;
}

double
loft_tangent_distance(const double *a, const double *b, size_t nseg, int dim)
{
	double most = 0;

	for (size_t i = 0; i < nseg; i++) {
		for (int end = 2; end <= 3; end++) {
			double ta[LOFT_MAXDIM], tb[LOFT_MAXDIM];

			vcopy(ta, a + (4 * i + end) * dim, dim);
			vcopy(tb, b + (4 * i + end) * dim, dim);
			vunit(ta, dim);
			vunit(tb, dim);
			if (vdist(ta, tb, dim) > most)
				most = vdist(ta, tb, dim);
		}
	}
	return most;
}
