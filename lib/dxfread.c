/*
 * dxfread.c: ASCII DXF (R12 to current) into loft records.  A DXF is
 * pairs of lines, a group code and its value; the ENTITIES section's
 * entities become records in the order of the file:
 *
 *   LINE, LWPOLYLINE, POLYLINE (VERTEX ... SEQEND), ARC, CIRCLE, POINT,
 *   SPLINE by fit points           knot (points) records;
 *   SPLINE by control points       exact pieces: `cubic` (degree 1 to 3)
 *                                  or `bezier` records (degree 4 up).
 *
 * Arcs (bulges, ARC, CIRCLE) are chords within c->tol.  $INSUNITS
 * scales the drawing to millimetres.  POINTs on layer 2 at the vertices
 * of knot records, or at the joints of cubic records, are ASTM D6673
 * turn points: they become corners= of those records instead of records
 * of their own.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

/* Turn points lie on polyline vertices, written with the same digits;
 * nearer than this fraction of the drawing's extent is "at" one (a
 * micrometre on a metre-wide marker: far below any two vertices'
 * spacing, far above the rounding of coordinates written with 6 or more
 * significant digits). */
#define TURN_TOL 1e-6

/* A SPLINE's weights within this of each other are equal: the spline
 * is polynomial (the weights of non-rational splines are written 1). */
#define WEIGHT_SAME 1e-12

/* A clamped rational SPLINE whose ends are this near (relative to its
 * first point's size) is closed: the ends of a NURBS circle or ellipse
 * are cos and sin of 0 and 2 pi, a rounding apart. */
#define ENDS_SAME 1e-12

#define MAX_DEGREE 63           /* loft.5's bezier records */

struct nums {
	double *v;
	size_t n, cap;
};

/* Attributes read back from a record's XDATA, at most (tocad writes a
 * few: size=, offset=, name=, id=). */
#define XATTR_MAX 16

enum { S_NONE, S_HEADER, S_TABLES, S_BLOCKS, S_ENTITIES, S_REPLAY, S_OTHER };

/* One entity: the groups loft uses, collected until the next 0 group. */
struct ent {
	char name[32];
	long line;
	const char *handle, *layer;
	size_t nhandle, nlayer;
	struct loft__pts p10, p11;      /* 10/20/30, 11/21/31 */
	unsigned m10, m11;              /* coordinates the last point has:
					 * bit k for group 10 + 10 k */
	struct nums bulge;              /* 42 per 10 point (polylines) */
	struct nums g40, g41;           /* knots (radius), weights */
	double t12[3], t13[3], ext[3], elev, a50, a51;
	double g42, g43, g44, g45;      /* INSERT: scales, spacings */
	int has12, has13, has50, has51, has42, has43;
	long f70, f71, f73, f90, f62;
	int has71, has73, has90, has62;
	const char *g2;                 /* a BLOCK's or INSERT's block */
	size_t n2;
	struct xattrs {                 /* XDATA of LOFT: "key=value" */
		const char *s[XATTR_MAX];
		size_t n[XATTR_MAX];
		int count;
	} xa;
	int in_loft;                    /* in XDATA of application LOFT */
	int bad;                        /* a message is in msg */
	char msg[200];
};

/* A POLYLINE while its VERTEX entities come in. */
struct poly {
	int open, bad, refused;
	long line, flags;
	char handle[24];
	const char *layer;
	size_t nlayer;
	double ext[3], elev;
	struct loft__pts v;
	struct nums bulge;
	struct xattrs xa;
};

struct knotrec {                /* a knot record written: for corners= */
	size_t hdr;             /* offset in w of its header line's end */
	size_t v0, nv;          /* its knots in verts */
	long grp;               /* the INSERT it came by (0: none) */
};

struct turn {                   /* a POINT on layer 2 */
	double x[3];
	size_t a, b;            /* its record's text in w */
	int used;
	long grp;               /* the INSERT it came by (0: none) */
};

struct name {                   /* a name in the document */
	const char *s;
	size_t n;
};

struct block {                  /* a BLOCK of the BLOCKS section */
	struct name name;
	double base[3];
	const char *at;         /* its first entity's 0 group */
	long line;              /* the line before at */
};

/* Blocks inserted deeper than this are not read: real drawings nest a
 * few levels, and a block that inserts itself stops here. */
#define INSERT_DEPTH 16

/* Entities drawn by INSERTs, at most, per document: arrays of nested
 * blocks multiply, and a few hostile groups would otherwise ask for
 * 10^20 records.  Four million is far above any real drawing. */
#define INSERT_BUDGET 4000000L

struct dxf {
	const char *p, *end;
	long line;              /* lines read */
	struct loft_cadin *c;
	double scale;           /* drawing units to millimetres */
	struct ent e;
	struct poly pl;
	int sec, want_name, in_ent, eof;
	const char *var;        /* the HEADER variable being read */
	size_t nvar;
	struct ent lay;         /* TABLES: the entry being read */
	int in_lay;
	struct name *off;       /* layers off or frozen, sorted when read */
	size_t noff, offcap;
	int offsorted;
	struct block *blk;      /* the BLOCKS section's blocks */
	size_t nblk, blkcap;
	int blksorted, in_block;
	int nins;               /* INSERTs being drawn, nested */
	double xf[12], stretch; /* their transform (see struct frame) */
	struct name ins_layer, ins_block;       /* the outermost's */
	long grp, budget;
	int said_deep;          /* the depth was said */
	struct pair *hp;        /* a HATCH's groups (-F), in order */
	size_t nhp, hpcap;
	struct loft__passed passed, hidden;
	const struct xattrs *xa;        /* the entity's, for put_where */
	int turns;              /* the document may hold turn points */
	struct loft__pts verts, knots, work;
	struct knotrec *kr;
	size_t nkr, krcap;
	struct turn *tp;
	size_t ntp, tpcap;
	struct nums seg;        /* spline pieces */
	size_t *straight, nstraight;    /* a polyline's straight spans */
	struct loft__echo *echo;        /* coordinates' texts (may be NULL) */
	int oom;
};

static int
nums_add(struct nums *s, double x)
{
	if (s->n + 1 > s->cap && loft__grow((void **)&s->v, &s->cap, s->n + 1,
	    sizeof *s->v) != 0)
		return -1;
	s->v[s->n++] = x;
	return 0;
}

/* The next line: its text without the line end and surrounding blanks. */
static int
next_line(struct dxf *d, const char **s, size_t *n)
{
	const char *a = d->p, *e;

	if (a >= d->end)
		return 0;
	e = memchr(a, '\n', (size_t)(d->end - a));
	d->p = e ? e + 1 : d->end;
	if (e == NULL)
		e = d->end;
	d->line++;
	while (a < e && (*a == ' ' || *a == '\t' || *a == '\r'))
		a++;
	while (e > a && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r'))
		e--;
	*s = a;
	*n = (size_t)(e - a);
	return 1;
}

struct pair {
	int code;
	const char *v;
	size_t n;
	long line;              /* of the code */
	const char *at;         /* where the code's line starts */
	long before;            /* the line before it */
};

/* The next pair: 1, 0 at the end, -1 for a code that is not a whole
 * number, -2 for a code with no value after it (a truncated file). */
static int
next_pair(struct dxf *d, struct pair *pr)
{
	const char *s;
	size_t n, i = 0;
	long code = 0;
	int neg = 0;

	pr->at = d->p;
	pr->before = d->line;
	if (!next_line(d, &s, &n))
		return 0;
	pr->line = d->line;
	pr->v = s;
	pr->n = n;
	if (n > 0 && s[0] == '-')
		neg = i = 1;
	if (i == n || n - i > 6)
		return -1;
	for (; i < n; i++) {
		if (s[i] < '0' || s[i] > '9')
			return -1;
		code = 10 * code + (s[i] - '0');
	}
	pr->code = (int)(neg ? -code : code);
	if (!next_line(d, &pr->v, &pr->n))
		return -2;
	return 1;
}

/* The entity's name for messages: "LINE (handle 2F)". */
static const char *
ent_name(const struct ent *e, char *buf, size_t size)
{
	char h[17];

	if (e->nhandle > 0)
		snprintf(buf, size, "%s (handle %s)", e->name,
		    loft__cadin_quote(h, sizeof h, e->handle, e->nhandle));
	else
		snprintf(buf, size, "%s", e->name);
	return buf;
}

static void
ent_bad(struct ent *e, const char *what, const struct pair *pr)
{
	if (e->bad)
		return;
	char q[31];

	e->bad = 1;
	snprintf(e->msg, sizeof e->msg, "group %d '%s' %s (line %ld)",
	    pr->code, loft__cadin_quote(q, sizeof q, pr->v, pr->n), what,
	    pr->line);
}

static int
pair_num(struct ent *e, const struct pair *pr, double *x)
{
	if (loft_parse_num(pr->v, pr->n, x, NULL) != 0) {
		ent_bad(e, "is not a finite number", pr);
		return -1;
	}
	return 0;
}

/* A coordinate: as pair_num, its text noted for the output. */
static int
coord_num(struct dxf *d, struct ent *e, const struct pair *pr, double *x)
{
	if (loft__echo_parse(d->echo, pr->v, pr->n, x) != 0) {
		ent_bad(e, "is not a finite number", pr);
		return -1;
	}
	return 0;
}

static int
pair_int(struct ent *e, const struct pair *pr, long *v)
{
	double x;

	if (pair_num(e, pr, &x) != 0)
		return -1;
	if (x != floor(x) || fabs(x) > 1e9) {
		ent_bad(e, "is not a whole number", pr);
		return -1;
	}
	*v = (long)x;
	return 0;
}

static void
ent_start(struct dxf *d, struct ent *e, const struct pair *pr)
{
	d->nhp = 0;
	loft__cadin_quote(e->name, sizeof e->name, pr->v, pr->n);
	e->line = pr->line;
	e->handle = e->layer = NULL;
	e->nhandle = e->nlayer = 0;
	e->p10.n = e->p11.n = e->bulge.n = e->g40.n = e->g41.n = 0;
	e->m10 = e->m11 = 0;
	e->has12 = e->has13 = e->has50 = e->has51 = e->has42 = e->has43 = 0;
	e->has62 = 0;
	e->g2 = NULL;
	e->n2 = 0;
	e->xa.count = 0;
	e->in_loft = 0;
	e->ext[0] = e->ext[1] = 0;
	e->ext[2] = 1;
	e->elev = e->a50 = e->a51 = 0;
	e->f70 = e->f71 = e->f73 = e->f90 = e->f62 = 0;
	e->g42 = e->g43 = e->g44 = e->g45 = 0;
	e->has71 = e->has73 = e->has90 = 0;
	e->bad = 0;
}

/*
 * Coordinate k (0 for group 10 or 11, 1 for 20 or 21, 2 for 30 or 31)
 * of a point: of the last point in s when it lacks that coordinate
 * still, else of a new point.  So a vertex whose 20 comes before its
 * 10 is one vertex, not a y given to the vertex before; a point never
 * given its x is refused at the entity's end.
 */
static void
coord(struct dxf *d, struct ent *e, struct loft__pts *s, unsigned *mask,
    int k, const struct pair *pr)
{
	double x[3] = { 0, 0, 0 };
	int poly = strcmp(e->name, "LWPOLYLINE") == 0 ||
	    strcmp(e->name, "VERTEX") == 0;

	if (coord_num(d, e, pr, &x[k]) != 0)
		return;
	if (s->n > 0 && !(*mask & 1u << k)) {
		s->p[3 * (s->n - 1) + k] = x[k];
		*mask |= 1u << k;
		return;
	}
	if (s->n > 0 && !(*mask & 1)) {
		ent_bad(e, "starts a point before the one before has its x "
		    "(group 10 or 11)", pr);
		return;
	}
	if (loft__pts_add(s, x) != 0 || (s == &e->p10 && poly &&
	    nums_add(&e->bulge, 0) != 0))
		d->oom = 1;
	*mask = 1u << k;
}

/* A 1000 string of LOFT's XDATA: kept when it is "key=value" as
 * loft.5 writes attributes (tocad's DXF; see dxf.c). */
static void
xattr_add(struct ent *e, const struct pair *pr)
{
	size_t k = 0;

	if (!e->in_loft || e->xa.count == XATTR_MAX || pr->n < 3)
		return;
	/* a name (loft.5): a letter, then letters, digits, '-' or '_' */
	while (k < pr->n && ((pr->v[k] | 0x20) >= 'a' && (pr->v[k] | 0x20) <=
	    'z' ? 1 : k > 0 && ((pr->v[k] >= '0' && pr->v[k] <= '9') ||
	    pr->v[k] == '-' || pr->v[k] == '_')))
		k++;
	if (k == 0 || k + 1 >= pr->n || pr->v[k] != '=')
		return;
	for (size_t i = k + 1; i < pr->n; i++)
		if (pr->v[i] < 33 || pr->v[i] > 126 || pr->v[i] == '#')
			return;
	e->xa.s[e->xa.count] = pr->v;
	e->xa.n[e->xa.count++] = pr->n;
}

static void
ent_group(struct dxf *d, struct ent *e, const struct pair *pr)
{
	if (d->c->fills && strcmp(e->name, "HATCH") == 0) {
		if (pr->code == 5 || pr->code == 8)
			;               /* read below too */
		else if (loft__grow((void **)&d->hp, &d->hpcap, d->nhp + 1,
		    sizeof *d->hp) != 0)
			d->oom = 1;
		else {
			d->hp[d->nhp++] = *pr;
			return;
		}
	}
	double x[3] = { 0, 0, 0 };
	int poly = strcmp(e->name, "LWPOLYLINE") == 0 ||
	    strcmp(e->name, "VERTEX") == 0;

	switch (pr->code) {
	case 5: e->handle = pr->v; e->nhandle = pr->n; break;
	case 2: e->g2 = pr->v; e->n2 = pr->n; break;
	case 1001: e->in_loft = loft__word_is(pr->v, pr->n, "LOFT"); break;
	case 1000: xattr_add(e, pr); break;
	case 8: e->layer = pr->v; e->nlayer = pr->n; break;
	case 43: e->has43 = pair_num(e, pr, &e->g43) == 0; break;
	case 44: pair_num(e, pr, &e->g44); break;
	case 45: pair_num(e, pr, &e->g45); break;
	case 62: e->has62 = pair_int(e, pr, &e->f62) == 0; break;
	case 10: case 20: case 30:
		coord(d, e, &e->p10, &e->m10, pr->code / 10 - 1, pr);
		break;
	case 11: case 21: case 31:
		coord(d, e, &e->p11, &e->m11, pr->code / 10 - 1, pr);
		break;
	case 12: e->has12 = pair_num(e, pr, &e->t12[0]) == 0; break;
	case 22: pair_num(e, pr, &e->t12[1]); break;
	case 32: pair_num(e, pr, &e->t12[2]); break;
	case 13: e->has13 = pair_num(e, pr, &e->t13[0]) == 0; break;
	case 23: pair_num(e, pr, &e->t13[1]); break;
	case 33: pair_num(e, pr, &e->t13[2]); break;
	case 38: pair_num(e, pr, &e->elev); break;
	case 40:
	case 41:
		if (pair_num(e, pr, &x[0]) == 0 &&
		    nums_add(pr->code == 40 ? &e->g40 : &e->g41, x[0]) != 0)
			d->oom = 1;
		break;
	case 42:
		if (!poly) {    /* a SPLINE's 42 is a tolerance */
			e->has42 = pair_num(e, pr, &e->g42) == 0;
			break;
		}
		if (pair_num(e, pr, &x[0]) != 0)
			break;
		if (e->bulge.n == 0)
			ent_bad(e, "comes before the vertex it bends", pr);
		else
			e->bulge.v[e->bulge.n - 1] = x[0];
		break;
	case 50: e->has50 = pair_num(e, pr, &e->a50) == 0; break;
	case 51: e->has51 = pair_num(e, pr, &e->a51) == 0; break;
	case 70: pair_int(e, pr, &e->f70); break;
	case 71: e->has71 = pair_int(e, pr, &e->f71) == 0; break;
	case 73: e->has73 = pair_int(e, pr, &e->f73) == 0; break;
	case 90: e->has90 = pair_int(e, pr, &e->f90) == 0; break;
	case 210: pair_num(e, pr, &e->ext[0]); break;
	case 220: pair_num(e, pr, &e->ext[1]); break;
	case 230: pair_num(e, pr, &e->ext[2]); break;
	}
}

/*
 * The arbitrary axis algorithm of the DXF reference: the x and y axes
 * of the object coordinate system whose z axis is the extrusion n.
 * Returns 0, or -1 when n is zero.
 */
static int
ocs_axes(const double *ext, double *ax, double *ay, double *az)
{
	double len;

	int e;

	/* scaled by a power of two first (exactly), so that a length of
	 * 1e-300 or 1e300 is a direction, not zero or infinity */
	len = vmaxabs(ext, 3);
	if (!(len > 0) || !isfinite(len))
		return -1;
	e = ilogb(len);
	for (int k = 0; k < 3; k++)
		az[k] = ldexp(ext[k], -e);
	len = vnorm(az, 3);
	for (int k = 0; k < 3; k++)
		az[k] /= len;
	if (fabs(az[0]) < 1.0 / 64 && fabs(az[1]) < 1.0 / 64) {
		ax[0] = az[2];          /* (0, 1, 0) x n */
		ax[1] = 0;
		ax[2] = -az[0];
	} else {
		ax[0] = -az[1];         /* (0, 0, 1) x n */
		ax[1] = az[0];
		ax[2] = 0;
	}
	len = vnorm(ax, 3);
	for (int k = 0; k < 3; k++)
		ax[k] /= len;
	ay[0] = az[1] * ax[2] - az[2] * ax[1];
	ay[1] = az[2] * ax[0] - az[0] * ax[2];
	ay[2] = az[0] * ax[1] - az[1] * ax[0];
	return 0;
}

/*
 * An object's frame: from the OCS of extrusion ext to the WCS, then
 * through the transform of the blocks it is inserted by (xf: a 3 by 3
 * matrix by rows, then a translation; NULL outside blocks), then to
 * millimetres.  stretch: the most xf lengthens a length (1 outside),
 * for the chords of arcs.
 */
struct frame {
	int plain;              /* extrusion (0, 0, 1): OCS is WCS */
	double ax[3], ay[3], az[3], scale, stretch;
	const double *xf;
};

static int
frame_of(const struct dxf *d, const double *ext, struct frame *f)
{
	f->scale = d->scale;
	f->xf = d->nins > 0 ? d->xf : NULL;
	f->stretch = d->nins > 0 ? d->stretch : 1;
	f->plain = ext[0] == 0 && ext[1] == 0 && ext[2] > 0;
	return f->plain ? 0 : ocs_axes(ext, f->ax, f->ay, f->az);
}

/* The frame of WCS coordinates (extrusion (0, 0, 1)). */
static void
wcs_frame(const struct dxf *d, struct frame *f)
{
	static const double up[3] = { 0, 0, 1 };

	frame_of(d, up, f);
}

/* Point (lin 0) or direction (lin 1) o through the block transform m. */
static void
xf_apply(const double *m, const double *o, double *w, int lin)
{
	double r[3];            /* o and w may be one */

	for (int k = 0; k < 3; k++)
		r[k] = m[3 * k] * o[0] + m[3 * k + 1] * o[1] + m[3 * k + 2] *
		    o[2] + (lin ? 0 : m[9 + k]);
	vcopy(w, r, 3);
}

static void
to_world(const struct frame *f, const double *o, double *w)
{
	double p[3];

	for (int k = 0; k < 3; k++)
		p[k] = f->plain ? o[k] : o[0] * f->ax[k] + o[1] * f->ay[k] +
		    o[2] * f->az[k];
	if (f->xf != NULL)
		xf_apply(f->xf, p, p, 0);
	for (int k = 0; k < 3; k++)
		w[k] = p[k] * f->scale;
}

/* Append point o (in the OCS) to d->knots; -1 when out of memory. */
static int
knot(struct dxf *d, const struct frame *f, const double *o)
{
	double w[3];

	to_world(f, o, w);
	if (loft__pts_add(&d->knots, w) != 0) {
		d->oom = 1;
		return -1;
	}
	return 0;
}

/* The points strictly inside the arc about centre c (OCS) of radius r
 * from angle a0 through sweep: n - 1 points for n chords. */
static int
arc_inside(struct dxf *d, const struct frame *f, const double *c, double r,
    double a0, double sweep, long n)
{
	for (long k = 1; k < n; k++) {
		double a = a0 + sweep * (double)k / (double)n;
		double o[3] = { c[0] + r * cos(a), c[1] + r * sin(a), c[2] };

		if (knot(d, f, o) != 0)
			return -1;
	}
	return 0;
}

/*
 * The straight spans of a polyline (issue 23): of its edges, the lines
 * that a bulge's arc meets with the same tangent, as loft_straight_spans
 * finds them on the edges as segments (a line's tangents its chord, an
 * arc's the chord turned by a quarter of its included angle 4 atan(b)
 * either way, in the OCS: a tangent's direction survives the affine maps
 * to the world), into d->straight as the knot numbers of their first
 * vertices, first[i] for vertex i.  Nothing when out of memory.
 */
static void
polyline_straight(struct dxf *d, const double *v, const double *b, size_t n,
    int closed, const size_t *first)
{
	size_t ne = closed ? n : n - 1, k;
	double *seg;

	d->nstraight = 0;
	if (b == NULL || n < 2 || (seg = malloc(ne * 8 * sizeof *seg)) ==
	    NULL)
		return;
	for (size_t i = 0; i < ne; i++) {
		const double *p = v + 3 * i, *q = v + 3 * ((i + 1) % n);
		double *r = seg + 8 * i, c[2] = { q[0] - p[0], q[1] - p[1] };
		double h = fabs(b[i]) >= DBL_EPSILON ? 2 * atan(b[i]) : 0;

		r[0] = p[0], r[1] = p[1], r[2] = q[0], r[3] = q[1];
		r[4] = c[0] * cos(h) + c[1] * sin(h);
		r[5] = c[1] * cos(h) - c[0] * sin(h);
		r[6] = c[0] * cos(h) - c[1] * sin(h);
		r[7] = c[1] * cos(h) + c[0] * sin(h);
	}
	free(d->straight);
	if ((d->straight = malloc(ne * sizeof *d->straight)) != NULL) {
		k = loft_straight_spans(seg, ne, 2, closed, d->straight);
		for (size_t j = 0; j < k; j++)
			d->straight[j] = first[d->straight[j]];
		d->nstraight = k;
	}
	free(seg);
}

/*
 * The vertices v[0..n) with bulges b (OCS, z from elev) as knots: each
 * bulge b != 0 bends the edge to the next vertex into an arc of
 * included angle 4 atan(b), counter-clockwise for b > 0, sampled by
 * chords.  Returns 0, or -1 with msg filled.
 */
static int
polyline_knots(struct dxf *d, const struct frame *f, const double *v,
    const double *b, size_t n, int closed, int zfromv, double elev,
    char *msg, size_t msize)
{
	size_t *first;

	d->knots.n = 0;
	if (closed && n > 1 && v[0] == v[3 * (n - 1)] &&
	    v[1] == v[3 * (n - 1) + 1] && v[2] == v[3 * (n - 1) + 2])
		n--;            /* the first vertex repeated at the end */
	if ((first = malloc(n * sizeof *first)) == NULL) {
		d->oom = 1;
		return -1;
	}
	for (size_t i = 0; i < n; i++) {
		const double *p = v + 3 * i, *q = v + 3 * ((i + 1) % n);
		double o[3] = { p[0], p[1], zfromv ? p[2] : elev };
		double dx = q[0] - p[0], dy = q[1] - p[1], bu = b ? b[i] : 0;

		first[i] = d->knots.n;
		if (knot(d, f, o) != 0)
			return free(first), -1;
		/* a bulge below DBL_EPSILON stands the arc's middle less
		 * than the chord's rounding off it: a straight segment */
		if (fabs(bu) >= DBL_EPSILON && (i + 1 < n || closed) &&
		    (dx != 0 || dy != 0)) {
			/* (1 - b^2) / 4b, with no b^2 to overflow */
			double h = (1 / bu - bu) / 4;
			double cc[3] = { (p[0] + q[0]) / 2 - h * dy,
			    (p[1] + q[1]) / 2 + h * dx, o[2] };
			double r = hypot(p[0] - cc[0], p[1] - cc[1]);
			double sweep = 4 * atan(bu);
			long m = loft__arc_chords(d->c, r * f->scale *
			    f->stretch, sweep);

			if (!isfinite(r) || !isfinite(h)) {
				snprintf(msg, msize, "vertex %zu: bulge %g "
				    "makes no arc", i + 1, bu);
				return free(first), -1;
			}
			if (m < 0) {
				snprintf(msg, msize, "vertex %zu: its arc needs "
				    "more than %d chords for the tolerance",
				    i + 1, LOFT_CADIN_ARC_MAX);
				return free(first), -1;
			}
			if (arc_inside(d, f, cc, r, atan2(p[1] - cc[1],
			    p[0] - cc[0]), sweep, m) != 0)
				return free(first), -1;
		}
	}
	polyline_straight(d, v, b, n, closed, first);
	free(first);
	return 0;
}

/* Format the vector t (dim numbers) as "x,y[,z]" into buf. */
static void
vector_text(char *buf, const double *t, int dim)
{
	size_t k = 0;

	for (int q = 0; q < dim; q++) {
		if (q > 0)
			buf[k++] = ',';
		k += (size_t)loft_format_num(buf + k, t[q], 0);
	}
	buf[k] = '\0';
}

/*
 * Keep the vertices v of the record just written, whose header line
 * ends at hdr in the output, for the turn points: a knot record's knots,
 * a cubic record's joints (loft.5's corners= counts either from 1).
 */
static void
keep_vertices(struct dxf *d, size_t hdr, const struct loft__pts *v)
{
	if (!d->turns)
		return;
	if (loft__grow((void **)&d->kr, &d->krcap, d->nkr + 1, sizeof *d->kr)
	    != 0 || loft__grow((void **)&d->verts.p, &d->verts.cap,
	    3 * (d->verts.n + v->n), sizeof *d->verts.p) != 0) {
		d->oom = 1;
		return;
	}
	d->kr[d->nkr].hdr = hdr;
	d->kr[d->nkr].v0 = d->verts.n;
	d->kr[d->nkr].nv = v->n;
	d->kr[d->nkr].grp = d->grp;
	d->nkr++;
	memcpy(d->verts.p + 3 * d->verts.n, v->p, 3 * v->n * sizeof *v->p);
	d->verts.n += v->n;
}

#define XATTR_KEY 32     /* a key longer than this is no loft key */

/* Whether fromcad writes key itself, from the entity (not from XDATA). */
static int
attr_own(const char *key)
{
	static const char *const own[] = { "layer", "block", "closed",
	    "corners", "piece", "start", "end", "straight", NULL };

	for (int i = 0; own[i] != NULL; i++)
		if (strcmp(key, own[i]) == 0)
			return 1;
	return 0;
}

/* A record's layer= (the INSERT's for an entity of layer 0 in a
 * block, as CAD draws it) and block= (the outermost INSERT's). */
static void
put_where(const struct dxf *d, struct loft_writer *w, const char *layer,
    size_t nlayer)
{
	if (d->nins > 0 && nlayer == 1 && layer[0] == '0') {
		layer = d->ins_layer.s;
		nlayer = d->ins_layer.n;
	}
	loft__cadin_put_name(w, "layer", layer, nlayer);
	if (d->nins > 0)
		loft__cadin_put_name(w, "block", d->ins_block.s,
		    d->ins_block.n);
	for (int i = 0; d->xa != NULL && i < d->xa->count; i++) {
		const char *s = d->xa->s[i], *eq = memchr(s, '=', d->xa->n[i]);
		char key[XATTR_KEY];

		if (eq == NULL || (size_t)(eq - s) >= sizeof key)
			continue;
		memcpy(key, s, (size_t)(eq - s));
		key[eq - s] = '\0';
		if (!attr_own(key))
			loft__cadin_put_name(w, key, eq + 1, d->xa->n[i] -
			    (size_t)(eq - s) - 1);
	}
}

/*
 * Write d->knots as a knot record of the entity with layer (and, for a
 * SPLINE, its end tangents) and keep its knots for the turn points.
 */
static void
put_knots(struct dxf *d, const char *layer, size_t nlayer, long line,
    int closed, const double *start, const double *end)
{
	struct loft_writer *w = d->c->w;
	size_t mark = w->len, hdr, n = d->knots.n;
	int dim = loft__pts_dim(d->knots.p, n);
	char buf[3 * LOFT_NUMBUF + 4];

	loft_put_type(w, "points");
	loft_put_attr(w, "closed", closed ? "1" : "0");
	put_where(d, w, layer, nlayer);
	loft__cadin_put_list(w, "straight", d->straight, d->nstraight);
	d->nstraight = 0;       /* a polyline's, this once */
	if (start != NULL) {
		vector_text(buf, start, dim);
		loft_put_attr(w, "start", buf);
	}
	if (end != NULL) {
		vector_text(buf, end, dim);
		loft_put_attr(w, "end", buf);
	}
	hdr = w->len;
	loft_end_line(w);
	loft__pts_put(w, d->echo, d->knots.p, n, dim);
	loft_end_record(w);
	if (loft__cadin_done(d->c, mark, line) == 0)
		keep_vertices(d, hdr, &d->knots);
}

/* 0, or -1 after the message "NAME: what" for entity e. */
static int
refuse(struct dxf *d, const struct ent *e, const char *what)
{
	char nm[64];

	loft__cadin_say(d->c, e->line, "%s: %s", ent_name(e, nm, sizeof nm), what);
	return -1;
}

static void
do_line(struct dxf *d, struct ent *e)
{
	struct frame f;

	if (e->p10.n != 1 || e->p11.n != 1) {
		refuse(d, e, "a LINE needs one start (10/20/30) and one end "
		    "(11/21/31)");
		return;
	}
	wcs_frame(d, &f);
	d->knots.n = 0;
	if (knot(d, &f, e->p10.p) != 0 || knot(d, &f, e->p11.p) != 0)
		return;
	put_knots(d, e->layer, e->nlayer, e->line, 0, NULL, NULL);
}

static void
do_point(struct dxf *d, struct ent *e)
{
	struct frame f;
	struct loft_writer *w = d->c->w;
	size_t mark = w->len;
	double p[3];

	if (e->p10.n != 1) {
		refuse(d, e, "a POINT needs one point (10/20/30)");
		return;
	}
	wcs_frame(d, &f);
	to_world(&f, e->p10.p, p);
	loft_put_type(w, "points");
	put_where(d, w, e->layer, e->nlayer);
	loft_end_line(w);
	loft__echo_row(d->echo, w, p, loft__pts_dim(p, 1));
	loft_end_record(w);
	if (loft__cadin_done(d->c, mark, e->line) != 0 || e->nlayer != 1 ||
	    e->layer[0] != '2')
		return;
	if (loft__grow((void **)&d->tp, &d->tpcap, d->ntp + 1, sizeof *d->tp)
	    != 0) {
		d->oom = 1;
		return;
	}
	memcpy(d->tp[d->ntp].x, p, sizeof p);
	d->tp[d->ntp].a = mark;
	d->tp[d->ntp].b = w->len;
	d->tp[d->ntp].used = 0;
	d->tp[d->ntp].grp = d->grp;
	d->ntp++;
}

static void
do_lwpolyline(struct dxf *d, struct ent *e)
{
	struct frame f;
	char msg[160];

	if (e->p10.n == 0) {
		refuse(d, e, "an LWPOLYLINE needs vertices");
		return;
	}
	if (e->has90 && e->f90 != (long)e->p10.n) {
		snprintf(msg, sizeof msg, "group 90 says %ld vertices; it has "
		    "%zu", e->f90, e->p10.n);
		refuse(d, e, msg);
		return;
	}
	if (frame_of(d, e->ext, &f) != 0) {
		refuse(d, e, "its extrusion direction (210/220/230) is zero");
		return;
	}
	if (polyline_knots(d, &f, e->p10.p, e->bulge.v, e->p10.n, e->f70 & 1,
	    0, e->elev, msg, sizeof msg) != 0) {
		if (!d->oom)
			refuse(d, e, msg);
		return;
	}
	put_knots(d, e->layer, e->nlayer, e->line, e->f70 & 1, NULL, NULL);
}

/* ARC and CIRCLE: chords of the circle of centre 10/20/30, radius 40,
 * from angle 50 counter-clockwise to 51 (degrees). */
static void
do_arc(struct dxf *d, struct ent *e, int circle)
{
	struct frame f;
	double r, a0, a1, sweep;
	long n;

	if (e->p10.n != 1 || e->g40.n != 1 || (!circle && (!e->has50 ||
	    !e->has51))) {
		refuse(d, e, circle ? "a CIRCLE needs a centre (10/20/30) and "
		    "a radius (40)" : "an ARC needs a centre (10/20/30), a "
		    "radius (40) and its angles (50, 51)");
		return;
	}
	r = e->g40.v[0];
	if (r == 0 && !d->c->strict) {  /* draws nothing: no error */
		loft__passed_add(&d->passed, circle ? "CIRCLE of radius 0" :
		    "ARC of radius 0", circle ? 18 : 15);
		return;
	}
	if (!(r > 0)) {
		refuse(d, e, "its radius is not above 0");
		return;
	}
	if (frame_of(d, e->ext, &f) != 0) {
		refuse(d, e, "its extrusion direction (210/220/230) is zero");
		return;
	}
	a0 = circle ? 0 : fmod(e->a50, 360);
	a1 = circle ? 360 : fmod(e->a51, 360);
	if (a1 <= a0)
		a1 += 360;
	sweep = (a1 - a0) * M_PI / 180;
	a0 *= M_PI / 180;
	if ((n = loft__arc_chords(d->c, r * f.scale * f.stretch, sweep)) < 0) {
		refuse(d, e, "it needs more chords than the tolerance allows");
		return;
	}
	if (circle && n < 3)
		n = 3;
	d->knots.n = 0;
	{
		const double *c = e->p10.p;
		double o[3] = { c[0] + r * cos(a0), c[1] + r * sin(a0), c[2] };

		if (knot(d, &f, o) != 0 || arc_inside(d, &f, c, r, a0, sweep,
		    n) != 0)
			return;
		if (!circle) {
			o[0] = c[0] + r * cos(a0 + sweep);
			o[1] = c[1] + r * sin(a0 + sweep);
			if (knot(d, &f, o) != 0)
				return;
		}
	}
	put_knots(d, e->layer, e->nlayer, e->line, circle, NULL, NULL);
}

static void
do_arc_only(struct dxf *d, struct ent *e)
{
	do_arc(d, e, 0);
}

static void
do_circle(struct dxf *d, struct ent *e)
{
	do_arc(d, e, 1);
}

/*
 * Whether the curve of a SPLINE ends exactly where it starts: the first
 * point of its first span's Bezier form and the last of its last.  A
 * closed curve written as a clamped spline (as tocad writes one) carries
 * no closed flag (group 70 bit 1 means a periodic spline to most
 * readers), so this is how it is known.  The spline's knots are checked.
 */
static int
ends_meet(const double *t, const double *ctl, int p, size_t n, int dim)
{
	double b0[(MAX_DEGREE + 1) * 3], b1[(MAX_DEGREE + 1) * 3];
	size_t first = n, last = n;

	for (size_t i = (size_t)p; i < n; i++)
		if (t[i] < t[i + 1]) {
			if (first == n)
				first = i;
			last = i;
		}
	if (first == n)
		return 0;
	loft_bspline_span(t, ctl, p, first, dim, b0);
	loft_bspline_span(t, ctl, p, last, dim, b1);
	for (int q = 0; q < dim; q++)
		if (b0[q] != b1[p * dim + q])
			return 0;
	return 1;
}

/* Append the point b (dim numbers) to d->knots when the document may
 * hold turn points; -1 when out of memory. */
static int
joint_add(struct dxf *d, const double *b, int dim)
{
	double x[3] = { b[0], b[1], dim == 3 ? b[2] : 0 };

	if (!d->turns)
		return 0;
	if (loft__pts_add(&d->knots, x) != 0) {
		d->oom = 1;
		return -1;
	}
	return 0;
}

/* Whether a SPLINE's weights differ: a rational spline (those of a
 * polynomial one are written 1, or all alike). */
static int
rational(const struct ent *e)
{
	for (size_t k = 1; k < e->g41.n; k++)
		if (fabs(e->g41.v[k] - e->g41.v[0]) > WEIGHT_SAME *
		    fabs(e->g41.v[0]))
			return 1;
	return 0;
}

/* Whether a SPLINE by control points is whole: degree, counts, knots
 * and weights; 0, or -1 after saying what is wrong. */
static int
spline_check(struct dxf *d, struct ent *e)
{
	size_t n = e->p10.n;
	const double *t = e->g40.v;
	int p = (int)e->f71;
	char msg[160];

	if (!e->has71 || p < 1 || p > MAX_DEGREE) {
		snprintf(msg, sizeof msg, "degree (group 71) %ld: loft reads "
		    "degrees 1 to %d", e->f71, MAX_DEGREE);
		refuse(d, e, msg);
		return -1;
	}
	if (e->has73 && e->f73 != (long)n) {
		snprintf(msg, sizeof msg, "group 73 says %ld control points; "
		    "it has %zu", e->f73, n);
		refuse(d, e, msg);
		return -1;
	}
	if (n < (size_t)p + 1 || e->g40.n != n + (size_t)p + 1) {
		snprintf(msg, sizeof msg, "%zu control points of degree %d "
		    "need %zu knots (group 40); it has %zu", n, p,
		    n + (size_t)p + 1, e->g40.n);
		refuse(d, e, n < (size_t)p + 1 ? "fewer control points than "
		    "its degree needs" : msg);
		return -1;
	}
	for (size_t k = 1; k < e->g40.n; k++)
		if (t[k] < t[k - 1]) {
			snprintf(msg, sizeof msg, "knot %zu (%g) is below the "
			    "one before it", k + 1, t[k]);
			refuse(d, e, msg);
			return -1;
		}
	if (rational(e) && e->g41.n != n) {
		snprintf(msg, sizeof msg, "%zu control points need as many "
		    "weights (group 41); it has %zu", n, e->g41.n);
		refuse(d, e, msg);
		return -1;
	}
	for (size_t k = 0; k < e->g41.n; k++)
		if (!(e->g41.v[k] > 0) || !(e->g41.v[k] < 1e300)) {
			refuse(d, e, "its weights are not all above 0 (and "
			    "finite)");
			return -1;
		}
	return 0;
}

/* ---- rational splines: cubic pieces within the tolerance ------------ */

/* Samples inside each cubic piece at which a rational piece's error is
 * measured: the error of a Hermite cubic through a smooth curve's ends
 * and end tangents is a smooth function vanishing to second order at
 * both ends, so 7 inner samples find its largest value to within a few
 * per cent; the tolerance is then halved against that. */
#define RAT_SAMPLES 8

/* The point x and derivative dx (dim numbers each) at t of the rational
 * Bezier h[0..p] (homogeneous: dim numbers times the weight, then the
 * weight); work holds (p + 1) (dim + 1). */
static void
rat_eval(const double *h, int p, int dim, double t, double *x, double *dx,
    double *work)
{
	int hd = dim + 1;
	double a[4] = { 0, 0, 0, 1 }, da[4] = { 0, 0, 0, 0 };

	if (dim < 1 || dim > 3)         /* precondition: as rat_rows checks */
		return;
	memcpy(work, h, (size_t)((p + 1) * hd) * sizeof *work);
	for (int r = 1; r < p; r++)             /* de Casteljau to 2 left */
		for (int k = 0; k <= p - r; k++)
			for (int q = 0; q < hd; q++)
				work[k * hd + q] += t * (work[(k + 1) * hd + q] -
				    work[k * hd + q]);
	for (int q = 0; q < hd; q++) {
		a[q] = work[q] + t * (work[hd + q] - work[q]);
		da[q] = p * (work[hd + q] - work[q]);
	}
	for (int q = 0; q < dim; q++) {         /* (A / w)' = (A' - C w') / w */
		x[q] = a[q] / a[dim];
		dx[q] = (da[q] - x[q] * da[dim]) / a[dim];
	}
}

/* The Hermite rows of the rational piece h over [0, 1] cut into k
 * equal parts, into rows (4 dim each); its largest sampled distance
 * from the rational curve. */
static double
rat_rows(const double *h, int p, int dim, long k, double *rows, double *work)
{
	double err = 0, x[3], dx[3], y[3], dy[3];

	if (dim < 1 || dim > 3)         /* a point of 1 to 3 numbers */
		return INFINITY;
	for (long j = 0; j < k; j++) {
		double t0 = (double)j / (double)k, t1 = (double)(j + 1) /
		    (double)k, hl = t1 - t0, *r = rows + 4 * dim * j;

		rat_eval(h, p, dim, t0, x, dx, work);
		rat_eval(h, p, dim, t1, y, dy, work);
		for (int q = 0; q < dim; q++) {
			r[q] = x[q];
			r[dim + q] = y[q];
			r[2 * dim + q] = hl * dx[q];
			r[3 * dim + q] = hl * dy[q];
		}
		for (int i = 1; i < RAT_SAMPLES; i++) {
			double s = (double)i / RAT_SAMPLES, u = 1 - s;
			double h0 = u * u * (1 + 2 * s), h1 = s * s * (3 - 2 * s);
			double g0 = s * u * u, g1 = -s * s * u, c[3];

			rat_eval(h, p, dim, t0 + s * hl, y, dy, work);
			for (int q = 0; q < dim; q++)
				c[q] = h0 * r[q] + h1 * r[dim + q] + g0 *
				    r[2 * dim + q] + g1 * r[3 * dim + q] - y[q];
			err = fmax(err, vnorm(c, dim));
		}
	}
	return err;
}

/*
 * A rational SPLINE (weights 41 that differ): each span's rational
 * Bezier piece (loft_bspline_span on the homogeneous points) as cubic
 * pieces within the tolerance, halved until they are: c->tol, or
 * LOFT_CADIN_ARC_REL of half the extent of the piece's control points
 * (of the radius, for a circle's quarter).  ctl: the control points in
 * millimetres, dim each.
 */
static void
spline_rational(struct dxf *d, struct ent *e, const double *ctl, int dim,
    int closed)
{
	struct loft_writer *w = d->c->w;
	size_t n = e->p10.n, mark = w->len;
	const double *t = e->g40.v;
	int p = (int)e->f71, hd = dim + 1;
	double *hc, *rows = NULL, b[(MAX_DEGREE + 1) * 4];
	double work[(MAX_DEGREE + 1) * 4], first[3];
	long total = 0;
	size_t last = n - 1;

	while (last > (size_t)p && !(t[last] < t[last + 1]))
		last--;         /* the last span that is not empty */

	if ((hc = malloc(n * (size_t)hd * sizeof *hc)) == NULL) {
		d->oom = 1;
		return;
	}
	for (size_t k = 0; k < n; k++) {
		for (int q = 0; q < dim; q++)
			hc[k * (size_t)hd + (size_t)q] = ctl[k * (size_t)dim +
			    (size_t)q] * e->g41.v[k];
		hc[k * (size_t)hd + (size_t)dim] = e->g41.v[k];
	}
	loft_put_type(w, "cubic");
	loft_put_attr(w, "closed", closed ? "1" : "0");
	put_where(d, w, e->layer, e->nlayer);
	loft_end_line(w);
	for (size_t i = (size_t)p; i < n && !d->oom; i++) {
		double lo[3], hi[3], ext = 0, tol, err = HUGE_VAL;
		long k = 1;
		size_t cap = 0;

		if (!(t[i] < t[i + 1]))
			continue;
		loft_bspline_span(t, hc, p, i, hd, b);
		for (int q = 0; q < dim; q++) {
			lo[q] = hi[q] = b[q] / b[dim];
			for (int j = 1; j <= p; j++) {
				lo[q] = fmin(lo[q], b[j * hd + q] / b[j * hd + dim]);
				hi[q] = fmax(hi[q], b[j * hd + q] / b[j * hd + dim]);
			}
			ext = hypot(ext, hi[q] - lo[q]);
		}
		tol = d->c->tol > 0 ? d->c->tol : LOFT_CADIN_ARC_REL * ext / 2;
		for (;;) {
			if (loft__grow((void **)&rows, &cap, (size_t)k * 4 *
			    (size_t)dim, sizeof *rows) != 0) {
				d->oom = 1;
				break;
			}
			err = rat_rows(b, p, dim, k, rows, work);
			if (err <= tol / 2 || !(err == err) || total + 2 * k >
			    LOFT_CADIN_ARC_MAX)
				break;
			k *= 2;
		}
		if (d->oom || !(err <= tol / 2)) {
			free(rows);
			free(hc);
			loft_writer_cut(w, mark);
			w->col = 0;
			if (!d->oom)
				refuse(d, e, "its rational pieces need more cubic "
				    "pieces than the tolerance allows");
			return;
		}
		if (total == 0)
			memcpy(first, rows, (size_t)dim * sizeof *first);
		total += k;
		if (closed && i == last)        /* ends on its start exactly */
			memcpy(rows + 4 * dim * (k - 1) + dim, first,
			    (size_t)dim * sizeof *first);
		for (long j = 0; j < k; j++)
			loft__echo_row(d->echo, w, rows + 4 * dim * j, 4 * dim);
		free(rows);
		rows = NULL;
	}
	free(hc);
	loft_end_record(w);
	loft__cadin_done(d->c, mark, e->line);
}

/* The Bezier piece b[0..p] (dim each) of a SPLINE, number k: a row of
 * the cubic record being written (degree 3 or less), or a bezier
 * record of its own. */
static void
put_piece(struct dxf *d, const struct ent *e, const double *b, int p,
    int dim, size_t k)
{
	struct loft_writer *w = d->c->w;
	double row[12];
	char num[24];

	if (p <= 3) {
		/* degree 1 and 2 raised to 3 exactly: the ends stay,
		 * P'_A = p (b1 - b0), P'_B = p (b_p - b_{p-1}) */
		if (p == 3)
			loft__bezier_hermite(b, dim, row);
		else
			for (int q = 0; q < dim; q++) {
				row[q] = b[q];
				row[dim + q] = b[p * dim + q];
				row[2 * dim + q] = p * (b[dim + q] - b[q]);
				row[3 * dim + q] = p * (b[p * dim + q] -
				    b[(p - 1) * dim + q]);
			}
		loft__echo_row(d->echo, w, row, 4 * dim);
		return;
	}
	snprintf(num, sizeof num, "%zu", k);
	loft_put_type(w, "bezier");
	put_where(d, w, e->layer, e->nlayer);
	loft_put_attr(w, "piece", num);
	loft_end_line(w);
	for (int j = 0; j <= p; j++)
		loft__echo_row(d->echo, w, b + j * dim, dim);
	loft_end_record(w);
}

/* A SPLINE by control points: its Bezier pieces, exactly. */
static void
spline_ctl(struct dxf *d, struct ent *e)
{
	struct loft_writer *w = d->c->w;
	size_t n = e->p10.n, mark = w->len, npieces = 0;
	const double *t = e->g40.v;
	int p = (int)e->f71, dim, cubic, closed;
	size_t hdr = mark;
	double b[(MAX_DEGREE + 1) * 3];
	double *ctl;
	struct frame f;

	if (spline_check(d, e) != 0)
		return;
	/* the control points in millimetres, in place */
	ctl = e->p10.p;
	wcs_frame(d, &f);
	for (size_t k = 0; k < n; k++)
		to_world(&f, ctl + 3 * k, ctl + 3 * k);
	dim = loft__pts_dim(ctl, n);
	if (dim == 2)           /* close up to rows of dim numbers */
		for (size_t k = 0; k < n; k++) {
			ctl[2 * k] = ctl[3 * k];
			ctl[2 * k + 1] = ctl[3 * k + 1];
		}
	cubic = p <= 3;
	closed = e->f70 & 1 || ends_meet(t, ctl, p, n, dim);
	if (rational(e)) {      /* closed: flagged, or clamped on one point */
		spline_rational(d, e, ctl, dim, e->f70 & 1 || (t[0] == t[p] &&
		    t[n] == t[n + (size_t)p] && vdist(ctl, ctl + (n - 1) *
		    (size_t)dim, dim) <= ENDS_SAME * vmaxabs(ctl, dim)));
		return;
	}
	d->knots.n = 0;         /* a cubic's joints, for turn points */
	if (cubic) {
		loft_put_type(w, "cubic");
		loft_put_attr(w, "closed", closed ? "1" : "0");
		put_where(d, w, e->layer, e->nlayer);
		hdr = w->len;
		loft_end_line(w);
	}
	for (size_t i = (size_t)p; i < n; i++) {
		if (!(t[i] < t[i + 1]))
			continue;       /* an empty span */
		loft_bspline_span(t, ctl, p, i, dim, b);
		npieces++;
		if (cubic && joint_add(d, b, dim) != 0) {
			loft_writer_cut(w, mark);
			w->col = 0;
			return;
		}
		put_piece(d, e, b, p, dim, npieces);
	}
	if (npieces == 0) {
		loft_writer_cut(w, mark);
		w->col = 0;
		refuse(d, e, "its knots span nothing: no piece of curve");
		return;
	}
	if (!cubic) {
		loft__cadin_done(d->c, mark, e->line);
		return;
	}
	loft_end_record(w);
	if (!closed && joint_add(d, b + p * dim, dim) != 0) {
		loft_writer_cut(w, mark);
		return;
	}
	if (loft__cadin_done(d->c, mark, e->line) == 0)
		keep_vertices(d, hdr, &d->knots);
}

static void
do_spline(struct dxf *d, struct ent *e)
{
	struct frame f;

	if (e->p10.n > 0) {
		spline_ctl(d, e);
		return;
	}
	if (e->p11.n < 2) {
		refuse(d, e, "a SPLINE needs control points (10/20/30) or "
		    "fit points (11/21/31)");
		return;
	}
	wcs_frame(d, &f);
	d->knots.n = 0;
	for (size_t k = 0; k < e->p11.n; k++)
		if (knot(d, &f, e->p11.p + 3 * k) != 0)
			return;
	if (e->f70 & 1 && d->knots.n > 1 && memcmp(d->knots.p, d->knots.p +
	    3 * (d->knots.n - 1), 3 * sizeof *d->knots.p) == 0)
		d->knots.n--;
	put_knots(d, e->layer, e->nlayer, e->line, e->f70 & 1,
	    e->has12 && !(e->f70 & 1) ? e->t12 : NULL,
	    e->has13 && !(e->f70 & 1) ? e->t13 : NULL);
}

/* A POLYLINE's vertices so far, as one knot record. */
static void
poly_end(struct dxf *d, int complete)
{
	struct poly *pl = &d->pl;
	struct ent tmp;
	struct frame f;
	char msg[160];
	int plane = !(pl->flags & 8);

	if (!pl->open)
		return;
	pl->open = 0;
	snprintf(tmp.name, sizeof tmp.name, "POLYLINE");
	tmp.line = pl->line;
	tmp.handle = pl->handle;
	tmp.nhandle = strlen(pl->handle);
	if (pl->bad || pl->refused)
		return;         /* said so already */
	if (!complete) {
		refuse(d, &tmp, "no SEQEND ends its vertices: not read");
		return;
	}
	if (pl->v.n == 0) {
		refuse(d, &tmp, "a POLYLINE needs vertices");
		return;
	}
	if (frame_of(d, plane ? pl->ext : (double[3]){ 0, 0, 1 }, &f) != 0) {
		refuse(d, &tmp, "its extrusion direction (210/220/230) is "
		    "zero");
		return;
	}
	if (polyline_knots(d, &f, pl->v.p, plane ? pl->bulge.v : NULL,
	    pl->v.n, pl->flags & 1, !plane, pl->elev, msg, sizeof msg) != 0) {
		if (!d->oom)
			refuse(d, &tmp, msg);
		return;
	}
	d->xa = &pl->xa;
	put_knots(d, pl->layer, pl->nlayer, pl->line, pl->flags & 1, NULL,
	    NULL);
}

static void
poly_start(struct dxf *d, struct ent *e)
{
	struct poly *pl = &d->pl;

	pl->open = 1;
	pl->bad = pl->refused = 0;
	pl->line = e->line;
	loft__cadin_quote(pl->handle, 17, e->handle ? e->handle : "",
	    e->nhandle);
	pl->layer = e->layer;
	pl->nlayer = e->nlayer;
	pl->flags = e->f70;
	pl->xa = e->xa;
	memcpy(pl->ext, e->ext, sizeof pl->ext);
	pl->elev = e->p10.n > 0 ? e->p10.p[2] : e->elev;
	pl->v.n = pl->bulge.n = 0;
	if (e->f70 & (16 | 64)) {
		pl->refused = 1;
		refuse(d, e, "a polygon or polyface mesh is a surface loft "
		    "does not read");
	}
}

static void
vertex(struct dxf *d, struct ent *e)
{
	struct poly *pl = &d->pl;

	if (!pl->open) {
		refuse(d, e, "a VERTEX outside a POLYLINE");
		return;
	}
	if (pl->refused || pl->bad)
		return;
	if (e->p10.n != 1) {
		pl->bad = 1;
		refuse(d, e, "a VERTEX needs one point (10/20/30): its "
		    "POLYLINE is not read");
		return;
	}
	if (e->f70 & 16)
		return;         /* a spline frame's control point: not drawn */
	if (loft__pts_add(&pl->v, e->p10.p) != 0 ||
	    nums_add(&pl->bulge, e->bulge.n > 0 ? e->bulge.v[0] : 0) != 0)
		d->oom = 1;
}

/*
 * ELLIPSE: centre 10/20/30 and the end of its major axis 11/21/31
 * (from the centre, WCS), the minor axis 40 times as long along the
 * extrusion cross the major axis, from parameter 41 to 42 (radians;
 * the whole ellipse by default).  The affine image of the unit
 * circle's cubic pieces (loft__arc_unit): within the tolerance of a
 * circle of the major radius, which the map stretches no more.
 */
static void
do_ellipse(struct dxf *d, struct ent *e)
{
	struct loft_writer *w = d->c->w;
	struct frame f;
	double *maj, mn[3], n[3], r, t0, sweep, q[12], row[12];
	size_t mark = w->len;
	long np;
	int full, dim = 2;

	if (e->p10.n != 1 || e->p11.n != 1 || e->g40.n != 1 ||
	    !(e->g40.v[0] > 0)) {
		refuse(d, e, "an ELLIPSE needs a centre (10/20/30), a major "
		    "axis (11/21/31) and a ratio above 0 (40)");
		return;
	}
	maj = e->p11.p;
	if (ocs_axes(e->ext, n, n, n) != 0 || !(vnorm(maj, 3) > 0)) {
		refuse(d, e, "its major axis or its extrusion is zero");
		return;
	}
	vcopy(n, e->ext, 3);
	vunit(n, 3);
	mn[0] = e->g40.v[0] * (n[1] * maj[2] - n[2] * maj[1]);
	mn[1] = e->g40.v[0] * (n[2] * maj[0] - n[0] * maj[2]);
	mn[2] = e->g40.v[0] * (n[0] * maj[1] - n[1] * maj[0]);
	t0 = e->g41.n > 0 ? e->g41.v[0] : 0;
	sweep = (e->has42 ? e->g42 : 2 * M_PI) - t0;
	full = e->g41.n == 0 || fabs(fabs(sweep) - 2 * M_PI) < 1e-12;
	if (full)
		sweep = 2 * M_PI;
	sweep = fmod(sweep, 2 * M_PI);
	if (!(sweep > 0))
		sweep += 2 * M_PI;
	wcs_frame(d, &f);
	r = vnorm(maj, 3) * fmax(1, e->g40.v[0]);
	if ((np = loft__arc_cubics(d->c, r * f.scale * f.stretch, sweep)) < 0) {
		refuse(d, e, "it needs more cubic pieces than the tolerance "
		    "allows");
		return;
	}
	for (int pass = 0; pass < 2; pass++) {  /* the dimension; then out */
		if (pass == 1) {
			loft_put_type(w, "cubic");
			loft_put_attr(w, "closed", full ? "1" : "0");
			put_where(d, w, e->layer, e->nlayer);
			loft_end_line(w);
		}
		for (long i = 0; i < np; i++) {
			double h = sweep / (double)np, a = t0 + h * (double)i;
			double u[8];

			loft__arc_unit(a, h, i + 1 == np ? t0 + sweep : a + h, u);
			for (int j = 0; j < 4; j++) {
				double o[3];

				for (int k = 0; k < 3; k++)
					o[k] = e->p10.p[k] + u[2 * j] * maj[k] +
					    u[2 * j + 1] * mn[k];
				to_world(&f, o, q + 3 * j);
				if (q[3 * j + 2] != 0)
					dim = 3;
			}
			if (pass == 0)
				continue;
			if (dim == 2)
				for (int j = 1; j < 4; j++) {
					q[2 * j] = q[3 * j];
					q[2 * j + 1] = q[3 * j + 1];
				}
			loft__bezier_hermite(q, dim, row);
			loft__echo_row(d->echo, w, row, 4 * dim);
		}
	}
	loft_end_record(w);
	loft__cadin_done(d->c, mark, e->line);
}

/* ---- layers: those off or frozen ------------------------------------ */

/* Names compared as DXF does, ignoring ASCII case. */
static int
name_cmp(const void *a, const void *b)
{
	const struct name *p = a, *q = b;

	if (p->n != q->n)
		return p->n < q->n ? -1 : 1;
	for (size_t i = 0; i < p->n; i++) {
		int x = (unsigned char)p->s[i], y = (unsigned char)q->s[i];

		x = x >= 'a' && x <= 'z' ? x - 32 : x;
		y = y >= 'a' && y <= 'z' ? y - 32 : y;
		if (x != y)
			return x < y ? -1 : 1;
	}
	return 0;
}

/* A group of a TABLES entry: a LAYER's name (2), colour (62, negative
 * when off) and flags (70, bit 1 when frozen). */
static void
table_group(struct dxf *d, const struct pair *pr)
{
	double x;

	if (!d->in_lay)
		return;
	if (pr->code == 2) {
		d->lay.g2 = pr->v;
		d->lay.n2 = pr->n;
	} else if ((pr->code == 62 || pr->code == 70) &&
	    loft_parse_num(pr->v, pr->n, &x, NULL) == 0 && fabs(x) < 1e9)
		*(pr->code == 62 ? &d->lay.f62 : &d->lay.f70) = (long)x;
}

/* A TABLES entry ended: a LAYER off or frozen is kept. */
static void
table_end(struct dxf *d)
{
	struct name *nm;

	if (!d->in_lay || d->lay.g2 == NULL || !(d->lay.f62 < 0 ||
	    d->lay.f70 & 1))
		return;
	if (loft__grow((void **)&d->off, &d->offcap, d->noff + 1,
	    sizeof *d->off) != 0) {
		d->oom = 1;
		return;
	}
	nm = &d->off[d->noff++];
	nm->s = d->lay.g2;
	nm->n = d->lay.n2;
	d->offsorted = 0;
}

static int
layer_off(struct dxf *d, const char *s, size_t n)
{
	struct name key = { s, n };

	if (d->noff == 0 || s == NULL)
		return 0;
	if (!d->offsorted) {
		qsort(d->off, d->noff, sizeof *d->off, name_cmp);
		d->offsorted = 1;
	}
	return bsearch(&key, d->off, d->noff, sizeof *d->off, name_cmp) !=
	    NULL;
}

/* ---- blocks --------------------------------------------------------- */

static int
block_cmp(const void *a, const void *b)
{
	const struct block *p = a, *q = b;

	return name_cmp(&p->name, &q->name);
}

/* A BLOCK entity ended, its entities from pr on: kept by name. */
static void
block_add(struct dxf *d, const struct ent *e, const struct pair *pr)
{
	struct block *b;

	if (e->g2 == NULL || e->bad)
		return;
	if (loft__grow((void **)&d->blk, &d->blkcap, d->nblk + 1,
	    sizeof *d->blk) != 0) {
		d->oom = 1;
		return;
	}
	b = &d->blk[d->nblk++];
	b->name.s = e->g2;
	b->name.n = e->n2;
	memset(b->base, 0, sizeof b->base);
	if (e->p10.n > 0)
		vcopy(b->base, e->p10.p, 3);
	b->at = pr->at;
	b->line = pr->before;
	d->blksorted = 0;
}

static const struct block *
block_find(struct dxf *d, const char *s, size_t n)
{
	struct block key;

	memset(&key, 0, sizeof key);
	if (d->nblk == 0 || s == NULL)
		return NULL;
	if (!d->blksorted) {    /* stable for equal names: the first wins */
		qsort(d->blk, d->nblk, sizeof *d->blk, block_cmp);
		d->blksorted = 1;
	}
	key.name.s = s;
	key.name.n = n;
	return bsearch(&key, d->blk, d->nblk, sizeof *d->blk, block_cmp);
}

/* The largest factor by which the 3 by 3 matrix m (by rows) stretches a
 * length: its largest column when the columns are orthogonal (rotations
 * and scales, as INSERTs make), else its Frobenius norm (a bound). */
static double
stretch_of(const double *m)
{
	double c[3][3], big = 0, fro = 0;
	int orth = 1;

	for (int j = 0; j < 3; j++) {
		for (int k = 0; k < 3; k++)
			c[j][k] = m[3 * k + j];
		big = fmax(big, vnorm(c[j], 3));
		fro = hypot(fro, vnorm(c[j], 3));
	}
	for (int j = 0; j < 3; j++)
		for (int k = j + 1; k < 3; k++)
			if (fabs(vdot(c[j], c[k], 3)) > 1e-12 * fro * fro)
				orth = 0;
	return orth ? big : fro;
}

static void read_pairs(struct dxf *);

/* The entities of block b once more, through the transform (L, t) of
 * an INSERT (composed with those it is inside). */
static void
replay(struct dxf *d, const struct block *b, const double *L, const double *t)
{
	const char *p = d->p;
	long line = d->line;
	int sec = d->sec;
	double old[12], st = d->stretch, m[12];

	memcpy(old, d->xf, sizeof old);
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			m[3 * i + j] = d->nins == 0 ? L[3 * i + j] :
			    old[3 * i] * L[j] + old[3 * i + 1] * L[3 + j] +
			    old[3 * i + 2] * L[6 + j];
		m[9 + i] = t[i];
	}
	if (d->nins > 0)
		xf_apply(old, t, m + 9, 0);
	memcpy(d->xf, m, sizeof m);
	d->stretch = stretch_of(m);
	d->nins++;
	d->p = b->at;
	d->line = b->line;
	d->sec = S_REPLAY;
	d->in_ent = 0;
	read_pairs(d);
	poly_end(d, 0);
	d->nins--;
	d->eof = 0;
	d->in_ent = 0;
	d->p = p;
	d->line = line;
	d->sec = sec;
	memcpy(d->xf, old, sizeof old);
	d->stretch = st;
}

/*
 * INSERT: block 2 drawn at 10/20/30 (in the OCS of 210/220/230), its
 * base point there, scaled by 41, 42, 43 and turned by 50 degrees, as
 * 70 columns and 71 rows spaced 44 and 45 (in the turned frame).
 */
static void
do_insert(struct dxf *d, struct ent *e)
{
	double s[3] = { e->g41.n > 0 ? e->g41.v[0] : 1,
	    e->has42 ? e->g42 : 1, e->has43 ? e->g43 : 1 };
	double ro = e->a50 * M_PI / 180, cr = cos(ro), sr = sin(ro);
	double ax[3] = { 1, 0, 0 }, ay[3] = { 0, 1, 0 }, az[3] = { 0, 0, 1 };
	double L[9], t[3];
	long cols = e->f70 > 1 ? e->f70 : 1, rows = e->f71 > 1 ? e->f71 : 1;
	const struct block *b = block_find(d, e->g2, e->n2);
	int top = d->nins == 0;
	struct name lay = d->ins_layer;
	/* what is needed of e, which drawing the block overwrites */
	double at[3] = { 0, 0, 0 }, sp[2] = { e->g44, e->g45 };
	struct ent me;

	if (e->p10.n > 0)
		vcopy(at, e->p10.p, 3);
	memcpy(me.name, e->name, sizeof me.name);
	me.line = e->line;
	me.handle = e->handle;
	me.nhandle = e->nhandle;

	if (b == NULL) {
		refuse(d, e, "no block of its name (group 2) in "
		    "the BLOCKS section");
		return;
	}
	if (d->nins >= INSERT_DEPTH) {  /* said once a document */
		if (!d->said_deep++)
			refuse(d, e, "blocks nested deeper than 16 INSERTs "
			    "(does a block insert itself?): not read");
		return;
	}
	if (!(e->ext[0] == 0 && e->ext[1] == 0 && e->ext[2] > 0) &&
	    ocs_axes(e->ext, ax, ay, az) != 0) {
		refuse(d, e, "its extrusion direction "
		    "(210/220/230) is zero");
		return;
	}
	/* L = A R S: columns of A the OCS axes, R the turn about z */
	for (int k = 0; k < 3; k++) {
		L[3 * k] = (ax[k] * cr + ay[k] * sr) * s[0];
		L[3 * k + 1] = (-ax[k] * sr + ay[k] * cr) * s[1];
		L[3 * k + 2] = az[k] * s[2];
	}
	if (top || !(e->nlayer == 1 && e->layer[0] == '0')) {
		d->ins_layer.s = e->layer;      /* layer 0 takes the outer's */
		d->ins_layer.n = e->nlayer;
	}
	if (top) {
		d->ins_block.s = e->g2;
		d->ins_block.n = e->n2;
		d->grp++;
	}
	for (long r = 0; r < rows && d->budget > 0 && !d->oom; r++)
		for (long c = 0; c < cols && d->budget > 0 && !d->oom; c++) {
			/* the grid's offset, turned, in the OCS */
			double ox = sp[0] * (double)c, oy = sp[1] * (double)r;
			double o[3] = { at[0], at[1], at[2] };

			o[0] += cr * ox - sr * oy;
			o[1] += sr * ox + cr * oy;
			for (int k = 0; k < 3; k++)
				t[k] = o[0] * ax[k] + o[1] * ay[k] + o[2] *
				    az[k] - (L[3 * k] * b->base[0] +
				    L[3 * k + 1] * b->base[1] + L[3 * k + 2] *
				    b->base[2]);
			d->budget--;
			replay(d, b, L, t);
		}
	if (d->budget <= 0 && d->budget-- == 0)
		refuse(d, &me, "INSERTs draw more than 4,000,000 entities: "
		    "the rest is not read");
	d->ins_layer = lay;
}

/* ---- HATCH boundaries (fromcad -F) ---------------------------------- */

/* An edge whose end is this near the end of the edge before (relative
 * to the coordinates' size) meets it there: it runs backwards, and is
 * turned round.  An edge meeting at neither end is taken as written. */
#define HATCH_MEET 1e-9

/* The cubic pieces one rational span of a spline edge may take: as
 * many as a quarter circle needs at 1e-12 of its radius (about 300),
 * with room to spare. */
#define HATCH_RAT_MAX 1024

/* The next group of the HATCH's groups h at *i: its number when it has
 * the code, else -1 (the boundary is not as DXF writes it). */
static int
hnum(const struct dxf *d, size_t *i, int code, double *x)
{
	const struct pair *h = d->hp;

	if (*i >= d->nhp || h[*i].code != code ||
	    loft_parse_num(h[*i].v, h[*i].n, x, NULL) != 0)
		return -1;
	(*i)++;
	return 0;
}

/* A whole-number group, 0 to max, as hnum. */
static int
hint(const struct dxf *d, size_t *i, int code, long max, long *v)
{
	double x;

	if (hnum(d, i, code, &x) != 0 || x != floor(x) || x < 0 || x > max)
		return -1;
	*v = (long)x;
	return 0;
}

/* A polyline boundary path (after its 92): vertices with bulges, into
 * d->verts (x, y, bulge); -1 when malformed. */
static int
hatch_poly(struct dxf *d, size_t *i)
{
	long bulge, closed, n;

	if (hint(d, i, 72, 1, &bulge) || hint(d, i, 73, 1, &closed) ||
	    hint(d, i, 93, 10000000, &n))
		return -1;
	for (long k = 0; k < n; k++) {
		double v[3] = { 0, 0, 0 };

		if (hnum(d, i, 10, &v[0]) || hnum(d, i, 20, &v[1]) ||
		    (bulge && hnum(d, i, 42, &v[2])))
			return -1;
		if (loft__pts_add(&d->work, v) != 0) {
			d->oom = 1;
			return -1;
		}
	}
	return 0;
}

/* The world tolerance for a curve of OCS size ext under f: -t, or
 * LOFT_CADIN_ARC_REL of the size as arcs have it; in OCS units. */
static double
hatch_tol(const struct dxf *d, const struct frame *f, double ext)
{
	double s = f->scale * f->stretch;

	return d->c->tol > 0 ? d->c->tol / s : LOFT_CADIN_ARC_REL * ext;
}

/*
 * The polynomial Bezier b[0..p] (x, y each, OCS) as chords within tol:
 * a chord over a parameter step h stands at most M h^2 / 8 off a curve
 * whose second derivative is at most M, and M is at most p (p - 1)
 * times the largest second difference of the points.  The chords'
 * starts go to pts (z 0); its end does not.  0, or -1 (too many).
 */
static int
bezier_chords(struct dxf *d, const double *b, int p, double tol,
    struct loft__pts *pts)
{
	double m = 0, n = 1, q[2 * (LOFT_BSPLINE_MAXDEG + 1)];

	for (int j = 0; j + 2 <= p; j++)
		m = fmax(m, hypot(b[2 * j + 4] - 2 * b[2 * j + 2] + b[2 * j],
		    b[2 * j + 5] - 2 * b[2 * j + 3] + b[2 * j + 1]));
	m *= p * (p - 1);
	if (m > 0)
		n = ceil(sqrt(m / (8 * tol)));
	if (!(n <= LOFT_CADIN_ARC_MAX))
		return -1;
	for (long k = 0; k < (long)n; k++) {
		double u = (double)k / n, o[3] = { 0, 0, 0 };

		memcpy(q, b, 2 * (size_t)(p + 1) * sizeof *q);
		for (int r = p; r > 0; r--)     /* de Casteljau */
			for (int j = 0; j < 2 * r; j++)
				q[j] += u * (q[j + 2] - q[j]);
		o[0] = q[0];
		o[1] = q[1];
		if (loft__pts_add(pts, o) != 0) {
			d->oom = 1;
			return -1;
		}
	}
	return 0;
}

/* An ellipse edge (after its 72): centre, major axis end (relative),
 * ratio, start and end angles (degrees from the major axis, not
 * parameters; clockwise ones mirrored as an arc edge's), as chords:
 * the second derivative is at most the major radius M, so a parameter
 * step h stands at most M h^2 / 8 off.  Its points, end too, to pts. */
static int
hatch_ellipse(struct dxf *d, const struct frame *f, size_t *i,
    struct loft__pts *pts)
{
	double c[2], mj[2], ra, a0, a1, sw, u0, du, r, tol, n;
	long ccw;

	if (hnum(d, i, 10, &c[0]) || hnum(d, i, 20, &c[1]) ||
	    hnum(d, i, 11, &mj[0]) || hnum(d, i, 21, &mj[1]) ||
	    hnum(d, i, 40, &ra) || hnum(d, i, 50, &a0) ||
	    hnum(d, i, 51, &a1) || hint(d, i, 73, 1, &ccw) || !(ra > 0) ||
	    !(hypot(mj[0], mj[1]) > 0))
		return -1;
	sw = a1 - a0;           /* in (0, 360]: fmod, as a loop of 360s
				 * never ends on a huge angle */
	if (sw <= 0)
		sw = fmod(sw, 360) + 360;
	a0 *= M_PI / 180;
	a1 *= M_PI / 180;
	/* the parameter of an angle: atan2(sin a / ratio, cos a) */
	u0 = atan2(sin(a0) / ra, cos(a0));
	du = sw >= 360 ? 2 * M_PI : atan2(sin(a1) / ra, cos(a1)) - u0;
	while (du <= 0)
		du += 2 * M_PI;
	if (!ccw)
		u0 = -u0, du = -du;
	r = hypot(mj[0], mj[1]) * fmax(1, ra);
	tol = hatch_tol(d, f, r);
	n = fmax(ceil(fabs(du) / (M_PI / 2)),
	    ceil(fabs(du) * sqrt(r / (8 * tol))));
	if (!(n <= LOFT_CADIN_ARC_MAX))
		return -3;
	for (long k = 0; k <= (long)n; k++) {
		double u = u0 + du * (double)k / n;
		double o[3] = { c[0] + cos(u) * mj[0] - sin(u) * ra * mj[1],
		    c[1] + cos(u) * mj[1] + sin(u) * ra * mj[0], 0 };

		if (loft__pts_add(pts, o) != 0) {
			d->oom = 1;
			return -1;
		}
	}
	return 0;
}

/* The spline edge's Bezier piece b (degree p, points of hd numbers:
 * x, y, or w x, w y, w) as chords into pts: a rational one first as
 * cubics within half the tolerance (loft_rational_cubics), each cubic
 * then chorded within the other half.  0, -1 (memory), -3 (the
 * tolerance wants too many pieces). */
static int
spline_piece(struct dxf *d, const struct frame *f, const double *b, int p,
    int hd, double *cub, struct loft__pts *pts)
{
	double ext = 0, tol, lo[2], hi[2];
	size_t n;

	for (int q = 0; q < 2; q++) {
		lo[q] = hi[q] = b[q] / (hd == 3 ? b[2] : 1);
		for (int j = 1; j <= p; j++) {
			double x = b[j * hd + q] / (hd == 3 ? b[j * hd + 2] : 1);

			lo[q] = fmin(lo[q], x);
			hi[q] = fmax(hi[q], x);
		}
		ext = hypot(ext, hi[q] - lo[q]);
	}
	tol = hatch_tol(d, f, ext);
	if (hd == 2)
		return bezier_chords(d, b, p, tol, pts) != 0 ? d->oom ? -1 :
		    -3 : 0;
	if (loft_rational_cubics(b, p, 2, tol / 2, HATCH_RAT_MAX, cub, &n,
	    NULL) != 0)
		return -3;
	for (size_t k = 0; k < n; k++)
		if (bezier_chords(d, cub + 8 * k, 3, tol / 2, pts) != 0)
			return d->oom ? -1 : -3;
	return 0;
}

/* The fit data after a spline edge's control points, passed over: 97
 * and its 11/21, then 12/22 and 13/23.  The 97 of fit points and the
 * path's own 97 (its source objects) look alike: a 97 is taken for
 * fit points only when what follows it is as DXF writes them (the next
 * edge's 72, or the path's 97, after the last edge). */
static void
spline_fit(const struct dxf *d, size_t *i, int last)
{
	size_t j = *i;
	long nf;
	double x;

	if (hint(d, &j, 97, 10000000, &nf) == 0) {
		long k = 0;

		while (k < nf && hnum(d, &j, 11, &x) == 0 &&
		    hnum(d, &j, 21, &x) == 0)
			k++;
		if (k == nf) {
			size_t s = j;

			if (hnum(d, &j, 12, &x) == 0 && hnum(d, &j, 22, &x) != 0)
				j = s;
			s = j;
			if (hnum(d, &j, 13, &x) == 0 && hnum(d, &j, 23, &x) != 0)
				j = s;
			if (j < d->nhp && d->hp[j].code == (last ? 97 : 72))
				*i = j;
		}
		if (*i == j)
			return;
	}
	j = *i;                 /* no fit points: tangents alone */
	if (hnum(d, &j, 12, &x) == 0 && hnum(d, &j, 22, &x) == 0)
		*i = j;
	j = *i;
	if (hnum(d, &j, 13, &x) == 0 && hnum(d, &j, 23, &x) == 0)
		*i = j;
}

/* A spline edge (after its 72): degree 94, rational 73, periodic 74,
 * knots 95/40, control points 96/10/20 with weights 42, then fit data
 * (passed over: the control points are the curve); its Bezier pieces
 * (loft_bspline_bezier, in homogeneous form when rational) as chords,
 * end too, to pts.  0, -1 (malformed), -3 (too many chords). */
static int
hatch_spline(struct dxf *d, const struct frame *f, size_t *i, int last,
    struct loft__pts *pts)
{
	long deg, rat, per, nk, nc;
	double *t = NULL, *c = NULL, *out = NULL, *cub = NULL;
	int hd, r = -1;
	size_t ns;

	if (hint(d, i, 94, LOFT_BSPLINE_MAXDEG, &deg) || deg < 1 ||
	    hint(d, i, 73, 1, &rat) || hint(d, i, 74, 1, &per) ||
	    hint(d, i, 95, 10000000, &nk) || hint(d, i, 96, 10000000, &nc) ||
	    nk != nc + deg + 1 || nc <= deg ||
	    (size_t)(nk + 2 * nc) > d->nhp - *i)
		return -1;
	hd = rat ? 3 : 2;
	t = malloc((size_t)nk * sizeof *t);
	c = malloc((size_t)nc * 3 * sizeof *c);
	cub = malloc(8 * HATCH_RAT_MAX * sizeof *cub);
	if (t == NULL || c == NULL || cub == NULL)
		goto oom;
	for (long k = 0; k < nk; k++)
		if (hnum(d, i, 40, &t[k]))
			goto done;
	for (long k = 0; k < nc; k++) {
		double *q = c + k * hd, w = 1;

		if (hnum(d, i, 10, &q[0]) || hnum(d, i, 20, &q[1]) ||
		    (rat && (hnum(d, i, 42, &w) || !(w > 0))))
			goto done;
		if (rat)
			q[0] *= w, q[1] *= w, q[2] = w;
	}
	spline_fit(d, i, last);
	if (loft_bspline_check(t, (size_t)nc, (int)deg, NULL) != 0)
		goto done;
	ns = loft_bspline_spans(t, (size_t)nc, (int)deg);
	if ((out = malloc(ns * (size_t)(deg + 1) * (size_t)hd *
	    sizeof *out)) == NULL)
		goto oom;
	if (loft_bspline_bezier(t, (size_t)nc, (int)deg, c, hd, out, NULL,
	    NULL) != 0)
		goto done;
	for (size_t k = 0; k < ns; k++)
		if ((r = spline_piece(d, f, out + k * (size_t)(deg + 1) *
		    (size_t)hd, (int)deg, hd, cub, pts)) != 0)
			goto done;
	{
		const double *e = out + (ns * (size_t)(deg + 1) - 1) *
		    (size_t)hd;
		double o[3] = { e[0], e[1], 0 };

		if (rat)
			o[0] /= e[2], o[1] /= e[2];
		if (loft__pts_add(pts, o) != 0)
			goto oom;
	}
	r = 0;
	goto done;
oom:
	d->oom = 1;
	r = -1;
done:
	free(t);
	free(c);
	free(out);
	free(cub);
	return r;
}

/* The edge in pts (points, its end last) after the edge ending at prev:
 * turned round when its end, not its start, meets prev; its points but
 * the end to d->work as vertices of no bulge.  prev becomes its end. */
static int
curve_vertices(struct dxf *d, struct loft__pts *pts, double *prev, long k)
{
	double *p = pts->p, *e = p + 3 * (pts->n - 1);
	double db = hypot(e[0] - prev[0], e[1] - prev[1]);

	if (k > 0 && db < hypot(p[0] - prev[0], p[1] - prev[1]) &&
	    db <= HATCH_MEET * (fabs(prev[0]) + fabs(prev[1]) +
	    fabs(p[0]) + fabs(p[1])))
		for (size_t a = 0, b = pts->n - 1; a < b; a++, b--)
			for (int q = 0; q < 3; q++) {
				double s = p[3 * a + q];

				p[3 * a + q] = p[3 * b + q];
				p[3 * b + q] = s;
			}
	for (size_t a = 0; a + 1 < pts->n; a++)
		if (loft__pts_add(&d->work, p + 3 * a) != 0) {
			d->oom = 1;
			return -1;
		}
	prev[0] = p[3 * (pts->n - 1)];
	prev[1] = p[3 * (pts->n - 1) + 1];
	return 0;
}

/* Whether p and q are one point, to HATCH_MEET of their size. */
static int
hatch_meet(const double *p, const double *q)
{
	return hypot(p[0] - q[0], p[1] - q[1]) <= HATCH_MEET * (fabs(p[0]) +
	    fabs(p[1]) + fabs(q[0]) + fabs(q[1]));
}

/* Before edge k, from a to b as written: where it meets neither end of
 * the edge before (prev) and that edge closed the loop begun at first,
 * a row of NaN cuts the loop off and a new one begins at a (one edge
 * path may hold several loops; ezdxf chains them so too).  A gap in a
 * loop not yet closed is bridged by a straight chord.  0, or -1. */
static int
hatch_cut(struct dxf *d, const double *a, const double *b,
    const double *prev, double *first, long k)
{
	double cut[3] = { NAN, NAN, NAN };

	if (k > 0 && (hatch_meet(a, prev) || hatch_meet(b, prev) ||
	    !hatch_meet(prev, first)))
		return 0;
	first[0] = a[0];
	first[1] = a[1];
	if (k > 0 && loft__pts_add(&d->work, cut) != 0) {
		d->oom = 1;
		return -1;
	}
	return 0;
}

/* An edge boundary path (after its 92): lines and circular arcs as
 * vertices with bulges (an arc's bulge is tan of a quarter of its
 * sweep, negative clockwise), each edge turned where it runs from the
 * end of the one before to its own start (writers do not orient them);
 * ellipse and spline edges as chords within the tolerance (vertices of
 * no bulge).  0, -1 (malformed), -3 (too many chords). */
static int
hatch_edges(struct dxf *d, const struct frame *f, size_t *i)
{
	long n, type, ccw;
	double prev[2] = { 0, 0 }, first[2] = { 0, 0 }, r = 0;
	struct loft__pts pts = { NULL, 0, 0 };
	int rc = 0;

	if (hint(d, i, 93, 10000000, &n))
		return -1;
	for (long k = 0; k < n && rc == 0; k++) {
		double a[3] = { 0, 0, 0 }, b[2], c[2], a0, a1, sw, s0, s1;

		if (hint(d, i, 72, 4, &type) || type == 0) {
			rc = -1;
			break;
		}
		if (type >= 3) {
			pts.n = 0;
			rc = type == 3 ? hatch_ellipse(d, f, i, &pts) :
			    hatch_spline(d, f, i, k + 1 == n, &pts);
			if (rc == 0 && (pts.p == NULL || pts.n == 0))
				rc = -1;        /* an edge of no point */
			if (rc == 0)
				rc = hatch_cut(d, pts.p, pts.p + 3 * (pts.n - 1),
				    prev, first, k);
			if (rc == 0)
				rc = curve_vertices(d, &pts, prev, k);
			continue;
		}
		if (type == 1) {
			if (hnum(d, i, 10, &a[0]) || hnum(d, i, 20, &a[1]) ||
			    hnum(d, i, 11, &b[0]) || hnum(d, i, 21, &b[1]))
				rc = -1;
		} else {
			if (hnum(d, i, 10, &c[0]) || hnum(d, i, 20, &c[1]) ||
			    hnum(d, i, 40, &r) || hnum(d, i, 50, &a0) ||
			    hnum(d, i, 51, &a1) || hint(d, i, 73, 1, &ccw))
				rc = -1;
			if (rc != 0)
				break;
			/* a clockwise arc has its angles mirrored in the
			 * x axis, and runs clockwise from -50 to -51 */
			sw = a1 - a0;   /* in (0, 360], as above */
			if (sw <= 0)
				sw = fmod(sw, 360) + 360;
			s0 = (ccw ? a0 : -a0) * M_PI / 180;
			s1 = (ccw ? a1 : -a1) * M_PI / 180;
			a[0] = c[0] + r * cos(s0);
			a[1] = c[1] + r * sin(s0);
			b[0] = c[0] + r * cos(s1);
			b[1] = c[1] + r * sin(s1);
			a[2] = (ccw ? 1 : -1) * tan(fmin(sw, 360) * M_PI / 720);
		}
		if (rc != 0 || (rc = hatch_cut(d, a, b, prev, first, k)) != 0)
			break;
		if (k > 0 && hypot(b[0] - prev[0], b[1] - prev[1]) <
		    hypot(a[0] - prev[0], a[1] - prev[1]) && hypot(b[0] -
		    prev[0], b[1] - prev[1]) <= HATCH_MEET * (fabs(prev[0]) +
		    fabs(prev[1]) + r)) {
			double t0 = a[0], t1 = a[1];    /* turned round */

			a[0] = b[0];
			a[1] = b[1];
			b[0] = t0;
			b[1] = t1;
			a[2] = -a[2];
		}
		prev[0] = b[0];
		prev[1] = b[1];
		if (loft__pts_add(&d->work, a) != 0) {
			d->oom = 1;
			rc = -1;
		}
	}
	free(pts.p);
	return rc;
}

/* The path in d->work as closed knot records, one a loop (the loops
 * apart at rows of NaN, hatch_edges's cuts).  0, or -1 after refusing
 * the entity (what was written of the path stays). */
static int
hatch_loops(struct dxf *d, struct ent *e, const struct frame *f, double z)
{
	char msg[160];

	for (size_t a = 0, b; a < d->work.n; a = b + 1) {
		const double *v = d->work.p + 3 * a;

		for (b = a; b < d->work.n && !isnan(d->work.p[3 * b]); b++)
			;
		d->seg.n = 0;           /* the bulges, apart */
		for (size_t q = 0; q < b - a; q++)
			if (nums_add(&d->seg, v[3 * q + 2]) != 0) {
				d->oom = 1;
				return -1;
			}
		/* z from the elevation: the third numbers are not read */
		if (polyline_knots(d, f, v, d->seg.v, b - a, 1, 0, z, msg,
		    sizeof msg) != 0) {
			if (!d->oom)
				refuse(d, e, msg);
			return -1;
		}
		put_knots(d, e->layer, e->nlayer, e->line, 1, NULL, NULL);
	}
	return 0;
}

/* The boundary paths of a HATCH (its groups in d->hp): each a closed
 * knot record, arcs as chords within the tolerance. */
static void
do_hatch(struct dxf *d, struct ent *e)
{
	size_t i = 0;
	long np, flags, ns;
	double elev[3] = { 0, 0, 0 }, ext[3] = { 0, 0, 1 };
	struct frame f;

	while (i < d->nhp && d->hp[i].code != 91) {     /* the head */
		const struct pair *h = &d->hp[i++];
		double x;

		if (loft_parse_num(h->v, h->n, &x, NULL) != 0)
			continue;
		if (h->code == 30)
			elev[2] = x;
		else if (h->code >= 210 && h->code <= 230 && h->code % 10 == 0)
			ext[h->code / 10 - 21] = x;
	}
	if (hint(d, &i, 91, 1000000, &np) != 0 || frame_of(d, ext, &f) != 0) {
		refuse(d, e, "its boundary paths (group 91) are not as DXF "
		    "writes them, or its extrusion is zero");
		return;
	}
	for (long k = 0; k < np && !d->oom; k++) {
		int r = -1;

		d->work.n = 0;
		if (hint(d, &i, 92, 1L << 30, &flags) == 0)
			r = flags & 2 ? hatch_poly(d, &i) :
			    hatch_edges(d, &f, &i);
		if (r == 0 && hint(d, &i, 97, 10000000, &ns) == 0)
			i += (size_t)ns;        /* its source objects, 330 */
		else if (r == 0)
			r = -1;
		if (r != 0) {
			if (!d->oom)
				refuse(d, e, r == -3 ? "an ellipse or spline "
				    "edge needs more chords than the "
				    "tolerance allows" : "its boundary paths "
				    "are not as DXF writes them");
			return;
		}
		if (hatch_loops(d, e, &f, elev[2]) != 0)
			return;
	}
}

/* ---- entities, by kind ------------------------------------------------ */

/* Entities that annotate a drawing or fill an area: passed over and
 * counted (-S: refused).  HATCH is a fill; XLINE and RAY are endless
 * construction lines. */
static const char *const annotation[] = { "TEXT", "MTEXT", "DIMENSION",
	"ARC_DIMENSION", "LARGE_RADIAL_DIMENSION", "LEADER", "MLEADER",
	"MULTILEADER", "TOLERANCE", "ATTRIB", "ATTDEF", "IMAGE", "WIPEOUT",
	"OLE2FRAME", "OLEFRAME", "VIEWPORT", "ACAD_TABLE", "RTEXT",
	"ARCALIGNEDTEXT", "XLINE", "RAY", "HATCH", "MPOLYGON", "SOLID",
	"TRACE", "SHAPE", "UNDERLAY", "PDFUNDERLAY", "DWFUNDERLAY",
	"DGNUNDERLAY", "LIGHT", "SUN", NULL };

static const struct {
	const char *name;
	void (*read)(struct dxf *, struct ent *);
} readers[] = {
	{ "LINE", do_line }, { "POINT", do_point },
	{ "LWPOLYLINE", do_lwpolyline }, { "SPLINE", do_spline },
	{ "ARC", do_arc_only }, { "CIRCLE", do_circle },
	{ "ELLIPSE", do_ellipse }, { "POLYLINE", poly_start },
	{ "VERTEX", vertex }, { "INSERT", do_insert },
};

/* Whether the entity just ended is whole; if not, says why (once). */
static int
ent_whole(struct dxf *d, struct ent *e)
{
	char msg[240];

	if (!e->bad && ((e->p10.n > 0 && !(e->m10 & 1)) ||
	    (e->p11.n > 0 && !(e->m11 & 1)))) {
		e->bad = 1;
		snprintf(e->msg, sizeof e->msg, "its last point has no x "
		    "(group 10 or 11)");
	}
	if (!e->bad)
		return 1;
	snprintf(msg, sizeof msg, "%s: not read", e->msg);
	if (strcmp(e->name, "VERTEX") == 0 && d->pl.open && !d->pl.bad) {
		d->pl.bad = 1;
		snprintf(msg, sizeof msg, "%s: its POLYLINE is not read",
		    e->msg);
	}
	refuse(d, e, msg);
	return 0;
}

/* The entity just ended: its record, or a message, or counted as an
 * annotation or as hidden. */
static void
ent_end(struct dxf *d, struct ent *e)
{
	const char *n = e->name, *layer = e->layer;
	size_t nlayer = e->nlayer, k;

	if (strcmp(n, "VERTEX") != 0 && strcmp(n, "SEQEND") != 0)
		poly_end(d, 0);
	if (strcmp(n, "SEQEND") == 0) {
		poly_end(d, 1);
		return;
	}
	if (!ent_whole(d, e))
		return;
	d->xa = &e->xa;
	if (d->nins > 0 && nlayer == 1 && layer[0] == '0') {
		layer = d->ins_layer.s;
		nlayer = d->ins_layer.n;
	}
	if (!d->c->hidden && strcmp(n, "VERTEX") != 0 &&
	    layer_off(d, layer, nlayer)) {
		loft__passed_add(&d->hidden, n, strlen(n));
		if (strcmp(n, "POLYLINE") == 0) {
			poly_start(d, e);
			d->pl.refused = 1;      /* its vertices too */
		}
		return;
	}
	if (d->c->fills && strcmp(n, "HATCH") == 0) {
		do_hatch(d, e);
		return;
	}
	for (k = 0; annotation[k] != NULL; k++)
		if (strcmp(n, annotation[k]) == 0) {
			if (d->c->strict)
				refuse(d, e, "an annotation or a fill: not "
				    "read (-S)");
			else
				loft__passed_add(&d->passed, n, strlen(n));
			return;
		}
	for (k = 0; k < sizeof readers / sizeof readers[0]; k++)
		if (strcmp(n, readers[k].name) == 0) {
			readers[k].read(d, e);
			return;
		}
	refuse(d, e, "not read: loft reads LINE, LWPOLYLINE, POLYLINE, "
	    "SPLINE, ARC, CIRCLE, ELLIPSE, POINT and INSERT entities");
}

/* $INSUNITS codes to millimetres (the DXF reference's table). */
static const double unit_mm[] = {
	1,              /* 0 unitless: kept */
	25.4, 304.8, 1609344, 1, 10, 1000, 1e6,         /* in ft mi mm cm m km */
	25.4e-6, 0.0254, 914.4, 1e-7, 1e-6, 1e-3,       /* uin mil yd A nm um */
	100, 1e4, 1e5, 1e12, 1.495978707e14,            /* dm dam hm Gm AU */
	9.4607304725808e18, 3.0856775814913673e19,      /* ly pc */
	1200000.0 / 3937                                /* US survey foot */
};

/* A HEADER variable's value: $INSUNITS sets the scale. */
static void
header_var(struct dxf *d, const char *var, size_t nvar, const struct pair *pr)
{
	double x;

	if (pr->code != 70 || nvar != 9 || memcmp(var, "$INSUNITS", 9) != 0)
		return;
	if (loft_parse_num(pr->v, pr->n, &x, NULL) != 0 || x != floor(x) ||
	    x < 0 || x >= (double)(sizeof unit_mm / sizeof unit_mm[0])) {
		char q[21];

		loft__cadin_say(d->c, pr->line, "$INSUNITS '%s' is no unit "
		    "loft knows: the drawing's numbers are kept as they are",
		    loft__cadin_quote(q, sizeof q, pr->v, pr->n));
		return;
	}
	d->scale = unit_mm[(int)x];
}

/* ---- turn points ---------------------------------------------------- */

struct cell {
	long long x, y;
	size_t v;               /* index in verts */
};

static int
cell_cmp(const void *a, const void *b)
{
	const struct cell *p = a, *q = b;

	if (p->x != q->x)
		return p->x < q->x ? -1 : 1;
	if (p->y != q->y)
		return p->y < q->y ? -1 : 1;
	return p->v < q->v ? -1 : p->v > q->v;
}

static long long
cell_of(double x, double tol)
{
	double c = floor(x / tol);

	return c > 1e18 ? (long long)1e18 : c < -1e18 ? -(long long)1e18 :
	    (long long)c;
}

struct corner {
	size_t rec, knot;
};

static int
corner_cmp(const void *a, const void *b)
{
	const struct corner *p = a, *q = b;

	if (p->rec != q->rec)
		return p->rec < q->rec ? -1 : 1;
	return p->knot < q->knot ? -1 : p->knot > q->knot;
}

/* The knot record holding vertex v. */
static size_t
record_of(const struct dxf *d, size_t v)
{
	size_t lo = 0, hi = d->nkr;

	while (hi - lo > 1) {
		size_t m = (lo + hi) / 2;

		if (d->kr[m].v0 <= v)
			lo = m;
		else
			hi = m;
	}
	return lo;
}

/* Match the turn points to vertices into cs; returns their count, or
 * (size_t)-1 when out of memory. */
static size_t
match_turns(struct dxf *d, struct corner *cs)
{
	size_t nv = d->verts.n, nc = 0;
	const double *v = d->verts.p;
	double lo[3], hi[3], ext = 0, tol;
	struct cell *g;

	for (int k = 0; k < 3; k++) {
		lo[k] = hi[k] = v[k];
		for (size_t i = 1; i < nv; i++) {
			lo[k] = fmin(lo[k], v[3 * i + k]);
			hi[k] = fmax(hi[k], v[3 * i + k]);
		}
		ext = hypot(ext, hi[k] - lo[k]);
	}
	tol = TURN_TOL * ext;
	if (!(tol > 0) || !isfinite(tol))
		tol = DBL_MIN;  /* one point, or none but exact */
	if ((g = malloc(nv * sizeof *g)) == NULL)
		return (size_t)-1;
	for (size_t i = 0; i < nv; i++) {
		g[i].x = cell_of(v[3 * i], tol);
		g[i].y = cell_of(v[3 * i + 1], tol);
		g[i].v = i;
	}
	qsort(g, nv, sizeof *g, cell_cmp);
	for (size_t t = 0; t < d->ntp; t++) {
		const double *x = d->tp[t].x;
		long long cx = cell_of(x[0], tol), cy = cell_of(x[1], tol);
		size_t best = (size_t)-1;
		double bd = tol;

		for (int dx = -1; dx <= 1; dx++)
			for (int dy = -1; dy <= 1; dy++) {
				struct cell key = { cx + dx, cy + dy, 0 };
				size_t a = 0, b = nv;

				while (a < b) {         /* first >= key */
					size_t m = (a + b) / 2;

					if (cell_cmp(&g[m], &key) < 0)
						a = m + 1;
					else
						b = m;
				}
				for (; a < nv && g[a].x == key.x && g[a].y ==
				    key.y; a++) {
					double dd = vdist(v + 3 * g[a].v, x, 3);

					if (d->kr[record_of(d, g[a].v)].grp !=
					    d->tp[t].grp)
						continue;       /* another piece */
					if (dd <= bd && (best == (size_t)-1 ||
					    dd < bd || g[a].v < best)) {
						bd = dd;
						best = g[a].v;
					}
				}
			}
		if (best != (size_t)-1) {
			size_t r = record_of(d, best);

			cs[nc].rec = r;
			cs[nc].knot = best - d->kr[r].v0 + 1;
			nc++;
			d->tp[t].used = 1;
		}
	}
	free(g);
	return nc;
}

/* Append s[0..n) to the buffer *b of length *len; -1 when out of memory. */
static int
append(char **b, size_t *len, size_t *cap, const char *s, size_t n)
{
	if (loft__grow((void **)b, cap, *len + n + 1, 1) != 0)
		return -1;
	memcpy(*b + *len, s, n);
	*len += n;
	return 0;
}

/*
 * Rewrite the text of this document's records in w (from base on):
 * corners= added to the knot records the matched turn points lie on,
 * the matched points' own records left out.
 */
static int
apply_turns(struct dxf *d, size_t base)
{
	struct loft_writer *w = d->c->w;
	struct corner *cs;
	size_t nc, at = base, ci = 0, ti = 0, len = 0, cap = 0;
	char *nb = NULL, num[24];
	int rc = 0;

	if (d->ntp == 0 || d->nkr == 0)
		return 0;
	if ((cs = malloc(d->ntp * sizeof *cs)) == NULL)
		return -1;
	if ((nc = match_turns(d, cs)) == (size_t)-1) {
		free(cs);
		return -1;
	}
	qsort(cs, nc, sizeof *cs, corner_cmp);
	if (append(&nb, &len, &cap, w->buf, base) != 0)
		rc = -1;
	for (size_t r = 0; r < d->nkr && rc == 0; r++) {
		size_t h = d->kr[r].hdr;
		int first = 1;

		if (ci >= nc || cs[ci].rec != r)
			continue;
		/* the text before this header's end, less matched points */
		for (; ti < d->ntp && d->tp[ti].a < h; ti++)
			if (d->tp[ti].used) {
				rc |= append(&nb, &len, &cap, w->buf + at,
				    d->tp[ti].a - at);
				at = d->tp[ti].b;
			}
		rc |= append(&nb, &len, &cap, w->buf + at, h - at);
		at = h;
		rc |= append(&nb, &len, &cap, " corners=", 9);
		for (; ci < nc && cs[ci].rec == r; ci++) {
			if (ci > 0 && cs[ci - 1].rec == r && cs[ci - 1].knot ==
			    cs[ci].knot)
				continue;
			snprintf(num, sizeof num, "%s%zu", first ? "" : ",",
			    cs[ci].knot);
			rc |= append(&nb, &len, &cap, num, strlen(num));
			first = 0;
		}
	}
	for (; ti < d->ntp && rc == 0; ti++)
		if (d->tp[ti].used) {
			rc |= append(&nb, &len, &cap, w->buf + at, d->tp[ti].a -
			    at);
			at = d->tp[ti].b;
		}
	if (rc == 0)
		rc = append(&nb, &len, &cap, w->buf + at, w->len - at);
	free(cs);
	if (rc != 0) {
		free(nb);
		return -1;
	}
	free(w->buf);
	w->buf = nb;
	w->len = len;
	w->cap = cap;
	return 0;
}

/* ---- the document --------------------------------------------------- */

/* Whether the line word stands anywhere in buf[0..len), blanks around. */
static int
find_word(const char *buf, size_t len, const char *word)
{
	size_t n = strlen(word);

	for (const char *p = buf, *e = buf + len; p < e;) {
		const char *q = memchr(p, word[0], (size_t)(e - p));

		if (q == NULL)
			return 0;
		if ((size_t)(e - q) >= n && memcmp(q, word, n) == 0 &&
		    (q == buf || q[-1] == '\n' || q[-1] == ' ' || q[-1] == '\t') &&
		    (q + n == e || q[n] == '\n' || q[n] == '\r' || q[n] == ' '))
			return 1;
		p = q + 1;
	}
	return 0;
}


static void
dxf_free(struct dxf *d)
{
	struct ent *e = &d->e;

	free(e->p10.p);
	free(e->p11.p);
	free(e->bulge.v);
	free(e->g40.v);
	free(e->g41.v);
	free(d->pl.v.p);
	free(d->pl.bulge.v);
	free(d->verts.p);
	free(d->knots.p);
	free(d->straight);
	free(d->work.p);
	free(d->kr);
	free(d->tp);
	free(d->seg.v);
	free(d->echo);
	free(d->off);
	free(d->blk);
	free(d->hp);
}

/* Skip to the next line that is a 0 group code; 1 if there is one. */
static int
resync(struct dxf *d)
{
	const char *s;
	size_t n;

	for (;;) {
		const char *at = d->p;
		long line = d->line;

		if (!next_line(d, &s, &n))
			return 0;
		if (n == 1 && s[0] == '0') {
			d->p = at;
			d->line = line;
			return 1;
		}
	}
}

/* A line where a group code must be is no whole number: said (not
 * again when a block is drawn once more), and reading goes on at the
 * next 0 group; 0, or -1 at the end of the file. */
static int
bad_code(struct dxf *d, const struct pair *pr)
{
	char q[31];

	if (d->nins == 0)
		loft__cadin_say(d->c, pr->line, "'%s' is not a group code (a "
		    "whole number)%s", loft__cadin_quote(q, sizeof q, pr->v,
		    pr->n), d->in_ent ? "; the entity it is in is not read" :
		    "");
	if (d->in_ent)
		d->e.bad = 2;   /* said */
	return resync(d) ? 0 : -1;
}

/* A group of code other than 0. */
static void
on_group(struct dxf *d, const struct pair *pr)
{
	if (d->want_name) {
		d->want_name = 0;
		if (pr->code == 2) {
			d->sec = loft__word_is(pr->v, pr->n, "HEADER") ? S_HEADER :
			    loft__word_is(pr->v, pr->n, "TABLES") ? S_TABLES :
			    loft__word_is(pr->v, pr->n, "BLOCKS") ? S_BLOCKS :
			    loft__word_is(pr->v, pr->n, "ENTITIES") ? S_ENTITIES :
			    S_OTHER;
			return;
		}
		d->sec = S_OTHER;
	}
	if (d->in_ent)
		ent_group(d, &d->e, pr);
	else if (d->sec == S_TABLES)
		table_group(d, pr);
	else if (d->sec == S_HEADER && pr->code == 9) {
		d->var = pr->v;
		d->nvar = pr->n;
	} else if (d->sec == S_HEADER && d->var != NULL)
		header_var(d, d->var, d->nvar, pr);
}

/* The entity being read ends (at the 0 group pr). */
static void
ent_close(struct dxf *d, const struct pair *pr)
{
	d->in_ent = 0;
	if (d->sec == S_BLOCKS)
		block_add(d, &d->e, pr);
	else if (d->e.bad == 2 && strcmp(d->e.name, "VERTEX") == 0)
		d->pl.bad = 1;
	else if (d->e.bad == 2)
		poly_end(d, 0);
	else
		ent_end(d, &d->e);
}

/* A 0 group: an entity, a table entry or a section starts or ends. */
static void
on_zero(struct dxf *d, const struct pair *pr)
{
	int ends = loft__word_is(pr->v, pr->n, "ENDSEC") ||
	    loft__word_is(pr->v, pr->n, "EOF");

	if (d->in_ent)
		ent_close(d, pr);
	if (d->sec == S_TABLES) {
		table_end(d);
		d->in_lay = loft__word_is(pr->v, pr->n, "LAYER");
		d->lay.g2 = NULL;
		d->lay.f62 = d->lay.f70 = 0;
	}
	if (d->sec == S_REPLAY) {       /* a block's entities, once more */
		if (ends || loft__word_is(pr->v, pr->n, "ENDBLK") ||
		    loft__word_is(pr->v, pr->n, "SECTION")) {
			d->eof = 1;
			return;
		}
		if (d->budget-- <= 0) {
			d->eof = 1;
			return;
		}
	}
	if (loft__word_is(pr->v, pr->n, "SECTION"))
		d->want_name = 1;
	else if (ends) {
		poly_end(d, 0);
		d->sec = S_NONE;
		d->eof = loft__word_is(pr->v, pr->n, "EOF");
	} else if (d->sec == S_ENTITIES || d->sec == S_REPLAY ||
	    (d->sec == S_BLOCKS && loft__word_is(pr->v, pr->n, "BLOCK"))) {
		ent_start(d, &d->e, pr);
		d->in_ent = 1;
	}
}

/* Read pairs to the end of the file (or, drawing a block, its ENDBLK). */
static void
read_pairs(struct dxf *d)
{
	struct pair pr;
	int r;

	while (!d->eof && !d->oom && (r = next_pair(d, &pr)) != 0) {
		if (r == -2)
			break;          /* truncated: said at the end */
		if (r < 0) {
			if (bad_code(d, &pr) != 0)
				break;
		} else if (pr.code != 0)
			on_group(d, &pr);
		else
			on_zero(d, &pr);
	}
}

/* The document is read: what was passed over is noted, a truncation
 * said, the turn points applied. */
static void
dxf_finish(struct dxf *d, size_t base)
{
	struct loft_cadin *c = d->c;

	if (!d->eof && !d->oom) {
		if (d->in_ent) {
			char nm[64];

			loft__cadin_say(c, d->e.line, "%s: the file ends inside "
			    "it (truncated?): not read", ent_name(&d->e, nm,
			    sizeof nm));
			d->pl.refused = 1;
		}
		poly_end(d, 0);
		loft__cadin_say(c, d->line, "the file ends without an EOF "
		    "group: truncated?");
	}
	if (!d->oom && apply_turns(d, base) != 0)
		d->oom = 1;
	loft__passed_say(c, &d->passed, "(annotations, fills and empty "
	    "arcs; -S makes them errors)");
	loft__passed_say(c, &d->hidden, "on layers off or frozen (-H reads "
	    "them)");
}

int
loft_dxf_read(const char *buf, size_t len, struct loft_cadin *c)
{
	static const char bin[] = "AutoCAD Binary DXF";
	struct dxf *d;
	size_t base = c->w->len;
	long nbad = c->nbad;
	int oom;

	if (len >= sizeof bin - 1 && memcmp(buf, bin, sizeof bin - 1) == 0) {
		loft__cadin_say(c, 1, "a binary DXF: loft reads ASCII DXF (save "
		    "the drawing as ASCII DXF)");
		return LOFT_EINPUT;
	}
	if ((d = calloc(1, sizeof *d)) == NULL) {
		loft__cadin_say(c, 0, "out of memory");
		return LOFT_ENOMEM;
	}
	d->p = buf;
	d->end = buf + len;
	d->c = c;
	d->scale = 1;
	d->stretch = 1;
	d->budget = INSERT_BUDGET;
	if ((d->echo = calloc(1, sizeof *d->echo)) != NULL) {
		d->echo->doc = buf;     /* none: every number formatted */
		d->echo->len = len;
	}
	/* the records are shorter than the groups they come from: room for
	 * them at once saves copying the output as it grows (if there is
	 * no such room, it grows as usual) */
	loft__grow((void **)&c->w->buf, &c->w->cap, c->w->len + len + 1, 1);
	/* no word POINT, no turn points: the knots need not be kept */
	d->turns = find_word(buf, len, "POINT");
	read_pairs(d);
	dxf_finish(d, base);
	dxf_free(d);
	oom = d->oom;
	if (oom)
		loft__cadin_say(c, d->line, "out of memory");
	free(d);
	if (oom)
		return LOFT_ENOMEM;
	return c->nbad > nbad ? LOFT_EINPUT : 0;
}
