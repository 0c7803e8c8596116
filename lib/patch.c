/*
 * patch.c: MacCallum's bi-quartic patches (MacCallum 1970, sections 3
 * to 6): evaluation, `patch` records and designs of patches that name
 * their neighbours, splitting, dragging, joining, and first patches.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

const char *const loft_edge_name[4] = { "u0", "u1", "v0", "v1" };

/*
 * Two ends of links closer than this, in an edge's parameter [0, 1],
 * are the same place: a split at the parameter of an earlier T-junction,
 * reached through a few rescalings that each round by 1e-16, must not
 * leave a sliver of a link behind.
 */
#define LINK_EPS 1e-9

/* Ids go up to this, so that new ones fit a long on every system. */
#define ID_MAX 1000000000L

/* Entry (i, j) of B, dim numbers. */
#define BIJ(b, i, j, dim) ((b) + (5 * (i) + (j)) * (dim))

/*
 * Section 4: f(u, v) = u M B M^t v^t = sum_i H_i(u) g_i(v), where
 * g_i(v) = sum_j B[i][j] H_j(v) is the quartic in v of row i.
 */
void
loft_patch_eval(const double *b, int dim, double u, double v,
    double *p, double *du, double *dv)
{
	double g[5][LOFT_MAXDIM], gv[5][LOFT_MAXDIM];
	const double *k[5];

	for (int i = 0; i < 5; i++) {
		for (int j = 0; j < 5; j++)
			k[j] = BIJ(b, i, j, dim);
		loft__quartic_combine(k, dim, v, g[i], dv ? &gv[i][0] : NULL,
		    NULL);
	}
	for (int i = 0; i < 5; i++)
		k[i] = g[i];
	loft__quartic_combine(k, dim, u, p, du, NULL);
	if (dv != NULL) {
		for (int i = 0; i < 5; i++)
			k[i] = gv[i];
		loft__quartic_combine(k, dim, u, dv, NULL, NULL);
	}
}

/*
 * Section 5.  The piece of a quartic from lo to hi, over its own
 * s in [0, 1] (u = lo + s (hi - lo)), has coefficients
 * sum_k W[i][k] K_k: the values H_k(lo) and H_k(hi), (hi - lo) times
 * the slopes H'_k there, and H_k at the middle.  At lo = 0 and hi = 1
 * the rows are unit vectors (H exact there), so the old edge's entries
 * are copied unchanged; the paper's list of scaled slopes and twists
 * is rows 0 to 3 of this, and row 4 recomputes the (h) entries.
 */
static void
split_weights(double lo, double hi, double w[5][5])
{
	double h[5], dh[5], len = hi - lo;

	loft_quartic_h(lo, h, dh, NULL);
	for (int k = 0; k < 5; k++) {
		w[0][k] = h[k];
		w[2][k] = len * dh[k];
	}
	loft_quartic_h(hi, h, dh, NULL);
	for (int k = 0; k < 5; k++) {
		w[1][k] = h[k];
		w[3][k] = len * dh[k];
	}
	loft_quartic_h(lo + len / 2, h, NULL, NULL);
	for (int k = 0; k < 5; k++)
		w[4][k] = h[k];
}

/* b2 = W b (dir 0, acting on the u index) or b W^t (dir 1). */
static void
apply_weights(const double *b, int dim, int dir, double w[5][5], double *b2)
{
	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 5; j++)
			for (int c = 0; c < dim; c++) {
				double s = 0;

				for (int k = 0; k < 5; k++)
					s += dir == 0 ?
					    w[i][k] * BIJ(b, k, j, dim)[c] :
					    w[j][k] * BIJ(b, i, k, dim)[c];
				BIJ(b2, i, j, dim)[c] = s;
			}
}

void
loft_patch_split_coef(const double *b, int dim, int dir, double t,
    double *b1, double *b2)
{
	double w[5][5];

	split_weights(0, t, w);
	apply_weights(b, dim, dir, w, b1);
	split_weights(t, 1, w);
	apply_weights(b, dim, dir, w, b2);
}

double
loft_patch_size(const double *b, int dim)
{
	double lo[LOFT_MAXDIM] = { 0 }, hi[LOFT_MAXDIM] = { 0 }, p[LOFT_MAXDIM];
	double s = 0;           /* lo, hi: set at (0, 0) first */

	for (int i = 0; i <= 4; i++)
		for (int j = 0; j <= 4; j++) {
			loft_patch_eval(b, dim, i / 4.0, j / 4.0, p, NULL, NULL);
			for (int c = 0; c < dim; c++) {
				if ((i == 0 && j == 0) || p[c] < lo[c])
					lo[c] = p[c];
				if ((i == 0 && j == 0) || p[c] > hi[c])
					hi[c] = p[c];
			}
		}
	for (int c = 0; c < dim; c++)
		s += (hi[c] - lo[c]) * (hi[c] - lo[c]);
	return sqrt(s);
}

/* ------------------------------------------------------------------ */
/* First patches */

/* The quartic coefficients of 1 - u and of u. */
static const double lin0[5] = { 1, 0, -1, -1, 0.5 };
static const double lin1[5] = { 0, 1, 1, 1, 0.5 };

/* B[i][j] = sum over corners of l_a[i] l_b[j] P_ab: the bilinear patch. */
void
loft_patch_bilinear(const double *corner, int dim, double *b)
{
	const double *p00 = corner, *p10 = corner + dim,
	    *p01 = corner + 2 * dim, *p11 = corner + 3 * dim;

	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 5; j++)
			for (int c = 0; c < dim; c++)
				BIJ(b, i, j, dim)[c] =
				    lin0[i] * lin0[j] * p00[c] +
				    lin1[i] * lin0[j] * p10[c] +
				    lin0[i] * lin1[j] * p01[c] +
				    lin1[i] * lin1[j] * p11[c];
}

int
loft_curve_segments(const struct loft_record *rec, struct loft_curve *c,
    struct loft_error *err)
{
	int rc = loft_curve_from_record(rec, c, err);

	if (rc == 0 && (!loft_record_is(rec, LOFT_KIND_SEGMENTS) ||
	    c->quartic == NULL))
		return loft_fail(err, LOFT_EINPUT, -1, "a %s record: want a "
		    "curve of cubic or quartic segments", c->type);
	return rc;
}

/*
 * Coons' bilinearly blended patch, the Boolean sum
 *   f = (1 - u) a(v) + u b(v) + (1 - v) c(u) + v d(u) - bilinear(corners)
 * with a, b the edges u = 0, 1 and c, d the edges v = 0, 1.  Each term
 * is a tensor of quartics, so f is a bi-quartic: B = l (x) a + ... .
 * Its cross-boundary derivatives blend linearly between the corners,
 * and its twist at (0,0), for one, is
 *   (10)_v - (00)_v + (01)_u - (00)_u - ((11) - (10) - (01) + (00)).
 */
int
loft_patch_coons(const double *const *cv, int dim, double *b,
    struct loft_error *err)
{
	static const char *const what[4] = { "1 (v=0)", "2 (v=1)",
	    "3 (u=0)", "4 (u=1)" };
	/* corner: name, curve and end (0 start, 1 end) on each side */
	static const struct { const char *name; int c1, e1, c2, e2; } cn[4] = {
		{ "(00)", 0, 0, 2, 0 }, { "(10)", 0, 1, 3, 0 },
		{ "(01)", 1, 0, 2, 1 }, { "(11)", 1, 1, 3, 1 },
	};
	double corner[4 * LOFT_MAXDIM], lo[LOFT_MAXDIM] = { 0 },
	    hi[LOFT_MAXDIM] = { 0 };    /* set by the first end first */
	double size = 0;

	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "boundary curves of %d "
		    "coordinates: want 2 or 3", dim);
	for (int q = 0; q < 4; q++)
		for (int e = 0; e < 2; e++)
			for (int c = 0; c < dim; c++) {
				double x = cv[q][e * dim + c];

				if ((q == 0 && e == 0) || x < lo[c])
					lo[c] = x;
				if ((q == 0 && e == 0) || x > hi[c])
					hi[c] = x;
			}
	for (int c = 0; c < dim; c++)
		size += (hi[c] - lo[c]) * (hi[c] - lo[c]);
	size = sqrt(size);
	for (int k = 0; k < 4; k++) {
		const double *x = cv[cn[k].c1] + cn[k].e1 * dim,
		    *y = cv[cn[k].c2] + cn[k].e2 * dim;
		double gap = vdist(x, y, dim);

		if (!(gap <= LOFT_CORNER_TOL * size))
			return loft_fail(err, LOFT_EGEOM, cn[k].c2, "corner %s: "
			    "the %s of curve %s is %g from the %s of curve %s",
			    cn[k].name, cn[k].e1 ? "end" : "start",
			    what[cn[k].c1], gap, cn[k].e2 ? "end" : "start",
			    what[cn[k].c2]);
		vcopy(corner + k * dim, x, dim);
	}
	loft_patch_bilinear(corner, dim, b);
	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 5; j++)
			for (int c = 0; c < dim; c++)
				BIJ(b, i, j, dim)[c] =
				    lin0[i] * cv[2][j * dim + c] +
				    lin1[i] * cv[3][j * dim + c] +
				    cv[0][i * dim + c] * lin0[j] +
				    cv[1][i * dim + c] * lin1[j] -
				    BIJ(b, i, j, dim)[c];
	/* the boundaries exactly as given, corners from c and d */
	for (int k = 0; k < 5; k++) {
		vcopy(BIJ(b, 0, k, dim), cv[2] + k * dim, dim);
		vcopy(BIJ(b, 1, k, dim), cv[3] + k * dim, dim);
	}
	for (int k = 0; k < 5; k++) {
		vcopy(BIJ(b, k, 0, dim), cv[0] + k * dim, dim);
		vcopy(BIJ(b, k, 1, dim), cv[1] + k * dim, dim);
	}
	return 0;
}

/* ------------------------------------------------------------------ */
/* The index of ids: nothing in a design is quadratic in its patches */

/*
 * Entries (id, index of the patch in d->p), sorted by id, then index,
 * so that a lookup is a binary search.  Entries are appended as patches
 * come; while ids come in increasing order (a split's new ids are the
 * largest) the index stays sorted, and otherwise the next lookup sorts
 * it, once.  A split patch's entry is marked gone, and gone entries are
 * dropped when they are half of all, so each split costs O(log n)
 * amortised.
 */
struct slot {
	long id;
	size_t i;
	int gone;
};

struct loft_design_index {
	struct slot *e;
	size_t n, cap;
	size_t sorted;          /* e[0..sorted) is in order */
	size_t gone;            /* entries marked gone */
};

static int
slot_cmp(const void *a, const void *b)
{
	const struct slot *x = a, *y = b;

	if (x->id != y->id)
		return x->id < y->id ? -1 : 1;
	return x->i < y->i ? -1 : x->i > y->i;
}

/* Make room for k more entries, so that index_add cannot fail. */
static int
index_reserve(struct loft_design *d, size_t k)
{
	if (d->index == NULL && (d->index = calloc(1, sizeof *d->index)) ==
	    NULL)
		return LOFT_ENOMEM;
	if (loft__grow((void **)&d->index->e, &d->index->cap,
	    d->index->n + k, sizeof *d->index->e) != 0)
		return LOFT_ENOMEM;
	return 0;
}

/* Append (id, i); index_reserve made room. */
static void
index_add(struct loft_design *d, long id, size_t i)
{
	struct loft_design_index *x = d->index;
	struct slot s = { id, i, 0 };

	if (x->sorted == x->n && (x->n == 0 ||
	    slot_cmp(&x->e[x->n - 1], &s) < 0))
		x->sorted++;
	x->e[x->n++] = s;
}

/* Sort the index if patches came out of order; the first entry with id. */
static size_t
index_lower(const struct loft_design *d, long id)
{
	struct loft_design_index *x = d->index;
	size_t lo = 0, hi = x->n;

	if (x->sorted < x->n) {
		qsort(x->e, x->n, sizeof *x->e, slot_cmp);
		x->sorted = x->n;
	}
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;

		if (x->e[mid].id < id)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/* Mark the entry of patch i, with id, gone. */
static void
index_drop(struct loft_design *d, long id, size_t i)
{
	struct loft_design_index *x = d->index;
	size_t k = index_lower(d, id), m = 0;

	while (k < x->n && x->e[k].id == id && x->e[k].i != i)
		k++;
	if (k == x->n || x->e[k].id != id || x->e[k].gone)
		return;
	x->e[k].gone = 1;
	if (++x->gone * 2 <= x->n)
		return;
	for (k = 0; k < x->n; k++)
		if (!x->e[k].gone)
			x->e[m++] = x->e[k];
	x->n = x->sorted = m;
	x->gone = 0;
}

/* ------------------------------------------------------------------ */
/* Designs: patch records and neighbour links */

static int
add_link(struct loft_patch *p, int e, long id, double a, double b)
{
	size_t i;

	/* most edges have one or two neighbours: start small (a design
	 * of n patches holds 4 n of these lists) */
	if (p->nlink[e] == p->linkcap[e]) {
		size_t cap = p->linkcap[e] ? 2 * p->linkcap[e] : 2;
		struct loft_link *l = cap > (size_t)-1 / sizeof *l ? NULL :
		    realloc(p->link[e], cap * sizeof *l);

		if (l == NULL)
			return LOFT_ENOMEM;
		p->link[e] = l;
		p->linkcap[e] = cap;
	}
	/* keep the list sorted by where each link starts on the edge */
	for (i = p->nlink[e]; i > 0 && fmin(p->link[e][i - 1].a,
	    p->link[e][i - 1].b) > fmin(a, b); i--)
		p->link[e][i] = p->link[e][i - 1];
	p->link[e][i].id = id;
	p->link[e][i].a = a;
	p->link[e][i].b = b;
	p->nlink[e]++;
	return 0;
}

static void
drop_link(struct loft_patch *p, int e, size_t k)
{
	memmove(&p->link[e][k], &p->link[e][k + 1],
	    (p->nlink[e] - k - 1) * sizeof p->link[e][k]);
	p->nlink[e]--;
}

/* Find the link to id on any edge of p: 1 and *e, *k; 0 when none. */
static int
find_link(const struct loft_patch *p, long id, int *e, size_t *k)
{
	for (int f = 0; f < 4; f++)
		for (size_t i = 0; i < p->nlink[f]; i++)
			if (p->link[f][i].id == id) {
				*e = f;
				*k = i;
				return 1;
			}
	return 0;
}

int
loft__patch_shape(const struct loft_record *rec, struct loft_error *err)
{
	if (rec->nrows != 5)
		return loft_fail(err, LOFT_EINPUT, -1, "patch record has %zu "
		    "row%s; a patch has 5", rec->nrows, rec->nrows == 1 ? "" :
		    "s");
	if (rec->ncols != 10 && rec->ncols != 15)
		return loft_fail(err, LOFT_EINPUT, 0, "patch rows need 10 or 15 "
		    "numbers, not %d", rec->ncols);
	return 0;
}
/* Parse one item of a neighbour list, "id" or "id:a:b", into l. */
static int
parse_item(const char *s, size_t len, struct loft_link *l,
    struct loft_error *err)
{
	char buf[64];
	const char *c1, *c2;

	if (len == 0 || len >= sizeof buf)
		return LOFT_EINPUT;
	memcpy(buf, s, len);
	buf[len] = '\0';
	c1 = strchr(buf, ':');
	c2 = c1 ? strchr(c1 + 1, ':') : NULL;
	l->a = 0;
	l->b = 1;
	if (c1 != NULL && (c2 == NULL || strchr(c2 + 1, ':') != NULL))
		return LOFT_EINPUT;
	if (c1 != NULL) {
		buf[c1 - buf] = '\0';
		if (loft_parse_num(c1 + 1, (size_t)(c2 - c1 - 1), &l->a,
		    err) != 0 || loft_parse_num(c2 + 1, strlen(c2 + 1), &l->b,
		    err) != 0)
			return LOFT_EINPUT;
	}
	return loft_parse_int(buf, 1, ID_MAX, &l->id, err);
}

static int
parse_links(struct loft_patch *p, int e, const char *val,
    struct loft_error *err)
{
	const char *s = val;

	for (;;) {
		size_t len = strcspn(s, ",");
		struct loft_link l;

		if (parse_item(s, len, &l, err) != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: "
			    "want neighbour ids, or id:from:to, separated by "
			    "commas", loft_edge_name[e], val);
		if (!(l.a >= 0 && l.a <= 1 && l.b >= 0 && l.b <= 1) ||
		    !(fabs(l.a - l.b) > LINK_EPS))
			return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: "
			    "from and to must differ and lie from 0 to 1",
			    loft_edge_name[e], val);
		if (add_link(p, e, l.id, l.a, l.b) != 0)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		if (s[len] == '\0')
			return 0;
		s += len + 1;
	}
}

static void
patch_free(struct loft_patch *p)
{
	for (int e = 0; e < 4; e++)
		free(p->link[e]);
	memset(p, 0, sizeof *p);
}

static int
design_grow(struct loft_design *d, struct loft_error *err)
{
	if (loft__grow((void **)&d->p, &d->cap, d->n + 1, sizeof *d->p) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	memset(&d->p[d->n], 0, sizeof d->p[d->n]);
	return 0;
}

int
loft_design_new(struct loft_design *d, const double *b, int dim, long id,
    struct loft_error *err)
{
	struct loft_patch *p;

	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, -1, "a patch of %d "
		    "coordinates: want 2 or 3", dim);
	if (id < 1 || id > ID_MAX)
		return loft_fail(err, LOFT_EINPUT, -1, "id %ld: want a whole "
		    "number from 1 to %ld", id, ID_MAX);
	if (design_grow(d, err) != 0 || index_reserve(d, 1) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	index_add(d, id, d->n);
	p = &d->p[d->n++];
	p->id = id;
	p->dim = dim;
	p->scale[0] = p->scale[1] = 1;
	memcpy(p->b, b, 25 * (size_t)dim * sizeof *b);
	if (id > d->maxid)
		d->maxid = id;
	return 0;
}

int
loft_patch_id(const struct loft_record *rec, long *id, struct loft_error *err)
{
	const char *v = loft_attr(rec, "id");

	if (v == NULL)
		return loft_fail(err, LOFT_EINPUT, -1, "patch has no id=");
	if (loft_parse_int(v, 1, ID_MAX, id, err) != 0)
		return loft_fail(err, LOFT_EINPUT, -1, "attribute id=%s: want "
		    "a whole number from 1 to %ld", v, ID_MAX);
	return 0;
}

int
loft_design_add(struct loft_design *d, const struct loft_record *rec,
    struct loft_error *err)
{
	static const char *const sname[2] = { "su", "sv" };
	struct loft_patch *p;
	const char *v;
	int dim = rec->ncols / 5, rc;
	long id;

	if (!loft_record_is(rec, LOFT_KIND_MEMBER))
		return loft_fail(err, LOFT_EINPUT, -1, "not a patch record");
	if (loft__patch_shape(rec, err) != 0)
		return LOFT_EINPUT;
	if (loft_patch_id(rec, &id, err) != 0)
		return LOFT_EINPUT;
	if (design_grow(d, err) != 0 || index_reserve(d, 1) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	p = &d->p[d->n];
	p->id = id;
	p->dim = dim;
	p->rec = rec;
	memcpy(p->b, rec->num, 25 * (size_t)dim * sizeof *p->b);
	for (int k = 0; k < 2; k++) {
		p->scale[k] = 1;
		v = loft_attr(rec, sname[k]);
		if (v != NULL && (loft_parse_num(v, strlen(v), &p->scale[k],
		    err) != 0 || !(p->scale[k] > 0))) {
			patch_free(p);
			return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: "
			    "want a scale factor above 0", sname[k], v);
		}
	}
	for (int e = 0; e < 4; e++)
		if ((v = loft_attr(rec, loft_edge_name[e])) != NULL &&
		    (rc = parse_links(p, e, v, err)) != 0) {
			patch_free(p);
			return rc;
		}
	if (p->id > d->maxid)
		d->maxid = p->id;
	index_add(d, p->id, d->n);
	d->n++;
	return 0;
}

void
loft_design_free(struct loft_design *d)
{
	for (size_t i = 0; i < d->n; i++)
		patch_free(&d->p[i]);
	free(d->p);
	if (d->index != NULL)
		free(d->index->e);
	free(d->index);
	memset(d, 0, sizeof *d);
}

/* With duplicate ids (loft_design_check refuses them), the first. */
long
loft_design_find(const struct loft_design *d, long id)
{
	size_t k;

	if (d->index == NULL)
		return -1;
	for (k = index_lower(d, id); k < d->index->n &&
	    d->index->e[k].id == id; k++)
		if (!d->index->e[k].gone)
			return (long)d->index->e[k].i;
	return -1;
}

/*
 * Every link of a design, as (patch index, neighbour id, where), sorted
 * by the first two: loft_design_check finds a link back, and a
 * neighbour named twice, by binary search.
 */
struct named {
	size_t from;
	long to;
	int e;
	size_t k;
};

static int
named_cmp(const void *a, const void *b)
{
	const struct named *x = a, *y = b;

	if (x->from != y->from)
		return x->from < y->from ? -1 : 1;
	if (x->to != y->to)
		return x->to < y->to ? -1 : 1;
	return x->e != y->e ? x->e - y->e : (x->k > y->k) - (x->k < y->k);
}

/* The first of all[0..n) that patch from has to id, or NULL. */
static const struct named *
named_find(const struct named *all, size_t n, size_t from, long to)
{
	size_t lo = 0, hi = n;

	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;

		if (all[mid].from < from || (all[mid].from == from &&
		    all[mid].to < to))
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo < n && all[lo].from == from && all[lo].to == to ?
	    &all[lo] : NULL;
}

/* Check patch i's links against all[0..nall); 0 or LOFT_EINPUT. */
static int
check_links(const struct loft_design *d, size_t i, const struct named *all,
    size_t nall, struct loft_error *err)
{
	const struct loft_patch *p = &d->p[i];

	for (int e = 0; e < 4; e++)
		for (size_t k = 0; k < p->nlink[e]; k++) {
			const struct loft_link *l = &p->link[e][k], *m;
			long n = loft_design_find(d, l->id);
			const struct named *x;

			if (l->id == p->id)
				return loft_fail(err, LOFT_EINPUT, -1, "patch %ld "
				    "names itself as neighbour across %s",
				    p->id, loft_edge_name[e]);
			if (n < 0)
				return loft_fail(err, LOFT_EINPUT, -1, "patch %ld: "
				    "neighbour %ld across %s is not in the "
				    "design", p->id, l->id, loft_edge_name[e]);
			x = named_find(all, nall, i, l->id);
			if (x + 1 < all + nall && x[1].from == i &&
			    x[1].to == l->id)
				return loft_fail(err, LOFT_EINPUT, -1, "patch %ld "
				    "names neighbour %ld more than once",
				    p->id, l->id);
			if ((x = named_find(all, nall, (size_t)n, p->id)) == NULL)
				return loft_fail(err, LOFT_EINPUT, -1, "patch %ld "
				    "names %ld across %s, but %ld does not name "
				    "%ld", p->id, l->id, loft_edge_name[e],
				    l->id, p->id);
			m = &d->p[n].link[x->e][x->k];
			if ((l->a < l->b) != (m->a < m->b))
				return loft_fail(err, LOFT_EINPUT, -1, "patches "
				    "%ld and %ld disagree on which way their "
				    "common edge runs", p->id, l->id);
		}
	return 0;
}

/*
 * The first patch whose id an earlier patch has, or d->n: in the sorted
 * index, every entry after the first of a run of equal ids.
 */
static size_t
first_duplicate(const struct loft_design *d)
{
	const struct loft_design_index *x = d->index;
	size_t dup = d->n;

	if (x == NULL || d->n == 0)
		return dup;
	(void)index_lower(d, 0);        /* sorts */
	for (size_t k = 1; k < x->n; k++)
		if (!x->e[k].gone && !x->e[k - 1].gone &&
		    x->e[k].id == x->e[k - 1].id && x->e[k].i < dup)
			dup = x->e[k].i;
	return dup;
}

int
loft_design_check(const struct loft_design *d, size_t *bad,
    struct loft_error *err)
{
	struct named *all = NULL;
	size_t nall = 0, dup = first_duplicate(d);
	int rc = 0;

	*bad = 0;
	for (size_t i = 0; i < d->n; i++)
		for (int e = 0; e < 4; e++)
			nall += d->p[i].nlink[e];
	if (nall > 0 && (all = malloc(nall * sizeof *all)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	nall = 0;
	for (size_t i = 0; i < d->n; i++)
		for (int e = 0; e < 4; e++)
			for (size_t k = 0; k < d->p[i].nlink[e]; k++)
				all[nall++] = (struct named){ i,
				    d->p[i].link[e][k].id, e, k };
	if (nall > 0)
		qsort(all, nall, sizeof *all, named_cmp);
	for (size_t i = 0; i < d->n && rc == 0; i++) {
		*bad = i;
		if (d->p[i].dim != d->p[0].dim)
			rc = loft_fail(err, LOFT_EINPUT, -1, "patch %ld has %d "
			    "coordinates, patch %ld %d: a design has one "
			    "dimension", d->p[i].id, d->p[i].dim, d->p[0].id,
			    d->p[0].dim);
		else if (i == dup)
			rc = loft_fail(err, LOFT_EINPUT, -1, "id %ld is used "
			    "twice", d->p[i].id);
		else
			rc = check_links(d, i, all, nall, err);
	}
	free(all);
	return rc;
}

/* ------------------------------------------------------------------ */
/* Splitting (section 5) */

/*
 * Where the point at parameter s of p's edge, inside the link l = (q, a,
 * b), lies on q's edge, whose link back to p is m: q's parameter runs
 * from min(m.a, m.b) to max(m.a, m.b) while p's runs from a to b.
 */
static double
across(const struct loft_link *l, const struct loft_link *m, double s)
{
	double lo = fmin(m->a, m->b), hi = fmax(m->a, m->b);

	if (s == l->a)
		return lo;
	if (s == l->b)
		return hi;
	return lo + (s - l->a) / (l->b - l->a) * (hi - lo);
}

/* Rename the link to old in p's list as new. */
static void
rename_link(struct loft_patch *p, long old, long new)
{
	int e;
	size_t k;

	if (find_link(p, old, &e, &k))
		p->link[e][k].id = new;
}

/* An edge parameter within LINK_EPS of an end of the edge is that end. */
static double
snap(double s)
{
	return s < LINK_EPS ? 0 : s > 1 - LINK_EPS ? 1 : s;
}

/*
 * The part of a cut edge's link l = (q, a, b) that falls on child c
 * (0: parameter 0 to t, 1: t to 1) of the patch being split, as links
 * on both sides.  The child's edge parameter is s/t or (s - t)/(1 - t).
 */
static int
cut_link(struct loft_design *d, struct loft_patch *child, int e, int c,
    double t, const struct loft_link *l, long qi, int f,
    const struct loft_link *back)
{
	double lo = fmin(l->a, l->b), hi = fmax(l->a, l->b), p0, p1, s0, s1;

	p0 = c == 0 ? lo : fmax(lo, t);
	p1 = c == 0 ? fmin(hi, t) : hi;
	if (!(p1 - p0 > LINK_EPS))
		return 0;
	s0 = snap(c == 0 ? p0 / t : (p0 - t) / (1 - t));
	s1 = snap(c == 0 ? p1 / t : (p1 - t) / (1 - t));
	if (add_link(child, e, l->id, l->a < l->b ? s0 : s1,
	    l->a < l->b ? s1 : s0) != 0 ||
	    add_link(&d->p[qi], f, child->id, snap(across(l, back, p0)),
	    snap(across(l, back, p1))) != 0)
		return LOFT_ENOMEM;
	return 0;
}

/* loft_design_split's preconditions: 0, or LOFT_EINPUT with err. */
static int
split_check(const struct loft_design *d, size_t i, int dir, double t,
    struct loft_error *err)
{
	if (i >= d->n || (dir != 0 && dir != 1) || !(t > 0 && t < 1))
		return loft_fail(err, LOFT_EINPUT, -1, "split of patch %zu of "
		    "%zu, direction %d, at %g: want a patch of the design, "
		    "direction 0 or 1, 0 < t < 1", i, d->n, dir, t);
	/* the links the children keep are renamed in the neighbours: each
	 * must be there (loft_design_check's promise, checked here) */
	for (int e = 0; e < 4; e++)
		for (size_t k = 0; k < d->p[i].nlink[e]; k++)
			if (loft_design_find(d, d->p[i].link[e][k].id) < 0)
				return loft_fail(err, LOFT_EINPUT, -1, "patch %ld:"
				    " neighbour %ld across %s is not in the "
				    "design", d->p[i].id, d->p[i].link[e][k].id,
				    loft_edge_name[e]);
	if (d->maxid > ID_MAX - 2)
		return loft_fail(err, LOFT_EINPUT, -1, "ids are used up (the "
		    "largest is %ld)", d->maxid);
	return 0;
}

/* The links of q across the edges cut[0..1] the split cuts, divided at
 * t between the children ch (and renamed in the neighbours): 0, or -1
 * when memory ran out. */
static int
split_cut_links(struct loft_design *d, struct loft_patch *q,
    struct loft_patch *ch, const int *cut, double t)
{
	for (int k = 0; k < 2; k++) {
		int e = cut[k];

		for (size_t m = 0; m < q->nlink[e]; m++) {
			struct loft_link l = q->link[e][m], back;
			long qi = loft_design_find(d, l.id);
			int f;
			size_t r;

			if (qi < 0 || !find_link(&d->p[qi], q->id, &f, &r))
				continue;       /* loft_design_check refuses */
			back = d->p[qi].link[f][r];
			drop_link(&d->p[qi], f, r);
			for (int c = 0; c < 2; c++)
				if (cut_link(d, &ch[c], e, c, t, &l, qi, f,
				    &back) != 0)
					return -1;
		}
	}
	return 0;
}

int
loft_design_split(struct loft_design *d, size_t i, int dir, double t,
    struct loft_error *err)
{
	int keep0 = dir == 0 ? LOFT_U0 : LOFT_V0;
	int keep1 = dir == 0 ? LOFT_U1 : LOFT_V1;
	int cut[2] = { dir == 0 ? LOFT_V0 : LOFT_U0,
	    dir == 0 ? LOFT_V1 : LOFT_U1 };
	struct loft_patch ch[2], *q;

	if (split_check(d, i, dir, t, err) != 0)
		return LOFT_EINPUT;
	if (design_grow(d, err) != 0 || index_reserve(d, 2) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	q = &d->p[i];
	memset(ch, 0, sizeof ch);
	for (int c = 0; c < 2; c++) {
		ch[c].id = d->maxid + 1 + c;
		ch[c].dim = q->dim;
		ch[c].rec = q->rec;
		ch[c].scale[0] = q->scale[0];
		ch[c].scale[1] = q->scale[1];
		ch[c].scale[dir] *= c == 0 ? t : 1 - t;
	}
	loft_patch_split_coef(q->b, q->dim, dir, t, ch[0].b, ch[1].b);
	/* the edges each child keeps whole, and the new one between */
	for (int c = 0; c < 2; c++) {
		int e = c == 0 ? keep0 : keep1;

		ch[c].link[e] = q->link[e];
		ch[c].nlink[e] = q->nlink[e];
		ch[c].linkcap[e] = q->linkcap[e];
		q->link[e] = NULL;
		q->nlink[e] = q->linkcap[e] = 0;
		for (size_t k = 0; k < ch[c].nlink[e]; k++)
			rename_link(&d->p[loft_design_find(d,
			    ch[c].link[e][k].id)], q->id, ch[c].id);
	}
	if (add_link(&ch[0], keep1, ch[1].id, 0, 1) != 0 ||
	    add_link(&ch[1], keep0, ch[0].id, 0, 1) != 0)
		goto nomem;
	/* the edges the split cuts: their links divide at t */
	if (split_cut_links(d, q, ch, cut, t) != 0)
		goto nomem;
	index_drop(d, q->id, i);
	patch_free(q);
	d->p[i] = ch[0];
	d->p[d->n] = ch[1];
	index_add(d, ch[0].id, i);
	index_add(d, ch[1].id, d->n);
	d->n++;
	d->maxid += 2;
	return 0;
nomem:
	patch_free(&ch[0]);
	patch_free(&ch[1]);
	return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
}

/* ------------------------------------------------------------------ */
/* Dragging (section 4) */

/* The normal direction of edge e: 0 (u) for u0, u1; 1 (v) for v0, v1. */
static int
normal_dir(int e)
{
	return e == LOFT_U0 || e == LOFT_U1 ? 0 : 1;
}

/* Whether edge e lies at parameter 0 of its normal direction. */
static int
at_zero(int e)
{
	return e == LOFT_U0 || e == LOFT_V0;
}

/* B += outer(x, y) c: x over the u index, y over the v index. */
static void
add_tensor(double *b, int dim, const double *x, const double *y,
    const double *c)
{
	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 5; j++)
			vaxpy(BIJ(b, i, j, dim), x[i] * y[j], c, dim);
}

/*
 * The neighbour that the edge rule can drag with p across p's edge e,
 * near which the dragged point lies, at edge parameter s.  Along the
 * edge the bump must be c H5 over all of p's edge, to keep p's two
 * edges beside it (a quartic with double roots at both ends is c H5);
 * for the same reason it is c H5 over all of the neighbour's edge.  So
 * the neighbour covering s must lie along all of p's edge and p along
 * all of the neighbour's: at a T-junction, on either side, no patch
 * but a third could take up the difference, and the central rule
 * applies.  Returns 1 with its index and edge, or 0 with why not.
 */
static int
edge_neighbour(const struct loft_design *d, const struct loft_patch *p,
    int e, double s, long *qi, int *f, char *why, size_t len)
{
	const char *name = loft_edge_name[e], *along = e == LOFT_U0 ||
	    e == LOFT_U1 ? "v" : "u", *back_along;
	const struct loft_link *l = NULL, *m;
	size_t k, r;

	for (k = 0; k < p->nlink[e] && l == NULL; k++)
		if (s >= fmin(p->link[e][k].a, p->link[e][k].b) - LINK_EPS &&
		    s <= fmax(p->link[e][k].a, p->link[e][k].b) + LINK_EPS)
			l = &p->link[e][k];
	if (l == NULL) {
		snprintf(why, len, p->nlink[e] == 0 ? "no neighbour across %s" :
		    "no neighbour across %s at %s=%g", name, along, s);
		return 0;
	}
	if (fabs(l->a - l->b) < 1 - LINK_EPS) {
		snprintf(why, len, "a T-junction on %s: neighbour %ld lies "
		    "along %s=%g to %g of it, and the edge rule needs one "
		    "along all of it", name, l->id, along, fmin(l->a, l->b),
		    fmax(l->a, l->b));
		return 0;
	}
	if ((*qi = loft_design_find(d, l->id)) < 0 ||
	    !find_link(&d->p[*qi], p->id, f, &r)) {
		snprintf(why, len, "neighbour %ld across %s does not name "
		    "this patch", l->id, name);     /* loft_design_check */
		return 0;
	}
	m = &d->p[*qi].link[*f][r];
	back_along = *f == LOFT_U0 || *f == LOFT_U1 ? "v" : "u";
	if (fabs(m->a - m->b) < 1 - LINK_EPS) {
		snprintf(why, len, "a T-junction on %s of neighbour %ld: this "
		    "patch lies along %s=%g to %g of it, and the edge rule "
		    "would move %ld's other neighbours there", loft_edge_name[*f],
		    l->id, back_along, fmin(m->a, m->b), fmax(m->a, m->b), l->id);
		return 0;
	}
	return 1;
}

/*
 * Section 4.  Central rule: delta(hh) = delta / (H5(u) H5(v)).  Near
 * edge e with neighbour q across all of it: in the direction across
 * the edge the two patches are one quartic in w, p on [0, w_p] and q on
 * [w_p, 1] with w_p = r_p / (r_p + r_q) (the scale factors across the
 * edge), the common edge at w_p; both take the exact restriction of the
 * bump delta H5(w) H5(v) / H_d, H_d its value at the dragged point.  So
 * the common edge moves by delta H_p / H_d and its slope by
 * delta H'_p / H_d, and everything else on the rim of the pair stays.
 * Along the edge the bump is H5 in both (H5(1 - s) = H5(s), so either
 * sense of the common edge gives the same coefficients).
 */
int
loft_design_drag(struct loft_design *d, size_t i, double u, double v,
    const double *delta, double edge, struct loft_drag_info *info,
    struct loft_error *err)
{
	static const double h5[5] = { 0, 0, 0, 0, 1 };
	struct loft_patch *p;
	double rho[4] = { u, 1 - u, v, 1 - v }, c[LOFT_MAXDIM], hd;
	int e = 0, dim;
	long qi;
	int f;

	memset(info, 0, sizeof *info);
	if (i >= d->n)
		return loft_fail(err, LOFT_EINPUT, -1, "patch %zu of a design "
		    "of %zu", i, d->n);
	p = &d->p[i];
	dim = p->dim;
	if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
		return loft_fail(err, LOFT_EINPUT, -1, "(u, v) = (%g, %g) is "
		    "outside the patch", u, v);
	for (int k = 0; k < dim; k++)
		if (!isfinite(delta[k]))
			return loft_fail(err, LOFT_EINPUT, -1, "the drag is not "
			    "finite");
	info->piece = (long)i;
	info->other = -1;
	for (int k = 1; k < 4; k++)
		if (rho[k] < rho[e])
			e = k;
	info->edge = e;
	info->rule = LOFT_DRAG_CENTRAL;
	if (rho[e] < edge) {
		if (edge_neighbour(d, p, e, normal_dir(e) == 0 ? v : u, &qi,
		    &f, info->why, sizeof info->why)) {
			struct loft_patch *q = &d->p[qi];
			int n = normal_dir(e), nq = normal_dir(f);
			double rp = p->scale[n], rq = q->scale[nq];
			double wp = rp / (rp + rq), along = n == 0 ? v : u;
			double phip[5], phiq[5];

			loft__bump(at_zero(e) ? wp : 0, at_zero(e) ? -wp : wp,
			    phip);
			loft__bump(at_zero(f) ? wp : 1, at_zero(f) ? 1 - wp :
			    -(1 - wp), phiq);
			hd = loft__h5(wp * (1 - rho[e])) * loft__h5(along);
			if (!(hd > 0))
				return loft_fail(err, LOFT_EGEOM, -1, "the point "
				    "at u=%g v=%g is a corner of the patch, "
				    "which dragging keeps fixed", u, v);
			vscale(c, 1 / hd, delta, dim);
			add_tensor(p->b, dim, n == 0 ? phip : h5,
			    n == 0 ? h5 : phip, c);
			add_tensor(q->b, dim, nq == 0 ? phiq : h5,
			    nq == 0 ? h5 : phiq, c);
			info->rule = LOFT_DRAG_EDGE;
			info->other = qi;
			info->hd = hd;
			info->hp = loft__h5(wp) * loft__h5(along);
			return 0;
		}
		info->rule = LOFT_DRAG_FALLBACK;
	}
	hd = loft__h5(u) * loft__h5(v);
	if (!(hd > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "the point at u=%g v=%g "
		    "is on the patch's edge %s, which dragging keeps fixed%s%s%s",
		    u, v, loft_edge_name[e], info->why[0] ? " (" : "",
		    info->why, info->why[0] ? ")" : "");
	vaxpy(BIJ(p->b, 4, 4, dim), 1 / hd, delta, dim);
	info->hd = hd;
	return 0;
}

/* ------------------------------------------------------------------ */
/* Joining (section 6) */

/*
 * The quartic along edge e of b, over its own parameter: which 0 the
 * points, which 1 the derivative across the edge (in +u or +v).
 */
static void
edge_get(const double *b, int dim, int e, int which, double *q)
{
	int r = (at_zero(e) ? 0 : 1) + 2 * which;

	for (int k = 0; k < 5; k++)
		vcopy(q + k * dim, normal_dir(e) == 0 ? BIJ(b, r, k, dim) :
		    BIJ(b, k, r, dim), dim);
}

static void
edge_set(double *b, int dim, int e, int which, const double *q)
{
	int r = (at_zero(e) ? 0 : 1) + 2 * which;

	for (int k = 0; k < 5; k++)
		vcopy(normal_dir(e) == 0 ? BIJ(b, r, k, dim) :
		    BIJ(b, k, r, dim), q + k * dim, dim);
}

/* q(s) -> q(1 - s): ends swap, slopes swap and change sign. */
static void
reverse_quartic(double *q, int dim)
{
	double t[LOFT_MAXDIM];

	vcopy(t, q, dim);
	vcopy(q, q + dim, dim);
	vcopy(q + dim, t, dim);
	vcopy(t, q + 2 * dim, dim);
	vscale(q + 2 * dim, -1, q + 3 * dim, dim);
	vscale(q + 3 * dim, -1, t, dim);
}

/* Samples along an edge, for distances and mismatches. */
#define EDGE_SAMPLES 16

/* The largest distance between quartics x(s) and y(s or 1 - s). */
static double
edge_gap(const double *x, const double *y, int dim, int rev)
{
	double gap = 0, px[LOFT_MAXDIM], py[LOFT_MAXDIM];

	for (int k = 0; k <= EDGE_SAMPLES; k++) {
		double s = (double)k / EDGE_SAMPLES;

		loft_quartic_eval(x, dim, s, px, NULL, NULL);
		loft_quartic_eval(y, dim, rev ? 1 - s : s, py, NULL, NULL);
		gap = fmax(gap, vdist(px, py, dim));
	}
	return gap;
}

/*
 * How well p and s meet along p's edge e and s's edge f: the largest
 * distance, and the largest difference of the derivatives across the
 * edge in the common parameter (each divided by its scale factor, both
 * pointing from p into s) relative to the largest of p's.
 */
static void
edge_mismatch(const struct loft_patch *p, int e, const struct loft_patch *s,
    int f, int rev, double *pos, double *slope)
{
	int dim = p->dim, np = normal_dir(e), ns = normal_dir(f);
	double big = 0, diff = 0;

	*pos = 0;
	for (int k = 0; k <= EDGE_SAMPLES; k++) {
		double a = (double)k / EDGE_SAMPLES, b = rev ? 1 - a : a;
		double xp = at_zero(e) ? 0 : 1, xs = at_zero(f) ? 0 : 1;
		double pp[LOFT_MAXDIM], ps[LOFT_MAXDIM], dp[2][LOFT_MAXDIM],
		    ds[2][LOFT_MAXDIM], gp[LOFT_MAXDIM], gs[LOFT_MAXDIM];

		loft_patch_eval(p->b, dim, np == 0 ? xp : a, np == 0 ? a : xp,
		    pp, dp[0], dp[1]);
		loft_patch_eval(s->b, dim, ns == 0 ? xs : b, ns == 0 ? b : xs,
		    ps, ds[0], ds[1]);
		*pos = fmax(*pos, vdist(pp, ps, dim));
		vscale(gp, (at_zero(e) ? -1 : 1) / p->scale[np], dp[np], dim);
		vscale(gs, (at_zero(f) ? 1 : -1) / s->scale[ns], ds[ns], dim);
		big = fmax(big, vnorm(gp, dim));
		diff = fmax(diff, vdist(gp, gs, dim));
	}
	*slope = big > 0 ? diff / big : diff;
}

/* The edges of s beside edge f, which meet it at its ends. */
static void
beside(int f, int *g)
{
	g[0] = normal_dir(f) == 0 ? LOFT_V0 : LOFT_U0;
	g[1] = normal_dir(f) == 0 ? LOFT_V1 : LOFT_U1;
}

/*
 * Section 6: the principal p does not change; the subsidiary s takes
 * p's edge as its own (reversed if they run opposite ways) and, across
 * it, p's derivative times r_s / r_p with the sign that makes both point
 * the same way in the common parameter: then f_x = f_n / r is the same
 * on both sides.  Only the two rows (or columns) of s's B along that
 * edge change, so s's opposite edge keeps its neighbours.
 */
int
loft_design_join(struct loft_design *d, size_t ip, size_t is,
    struct loft_join_info *info, struct loft_error *err)
{
	struct loft_patch *p, *s;
	double qp[5 * LOFT_MAXDIM], qs[5 * LOFT_MAXDIM], best = -1;
	int dim, g[2];

	memset(info, 0, sizeof *info);
	if (ip >= d->n || is >= d->n)
		return loft_fail(err, LOFT_EINPUT, -1, "patches %zu and %zu of "
		    "a design of %zu", ip, is, d->n);
	p = &d->p[ip];
	s = &d->p[is];
	dim = p->dim;
	if (s->dim != dim)
		return loft_fail(err, LOFT_EINPUT, -1, "patches of %d and %d "
		    "coordinates", dim, s->dim);
	if (ip == is)
		return loft_fail(err, LOFT_EGEOM, -1, "a patch cannot be joined "
		    "to itself");
	info->size = fmax(loft_patch_size(p->b, dim),
	    loft_patch_size(s->b, dim));
	for (int e = 0; e < 4; e++)
		for (int f = 0; f < 4; f++)
			for (int rev = 0; rev < 2; rev++) {
				double gap;

				edge_get(p->b, dim, e, 0, qp);
				edge_get(s->b, dim, f, 0, qs);
				gap = edge_gap(qp, qs, dim, rev);
				if (best < 0 || gap < best) {
					best = gap;
					info->edge_p = e;
					info->edge_s = f;
					info->reversed = rev;
				}
			}
	info->gap = best;
	if (!(best <= LOFT_JOIN_GAP * info->size))
		return loft_fail(err, LOFT_EGEOM, -1, "patches %ld and %ld share "
		    "no edge: the nearest, %s of %ld and %s of %ld, are %g "
		    "apart, more than %g of their size %g", p->id, s->id,
		    loft_edge_name[info->edge_p], p->id,
		    loft_edge_name[info->edge_s], s->id, best, LOFT_JOIN_GAP,
		    info->size);
	if (p->nlink[info->edge_p] > 0 || s->nlink[info->edge_s] > 0)
		return loft_fail(err, LOFT_EGEOM, -1, "edge %s of %ld already "
		    "has a neighbour", p->nlink[info->edge_p] > 0 ?
		    loft_edge_name[info->edge_p] : loft_edge_name[info->edge_s],
		    p->nlink[info->edge_p] > 0 ? p->id : s->id);
	beside(info->edge_s, g);
	for (int k = 0; k < 2; k++)
		if (s->nlink[g[k]] > 0)
			return loft_fail(err, LOFT_EGEOM, -1, "the subsidiary %ld "
			    "has a neighbour across %s, which meets the edge "
			    "to join: joining would break that edge (join "
			    "before splitting)", s->id, loft_edge_name[g[k]]);
	/* the edge itself */
	edge_get(p->b, dim, info->edge_p, 0, qp);
	if (info->reversed)
		reverse_quartic(qp, dim);
	edge_set(s->b, dim, info->edge_s, 0, qp);
	/* the derivative across it, in s's scale */
	edge_get(p->b, dim, info->edge_p, 1, qp);
	if (info->reversed)
		reverse_quartic(qp, dim);
	for (int k = 0; k < 5 * dim; k++)
		qp[k] *= (at_zero(info->edge_p) ? -1 : 1) *
		    (at_zero(info->edge_s) ? 1 : -1) *
		    s->scale[normal_dir(info->edge_s)] /
		    p->scale[normal_dir(info->edge_p)];
	edge_set(s->b, dim, info->edge_s, 1, qp);
	if (add_link(p, info->edge_p, s->id, info->reversed ? 1 : 0,
	    info->reversed ? 0 : 1) != 0 ||
	    add_link(s, info->edge_s, p->id, info->reversed ? 1 : 0,
	    info->reversed ? 0 : 1) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	edge_mismatch(p, info->edge_p, s, info->edge_s, info->reversed,
	    &info->pos_after, &info->slope_after);
	return 0;
}
