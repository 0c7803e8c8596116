/*
 * approx.c: a fair curve near noisy points (splinefit -e).  The points
 * are samples of an outline, in order along it; the curve is the fair
 * spline of fair.c (least bending energy over the G2 cubics) through a
 * few knots that are not the points but are placed so that every point
 * is within the tolerance of the curve.
 *
 * The knots start few (APPROX_START_SPANS spans, evenly along a moving
 * average of the points) and are then, in rounds:
 *   - moved (corrected): the curve is fitted through them, each point is
 *     projected onto it (its foot), and each knot moves by the mean of
 *     the residuals (point minus foot) of the points on its two spans,
 *     weighted by the hat function of the spans (1 at the knot, 0 at its
 *     neighbours).  A knot moved so is where the residuals near it
 *     balance: the condition of least squares for a curve that follows
 *     its knots locally, which a fair spline does.  A few sweeps settle
 *     it; the noise averages out over the points of two spans;
 *   - split: every span with a point farther than the tolerance gets a
 *     knot at its middle (on the curve, so the curve hardly changes),
 *     and the sweeps begin again.
 * Once every point is within the tolerance, each knot in turn is tried
 * without (remove_knots): it goes where the points near it stay within
 * the tolerance and their squared distances grow by no more than noise
 * would (APPROX_NEED); then each wiggle, a short stretch of curvature
 * of the other sign between two inflexions (APPROX_WIGGLE), loses a
 * knot that holds it where the points allow (straighten).  A wiggle
 * still left, where the points leave no room for fewer knots, is
 * faired: the knots near it move, by damped least squares, to where the
 * points fit best with the curvature there of the sign round it
 * (fair_wiggles).  So the knots are as few as the points show a need
 * of, each the balance of many points, and an inflexion is kept only
 * where the points ask.  Everything is relative to the
 * spans and the tolerance: nothing depends on the units.  A closed
 * outline is started at its lexicographically least point (or its
 * first corner), which is the same point wherever the input starts.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* Spans to start with, over the whole outline: an ellipse needs about
 * this many, an insole a few more; fewer would make the first feet of
 * the points too coarse. */
#define APPROX_START_SPANS 8

/* The moving average that gives the points' first parameter (their
 * distance along it) and the first knots spans this fraction of the
 * points either side: enough to calm the noise, little enough not to
 * cut a corner of the outline by more than a correction undoes. */
#define APPROX_SMOOTH 0.01

/* Correction sweeps at most per round, and a round's sweeps stop once
 * no knot moves more than APPROX_SETTLED of the tolerance. */
#define APPROX_SWEEPS 12
#define APPROX_SETTLED 1e-3

/* A span is split only where at least this many points lie on it: a
 * knot between fewer is no average. */
#define APPROX_SPLIT_MIN 2

/* Knots are removed, after the tolerance is met, only from curves of at
 * most this many (each removal is tried), and each try moves the knots
 * of APPROX_WINDOW spans either side of the one it merges, in
 * APPROX_TRY_SWEEPS sweeps over the points on them. */
#define APPROX_REMOVE_MAX 256
#define APPROX_WINDOW 2
/* A loop the crossing check finds is cut (its knots removed) where it
 * takes this many knots at most. */
#define APPROX_LOOP_KNOTS 8
#define APPROX_TRY_SWEEPS 4

/* A removal is kept only where the squares of the distances of the
 * points near it grow by less than this many times the variance of
 * the noise (estimated by the mean square distance of all the points):
 * a knot the points do not ask for adds about one or two variances (a
 * chi-square of one or two degrees of freedom, which passes 16 once in
 * some thousands); one they ask for adds many.  So the knots that stay
 * are those the points show a need of, and the curve keeps to the
 * outline rather than using the tolerance. */
#define APPROX_NEED 16.0

/* A run of curvature of one sign between two inflexions is a wiggle
 * when it turns the tangent by less than this (radians): a few
 * degrees, far below any shape a designer draws between inflexions and
 * above what noise on a straight stretch makes a knot hold.  Sampled
 * APPROX_KSAMPLES times a span; a curvature times the length below
 * APPROX_FLAT has no sign. */
#define APPROX_WIGGLE 0.05
/* A removal that straightens a wiggle may take this many new knots (one:
 * more brought back as many inflexions as they took) elsewhere near
 * it, where the points then ask for them. */
#define APPROX_RELOCATE 1
#define APPROX_KSAMPLES 16
#define APPROX_FLAT 1e-9
/* A line needs this many points to lean on; between two corners fewer
 * start as one span (the end of a serif: a knot there would bend a
 * stretch the points cannot hold). */
#define APPROX_LINE_MIN 6

/* Newton steps at most projecting a point onto the curve, each at most
 * APPROX_MAXSTEP in u; stop below APPROX_FOOT in u. */
#define APPROX_NEWTON 16
#define APPROX_MAXSTEP 0.5
/* A foot is found once a Newton step moves it less than this fraction
 * of the tolerance along the curve: the distance is then right to far
 * less (its error is second order in the step). */
#define APPROX_FOOT 1e-7

/* Points within this fraction of their extent from the line through
 * the two farthest apart are on that line. */
#define APPROX_LINE 1e-9

/* Fits kept: the fair fit through the knots is most of -e's cost, and
 * the fairing's steps refit knots they have moved back (a step the
 * merit refused undone, the Jacobian's last move undone: the move
 * subtracted again, which often gives the same bits), or fit the same
 * knots twice in a row; so the latest APPROX_KEPT distinct fits are kept
 * with the knots and corners they were fitted from, and a fit asked of
 * the same (bit for bit) is copied, not done again.  On the 200 noisy
 * glyph contours of make compare-approx (-e and -e -C) that cuts the
 * time by 11% (888 s to 788 s), and every output is the same, byte for
 * byte. */
#define APPROX_KEPT 2

struct kept {
	double *k, *seg;        /* the knots, and the curve through them */
	size_t *corner, m, nc;  /* how many knots; the corners among them */
};

struct work {
	int dim, closed;
	size_t n, m, shift;     /* points, knots, where the outline starts */
	double tol;             /* in the scaled units */
	int e;                  /* the points are scaled by 2^-e */
	const double *q;        /* the points from the start */
	double *qbuf;           /* their copy, for a closed outline */
	const double *cq;       /* the same with the corners' knots */
	double *cqbuf;          /* where those are not the points */
	double *sm, *s;         /* moving average; its length to each point */
	size_t *fj;             /* the foot of each point: span, u */
	double *fu, *dist;
	double *k, *acc, *wsum; /* knots; a sweep's sums */
	unsigned char *fixed;   /* corners stay where they are */
	size_t *corner, nc;     /* knots that are corners */
	size_t *kidx;           /* the first knots' points; then scratch:
	                         * split's counts, the check's points on
	                         * each span */
	double *seg;            /* the curve through the knots */
	double *pow;            /* its spans in powers of u */
	double *spanmax;        /* the largest distance on each span */
	size_t *eoff, *elist;   /* the polyline's edges near each span */
	double *sk, *sseg, *sfu;        /* a try's saved knots, curve, feet */
	size_t *sfj;
	unsigned char *sfixed, *tried, *near;  /* near: points of a try */
	unsigned char *cut;     /* knots inside a loop the check found */
	unsigned char *stried;
	double *sdist;
	size_t sm0;
	int checks;             /* checks that found spans astray */
	int nomem;              /* memory ran out, in a try too: the run
	                         * fails (approx_run), never takes another
	                         * turn quietly */
	size_t start;           /* spans to start with */
	struct loft_fit_opts fit;
	struct kept kept[APPROX_KEPT];
	int newest;             /* the kept fit made last */
};

static void
work_free(struct work *w)
{
	free(w->qbuf);
	free(w->cqbuf);
	free(w->sm);
	free(w->s);
	free(w->fj);
	free(w->fu);
	free(w->dist);
	free(w->k);
	free(w->acc);
	free(w->wsum);
	free(w->fixed);
	free(w->corner);
	free(w->kidx);
	free(w->seg);
	free(w->pow);
	free(w->spanmax);
	free(w->eoff);
	free(w->elist);
	free(w->sk);
	free(w->sseg);
	free(w->sfu);
	free(w->sfj);
	free(w->sfixed);
	free(w->tried);
	free(w->near);
	free(w->stried);
	free(w->sdist);
	free(w->cut);
	for (int c = 0; c < APPROX_KEPT; c++) {
		free(w->kept[c].k);
		free(w->kept[c].seg);
		free(w->kept[c].corner);
	}
}

static int
work_alloc(struct work *w, size_t n, int dim)
{
	size_t m = n + 2;

	w->qbuf = malloc(n * dim * sizeof *w->qbuf);
	w->sm = malloc(n * dim * sizeof *w->sm);
	w->s = malloc((n + 1) * sizeof *w->s);
	w->fj = malloc((n + 1) * sizeof *w->fj);   /* first_knots' too */
	w->fu = malloc(n * sizeof *w->fu);
	w->dist = malloc(n * sizeof *w->dist);
	w->k = malloc(m * dim * sizeof *w->k);
	w->acc = malloc(m * dim * sizeof *w->acc);
	w->wsum = malloc(m * sizeof *w->wsum);
	w->fixed = malloc(m);
	w->corner = malloc(m * sizeof *w->corner);
	w->kidx = malloc(m * sizeof *w->kidx);
	w->seg = malloc(4 * dim * m * sizeof *w->seg);
	w->pow = malloc(4 * dim * m * sizeof *w->pow);
	w->spanmax = malloc(m * sizeof *w->spanmax);
	w->eoff = malloc((m + 1) * sizeof *w->eoff);
	w->elist = malloc(6 * n * sizeof *w->elist);
	w->sk = malloc(m * dim * sizeof *w->sk);
	w->sseg = malloc(4 * dim * m * sizeof *w->sseg);
	w->sfu = malloc(n * sizeof *w->sfu);
	w->sfj = malloc(n * sizeof *w->sfj);
	w->sfixed = malloc(m);
	w->tried = malloc(m);
	w->near = malloc(n);
	w->stried = malloc(m);
	w->sdist = malloc(n * sizeof *w->sdist);
	w->cut = malloc(m);
	for (int c = 0; c < APPROX_KEPT; c++) {
		w->kept[c].k = malloc(m * dim * sizeof *w->kept[c].k);
		w->kept[c].seg = malloc(4 * dim * m * sizeof *w->kept[c].seg);
		w->kept[c].corner = malloc(m * sizeof *w->kept[c].corner);
		w->kept[c].m = 0;       /* none yet */
		if (!w->kept[c].k || !w->kept[c].seg || !w->kept[c].corner)
			return -1;
	}
	return w->qbuf && w->sm && w->s && w->fj && w->fu && w->dist && w->k &&
	    w->acc && w->wsum && w->fixed && w->corner && w->kidx && w->seg &&
	    w->spanmax && w->eoff && w->elist && w->pow && w->sk && w->sseg &&
	    w->sfu && w->sfj && w->sfixed &&
	    w->tried && w->near && w->stried && w->sdist && w->cut ? 0 : -1;
}

/* The checks of the counts and the tolerance, before any work: after
 * them there are at least LOFT_APPROX_MIN_OPEN points. */
static int
check_args(const struct loft_approx_opts *o, size_t n, int dim,
    struct loft_error *err)
{
	size_t need = o->closed ? LOFT_APPROX_MIN_CLOSED : LOFT_APPROX_MIN_OPEN;

	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "points have %d "
		    "coordinates; 2 or 3 are needed", dim);
	if (!(o->tol > 0) || !isfinite(o->tol))
		return loft_fail(err, LOFT_EINPUT, -1, "tolerance %g: want a "
		    "positive number", o->tol);
	if (n < need)
		return loft_fail(err, LOFT_EGEOM, -1, "%zu point%s: %s "
		    "approximation needs at least %zu", n, n == 1 ? "" : "s",
		    o->closed ? "a closed" : "an open", need);
	return 0;
}

/* The direction of the line all n points lie on (to within APPROX_LINE
 * of their spread) into d, and 1; 0 where they lie on none. */
static int
on_a_line(const double *p, size_t n, int dim, double *d)
{
	double far = 0, off = 0;
	size_t b = 0;

	for (size_t i = 1; i < n; i++)
		if (vdist(p + i * dim, p, dim) > far) {
			far = vdist(p + i * dim, p, dim);
			b = i;
		}
	/* the distance of each point from the line p[0] p[b] */
	vsub(d, p + b * dim, p, dim);
	vunit(d, dim);
	for (size_t i = 0; i < n; i++) {
		double r[LOFT_MAXDIM];

		vsub(r, p + i * dim, p, dim);
		vaxpy(r, -vdot(r, d, dim), d, dim);
		off = fmax(off, vnorm(r, dim));
	}
	return !(off > APPROX_LINE * far);
}

/* Whether points on the line along d turn back along it somewhere. */
static int
turns_back(const double *p, size_t n, int dim, const double *d)
{
	double was = 0, r[LOFT_MAXDIM];

	for (size_t i = 1; i < n; i++) {
		double go;

		vsub(r, p + i * dim, p + (i - 1) * dim, dim);
		go = vdot(r, d, dim);
		if ((go < 0 && was > 0) || (go > 0 && was < 0))
			return 1;       /* (a product of tiny steps is 0) */
		was = go != 0 ? go : was;
	}
	return 0;
}

/* The checks of the points' spread, after check_args: a closed outline
 * (or an open one with end tangents given) must not lie on a line.
 * Where open points pass on a line, its direction into line and 1 into
 * *on; else 0. */
static int
check_input(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim, double *line, int *on, struct loft_error *err)
{
	double lo[LOFT_MAXDIM], hi[LOFT_MAXDIM], d[LOFT_MAXDIM];

	vcopy(lo, p, dim);
	vcopy(hi, p, dim);
	for (size_t i = 1; i < n; i++)
		for (int c = 0; c < dim; c++) {
			lo[c] = fmin(lo[c], p[i * dim + c]);
			hi[c] = fmax(hi[c], p[i * dim + c]);
		}
	vsub(d, hi, lo, dim);
	if (o->tol >= vnorm(d, dim) / 2)
		return loft_fail(err, LOFT_EINPUT, -1, "tolerance %g is larger "
		    "than the outline: every point is within it of the middle "
		    "of their box (half its diagonal is %g)", o->tol,
		    vnorm(d, dim) / 2);
	if (!(*on = on_a_line(p, n, dim, line)))
		return 0;
	if (o->closed || o->have_start || o->have_end)
		return loft_fail(err, LOFT_EGEOM, -1, "the points all lie on a "
		    "line: no outline to approximate");
	if (turns_back(p, n, dim, line))
		return loft_fail(err, LOFT_EGEOM, -1, "the points all lie on a "
		    "line and turn back along it: no outline to approximate");
	return 0;
}

/* Knot of collinear_runs at point i: the point, or where i is a corner
 * with its place given, that place. */
static const double *
run_knot(const struct loft_approx_opts *o, const double *p, size_t i,
    int dim)
{
	for (size_t c = 0; o->corner_at != NULL && c < o->ncorner; c++)
		if (o->corner[c] == i)
			return o->corner_at + c * dim;
	return p + i * dim;
}

/* The straight segment from knot a to knot b of collinear_runs, the
 * next of info->nseg in seg. */
static void
run_segment(const struct loft_approx_opts *o, const double *p, size_t a,
    size_t b, int dim, double *seg, struct loft_approx_info *info)
{
	double *s = seg + info->nseg++ * 4 * dim;

	vcopy(s, run_knot(o, p, a, dim), dim);
	vcopy(s + dim, run_knot(o, p, b, dim), dim);
	vsub(s + 2 * dim, s + dim, s, dim);
	vcopy(s + 3 * dim, s + 2 * dim, dim);
}

/* Open points all on the line along d, running one way along it
 * (check_input): straight segments between the first, each corner, and
 * the last, into seg; *info as loft_approx's. */
static void
collinear_runs(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim, const double *d, double *seg, struct loft_approx_info *info)
{
	double r[LOFT_MAXDIM];
	size_t last = 0;

	for (size_t c = 0; c < o->ncorner; c++)
		if (o->corner[c] > last && o->corner[c] < n - 1) {
			run_segment(o, p, last, o->corner[c], dim, seg, info);
			last = o->corner[c];
		}
	run_segment(o, p, last, n - 1, dim, seg, info);
	info->nknots = info->nseg + 1;
	for (size_t i = 0; i < n; i++) {
		vsub(r, p + i * dim, p, dim);
		vaxpy(r, -vdot(r, d, dim), d, dim);
		if (vnorm(r, dim) >= info->dist) {
			info->dist = vnorm(r, dim);
			info->where = i;
		}
	}
}

/* Where a closed outline starts: its first corner, else its
 * lexicographically least point (the same wherever the input starts). */
static size_t
start_point(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim)
{
	size_t a = 0;

	if (!o->closed)
		return 0;
	if (o->ncorner > 0)
		return o->corner[0];
	for (size_t i = 1; i < n; i++)
		for (int c = 0; c < dim; c++) {
			double x = p[i * dim + c], y = p[a * dim + c];

			if (x != y) {
				if (x < y)
					a = i;
				break;
			}
		}
	return a;
}

/* Into back[i] and ahead[i], how many points lie from point i back to
 * the corner before it and on to the corner after it (of the ncorner
 * corners, increasing), round the end when closed; n where there is
 * none.  Both are 0 at a corner. */
static void
corner_gaps(const struct work *w, const size_t *corner, size_t ncorner,
    size_t *back, size_t *ahead)
{
	size_t n = w->n, last = n, c = 0;

	for (size_t i = 0; i < n; i++)
		back[i] = ahead[i] = n;
	if (ncorner == 0)
		return;
	if (w->closed)          /* the last corner, a lap back */
		last = corner[ncorner - 1];
	for (size_t i = 0; i < n; i++) {
		if (c < ncorner && corner[c] == i)
			last = corner[c++];
		if (last < n)
			back[i] = i >= last ? i - last : i + n - last;
	}
	last = w->closed ? corner[0] : n;
	c = ncorner;
	for (size_t i = n; i-- > 0;) {
		if (c > 0 && corner[c - 1] == i)
			last = corner[--c];
		if (last < n)
			ahead[i] = last >= i ? last - i : last + n - i;
	}
}

/* The moving average of the points, and the length along it to each
 * point (s[n]: the whole, round the closing chord when closed).  Where
 * two corners (of the ncorner, increasing) lie closer together than the
 * window, the window of a point between them narrows to the nearer,
 * and a corner's point is left as it is: an average across two
 * corners at once (a serif's) lies off the points between them, and
 * the knots put on it there are held by none of them (on 1,600 noisy
 * points round FreeSerif's h, H and U, the fits with the true corners
 * found then strayed, and 40 of their 42 were given up for the fit
 * without corners).  Across one corner of a longer run the average
 * stays: the knots settle from it as before.  Returns 0, or -1 out of
 * memory. */
static int
smooth(struct work *w, const size_t *corner, size_t ncorner)
{
	size_t n = w->n, hw = (size_t)(APPROX_SMOOTH * n);
	int dim = w->dim;
	double *pre = malloc((n + 1) * dim * sizeof *pre);
	size_t *back = malloc(n * sizeof *back);
	size_t *ahead = malloc(n * sizeof *ahead);

	if (pre == NULL || back == NULL || ahead == NULL) {
		free(pre);
		free(back);
		free(ahead);
		return -1;
	}
	corner_gaps(w, corner, ncorner, back, ahead);
	/* pre[i]: the sum of the first i points */
	memset(pre, 0, dim * sizeof *pre);
	for (size_t i = 0; i < n; i++)
		for (int c = 0; c < dim; c++)
			pre[(i + 1) * dim + c] = pre[i * dim + c] +
			    w->q[i * dim + c];
	for (size_t i = 0; i < n; i++) {
		size_t h = hw;

		if (!w->closed) {
			h = i < h ? i : h;
			h = n - 1 - i < h ? n - 1 - i : h;
		}
		if (h > (n - 1) / 2)
			h = (n - 1) / 2;
		if (back[i] + ahead[i] < 2 * h) {       /* a short run */
			h = back[i] < h ? back[i] : h;
			h = ahead[i] < h ? ahead[i] : h;
		}
		for (int c = 0; c < dim; c++) {
			/* points i - h .. i + h, round the end when closed */
			double sum;
			size_t lo = (i + n - h) % n, hi = (i + h) % n;

			if (lo <= hi)
				sum = pre[(hi + 1) * dim + c] - pre[lo * dim + c];
			else
				sum = pre[n * dim + c] - pre[lo * dim + c] +
				    pre[(hi + 1) * dim + c];
			w->sm[i * dim + c] = sum / (2 * h + 1);
		}
	}
	free(pre);
	free(back);
	free(ahead);
	w->s[0] = 0;
	for (size_t i = 1; i <= n; i++)
		w->s[i] = w->s[i - 1] + (i < n || w->closed ?
		    vdist(w->sm + (i % n) * dim, w->sm + (i - 1) * dim, dim) : 0);
	return 0;
}

/* The count of spans. */
static size_t
nseg_of(const struct work *w)
{
	return w->closed ? w->m : w->m - 1;
}

/* w->corner[0..nc): the knots that are fixed, from w->fixed. */
static void
list_corners(struct work *w)
{
	w->nc = 0;
	for (size_t j = 0; j < w->m; j++)
		if (w->fixed[j])
			w->corner[w->nc++] = j;
}

/* Add knot at point i (a corner: the point itself, fixed). */
static void
add_knot(struct work *w, size_t i, int corner)
{
	size_t j = w->m++;

	w->kidx[j] = i;
	w->fixed[j] = (unsigned char)corner;
	vcopy(w->k + j * w->dim, (corner ? w->cq : w->sm) + i * w->dim, w->dim);
	if (corner)
		w->corner[w->nc++] = j;
}

/*
 * The first knots: the corners (and the ends of an open outline), and
 * between each two of them spans of even length along the average, as
 * many as their share of w->start, two at least where there
 * are points enough (a closed curve needs three knots), or every point
 * where w->start is n or more.  The feet of
 * the points: their span, and u by length along the average.  The
 * breaks between pieces go in w->fj first: n + 1 of them where every
 * point of a closed outline is a corner (the last is the first again).
 */
static void
first_knots(struct work *w, const size_t *corner, size_t ncorner)
{
	size_t n = w->n, nb = 0, *br = w->fj;   /* fj as scratch */
	double total = w->s[n];

	w->m = w->nc = 0;
	if (w->closed && ncorner == 0)
		br[nb++] = 0;
	if (!w->closed && (ncorner == 0 || corner[0] != 0))
		br[nb++] = 0;
	for (size_t c = 0; c < ncorner; c++)
		br[nb++] = corner[c];
	if (!w->closed && br[nb - 1] != n - 1)
		br[nb++] = n - 1;
	if (w->closed)
		br[nb] = n;
	for (size_t b = 0; b < nb - !w->closed; b++) {
		size_t i0 = br[b], i1 = br[b + 1], spans, last = i0;
		double len = w->s[i1] - w->s[i0];
		int corner_here = ncorner > 0 && (w->closed || b > 0 ||
		    corner[0] == 0);

		add_knot(w, i0, corner_here);
		if (w->start >= n) {            /* every point a knot */
			for (size_t i = i0 + 1; i < i1; i++)
				add_knot(w, i, 0);
			continue;
		}
		spans = (size_t)(w->start * len / total + 0.5);
		if (spans < 2)
			spans = i1 - i0 >= APPROX_LINE_MIN ? 2 : 1;
		for (size_t t = 1, i = i0; t < spans; t++) {
			double at = w->s[i0] + len * t / spans;

			while (i < i1 && w->s[i + 1] <= at)
				i++;
			if (i > last && i < i1)
				add_knot(w, last = i, 0);
		}
	}
	if (!w->closed)
		add_knot(w, n - 1, ncorner > 0 && corner[ncorner - 1] == n - 1);
	for (size_t j = 0; j < nseg_of(w); j++) {
		size_t a = w->kidx[j], b = j + 1 < w->m ? w->kidx[j + 1] : n;
		double len = w->s[b] - w->s[a];

		for (size_t i = a; i < b; i++) {
			w->fj[i] = j;
			w->fu[i] = len > 0 ? (w->s[i] - w->s[a]) / len : 0;
		}
	}
	if (!w->closed) {
		w->fj[n - 1] = w->m - 2;
		w->fu[n - 1] = 1;
	}
}

/* The point of span j at u, and its first two derivatives (unless
 * d1 is NULL), from the powers of u. */
static inline void
span_eval(const struct work *w, size_t j, double u, double *p, double *d1,
    double *d2)
{
	int d = w->dim;
	const double *c = w->pow + j * 4 * d;

	for (int k = 0; k < d; k++) {
		double c1 = c[d + k], c2 = c[2 * d + k], c3 = c[3 * d + k];

		p[k] = c[k] + u * (c1 + u * (c2 + u * c3));
		if (d1 != NULL) {
			d1[k] = c1 + u * (2 * c2 + 3 * u * c3);
			d2[k] = 2 * c2 + 6 * u * c3;
		}
	}
}

/*
 * Move the foot (*j, *u) of x by Newton's method on (C(u) - x).C'(u)
 * to the nearest point of the curve near it, passing from span to span;
 * returns the distance.
 */
static double
project(const struct work *w, const double *x, size_t *j, double *u)
{
	int dim = w->dim;
	size_t jj = *j, ns = nseg_of(w);
	double uu = *u, p[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM];
	double r[LOFT_MAXDIM], done = APPROX_FOOT * w->tol;

	for (int it = 0; it < APPROX_NEWTON; it++) {
		double f, v, fp, du;

		span_eval(w, jj, uu, p, d1, d2);
		vsub(r, p, x, dim);
		f = vdot(d1, r, dim);
		v = vdot(d1, d1, dim);
		fp = v + vdot(d2, r, dim);
		if (!(fp > 0))
			fp = v;
		if (!(fp > 0))
			break;
		du = -f / fp;
		if (du > APPROX_MAXSTEP)
			du = APPROX_MAXSTEP;
		else if (du < -APPROX_MAXSTEP)
			du = -APPROX_MAXSTEP;
		uu += du;
		if (uu < 0) {
			if (jj > 0 || w->closed) {
				jj = jj > 0 ? jj - 1 : ns - 1;
				uu += 1;
			} else {
				uu = 0;
			}
		} else if (uu > 1) {
			if (jj + 1 < ns || w->closed) {
				jj = jj + 1 < ns ? jj + 1 : 0;
				uu -= 1;
			} else {
				uu = 1;
			}
		}
		if (du * du * v < done * done)
			break;
	}
	span_eval(w, jj, uu, p, NULL, NULL);
	*j = jj;
	*u = uu;
	return vdist(p, x, dim);
}

/* The spans of the curve in powers of u, for projecting. */
static void
powers(struct work *w)
{
	for (size_t j = 0; j < nseg_of(w); j++) {
		const double *g = w->seg + j * 4 * w->dim;
		double *c = w->pow + j * 4 * w->dim;

		for (int k = 0, d = w->dim; k < d; k++) {
			double pa = g[k], pb = g[d + k], da = g[2 * d + k];
			double db = g[3 * d + k];

			c[k] = pa;
			c[d + k] = da;
			c[2 * d + k] = 3 * (pb - pa) - 2 * da - db;
			c[3 * d + k] = 2 * (pa - pb) + da + db;
		}
	}
}

/* Whether kept fit c was fitted from the knots and corners of w as they
 * are now, bit for bit (never where straight spans are asked for). */
static int
kept_same(const struct work *w, const struct kept *c)
{
	return c->m == w->m && c->nc == w->nc && w->fit.nstraight == 0 &&
	    memcmp(c->k, w->k, w->m * w->dim * sizeof *w->k) == 0 &&
	    memcmp(c->corner, w->corner, w->nc * sizeof *w->corner) == 0;
}

/* The curve through the knots: a kept fit of the same knots copied,
 * else fitted (and kept, in place of the older). */
static int
fit_curve(struct work *w, struct loft_error *err)
{
	struct loft_fit_opts fo = w->fit;
	struct loft_error ferr;
	size_t size = 4 * (size_t)w->dim * nseg_of(w) * sizeof *w->seg;
	struct kept *c;
	int rc;

	for (int t = 0; t < APPROX_KEPT; t++)
		if (kept_same(w, c = &w->kept[(w->newest + t) % APPROX_KEPT])) {
			memcpy(w->seg, c->seg, size);
			powers(w);
			return 0;
		}
	fo.corner = w->nc > 0 ? w->corner : NULL;
	fo.ncorner = w->nc;
	rc = loft_fit(&fo, w->k, w->m, w->dim, w->seg, NULL, &ferr);
	if (rc != 0) {
		w->nomem |= rc == LOFT_ENOMEM;
		return loft_fail(err, LOFT_EGEOM, -1, "the curve through %zu "
		    "knots fails: %s", w->m, ferr.msg);
	}
	powers(w);
	if (w->fit.nstraight == 0) {
		w->newest = (w->newest + 1) % APPROX_KEPT;
		c = &w->kept[w->newest];
		c->m = w->m;
		c->nc = w->nc;
		memcpy(c->k, w->k, w->m * w->dim * sizeof *w->k);
		memcpy(c->corner, w->corner, w->nc * sizeof *w->corner);
		memcpy(c->seg, w->seg, size);
	}
	return 0;
}

/* Fit the curve through the knots and project every point onto it;
 * the largest distance into *worst (its point *at). */
static int
fit_project(struct work *w, double *worst, size_t *at, struct loft_error *err)
{
	size_t ns = nseg_of(w);

	if (fit_curve(w, err) != 0)
		return LOFT_EGEOM;
	*worst = 0;
	*at = 0;
	for (size_t j = 0; j < ns; j++)
		w->spanmax[j] = 0;
	for (size_t i = 0; i < w->n; i++) {
		double d = project(w, w->q + i * w->dim, &w->fj[i], &w->fu[i]);

		if (!isfinite(d))
			return loft_fail(err, LOFT_EGEOM, -1, "the curve through "
			    "%zu knots overflows", w->m);
		w->dist[i] = d;
		if (d > w->spanmax[w->fj[i]])
			w->spanmax[w->fj[i]] = d;
		if (d > *worst) {
			*worst = d;
			*at = i;
		}
	}
	return 0;
}

/* One sweep: each free knot moves by the hat-weighted mean residual of
 * the points on its spans.  Returns the largest move. */
static double
correct(struct work *w)
{
	int dim = w->dim;
	size_t m = w->m;
	double big = 0;

	memset(w->acc, 0, m * dim * sizeof *w->acc);
	memset(w->wsum, 0, m * sizeof *w->wsum);
	for (size_t i = 0; i < w->n; i++) {
		size_t a = w->fj[i], b = a + 1 < m ? a + 1 : 0;
		double p[LOFT_MAXDIM], r[LOFT_MAXDIM], u = w->fu[i];

		span_eval(w, a, u, p, NULL, NULL);
		vsub(r, w->q + i * dim, p, dim);
		vaxpy(w->acc + a * dim, 1 - u, r, dim);
		vaxpy(w->acc + b * dim, u, r, dim);
		w->wsum[a] += 1 - u;
		w->wsum[b] += u;
	}
	for (size_t j = 0; j < m; j++) {
		double d[LOFT_MAXDIM];

		if (w->fixed[j] || !(w->wsum[j] > 0))
			continue;
		vscale(d, 1 / w->wsum[j], w->acc + j * dim, dim);
		vaxpy(w->k + j * dim, 1, d, dim);
		big = fmax(big, vnorm(d, dim));
	}
	return big;
}

/* The two-way check: each span is sampled at APPROX_STRAY_SAMPLES
 * points, each of which must be within the tolerance plus half the
 * mean spacing of the points of the polyline through the points near
 * the span (their feet within one span of it): the points' distance to
 * the curve alone misses a loop the curve makes between two of them.
 * The outline between two points a spacing apart along it lies within
 * half of it of one of them.  (With the whole spacing, a needle that
 * left the points by 15 at the end of a stroke 15 wide, tolerance 7.6,
 * spacing 8, passed; on make compare-approx's glyphs with three other
 * draws of the noise, half takes the 90th percentile of the distance
 * from the true outline from 5.42, 5.48 and 4.68 sigmas to 5.16, 5.11
 * and 4.68, and 5 curves 1.6 to 2.9 sigmas nearer, 1 0.3 farther.) */
#define APPROX_STRAY_SAMPLES 16

/* A knot put on the points to pull a span astray back keeps this
 * fraction of the tolerance from the span's ends (else it is the
 * middle of their chord): nearer, the fit through them is ill-posed. */
#define APPROX_APART 0.25

/* Checks both ways that find spans astray, at most, in one try (a
 * round counts two where its loops were cut and it fails again after
 * fairing): each round after one mends the spans astray; past these, a
 * span still astray is one the points' own noise draws, which more
 * knots only follow closer. */
#define APPROX_CHECK_ROUNDS 3

/* A span so marked in spanmax is split wherever it lies (split). */
#define APPROX_FORCE HUGE_VAL

/* Whether span a is span b or a neighbour of it. */
static int
span_near(const struct work *w, size_t a, size_t b)
{
	size_t ns = nseg_of(w), d = a >= b ? a - b : b - a;

	return d <= 1 || (w->closed && ns - d <= 1);
}

/* The spans near edge i of the points' polyline (from point i to the
 * next): those span_near the foot of either end, each once, into c;
 * returns how many (6 at most). */
static int
edge_spans(const struct work *w, size_t i, size_t *c)
{
	size_t ns = nseg_of(w), end[2] = { w->fj[i], w->fj[(i + 1) % w->n] };
	int k = 0;

	for (int e = 0; e < 2; e++)
		for (int o = -1; o <= 1; o++) {
			size_t j = end[e] + ns + o;     /* end[e] + o, cyclic */
			int seen = 0;

			if (!w->closed && (j < ns || j >= 2 * ns))
				continue;       /* off an open curve's ends */
			j %= ns;
			for (int t = 0; t < k; t++)
				seen |= c[t] == j;
			if (!seen && span_near(w, end[e], j))
				c[k++] = j;
		}
	return k;
}

/* The edges of the points' polyline near each span, from the feet as
 * they are: those of span j (edge_spans) are elist[eoff[j] ..
 * eoff[j + 1]), in the order of the edges.  So polyline_foot visits
 * only them, not every edge, and the stray check is linear in the
 * points rather than in their product with the samples. */
static void
near_edges(struct work *w)
{
	size_t ns = nseg_of(w), ne = w->closed ? w->n : w->n - 1, c[6];
	size_t *off = w->eoff;

	memset(off, 0, (ns + 1) * sizeof *off);
	for (size_t i = 0; i < ne; i++)
		for (int k = 0, nk = edge_spans(w, i, c); k < nk; k++)
			off[c[k] + 1]++;
	for (size_t j = 0; j < ns; j++)
		off[j + 1] += off[j];
	/* off[j] runs along span j's list as it fills, ending at its
	 * successor's start; then each moves back one */
	for (size_t i = 0; i < ne; i++)
		for (int k = 0, nk = edge_spans(w, i, c); k < nk; k++)
			w->elist[off[c[k]]++] = i;
	for (size_t j = ns; j > 0; j--)
		off[j] = off[j - 1];
	off[0] = 0;
}

/* The nearest point to x of the polyline of the points near span j
 * (edge i from point i to the next; the list of near_edges, made from
 * the feet as they are), into f; returns its distance. */
static double
polyline_foot(const struct work *w, size_t j, const double *x, double *f)
{
	int dim = w->dim;
	double best = HUGE_VAL;

	for (size_t e = w->eoff[j]; e < w->eoff[j + 1]; e++) {
		size_t i = w->elist[e], i1 = (i + 1) % w->n;
		const double *a = w->q + i * dim, *b = w->q + i1 * dim;
		double ab[LOFT_MAXDIM], ax[LOFT_MAXDIM], c[LOFT_MAXDIM], t, l2, d;

		vsub(ab, b, a, dim);
		vsub(ax, x, a, dim);
		l2 = vdot(ab, ab, dim);
		t = l2 > 0 ? vdot(ab, ax, dim) / l2 : 0;
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		vcopy(c, a, dim);
		vaxpy(c, t, ab, dim);
		if ((d = vdist(c, x, dim)) < best) {
			best = d;
			if (f != NULL)
				vcopy(f, c, dim);
		}
	}
	return best;
}

/* The largest distance on each span, from the points' feet. */
static void
span_max(struct work *w)
{
	for (size_t j = 0; j < nseg_of(w); j++)
		w->spanmax[j] = 0;
	for (size_t i = 0; i < w->n; i++)
		if (w->dist[i] > w->spanmax[w->fj[i]])
			w->spanmax[w->fj[i]] = w->dist[i];
}

/* Mark (APPROX_FORCE in spanmax) each span that strays from the
 * points' polyline; returns how many. */
static size_t
stray_spans(struct work *w)
{
	size_t ns = nseg_of(w), bad = 0;
	double room = w->tol + w->s[w->n] / w->n / 2;

	near_edges(w);
	for (size_t j = 0; j < ns; j++)
		for (int k = 1; k < APPROX_STRAY_SAMPLES; k++) {
			double x[LOFT_MAXDIM];

			span_eval(w, j, (double)k / APPROX_STRAY_SAMPLES, x,
			    NULL, NULL);
			if (polyline_foot(w, j, x, NULL) > room) {
				w->spanmax[j] = APPROX_FORCE;
				bad++;
				break;
			}
		}
	return bad;
}

/* Spans ja and jb cross: the knots between them the shorter way round
 * (APPROX_LOOP_KNOTS at most, all free) marked to cut, the curve there
 * a loop no point asks for where the spans between hold fewer points
 * in all (w->kidx) than APPROX_SPLIT_MIN times their count. */
static void
mark_loop(struct work *w, size_t ja, size_t jb)
{
	size_t ns = nseg_of(w), a = ja < jb ? ja : jb, b = ja < jb ? jb : ja;
	size_t len = b - a, pts = 0, fresh = 0;

	if (w->closed && ns - len < len) {      /* the way round the end */
		a = b;
		len = ns - len;
	}
	if (len == 0 || len > APPROX_LOOP_KNOTS)
		return;
	for (size_t t = 1; t <= len; t++) {
		if (w->fixed[(a + t) % w->m])
			return;
		pts += t < len ? w->kidx[(a + t) % ns] : 0;
		fresh += !w->cut[(a + t) % w->m];
	}
	if (fresh == 0 || pts >= APPROX_SPLIT_MIN * (len - 1) + (len == 1))
		return;
	for (size_t t = 1; t <= len; t++)
		w->cut[(a + t) % w->m] = 1;
}

/* The self-crossing check of a plane curve: its polyline of
 * APPROX_STRAY_SAMPLES edges a span, filed in a grid; two edges, not
 * neighbours, that cross mark both their spans. */
struct crossing {
	struct work *w;
	double *pt;
	size_t ne, e, bad;
};

static void
edge_of(const struct crossing *c, size_t e, double *sg)
{
	size_t e1 = (e + 1) % (c->ne + !c->w->closed);

	sg[0] = c->pt[2 * e];
	sg[1] = c->pt[2 * e + 1];
	sg[2] = c->pt[2 * e1];
	sg[3] = c->pt[2 * e1 + 1];
}

/* Spans ja and jb of c cross: both marked (APPROX_FORCE), counted
 * where not yet, and the loop between them marked to cut. */
static void
mark_cross(struct crossing *c, size_t ja, size_t jb)
{
	c->bad += (c->w->spanmax[ja] != APPROX_FORCE) +
	    (c->w->spanmax[jb] != APPROX_FORCE && jb != ja);
	c->w->spanmax[ja] = c->w->spanmax[jb] = APPROX_FORCE;
	mark_loop(c->w, ja, jb);
}

static int
edge_crosses(void *ctx, size_t f)
{
	struct crossing *c = ctx;
	size_t d = c->e > f ? c->e - f : f - c->e;
	double s[4], t[4];

	if (d <= 1 || (c->w->closed && c->ne - d <= 1))
		return 0;
	edge_of(c, c->e, s);
	edge_of(c, f, t);
	if (loft_segments_cross(s, t))
		mark_cross(c, c->e / APPROX_STRAY_SAMPLES,
		    f / APPROX_STRAY_SAMPLES);
	return 0;
}

/* Where the curve turns back at a joint (its tangents, or the edges of
 * its polyline, either side point against each other), the
 * APPROX_FOLD_EDGES edges either side are sampled finer, and finer
 * still towards the joint (loft_sides_cross), and tested against each
 * other: the two sides of a needle tip run close and nearly along each
 * other there, and can cross where the edges do not, or within the two
 * edges at the tip, which the grid's test skips as neighbours.  (A
 * stroke's end 1.1 tolerances wide, read as one corner, turned by 179
 * degrees; the sides crossed at 0.04 and 0.11 of their spans from the
 * tip, and no two edges did.) */
#define APPROX_FOLD_EDGES 4

/* loft_sides_cross's eval: the point of span s of the work ctx. */
static void
span_point(const void *ctx, size_t s, double u, double *p)
{
	span_eval(ctx, s, u, p, NULL, NULL);
}

/* The folds at the joints of the plane curve: both spans beside each
 * marked as crossing. */
static void
fold_spans(struct crossing *c)
{
	struct work *w = c->w;
	size_t ns = nseg_of(w), np = c->ne + !w->closed;
	double in[2], out[2], tin[2] = { 0, 0 }, tout[2] = { 0, 0 };
	double x[2] = { 0, 0 }, d2[2] = { 0, 0 };
	const double *p = c->pt;

	for (size_t j = !w->closed; j < ns; j++) {
		size_t k = j * APPROX_STRAY_SAMPLES, i = (k + np - 1) % np;
		size_t pj = (j + ns - 1) % ns;

		vsub(in, p + 2 * k, p + 2 * i, 2);
		vsub(out, p + 2 * k + 2, p + 2 * k, 2);
		span_eval(w, pj, 1, x, tin, d2);
		span_eval(w, j, 0, x, tout, d2);
		if ((vdot(in, out, 2) < 0 || vdot(tin, tout, 2) < 0) &&
		    loft_sides_cross(span_point, w, pj, j,
		    (double)APPROX_FOLD_EDGES / APPROX_STRAY_SAMPLES))
			mark_cross(c, pj, j);
	}
}

/* A knot the curve passes backwards: its tangent there points against
 * the way the points run past it by more than the angle whose cosine
 * is -APPROX_HOOK.  The way is from the point half a tolerance back
 * from the last point on the span before the knot to the one half a
 * tolerance on from the first on the span after (the nearest spans
 * with points; where the feet run backwards there, from before the
 * first of those two points to after the last), where those lie a
 * tolerance apart: the points' own U-turn turns that way with the
 * curve.  The curve runs on past such a knot and turns back, a hook,
 * which strays less than the spacing past the points and crosses
 * nothing, so neither check sees it.  (Once faint corners were dropped
 * (corners.c), the noisy contour 110 of tests/approx.sh's glyphs, a
 * Linux Libertine r, hooked at the foot of its stem, 6.5 sigmas from
 * the true outline, two knots there in the wrong order along the
 * points; contour 8, FreeSerif's f, had a cusp, a radius of 0.002
 * tolerances.) */
#define APPROX_HOOK 0.25

/* The point of w from point i (of the points as shifted) on in the
 * direction dir (1 or -1) at least len from it, or the last there is
 * (an open outline's end, or half way round a closed one). */
static size_t
point_beyond(const struct work *w, size_t i, int dir, double len)
{
	const double *p = w->q + i * w->dim;
	size_t j = i;

	for (size_t k = 0; k < w->n / 2; k++) {
		double d[LOFT_MAXDIM];

		if (!w->closed && (dir < 0 ? j == 0 : j + 1 == w->n))
			break;
		j = dir < 0 ? (j + w->n - 1) % w->n : (j + 1) % w->n;
		vsub(d, w->q + j * w->dim, p, w->dim);
		if (vnorm(d, w->dim) >= len)
			break;
	}
	return j;
}

/* Mark each free knot the curve passes backwards (see APPROX_HOOK) to
 * cut; returns how many, or (size_t)-1 out of memory. */
static size_t
hook_knots(struct work *w)
{
	size_t ns = nseg_of(w), bad = 0, none = (size_t)-1, *last;
	size_t *first = malloc(2 * ns * sizeof *first);
	int dim = w->dim;

	if (first == NULL)
		return none;
	last = first + ns;
	for (size_t j = 0; j < ns; j++)
		first[j] = none;
	for (size_t i = 0; i < w->n; i++) {
		if (first[w->fj[i]] == none)
			first[w->fj[i]] = i;
		last[w->fj[i]] = i;
	}
	for (size_t j = !w->closed; j < ns; j++) {
		size_t a = (j + ns - 1) % ns, b = j, lo, hi;
		double x[LOFT_MAXDIM], t[LOFT_MAXDIM], d2[LOFT_MAXDIM];
		double d[LOFT_MAXDIM];

		for (size_t k = 1; first[a] == none && k < ns &&
		    (w->closed || a > 0); k++)
			a = (a + ns - 1) % ns;  /* the nearest with points */
		for (size_t k = 1; first[b] == none && k < ns &&
		    (w->closed || b + 1 < ns); k++)
			b = (b + 1) % ns;
		if (w->fixed[j] || first[a] == none || first[b] == none)
			continue;
		lo = last[a];
		hi = first[b];
		if ((hi + w->n - lo) % w->n > w->n / 2) {
			lo = first[b];  /* feet out of order: round them */
			hi = last[a];
		}
		span_eval(w, j, 0, x, t, d2);
		vsub(d, w->q + point_beyond(w, hi, 1, w->tol / 2) * dim,
		    w->q + point_beyond(w, lo, -1, w->tol / 2) * dim, dim);
		if (!(vnorm(d, dim) >= w->tol) || !(vdot(t, d, dim) <
		    -APPROX_HOOK * vnorm(t, dim) * vnorm(d, dim)))
			continue;
		w->cut[j] = 1;
		bad++;
	}
	free(first);
	return bad;
}

/* Mark the spans of the plane curve that cross; returns how many,
 * or (size_t)-1 out of memory. */
static size_t
crossing_spans(struct work *w)
{
	size_t ns = nseg_of(w), np = ns * APPROX_STRAY_SAMPLES + !w->closed;
	struct crossing c = { w, malloc(2 * np * sizeof(double)), 0, 0, 0 };
	struct loft_grid g;
	double lo[2] = { HUGE_VAL, HUGE_VAL }, cell, sg[4];
	size_t e;

	if (w->dim != 2 || c.pt == NULL) {
		free(c.pt);
		return w->dim != 2 ? 0 : (size_t)-1;
	}
	c.ne = w->closed ? np : np - 1;
	for (size_t i = 0; i < np; i++) {
		size_t j = i / APPROX_STRAY_SAMPLES < ns ?
		    i / APPROX_STRAY_SAMPLES : ns - 1;

		span_eval(w, j, (double)(i - j * APPROX_STRAY_SAMPLES) /
		    APPROX_STRAY_SAMPLES, c.pt + 2 * i, NULL, NULL);
		lo[0] = fmin(lo[0], c.pt[2 * i]);
		lo[1] = fmin(lo[1], c.pt[2 * i + 1]);
	}
	cell = 2 * w->s[w->n] / c.ne;
	if (!(cell > 0) || loft_grid_init(&g, cell, cell, lo, 4 * c.ne) != 0) {
		free(c.pt);
		return cell > 0 ? (size_t)-1 : 0;
	}
	for (e = 0; e < c.ne; e++) {
		edge_of(&c, e, sg);
		if (loft_grid_add_segment(&g, sg, e) != 0)
			break;
	}
	for (size_t f = 0; f < c.ne && e == c.ne; f++) {
		edge_of(&c, c.e = f, sg);
		loft_grid_each_along(&g, sg, edge_crosses, &c);
	}
	if (e == c.ne)
		fold_spans(&c);
	loft_grid_free(&g);
	free(c.pt);
	return e == c.ne ? c.bad : (size_t)-1;
}

/* Both checks once every point is within the tolerance: the spans that
 * stray or cross, marked; how many.  The marks of an earlier check are
 * cleared first (from the points' feet, as fit_project left them), or
 * a span still astray from then would not be counted. */
static size_t
check_spans(struct work *w, double worst)
{
	size_t bad, cross;

	if (worst > w->tol)
		return 0;
	span_max(w);
	memset(w->cut, 0, w->m);
	memset(w->kidx, 0, nseg_of(w) * sizeof *w->kidx);
	for (size_t i = 0; i < w->n; i++)
		w->kidx[w->fj[i]]++;
	bad = stray_spans(w);
	if ((cross = crossing_spans(w)) == (size_t)-1) {
		w->nomem = 1;
		return cross;
	}
	return bad + cross;
}

/*
 * Split every span with a point farther than the tolerance (only ==
 * ALL_SPANS) or span only, where it has at least APPROX_SPLIT_MIN
 * points, at its middle, while the knots number at most the points.
 * Returns how many were split.
 */
#define ALL_SPANS ((size_t)-1)
static size_t
split(struct work *w, size_t only)
{
	int dim = w->dim;
	size_t ns = nseg_of(w), *count = w->kidx, add = 0, *to = w->corner;
	double *kn = w->acc;    /* the new knots, in the sums' room */
	unsigned char *fx = (unsigned char *)w->wsum;

	memset(count, 0, ns * sizeof *count);
	for (size_t i = 0; i < w->n; i++)
		count[w->fj[i]]++;
	for (size_t j = 0; j < ns; j++) {
		count[j] = (only == j || (only == ALL_SPANS &&
		    w->spanmax[j] > w->tol)) && (count[j] >= APPROX_SPLIT_MIN ||
		    w->spanmax[j] == APPROX_FORCE) && w->m + add < w->n;
		add += count[j];
	}
	if (add == 0)
		return 0;
	for (size_t j = 0; j < ns; j++)
		if (count[j] && w->spanmax[j] == APPROX_FORCE) {
			near_edges(w);  /* polyline_foot's, for the feet now */
			break;
		}
	/* knots and their flags, the new after the span's first; to[j]: where
	 * knot j goes */
	for (size_t j = 0, t = 0; j < w->m; j++) {
		vcopy(kn + t * dim, w->k + j * dim, dim);
		fx[t] = w->fixed[j];
		to[j] = t++;
		if (j < ns && count[j]) {
			loft_cubic_eval(w->seg + j * 4 * dim, dim, 0.5,
			    kn + t * dim, NULL, NULL);
			if (w->spanmax[j] == APPROX_FORCE) {
				/* a span astray: the new knot on the points */
				double x[LOFT_MAXDIM];

				vcopy(x, kn + t * dim, dim);
				polyline_foot(w, j, x, kn + t * dim);
				if (fmin(vdist(kn + t * dim, w->k + j * dim,
				    dim), vdist(kn + t * dim, w->k + ((j + 1) %
				    w->m) * dim, dim)) < APPROX_APART * w->tol) {
					/* at a knot: the chord's middle */
					vcopy(kn + t * dim, w->k + j * dim, dim);
					vaxpy(kn + t * dim, 1, w->k + ((j + 1) %
					    w->m) * dim, dim);
					vscale(kn + t * dim, 0.5, kn + t * dim,
					    dim);
				}
			}
			fx[t++] = 0;
		}
	}
	for (size_t i = 0; i < w->n; i++) {
		size_t j = w->fj[i];

		if (count[j]) {
			w->fj[i] = to[j] + (w->fu[i] >= 0.5);
			w->fu[i] = w->fu[i] >= 0.5 ? 2 * w->fu[i] - 1 :
			    2 * w->fu[i];
		} else {
			w->fj[i] = to[j];
		}
	}
	w->m += add;
	memcpy(w->k, kn, w->m * dim * sizeof *w->k);
	memcpy(w->fixed, fx, w->m);
	list_corners(w);
	return add;
}

/* Whether span j is within APPROX_WINDOW spans of span c. */
static int
in_window(const struct work *w, size_t j, size_t c)
{
	size_t ns = nseg_of(w), d = j >= c ? j - c : c - j;

	if (w->closed && ns - d < d)
		d = ns - d;
	return d <= APPROX_WINDOW;
}

/* Remove knot r (free, not an end), its two spans merged into one;
 * returns the merged span. */
static size_t
remove_knot(struct work *w, size_t r)
{
	int dim = w->dim;
	size_t m = w->m, before = r > 0 ? r - 1 : m - 1;
	size_t merged = r > 0 ? r - 1 : m - 2;

	for (size_t i = 0; i < w->n; i++) {
		size_t j = w->fj[i];

		if (j == before) {
			w->fj[i] = merged;
			w->fu[i] /= 2;
		} else if (j == r) {
			w->fj[i] = merged;
			w->fu[i] = 0.5 + w->fu[i] / 2;
		} else {
			w->fj[i] = j > r ? j - 1 : j;
		}
	}
	memmove(w->k + r * dim, w->k + (r + 1) * dim,
	    (m - r - 1) * dim * sizeof *w->k);
	memmove(w->fixed + r, w->fixed + r + 1, m - r - 1);
	memmove(w->tried + r, w->tried + r + 1, m - r - 1);
	w->m--;
	list_corners(w);
	return merged;
}

/*
 * The sweeps of a try, on the points marked near (those of the spans
 * within APPROX_WINDOW of span c), moving the knots between those
 * spans; returns the largest distance of those points after, or
 * HUGE_VAL when the fit fails, and the sum of their squares in *ss.
 */
static double
local_sweeps(struct work *w, size_t c, double *ss)
{
	int dim = w->dim;
	size_t m = w->m;
	double worst = 0;
	struct loft_error err;

	if (fit_curve(w, &err) != 0)
		return HUGE_VAL;
	for (int s = 0; s <= APPROX_TRY_SWEEPS; s++) {
		memset(w->acc, 0, m * dim * sizeof *w->acc);
		memset(w->wsum, 0, m * sizeof *w->wsum);
		worst = 0;
		*ss = 0;
		for (size_t i = 0; i < w->n; i++) {
			size_t a, b;
			double p[LOFT_MAXDIM], r[LOFT_MAXDIM], u, d;

			if (!w->near[i])
				continue;
			d = project(w, w->q + i * dim, &w->fj[i], &w->fu[i]);
			worst = fmax(worst, d);
			*ss += d * d;
			a = w->fj[i], b = a + 1 < m ? a + 1 : 0, u = w->fu[i];
			span_eval(w, a, u, p, NULL, NULL);
			vsub(r, w->q + i * dim, p, dim);
			vaxpy(w->acc + a * dim, 1 - u, r, dim);
			vaxpy(w->acc + b * dim, u, r, dim);
			w->wsum[a] += 1 - u;
			w->wsum[b] += u;
		}
		if (s == APPROX_TRY_SWEEPS || !(worst <= HUGE_VAL))
			break;
		for (size_t j = 0; j < m; j++) {
			/* knot j joins spans j - 1 and j */
			size_t prev = j > 0 ? j - 1 : nseg_of(w) - 1;

			if (w->fixed[j] || !(w->wsum[j] > 0) ||
			    (!w->closed && (j == 0 || j == m - 1)) ||
			    !in_window(w, j, c) || !in_window(w, prev, c))
				continue;
			vaxpy(w->k + j * dim, 1 / w->wsum[j], w->acc + j * dim,
			    dim);
		}
		if (fit_curve(w, &err) != 0)
			return HUGE_VAL;
	}
	return worst;
}

/* Whether knot j may be removed: free, not an end, and more left than
 * a curve needs (one more, to keep room to bend). */
static int
removable(const struct work *w, size_t j)
{
	size_t mins = w->closed ? LOFT_MIN_CLOSED + 1 : LOFT_MIN_OPEN + 1;

	return w->m > mins && !w->fixed[j] &&
	    (w->closed || (j > 0 && j + 1 < w->m));
}

/* Remove the knots of the loops marked to cut (mark_loop), last first,
 * while the curve keeps more knots than it needs; returns how many. */
static size_t
cut_loops(struct work *w)
{
	size_t cut = 0;

	for (size_t r = w->m; r-- > 0;)
		if (w->cut[r] && removable(w, r)) {
			remove_knot(w, r);
			cut++;
		}
	return cut;
}

static void
save_state(struct work *w)
{
	int dim = w->dim;

	memcpy(w->sk, w->k, w->m * dim * sizeof *w->k);
	memcpy(w->sseg, w->seg, 4 * dim * nseg_of(w) * sizeof *w->seg);
	memcpy(w->sfixed, w->fixed, w->m);
	memcpy(w->stried, w->tried, w->m);
	memcpy(w->sfj, w->fj, w->n * sizeof *w->fj);
	memcpy(w->sfu, w->fu, w->n * sizeof *w->fu);
	memcpy(w->sdist, w->dist, w->n * sizeof *w->dist);
	w->sm0 = w->m;
}

static void
restore_state(struct work *w)
{
	int dim = w->dim;

	w->m = w->sm0;
	memcpy(w->k, w->sk, w->m * dim * sizeof *w->k);
	memcpy(w->seg, w->sseg, 4 * dim * nseg_of(w) * sizeof *w->seg);
	memcpy(w->fixed, w->sfixed, w->m);
	memcpy(w->tried, w->stried, w->m);
	memcpy(w->fj, w->sfj, w->n * sizeof *w->fj);
	memcpy(w->fu, w->sfu, w->n * sizeof *w->fu);
	memcpy(w->dist, w->sdist, w->n * sizeof *w->dist);
	powers(w);
	list_corners(w);
}

/*
 * Remove knot r (the state saved first) and settle the knots near it:
 * returns the largest distance of the points near it after (HUGE_VAL
 * when the fit fails) and how much the sum of their squares grew in
 * *grow.  The caller keeps it, or restores the state.
 */
static double
try_remove(struct work *w, size_t r, double *grow)
{
	size_t c;
	double before = 0, after = 0, d;

	save_state(w);
	c = remove_knot(w, r);
	for (size_t i = 0; i < w->n; i++) {
		w->near[i] = (unsigned char)in_window(w, w->fj[i], c);
		if (w->near[i])
			before += w->dist[i] * w->dist[i];
	}
	d = local_sweeps(w, c, &after);
	*grow = after - before;
	return d;
}

/* A try kept: the distances of the points near it, and the spans'. */
static void
keep_try(struct work *w)
{
	for (size_t i = 0; i < w->n; i++)
		if (w->near[i])
			w->dist[i] = project(w, w->q + i * w->dim, &w->fj[i],
			    &w->fu[i]);
	span_max(w);
}

/*
 * Once the tolerance is met: try removing each free knot, those whose
 * spans have the most room first (the least largest distance), and
 * keep each removal after which the points near it are still within the
 * tolerance and fit nearly as well (APPROX_NEED).
 */
static void
remove_knots(struct work *w)
{
	double var = 0;

	for (size_t i = 0; i < w->n; i++)
		var += w->dist[i] * w->dist[i];
	var /= w->n;
	memset(w->tried, 0, w->m);
	for (;;) {
		size_t best = w->m, ns = nseg_of(w);
		double room = HUGE_VAL, grow, d;

		for (size_t j = 0; j < w->m; j++) {
			size_t prev = j > 0 ? j - 1 : ns - 1;

			if (w->tried[j] || !removable(w, j))
				continue;
			d = fmax(w->spanmax[prev], w->spanmax[j]);
			if (d < room) {
				room = d;
				best = j;
			}
		}
		if (best == w->m)
			return;
		w->tried[best] = 1;
		d = try_remove(w, best, &grow);
		if (d <= w->tol && grow < APPROX_NEED * var)
			keep_try(w);
		else
			restore_state(w);
	}
}

/* The turn at sample t of the plane curve (APPROX_KSAMPLES a span, at
 * the middles of equal parts): the curvature times the length of the
 * part, in *x; returns its sign, 0 where the curvature times the
 * length of the curve is below APPROX_FLAT. */
static int
sample_turn(const struct work *w, size_t t, double *x)
{
	size_t ns = nseg_of(w);
	double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 }, v, k;
	double u = ((t % APPROX_KSAMPLES) + 0.5) / APPROX_KSAMPLES;

	span_eval(w, t / APPROX_KSAMPLES, u, p, d1, d2);
	v = hypot(d1[0], d1[1]);
	*x = 0;
	if (!(v > 0))
		return 0;
	k = (d1[0] * d2[1] - d1[1] * d2[0]) / (v * v * v);
	*x = k * v / APPROX_KSAMPLES;
	if (!(fabs(*x) * ns > APPROX_FLAT))
		return 0;
	return k > 0 ? 1 : -1;
}

/*
 * The sign changes of the curvature of a plane curve (its inflexions),
 * returned, and its weakest wiggle: the run of one sign between two
 * changes whose turn (the integral of the curvature along it) is least,
 * below APPROX_WIGGLE and above floor: its spans *ja to *jb (cyclically
 * on a closed curve), its turn *turn (HUGE_VAL when there is none) and
 * the sign of its curvature *wsign.
 */
static size_t
wiggle(const struct work *w, double floor, size_t *ja, size_t *jb,
    double *turn, int *wsign)
{
	size_t total = nseg_of(w) * APPROX_KSAMPLES, t0 = 0, start, changes = 0;
	int sign = 0, last = 0;
	double sum = 0, x;

	*turn = HUGE_VAL;
	if (total == 0)         /* no span: never, the ends stay knots */
		return 0;
	if (w->closed) {
		/* start at a change, so that every run lies between two */
		for (size_t t = 0; t < total; t++) {
			int sg = sample_turn(w, t, &x);

			last = sg ? sg : last;
		}
		for (; t0 < total; t0++) {
			int sg = sample_turn(w, t0, &x);

			if (sg && sg != last)
				break;
			last = sg ? sg : last;
		}
		if (t0 == total)
			return 0;
	}
	start = t0;
	for (size_t i = 0; i <= total; i++) {
		size_t t = (t0 + i) % total;
		int sg = i < total ? sample_turn(w, t, &x) : 0;

		if (i < total && (sg == 0 || sg == sign || sign == 0)) {
			sign = sign ? sign : sg;
			sum += x;
			continue;
		}
		/* a run from start to t ends; an open curve's first and last
		 * have no change beyond them */
		if ((w->closed || (start != 0 && i < total)) &&
		    fabs(sum) < APPROX_WIGGLE && fabs(sum) > floor &&
		    fabs(sum) < *turn) {
			*turn = fabs(sum);
			*wsign = sum > 0 ? 1 : -1;
			*ja = start / APPROX_KSAMPLES;
			*jb = ((t + total - 1) % total) / APPROX_KSAMPLES;
		}
		if (i < total || w->closed)
			changes++;
		start = t;
		sign = sg;
		sum = x;
	}
	return changes;
}

/*
 * A removal that straightened a wiggle but left points near it beyond
 * the tolerance: split the span nearby with the farthest point instead,
 * settle the knots near it, and keep that if every point is within the
 * tolerance and the inflexions are still fewer than changes.
 */
static int
relocate(struct work *w, size_t changes)
{
	size_t ja, jb;
	double turn, ss;
	int sg;

	keep_try(w);
	for (int t = 0; t < APPROX_RELOCATE; t++) {
		size_t worst = ALL_SPANS;
		double far = 0;
		int over = 0;

		for (size_t i = 0; i < w->n; i++)
			if (w->near[i] && w->spanmax[w->fj[i]] > far) {
				far = w->spanmax[w->fj[i]];
				worst = w->fj[i];
			}
		if (worst == ALL_SPANS || split(w, worst) == 0)
			return 0;
		for (size_t i = 0; i < w->n; i++)
			w->near[i] = (unsigned char)in_window(w, w->fj[i], worst);
		local_sweeps(w, worst, &ss);
		for (size_t i = 0; i < w->n; i++)
			w->dist[i] = project(w, w->q + i * w->dim, &w->fj[i],
			    &w->fu[i]);
		span_max(w);
		for (size_t j = 0; j < nseg_of(w); j++)
			over |= w->spanmax[j] > w->tol;
		if (!over)
			return wiggle(w, 0, &ja, &jb, &turn, &sg) < changes;
		for (size_t i = 0; i < w->n; i++)
			w->near[i] = (unsigned char)(w->dist[i] > w->tol);
	}
	return 0;
}

/*
 * Straighten the wiggles: a stretch of curvature of the other sign
 * between two inflexions that turns by less than APPROX_WIGGLE is
 * noise a knot holds, not a shape the tolerance asks for.  For each,
 * weakest first, remove the first knot on or next to it after which
 * the points are within the tolerance and there are fewer inflexions.
 */
static void
straighten(struct work *w)
{
	double floor = 0, turn, grow;
	size_t ja = 0, jb = 0;  /* set by wiggle() where turn is finite */
	int sg;

	if (w->dim != 2)
		return;
	memset(w->tried, 0, w->m);
	for (;;) {
		size_t changes = wiggle(w, floor, &ja, &jb, &turn, &sg);
		size_t m = w->m;
		int done = 0;

		if (turn == HUGE_VAL)
			return;
		for (size_t t = 0; t <= (jb + m - ja) % m + 1 && !done; t++) {
			size_t r = (ja + t) % m;
			size_t a2, b2;
			double t2;

			if (!removable(w, r))
				continue;
			if (try_remove(w, r, &grow) <= w->tol &&
			    wiggle(w, 0, &a2, &b2, &t2, &sg) < changes) {
				keep_try(w);
				done = 1;
			} else if (wiggle(w, 0, &a2, &b2, &t2, &sg) < changes &&
			    relocate(w, changes)) {
				done = 1;
			} else {
				restore_state(w);
			}
		}
		if (!done)
			floor = turn;
	}
}

/*
 * The wiggles no removal straightens (the points near them leave no
 * room for fewer knots) are faired instead (fair_wiggles): the knots
 * near one move along their normals to where the points fit best with
 * the curvature on the wiggle's spans of the sign of the curve round
 * it.  Levenberg-Marquardt steps (fair_step) on a merit: the squares of
 * the points' distances along their normals, APPROX_FAIR_HEAVY times
 * the squares of what they go beyond APPROX_FAIR_USE of the tolerance,
 * and a weight times the squares of what the curvature times the
 * curve's length falls short of APPROX_FAIR_MARGIN at the samples
 * (APPROX_FAIR_SAMPLES a span and where the span's is least); each
 * weight grows by APPROX_FAIR_PENALTY after a step that leaves its
 * fault.  The derivatives are differences of the curve through the
 * knots moved by APPROX_FAIR_DIFF of the tolerance.  The best right
 * state of APPROX_FAIR_STEPS (least sum of squares, every point near
 * within the tolerance, every sample of its sign) is kept when every
 * point is within the tolerance, the inflexions, counted exactly
 * (wiggle_exact), are fewer and the bending energy is no more than
 * APPROX_FAIR_ENERGY above; else the knots are as they were.
 */
#define APPROX_FAIR_STEPS 30
/* A wiggle straightened bends the curve less: a fairing that raises its
 * bending energy by more than this fraction has bent it elsewhere (to a
 * cusp, at worst) and is not kept. */
#define APPROX_FAIR_ENERGY 0.01
/* The knots moved: those of the wiggle's spans and one more either
 * side, or, when that fails, APPROX_FAIR_WIDE more; at most
 * APPROX_FAIR_KNOTS (a longer wiggle is not one). */
#define APPROX_FAIR_WIDE 2
#define APPROX_FAIR_KNOTS 12
/* A curvature times the length of the curve this small is as good as
 * the wrong sign: the judge of a sign is APPROX_FLAT, far below. */
#define APPROX_FAIR_MARGIN 1e-3
#define APPROX_FAIR_DIFF 1e-4
#define APPROX_FAIR_USE 0.9
#define APPROX_FAIR_HEAVY 100.0
#define APPROX_FAIR_PENALTY 10.0
/* Dampings tried a step at most (each tenfold), and the least damping
 * (of the normal equations' diagonal). */
#define APPROX_FAIR_TRIES 8
#define APPROX_FAIR_MU 1e-3
/* Curvature samples a span, and one more where it is least. */
#define APPROX_FAIR_SAMPLES 32
#define APPROX_FAIR_TS (APPROX_FAIR_KNOTS * (APPROX_FAIR_SAMPLES + 1))

struct fairing {
	size_t nv, np, nt;      /* knots moved, points, curvature samples */
	size_t kv[APPROX_FAIR_KNOTS];
	double nrm[APPROX_FAIR_KNOTS][2];
	size_t *pi, *tsj;       /* the points near; the samples' spans */
	double *tsu;            /* and where on them */
	double *nf, *c0, *d, *a, *kap, *g;
	double len;             /* the curve's length */
	int sign;               /* the sign the samples should have */
	int wide;               /* knots moved beyond the wiggle either side */
	double heavy;           /* the weight of the distances beyond use */
	double ss;              /* the sum of the squares of the distances */
	double best, kbest[APPROX_FAIR_KNOTS][2];  /* the best that is right */
};

/* The curvature of span j at u times the curve's length. */
static double
kappa_len(const struct work *w, size_t j, double u, double len)
{
	double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 }, v;

	span_eval(w, j, u, p, d1, d2);
	v = hypot(d1[0], d1[1]);
	return v > 0 ? (d1[0] * d2[1] - d1[1] * d2[0]) / (v * v * v) * len : 0;
}

/* The curve's length, from the curvature samples' points. */
static double
curve_len(const struct work *w)
{
	double len = 0;

	for (size_t t = 0; t < nseg_of(w) * APPROX_KSAMPLES; t++) {
		double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 };

		span_eval(w, t / APPROX_KSAMPLES, ((t % APPROX_KSAMPLES) + 0.5) /
		    APPROX_KSAMPLES, p, d1, d2);
		len += hypot(d1[0], d1[1]) / APPROX_KSAMPLES;
	}
	return len;
}

/* Span j + o, cyclically on a closed curve; ALL_SPANS off an open one. */
static size_t
span_off(const struct work *w, size_t j, long o)
{
	long ns = (long)nseg_of(w), t = (long)j + o;

	if (w->closed)
		return (size_t)(((t % ns) + ns) % ns);
	return t < 0 || t >= ns ? ALL_SPANS : (size_t)t;
}

/* The numerator of the curvature of plane span j, the cross product of
 * its first two derivatives, a quadratic q[0] + q[1] u + q[2] u^2. */
static void
span_cross(const struct work *w, size_t j, double *q)
{
	const double *c = w->pow + j * 8;

	q[0] = 2 * (c[2] * c[5] - c[3] * c[4]);
	q[1] = 6 * (c[2] * c[7] - c[3] * c[6]);
	q[2] = 6 * (c[4] * c[7] - c[5] * c[6]);
}

/* The sign of the curvature of span j at u, 0 where the curvature
 * times the length len is below APPROX_FLAT. */
static int
cross_sign(const struct work *w, size_t j, double u, double len)
{
	return kappa_len(w, j, u, len) > APPROX_FLAT ? 1 :
	    kappa_len(w, j, u, len) < -APPROX_FLAT ? -1 : 0;
}

/* Where on span j the quadratic q is least times sign: 0, 1 or its
 * vertex. */
static double
cross_least(const double *q, int sign)
{
	double best = 0, f0 = sign * q[0], f1 = sign * (q[0] + q[1] + q[2]);

	if (f1 < f0)
		best = 1, f0 = f1;
	if (q[2] != 0) {
		double u = -q[1] / (2 * q[2]);

		if (u > 0 && u < 1 && sign * (q[0] + u * (q[1] + u * q[2])) < f0)
			best = u;
	}
	return best;
}

/* The tangent's angle turned from (j0, u0) to (j1, u1) along the curve,
 * in steps of at most 1 / APPROX_KSAMPLES of a span. */
static double
turn_between(const struct work *w, size_t j0, double u0, size_t j1, double u1)
{
	double p[2] = { 0, 0 }, a[2] = { 0, 0 }, b[2] = { 0, 0 };
	double d2[2] = { 0, 0 }, turn = 0;
	size_t j = j0, ns = nseg_of(w);
	double u = u0;

	span_eval(w, j, u, p, a, d2);
	for (int guard = 0; guard < (int)(ns + 1) * APPROX_KSAMPLES + 2;
	    guard++) {
		int last = j == j1 && u1 >= u && u1 - u <= 1.0 / APPROX_KSAMPLES;

		u = last ? u1 : u + 1.0 / APPROX_KSAMPLES;
		if (u > 1 && !last) {
			span_eval(w, j, 1, p, b, d2);
			turn += atan2(a[0] * b[1] - a[1] * b[0], vdot(a, b, 2));
			vcopy(a, b, 2);
			j = (j + 1) % ns;
			u = 0;
			continue;
		}
		span_eval(w, j, u, p, b, d2);
		turn += atan2(a[0] * b[1] - a[1] * b[0], vdot(a, b, 2));
		vcopy(a, b, 2);
		if (last)
			break;
	}
	return turn;
}

/*
 * The inflexions of a plane curve found exactly (where the quadratic
 * numerator of each span's curvature changes sign), returned (0, and
 * w->nomem set, out of memory), and its weakest wiggle as for wiggle():
 * the run between two of them whose turn is least, below APPROX_WIGGLE
 * and above floor.
 */
static size_t
wiggle_exact(struct work *w, double floor, size_t *ja, size_t *jb,
    double *turn, int *wsign)
{
	size_t ns = nseg_of(w), nch = 0, cap = 4 * ns + 4;
	size_t *cj = malloc(cap * sizeof *cj);
	double *cu = malloc(cap * sizeof *cu), len = curve_len(w);
	int last = 0;

	*turn = HUGE_VAL;
	if (cj == NULL || cu == NULL) {
		free(cj);
		free(cu);
		w->nomem = 1;
		return 0;
	}
	for (int pass = 0; pass < 1 + w->closed; pass++)
		for (size_t j = 0; j < ns; j++) {
			double q[3], at[3] = { 0, 0.5, 1 };
			int n = 3;

			span_cross(w, j, q);
			if (q[2] != 0 && -q[1] / (2 * q[2]) > 0 &&
			    -q[1] / (2 * q[2]) < 1)
				at[1] = -q[1] / (2 * q[2]);
			for (int k = 0; k < n; k++) {
				int sg = cross_sign(w, j, at[k], len);
				double lo = k > 0 ? at[k - 1] : 0, hi = at[k];

				if (sg == 0 || sg == last) {
					last = sg ? sg : last;
					continue;
				}
				if (last != 0 && pass == w->closed) {
					for (int b = 0; b < 60 && k > 0; b++) {
						double mid = (lo + hi) / 2;

						int at = cross_sign(w, j, mid, len);

						*(at == sg ? &hi : &lo) = mid;
					}
					cj[nch] = j;
					cu[nch++] = k > 0 ? hi : 0;
				}
				last = sg;
			}
		}
	for (size_t c = 0; c + (w->closed ? 0 : 1) < nch; c++) {
		size_t d = (c + 1) % nch;
		double t = turn_between(w, cj[c], cu[c], cj[d], cu[d]);

		if (nch < 2)
			break;
		if (fabs(t) < APPROX_WIGGLE && fabs(t) > floor &&
		    fabs(t) < *turn) {
			*turn = fabs(t);
			*wsign = t > 0 ? 1 : -1;
			*ja = cj[c];
			*jb = cj[d];
		}
	}
	free(cj);
	free(cu);
	return nch;
}

/* The knots to move (those of the wiggle's spans ja..jb and f->wide
 * beyond either side, free), the points near (on the spans one more
 * beyond) and the curvature samples (of the wiggle's spans); 0 when too
 * many or none. */
static int
fair_setup(struct work *w, struct fairing *f, size_t ja, size_t jb,
    unsigned char *on)
{
	size_t ns = nseg_of(w), len = (jb + ns - ja) % ns + 1;

	if (!w->closed)
		len = jb - ja + 1;
	f->nv = f->np = f->nt = 0;
	if (len + 1 + 2 * (size_t)f->wide > APPROX_FAIR_KNOTS ||
	    len + 2 + 2 * (size_t)f->wide >= ns)
		return 0;
	for (long o = -f->wide; o <= (long)len + f->wide; o++) {
		size_t j = span_off(w, ja, o);

		/* knot j starts span j; an open curve's last is an end */
		if (j == ALL_SPANS || w->fixed[j] || (!w->closed &&
		    (j == 0 || j == w->m - 1)))
			continue;
		f->kv[f->nv++] = j;
	}
	memset(on, 0, ns);
	for (long o = -f->wide - 1; o < (long)len + f->wide + 1; o++)
		if (span_off(w, ja, o) != ALL_SPANS)
			on[span_off(w, ja, o)] = 1;
	for (size_t i = 0; i < w->n; i++)
		if (on[w->fj[i]])
			f->pi[f->np++] = i;
	for (size_t o = 0; o < len; o++)
		for (size_t t = 0; t <= APPROX_FAIR_SAMPLES; t++) {
			f->tsj[f->nt] = span_off(w, ja, (long)o);
			f->tsu[f->nt++] = t < APPROX_FAIR_SAMPLES ? (t + 0.5) /
			    APPROX_FAIR_SAMPLES : -1;
		}
	return f->nv > 0;
}

/* The normals at the knots to move, from the current curve. */
static void
fair_normals(const struct work *w, struct fairing *f)
{
	for (size_t v = 0; v < f->nv; v++) {
		size_t j = f->kv[v];
		double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 }, s;

		if (j < nseg_of(w))
			span_eval(w, j, 0, p, d1, d2);
		else
			span_eval(w, j - 1, 1, p, d1, d2);
		s = hypot(d1[0], d1[1]);
		f->nrm[v][0] = s > 0 ? -d1[1] / s : 0;
		f->nrm[v][1] = s > 0 ? d1[0] / s : 0;
	}
}

/* The points' feet on the curve and their curve points, and the
 * samples' curvatures, into c0 and kap (or, after a knot's move, the
 * column col of the derivatives, into a and g). */
static void
fair_eval(const struct work *w, struct fairing *f, long col, double h)
{
	for (size_t k = 0; k < f->np; k++) {
		size_t i = f->pi[k];
		double p[2] = { 0, 0 };

		span_eval(w, w->fj[i], w->fu[i], p, NULL, NULL);
		if (col < 0) {
			vcopy(f->c0 + 2 * k, p, 2);
		} else {
			f->a[k * f->nv + col] = (f->nf[2 * k] * (p[0] -
			    f->c0[2 * k]) + f->nf[2 * k + 1] * (p[1] -
			    f->c0[2 * k + 1])) / h;
		}
	}
	for (size_t k = 0; k < f->nt; k++) {
		double kl;

		if (col < 0 && (k + 1) % (APPROX_FAIR_SAMPLES + 1) == 0) {
			/* the span's least, held during the differences */
			double q[3];

			span_cross(w, f->tsj[k], q);
			f->tsu[k] = cross_least(q, f->sign);
		}
		kl = kappa_len(w, f->tsj[k], f->tsu[k], f->len);

		if (col < 0)
			f->kap[k] = kl;
		else
			f->g[k * f->nv + col] = -f->sign * (kl - f->kap[k]) / h;
	}
}

/* The feet of the points near, their signed distances and normals. */
static void
fair_feet(struct work *w, struct fairing *f)
{
	for (size_t k = 0; k < f->np; k++) {
		size_t i = f->pi[k];
		double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 }, s;

		project(w, w->q + i * 2, &w->fj[i], &w->fu[i]);
		span_eval(w, w->fj[i], w->fu[i], p, d1, d2);
		s = hypot(d1[0], d1[1]);
		f->nf[2 * k] = s > 0 ? -d1[1] / s : 0;
		f->nf[2 * k + 1] = s > 0 ? d1[0] / s : 0;
		f->d[k] = f->nf[2 * k] * (w->q[2 * i] - p[0]) +
		    f->nf[2 * k + 1] * (w->q[2 * i + 1] - p[1]);
	}
}

/* The merit of the knots as they are: the squares of the points'
 * distances, heavy times the squares of what they go beyond
 * APPROX_FAIR_USE of the tolerance, lambda times the squares of what the
 * curvature falls short of APPROX_FAIR_MARGIN in its sign; and whether
 * a point is beyond the tolerance (*far) or a sample short (*bent). */
static double
fair_merit(struct work *w, struct fairing *f, double lambda, int *far,
    int *bent)
{
	double sum = 0, use = APPROX_FAIR_USE * w->tol;

	fair_feet(w, f);
	fair_eval(w, f, -1, 0);
	*far = *bent = 0;
	for (size_t k = 0; k < f->np; k++)
		sum += f->d[k] * f->d[k];
	f->ss = sum;
	for (size_t k = 0; k < f->np; k++) {
		double over = fabs(f->d[k]) - use;

		if (over > 0)
			sum += f->heavy * over * over;
		*far |= fabs(f->d[k]) > w->tol;
	}
	for (size_t k = 0; k < f->nt; k++) {
		double gap = APPROX_FAIR_MARGIN - f->sign * f->kap[k];

		if (gap > 0)
			sum += lambda * gap * gap;
		*bent |= gap > 0;
	}
	return sum;
}

/* The derivatives of the distances (a) and the curvature's shortfalls
 * (g) in the moves of the knots along their normals, by differences. */
static int
fair_jacobian(struct work *w, struct fairing *f)
{
	double h = APPROX_FAIR_DIFF * w->tol;
	struct loft_error err;

	fair_normals(w, f);
	for (size_t v = 0; v < f->nv; v++) {
		double *kn = w->k + f->kv[v] * 2;

		vaxpy(kn, h, f->nrm[v], 2);
		if (fit_curve(w, &err) != 0)
			return -1;
		fair_eval(w, f, (long)v, h);
		vaxpy(kn, -h, f->nrm[v], 2);
	}
	return fit_curve(w, &err);
}

/* The normal equations of the merit's linear model, damped by mu times
 * their diagonal, solved into x; -1 if singular. */
static int
fair_solve(const struct work *w, const struct fairing *f, double lambda,
    double mu, double *x)
{
	size_t nv = f->nv;
	double m[APPROX_FAIR_KNOTS * APPROX_FAIR_KNOTS], use = APPROX_FAIR_USE *
	    w->tol;

	memset(m, 0, sizeof m);
	memset(x, 0, nv * sizeof *x);
	for (size_t k = 0; k < f->np; k++) {
		const double *ak = f->a + k * nv;
		double over = fabs(f->d[k]) - use, wt = over > 0 ? 1 + f->heavy :
		    1, rhs = f->d[k];

		if (over > 0)   /* d - a x and (|d| - use) - sgn(d) a x */
			rhs += f->heavy * over * (f->d[k] > 0 ? 1 : -1);
		for (size_t r = 0; r < nv; r++) {
			x[r] += rhs * ak[r];
			for (size_t c = 0; c < nv; c++)
				m[r * nv + c] += wt * ak[r] * ak[c];
		}
	}
	for (size_t k = 0; k < f->nt; k++) {
		const double *gk = f->g + k * nv;
		double gap = APPROX_FAIR_MARGIN - f->sign * f->kap[k];

		if (!(gap > 0))
			continue;
		for (size_t r = 0; r < nv; r++) {
			x[r] -= lambda * gap * gk[r];
			for (size_t c = 0; c < nv; c++)
				m[r * nv + c] += lambda * gk[r] * gk[c];
		}
	}
	for (size_t r = 0; r < nv; r++)
		m[r * nv + r] = m[r * nv + r] * (1 + mu) + 1e-300;
	return loft__cholesky_solve(m, x, nv, 0, NULL, NULL);
}

/* The knots moved along their normals by s times x. */
static void
fair_move(struct work *w, const struct fairing *f, const double *x, double s)
{
	for (size_t v = 0; v < f->nv; v++)
		vaxpy(w->k + f->kv[v] * 2, s * x[v], f->nrm[v], 2);
}

/* The first weight of the curvature: APPROX_FAIR_PENALTY times the
 * ratio of the distances' derivatives to the curvature's. */
static double
fair_lambda(const struct fairing *f)
{
	double sa = 0, sg = 0;

	for (size_t k = 0; k < f->np * f->nv; k++)
		sa += f->a[k] * f->a[k];
	for (size_t k = 0; k < f->nt * f->nv; k++)
		sg += f->g[k] * f->g[k];
	return sg > 0 ? APPROX_FAIR_PENALTY * sa / sg : 1;
}

/* Keep the knots as the best when they are right (no point near
 * beyond the tolerance, no sample short) and fit better. */
static void
fair_best(const struct work *w, struct fairing *f, int far, int bent)
{
	if (far || bent || !(f->ss < f->best))
		return;
	f->best = f->ss;
	for (size_t v = 0; v < f->nv; v++)
		vcopy(f->kbest[v], w->k + f->kv[v] * 2, 2);
}

/*
 * One Levenberg-Marquardt step of the fairing: the model linearised,
 * the step damped until the merit falls (APPROX_FAIR_TRIES at most),
 * then the weights of what is still wrong grown (all of them, and the
 * damping reset, when no step lowers the merit).  The knots before the
 * step are kept when the best (fair_best).  Returns -1 when a fit
 * fails, else 0.
 */
static int
fair_step(struct work *w, struct fairing *f, double *lambda, double *mu)
{
	double x[APPROX_FAIR_KNOTS] = { 0 }, m0, m1;  /* f->nv of them */
	struct loft_error err;
	int far, bent;

	m0 = fair_merit(w, f, *lambda, &far, &bent);
	fair_best(w, f, far, bent);
	if (fair_jacobian(w, f) != 0)
		return -1;
	if (*lambda == 0) {
		*lambda = fair_lambda(f);
		m0 = fair_merit(w, f, *lambda, &far, &bent);
	}
	for (int t = 0; t < APPROX_FAIR_TRIES; t++, *mu *= 10) {
		if (fair_solve(w, f, *lambda, *mu, x) != 0)
			return -1;
		fair_move(w, f, x, 1);
		if (fit_curve(w, &err) != 0)
			return -1;
		m1 = fair_merit(w, f, *lambda, &far, &bent);
		if (m1 < m0) {
			*mu = fmax(*mu / 10, APPROX_FAIR_MU);
			if (bent)
				*lambda *= APPROX_FAIR_PENALTY;
			if (far)
				f->heavy *= APPROX_FAIR_PENALTY;
			return 0;
		}
		fair_move(w, f, x, -1);
		if (fit_curve(w, &err) != 0)
			return -1;
	}
	*lambda *= APPROX_FAIR_PENALTY;
	f->heavy *= APPROX_FAIR_PENALTY;
	*mu = APPROX_FAIR_MU;
	return 0;
}

/* The bending energy of the curve (the integral of the curvature
 * squared along it), by the midpoint rule over the curvature samples,
 * times the curve's length len (so free of the units). */
static double
curve_energy(const struct work *w, double len)
{
	double e = 0;

	for (size_t t = 0; t < nseg_of(w) * APPROX_KSAMPLES; t++) {
		double p[2] = { 0, 0 }, d1[2] = { 0, 0 }, d2[2] = { 0, 0 };
		double u = ((t % APPROX_KSAMPLES) + 0.5) /
		    APPROX_KSAMPLES, k;

		span_eval(w, t / APPROX_KSAMPLES, u, p, d1, d2);
		k = kappa_len(w, t / APPROX_KSAMPLES, u, 1);
		e += k * k * hypot(d1[0], d1[1]) / APPROX_KSAMPLES;
	}
	return isfinite(e) ? e * len : HUGE_VAL;
}

/* Fair the wiggle on spans ja..jb of curvature of sign wsign; 1 if
 * kept (every point within the tolerance, fewer inflexions than
 * changes), else the state as it was. */
static int
fair_one(struct work *w, struct fairing *f, size_t ja, size_t jb, int wsign,
    size_t changes, unsigned char *on)
{
	double lambda = 0, mu = APPROX_FAIR_MU, worst, energy;
	size_t at, a2, b2;
	struct loft_error err;
	int rc = 0, sg;
	double t2;

	if (!fair_setup(w, f, ja, jb, on))
		return 0;
	f->sign = -wsign;
	f->heavy = APPROX_FAIR_HEAVY;
	f->len = curve_len(w);
	energy = curve_energy(w, f->len);
	save_state(w);
	f->best = HUGE_VAL;
	for (int s = 0; s < APPROX_FAIR_STEPS && rc == 0; s++)
		rc = fair_step(w, f, &lambda, &mu);
	if (rc >= 0) {
		int far, bent;

		fair_merit(w, f, lambda, &far, &bent);
		fair_best(w, f, far, bent);
	}
	if (rc >= 0 && f->best < HUGE_VAL) {
		for (size_t v = 0; v < f->nv; v++)
			vcopy(w->k + f->kv[v] * 2, f->kbest[v], 2);
		rc = fit_curve(w, &err);
	}
	if (rc >= 0 && f->best < HUGE_VAL &&
	    fit_project(w, &worst, &at, &err) == 0 &&
	    worst <= w->tol &&
	    wiggle_exact(w, 0, &a2, &b2, &t2, &sg) < changes &&
	    curve_energy(w, curve_len(w)) <= energy * (1 + APPROX_FAIR_ENERGY))
		return 1;
	restore_state(w);
	return 0;
}

/* Fair each wiggle left, weakest first (fair_one), that turns by less
 * than the tolerance over the mean length of a span: the tilt the band
 * of the tolerance allows a span, which noise may take up; a wiggle
 * that turns more the points draw. */
static int
fair_wiggles(struct work *w)
{
	struct fairing f;
	unsigned char *on = malloc(w->m);
	double floor = 0, turn;
	size_t ja = 0, jb = 0, nmax = w->n;
	int sg = 0, rc = 0;

	if (w->dim != 2) {
		free(on);
		return 0;
	}
	f.pi = malloc(nmax * sizeof *f.pi);
	f.tsj = malloc(APPROX_FAIR_TS * sizeof *f.tsj);
	f.tsu = malloc(APPROX_FAIR_TS * sizeof *f.tsu);
	f.nf = malloc(2 * nmax * sizeof *f.nf);
	f.c0 = malloc(2 * nmax * sizeof *f.c0);
	f.d = malloc(nmax * sizeof *f.d);
	f.a = malloc(nmax * APPROX_FAIR_KNOTS * sizeof *f.a);
	f.kap = malloc(APPROX_FAIR_TS * sizeof *f.kap);
	f.g = malloc(APPROX_FAIR_TS * APPROX_FAIR_KNOTS * sizeof *f.g);
	if (on == NULL || f.pi == NULL || f.tsj == NULL || f.tsu == NULL ||
	    f.nf == NULL || f.c0 == NULL || f.d == NULL || f.a == NULL ||
	    f.kap == NULL || f.g == NULL) {
		rc = -1;
	} else {
		for (;;) {
			size_t changes = wiggle_exact(w, floor, &ja, &jb, &turn,
			    &sg);

			if (turn == HUGE_VAL)
				break;
			if (turn >= w->tol * nseg_of(w) / curve_len(w)) {
				/* more than the band of the tolerance tilts a
				 * span by: the points draw it */
				floor = turn;
				continue;
			}
			f.wide = 1;
			if (fair_one(w, &f, ja, jb, sg, changes, on))
				continue;
			f.wide = APPROX_FAIR_WIDE;
			if (!fair_one(w, &f, ja, jb, sg, changes, on))
				floor = turn;
		}
	}
	free(on);
	free(f.pi);
	free(f.tsj);
	free(f.tsu);
	free(f.nf);
	free(f.c0);
	free(f.d);
	free(f.a);
	free(f.kap);
	free(f.g);
	return rc;
}

/* The span the curve written starts with: the one the input's first
 * point lies on (closed), else the first. */
static size_t
first_span(const struct work *w)
{
	return w->closed ? w->fj[(w->n - w->shift) % w->n] : 0;
}

/* The segments into seg from the start of the input: a closed curve's
 * rotated so the span of the input's first point comes first. */
static void
put_segments(const struct work *w, double *seg)
{
	size_t ns = nseg_of(w), row = 4 * w->dim, first = first_span(w);

	for (size_t j = 0; j < ns; j++)
		memcpy(seg + j * row, w->seg + ((j + first) % ns) * row,
		    row * sizeof *seg);
}

/* The spans check_spans marked astray (where it found bad > 0 of them)
 * as flags in the order of put_segments, into astray. */
static void
put_astray(const struct work *w, size_t bad, unsigned char *astray)
{
	size_t ns = nseg_of(w), first = first_span(w);

	for (size_t j = 0; j < ns; j++)
		astray[j] = bad > 0 &&
		    w->spanmax[(j + first) % ns] == APPROX_FORCE;
}

void
loft_approx_defaults(struct loft_approx_opts *o)
{
	memset(o, 0, sizeof *o);
	o->closed = 1;
	o->maxround = LOFT_APPROX_ROUNDS;
}

/* Correction sweeps until the knots settle (APPROX_SWEEPS at most). */
static int
settle(struct work *w, double *worst, size_t *at, struct loft_error *err)
{
	for (int s = 0; s < APPROX_SWEEPS; s++) {
		double move = correct(w);

		if (fit_project(w, worst, at, err) != 0)
			return LOFT_EGEOM;
		if (move < APPROX_SETTLED * w->tol)
			break;
	}
	return 0;
}

/* Where no span far from the points has points enough to split at
 * its middle (a span over a corner's few points): split each such span
 * anyway, its new knot on the points' polyline, so the curve is pulled
 * to them.  Returns how many. */
static size_t
split_far(struct work *w)
{
	for (size_t j = 0; j < nseg_of(w); j++)
		if (w->spanmax[j] > w->tol)
			w->spanmax[j] = APPROX_FORCE;
	return split(w, ALL_SPANS);
}

/* A span becomes straight where every point on it (this many at
 * least: a line needs points to lean on) is within APPROX_LINE_FRAC of
 * the tolerance of the chord between its knots: noise that close to a
 * line is the line's, and the rest of the tolerance is left for the
 * curve beside it, which the straight span now ends with its
 * direction. */
#define APPROX_LINE_FRAC 0.75

/* Whether the points on span j lie along the chord of its knots. */
static int
span_is_line(const struct work *w, size_t j)
{
	int dim = w->dim;
	const double *a = w->k + j * dim, *b = w->k + ((j + 1) % w->m) * dim;
	double u[LOFT_MAXDIM];
	size_t count = 0;

	vsub(u, b, a, dim);
	if (!(vunit(u, dim) > 0))
		return 0;
	for (size_t i = 0; i < w->n; i++) {
		double r[LOFT_MAXDIM];

		if (w->fj[i] != j)
			continue;
		vsub(r, w->q + i * dim, a, dim);
		vaxpy(r, -vdot(r, u, dim), u, dim);
		if (vnorm(r, dim) > APPROX_LINE_FRAC * w->tol)
			return 0;
		count++;
	}
	return count >= APPROX_LINE_MIN;
}

/* The inflexions of the curve as measure(1) counts them (exactly, a
 * straight stretch between bends of opposite sign one); 0 for a space
 * curve, whose curvature has no sign. */
static long
inflexions(const struct work *w)
{
	struct loft_curve c;
	struct loft_error err;
	long count;

	loft_curve_cubic(&c, w->seg, nseg_of(w), w->dim, w->closed);
	return loft_curve_inflexions(&c, &count, &err) == 0 ? count : 0;
}

/* Straight runs of points become straight spans: the spans whose points
 * lie along their chord are refitted straight, kept where every point
 * is still within the tolerance, the curve passes both checks and it
 * has no more inflexions than before (a line between bends of one sign
 * must not bring in reverse bends).  Returns 0, or an error. */
static int
straight_runs(struct work *w, double *worst, size_t *at,
    struct loft_error *err)
{
	size_t ns = nseg_of(w), nl = 0, *line = malloc(ns * sizeof *line);

	if (line == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t j = 0; j < ns; j++)
		if (span_is_line(w, j))
			line[nl++] = j;
	if (nl > 0) {
		double was = *worst;
		size_t wat = *at;
		long infl = inflexions(w);

		save_state(w);
		w->fit.straight = line;
		w->fit.nstraight = nl;
		if (fit_project(w, worst, at, err) != 0 ||
		    *worst > w->tol || check_spans(w, *worst) != 0 ||
		    inflexions(w) > infl) {
			restore_state(w);       /* the curve as it was */
			*worst = was;
			*at = wat;
		}
	}
	w->fit.straight = NULL;
	w->fit.nstraight = 0;
	free(line);
	return 0;
}

/* Cut knot j of w and settle the rest again; kept where every point
 * is still within the tolerance, the curve passes both checks and
 * passes fewer than hooks knots backwards (see APPROX_HOOK), else the
 * curve is as it was.  Returns whether it was kept. */
static int
unhook_one(struct work *w, size_t j, size_t hooks, double *worst,
    size_t *at)
{
	double was = *worst;
	size_t wat = *at;
	struct loft_error err;

	save_state(w);
	memset(w->cut, 0, w->m);
	w->cut[j] = 1;
	if (cut_loops(w) == 1 && fit_project(w, worst, at, &err) == 0 &&
	    settle(w, worst, at, &err) == 0 && *worst <= w->tol &&
	    check_spans(w, *worst) == 0 && (memset(w->cut, 0, w->m),
	    hook_knots(w) < hooks))
		return 1;
	restore_state(w);       /* the curve as it was */
	*worst = was;
	*at = wat;
	return 0;
}

/* Where the curve passes knots backwards (see APPROX_HOOK), the first
 * of them cut, where unhook_one keeps the cut.  One only: a hook
 * mostly has one such knot, and each try settles the curve again (the
 * knots of fits that went on to fail their checks, tried each in turn,
 * cost the noisy glyphs of make compare-approx a fifth more time).
 * (Cut all at once, the knot of the hook at the foot of that r and the
 * one before it left its curve astray.)  Returns 0, or an error. */
static int
unhook(struct work *w, double *worst, size_t *at, struct loft_error *err)
{
	size_t hooks;

	memset(w->cut, 0, w->m);
	if ((hooks = hook_knots(w)) == (size_t)-1)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t j = 0; hooks > 0 && j < w->m; j++)
		if (w->cut[j]) {
			unhook_one(w, j, hooks, worst, at);
			break;
		}
	return w->nomem ? loft_fail(err, LOFT_ENOMEM, -1, "out of memory") :
	    0;
}

/* The checks both ways (check_spans) of a round: the spans astray into
 * *bad, counted in w->checks; where the check found loops, they are cut
 * and the knots settled again, and *bad is the check of the curve then.
 * Returns 0, or an error. */
static int
check_round(struct work *w, double *worst, size_t *at, size_t *bad,
    struct loft_error *err)
{
	if ((*bad = check_spans(w, *worst)) > 0)
		w->checks++;
	if (*bad == (size_t)-1)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (*bad > 0 && cut_loops(w) > 0) {
		if (fit_project(w, worst, at, err) != 0 ||
		    settle(w, worst, at, err) != 0)
			return LOFT_EGEOM;
		if ((*bad = check_spans(w, *worst)) == (size_t)-1)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	return 0;
}

/*
 * Remove the knots the points do not ask for, once (when the tolerance
 * is first met); then the checks both ways (check_round), and where the
 * curve passes them, the wiggles left faired and the checks again.  A
 * curve astray is not faired: the next round splits its spans, or,
 * past APPROX_CHECK_ROUNDS, a try from more spans most often takes its
 * place.  Fairing curves about to change took most of the time on
 * dense outlines with corners.  Returns 0, or an error.
 */
static int
tidy(struct work *w, int *removed, double *worst, size_t *at, size_t *bad,
    struct loft_error *err)
{
	size_t astray;
	int rc;

	if (*worst <= w->tol && !*removed) {
		*removed = 1;
		if (w->m <= APPROX_REMOVE_MAX) {
			remove_knots(w);
			straighten(w);
		}
		if (fit_project(w, worst, at, err) != 0 ||
		    settle(w, worst, at, err) != 0)
			return LOFT_EGEOM;
	}
	*bad = 0;
	if (w->checks < APPROX_CHECK_ROUNDS) {
		if ((rc = check_round(w, worst, at, bad, err)) != 0 || *bad > 0)
			return rc;
	} else if ((astray = check_spans(w, *worst)) != 0) {
		/* past the rounds of checks: not faired, not counted */
		return astray == (size_t)-1 ? loft_fail(err, LOFT_ENOMEM, -1,
		    "out of memory") : 0;
	}
	if (*worst <= w->tol && w->m <= APPROX_REMOVE_MAX) {
		if (fair_wiggles(w) != 0)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		if (fit_project(w, worst, at, err) != 0)
			return LOFT_EGEOM;
	}
	if (w->checks >= APPROX_CHECK_ROUNDS)
		return 0;
	return check_round(w, worst, at, bad, err);
}

/* The error of a fit that ends with its largest distance worst (scaled)
 * from point at (of the points as shifted), with knots knots after
 * round rounds of splitting. */
static int
short_fail(const struct loft_approx_opts *o, const struct work *w,
    double worst, size_t at, size_t knots, int round, struct loft_error *err)
{
	size_t where = (at + w->shift) % w->n;

	return loft_fail(err, LOFT_ENOCONV, (long)where, "tolerance %g not "
	    "met: the largest distance reached is %g, from point %zu, with "
	    "%zu knots after %d round%s of splitting%s", o->tol,
	    ldexp(worst, w->e), where + 1, knots, round, round == 1 ? "" : "s",
	    round >= o->maxround ? "" : " (no span left to split)");
}

/* Where no span is left to split and the tolerance is not met, the
 * knots at the points themselves, every one (and the corners' places):
 * the fair curve through them all.  Taken where every point is then
 * within the tolerance, it passes both checks, and it has no more
 * inflexions than the fit that fell short: on a few points of a smooth
 * outline (10 points on an ellipse 86 by 34, at a tolerance of 0.43)
 * the correction sweeps leave the knots off the points, where noisy
 * points asked to be followed closer than their noise wiggle through
 * every point and keep the error.  Returns 1 when taken; else 0, the
 * fit left to fail. */
static int
every_point(struct work *w, const size_t *corner, size_t ncorner,
    double *worst, size_t *at)
{
	long infl = inflexions(w);
	size_t start = w->start;
	struct loft_error err;

	w->start = w->n;
	first_knots(w, corner, ncorner);
	w->start = start;
	for (size_t j = 0; j < w->m; j++)
		vcopy(w->k + j * w->dim, w->cq + w->kidx[j] * w->dim, w->dim);
	return fit_project(w, worst, at, &err) == 0 && *worst <= w->tol &&
	    check_spans(w, *worst) == 0 && inflexions(w) <= infl;
}

/* The rounds of one fit: 0, or an error (or none where memory ran out
 * in a try; approx_run says so). */
static int
approx_rounds(struct work *w, const struct loft_approx_opts *o,
    const size_t *corner, struct loft_approx_info *info,
    struct loft_error *err)
{
	double worst;
	size_t at, bad = 0, knots;
	int round, removed = 0, rc;

	if (smooth(w, corner, o->ncorner) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	first_knots(w, corner, o->ncorner);
	if (fit_project(w, &worst, &at, err) != 0)
		return LOFT_EGEOM;
	for (round = 1;; round++) {
		if (settle(w, &worst, &at, err) != 0)
			return LOFT_EGEOM;
		if ((rc = tidy(w, &removed, &worst, &at, &bad, err)) != 0)
			return rc;
		if ((worst <= w->tol && bad == 0) || round >= o->maxround ||
		    (split(w, ALL_SPANS) == 0 && split_far(w) == 0))
			break;
		if (fit_project(w, &worst, &at, err) != 0)
			return LOFT_EGEOM;
	}
	knots = w->m;
	if (worst > w->tol && round < o->maxround) {
		double short_of = worst;
		size_t from = at;

		if (every_point(w, corner, o->ncorner, &worst, &at)) {
			knots = w->m;
		} else {
			worst = short_of;       /* the fit before, its error */
			at = from;
		}
	}
	if (worst <= w->tol) {
		if ((rc = unhook(w, &worst, &at, err)) != 0 ||
		    (rc = straight_runs(w, &worst, &at, err)) != 0)
			return rc;
		knots = w->m;   /* fewer where hooks were cut */
	}
	info->nknots = knots;
	info->nseg = w->closed ? knots : knots - 1;
	info->dist = worst;
	info->where = (at + w->shift) % w->n;
	info->rounds = round;
	if (worst > w->tol)
		return short_fail(o, w, worst, at, knots, round, err);
	return 0;
}

/* One fit from w->start spans (approx_rounds); LOFT_ENOMEM wherever
 * memory ran out, a try's included: a try that could not be made would
 * otherwise change the curve, or its error, quietly. */
static int
approx_run(struct work *w, const struct loft_approx_opts *o,
    const size_t *corner, struct loft_approx_info *info,
    struct loft_error *err)
{
	int rc = approx_rounds(w, o, corner, info, err);

	return w->nomem ? loft_fail(err, LOFT_ENOMEM, -1, "out of memory") :
	    rc;
}

/* A fit that ends astray or crossing itself (past APPROX_CHECK_ROUNDS),
 * or short of the tolerance, is tried again from more spans, as many
 * as each of these while the points give each span this many at least:
 * the few first knots of a thin stroke or a loop can settle on its two
 * sides in turn, and the curve folds between them; from knots this
 * close along the points, no knot spans two sides.  (96 is the most
 * that 400 points allow: without it, the end of a stroke of FreeSerif's
 * m, of make compare-approx's corpus with the noise of seed 2, whose
 * corners were not found, folded from 48 as from the first spans.) */
static const size_t approx_retry[] = { 48, 96, 128 };
#define APPROX_RETRY_POINTS 4

/* The fit, and its tries again (approx_retry) while it fails a check:
 * the first that passes, else the one that fails on the fewest spans,
 * else the first's error.  The segments (scaled) into seg. */
static int
approx_tries(struct work *w, const struct loft_approx_opts *o,
    const size_t *corner, double *seg, struct loft_approx_info *info,
    struct loft_error *err)
{
	size_t best = (size_t)-1, nr = sizeof approx_retry / sizeof *approx_retry;
	int rc = LOFT_ENOCONV;

	w->start = APPROX_START_SPANS;
	for (size_t r = 0; r <= nr && best > 0; r++) {
		struct loft_approx_info ti = { 0 }, *ip = r == 0 ? info : &ti;
		struct loft_error te;
		size_t bad;
		int trc;

		if (r > 0)
			w->start = approx_retry[r - 1];
		if (w->start * APPROX_RETRY_POINTS > w->n && r > 0)
			break;
		w->checks = 0;
		trc = approx_run(w, o, corner, ip, r == 0 ? err : &te);
		if (trc == LOFT_ENOMEM)
			return r == 0 ? trc : loft_fail(err, trc, -1, "%s",
			    te.msg);
		rc = r == 0 ? trc : rc;
		if (trc != 0)
			continue;
		if ((bad = check_spans(w, ip->dist)) == (size_t)-1)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		if (r == 0 || rc != 0 || bad < best) {
			best = bad;
			rc = 0;
			*info = *ip;
			info->astray = bad;
			put_segments(w, seg);
			if (o->astray != NULL)
				put_astray(w, bad, o->astray);
		}
	}
	return rc;
}

/* w->cq: the points, scaled, with the corners' knots of o->corner_at
 * at the corners (corner: their points from the start).  Returns 0, or
 * an error. */
static int
corner_places(struct work *w, const struct loft_approx_opts *o,
    const size_t *corner, struct loft_error *err)
{
	size_t n = w->n;
	int dim = w->dim;
	double lo[LOFT_MAXDIM], hi[LOFT_MAXDIM], diag;

	if ((w->cqbuf = malloc(n * dim * sizeof *w->cqbuf)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	memcpy(w->cqbuf, w->qbuf, n * dim * sizeof *w->cqbuf);
	w->cq = w->cqbuf;
	vcopy(lo, w->q, dim);
	vcopy(hi, w->q, dim);
	for (size_t i = 1; i < n; i++)
		for (int k = 0; k < dim; k++) {
			lo[k] = fmin(lo[k], w->q[i * dim + k]);
			hi[k] = fmax(hi[k], w->q[i * dim + k]);
		}
	diag = vdist(lo, hi, dim);
	for (size_t c = 0; c < o->ncorner; c++) {
		double *x = w->cqbuf + corner[c] * dim;

		for (int k = 0; k < dim; k++)
			x[k] = ldexp(o->corner_at[c * dim + k], -w->e);
		if (!(vdist(x, w->q + corner[c] * dim, dim) <= diag))
			return loft_fail(err, LOFT_EINPUT, -1, "the knot of "
			    "corner %zu is not finite, or farther from its "
			    "point than the points' box is across", c + 1);
	}
	return 0;
}

int
loft_approx(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_approx_info *info,
    struct loft_error *err)
{
	struct work w = { 0 };
	struct loft_approx_info dummy;
	size_t *corner = NULL;
	double dir[LOFT_MAXDIM];
	int rc, e = 0, line = 0;

	if (info == NULL)
		info = &dummy;
	memset(info, 0, sizeof *info);
	if (o->astray != NULL)
		memset(o->astray, 0, n);
	if ((rc = check_args(o, n, dim, err)) != 0 ||
	    (rc = check_input(o, p, n, dim, dir, &line, err)) != 0)
		return rc;
	if (line) {     /* open and running one way, as check_input says */
		collinear_runs(o, p, n, dim, dir, seg, info);
		return 0;
	}
	w.dim = dim;
	w.closed = o->closed;
	w.n = n;
	/* the points scaled by a power of two (exactly) into the unit box,
	 * so that no square of a distance overflows or underflows (they are
	 * finite, and not all one point: check_input) */
	(void)unit_exponent(p, n, dim, &e);
	w.e = e;
	w.tol = ldexp(o->tol, -e);
	loft_fit_defaults(&w.fit);
	w.fit.method = LOFT_FAIR;
	w.fit.quick = 1;        /* its trial fits are many, their knots dense */
	w.fit.closed = o->closed;
	w.fit.have_start = !o->closed && o->have_start;
	w.fit.have_end = !o->closed && o->have_end;
	vcopy(w.fit.start, o->start, dim);
	vcopy(w.fit.end, o->end, dim);
	if (work_alloc(&w, n, dim) != 0 ||
	    (corner = malloc((o->ncorner + 1) * sizeof *corner)) == NULL) {
		work_free(&w);
		free(corner);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	w.shift = start_point(o, p, n, dim);
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < dim; k++)
			w.qbuf[i * dim + k] = ldexp(p[((i + w.shift) % n) * dim +
			    k], -e);
	w.q = w.cq = w.qbuf;
	for (size_t c = 0; c < o->ncorner; c++)
		corner[c] = (o->corner[c] + n - w.shift) % n;
	if (o->corner_at != NULL && o->ncorner > 0 &&
	    (rc = corner_places(&w, o, corner, err)) != 0) {
		free(corner);
		work_free(&w);
		return rc;
	}
	rc = approx_tries(&w, o, corner, seg, info, err);
	info->dist = ldexp(info->dist, e);
	if (rc == 0) {
		for (size_t i = 0; i < 4 * dim * info->nseg; i++)
			seg[i] = ldexp(seg[i], e);
	} else {
		info->nseg = 0;
	}
	free(corner);
	work_free(&w);
	return rc;
}
