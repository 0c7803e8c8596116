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

/* Most mesh steps along a patch side: 256^2 cells a patch. */
#define MAX_STEPS 256

/*
 * Vertices of a mesh nearer than this part of the design's size are one:
 * an edge evaluated from the two patches that share it agrees to a few
 * rounding errors (1e-15), and no mesh cell of at most MAX_STEPS steps
 * is anywhere near as small.
 */
#define WELD_TOL 1e-9

/* Edge parameters nearer than this are one place (loft.5's links). */
#define EDGE_TOL 1e-9

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

/*
 * The steps along each side of patch (m, n, ctl) for a mesh within tol:
 * linear interpolation over cells of h = 1/N errs by at most
 * h^2 (M_uu + 2 M_uv + M_vv) / 8, M the bounds of the second derivatives
 * that the net's second differences give (times m (m - 1), m n, n (n - 1)).
 */
static long
steps_for(const double *ctl, int m, int n, double tol)
{
	double muu = 0, muv = 0, mvv = 0, t;
	const double *p = ctl;

#define P(i, j) (p + 3 * ((size_t)(i) * (n + 1) + (j)))
	for (int i = 0; i <= m; i++)
		for (int j = 0; j <= n; j++) {
			double a[3];

			if (i + 2 <= m) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i + 2, j)[k] -
					    2 * P(i + 1, j)[k] + P(i, j)[k];
				if ((t = m * (m - 1) * vnorm(a, 3)) > muu)
					muu = t;
			}
			if (j + 2 <= n) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i, j + 2)[k] -
					    2 * P(i, j + 1)[k] + P(i, j)[k];
				if ((t = n * (n - 1) * vnorm(a, 3)) > mvv)
					mvv = t;
			}
			if (i + 1 <= m && j + 1 <= n) {
				for (int k = 0; k < 3; k++)
					a[k] = P(i + 1, j + 1)[k] -
					    P(i + 1, j)[k] - P(i, j + 1)[k] +
					    P(i, j)[k];
				if ((t = m * n * vnorm(a, 3)) > muv)
					muv = t;
			}
		}
#undef P
	t = ceil(sqrt((muu + 2 * muv + mvv) / (8 * tol)));
	return !(t >= 1) ? 1 : t > MAX_STEPS ? MAX_STEPS : (long)t;
}

struct mesh {
	double *v;
	size_t nv, vcap;
	size_t *t;
	size_t nt, tcap;
};

/* The points of an edge beyond its N steps: parameters, sorted. */
struct extra {
	double *t;
	size_t n, cap;
};

static int
by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

/*
 * The extra points of edge e of design patch ip: the steps k/N of each
 * neighbour across it that fall between this edge's own steps (a
 * T-junction: the neighbour covers part of the edge), mapped into this
 * edge's parameter by the two links; sorted, each once.
 */
static int
edge_extras(const struct loft_design *dz, size_t ip, int e, long N,
    struct extra *x)
{
	const struct loft_patch *p = &dz->p[ip];

	x->n = 0;
	for (size_t l = 0; l < p->nlink[e]; l++) {
		const struct loft_link *L = &p->link[e][l];
		long iq = loft_design_find(dz, L->id);
		const struct loft_link *B = NULL;

		if (iq < 0)
			continue;
		for (int f = 0; f < 4 && B == NULL; f++)
			for (size_t k = 0; k < dz->p[iq].nlink[f]; k++)
				if (dz->p[iq].link[f][k].id == p->id)
					B = &dz->p[iq].link[f][k];
		if (B == NULL || fabs(B->b - B->a) < EDGE_TOL)
			continue;
		for (long k = 0; k <= N; k++) {
			double s = (double)k / N, lo = fmin(B->a, B->b);
			double hi = fmax(B->a, B->b), t, r;

			if (s < lo - EDGE_TOL || s > hi + EDGE_TOL)
				continue;
			t = L->a + (s - B->a) * (L->b - L->a) / (B->b - B->a);
			r = t * N - floor(t * N + 0.5);
			if (t <= EDGE_TOL || t >= 1 - EDGE_TOL ||
			    fabs(r) <= EDGE_TOL * N)
				continue;       /* one of this edge's own steps */
			if (loft__grow((void **)&x->t, &x->cap, x->n + 1,
			    sizeof *x->t) != 0)
				return LOFT_ENOMEM;
			x->t[x->n++] = t;
		}
	}
	if (x->n > 1)
		qsort(x->t, x->n, sizeof *x->t, by_value);
	return 0;
}

static int
add_vertex(struct mesh *me, const struct loft_bsurf *s, double u, double v,
    size_t *at)
{
	if (loft__grow((void **)&me->v, &me->vcap, 3 * (me->nv + 1),
	    sizeof *me->v) != 0)
		return LOFT_ENOMEM;
	loft_bezier_surface_eval(s->ctl, s->m, s->n, u, v, me->v + 3 * me->nv,
	    NULL, NULL);
	*at = me->nv++;
	return 0;
}

static int
add_triangle(struct mesh *me, size_t a, size_t b, size_t c)
{
	if (loft__grow((void **)&me->t, &me->tcap, 3 * (me->nt + 1),
	    sizeof *me->t) != 0)
		return LOFT_ENOMEM;
	me->t[3 * me->nt] = a;
	me->t[3 * me->nt + 1] = b;
	me->t[3 * me->nt + 2] = c;
	me->nt++;
	return 0;
}

/* The extras of x strictly between lo and hi, from lo's end: "rev" from hi's. */
static int
side(struct mesh *me, const struct loft_bsurf *s, const struct extra *x,
    double lo, double hi, int rev, int dir, double fixed, size_t *poly,
    size_t *np)
{
	for (size_t k = 0; k < x->n; k++) {
		double t = x->t[rev ? x->n - 1 - k : k];
		int rc;

		if (t <= lo || t >= hi)
			continue;
		rc = dir == 0 ? add_vertex(me, s, t, fixed, &poly[*np]) :
		    add_vertex(me, s, fixed, t, &poly[*np]);
		if (rc != 0)
			return rc;
		++*np;
	}
	return 0;
}

/*
 * Patch s on an N x N grid: two triangles a cell, counter-clockwise in
 * (u, v); a cell with extra points on its sides (x[edge], by enum
 * loft_edge) a fan around its centre through all its points.
 */
static int
mesh_patch(struct mesh *me, const struct loft_bsurf *s, long N,
    const struct extra *x)
{
	size_t base = me->nv, w = (size_t)N + 1, at;
	size_t *poly = NULL;
	int rc = 0;

	for (size_t i = 0; rc == 0 && i < w; i++)
		for (size_t j = 0; rc == 0 && j < w; j++)
			rc = add_vertex(me, s, (double)i / N, (double)j / N, &at);
	for (size_t i = 0; rc == 0 && i + 1 < w; i++)
		for (size_t j = 0; rc == 0 && j + 1 < w; j++) {
			size_t a = base + i * w + j, b = a + w, np = 0, c;
			double u0 = (double)i / N, u1 = (double)(i + 1) / N;
			double v0 = (double)j / N, v1 = (double)(j + 1) / N;
			size_t cap = 4 + (j == 0 ? x[LOFT_V0].n : 0) +
			    (i + 2 == w ? x[LOFT_U1].n : 0) +
			    (j + 2 == w ? x[LOFT_V1].n : 0) +
			    (i == 0 ? x[LOFT_U0].n : 0);

			if (cap == 4) {
				rc = add_triangle(me, a, b, b + 1) ||
				    add_triangle(me, a, b + 1, a + 1);
				continue;
			}
			free(poly);
			if ((poly = malloc(cap * sizeof *poly)) == NULL)
				return LOFT_ENOMEM;
			/* counter-clockwise: v = v0, u = u1, v = v1, u = u0 */
			poly[np++] = a;
			if (j == 0)
				rc = side(me, s, &x[LOFT_V0], u0, u1, 0, 0, 0, poly,
				    &np);
			poly[np++] = b;
			if (rc == 0 && i + 2 == w)
				rc = side(me, s, &x[LOFT_U1], v0, v1, 0, 1, 1, poly,
				    &np);
			poly[np++] = b + 1;
			if (rc == 0 && j + 2 == w)
				rc = side(me, s, &x[LOFT_V1], u0, u1, 1, 0, 1, poly,
				    &np);
			poly[np++] = a + 1;
			if (rc == 0 && i == 0)
				rc = side(me, s, &x[LOFT_U0], v0, v1, 1, 1, 0, poly,
				    &np);
			if (rc == 0)
				rc = add_vertex(me, s, (u0 + u1) / 2, (v0 + v1) / 2,
				    &c);
			for (size_t k = 0; rc == 0 && k < np; k++)
				rc = add_triangle(me, c, poly[k], poly[(k + 1) % np]);
		}
	free(poly);
	return rc ? LOFT_ENOMEM : 0;
}

static const double *weld_v;

static int
by_x(const void *a, const void *b)
{
	double xa = weld_v[3 * *(const size_t *)a];
	double xb = weld_v[3 * *(const size_t *)b];

	return xa < xb ? -1 : xa > xb;
}

/*
 * Weld: vertices within tol are one (the first of them by x), triangles
 * that lose a side to it dropped, the vertices renumbered densely.
 */
static int
weld(struct mesh *me, double tol)
{
	size_t *ord = malloc((me->nv + 1) * sizeof *ord);
	size_t *to = malloc((me->nv + 1) * sizeof *to);
	size_t nv = 0, nt = 0;

	if (ord == NULL || to == NULL) {
		free(ord);
		free(to);
		return LOFT_ENOMEM;
	}
	for (size_t i = 0; i < me->nv; i++) {
		ord[i] = i;
		to[i] = (size_t)-1;
	}
	weld_v = me->v;
	qsort(ord, me->nv, sizeof *ord, by_x);
	for (size_t a = 0; a < me->nv; a++) {
		size_t i = ord[a];

		if (to[i] != (size_t)-1)
			continue;
		to[i] = i;
		for (size_t b = a + 1; b < me->nv &&
		    me->v[3 * ord[b]] - me->v[3 * i] <= tol; b++)
			if (to[ord[b]] == (size_t)-1 &&
			    vdist(me->v + 3 * ord[b], me->v + 3 * i, 3) <= tol)
				to[ord[b]] = i;
	}
	/* renumber the kept vertices in their order, then the triangles */
	for (size_t i = 0; i < me->nv; i++)
		if (to[i] == i) {
			vcopy(me->v + 3 * nv, me->v + 3 * i, 3);
			ord[i] = nv++;
		}
	for (size_t k = 0; k < me->nt; k++) {
		size_t a = ord[to[me->t[3 * k]]], b = ord[to[me->t[3 * k + 1]]];
		size_t c = ord[to[me->t[3 * k + 2]]];

		if (a == b || b == c || a == c)
			continue;
		me->t[3 * nt] = a;
		me->t[3 * nt + 1] = b;
		me->t[3 * nt + 2] = c;
		nt++;
	}
	me->nv = nv;
	me->nt = nt;
	free(ord);
	free(to);
	return 0;
}

/* A triangle's side: its ends (lower first), the triangle, its sense. */
struct side {
	size_t a, b, t;
	int up;                 /* the triangle runs from a to b */
};

static int
by_ends(const void *x, const void *y)
{
	const struct side *p = x, *q = y;

	if (p->a != q->a)
		return p->a < q->a ? -1 : 1;
	return p->b < q->b ? -1 : p->b > q->b;
}

/*
 * Orient the welded mesh consistently: across each side two triangles
 * share, they must run it opposite ways.  Each connected piece keeps the
 * orientation of its first triangle (its first patch's f_u x f_v) and the
 * rest follow by a breadth-first walk; a piece that cannot be oriented
 * (a Moebius band) keeps what the walk gave it.
 */
static int
orient(struct mesh *me)
{
	size_t ns = 3 * me->nt, head = 0, tail = 0;
	struct side *s = malloc((ns + 1) * sizeof *s);
	size_t *nb = malloc((ns + 1) * sizeof *nb);
	size_t *queue = malloc((me->nt + 1) * sizeof *queue);
	unsigned char *same = malloc(ns + 1), *flip = calloc(me->nt + 1, 1);
	unsigned char *seen = calloc(me->nt + 1, 1);
	int rc = LOFT_ENOMEM;

	if (s == NULL || nb == NULL || queue == NULL || same == NULL ||
	    flip == NULL || seen == NULL)
		goto out;
	for (size_t t = 0; t < me->nt; t++)
		for (int k = 0; k < 3; k++) {
			size_t a = me->t[3 * t + k], b = me->t[3 * t + (k + 1) % 3];
			struct side *e = &s[3 * t + k];

			e->a = a < b ? a : b;
			e->b = a < b ? b : a;
			e->t = t;
			e->up = a < b;
			nb[3 * t + k] = (size_t)-1;
		}
	qsort(s, ns, sizeof *s, by_ends);
	/* a side of exactly two triangles links them, in a free slot */
	for (size_t i = 0; i + 1 < ns; i++) {
		size_t j = i + 1;

		if (by_ends(&s[i], &s[j]) != 0 || (j + 1 < ns &&
		    by_ends(&s[j], &s[j + 1]) == 0))
			continue;
		for (int r = 0; r < 2; r++) {
			size_t t = s[r ? j : i].t, k = 3 * t;

			while (k < 3 * t + 2 && nb[k] != (size_t)-1)
				k++;
			nb[k] = s[r ? i : j].t;
			same[k] = s[i].up == s[j].up;
		}
		i = j;
	}
	for (size_t t0 = 0; t0 < me->nt; t0++) {
		if (seen[t0])
			continue;
		seen[t0] = 1;
		queue[tail++] = t0;
		while (head < tail) {
			size_t t = queue[head++];

			for (size_t k = 3 * t; k < 3 * t + 3; k++) {
				size_t n = nb[k];

				if (n == (size_t)-1 || seen[n])
					continue;
				seen[n] = 1;
				flip[n] = flip[t] ^ same[k];
				queue[tail++] = n;
			}
		}
	}
	for (size_t t = 0; t < me->nt; t++)
		if (flip[t]) {
			size_t x = me->t[3 * t + 1];

			me->t[3 * t + 1] = me->t[3 * t + 2];
			me->t[3 * t + 2] = x;
		}
	rc = 0;
out:
	free(s);
	free(nb);
	free(queue);
	free(same);
	free(flip);
	free(seen);
	return rc;
}

static int
make_mesh(struct loft_cad_doc *d)
{
	struct mesh me = { NULL, 0, 0, NULL, 0, 0 };
	struct extra x[4] = { { NULL, 0, 0 }, { NULL, 0, 0 }, { NULL, 0, 0 },
	    { NULL, 0, 0 } };
	double size = 0, tol;
	long N = d->o.per;
	int rc = 0;

	for (int k = 0; k < 3; k++)
		size = hypot(size, d->box[3 + k] - d->box[k]);
	tol = d->o.tol > 0 ? d->o.tol : LOFT_CAD_MESHTOL * size;
	/* one step count for every patch, so shared edges match */
	for (size_t i = 0; N == 0 && i < d->nsurf; ) {
		int m = (int)d->surf[i], n = (int)d->surf[i + 1];
		long s = steps_for(d->surf + i + SURF_HEAD, m, n, tol);

		N = s > N ? s : N;
		i += SURF_HEAD + 3 * (size_t)(m + 1) * (n + 1);
	}
	N = N > 0 ? N : 1;
	for (size_t i = 0; rc == 0 && i < d->nsurf; ) {
		struct loft_bsurf s = { d->surf + i + SURF_HEAD,
		    (int)d->surf[i], (int)d->surf[i + 1] };
		long ip = (long)d->surf[i + 2];

		for (int e = 0; e < 4; e++) {
			x[e].n = 0;
			if (rc == 0 && ip >= 0)
				rc = edge_extras(&d->design, (size_t)ip, e, N, &x[e]);
		}
		if (rc == 0)
			rc = mesh_patch(&me, &s, N, x);
		i += SURF_HEAD + 3 * (size_t)(s.m + 1) * (s.n + 1);
	}
	for (int e = 0; e < 4; e++)
		free(x[e].t);
	if (rc == 0)
		rc = weld(&me, WELD_TOL * size);
	if (rc == 0)
		rc = orient(&me);
	if (rc == 0 && me.nt == 0)
		rc = LOFT_EGEOM;        /* no area: no facet (issue 28) */
	if (rc == 0)
		rc = d->f->mesh(d, me.v, me.nv, me.t, me.nt);
	free(me.v);
	free(me.t);
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
