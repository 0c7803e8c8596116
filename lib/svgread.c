/*
 * svgread.c: SVG into loft records, in millimetres with the y axis up.
 * path, polyline, polygon, line, rect, circle and ellipse elements are
 * read, under any nesting of g (and a) elements with their transforms.
 * Each subpath of a path is a record: a `cubic` record where it has a
 * curve (C, S, Q, T exactly, A within c->tol), a knot record where it is
 * straight segments only, as polylines and polygons are.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

/* Elements nested deeper are not read: a real drawing nests a few
 * levels, and a bound keeps the stack fixed however hostile the file. */
#define SVG_DEPTH 256

#define MAX_ATTRS 64

struct attr {
	const char *k, *v;
	size_t kn, vn;
};

struct elem {
	const char *name;
	size_t nn;
	long line;
	const char *at;         /* its '<', for lines inside it */
	struct attr a[MAX_ATTRS];
	int na;
};

struct level {
	double m[6];            /* user space to millimetres */
	const char *layer;
	size_t nlayer;
	int inklayer;           /* layer named by an Inkscape layer */
	int hidden;             /* visibility hidden (inherited) */
};

struct idref {                  /* an id="..." of the document */
	const char *s;
	size_t n;
	const char *at;         /* the '<' of its element */
	long line;
};

struct svg {
	struct loft_cadin *c;
	const char *buf, *p, *end;
	long line;              /* of p */
	struct level st[SVG_DEPTH];
	int depth;              /* levels of open elements read */
	long skip;              /* open elements passed over */
	struct open {           /* every open element, innermost last */
		const char *name;
		size_t nn;
		long line;
		int kind;       /* 0: a level of st, 1: passed over */
	} *open;
	size_t nopen, opencap;
	int after;              /* elements after the root closed */
	size_t base;            /* open elements below what a use draws */
	int nuse, target;       /* uses being drawn; the next is one's */
	int said_deep;          /* the depth was said */
	double use_w, use_h;    /* the box of the use drawn (0: none) */
	long budget;            /* elements uses may still draw */
	struct idref *ids;      /* every id, sorted (once a use asks) */
	size_t nids, idcap;
	int indexed;
	struct loft__passed passed, hide;
	int root;               /* the root svg was seen */
	struct nums { double *v; size_t n, cap; } seg;  /* a subpath */
	int oom;
};

/* The first n2 bytes t in s[0..n), or NULL (memmem is not C99). */
static const char *
find(const char *s, size_t n, const char *t, size_t n2)
{
	for (const char *p = s; n2 <= n && p <= s + (n - n2); p++) {
		p = memchr(p, t[0], (size_t)(s + (n - n2) - p) + 1);
		if (p == NULL)
			return NULL;
		if (memcmp(p, t, n2) == 0)
			return p;
	}
	return NULL;
}

/* ---- the affine maps ------------------------------------------------- */

/* r = a b: first b, then a. */
static void
mat_mul(const double *a, const double *b, double *r)
{
	double t[6];

	t[0] = a[0] * b[0] + a[2] * b[1];
	t[1] = a[1] * b[0] + a[3] * b[1];
	t[2] = a[0] * b[2] + a[2] * b[3];
	t[3] = a[1] * b[2] + a[3] * b[3];
	t[4] = a[0] * b[4] + a[2] * b[5] + a[4];
	t[5] = a[1] * b[4] + a[3] * b[5] + a[5];
	memcpy(r, t, sizeof t);
}

static void
mat_apply(const double *m, const double *p, double *q)
{
	double x = p[0], y = p[1];

	q[0] = m[0] * x + m[2] * y + m[4];
	q[1] = m[1] * x + m[3] * y + m[5];
}

/* The largest factor by which m stretches a length. */
static double
mat_stretch(const double *m)
{
	double s = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
	double det = m[0] * m[3] - m[1] * m[2];

	return sqrt((s + sqrt(fmax(0, s * s - 4 * det * det))) / 2);
}

/* ---- numbers --------------------------------------------------------- */

static int
is_wsp(int ch)
{
	return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' ||
	    ch == '\f';
}

static int
is_digit(int ch)
{
	return ch >= '0' && ch <= '9';
}

/* Skip white space and at most one comma. */
static const char *
skip_sep(const char *s, const char *e)
{
	while (s < e && is_wsp((unsigned char)*s))
		s++;
	if (s < e && *s == ',')
		for (s++; s < e && is_wsp((unsigned char)*s); s++)
			;
	return s;
}

/*
 * An SVG number at *s: sign, digits, a point and digits, an exponent;
 * "1.5.5" is 1.5 and .5, "1-2" is 1 and -2.  Returns 0 and moves *s past
 * it, or -1 (not a number there, or not finite).
 */
static int
svg_num(const char **s, const char *e, double *x)
{
	const char *a = skip_sep(*s, e), *p = a;
	int digits = 0;

	if (p < e && (*p == '+' || *p == '-'))
		p++;
	while (p < e && is_digit((unsigned char)*p)) {
		p++;
		digits++;
	}
	if (p < e && *p == '.') {
		p++;
		while (p < e && is_digit((unsigned char)*p)) {
			p++;
			digits++;
		}
	}
	if (digits == 0)
		return -1;
	if (p < e && (*p == 'e' || *p == 'E')) {
		const char *q = p + 1;

		if (q < e && (*q == '+' || *q == '-'))
			q++;
		if (q < e && is_digit((unsigned char)*q)) {
			while (q < e && is_digit((unsigned char)*q))
				q++;
			p = q;
		}
	}
	if (loft_parse_num(a, (size_t)(p - a), x, NULL) != 0)
		return -1;
	*s = p;
	return 0;
}

/* An arc's flag: a single 0 or 1. */
static int
svg_flag(const char **s, const char *e, int *f)
{
	const char *a = skip_sep(*s, e);

	if (a >= e || (*a != '0' && *a != '1'))
		return -1;
	*f = *a == '1';
	*s = a + 1;
	return 0;
}

/* ---- elements and their attributes ----------------------------------- */

static const struct attr *
attr_of(const struct elem *el, const char *key)
{
	size_t n = strlen(key);

	for (int i = 0; i < el->na; i++)
		if (el->a[i].kn == n && memcmp(el->a[i].k, key, n) == 0)
			return &el->a[i];
	return NULL;
}

static int
name_is(const struct elem *el, const char *name)
{
	return el->nn == strlen(name) && memcmp(el->name, name, el->nn) == 0;
}

/* The line of position at inside element el. */
static long
line_at(const struct elem *el, const char *at)
{
	long line = el->line;

	for (const char *p = el->at; p < at; p++)
		line += *p == '\n';
	return line;
}

static void
say_el(struct svg *s, const struct elem *el, const char *at, const char *what)
{
	const struct attr *id = attr_of(el, "id");
	char nm[41], q[41];

	loft__cadin_quote(nm, sizeof nm, el->name, el->nn);
	if (id != NULL)
		loft__cadin_say(s->c, line_at(el, at), "%s id=%s: %s", nm,
		    loft__cadin_quote(q, sizeof q, id->v, id->vn), what);
	else
		loft__cadin_say(s->c, line_at(el, at), "%s: %s", nm, what);
}

/* A number attribute (with no unit): 0, 1 when absent, -1 when bad. */
static int
num_attr(struct svg *s, const struct elem *el, const char *key, double *x)
{
	const struct attr *a = attr_of(el, key);
	const char *p;
	char msg[80];

	*x = 0;
	if (a == NULL)
		return 1;
	p = a->v;
	if (svg_num(&p, a->v + a->vn, x) != 0 || skip_sep(p, a->v + a->vn) !=
	    a->v + a->vn) {
		snprintf(msg, sizeof msg, "%s is not a number", key);
		say_el(s, el, a->v, msg);
		return -1;
	}
	return 0;
}

/* An attribute that is one number and nothing else, or 0. */
static double
plain_num(const struct attr *a)
{
	const char *p;
	double x;

	if (a == NULL)
		return 0;
	p = a->v;
	if (svg_num(&p, a->v + a->vn, &x) != 0 || skip_sep(p, a->v + a->vn) !=
	    a->v + a->vn)
		return 0;
	return x;
}

/* A length of the root svg in millimetres, or 0 when absent or in a
 * unit relative to something unknown (%, em, ex). */
static double
length_mm(const struct attr *a)
{
	static const struct { const char *u; double mm; } units[] = {
		{ "", 25.4 / 96 }, { "px", 25.4 / 96 }, { "mm", 1 },
		{ "cm", 10 }, { "in", 25.4 }, { "pt", 25.4 / 72 },
		{ "pc", 25.4 / 6 }, { "q", 0.25 },
	};
	const char *p;
	double x;
	size_t un;

	if (a == NULL)
		return 0;
	p = a->v;
	if (svg_num(&p, a->v + a->vn, &x) != 0 || !(x > 0))
		return 0;
	un = (size_t)(a->v + a->vn - p);
	while (un > 0 && is_wsp((unsigned char)p[un - 1]))
		un--;
	for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
		if (loft__word_is(p, un, units[i].u))
			return x * units[i].mm;
	return 0;
}

/*
 * Parse a transform list into m (which starts as the identity).
 * Returns 0, or -1 after complaining.
 */
static int
transform(struct svg *s, const struct elem *el, double *m)
{
	static const char *const fn[] = { "matrix", "translate", "scale",
	    "rotate", "skewX", "skewY" };
	const struct attr *a = attr_of(el, "transform");
	const char *p, *e;

	m[0] = m[3] = 1;
	m[1] = m[2] = m[4] = m[5] = 0;
	if (a == NULL)
		return 0;
	p = a->v;
	e = a->v + a->vn;
	for (;;) {
		double v[6], t[6] = { 1, 0, 0, 1, 0, 0 }, r;
		int f, n = 0;
		size_t k;

		p = skip_sep(p, e);
		if (p == e)
			return 0;
		for (f = 0; f < 6; f++) {
			k = strlen(fn[f]);
			if ((size_t)(e - p) > k && memcmp(p, fn[f], k) == 0)
				break;
		}
		if (f == 6)
			goto bad;
		for (p += k; p < e && is_wsp((unsigned char)*p); p++)
			;
		if (p == e || *p++ != '(')
			goto bad;
		while (n < 6 && svg_num(&p, e, &v[n]) == 0)
			n++;
		for (; p < e && is_wsp((unsigned char)*p); p++)
			;
		if (p == e || *p++ != ')')
			goto bad;
		switch (f) {
		case 0:
			if (n != 6)
				goto bad;
			memcpy(t, v, sizeof t);
			break;
		case 1:
			if (n != 1 && n != 2)
				goto bad;
			t[4] = v[0];
			t[5] = n == 2 ? v[1] : 0;
			break;
		case 2:
			if (n != 1 && n != 2)
				goto bad;
			t[0] = v[0];
			t[3] = n == 2 ? v[1] : v[0];
			break;
		case 3:
			if (n != 1 && n != 3)
				goto bad;
			r = v[0] * M_PI / 180;
			t[0] = t[3] = cos(r);
			t[1] = sin(r);
			t[2] = -t[1];
			if (n == 3) {   /* about (cx, cy) */
				t[4] = v[1] - t[0] * v[1] - t[2] * v[2];
				t[5] = v[2] - t[1] * v[1] - t[3] * v[2];
			}
			break;
		case 4:
		case 5:
			if (n != 1)
				goto bad;
			t[f == 4 ? 2 : 1] = tan(v[0] * M_PI / 180);
			break;
		}
		mat_mul(m, t, m);
	}
bad:
	say_el(s, el, p, "bad transform: not read");
	return -1;
}

/* ---- records ---------------------------------------------------------- */

/* The header of a record of element el: type, closed=, layer=, name=,
 * corners= when given, and for the nseg segments seg (user space) of a
 * cubic record, straight= (its lines that a curve meets smoothly: a
 * tangent's direction is kept by the user space's affine map). */
static void
put_header(struct svg *s, const struct elem *el, const char *type, int closed,
    const char *corners, const double *seg, size_t nseg)
{
	struct loft_writer *w = s->c->w;
	const struct level *lv = &s->st[s->depth - 1];
	const struct attr *id = attr_of(el, "id");

	loft_put_type(w, type);
	loft_put_attr(w, "closed", closed ? "1" : "0");
	loft__cadin_put_name(w, "layer", lv->layer, lv->nlayer);
	if (id != NULL)
		loft__cadin_put_name(w, "name", id->v, id->vn);
	if (corners != NULL)
		loft_put_attr(w, "corners", corners);
	if (seg != NULL)
		loft__cadin_put_straight(w, seg, nseg, 2, closed);
	loft_end_line(w);
}

static int
seg_add(struct svg *s, const double *v, int n)
{
	struct nums *g = &s->seg;

	if (loft__grow((void **)&g->v, &g->cap, g->n + (size_t)n,
	    sizeof *g->v) != 0) {
		s->oom = 1;
		return -1;
	}
	memcpy(g->v + g->n, v, (size_t)n * sizeof *v);
	g->n += (size_t)n;
	return 0;
}

/* A segment as Manning's row P_A P_B P'_A P'_B, user space. */
static int
seg_row(struct svg *s, const double *a, const double *b, const double *ta,
    const double *tb)
{
	double v[8] = { a[0], a[1], b[0], b[1], ta[0], ta[1], tb[0], tb[1] };

	return seg_add(s, v, 8);
}

/* A cubic Bezier's control points q[0..8) as a segment. */
static int
seg_bezier(struct svg *s, const double *q)
{
	double row[8];

	loft__bezier_hermite(q, 2, row);
	return seg_add(s, row, 8);
}

/*
 * The subpath in s->seg (rows of 8 numbers in user space) as a record: a
 * knot record when every segment is straight (straight != 0), else a
 * cubic record.  Points go through m, tangents through its linear part.
 */
static void
put_subpath(struct svg *s, const struct elem *el, const double *m, int closed,
    int straight)
{
	struct loft_writer *w = s->c->w;
	size_t n = s->seg.n / 8, mark = w->len;
	const double *g = s->seg.v;
	double row[8];

	if (n == 0)
		return;
	put_header(s, el, straight ? "points" : "cubic", closed, NULL,
	    straight ? NULL : g, n);
	for (size_t i = 0; i < n; i++) {
		const double *r = g + 8 * i;

		mat_apply(m, r, row);
		mat_apply(m, r + 2, row + 2);
		for (int k = 4; k < 8; k += 2) {
			row[k] = m[0] * r[k] + m[2] * r[k + 1];
			row[k + 1] = m[1] * r[k] + m[3] * r[k + 1];
		}
		if (straight) {
			loft_put_row(w, row, 2);
			if (i + 1 == n && !closed)
				loft_put_row(w, row + 2, 2);
		} else {
			loft_put_row(w, row, 8);
		}
	}
	loft_end_record(w);
	loft__cadin_done(s->c, mark, el->line);
}

/* A straight segment from a to b: both tangents b - a. */
static int
line_to(struct svg *s, const double *a, const double *b)
{
	double t[2] = { b[0] - a[0], b[1] - a[1] };

	return seg_row(s, a, b, t, t);
}

/*
 * The elliptic arc of centre c, radii rx, ry, x axis turned by phi, from
 * angle t0 through dt (radians, on the unit circle before the ellipse's
 * stretch), as n cubic pieces: on the unit circle each piece from t to
 * t + h has its inner control points (4/3) tan(h/4) along the end
 * tangents (the error of loft__arc_cubics).
 */
static int
arc_cubics(struct svg *s, const double *c, double rx, double ry, double phi,
    double t0, double dt, long n)
{
	double h = dt / (double)n;
	double cp = cos(phi), sp = sin(phi);

	for (long i = 0; i < n; i++) {
		double a = t0 + h * (double)i, e = i + 1 == n ? t0 + dt : a + h;
		double u[8], v[8];

		loft__arc_unit(a, h, e, u);

		for (int j = 0; j < 4; j++) {
			double x = rx * u[2 * j], y = ry * u[2 * j + 1];

			v[2 * j] = c[0] + cp * x - sp * y;
			v[2 * j + 1] = c[1] + sp * x + cp * y;
		}
		if (seg_bezier(s, v) != 0)
			return -1;
	}
	return 0;
}

/* The number of cubic pieces for an arc of radii rx, ry under m. */
static long
arc_pieces(struct svg *s, const double *m, double rx, double ry, double dt)
{
	return loft__arc_cubics(s->c, fmax(rx, ry) * mat_stretch(m), dt);
}

/*
 * SVG's arc from a to b (the implementation notes' endpoint to centre
 * conversion, radii scaled up where too small for the ends).  Returns 0,
 * -1 when out of memory, -2 when it needs too many pieces.
 */
static int
arc_to(struct svg *s, const double *m, const double *a, double rx, double ry,
    double rot, int large, int sweep, const double *b)
{
	double phi = rot * M_PI / 180, cp = cos(phi), sp = sin(phi);
	double dx = (a[0] - b[0]) / 2, dy = (a[1] - b[1]) / 2;
	double x1 = cp * dx + sp * dy, y1 = -sp * dx + cp * dy;
	double lam, num, den, co, cx, cy, c[2], t0, t1, dt;
	long n;

	rx = fabs(rx);
	ry = fabs(ry);
	if (a[0] == b[0] && a[1] == b[1])
		return 0;
	if (rx == 0 || ry == 0)
		return line_to(s, a, b);
	lam = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
	if (lam > 1) {
		rx *= sqrt(lam);
		ry *= sqrt(lam);
	}
	num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
	den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
	co = den > 0 && num > 0 ? sqrt(num / den) : 0;
	if (large == sweep)
		co = -co;
	cx = co * rx * y1 / ry;
	cy = -co * ry * x1 / rx;
	c[0] = cp * cx - sp * cy + (a[0] + b[0]) / 2;
	c[1] = sp * cx + cp * cy + (a[1] + b[1]) / 2;
	t0 = atan2((y1 - cy) / ry, (x1 - cx) / rx);
	t1 = atan2((-y1 - cy) / ry, (-x1 - cx) / rx);
	dt = t1 - t0;
	if (sweep && dt < 0)
		dt += 2 * M_PI;
	else if (!sweep && dt > 0)
		dt -= 2 * M_PI;
	if (!isfinite(dt) || !isfinite(c[0]) || !isfinite(c[1]))
		return line_to(s, a, b);
	if ((n = arc_pieces(s, m, rx, ry, dt)) < 0)
		return -2;
	if (arc_cubics(s, c, rx, ry, phi, t0, dt, n) != 0)
		return -1;
	/* the arc's ends exactly where the path is */
	s->seg.v[s->seg.n - 8 * (size_t)n] = a[0];
	s->seg.v[s->seg.n - 8 * (size_t)n + 1] = a[1];
	s->seg.v[s->seg.n - 6] = b[0];
	s->seg.v[s->seg.n - 5] = b[1];
	return 0;
}

/* S's and T's first control point: the last control point of the
 * segment before reflected about the current point, if that segment
 * was of the same kind (after), else the current point. */
static void
reflect(int after, const double *cur, const double *ctl, double *q)
{
	q[0] = after ? 2 * cur[0] - ctl[0] : cur[0];
	q[1] = after ? 2 * cur[1] - ctl[1] : cur[1];
}

/* After a curved segment: its last control point c (for S or T), its
 * end e the current point, and the subpath no longer straight. */
static void
curve_end(double *ctl, const double *c, double *cur, const double *e,
    int *straight)
{
	ctl[0] = c[0];
	ctl[1] = c[1];
	cur[0] = e[0];
	cur[1] = e[1];
	*straight = 0;
}

/* A path being read: the current point, the subpath's start, the last
 * control point (for S and T), the command before, whether the subpath
 * is straight so far. */
struct pen {
	double cur[2], start[2], ctl[2];
	int prev, straight;
};

/*
 * Two points of path data this near (relative to their size) are one:
 * a path whose relative commands come back to its start, or ends on it
 * in rounded decimals, ends there, not a rounding's length off it (a
 * closing side of 1e-15 would be a knot on top of another).
 */
#define PATH_SAME 1e-12

static int
same_point(const double *a, const double *b)
{
	double d = fmax(fabs(a[0] - b[0]), fabs(a[1] - b[1]));

	return d <= PATH_SAME * fmax(fmax(fabs(a[0]), fabs(a[1])),
	    fmax(fabs(b[0]), fabs(b[1])));
}

/* Z: the closing side where the path is not back at its start (its
 * last point put exactly on the start where it nearly is), the subpath
 * written; 0, or -1 when out of memory. */
static int
close_subpath(struct svg *s, const struct elem *el, const double *m,
    struct pen *pn)
{
	if (s->seg.n > 0 && same_point(pn->cur, pn->start)) {
		s->seg.v[s->seg.n - 6] = pn->start[0];
		s->seg.v[s->seg.n - 5] = pn->start[1];
	} else if (s->seg.n > 0 && line_to(s, pn->cur, pn->start) != 0)
		return -1;
	put_subpath(s, el, m, 1, pn->straight);
	s->seg.n = 0;
	pn->straight = 1;
	pn->cur[0] = pn->start[0];
	pn->cur[1] = pn->start[1];
	pn->prev = 'Z';
	return 0;
}

/* Q and T, v their numbers (absolute): exactly the cubic with P'_A = 2
 * (control - start), P'_B = 2 (end - control). */
static int
quad_to(struct svg *s, struct pen *pn, int up, const double *v, int n)
{
	double qc[2], q[8];

	if (up == 'Q') {
		qc[0] = v[0];
		qc[1] = v[1];
	} else {
		reflect(pn->prev == 'Q' || pn->prev == 'T', pn->cur, pn->ctl,
		    qc);
	}
	q[0] = pn->cur[0];
	q[1] = pn->cur[1];
	q[2] = v[n - 2];
	q[3] = v[n - 1];
	for (int k = 0; k < 2; k++) {
		q[4 + k] = 2 * (qc[k] - q[k]);
		q[6 + k] = 2 * (q[2 + k] - qc[k]);
	}
	if (seg_row(s, q, q + 2, q + 4, q + 6) != 0)
		return -1;
	curve_end(pn->ctl, qc, pn->cur, q + 2, &pn->straight);
	return 0;
}

/* One segment of command up (not M or Z) with its numbers v (absolute);
 * 0, -1 when out of memory, -2 when an arc needs too many pieces. */
static int
segment(struct svg *s, const double *m, struct pen *pn, int up,
    const double *v, int n, int f1, int f2)
{
	double q[8];
	int rc;

	switch (up) {
	case 'L':
	case 'H':
	case 'V':
		q[0] = up == 'V' ? pn->cur[0] : v[0];
		q[1] = up == 'H' ? pn->cur[1] : up == 'V' ? v[0] : v[1];
		if (line_to(s, pn->cur, q) != 0)
			return -1;
		pn->cur[0] = q[0];
		pn->cur[1] = q[1];
		return 0;
	case 'C':
	case 'S':
		q[0] = pn->cur[0];
		q[1] = pn->cur[1];
		if (up == 'C')
			memcpy(q + 2, v, 6 * sizeof *v);
		else {          /* the reflection of the last control */
			reflect(pn->prev == 'C' || pn->prev == 'S', pn->cur,
			    pn->ctl, q + 2);
			memcpy(q + 4, v, 4 * sizeof *v);
		}
		if (seg_bezier(s, q) != 0)
			return -1;
		curve_end(pn->ctl, q + 4, pn->cur, q + 6, &pn->straight);
		return 0;
	case 'Q':
	case 'T':
		return quad_to(s, pn, up, v, n);
	default:                /* A */
		q[0] = v[5];
		q[1] = v[6];
		if ((rc = arc_to(s, m, pn->cur, v[0], v[1], v[2], f1, f2, q)) !=
		    0)
			return rc;
		pn->cur[0] = q[0];
		pn->cur[1] = q[1];
		pn->straight = 0;
		return 0;
	}
}

/* The numbers of command up at *p into v (arc flags as 0 and 1 in f1,
 * f2), made absolute from the current point where rel; the count, or
 * -1 when they are not there. */
static int
path_numbers(const char **p, const char *e, int up, int rel,
    const double *cur, double *v, int *f1, int *f2)
{
	int n = up == 'M' || up == 'L' || up == 'T' ? 2 : up == 'H' ||
	    up == 'V' ? 1 : up == 'C' ? 6 : up == 'A' ? 7 : 4;

	for (int k = 0; k < n; k++) {
		if (up == 'A' && (k == 3 || k == 4)) {
			if (svg_flag(p, e, k == 3 ? f1 : f2) != 0)
				return -1;
			v[k] = 0;
		} else if (svg_num(p, e, &v[k]) != 0) {
			return -1;
		}
	}
	if (up == 'H')
		v[0] += rel ? cur[0] : 0;
	else if (up == 'V')
		v[0] += rel ? cur[1] : 0;
	else if (rel)
		for (int k = up == 'A' ? 5 : 0; k < n; k += 2) {
			v[k] += cur[0];
			v[k + 1] += cur[1];
		}
	return n;
}

/* Say what is wrong at p in path data ending at e, and then what
 * became of the path (tail). */
static void
path_bad(struct svg *s, const struct elem *el, const char *why,
    const char *p, const char *e, const char *tail)
{
	char msg[200], q[13];

	p = skip_sep(p, e);
	snprintf(msg, sizeof msg, "%s at '%s': %s", why,
	    loft__cadin_quote(q, sizeof q, p, (size_t)(e - p)), tail);
	say_el(s, el, p, msg);
}

/* Path data: every subpath a record.  On an error in the data the path
 * is drawn up to the command in error, as SVG renders it (SVG 1.1 F.2,
 * SVG 2 9.5.4), and the error said; an arc of too many pieces leaves
 * the element not read at all. */
static void
do_path(struct svg *s, const struct elem *el, const double *m)
{
	const struct attr *d = attr_of(el, "d");
	struct loft_writer *w = s->c->w;
	size_t mark = w->len;
	const char *p, *e, *why = "bad path data";
	struct pen pn = { { 0, 0 }, { 0, 0 }, { 0, 0 }, 0, 1 };
	const char *at = NULL;  /* the command in error */
	int cmd = 0, rc = 0;
	long nbad = s->c->nbad;

	if (d == NULL)
		return;         /* no path: nothing drawn */
	p = d->v;
	e = d->v + d->vn;
	s->seg.n = 0;
	while ((p = skip_sep(p, e)) != e && rc == 0) {
		double v[7];
		int n, up, f1 = 0, f2 = 0;

		at = p;
		if (strchr("MmLlHhVvCcSsQqTtAaZz", *p) != NULL && *p != '\0')
			cmd = (unsigned char)*p++;
		else if (cmd == 0 || cmd == 'Z' || cmd == 'z')
			break;          /* numbers where a command must be */
		up = cmd & ~0x20;
		if (pn.prev == 0 && up != 'M') {
			why = "path data must start with a moveto (M or m)";
			break;
		}
		if (up == 'Z') {
			rc = close_subpath(s, el, m, &pn);
			at = NULL;
			continue;
		}
		if ((n = path_numbers(&p, e, up, cmd >= 'a', pn.cur, v, &f1,
		    &f2)) < 0) {
			if (skip_sep(p, e) != e)
				at = p; /* point at the number in error */
			break;
		}
		at = NULL;
		if (up == 'M') {
			put_subpath(s, el, m, 0, pn.straight);
			s->seg.n = 0;
			pn.straight = 1;
			pn.start[0] = pn.cur[0] = v[0];
			pn.start[1] = pn.cur[1] = v[1];
			cmd = cmd == 'm' ? 'l' : 'L';   /* further pairs */
			pn.prev = 'M';
			continue;
		}
		rc = segment(s, m, &pn, up, v, n, f1, f2);
		pn.prev = up;
	}
	if (rc == -1 || s->oom) {
		loft_writer_cut(w, mark);
		s->oom = 1;
		return;
	}
	if (rc == -2) {
		loft_writer_cut(w, mark);
		w->col = 0;
		path_bad(s, el, "an arc needs more cubic pieces than the "
		    "tolerance allows", p, e, "not read");
		return;
	}
	put_subpath(s, el, m, 0, pn.straight);
	if (s->c->nbad > nbad)
		loft_writer_cut(w, mark);  /* a record of it failed: none of it */
	else if (at != NULL)
		path_bad(s, el, why, at, e, w->len > mark ? "drawn up to there, "
		    "as SVG renders it" : "not read");
}

/* polyline and polygon: their points as a knot record. */
static void
do_poly(struct svg *s, const struct elem *el, const double *m, int closed)
{
	const struct attr *a = attr_of(el, "points");
	const char *p, *e;
	double v[2];

	s->seg.n = 0;
	if (a == NULL)
		return;
	p = a->v;
	e = a->v + a->vn;
	for (;;) {
		double x[2];

		if (skip_sep(p, e) == e)
			break;
		if (svg_num(&p, e, &x[0]) != 0 || svg_num(&p, e, &x[1]) != 0) {
			say_el(s, el, p, "points: want pairs of numbers: not "
			    "read");
			return;
		}
		if (s->seg.n > 0 && line_to(s, v, x) != 0)
			return;
		if (s->seg.n == 0 && seg_add(s, x, 2) != 0)
			return;
		v[0] = x[0];
		v[1] = x[1];
	}
	if (s->seg.n == 0)
		return;         /* no points: nothing drawn */
	if (s->seg.n == 2) {    /* one point: a knot record of one knot */
		size_t mark = s->c->w->len;
		double y[2];

		mat_apply(m, s->seg.v, y);
		put_header(s, el, "points", 0, NULL, NULL, 0);
		loft_put_row(s->c->w, y, 2);
		loft_end_record(s->c->w);
		loft__cadin_done(s->c, mark, el->line);
		return;
	}
	/* the first point alone, then a segment per further point */
	memmove(s->seg.v, s->seg.v + 2, (s->seg.n - 2) * sizeof *s->seg.v);
	s->seg.n -= 2;
	/* the closing side, unless the last point repeats the first */
	if (closed && (s->seg.v[s->seg.n - 6] != s->seg.v[0] ||
	    s->seg.v[s->seg.n - 5] != s->seg.v[1]) && line_to(s, s->seg.v + 
	    s->seg.n - 6, s->seg.v) != 0)
		return;
	put_subpath(s, el, m, closed, 1);
}

static void
do_line(struct svg *s, const struct elem *el, const double *m)
{
	double a[2], b[2];

	if (num_attr(s, el, "x1", &a[0]) < 0 || num_attr(s, el, "y1", &a[1]) <
	    0 || num_attr(s, el, "x2", &b[0]) < 0 ||
	    num_attr(s, el, "y2", &b[1]) < 0)
		return;
	s->seg.n = 0;
	if (line_to(s, a, b) == 0)
		put_subpath(s, el, m, 0, 1);
}

/* A rect with rounded corners: a closed cubic record, its sides
 * straight segments and its corners quarter ellipses of radii rx, ry
 * (cubic pieces within the tolerance), clockwise in user space from
 * (x + rx, y), as SVG draws it. */
static void
round_rect(struct svg *s, const struct elem *el, const double *m, double x,
    double y, double wd, double ht, double rx, double ry)
{
	/* the ends of the straight sides, equal where a radius is half
	 * the side (not a rounding apart); the corners' centres */
	double xl = x + rx, xr = 2 * rx == wd ? xl : x + wd - rx;
	double yt = y + ry, yb = 2 * ry == ht ? yt : y + ht - ry;
	double c[4][2] = { { xr, yt }, { xr, yb }, { xl, yb }, { xl, yt } };
	double se[4][4] = {     /* each corner's start and end */
		{ xr, y, x + wd, yt }, { x + wd, yb, xr, y + ht },
		{ xl, y + ht, x, yb }, { x, yt, xl, y } };
	long n = arc_pieces(s, m, rx, ry, M_PI / 2);

	if (n < 0) {
		say_el(s, el, el->at, "its corners need more cubic pieces than "
		    "the tolerance allows");
		return;
	}
	s->seg.n = 0;
	for (int k = 0; k < 4; k++) {   /* a side, then a corner */
		const double *a = se[(k + 3) % 4] + 2, *b = se[k];
		size_t first;

		if ((a[0] != b[0] || a[1] != b[1]) && line_to(s, a, b) != 0)
			return;
		first = s->seg.n;
		if (arc_cubics(s, c[k], rx, ry, 0, -M_PI / 2 + k * M_PI / 2,
		    M_PI / 2, n) != 0)
			return;
		s->seg.v[first] = b[0];         /* the corner's ends exactly */
		s->seg.v[first + 1] = b[1];
		s->seg.v[s->seg.n - 6] = se[k][2];
		s->seg.v[s->seg.n - 5] = se[k][3];
	}
	put_subpath(s, el, m, 1, 0);
}

/* rect: a closed knot record of its corners, or with rx or ry a cubic
 * record of its sides and rounded corners (SVG's rules: one radius
 * given is both; each at most half the side). */
static void
do_rect(struct svg *s, const struct elem *el, const double *m)
{
	double x, y, wd, ht, rx, ry, p[8];
	int hx, hy;

	if (num_attr(s, el, "x", &x) < 0 || num_attr(s, el, "y", &y) < 0 ||
	    num_attr(s, el, "width", &wd) < 0 ||
	    num_attr(s, el, "height", &ht) < 0 ||
	    (hx = num_attr(s, el, "rx", &rx)) < 0 ||
	    (hy = num_attr(s, el, "ry", &ry)) < 0)
		return;
	if (!(wd > 0) || !(ht > 0))
		return;         /* not drawn */
	if (hx != 0 || !(rx >= 0))
		rx = hy == 0 && ry > 0 ? ry : 0;
	if (hy != 0 || !(ry >= 0))
		ry = rx;
	rx = fmin(rx, wd / 2);
	ry = fmin(ry, ht / 2);
	if (rx > 0 && ry > 0) {
		round_rect(s, el, m, x, y, wd, ht, rx, ry);
		return;
	}
	p[0] = x;
	p[1] = y;
	p[2] = x + wd;
	p[3] = y;
	p[4] = x + wd;
	p[5] = y + ht;
	p[6] = x;
	p[7] = y + ht;
	{
		struct loft_writer *w = s->c->w;
		size_t mark = w->len;
		double q[2];

		put_header(s, el, "points", 1, "1,2,3,4", NULL, 0);
		for (int k = 0; k < 4; k++) {
			mat_apply(m, p + 2 * k, q);
			loft_put_row(w, q, 2);
		}
		loft_end_record(w);
		loft__cadin_done(s->c, mark, el->line);
	}
}

/* circle and ellipse: a closed cubic record within the tolerance. */
static void
do_ellipse(struct svg *s, const struct elem *el, const double *m, int circle)
{
	double c[2], rx, ry;
	long n;
	int hx, hy;

	if (num_attr(s, el, "cx", &c[0]) < 0 || num_attr(s, el, "cy", &c[1]) <
	    0)
		return;
	if (circle ? num_attr(s, el, "r", &rx) < 0 :
	    (hx = num_attr(s, el, "rx", &rx)) < 0 ||
	    (hy = num_attr(s, el, "ry", &ry)) < 0)
		return;
	if (circle)
		ry = rx;
	else if (hx == 1 && hy == 1) {  /* r, as Inkscape writes some */
		if (num_attr(s, el, "r", &rx) < 0)
			return;
		ry = rx;
	} else if (hx == 1 || hy == 1)  /* SVG 2's auto: the other one */
		*(hx == 1 ? &rx : &ry) = hx == 1 ? ry : rx;
	if (!(rx > 0) || !(ry > 0))
		return;         /* not drawn */
	if ((n = arc_pieces(s, m, rx, ry, 2 * M_PI)) < 0) {
		say_el(s, el, el->at, "needs more cubic pieces than the "
		    "tolerance allows");
		return;
	}
	s->seg.n = 0;
	if (arc_cubics(s, c, rx, ry, 0, 0, 2 * M_PI, n) != 0)
		return;
	s->seg.v[s->seg.n - 6] = s->seg.v[0];   /* closed exactly */
	s->seg.v[s->seg.n - 5] = s->seg.v[1];
	put_subpath(s, el, m, 1, 0);
}

/* The root svg's map from user space to millimetres, y turned up. */
static void
root_map(struct svg *s, const struct elem *el, double *m)
{
	const struct attr *vb = attr_of(el, "viewBox");
	const struct attr *par = attr_of(el, "preserveAspectRatio");
	double wmm = length_mm(attr_of(el, "width"));
	double hmm = length_mm(attr_of(el, "height"));
	double v[4], sx = 25.4 / 96, sy = sx;
	const char *p;
	int n = 0;

	if (vb != NULL) {
		p = vb->v;
		while (n < 4 && svg_num(&p, vb->v + vb->vn, &v[n]) == 0)
			n++;
		if (n != 4 || !(v[2] > 0) || !(v[3] > 0)) {
			say_el(s, el, vb->v, "viewBox is not four numbers with "
			    "width and height above 0: user units taken as "
			    "px");
			n = 0;
		}
	}
	if (n == 4 && (wmm > 0 || hmm > 0)) {
		sx = wmm > 0 ? wmm / v[2] : hmm / v[3];
		sy = hmm > 0 ? hmm / v[3] : sx;
		if (par == NULL || par->vn < 4 || memcmp(par->v, "none", 4)
		    != 0) {
			int slice = par != NULL && find(par->v, par->vn,
			    "slice", 5) != NULL;

			sx = sy = slice ? fmax(sx, sy) : fmin(sx, sy);
		}
	}
	m[0] = sx;
	m[3] = -sy;
	m[1] = m[2] = m[4] = m[5] = 0;
}

/* ---- the document ---------------------------------------------------- */

static int
is_name_char(int ch)
{
	return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
	    is_digit(ch) || ch == ':' || ch == '-' || ch == '_' || ch == '.' ||
	    ch >= 0x80;
}

/* Move past the text up to and with the string t; -1 when absent. */
static int
skip_past(struct svg *s, const char *t)
{
	size_t n = strlen(t);
	const char *q = find(s->p, (size_t)(s->end - s->p), t, n);

	if (q == NULL)
		return -1;
	for (; s->p < q + n; s->p++)
		s->line += *s->p == '\n';
	return 0;
}

/* Parse a start tag at s->p (past '<') into el; 1 for a tag that
 * closes itself, 0 for one that opens, -1 when malformed. */
static int
start_tag(struct svg *s, struct elem *el)
{
	const char *p = s->p, *e = s->end;
	int r = -1;

	el->name = p;
	while (p < e && is_name_char((unsigned char)*p))
		p++;
	el->nn = (size_t)(p - el->name);
	el->na = 0;
	if (el->nn == 0)
		goto out;
	for (;;) {
		struct attr *a;
		char q;

		while (p < e && is_wsp((unsigned char)*p))
			s->line += *p++ == '\n';
		if (p == e)
			goto out;
		if (*p == '>' || (*p == '/' && p + 1 < e && p[1] == '>')) {
			r = *p == '/';
			p += 1 + r;
			goto out;
		}
		a = el->na < MAX_ATTRS ? &el->a[el->na++] : &el->a[MAX_ATTRS -
		    1];
		a->k = p;
		while (p < e && is_name_char((unsigned char)*p))
			p++;
		a->kn = (size_t)(p - a->k);
		while (p < e && is_wsp((unsigned char)*p))
			s->line += *p++ == '\n';
		if (a->kn == 0 || p == e || *p++ != '=')
			goto out;
		while (p < e && is_wsp((unsigned char)*p))
			s->line += *p++ == '\n';
		if (p == e || (*p != '"' && *p != '\''))
			goto out;
		q = *p++;
		a->v = p;
		while (p < e && *p != q)
			s->line += *p++ == '\n';
		if (p == e)
			goto out;
		a->vn = (size_t)(p++ - a->v);
	}
out:
	s->p = p;
	return r;
}

static void open_pop(struct svg *);

/* ---- use: another element drawn again ------------------------------- */

/* Uses inside what a use draws, at most: real documents nest a few, and
 * an element that uses itself stops here. */
#define USE_DEPTH 16

/* Elements drawn by uses, at most, per document: uses of groups of uses
 * multiply, and a few hostile lines would otherwise ask for 10^20
 * records.  Four million is far above any real drawing. */
#define USE_BUDGET 4000000L

static int
id_cmp(const void *a, const void *b)
{
	const struct idref *p = a, *q = b;
	int c;

	if (p->n != q->n)
		return p->n < q->n ? -1 : 1;
	if ((c = memcmp(p->s, q->s, p->n)) != 0)
		return c;
	return p->at < q->at ? -1 : p->at > q->at;
}

/* The index of every id="..." in the document, by value: the tag it is
 * in (the '<' before it) and that tag's line; one pass, sorted. */
static int
id_index(struct svg *s)
{
	const char *lt = NULL;
	long line = 1, ltline = 1;

	s->indexed = 1;
	for (const char *p = s->buf; p + 4 < s->end; p++) {
		const char *v, *q;

		if (*p == '\n')
			line++;
		else if (*p == '<') {
			lt = p;
			ltline = line;
		}
		if (p[0] != 'i' || p[1] != 'd' || p[2] != '=' || (p[3] != '"' &&
		    p[3] != '\'') || p == s->buf || !is_wsp((unsigned char)p[-1]) ||
		    lt == NULL)
			continue;
		v = p + 4;
		if ((q = memchr(v, p[3], (size_t)(s->end - v))) == NULL)
			break;
		if (loft__grow((void **)&s->ids, &s->idcap, s->nids + 1,
		    sizeof *s->ids) != 0) {
			s->oom = 1;
			return -1;
		}
		s->ids[s->nids].s = v;
		s->ids[s->nids].n = (size_t)(q - v);
		s->ids[s->nids].at = lt;
		s->ids[s->nids].line = ltline;
		s->nids++;
	}
	qsort(s->ids, s->nids, sizeof *s->ids, id_cmp);
	return 0;
}

/* The first element of id v[0..n); NULL when there is none. */
static const struct idref *
id_find(struct svg *s, const char *v, size_t n)
{
	size_t lo = 0, hi;

	if (!s->indexed && id_index(s) != 0)
		return NULL;
	hi = s->nids;
	while (lo < hi) {               /* the first not below v */
		size_t m = (lo + hi) / 2;
		const struct idref *r = &s->ids[m];

		if (r->n < n || (r->n == n && memcmp(r->s, v, n) < 0))
			lo = m + 1;
		else
			hi = m;
	}
	if (lo < s->nids && s->ids[lo].n == n && memcmp(s->ids[lo].s, v, n) ==
	    0)
		return &s->ids[lo];
	return NULL;
}

static void parse(struct svg *s, int sub);

/*
 * use: the element its href names ("#id", in this document) drawn
 * again, translated by x and y under the use's transform; a symbol is
 * drawn as a group there.  It keeps its own id as name= and the use's
 * layer.
 */
static void
do_use(struct svg *s, const struct elem *el, const double *m)
{
	const struct attr *h = attr_of(el, "href");
	const struct idref *r;
	const char *p = s->p;
	long line = s->line;
	size_t base = s->base;
	int depth = s->depth;
	double x, y, t[6] = { 1, 0, 0, 1, 0, 0 };
	struct level lv;

	if (h == NULL)
		h = attr_of(el, "xlink:href");
	if (h == NULL || num_attr(s, el, "x", &x) < 0 ||
	    num_attr(s, el, "y", &y) < 0)
		return;         /* nothing to draw, or said */
	if (h->vn < 2 || h->v[0] != '#') {
		say_el(s, el, h->v, "a use of another document: not "
		    "read");
		return;
	}
	if (s->nuse >= USE_DEPTH) {     /* said once a document */
		if (!s->said_deep++)
			say_el(s, el, el->at, "uses nested deeper than 16 "
			    "(does it use itself?): not read");
		return;
	}
	if (s->budget-- <= 0) {
		if (s->budget == -1)
			say_el(s, el, el->at, "uses draw more than 4,000,000 "
			    "elements: the rest is not read");
		return;
	}
	if ((r = id_find(s, h->v + 1, h->vn - 1)) == NULL) {
		if (!s->oom)
			say_el(s, el, h->v, "no element of that id: not read");
		return;
	}
	/* a symbol's box; none (its own units) where they are absent or
	 * relative, as width="100%" */
	s->use_w = plain_num(attr_of(el, "width"));
	s->use_h = plain_num(attr_of(el, "height"));
	lv = s->st[s->depth - 1];
	t[4] = x;
	t[5] = y;
	mat_mul(m, t, lv.m);
	s->st[s->depth++] = lv;
	s->p = r->at;
	s->line = r->line;
	s->base = s->nopen;
	s->nuse++;
	s->target = 1;
	parse(s, 1);
	s->target = 0;
	while (s->nopen > s->base)
		open_pop(s);
	s->nuse--;
	s->depth = depth;
	s->base = base;
	s->p = p;
	s->line = line;
}

/* Elements that draw nothing themselves, passed over with what is in
 * them (a symbol is drawn only by a use); and those that draw what loft
 * cannot hold: annotations, passed over and counted (-S: refused). */
static const char *const quiet[] = { "defs", "title", "desc", "metadata",
	"style", "script", "symbol", "clipPath", "mask", "marker", "pattern",
	"linearGradient", "radialGradient", "filter", NULL };
static const char *const annotation[] = { "text", "image",
	"foreignObject", "video", "audio", "canvas", "iframe", NULL };

static int
in_list(const struct elem *el, const char *const *list)
{
	for (; *list != NULL; list++)
		if (name_is(el, *list))
			return 1;
	return 0;
}

/*
 * A presentation property of el: from its style attribute (which wins)
 * or the attribute of that name; 1 when it is value, else 0.
 */
static int
prop_is(const struct elem *el, const char *prop, const char *value)
{
	const struct attr *st = attr_of(el, "style"), *a = attr_of(el, prop);
	size_t n = strlen(prop);
	const char *v = a ? a->v : NULL, *e;
	size_t vn = a ? a->vn : 0;

	for (const char *p = st ? st->v : NULL, *end = st ? st->v + st->vn :
	    NULL; p != NULL && p < end; p++) {
		const char *q = p;

		while (q < end && is_wsp((unsigned char)*q))
			q++;
		if ((size_t)(end - q) > n && memcmp(q, prop, n) == 0) {
			for (q += n; q < end && is_wsp((unsigned char)*q); q++)
				;
			if (q < end && *q == ':') {
				for (q++; q < end && is_wsp((unsigned char)*q);
				    q++)
					;
				for (e = q; e < end && *e != ';'; e++)
					;
				v = q;
				vn = (size_t)(e - q);
			}
		}
		p = memchr(p, ';', (size_t)(end - p));
		if (p == NULL)
			break;
	}
	while (vn > 0 && is_wsp((unsigned char)v[vn - 1]))
		vn--;
	if (vn > 10 && memcmp(v + vn - 10, "!important", 10) == 0)
		for (vn -= 10; vn > 0 && is_wsp((unsigned char)v[vn - 1]); vn--)
			;
	return v != NULL && loft__word_is(v, vn, value);
}

/* Whether el is hidden: display:none (it and all in it), or under
 * visibility hidden or collapse (inherited; visible undoes it). */
static int
hidden(const struct elem *el, struct level *lv)
{
	if (prop_is(el, "visibility", "hidden") ||
	    prop_is(el, "visibility", "collapse"))
		lv->hidden = 1;
	else if (prop_is(el, "visibility", "visible"))
		lv->hidden = 0;
	return prop_is(el, "display", "none");
}

/* A nested svg's viewport: translate(x, y), then its viewBox fitted to
 * its width and height as preserveAspectRatio says (xMidYMid meet by
 * default); without width and height, user units are kept. */
static void
viewport(struct svg *s, const struct elem *el, double *t)
{
	const struct attr *vb = attr_of(el, "viewBox");
	const struct attr *par = attr_of(el, "preserveAspectRatio");
	double x, y, w, h, v[4], sx, sy;
	const char *p;
	int n = 0;

	t[0] = t[3] = 1;
	t[1] = t[2] = 0;
	if (name_is(el, "symbol")) {    /* the use's box, at its x, y */
		x = y = 0;
		w = s->use_w;
		h = s->use_h;
	} else if (num_attr(s, el, "x", &x) < 0 || num_attr(s, el, "y", &y) <
	    0 || num_attr(s, el, "width", &w) != 0 || num_attr(s, el,
	    "height", &h) != 0)
		x = y = w = h = 0;
	t[4] = x;
	t[5] = y;
	if (vb == NULL || !(w > 0) || !(h > 0))
		return;
	for (p = vb->v; n < 4 && svg_num(&p, vb->v + vb->vn, &v[n]) == 0; n++)
		;
	if (n != 4 || !(v[2] > 0) || !(v[3] > 0))
		return;
	sx = w / v[2];
	sy = h / v[3];
	if (par == NULL || find(par->v, par->vn, "none", 4) == NULL) {
		int slice = par != NULL && find(par->v, par->vn, "slice", 5);
		double k = slice ? fmax(sx, sy) : fmin(sx, sy);
		double ax = par && find(par->v, par->vn, "xMin", 4) ? 0 :
		    par && find(par->v, par->vn, "xMax", 4) ? 1 : 0.5;
		double ay = par && find(par->v, par->vn, "YMin", 4) ? 0 :
		    par && find(par->v, par->vn, "YMax", 4) ? 1 : 0.5;

		sx = sy = k;
		t[4] += ax * (w - v[2] * k);
		t[5] += ay * (h - v[3] * k);
	}
	t[0] = sx;
	t[3] = sy;
	t[4] -= v[0] * sx;
	t[5] -= v[1] * sy;
}

/* A drawing element (not a group): its records. */
static int
draw(struct svg *s, const struct elem *el, const double *m)
{
	if (name_is(el, "path"))
		do_path(s, el, m);
	else if (name_is(el, "polyline"))
		do_poly(s, el, m, 0);
	else if (name_is(el, "polygon"))
		do_poly(s, el, m, 1);
	else if (name_is(el, "line"))
		do_line(s, el, m);
	else if (name_is(el, "rect"))
		do_rect(s, el, m);
	else if (name_is(el, "circle"))
		do_ellipse(s, el, m, 1);
	else if (name_is(el, "ellipse"))
		do_ellipse(s, el, m, 0);
	else if (name_is(el, "use"))
		do_use(s, el, m);
	else
		return -1;
	return 0;
}

/* An element passed over by design: counted for the note (-S: an
 * error); returns 1 (passed over). */
static int
pass_over(struct svg *s, const struct elem *el, struct loft__passed *p)
{
	if (s->c->strict && p == &s->passed)
		say_el(s, el, el->at, "an annotation or an element loft does "
		    "not know: not read (-S)");
	else
		loft__passed_add(p, el->name, el->nn);
	return 1;
}

/* The level of an element inside up: its transform, layer, hidden. */
static int
level_of(struct svg *s, const struct elem *el, const struct level *up,
    struct level *lv)
{
	int g = name_is(el, "g") || name_is(el, "a") || name_is(el, "switch");
	const struct attr *mode = attr_of(el, "inkscape:groupmode");
	const struct attr *label = attr_of(el, "inkscape:label");
	const struct attr *id = attr_of(el, "id");
	double t[6];

	*lv = *up;
	if (transform(s, el, t) != 0)
		return -1;
	mat_mul(up->m, t, lv->m);
	if (name_is(el, "svg") || name_is(el, "symbol")) {
		viewport(s, el, t);
		mat_mul(lv->m, t, lv->m);
	}
	if (g && mode != NULL && mode->vn == 5 &&
	    memcmp(mode->v, "layer", 5) == 0 && (label || id)) {
		lv->layer = label ? label->v : id->v;
		lv->nlayer = label ? label->vn : id->vn;
		lv->inklayer = 1;
	} else if (g && id != NULL && !lv->inklayer) {
		lv->layer = id->v;
		lv->nlayer = id->vn;
	}
	return 0;
}

/* An element opened: 0 when it is read (and, if it opens, pushed), 1
 * when it and what is in it are passed over, -1 when the document is
 * no SVG. */
static int
element(struct svg *s, const struct elem *el, int opens)
{
	struct level *up = s->depth > 0 ? &s->st[s->depth - 1] : NULL, lv;
	int target = s->target;
	double t[6];

	s->target = 0;
	if (s->depth >= SVG_DEPTH - 1) {
		say_el(s, el, el->at, "nested deeper than 256 elements: not "
		    "read, nor what is in it");
		return 1;
	}
	if (!s->root) {
		if (!name_is(el, "svg")) {
			say_el(s, el, el->at, "the root element is not svg: "
			    "not an SVG document");
			return -1;
		}
		s->root = 1;
		memset(&lv, 0, sizeof lv);
		root_map(s, el, lv.m);
		if (transform(s, el, t) == 0)
			mat_mul(lv.m, t, lv.m);
	} else if (up == NULL || memchr(el->name, ':', el->nn) != NULL ||
	    (in_list(el, quiet) && !(target && name_is(el, "symbol")))) {
		return 1;
	} else if (in_list(el, annotation)) {
		return pass_over(s, el, &s->passed);
	} else {
		int g = name_is(el, "g") || name_is(el, "a") ||
		    name_is(el, "switch") || name_is(el, "svg") ||
		    name_is(el, "symbol");

		if (level_of(s, el, up, &lv) != 0)
			return 1;
		if (hidden(el, &lv) && !s->c->hidden)
			return pass_over(s, el, &s->hide);
		if (!g) {
			if (lv.hidden && !s->c->hidden)
				return pass_over(s, el, &s->hide);
			s->st[s->depth++] = lv; /* for put_header */
			if (draw(s, el, lv.m) != 0) {
				s->depth--;
				return pass_over(s, el, &s->passed);
			}
			s->depth--;
		}
	}
	if (opens)
		s->st[s->depth++] = lv;
	return 0;
}

/* ---- the XML stream: every element's open tag matched to its close -- */

/* Push an open element on s->open; kind 0: it pushed a level, 1: it
 * is passed over with what is in it (or inside one that is). */
static int
open_push(struct svg *s, const struct elem *el, int kind)
{
	struct open *o;

	if (loft__grow((void **)&s->open, &s->opencap, s->nopen + 1,
	    sizeof *s->open) != 0) {
		s->oom = 1;
		return -1;
	}
	o = &s->open[s->nopen++];
	o->name = el->name;
	o->nn = el->nn;
	o->line = el->line;
	o->kind = kind;
	s->skip += kind;
	return 0;
}

static void
open_pop(struct svg *s)
{
	const struct open *o = &s->open[--s->nopen];

	if (o->kind)
		s->skip--;
	else if (s->depth > 0)
		s->depth--;
}

/*
 * A closing tag at s->p (past "</"): it closes the innermost open
 * element of its name, and any opened inside that one and left open
 * (said so); one that closes nothing is said and passed over.  The
 * document is never cut short by it.
 */
static void
close_tag(struct svg *s, long line)
{
	const char *nm = s->p;
	size_t nn, i;
	char q[41], q2[41];

	while (s->p < s->end && is_name_char((unsigned char)*s->p))
		s->p++;
	nn = (size_t)(s->p - nm);
	if (skip_past(s, ">") != 0) {
		loft__cadin_say(s->c, line, "the document ends inside a tag: "
		    "truncated?");
		s->p = s->end;
		return;
	}
	loft__cadin_quote(q, sizeof q, nm, nn);
	for (i = s->nopen; i > s->base; i--)
		if (s->open[i - 1].nn == nn && memcmp(s->open[i - 1].name, nm,
		    nn) == 0)
			break;
	if (i == s->base) {
		loft__cadin_say(s->c, line, "</%s> closes no open element: "
		    "passed over", q);
		return;
	}
	if (i < s->nopen) {
		const struct open *o = &s->open[s->nopen - 1];

		loft__cadin_say(s->c, line, "</%s> comes while <%s> of line "
		    "%ld is open: it closes that too", q, loft__cadin_quote(q2,
		    sizeof q2, o->name, o->nn), o->line);
	}
	while (s->nopen >= i)
		open_pop(s);
}

/* A start tag at s->p (past '<'): the element read, or passed over. */
static void
open_tag(struct svg *s, struct elem *el)
{
	int r = start_tag(s, el), e;

	if (r < 0) {
		if (s->p >= s->end) {
			loft__cadin_say(s->c, el->line, "the document ends "
			    "inside a tag: truncated?");
			return;
		}
		loft__cadin_say(s->c, el->line, "malformed XML tag: passed over");
		skip_past(s, ">");
		return;
	}
	if (s->root && s->nopen == 0) {
		if (!s->after++)
			say_el(s, el, el->at, "after the root svg element "
			    "closed: not read");
		e = 1;
	} else if (s->skip > 0) {
		e = 1;
	} else if ((e = element(s, el, r == 0)) < 0) {
		s->p = s->end;  /* not an SVG document */
		return;
	}
	if (r == 0)
		open_push(s, el, e);
}

/* Comments, CDATA, processing instructions and DOCTYPE at s->p (past
 * '<'); 1 when it is one of them (passed over), else 0. */
static int
other_markup(struct svg *s, long line)
{
	int r;

	if (s->end - s->p >= 3 && memcmp(s->p, "!--", 3) == 0)
		r = skip_past(s, "-->");
	else if (s->end - s->p >= 8 && memcmp(s->p, "![CDATA[", 8) == 0)
		r = skip_past(s, "]]>");
	else if (s->p < s->end && *s->p == '?')
		r = skip_past(s, "?>");
	else if (s->p < s->end && *s->p == '!') {
		/* a DOCTYPE, maybe with an internal subset */
		const char *br = memchr(s->p, '[', (size_t)(s->end - s->p));
		const char *gt = memchr(s->p, '>', (size_t)(s->end - s->p));

		r = br != NULL && gt != NULL && br < gt ?
		    skip_past(s, "]") | skip_past(s, ">") : skip_past(s, ">");
	} else
		return 0;
	if (r != 0) {
		loft__cadin_say(s->c, line, "the document ends inside a "
		    "comment or declaration: truncated?");
		s->p = s->end;
	}
	return 1;
}

/* Read tags from s->p on, to the end; or (sub) those of the one
 * element there, which a use draws. */
static void
parse(struct svg *s, int sub)
{
	struct elem el;

	while (s->p < s->end && !s->oom) {
		const char *lt = memchr(s->p, '<', (size_t)(s->end - s->p));

		if (lt == NULL)
			break;
		for (; s->p < lt; s->p++)
			s->line += *s->p == '\n';
		el.at = s->p++;
		el.line = s->line;
		if (other_markup(s, el.line))
			continue;
		if (s->p < s->end && *s->p == '/') {
			s->p++;
			close_tag(s, el.line);
		} else
			open_tag(s, &el);
		if (sub && s->nopen <= s->base)
			break;
	}
}

int
loft_svg_read(const char *buf, size_t len, struct loft_cadin *c)
{
	struct svg *s = calloc(1, sizeof *s);
	long nbad = c->nbad;
	int r;

	if (s == NULL) {
		loft__cadin_say(c, 0, "out of memory");
		return LOFT_ENOMEM;
	}
	s->c = c;
	s->buf = s->p = buf;
	s->end = buf + len;
	s->line = 1;
	s->budget = USE_BUDGET;
	parse(s, 0);
	if (!s->oom && s->nopen > 0) {
		char q[41];

		loft__cadin_say(c, s->line, "the document ends inside <%s> of "
		    "line %ld: truncated?", loft__cadin_quote(q, sizeof q,
		    s->open[s->nopen - 1].name, s->open[s->nopen - 1].nn),
		    s->open[s->nopen - 1].line);
	} else if (!s->oom && !s->root && c->nbad == nbad)
		loft__cadin_say(c, s->line, "no svg element: not an SVG "
		    "document");
	if (s->oom)
		loft__cadin_say(c, s->line, "out of memory");
	loft__passed_say(c, &s->passed, "(annotations and elements loft "
	    "does not know; -S makes them errors)");
	loft__passed_say(c, &s->hide, "hidden (display:none, "
	    "visibility:hidden; -H reads them)");
	r = s->oom ? LOFT_ENOMEM : c->nbad > nbad ? LOFT_EINPUT : 0;
	free(s->seg.v);
	free(s->open);
	free(s->ids);
	free(s);
	return r;
}
