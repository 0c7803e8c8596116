/*
 * dxf.c: the DXF format (AutoCAD R2000, AC1015, as ezdxf and LibreCAD
 * read it): curves as LWPOLYLINE (plane) or POLYLINE (space) within the
 * tolerance, or exactly as SPLINE entities (tocad -s); knots as POINT
 * entities on layer 3, ASTM D6673's layer of curve points, and a curve's
 * corners (corners=) as POINTs on layer 2, its turn points.  Each curve
 * goes on a layer named by its size= and id= ("size_4.5"), or on layer
 * 1, D6673's boundary layer, when it has neither; the layer table lists
 * the layers in the order they first appear, so a graded set keeps its
 * order.  Units: $INSUNITS from tocad -u.  A curve's other attributes
 * (size=, offset=, name=, id=, ...) go with its entity as XDATA of the
 * application LOFT, one 1000 string "key=value" each, which fromcad
 * reads back onto its record.
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

struct dxf {
	unsigned long handle;   /* the last handle given out */
	char **layer;           /* in order of first use */
	size_t nlayer, layercap;
	size_t *hash;           /* open addressing: index + 1, or 0 */
	size_t hashcap;
	const char *cur;        /* the current record's layer */
	const struct loft_record *rec;  /* the current record */
};


/* A group's code line, right-justified in 3 columns as AutoCAD writes it
 * (by hand: snprintf here was most of the time of a large DXF). */
static void
code(struct loft_cad_doc *d, int c)
{
	char b[8];
	int n = 0, k;

	for (k = c; k > 0 || n == 0; k /= 10)
		b[6 - n++] = (char)('0' + k % 10);
	while (n < 3)
		b[6 - n++] = ' ';
	b[7] = '\n';
	loft_cad_put(d, b + 7 - n, (size_t)n + 1);
}

/* One group: its code line and its value line. */
static void
group(struct loft_cad_doc *d, int c, const char *val)
{
	code(d, c);
	loft_cad_puts(d, val);
	loft_cad_put(d, "\n", 1);
}

static void
group_num(struct loft_cad_doc *d, int c, double x)
{
	code(d, c);
	loft_cad_putnum(d, x);
	loft_cad_put(d, "\n", 1);
}

static void
group_int(struct loft_cad_doc *d, int code, long v)
{
	char buf[32];

	snprintf(buf, sizeof buf, "%ld", v);
	group(d, code, buf);
}

static void
group_handle(struct loft_cad_doc *d, unsigned long h)
{
	char buf[32];

	snprintf(buf, sizeof buf, "%lX", h);
	group(d, 5, buf);
}

/* Attributes the entity itself holds, or fromcad finds again: not in
 * the XDATA. */
static const char *const own_attr[] = { "closed", "corners", "layer",
	"block", "piece", NULL };

/* The current record's attributes as XDATA (the entity's last groups). */
static void
xdata(struct loft_cad_doc *d)
{
	const struct loft_record *r = ((struct dxf *)d->state)->rec;
	int first = 1;

	for (size_t i = 0; r != NULL && i < r->nattr; i++) {
		const char *k = r->attr[i].key;
		int own = 0;

		for (int j = 0; own_attr[j] != NULL; j++)
			own |= strcmp(k, own_attr[j]) == 0;
		if (own || r->attr[i].val == NULL)
			continue;
		if (first)
			group(d, 1001, "LOFT");
		first = 0;
		code(d, 1000);
		loft_cad_puts(d, k);
		loft_cad_put(d, "=", 1);
		loft_cad_puts(d, r->attr[i].val);
		loft_cad_put(d, "\n", 1);
	}
}

/* An entity's start: type, handle, layer. */
static void
entity(struct loft_cad_doc *d, const char *type, const char *subclass)
{
	struct dxf *x = d->state;

	group(d, 0, type);
	group_handle(d, ++x->handle);
	group(d, 100, "AcDbEntity");
	group(d, 8, x->cur);
	if (subclass != NULL)
		group(d, 100, subclass);
}

/* A point's groups 10, 20 (and 30), the bulk of a large DXF.  dim is 2
 * or 3 (cad.c's records); the bound on codes only makes that plain. */
static void
point(struct loft_cad_doc *d, const double *p, int dim)
{
	static const char *const codes[LOFT_MAXDIM] = { " 10\n", " 20\n",
	    " 30\n" };

	for (int k = 0; k < dim && k < LOFT_MAXDIM; k++) {
		loft_cad_put(d, codes[k], 4);
		loft_cad_putnum(d, p[k]);
		loft_cad_put(d, "\n", 1);
	}
}

static size_t
hash_name(const char *s)
{
	size_t h = 5381;

	while (*s)
		h = h * 33 + (unsigned char)*s++;
	return h;
}

/* The layer called name, added when new; NULL when out of memory. */
static const char *
layer(struct dxf *x, const char *name)
{
	size_t i, n = strlen(name);
	char *copy;

	if (2 * (x->nlayer + 1) > x->hashcap) {
		size_t cap = x->hashcap ? 2 * x->hashcap : 64;
		size_t *h = calloc(cap, sizeof *h);

		if (h == NULL)
			return NULL;
		for (size_t k = 0; k < x->nlayer; k++) {
			for (i = hash_name(x->layer[k]) % cap; h[i]; i = (i + 1) % cap)
				;
			h[i] = k + 1;
		}
		free(x->hash);
		x->hash = h;
		x->hashcap = cap;
	}
	for (i = hash_name(name) % x->hashcap; x->hash[i];
	    i = (i + 1) % x->hashcap)
		if (strcmp(x->layer[x->hash[i] - 1], name) == 0)
			return x->layer[x->hash[i] - 1];
	if (loft__grow((void **)&x->layer, &x->layercap, x->nlayer + 1,
	    sizeof *x->layer) != 0 || (copy = malloc(n + 1)) == NULL)
		return NULL;
	memcpy(copy, name, n + 1);
	x->layer[x->nlayer++] = copy;
	x->hash[i] = x->nlayer;
	return copy;
}

static int
dxf_begin(struct loft_cad_doc *d)
{
	struct dxf *x = calloc(1, sizeof *x);

	if (x == NULL)
		return LOFT_ENOMEM;
	x->handle = 0x20;       /* below: the tables' own handles */
	d->state = x;
	group(d, 0, "SECTION");
	group(d, 2, "ENTITIES");
	return 0;
}

static int
dxf_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	struct dxf *x = d->state;

	x->cur = layer(x, it->name[0] ? it->name : "1");
	x->rec = it->rec;
	return x->cur == NULL ? LOFT_ENOMEM : 0;
}

/* POINT entities on layer name. */
static int
points_on(struct loft_cad_doc *d, const char *name, const double *p,
    size_t n, int dim)
{
	struct dxf *x = d->state;

	if ((x->cur = layer(x, name)) == NULL)
		return LOFT_ENOMEM;
	for (size_t i = 0; i < n; i++) {
		entity(d, "POINT", "AcDbPoint");
		point(d, p + i * dim, 3 > dim ? dim : 3);
		if (dim == 2)
			group_num(d, 30, 0);
	}
	return 0;
}

/* Knots: D6673's curve points, layer 3. */
static int
dxf_points(struct loft_cad_doc *d, const double *p, size_t n, int dim)
{
	return points_on(d, "3", p, n, dim);
}

/* A curve's corners: D6673's turn points, layer 2, at the vertices. */
static int
dxf_turns(struct loft_cad_doc *d, const double *p, size_t n, int dim)
{
	return points_on(d, "2", p, n, dim);
}

static int
dxf_polyline(struct loft_cad_doc *d, const double *p, size_t n, int dim,
    int closed)
{
	/* a closed curve ends where it starts: that vertex once, flag 1 */
	if (closed && n > 2 && memcmp(p, p + (n - 1) * dim, dim *
	    sizeof *p) == 0)
		n--;
	else
		closed = 0;
	if (dim == 2) {
		entity(d, "LWPOLYLINE", "AcDbPolyline");
		group_int(d, 90, (long)n);
		group_int(d, 70, closed);
		for (size_t i = 0; i < n; i++)
			point(d, p + 2 * i, 2);
		xdata(d);
		return 0;
	}
	entity(d, "POLYLINE", "AcDb3dPolyline");
	group_int(d, 66, 1);
	group_num(d, 10, 0);
	group_num(d, 20, 0);
	group_num(d, 30, 0);
	group_int(d, 70, 8 | closed);
	xdata(d);
	for (size_t i = 0; i < n; i++) {
		entity(d, "VERTEX", "AcDbVertex");
		group(d, 100, "AcDb3dPolylineVertex");
		point(d, p + 3 * i, 3);
		group_int(d, 70, 32);
	}
	entity(d, "SEQEND", NULL);
	return 0;
}

/* A SPLINE: the Bezier pieces as one clamped B-spline. */
static int
dxf_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	size_t np = c->npieces * (size_t)c->deg + 1;

	entity(d, "SPLINE", "AcDbSpline");
	if (c->dim == 2) {
		group_num(d, 210, 0);
		group_num(d, 220, 0);
		group_num(d, 230, 1);
	}
	group_int(d, 70, c->dim == 2 ? 8 : 0);         /* planar */
	group_int(d, 71, c->deg);
	group_int(d, 72, (long)(np + (size_t)c->deg + 1));
	group_int(d, 73, (long)np);
	group_int(d, 74, 0);
	for (size_t i = 0; i <= c->npieces; i++)
		for (int r = 0; r < (i == 0 || i == c->npieces ? c->deg + 1 :
		    c->deg); r++)
			group_num(d, 40, (double)i);
	for (size_t k = 0; k < np; k++) {
		point(d, loft_cad_ctl(c, k), c->dim);
		if (c->dim == 2)
			group_num(d, 30, 0);
	}
	xdata(d);
	return 0;
}

/* The head, made last: it names every layer and the next handle. */
static int
dxf_end(struct loft_cad_doc *d)
{
	static const struct { const char *word; int code; } units[] = {
		{ "in", 1 }, { "mm", 4 }, { "cm", 5 }, { "m", 6 },
	};
	struct dxf *x = d->state;
	int unit = 0;

	group(d, 0, "ENDSEC");
	group(d, 0, "EOF");
	loft_cad_to_head(d, 1);
	for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
		if (strcmp(d->o.unit_name, units[i].word) == 0)
			unit = units[i].code;
	group(d, 999, "loft tocad");
	group(d, 0, "SECTION");
	group(d, 2, "HEADER");
	group(d, 9, "$ACADVER");
	group(d, 1, "AC1015");
	group(d, 9, "$HANDSEED");
	group_handle(d, x->handle + x->nlayer + 2);
	group(d, 9, "$INSUNITS");
	group_int(d, 70, unit);
	group(d, 9, "$MEASUREMENT");
	group_int(d, 70, unit != 1);
	group(d, 0, "ENDSEC");
	group(d, 0, "SECTION");
	group(d, 2, "TABLES");
	group(d, 0, "TABLE");
	group(d, 2, "LAYER");
	group_handle(d, 2);
	group(d, 100, "AcDbSymbolTable");
	group_int(d, 70, (long)x->nlayer);
	for (size_t i = 0; i < x->nlayer; i++) {
		group(d, 0, "LAYER");
		group_handle(d, ++x->handle);
		group(d, 100, "AcDbSymbolTableRecord");
		group(d, 100, "AcDbLayerTableRecord");
		group(d, 2, x->layer[i]);
		group_int(d, 70, 0);
		group_int(d, 62, 7);
		group(d, 6, "CONTINUOUS");
	}
	group(d, 0, "ENDTAB");
	group(d, 0, "TABLE");           /* LOFT, the XDATA's application */
	group(d, 2, "APPID");
	group_handle(d, 3);
	group(d, 100, "AcDbSymbolTable");
	group_int(d, 70, 1);
	group(d, 0, "APPID");
	group_handle(d, ++x->handle);
	group(d, 100, "AcDbSymbolTableRecord");
	group(d, 100, "AcDbRegAppTableRecord");
	group(d, 2, "LOFT");
	group_int(d, 70, 0);
	group(d, 0, "ENDTAB");
	group(d, 0, "ENDSEC");
	loft_cad_to_head(d, 0);
	return 0;
}

static void
dxf_free(struct loft_cad_doc *d)
{
	struct dxf *x = d->state;

	if (x == NULL)
		return;
	for (size_t i = 0; i < x->nlayer; i++)
		free(x->layer[i]);
	free(x->layer);
	free(x->hash);
	free(x);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_dxf = {
	.name = "dxf", .title = "DXF",
	.begin = dxf_begin, .end = dxf_end, .begin_record = dxf_begin_record,
	.curve = dxf_curve, .polyline = dxf_polyline, .points = dxf_points,
	.turns = dxf_turns, .free = dxf_free,
};
