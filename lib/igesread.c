/*
 * igesread.c: IGES 5.3 (the fixed 80-column form) read into loft's
 * records.  Read: rational B-spline curves (126) and surfaces (128),
 * lines (110, form 0), circular arcs (100) and bounded planes (108,
 * form 1, as the rectangle of their bounding curve), each moved by its
 * transformation matrix (124), in millimetres from the global section's
 * unit flag (and unit name).  Curves that are part of another entity
 * (a composite curve, a trimmed surface's bounds: subordinate in their
 * directory entry) are passed over, as their entity's own geometry is
 * read; surfaces are read wherever they are.  Entities of other
 * geometric kinds are counted in one message; the structure (views,
 * properties, groups, B-rep topology) is passed over.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

#define COLS 72                 /* the data columns of a line */
#define PCOLS 64                /* of a parameter line */

struct de {                     /* a directory entry: two lines */
	int type, form;
	long param, nparam;     /* its first parameter line, and count */
	long xform;             /* its 124's entry, or 0 */
	int subordinate;        /* status digits 3 and 4 */
	long line;              /* of the document, for messages */
	char label[9];
};

struct iges {
	const char *buf;
	size_t len;
	struct loft_cadin *c;
	char pd, rd;            /* parameter and record delimiters */
	const char **pline;     /* parameter lines, by number (1-based) */
	long np;
	size_t pcap;
	struct de *d;           /* entries, by (number + 1) / 2 */
	size_t nd, dcap;
	long pstart;            /* the document line of P 1 */
	double *v;              /* the parameters of the entity read */
	size_t nv, vcap;
	int oom;
	double mm;              /* millimetres in the model's unit */
	char *glob;             /* the global section's columns, joined */
	size_t nglob, gcap;
	long skip[1000];        /* entities passed over, by type */
};

/* An integer from columns [a, a + n) of line s (of length len). */
static long
field(const char *s, size_t len, size_t a, size_t n)
{
	long v = 0;
	int neg = 0;

	for (size_t i = a; i < a + n && i < len; i++) {
		if (s[i] == '-')
			neg = 1;
		else if (s[i] >= '0' && s[i] <= '9' && v < 100000000L)
			v = 10 * v + (s[i] - '0');
	}
	return neg ? -v : v;
}

/* The global section's delimiters: its first two fields, "1H," and
 * "1H;", or empty for the defaults. */
static void
delimiters(struct iges *g, const char *s, size_t n)
{
	size_t i = 0;

	g->pd = ',';
	g->rd = ';';
	if (n >= 3 && s[0] == '1' && (s[1] == 'H' || s[1] == 'h')) {
		g->pd = s[2];
		i = 3;
	}
	if (i < n && s[i] == g->pd)
		i++;
	if (i + 2 < n && s[i] == '1' && (s[i + 1] == 'H' || s[i + 1] == 'h'))
		g->rd = s[i + 2];
}

/* Every line into its section; -1 when out of memory. */
static int
scan(struct iges *g)
{
	const char *s = g->buf, *end = s + g->len;
	long line = 0;
	int got_g = 0;
	char gl[COLS + 1];
	struct de *e = NULL;

	while (s < end) {
		const char *nl = memchr(s, '\n', (size_t)(end - s));
		size_t n = nl ? (size_t)(nl - s) : (size_t)(end - s);

		line++;
		if (n > 0 && s[n - 1] == '\r')
			n--;
		if (n >= 73) {
			char sec = s[72];

			if (sec == 'G' && !got_g) {
				memcpy(gl, s, COLS);
				gl[COLS] = '\0';
				delimiters(g, gl, COLS);
				got_g = 1;
			}
			if (sec == 'G') {
				if (loft__grow((void **)&g->glob, &g->gcap,
				    g->nglob + COLS, 1) != 0)
					return -1;
				memcpy(g->glob + g->nglob, s, COLS);
				g->nglob += COLS;
			} else if (sec == 'D') {
				if (e == NULL) {
					if (loft__grow((void **)&g->d, &g->dcap,
					    g->nd + 1, sizeof *g->d) != 0)
						return -1;
					e = g->d + g->nd++;
					memset(e, 0, sizeof *e);
					e->type = (int)field(s, n, 0, 8);
					e->param = field(s, n, 8, 8);
					e->xform = field(s, n, 48, 8);
					e->subordinate = (int)(field(s, n, 66, 2));
					e->line = line;
				} else {
					e->nparam = field(s, n, 24, 8);
					e->form = (int)field(s, n, 32, 8);
					memcpy(e->label, s + 56, 8);
					e->label[8] = '\0';
					e = NULL;
				}
			} else if (sec == 'P') {
				if (g->np == 0)
					g->pstart = line;
				if (loft__grow((void **)&g->pline, &g->pcap,
				    (size_t)g->np + 2, sizeof *g->pline) != 0)
					return -1;
				g->pline[++g->np] = s;
			}
		}
		s = nl ? nl + 1 : end;
	}
	return 0;
}

/*
 * The parameters of entry e as numbers into g->v (a Hollerith string
 * counts as 0; an empty parameter as 0, IGES's default); -1 when they
 * cannot be read.  The first is the entity type.
 */
static int
params(struct iges *g, const struct de *e)
{
	char tok[80];
	size_t t = 0;

	g->nv = 0;
	if (e->param < 1 || e->nparam < 1 || e->param + e->nparam - 1 > g->np)
		return -1;
	for (long k = e->param; k < e->param + e->nparam; k++) {
		const char *s = g->pline[k];

		for (size_t i = 0; i < PCOLS; i++) {
			char ch = s[i];

			if (ch == '\n' || ch == '\r')
				break;
			if (ch == g->pd || ch == g->rd) {
				double x = 0;

				while (t > 0 && tok[t - 1] == ' ')
					t--;
				for (size_t q = 0; q < t; q++)
					if (tok[q] == 'D' || tok[q] == 'd')
						tok[q] = 'E';
				if (t > 0 && memchr(tok, 'H', t) != NULL)
					x = 0;  /* a string */
				else if (t > 0 && loft_parse_num(tok, t, &x,
				    NULL) != 0)
					return -1;
				if (loft__grow((void **)&g->v, &g->vcap, g->nv + 1,
				    sizeof *g->v) != 0) {
					g->oom = 1;
					return -1;
				}
				g->v[g->nv++] = x;
				t = 0;
				if (ch == g->rd)
					return 0;
			} else if (t < sizeof tok && !(t == 0 && ch == ' ')) {
				tok[t++] = ch;
			}
		}
	}
	return -1;
}

/* The entry of directory line k (odd), or NULL. */
static const struct de *
entry(const struct iges *g, long k)
{
	if (k < 1 || k % 2 == 0 || (size_t)((k + 1) / 2) > g->nd)
		return NULL;
	return g->d + (k - 1) / 2;
}

/* Apply entry e's transformation (124) to n points (3 each); -1 when
 * it cannot be read. */
static int
transform(struct iges *g, const struct de *e, double *p, size_t n)
{
	const struct de *x = entry(g, e->xform);
	double m[12];

	if (e->xform == 0)
		return 0;
	if (x == NULL || x->type != 124 || params(g, x) != 0 || g->nv < 13)
		return -1;
	memcpy(m, g->v + 1, sizeof m);
	for (size_t i = 0; i < n; i++) {
		double q[3];

		for (int r = 0; r < 3; r++)
			q[r] = m[4 * r] * p[3 * i] + m[4 * r + 1] * p[3 * i + 1] +
			    m[4 * r + 2] * p[3 * i + 2] + m[4 * r + 3];
		memcpy(p + 3 * i, q, sizeof q);
	}
	return 0;
}

/* transform, then into millimetres (g->mm): the transformation's
 * translation is in the model's unit too. */
static int
placed(struct iges *g, const struct de *e, double *p, size_t n)
{
	if (transform(g, e, p, n) != 0)
		return -1;
	for (size_t i = 0; i < 3 * n; i++)
		p[i] *= g->mm;
	return 0;
}

static struct loft__bsname
name_of(const struct de *e, long k)
{
	struct loft__bsname nm = { e->label, strlen(e->label), k };

	while (nm.nname > 0 && e->label[nm.nname - 1] == ' ')
		nm.nname--;
	while (nm.nname > 0 && nm.name[0] == ' ')
		nm.name++, nm.nname--;
	return nm;
}

/* 126: K, M, 4 flags, K + M + 2 knots, K + 1 weights, points. */
static int
curve126(struct iges *g, const struct de *e, long k)
{
	long K, M;
	size_t n, o = 7;
	double *ctl;
	struct loft__bs b;
	struct loft__bsname nm = name_of(e, k);
	int rc;

	K = g->nv > 3 ? (long)g->v[1] : -1;
	M = g->nv > 3 ? (long)g->v[2] : -1;
	if (K < 1 || M < 1 || M > LOFT_BSPLINE_MAXDEG || K > 100000000L ||
	    (size_t)(5 * K + M + 9) > g->nv) {
		loft__cadin_say(g->c, e->line, "126 (D%ld): its degree (1 to "
		    "%d) or counts do not fit its %zu parameters", k,
		    LOFT_BSPLINE_MAXDEG, g->nv);
		return -1;
	}
	n = (size_t)K + 1;
	if ((ctl = malloc(3 * n * sizeof *ctl)) == NULL) {
		g->oom = 1;
		return -1;
	}
	memcpy(ctl, g->v + o + (size_t)(K + M + 2) + n, 3 * n * sizeof *ctl);
	if (placed(g, e, ctl, n) != 0) {
		loft__cadin_say(g->c, e->line, "126 (D%ld): its transformation "
		    "cannot be read", k);
		free(ctl);
		return -1;
	}
	/* the transformation read its own parameters: read ours again */
	if (e->xform != 0 && params(g, e) != 0) {
		free(ctl);
		return -1;
	}
	b = (struct loft__bs){ (int)M, n, g->v + o, ctl, g->v + o +
	    (size_t)(K + M + 2) };
	rc = loft__bs_curve(g->c, &b, &nm, e->line);
	free(ctl);
	return rc;
}

/* 128: K1, K2, M1, M2, 5 flags, knots, weights, points with the u
 * index fastest: made u-major for loft__bs_surface. */
static int
surface128(struct iges *g, const struct de *e, long k)
{
	long K1, K2, M1, M2;
	size_t nu, nv, o = 10, nk1, nk2;
	double *ctl, *w;
	struct loft__bsurf s;
	struct loft__bsname nm = name_of(e, k);
	int rc = -1;

	K1 = g->nv > 5 ? (long)g->v[1] : -1;
	K2 = g->nv > 5 ? (long)g->v[2] : -1;
	M1 = g->nv > 5 ? (long)g->v[3] : -1;
	M2 = g->nv > 5 ? (long)g->v[4] : -1;
	if (K1 < 1 || K2 < 1 || M1 < 1 || M2 < 1 || M1 > LOFT_BSPLINE_MAXDEG ||
	    M2 > LOFT_BSPLINE_MAXDEG || K1 > 100000 || K2 > 100000 ||
	    o + (size_t)(K1 + M1 + 2 + K2 + M2 + 2) + 4 * (size_t)(K1 + 1) *
	    (size_t)(K2 + 1) > g->nv) {
		loft__cadin_say(g->c, e->line, "128 (D%ld): its degrees (1 to "
		    "%d) or counts do not fit its %zu parameters", k,
		    LOFT_BSPLINE_MAXDEG, g->nv);
		return -1;
	}
	nu = (size_t)K1 + 1;
	nv = (size_t)K2 + 1;
	nk1 = (size_t)(K1 + M1 + 2);
	nk2 = (size_t)(K2 + M2 + 2);
	ctl = malloc(3 * nu * nv * sizeof *ctl);
	w = malloc(nu * nv * sizeof *w);
	if (ctl == NULL || w == NULL) {
		g->oom = 1;
		goto done;
	}
	for (size_t j = 0; j < nv; j++)
		for (size_t i = 0; i < nu; i++) {
			const double *p = g->v + o + nk1 + nk2 + nu * nv +
			    3 * (j * nu + i);

			w[i * nv + j] = g->v[o + nk1 + nk2 + j * nu + i];
			memcpy(ctl + 3 * (i * nv + j), p, 3 * sizeof *p);
		}
	if (placed(g, e, ctl, nu * nv) != 0 || (e->xform != 0 &&
	    params(g, e) != 0)) {
		loft__cadin_say(g->c, e->line, "128 (D%ld): its transformation "
		    "cannot be read", k);
		goto done;
	}
	s = (struct loft__bsurf){ (int)M1, (int)M2, nu, nv, g->v + o,
	    g->v + o + nk1, ctl, w };
	rc = loft__bs_surface(g->c, &s, &nm, e->line);
done:
	free(ctl);
	free(w);
	return rc;
}

/* 110 form 0: a segment, as a B-spline of degree 1. */
static int
line110(struct iges *g, const struct de *e, long k)
{
	double ctl[6], t[4] = { 0, 0, 1, 1 };
	struct loft__bs b = { 1, 2, t, ctl, NULL };
	struct loft__bsname nm = name_of(e, k);

	if (g->nv < 7 || e->form != 0) {
		loft__cadin_say(g->c, e->line, e->form != 0 ? "110 (D%ld): an "
		    "unbounded line (form %d), passed over" : "110 (D%ld): "
		    "fewer than 6 coordinates", k, e->form);
		return -1;
	}
	memcpy(ctl, g->v + 1, sizeof ctl);
	if (placed(g, e, ctl, 2) != 0) {
		loft__cadin_say(g->c, e->line, "110 (D%ld): its transformation "
		    "cannot be read", k);
		return -1;
	}
	return loft__bs_curve(g->c, &b, &nm, e->line);
}

/*
 * 100: ZT, the centre, the start and the end in the plane z = ZT,
 * counterclockwise (a full circle when the ends meet), as rational
 * quadratic pieces of at most a quarter turn each, their middle points
 * where the end tangents meet (at the middle angle over cos h, weight
 * cos h, h half the piece's angle).
 */
static int
arc100(struct iges *g, const struct de *e, long k)
{
	double zt, cx, cy, r, a0, a1, sw, h, ctl[9 * 3], w[9], t[12];
	struct loft__bsname nm = name_of(e, k);
	struct loft__bs b;
	int n;

	if (g->nv < 8) {
		loft__cadin_say(g->c, e->line, "100 (D%ld): fewer than 7 "
		    "numbers", k);
		return -1;
	}
	zt = g->v[1], cx = g->v[2], cy = g->v[3];
	r = hypot(g->v[4] - cx, g->v[5] - cy);
	a0 = atan2(g->v[5] - cy, g->v[4] - cx);
	a1 = atan2(g->v[7] - cy, g->v[6] - cx);
	sw = a1 - a0;
	if (g->v[4] == g->v[6] && g->v[5] == g->v[7])
		sw = 2 * M_PI;
	else if (sw <= 0)
		sw += 2 * M_PI;
	if (!(r > 0) || !isfinite(r)) {
		loft__cadin_say(g->c, e->line, "100 (D%ld): an arc of no "
		    "radius", k);
		return -1;
	}
	n = (int)ceil(sw / (M_PI / 2) - 1e-12);
	n = n < 1 ? 1 : n > 4 ? 4 : n;
	h = sw / n / 2;
	for (int i = 0; i <= 2 * n; i++) {
		double u = a0 + i * h, s = i % 2 ? 1 / cos(h) : 1;

		ctl[3 * i] = cx + s * r * cos(u);
		ctl[3 * i + 1] = cy + s * r * sin(u);
		ctl[3 * i + 2] = zt;
		w[i] = i % 2 ? cos(h) : 1;
	}
	/* knots 0 0 0 1 1 ... n n n */
	t[0] = 0;
	for (int i = 1; i < 2 * n + 3; i++)
		t[i] = (i - 1) / 2;
	t[2 * n + 3] = n;
	if (placed(g, e, ctl, (size_t)(2 * n + 1)) != 0) {
		loft__cadin_say(g->c, e->line, "100 (D%ld): its transformation "
		    "cannot be read", k);
		return -1;
	}
	b = (struct loft__bs){ 2, (size_t)(2 * n + 1), t, ctl, w };
	return loft__bs_curve(g->c, &b, &nm, e->line);
}

/* Bounding curves nested deeper than this are taken for a loop. */
#define MAX_NEST 8

/* The points that bound curve entry k (126's control points, 110's
 * ends, 100's box, 102's members'), moved by their transformations,
 * appended to *p; -1 when out of memory. */
static int
curve_points(struct iges *g, long k, int depth, struct loft__pts *p)
{
	const struct de *e = entry(g, k);
	struct loft__pts own = { NULL, 0, 0 };
	int rc = 0;

	if (e == NULL || depth > MAX_NEST || params(g, e) != 0)
		return 0;
	if (e->type == 102) {
		size_t n = g->nv > 1 ? (size_t)g->v[1] : 0;
		long *m = malloc((n + 1) * sizeof *m);

		if (m == NULL || n + 2 > g->nv) {
			free(m);
			return m == NULL ? -1 : 0;
		}
		for (size_t i = 0; i < n; i++)
			m[i] = (long)g->v[2 + i];
		for (size_t i = 0; i < n && rc == 0; i++)
			rc = curve_points(g, m[i], depth + 1, p);
		free(m);
		return rc;
	}
	if (e->type == 110 && g->nv >= 7) {
		rc = loft__pts_add(&own, g->v + 1) || loft__pts_add(&own,
		    g->v + 4);
	} else if (e->type == 100 && g->nv >= 8) {
		double r = hypot(g->v[4] - g->v[2], g->v[5] - g->v[3]);

		for (int s = 0; s < 4 && rc == 0; s++) {
			double x[3] = { g->v[2] + (s == 0 ? r : s == 1 ? -r : 0),
			    g->v[3] + (s == 2 ? r : s == 3 ? -r : 0), g->v[1] };

			rc = loft__pts_add(&own, x);
		}
	} else if (e->type == 126 && g->nv > 3) {
		long K = (long)g->v[1], M = (long)g->v[2];

		if (K >= 1 && M >= 1 && (size_t)(5 * K + M + 9) <= g->nv)
			for (long i = 0; i <= K && rc == 0; i++)
				rc = loft__pts_add(&own, g->v + 7 + (K + M + 2) +
				    (K + 1) + 3 * i);
	}
	if (rc == 0 && transform(g, e, own.p, own.n) != 0)
		own.n = 0;
	for (size_t i = 0; i < own.n && rc == 0; i++)
		rc = loft__pts_add(p, own.p + 3 * i);
	free(own.p);
	return rc ? -1 : 0;
}

/* 108 form 1: the plane A x + B y + C z = D bounded by a curve, as the
 * rectangle of the curve's points in the plane's axes. */
static int
plane108(struct iges *g, const struct de *e, long k)
{
	double n[3], o[3], x[3], y[3], lo[2] = { INFINITY, INFINITY };
	double hi[2] = { -INFINITY, -INFINITY }, net[12], len, d;
	struct loft__pts p = { NULL, 0, 0 };
	struct loft__bsname nm = name_of(e, k);
	long bound;

	if (g->nv < 6 || e->form != 1) {
		loft__cadin_say(g->c, e->line, "108 (D%ld): an unbounded plane "
		    "(form %d), passed over", k, e->form);
		return -1;
	}
	memcpy(n, g->v + 1, sizeof n);
	d = g->v[4];
	bound = (long)g->v[5];
	len = hypot(hypot(n[0], n[1]), n[2]);
	if (!(len > 0) || !isfinite(len) || curve_points(g, bound, 0, &p) ||
	    p.n == 0) {
		loft__cadin_say(g->c, e->line, "108 (D%ld): no normal or no "
		    "bounding curve that loft reads", k);
		free(p.p);
		return -1;
	}
	for (int q = 0; q < 3; q++) {
		n[q] /= len;
		o[q] = n[q] * d / len;
	}
	/* x: square to the normal, away from its largest component */
	{
		double a[3] = { fabs(n[0]) < 0.9, fabs(n[0]) >= 0.9, 0 }, s;

		x[0] = a[1] * n[2] - a[2] * n[1];
		x[1] = a[2] * n[0] - a[0] * n[2];
		x[2] = a[0] * n[1] - a[1] * n[0];
		s = hypot(hypot(x[0], x[1]), x[2]);
		for (int q = 0; q < 3; q++)
			x[q] /= s;
		y[0] = n[1] * x[2] - n[2] * x[1];
		y[1] = n[2] * x[0] - n[0] * x[2];
		y[2] = n[0] * x[1] - n[1] * x[0];
	}
	for (size_t i = 0; i < p.n; i++)
		for (int a = 0; a < 2; a++) {
			double c = 0;

			for (int q = 0; q < 3; q++)
				c += (p.p[3 * i + q] - o[q]) * (a ? y[q] : x[q]);
			lo[a] = fmin(lo[a], c);
			hi[a] = fmax(hi[a], c);
		}
	free(p.p);
	if (!(hi[0] > lo[0] && hi[1] > lo[1])) {
		loft__cadin_say(g->c, e->line, "108 (D%ld): a bounding curve "
		    "of no area", k);
		return -1;
	}
	for (int i = 0; i < 2; i++)
		for (int j = 0; j < 2; j++)
			for (int q = 0; q < 3; q++)
				net[3 * (2 * i + j) + q] = o[q] + (i ? hi[0] :
				    lo[0]) * x[q] + (j ? hi[1] : lo[1]) * y[q];
	if (params(g, e) != 0 || placed(g, e, net, 4) != 0) {
		loft__cadin_say(g->c, e->line, "108 (D%ld): its transformation "
		    "cannot be read", k);
		return -1;
	}
	return loft__bs_patch(g->c, net, 1, 1, &nm, e->line);
}

int
loft__iges_sniff(const char *buf, size_t len)
{
	const char *nl = memchr(buf, '\n', len);
	size_t n = nl ? (size_t)(nl - buf) : len;

	if (n > 0 && buf[n - 1] == '\r')
		n--;
	return n >= 73 && buf[72] == 'S';
}

/* Geometric entity types loft does not read, for the message. */
static int
unread_geometry(int type)
{
	static const int t[] = { 104, 106, 112, 114, 118, 120, 122, 140, 190,
	    192, 194, 196, 198 };

	for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
		if (t[i] == type)
			return 1;
	return 0;
}

/* IGES 5.3's global parameter 14 (the units flag): millimetres in each
 * unit, by flag; 0: none (3 names the unit in parameter 15). */
static const double flag_mm[] = {
	0, 25.4, 1, 0, 304.8, 1609344, 1000, 1e6, 0.0254, 1e-3, 10, 2.54e-5,
};
/* Parameter 15's names of those units (flag 3 takes its unit from it). */
static const struct { const char *name; double mm; } name_mm[] = {
	{ "IN", 25.4 }, { "INCH", 25.4 }, { "MM", 1 }, { "FT", 304.8 },
	{ "MI", 1609344 }, { "M", 1000 }, { "KM", 1e6 }, { "MIL", 0.0254 },
	{ "UM", 1e-3 }, { "CM", 10 }, { "UIN", 2.54e-5 },
};

/* Global parameter want (from 1) of the joined global section: its
 * text (a Hollerith string's characters) into *s, *n; 0, or -1 when
 * the section ends first. */
static int
global(const struct iges *g, int want, const char **s, size_t *n)
{
	const char *t = g->glob, *end = t != NULL ? t + g->nglob : t;

	for (int f = 1; t < end; f++) {
		const char *a, *b;
		size_t h = 0;

		while (t < end && *t == ' ')
			t++;
		for (a = t; t < end && *t >= '0' && *t <= '9' && h < 10000; t++)
			h = 10 * h + (size_t)(*t - '0');
		if (t > a && t < end && (*t == 'H' || *t == 'h') &&
		    h <= (size_t)(end - t - 1)) {
			a = t + 1;
			b = t = a + h;
		} else {
			for (t = a; t < end && *t != g->pd && *t != g->rd; t++)
				;
			for (b = t; b > a && b[-1] == ' '; b--)
				;
		}
		if (f == want) {
			*s = a;
			*n = (size_t)(b - a);
			return 0;
		}
		while (t < end && *t != g->pd && *t != g->rd)
			t++;
		if (t >= end || *t == g->rd)
			return -1;
		t++;
	}
	return -1;
}

/* g->mm from the units flag (parameter 14) and, for flag 3, the unit
 * name (15); 1 with a note when neither names a unit loft knows. */
static void
units(struct iges *g)
{
	const char *s = NULL, *ns = NULL;
	size_t n = 0, nn = 0;
	double x = 0;
	char msg[160], q[40];

	g->mm = 0;
	if (global(g, 14, &s, &n) == 0 && n > 0 &&
	    loft_parse_num(s, n, &x, NULL) == 0 && x >= 1 &&
	    x < (double)(sizeof flag_mm / sizeof flag_mm[0]) && x == (int)x)
		g->mm = flag_mm[(int)x];
	if (x == 3 && global(g, 15, &ns, &nn) == 0)
		for (size_t i = 0; i < sizeof name_mm / sizeof name_mm[0]; i++)
			if (loft__word_is(ns, nn, name_mm[i].name))
				g->mm = name_mm[i].mm;
	if (g->mm > 0)
		return;
	g->mm = 1;
	if (g->c->note == NULL)
		return;
	if (s == NULL || n == 0)
		snprintf(msg, sizeof msg, "no unit flag");
	else if (x == 3)
		snprintf(msg, sizeof msg, "unit flag 3 names unit '%s', which "
		    "loft does not know", loft__cadin_quote(q, sizeof q, ns,
		    ns ? nn : 0));
	else
		snprintf(msg, sizeof msg, "unit flag '%s' is no IGES unit "
		    "(1 to 11)", loft__cadin_quote(q, sizeof q, s, s ? n : 0));
	strncat(msg, ": coordinates kept as the file has them",
	    sizeof msg - strlen(msg) - 1);
	g->c->note(g->c->ctx, 0, msg);
}

int
loft_iges_read(const char *buf, size_t len, struct loft_cadin *c)
{
	struct iges g;
	long nbad = c->nbad;

	memset(&g, 0, sizeof g);
	g.mm = 1;
	g.buf = buf;
	g.len = len;
	g.c = c;
	g.pd = ',';
	g.rd = ';';
	if (scan(&g) != 0)
		g.oom = 1;
	if (!g.oom && g.nd == 0)
		loft__cadin_say(c, 0, "no directory entries: no IGES data");
	else if (!g.oom)
		units(&g);
	for (size_t i = 0; i < g.nd && !g.oom; i++) {
		const struct de *e = g.d + i;
		long k = 2 * (long)i + 1;
		int indep = e->subordinate == 0;

		if (e->type == 128 || (indep && (e->type == 126 ||
		    e->type == 110 || e->type == 100 || e->type == 108))) {
			if (params(&g, e) != 0) {
				if (!g.oom)
					loft__cadin_say(c, e->line, "%d (D%ld): "
					    "its parameters cannot be read",
					    e->type, k);
				continue;
			}
			switch (e->type) {
			case 126: (void)curve126(&g, e, k); break;
			case 128: (void)surface128(&g, e, k); break;
			case 110: (void)line110(&g, e, k); break;
			case 100: (void)arc100(&g, e, k); break;
			default: (void)plane108(&g, e, k); break;
			}
		} else if (unread_geometry(e->type) && (indep ||
		    e->type >= 114)) {
			g.skip[e->type]++;
		}
	}
	for (int t = 0; t < 1000; t++)
		if (g.skip[t] > 0)
			loft__cadin_say(c, 0, "%ld entities of type %d passed "
			    "over: loft reads 100, 108, 110, 126 and 128",
			    g.skip[t], t);
	if (g.oom)
		loft__cadin_say(c, 0, "out of memory");
	free(g.d);
	free(g.glob);
	free(g.pline);
	free(g.v);
	return g.oom ? LOFT_ENOMEM : c->nbad > nbad ? LOFT_EINPUT : 0;
}
