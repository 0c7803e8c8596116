/*
 * bsplineread.c: B-spline curves and surfaces read from a CAD document
 * (STEP, IGES) written as loft's records: polynomial ones exactly, as
 * their Bezier pieces (bspline.c) -- a curve of degree 3 or less one
 * cubic record, a higher one a bezier record a piece, a surface a
 * bezier-surface record a patch; rational ones (weights that differ) as
 * cubic pieces and bicubic patches within the reading's tolerance.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

/*
 * Weights that differ by no more than this part of the first are one
 * weight: the curve is then polynomial (the weights cancel).  A few
 * units of rounding of a written decimal.
 */
#define WEIGHT_SAME 1e-15

/* The most cubic pieces a rational span, bicubic patches a side. */
#define RATIONAL_PIECES 4096
#define RATIONAL_SIDE 64

/* The tolerance of a rational piece whose control points span size. */
static double
rational_tol(const struct loft_cadin *c, double size)
{
	return c->tol > 0 ? c->tol : LOFT_CADIN_ARC_REL * size;
}

/* Whether the n weights w (NULL: none) make the B-spline rational. */
static int
is_rational(const double *w, size_t n)
{
	if (w == NULL)
		return 0;
	for (size_t i = 1; i < n; i++)
		if (fabs(w[i] - w[0]) > WEIGHT_SAME * fabs(w[0]))
			return 1;
	return 0;
}

/* The diagonal of the box of n points of dim numbers. */
static double
box_size(const double *p, size_t n, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++) {
		double lo = INFINITY, hi = -INFINITY;

		for (size_t i = 0; i < n; i++) {
			lo = fmin(lo, p[i * dim + k]);
			hi = fmax(hi, p[i * dim + k]);
		}
		s = hypot(s, hi - lo);
	}
	return s;
}

/* Begin a record of type with the document's name and entity. */
static void
head(struct loft_writer *w, const char *type, const struct loft__bsname *nm)
{
	loft_put_type(w, type);
	if (nm != NULL) {
		loft__cadin_put_name(w, "name", nm->name, nm->nname);
		if (nm->entity > 0) {
			char num[32];

			snprintf(num, sizeof num, "%ld", nm->entity);
			loft_put_attr(w, "entity", num);
		}
	}
}

/* The pieces b (npieces of degree p, dim each): one cubic record, or
 * a bezier record a piece. */
static void
put_pieces(struct loft_cadin *c, const double *b, size_t npieces, int p,
    int dim, const struct loft__bsname *nm)
{
	struct loft_writer *w = c->w;
	size_t stride = (size_t)(p + 1) * dim;
	const double *last;
	int closed;

	if (b == NULL || npieces == 0)
		return;         /* nothing to write (the callers have pieces) */
	last = b + (npieces - 1) * stride + p * dim;
	closed = memcmp(b, last, (size_t)dim * sizeof *b) == 0;

	if (p > 3) {
		for (size_t i = 0; i < npieces; i++) {
			char num[32];

			head(w, "bezier", nm);
			snprintf(num, sizeof num, "%zu", i + 1);
			if (npieces > 1)
				loft_put_attr(w, "piece", num);
			loft_end_line(w);
			for (int j = 0; j <= p; j++)
				loft_put_row(w, b + i * stride + j * dim, dim);
			loft_end_record(w);
		}
		return;
	}
	head(w, "cubic", nm);
	loft_put_attr(w, "closed", closed && npieces > 1 ? "1" : "0");
	loft_end_line(w);
	for (size_t i = 0; i < npieces; i++) {
		const double *e = b + i * stride;
		double row[12];

		/* degrees 1 and 2 raised to 3 exactly: the ends stay,
		 * P'_A = p (b1 - b0), P'_B = p (b_p - b_(p-1)) */
		if (p == 3)
			loft__bezier_hermite(e, dim, row);
		else
			for (int q = 0; q < dim; q++) {
				row[q] = e[q];
				row[dim + q] = e[p * dim + q];
				row[2 * dim + q] = p * (e[dim + q] - e[q]);
				row[3 * dim + q] = p * (e[p * dim + q] -
				    e[(p - 1) * dim + q]);
			}
		loft_put_row(w, row, 4 * dim);
	}
	loft_end_record(w);
}

/* The rational pieces hb (homogeneous, dim + 1 each) as cubics. */
static int
rational_pieces(struct loft_cadin *c, const double *hb, size_t npieces,
    int p, int dim, double size, const struct loft__bsname *nm, long line)
{
	double *cub = NULL;
	size_t n = 0, k, cap = 0;
	struct loft_error err;
	int rc = 0;

	for (size_t i = 0; i < npieces && rc == 0; i++) {
		if (loft__grow((void **)&cub, &cap, (n + RATIONAL_PIECES) * 4 *
		    (size_t)dim, sizeof *cub) != 0) {
			loft__cadin_say(c, line, "out of memory");
			rc = -1;
		} else if (loft_rational_cubics(hb + i * (size_t)(p + 1) *
		    (size_t)(dim + 1), p, dim, rational_tol(c, size),
		    RATIONAL_PIECES, cub + n * 4 * dim, &k, &err) != 0) {
			loft__cadin_say(c, line, "a rational curve: %s (-t "
			    "sets the tolerance)", err.msg);
			rc = -1;
		} else {
			n += k;
		}
	}
	if (rc == 0)
		put_pieces(c, cub, n, 3, dim, nm);
	free(cub);
	return rc;
}

int
loft__bs_curve(struct loft_cadin *c, const struct loft__bs *b,
    const struct loft__bsname *nm, long line)
{
	int rat = is_rational(b->w, b->n), dim = loft__pts_dim(b->ctl, b->n);
	int h = rat ? dim + 1 : dim;
	size_t ns, mark = c->w->len;
	double *ctl, *out;
	struct loft_error err;
	int rc = 0;

	if (loft_bspline_check(b->t, b->n, b->deg, &err) != 0) {
		loft__cadin_say(c, line, "%s", err.msg);
		return -1;
	}
	ns = loft_bspline_spans(b->t, b->n, b->deg);
	ctl = malloc(b->n * (size_t)h * sizeof *ctl);
	out = malloc(ns * (size_t)(b->deg + 1) * (size_t)h * sizeof *out);
	if (ctl == NULL || out == NULL) {
		loft__cadin_say(c, line, "out of memory");
		rc = -1;
		goto done;
	}
	for (size_t i = 0; i < b->n; i++) {
		double w = rat ? b->w[i] : 1;

		for (int k = 0; k < dim; k++)
			ctl[i * h + k] = w * b->ctl[3 * i + k];
		if (rat)
			ctl[i * h + dim] = w;
	}
	(void)loft_bspline_bezier(b->t, b->n, b->deg, ctl, h, out, NULL, &err);
	if (rat)
		rc = rational_pieces(c, out, ns, b->deg, dim, box_size(b->ctl,
		    b->n, 3), nm, line);
	else
		put_pieces(c, out, ns, b->deg, dim, nm);
	if (rc == 0)
		rc = loft__cadin_done(c, mark, line);
done:
	free(ctl);
	free(out);
	return rc;
}

/* One bezier-surface record of degrees m, n and points net. */
static void
put_patch(struct loft_writer *w, const double *net, int m, int n,
    const struct loft__bsname *nm)
{
	char num[16];

	head(w, "bezier-surface", nm);
	snprintf(num, sizeof num, "%d", m);
	loft_put_attr(w, "m", num);
	snprintf(num, sizeof num, "%d", n);
	loft_put_attr(w, "n", num);
	loft_end_line(w);
	for (int k = 0; k < (m + 1) * (n + 1); k++)
		loft_put_row(w, net + 3 * k, 3);
	loft_end_record(w);
}

int
loft__bs_patch(struct loft_cadin *c, const double *net, int m, int n,
    const struct loft__bsname *nm, long line)
{
	size_t mark = c->w->len;

	put_patch(c->w, net, m, n, nm);
	return loft__cadin_done(c, mark, line);
}

/* The rational patches hw (4 numbers a point) as bicubic ones. */
static int
rational_patches(struct loft_cadin *c, const double *hw, size_t np, int p,
    int q, double tol, const struct loft__bsname *nm, long line)
{
	double *cub = malloc(48 * RATIONAL_SIDE * RATIONAL_SIDE * sizeof *cub);
	struct loft_error err;
	size_t ku, kv;

	if (cub == NULL) {
		loft__cadin_say(c, line, "out of memory");
		return -1;
	}
	for (size_t i = 0; i < np; i++) {
		if (loft_rational_bicubics(hw + i * (size_t)(p + 1) * (q + 1) *
		    4, p, q, tol, RATIONAL_SIDE, cub, &ku, &kv, &err) != 0) {
			loft__cadin_say(c, line, "a rational surface: %s (-t "
			    "sets the tolerance)", err.msg);
			free(cub);
			return -1;
		}
		for (size_t j = 0; j < ku * kv; j++)
			put_patch(c->w, cub + 48 * j, 3, 3, nm);
	}
	free(cub);
	return 0;
}

int
loft__bs_surface(struct loft_cadin *c, const struct loft__bsurf *s,
    const struct loft__bsname *nm, long line)
{
	size_t n = s->nu * s->nv, np, mark = c->w->len;
	int rat = is_rational(s->w, n), h = rat ? 4 : 3, rc = 0;
	double *ctl, *out = NULL;
	struct loft_error err;

	if (loft_bspline_check(s->tu, s->nu, s->p, &err) != 0 ||
	    loft_bspline_check(s->tv, s->nv, s->q, &err) != 0) {
		loft__cadin_say(c, line, "%s", err.msg);
		return -1;
	}
	np = loft_bspline_spans(s->tu, s->nu, s->p) *
	    loft_bspline_spans(s->tv, s->nv, s->q);
	ctl = malloc(n * (size_t)h * sizeof *ctl);
	if (ctl != NULL)
		out = malloc(np * (size_t)(s->p + 1) * (s->q + 1) * h *
		    sizeof *out);
	if (ctl == NULL || out == NULL) {
		loft__cadin_say(c, line, "out of memory");
		rc = -1;
		goto done;
	}
	for (size_t i = 0; i < n; i++) {
		double w = rat ? s->w[i] : 1;

		for (int k = 0; k < 3; k++)
			ctl[i * h + k] = w * s->ctl[3 * i + k];
		if (rat)
			ctl[i * h + 3] = w;
	}
	if (loft_bspline_surface_bezier(s->tu, s->nu, s->p, s->tv, s->nv, s->q,
	    ctl, h, out, &err) != 0) {
		loft__cadin_say(c, line, "%s", err.msg);
		rc = -1;
	} else if (rat) {
		rc = rational_patches(c, out, np, s->p, s->q, rational_tol(c,
		    box_size(s->ctl, n, 3)), nm, line);
	} else {
		for (size_t i = 0; i < np; i++)
			put_patch(c->w, out + i * (size_t)(s->p + 1) * (s->q +
			    1) * 3, s->p, s->q, nm);
	}
	if (rc == 0)
		rc = loft__cadin_done(c, mark, line);
	else
		loft_writer_cut(c->w, mark);
done:
	free(ctl);
	free(out);
	return rc;
}

int
loft__bs_knots(const double *val, const long *mult, size_t nval, size_t want,
    double *t)
{
	size_t k = 0;

	for (size_t i = 0; i < nval; i++) {
		if (mult[i] < 1 || (size_t)mult[i] > want - k)
			return -1;
		for (long r = 0; r < mult[i]; r++)
			t[k++] = val[i];
	}
	return k == want ? 0 : -1;
}
