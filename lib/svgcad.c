/*
 * svgcad.c: SVG at true scale for templates and cutters: geometry only,
 * one path a curve record, width and height in millimetres (tocad -u
 * says what the stream's unit is) over a viewBox in the stream's units,
 * which is the box of the paths' control points.  y is up as in the
 * stream: the paths hold the stream's own numbers inside a group that
 * flips y, so the picture is the right way up.  Curves in the plane
 * (the x and y of a curve in space).  Pieces of degree 1, 2 and 3 are
 * exact (L, Q, C); of higher degree (quartics, beziers) cubics with the
 * piece's end points and end tangents, halved until each is within the
 * tolerance (the control points of their difference bound it).
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

/* Most halvings of a piece into cubics (as cad.c's flattening). */
#define MAX_HALVINGS 16

struct svg {
	double lo[2], hi[2];
	int any;
	double tol;
	const char *name;       /* of the record being written */
};

static void
grow_box(struct svg *s, const double *p)
{
	for (int k = 0; k < 2; k++) {
		if (!s->any || p[k] < s->lo[k])
			s->lo[k] = p[k];
		if (!s->any || p[k] > s->hi[k])
			s->hi[k] = p[k];
	}
	s->any = 1;
}

/* " x,y" of point p; grows the box. */
static void
put_xy(struct loft_cad_doc *d, const double *p)
{
	grow_box(d->state, p);
	loft_cad_puts(d, " ");
	loft_cad_putnum(d, p[0]);
	loft_cad_puts(d, ",");
	loft_cad_putnum(d, p[1]);
}

static int
svg_begin(struct loft_cad_doc *d)
{
	d->state = calloc(1, sizeof(struct svg));
	return d->state == NULL ? LOFT_ENOMEM : 0;
}

static int
svg_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	struct svg *s = d->state;

	s->tol = it->tol;
	s->name = it->name;
	loft_cad_puts(d, "<path d=\"");
	return 0;
}

/* The path's name as its title (an id may not hold the '+' of a size). */
static int
svg_end_record(struct loft_cad_doc *d)
{
	struct svg *s = d->state;

	if (s->name[0] == '\0') {
		loft_cad_puts(d, "\"/>\n");
		return 0;
	}
	loft_cad_puts(d, "\"><title>");
	loft_cad_puts(d, s->name);
	loft_cad_puts(d, "</title></path>\n");
	return 0;
}

/* Raise the degree of ctl (deg + 1 points of dim) by one into up. */
static void
elevate(const double *ctl, int deg, int dim, double *up)
{
	vcopy(up, ctl, dim);
	vcopy(up + (deg + 1) * dim, ctl + deg * dim, dim);
	for (int i = 1; i <= deg; i++)
		for (int k = 0; k < dim; k++)
			up[i * dim + k] = (i * ctl[(i - 1) * dim + k] +
			    (deg + 1 - i) * ctl[i * dim + k]) / (deg + 1);
}

/*
 * The cubic with piece q's (degree deg) ends and end derivatives into
 * c; returns a bound on its distance from q: the largest distance
 * between the control points of q and of c raised to degree deg.
 */
static double
hermite(const double *q, int deg, int dim, double *c)
{
	double a[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	double b[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM], worst = 0;
	const double *e = q + deg * dim, *f = q + (deg - 1) * dim;

	for (int k = 0; k < dim; k++) {
		c[k] = q[k];
		c[dim + k] = q[k] + deg * (q[dim + k] - q[k]) / 3;
		c[2 * dim + k] = e[k] - deg * (e[k] - f[k]) / 3;
		c[3 * dim + k] = e[k];
	}
	memcpy(a, c, 4 * dim * sizeof *a);
	for (int r = 3; r < deg; r++) {
		elevate(a, r, dim, b);
		memcpy(a, b, (r + 2) * dim * sizeof *a);
	}
	for (int i = 0; i <= deg; i++) {
		double t = vdist(a + i * dim, q + i * dim, dim);

		worst = t > worst ? t : worst;
	}
	return worst;
}

static int
cubics(struct loft_cad_doc *d, const double *q, int deg, int dim, int depth)
{
	double c[4 * LOFT_MAXDIM];
	double l[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	double r[LOFT_BEZIER_MAXPTS * LOFT_MAXDIM];
	struct svg *s = d->state;

	if (hermite(q, deg, dim, c) <= s->tol || depth == MAX_HALVINGS) {
		/* at MAX_HALVINGS the piece is 2^-16 of its parameter range;
		 * a cubic with its ends and end tangents errs by about
		 * h^4 max |C| / 384 with h = 2^-16 */
		loft_cad_puts(d, " C");
		for (int i = 1; i < 4; i++)
			put_xy(d, c + i * dim);
		return 0;
	}
	loft_bezier_split(q, deg, dim, 0.5, l, r);
	cubics(d, l, deg, dim, depth + 1);
	return cubics(d, r, deg, dim, depth + 1);
}

static int
svg_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	static const char cmd[] = " L Q C";
	int dim = c->dim, n = c->deg + 1;

	loft_cad_puts(d, "M");
	put_xy(d, c->ctl);
	for (size_t i = 0; i < c->npieces; i++) {
		const double *q = c->ctl + i * n * dim;

		if (c->deg > 3) {
			cubics(d, q, c->deg, dim, 0);
			continue;
		}
		loft_cad_put(d, cmd + 2 * (c->deg - 1), 2);
		for (int j = 1; j < n; j++)
			put_xy(d, q + j * dim);
	}
	if (c->closed)
		loft_cad_puts(d, " Z");
	return 0;
}

/* The head, made last: the page is the box of what was drawn. */
static int
svg_end(struct loft_cad_doc *d)
{
	struct svg *s = d->state;
	double w = s->hi[0] - s->lo[0], h = s->hi[1] - s->lo[1];
	double sw;

	if (!(w > 0) && !(h > 0))
		w = h = 1;              /* a curve of one point */
	else if (!(w > 0))
		w = h * 1e-3;
	else if (!(h > 0))
		h = w * 1e-3;
	sw = (w > h ? w : h) * 1e-3;    /* a hairline of the page */
	loft_cad_puts(d, "</g>\n</svg>\n");
	loft_cad_to_head(d, 1);
	loft_cad_puts(d, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
	loft_cad_putnum(d, w * d->o.unit_mm);
	loft_cad_puts(d, "mm\" height=\"");
	loft_cad_putnum(d, h * d->o.unit_mm);
	loft_cad_puts(d, "mm\" viewBox=\"");
	loft_cad_putnum(d, s->lo[0]);
	loft_cad_puts(d, " ");
	loft_cad_putnum(d, -s->lo[1] - h);
	loft_cad_puts(d, " ");
	loft_cad_putnum(d, w);
	loft_cad_puts(d, " ");
	loft_cad_putnum(d, h);
	loft_cad_puts(d, "\">\n<g transform=\"scale(1,-1)\" fill=\"none\" "
	    "stroke=\"black\" stroke-width=\"");
	loft_cad_putnum(d, sw);
	loft_cad_puts(d, "\">\n");
	loft_cad_to_head(d, 0);
	return 0;
}

static void
svg_free(struct loft_cad_doc *d)
{
	free(d->state);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_svg = {
	.name = "svg", .title = "SVG",
	.begin = svg_begin, .end = svg_end, .begin_record = svg_begin_record,
	.end_record = svg_end_record, .curve = svg_curve, .free = svg_free,
};
