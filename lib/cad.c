/*
 * cad.c: documents of the CAD formats (loftcad.h): records into their
 * exact Bezier forms, handed to the format's callbacks; curves into
 * polylines within a tolerance and surfaces into one welded mesh for the
 * formats that take only those; the numbers and knots the formats share.
 * Program layer (loftcad.h, on loftprog.h): it takes records.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

/*
 * Most polyline steps a piece: a tolerance that needs more is far below
 * the piece's rounding noise (or absurd for its size) and is refused
 * rather than met slowly.
 */
#define MAX_STEPS_PIECE 65536

/*
 * Vertices of a mesh nearer than this part of the design's size are one:
 * an edge evaluated from the two patches that share it agrees to a few
 * rounding errors (1e-15), and no mesh cell of at most 256 steps
 * is anywhere near as small.
 */
#define WELD_TOL 1e-9

#define SURF_HEAD 3     /* numbers before a kept surface's control points */

void
loft_cad_init(struct loft_cad_doc *d, const struct loft_cad_format *f,
    const struct loft_cad_opts *o)
{
	memset(d, 0, sizeof *d);
	d->f = f;
	d->o = *o;
}

void
loft_cad_put(struct loft_cad_doc *d, const void *s, size_t n)
{
	struct loft_writer *w = d->in_head ? &d->head : &d->out;

	if (w->bad)
		return;
	if (loft__grow((void **)&w->buf, &w->cap, w->len + n + 1, 1) != 0) {
		w->bad = LOFT_ENOMEM;
		return;
	}
	memcpy(w->buf + w->len, s, n);
	w->len += n;
}

void
loft_cad_to_head(struct loft_cad_doc *d, int on)
{
	d->in_head = on;
}

void
loft_cad_puts(struct loft_cad_doc *d, const char *s)
{
	loft_cad_put(d, s, strlen(s));
}

void
loft_cad_putnum(struct loft_cad_doc *d, double x)
{
	struct loft_writer *w = d->in_head ? &d->head : &d->out;

	if (!isfinite(x)) {
		w->bad = LOFT_EGEOM;
		return;
	}
	/* formatted in place, as loft_put_num does */
	if (w->bad || loft__grow((void **)&w->buf, &w->cap, w->len +
	    LOFT_NUMBUF, 1) != 0) {
		w->bad = w->bad ? w->bad : LOFT_ENOMEM;
		return;
	}
	w->len += (size_t)loft_format_num(w->buf + w->len, x, w->digits);
}

int
loft_cad_real(char *buf, double x)
{
	char t[LOFT_NUMBUF];
	int n = loft_format_num(t, x, 0), k = 0, i;

	for (i = 0; i < n && t[i] != 'e'; i++)
		buf[k++] = t[i];
	if (memchr(t, '.', (size_t)i) == NULL)
		buf[k++] = '.';
	if (i < n) {
		buf[k++] = 'E';
		for (i++; i < n; i++)
			buf[k++] = t[i];
	}
	buf[k] = '\0';
	return k;
}

void
loft_cad_knots(size_t npieces, int deg, double *knot, int *mult)
{
	for (size_t i = 0; i <= npieces; i++) {
		knot[i] = (double)i;
		mult[i] = i == 0 || i == npieces ? deg + 1 : deg;
	}
}

const double *
loft_cad_ctl(const struct loft_bcurve *c, size_t k)
{
	size_t i = k / (size_t)c->deg, j = k % (size_t)c->deg;

	if (i == c->npieces) {          /* the last point */
		i--;
		j = (size_t)c->deg;
	}
	return c->ctl + (i * (size_t)(c->deg + 1) + j) * (size_t)c->dim;
}

/* Room for n doubles of scratch. */
static int
scratch(struct loft_cad_doc *d, size_t n)
{
	return loft__grow((void **)&d->tmp, &d->tmpcap, n, sizeof *d->tmp);
}

/* The record's name from size= and id=: "size_4.5-id_2", "id_2" or "". */
static void
item_name(const struct loft_record *rec, char *buf, size_t cap)
{
	static const char *const keys[] = { "size", "id" };
	size_t k = 0;

	for (int i = 0; i < 2; i++) {
		const char *v = loft_attr(rec, keys[i]);

		if (v == NULL)
			continue;
		if (k > 0 && k + 1 < cap)
			buf[k++] = '-';
		for (const char *s = keys[i]; *s && k + 1 < cap; s++)
			buf[k++] = *s;
		if (k + 1 < cap)
			buf[k++] = '_';
		/* what every format takes in a name: letters, digits, . + - */
		for (; *v && k + 1 < cap; v++)
			buf[k++] = (*v >= 'a' && *v <= 'z') ||
			    (*v >= 'A' && *v <= 'Z') || (*v >= '0' && *v <= '9') ||
			    *v == '.' || *v == '+' || *v == '-' ? *v : '_';
	}
	buf[k] = '\0';
}

/*
 * The box of n points p of dim numbers into lo, hi (3 each, z = 0 in the
 * plane) and its diagonal into *size.  Returns 0, or LOFT_EGEOM when a
 * number or the diagonal is not finite.
 */
static int
measure(const double *p, size_t n, int dim, double *lo, double *hi,
    double *size, struct loft_error *err)
{
	double s = 0;

	for (int k = 0; k < 3; k++)
		lo[k] = hi[k] = 0;
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < dim; k++) {
			double x = p[i * dim + k];

			if (!isfinite(x))
				return loft_fail(err, LOFT_EGEOM, -1, "coefficients "
				    "too large: the Bezier form overflows");
			if (i == 0 || x < lo[k])
				lo[k] = x;
			if (i == 0 || x > hi[k])
				hi[k] = x;
		}
	for (int k = 0; k < 3; k++)
		s = hypot(s, hi[k] - lo[k]);
	if (!isfinite(s))
		return loft_fail(err, LOFT_EGEOM, -1, "coefficients too large: "
		    "the record's extent overflows");
	*size = s;
	return 0;
}

/* ---- curves into polylines ------------------------------------------ */

struct pts {
	double *p;
	size_t n, cap;
	int dim;
};

static int
pts_add(struct pts *s, const double *p)
{
	if (loft__grow((void **)&s->p, &s->cap, (s->n + 1) * s->dim,
	    sizeof *s->p) != 0)
		return LOFT_ENOMEM;
	vcopy(s->p + s->n++ * s->dim, p, s->dim);
	return 0;
}

/*
 * The polyline of c into s (s->dim set, s->p NULL): within tol, or at
 * -n equal parameter steps a piece.
 */
static int
make_polyline(const struct loft_cad_doc *d, struct pts *s,
    const struct loft_bcurve *c, double tol, struct loft_error *err)
{
	int rc = pts_add(s, c->ctl);
	long per = d->o.per;

	for (size_t i = 0; rc == 0 && i < c->npieces; i++) {
		const double *q = c->ctl + i * (c->deg + 1) * c->dim;
		long n = per > 0 ? per : loft_bezier_steps(q, c->deg, c->dim, tol,
		    MAX_STEPS_PIECE);
		double p[LOFT_MAXDIM] = { 0 };  /* s->dim == c->dim numbers */

		if (n == 0)
			return loft_fail(err, LOFT_EGEOM, -1, "the tolerance %g "
			    "needs more than %d steps a piece: give a larger -t",
			    tol, MAX_STEPS_PIECE);
		for (long j = 1; rc == 0 && j <= n; j++) {
			/* the piece's own end point exactly */
			if (j == n)
				vcopy(p, q + c->deg * c->dim, c->dim);
			else
				loft_bezier_eval(q, (size_t)c->deg + 1, c->dim,
				    (double)j / n, p, NULL, NULL);
			rc = pts_add(s, p);
		}
	}
	return rc == 0 ? 0 : loft_fail(err, rc, -1, "out of memory");
}

/* ---- corners -------------------------------------------------------- */

/*
 * Joint j (counted from 1, loft.5's corners=) of c as the document has
 * it: a SPLINE's control point there (exact), or the polyline's vertex,
 * the end of the piece before (piece 0's start for joint 1).
 */
static const double *
joint(const struct loft_bcurve *c, size_t j, int exact)
{
	if (exact || j == 1)
		return loft_cad_ctl(c, (j - 1) * (size_t)c->deg);
	return c->ctl + ((j - 2) * (size_t)(c->deg + 1) + (size_t)c->deg) *
	    (size_t)c->dim;
}

/*
 * The points the record's corners= names, into *out (malloc'd, dim
 * numbers each, *n of them; NULL and 0 when it has none): numbers from 1
 * to max in increasing order, what (from 1 to max, "joint" or "knot"
 * for the message), point k at at(src, k).  Returns 0, LOFT_EINPUT or
 * LOFT_ENOMEM.
 */
static int
corner_points(const struct loft_record *rec, size_t max, int dim,
    const char *what, const double *(*at)(const void *, size_t),
    const void *src, double **out, size_t *n, struct loft_error *err)
{
	const char *v = loft_attr(rec, "corners"), *s = v;
	size_t last = 0;
	double *p;

	*out = NULL;
	*n = 0;
	if (v == NULL)
		return 0;
	if ((p = malloc((strlen(v) / 2 + 1) * (size_t)dim * sizeof *p)) ==
	    NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (;;) {
		size_t len = strcspn(s, ","), j = 0, i;

		for (i = 0; i < len && s[i] >= '0' && s[i] <= '9' && j <= max;
		    i++)
			j = 10 * j + (size_t)(s[i] - '0');
		if (len == 0 || i < len || j < 1 || j > max || j <= last) {
			free(p);
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "corners=%s: want %s numbers from 1 to %zu in "
			    "increasing order, separated by commas", v, what,
			    max);
		}
		memcpy(p + *n * (size_t)dim, at(src, j), (size_t)dim *
		    sizeof *p);
		++*n;
		last = j;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	*out = p;
	return 0;
}

/* A curve's joint j (corner_points' at): of its polyline or its exact
 * form, as corner_points' caller chose. */
struct joints {
	const struct loft_bcurve *c;
	int exact;
};

static const double *
joint_at(const void *src, size_t j)
{
	const struct joints *js = src;

	return joint(js->c, j, js->exact);
}

/* A knot record's row k (from 1; corner_points' at). */
static const double *
knot_at(const void *src, size_t k)
{
	const struct loft_record *rec = src;

	return rec->num + (k - 1) * (size_t)rec->ncols;
}

/* ---- records -------------------------------------------------------- */

/* "a patch record is a surface: DXF takes curves and points" */
static int
cannot(struct loft_cad_doc *d, const char *type, const char *kind,
    struct loft_error *err)
{
	const struct loft_cad_format *f = d->f;
	int c = f->curve || f->polyline, s = f->surface || f->mesh;

	return loft_fail(err, LOFT_EINPUT, -1, "a %s record is %s: %s takes "
	    "%s%s%s%s", type, kind, f->title, c ? "curves" : "",
	    c && s ? " and " : "", s ? "surfaces" : "",
	    f->points ? " and points" : "");
}

/*
 * Measure the record whose control points are p[0..n) and fill it; 0 or
 * LOFT_EGEOM.  Nothing of the record is in the document yet.
 */
static int
item(const struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_cad_item *it, char *name, size_t cap, const double *p,
    size_t n, int dim, double *box, struct loft_error *err)
{
	item_name(rec, name, cap);
	it->rec = rec;
	it->name = name;
	it->cls = it->colour = NULL;
	it->width_px = 0;
	if (measure(p, n, dim, box, box + 3, &it->size, err) != 0)
		return LOFT_EGEOM;
	it->tol = d->o.tol > 0 ? d->o.tol : LOFT_CAD_RELTOL * it->size;
	return d->o.tol > 0 ? loft_tol_check(d->o.tol, it->size, 0, err) : 0;
}

/* The record goes in: the document's begin, its box, begin_record. */
static int
begin_item(struct loft_cad_doc *d, const struct loft_cad_item *it,
    const double *box)
{
	for (int k = 0; k < 3; k++) {
		if (d->nrec == 0 || box[k] < d->box[k])
			d->box[k] = box[k];
		if (d->nrec == 0 || box[3 + k] > d->box[3 + k])
			d->box[3 + k] = box[3 + k];
	}
	if (d->nrec++ == 0 && d->f->begin != NULL && d->f->begin(d) != 0)
		return LOFT_ENOMEM;
	return d->f->begin_record != NULL ? d->f->begin_record(d, it) : 0;
}

/* After the record's geometry (rc its callback's code): end_record. */
static int
end_item(struct loft_cad_doc *d, int rc)
{
	if (rc == 0 && d->f->end_record != NULL)
		rc = d->f->end_record(d);
	if (rc != 0)            /* the callbacks fail only for memory */
		d->bad = LOFT_ENOMEM;
	return 0;
}

static int
add_points(struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_error *err)
{
	struct loft_cad_item it;
	char name[128];
	double box[6], *turn = NULL;
	size_t nturn = 0;
	int rc;

	if (d->f->points == NULL)
		return cannot(d, "point", "a set of knots, no curve (fit one "
		    "with splinefit first)", err);
	if (rec->nrows == 0 || rec->ncols < 2 || rec->ncols > 3)
		return loft_fail(err, LOFT_EINPUT, 0, "points need 2 or 3 "
		    "numbers, not %d", rec->ncols);
	if (item(d, rec, &it, name, sizeof name, rec->num, rec->nrows,
	    rec->ncols, box, err) != 0)
		return LOFT_EGEOM;
	/* knots named corners= (fromcad's turn points) are turn points */
	if (d->f->turns != NULL && (rc = corner_points(rec, rec->nrows,
	    rec->ncols, "knot", knot_at, rec, &turn, &nturn, err)) != 0)
		return rc;
	rc = begin_item(d, &it, box) ||
	    d->f->points(d, rec->num, rec->nrows, rec->ncols) ||
	    (nturn > 0 && d->f->turns(d, turn, nturn, rec->ncols));
	free(turn);
	return end_item(d, rc);
}

static int
add_curve(struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_error *err)
{
	struct loft_curve c;
	struct loft_bcurve bc;
	struct loft_cad_item it;
	struct pts s = { NULL, 0, 0, 0 };
	char name[128];
	double box[6], *turn = NULL;
	size_t np, nturn = 0;
	struct joints js;
	int rc, exact;

	if (loft_curve_from_record(rec, &c, err) != 0)
		return LOFT_EINPUT;
	if (d->f->curve == NULL && d->f->polyline == NULL)
		return cannot(d, c.type, "a curve", err);
	bc.dim = s.dim = c.dim;
	bc.closed = c.closed;
	bc.npieces = c.npieces;
	bc.deg = c.degree;
	np = (size_t)(c.degree + 1) * c.dim;    /* numbers a piece */
	if (scratch(d, c.npieces * np) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	for (size_t i = 0; i < c.npieces; i++)
		(void)loft_curve_bezier(&c, i, d->tmp + i * np);
	bc.ctl = d->tmp;
	np = bc.npieces * (size_t)(bc.deg + 1);
	if (item(d, rec, &it, name, sizeof name, bc.ctl, np, bc.dim, box,
	    err) != 0)
		return LOFT_EGEOM;
	exact = d->f->curve != NULL && (d->o.exact || d->f->polyline == NULL);
	js.c = &bc;
	js.exact = exact;
	if (d->f->turns != NULL && (rc = corner_points(rec, bc.closed ?
	    bc.npieces : bc.npieces + 1, bc.dim, "joint", joint_at, &js,
	    &turn, &nturn, err)) != 0)
		return rc;
	if (!exact && (rc = make_polyline(d, &s, &bc, it.tol, err)) != 0) {
		free(s.p);
		free(turn);
		return rc;
	}
	rc = begin_item(d, &it, box) || (exact ? d->f->curve(d, &bc) :
	    d->f->polyline(d, s.p, s.n, s.dim, bc.closed)) ||
	    (nturn > 0 && d->f->turns(d, turn, nturn, bc.dim));
	free(s.p);
	free(turn);
	return end_item(d, rc);
}

/*
 * Keep a surface for the mesh: m, n, its patch's index in d->design (or
 * -1), then its control points.
 */
static int
keep_surface(struct loft_cad_doc *d, const struct loft_bsurf *s, long ip)
{
	size_t n = SURF_HEAD + 3 * (size_t)(s->m + 1) * (s->n + 1);

	if (loft__grow((void **)&d->surf, &d->surfcap, d->nsurf + n,
	    sizeof *d->surf) != 0)
		return LOFT_ENOMEM;
	d->surf[d->nsurf] = s->m;
	d->surf[d->nsurf + 1] = s->n;
	d->surf[d->nsurf + 2] = (double)ip;
	memcpy(d->surf + d->nsurf + SURF_HEAD, s->ctl, (n - SURF_HEAD) *
	    sizeof *d->surf);
	d->nsurf += n;
	return 0;
}

static int
add_surface(struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_error *err)
{
	struct loft_surface s;
	struct loft_bsurf bs;
	struct loft_cad_item it;
	char name[128];
	double box[6];
	size_t np;
	long ip = -1;

	if (loft_surface_from_record(rec, &s, err) != 0)
		return LOFT_EINPUT;
	if (d->f->surface == NULL && d->f->mesh == NULL)
		return cannot(d, s.type, "a surface", err);
	bs.m = s.m;
	bs.n = s.n;
	np = (size_t)(s.m + 1) * (s.n + 1);
	if (scratch(d, 3 * np) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	loft_surface_bezier(&s, d->tmp);
	bs.ctl = d->tmp;
	if (item(d, rec, &it, name, sizeof name, bs.ctl, np, 3, box, err) != 0)
		return LOFT_EGEOM;
	if (d->f->surface != NULL)
		return end_item(d, begin_item(d, &it, box) ||
		    d->f->surface(d, &bs));
	/* for the mesh: a patch with an id, and its neighbours */
	if (loft_record_is(rec, LOFT_KIND_MEMBER) &&
	    loft_attr(rec, "id") != NULL) {
		if (loft_design_add(&d->design, rec, err) != 0)
			return LOFT_EINPUT;
		d->design.p[d->design.n - 1].rec = NULL;    /* rec is reused */
		ip = (long)d->design.n - 1;
	}
	return end_item(d, begin_item(d, &it, box) || keep_surface(d, &bs, ip));
}

int
loft_cad_record(struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_error *err)
{
	if (loft_record_is(rec, LOFT_KIND_KNOTS))
		return add_points(d, rec, err);
	if (loft_is_surface(rec))
		return add_surface(d, rec, err);
	return add_curve(d, rec, err);
}

/* ---- surfaces into one mesh ------------------------------------------ */

/* The kept surfaces as one mesh (mesh.c), handed to the format. */
static int
make_mesh(struct loft_cad_doc *d)
{
	struct loft_mesh me;
	struct loft_surface *s = NULL;
	long *ip = NULL, N = d->o.per;
	size_t ns = 0, k = 0;
	double size = 0, tol;
	int rc;

	memset(&me, 0, sizeof me);
	for (int c = 0; c < 3; c++)
		size = hypot(size, d->box[3 + c] - d->box[c]);
	tol = d->o.tol > 0 ? d->o.tol : LOFT_CAD_MESHTOL * size;
	for (size_t i = 0; i < d->nsurf; ns++)
		i += SURF_HEAD + 3 * (size_t)(d->surf[i] + 1) *
		    (size_t)(d->surf[i + 1] + 1);
	s = malloc((ns + 1) * sizeof *s);
	ip = malloc((ns + 1) * sizeof *ip);
	rc = s == NULL || ip == NULL ? LOFT_ENOMEM : 0;
	/* one step count for every patch, so shared edges match: the
	 * first patch's, as the mesher has always taken it */
	for (size_t i = 0; rc == 0 && i < d->nsurf; k++) {
		int m = (int)d->surf[i], n = (int)d->surf[i + 1];

		loft_surface_from_bezier(d->surf + i + SURF_HEAD, m, n, &s[k]);
		ip[k] = (long)d->surf[i + 2];
		if (N == 0) {
			long st = loft_mesh_steps(s[k].coef, m, n, tol);

			N = st > N ? st : N;
		}
		i += SURF_HEAD + 3 * (size_t)(m + 1) * (n + 1);
	}
	if (rc == 0)
		rc = loft_mesh_surfaces(&me, s, ns, ip, &d->design, N,
		    WELD_TOL * size);
	if (rc == 0 && me.nt == 0)
		rc = LOFT_EGEOM;        /* no area: no facet (issue 28) */
	if (rc == 0)
		rc = d->f->mesh(d, me.v, me.nv, me.t, me.nt);
	loft_mesh_free(&me);
	free(s);
	free(ip);
	return rc;
}
int
loft_cad_finish(struct loft_cad_doc *d, struct loft_error *err)
{
	err->line = 0;
	err->row = -1;
	if (d->nrec == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "nothing to draw");
	if (!d->bad && d->nsurf > 0 && (d->bad = make_mesh(d)) == LOFT_EGEOM)
		return loft_fail(err, LOFT_EGEOM, -1, "the surfaces have no "
		    "area: a mesh of them has no facet to write");
	d->bad = d->bad ? LOFT_ENOMEM : 0;
	if (!d->bad && d->f->end != NULL && d->f->end(d) != 0)
		d->bad = LOFT_ENOMEM;
	if (d->bad || d->out.bad == LOFT_ENOMEM || d->head.bad == LOFT_ENOMEM)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	if (d->out.bad || d->head.bad)
		return loft_fail(err, LOFT_EGEOM, -1, "a number of the document "
		    "is not finite (the input is too extreme)");
	return 0;
}

void
loft_cad_attach(struct loft_cad_doc *d, struct loft_writer *w)
{
	d->out = *w;
	memset(w, 0, sizeof *w);
	d->in_head = 0;
}

void
loft_cad_detach(struct loft_cad_doc *d, struct loft_writer *w)
{
	*w = d->out;
	memset(&d->out, 0, sizeof d->out);
}

void
loft_cad_free(struct loft_cad_doc *d)
{
	if (d->f != NULL && d->f->free != NULL)
		d->f->free(d);
	loft_writer_free(&d->out);
	loft_writer_free(&d->head);
	free(d->tmp);
	free(d->surf);
	d->tmp = d->surf = NULL;
	loft_design_free(&d->design);
}
