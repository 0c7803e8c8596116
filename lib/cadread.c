/*
 * cadread.c: what the CAD readers (dxfread.c, svgread.c, csvread.c)
 * share: telling a document's format (each reader's sniff), the
 * dispatch through cadreaders.c's table, their complaints,
 * records written whole, attribute values from names, and arcs made
 * polynomial within a tolerance.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

int
loft__word_is(const char *s, size_t n, const char *word)
{
	size_t k;

	for (k = 0; k < n && word[k] != '\0'; k++) {
		int a = (unsigned char)s[k], b = (unsigned char)word[k];

		if (a >= 'A' && a <= 'Z')
			a += 'a' - 'A';
		if (b >= 'A' && b <= 'Z')
			b += 'a' - 'A';
		if (a != b)
			return 0;
	}
	return k == n && word[k] == '\0';
}

const char *
loft__cadin_quote(char *buf, size_t size, const char *s, size_t n)
{
	size_t k;

	for (k = 0; k < n && k + 1 < size; k++)
		buf[k] = (unsigned char)s[k] < 32 || s[k] == 127 ? '?' : s[k];
	buf[k] = '\0';
	return buf;
}

/* The line at s[0..len) without its end and surrounding white space. */
static void
trimmed_line(const char *s, size_t len, const char **a, size_t *n)
{
	const char *e = memchr(s, '\n', len);
	size_t m = e ? (size_t)(e - s) : len, i = 0;

	while (i < m && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r'))
		i++;
	while (m > i && (s[m - 1] == ' ' || s[m - 1] == '\t' ||
	    s[m - 1] == '\r'))
		m--;
	*a = s + i;
	*n = m - i;
}

/* Where buf's content starts: after a UTF-8 byte order mark and white
 * space; len when there is none. */
static size_t
content_start(const char *buf, size_t len)
{
	size_t i = loft_bom(buf, len);

	while (i < len && (buf[i] == ' ' || buf[i] == '\t' || buf[i] == '\r' ||
	    buf[i] == '\n'))
		i++;
	return i;
}

int
loft__dxf_sniff(const char *buf, size_t len)
{
	static const char bin[] = "AutoCAD Binary DXF";
	size_t i = content_start(buf, len), n, k = 0;
	const char *l, *nl;

	if (len >= sizeof bin - 1 && memcmp(buf, bin, sizeof bin - 1) == 0)
		return 1;
	if (i == len)
		return 0;
	/* a group code (a whole number) on its own line, then a value */
	trimmed_line(buf + i, len - i, &l, &n);
	while (k < n && l[k] >= '0' && l[k] <= '9')
		k++;
	return n > 0 && n <= 4 && k == n && (nl = memchr(buf + i, '\n',
	    len - i)) != NULL && nl + 1 < buf + len;
}

int
loft__step_sniff(const char *buf, size_t len)
{
	size_t i = content_start(buf, len);

	return len - i >= 12 && memcmp(buf + i, "ISO-10303-21", 12) == 0;
}

int
loft__svg_sniff(const char *buf, size_t len)
{
	size_t i = content_start(buf, len);

	return i < len && buf[i] == '<';
}

int
loft__csv_sniff(const char *buf, size_t len)
{
	size_t i = content_start(buf, len), n;
	const char *l;
	int x = 0, y = 0;

	if (i == len)
		return 0;
	/* Excel's "sep=;" line, or a header line that names an x and a y
	 * column */
	trimmed_line(buf + i, len - i, &l, &n);
	if (n >= 5 && (memcmp(l, "sep=", 4) == 0 || memcmp(l, "\"sep=", 5) == 0))
		return 1;
	for (size_t k = 0; k < n;) {
		size_t m = 0;

		while (k + m < n && strchr(",;\t \"'", l[k + m]) == NULL)
			m++;
		x |= loft__word_is(l + k, m, "x");
		y |= loft__word_is(l + k, m, "y");
		k += m + 1;
	}
	return x && y;
}

int
loft_cadin_sniff(const char *buf, size_t len)
{
	for (int i = 0; loft_cadin_readers[i].name != NULL; i++)
		if (loft_cadin_readers[i].sniff(buf, len))
			return i;
	return -1;
}

int
loft_cadin_read(int format, const char *buf, size_t len, struct loft_cadin *c)
{
	size_t bom = loft_bom(buf, len);

	buf += bom;     /* every reader starts after a byte order mark */
	len -= bom;
	return loft_cadin_readers[format].read(buf, len, c);
}

int
loft_cadin_find(const char *name, int *i, struct loft_error *err)
{
	const char *words[LOFT_CADIN_MAXREADERS + 1];
	int n = 0;

	for (const struct loft_cadin_reader *r = loft_cadin_readers;
	    r->name != NULL; r++)
		if (n < LOFT_CADIN_MAXREADERS)
			words[n++] = r->name;
	words[n] = NULL;
	return loft_parse_word(name, words, i, err);
}

void
loft__cadin_say(struct loft_cadin *c, long line, const char *fmt, ...)
{
	char msg[256];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	c->nbad++;
	c->complain(c->ctx, line, msg);
}

int
loft__cadin_done(struct loft_cadin *c, size_t mark, long line)
{
	struct loft_writer *w = c->w;
	int bad = w->bad;

	if (!bad)
		return 0;
	loft_writer_cut(w, mark);
	w->bad = 0;
	loft__cadin_say(c, line, "%s", bad == LOFT_ENOMEM ? "out of memory" :
	    "result is not finite (the input is too extreme)");
	return -1;
}

void
loft__cadin_put_name(struct loft_writer *w, const char *key, const char *s,
    size_t n)
{
	static const char hex[] = "0123456789ABCDEF";
	char buf[3 * 255 + 1];
	size_t k = 0;

	if (n == 0)
		return;
	if (n > 255)            /* a name this long is no layer name */
		n = 255;
	for (size_t i = 0; i < n; i++) {
		unsigned char b = (unsigned char)s[i];

		if (b < 33 || b > 126 || b == '%' || b == '#') {
			buf[k++] = '%';
			buf[k++] = hex[b >> 4];
			buf[k++] = hex[b & 15];
		} else {
			buf[k++] = (char)b;
		}
	}
	buf[k] = '\0';
	loft_put_attr(w, key, buf);
}

void
loft__cadin_put_list(struct loft_writer *w, const char *key, const size_t *v,
    size_t n)
{
	char *buf, *p;

	if (n == 0)
		return;
	if (n > SIZE_MAX / 24 || (buf = malloc(n * 24 + 1)) == NULL) {
		w->bad = LOFT_ENOMEM;
		return;
	}
	p = buf;
	for (size_t j = 0; j < n; j++)
		p += sprintf(p, "%s%zu", j > 0 ? "," : "", v[j] + 1);
	loft_put_attr(w, key, buf);
	free(buf);
}

void
loft__cadin_put_straight(struct loft_writer *w, const double *seg,
    size_t nseg, int dim, int closed)
{
	size_t *out;

	if (nseg < 2)
		return;         /* no neighbour to meet */
	if (nseg > SIZE_MAX / sizeof *out || (out = malloc(nseg *
	    sizeof *out)) == NULL) {
		w->bad = LOFT_ENOMEM;
		return;
	}
	loft__cadin_put_list(w, "straight", out, loft_straight_spans(seg, nseg,
	    dim, closed, out));
	free(out);
}

int
loft__pts_add(struct loft__pts *s, const double *x)
{
	double *q;

	if (3 * (s->n + 1) > s->cap && loft__grow((void **)&s->p, &s->cap,
	    3 * (s->n + 1), sizeof *s->p) != 0)
		return -1;
	q = s->p + 3 * s->n++;
	q[0] = x[0];
	q[1] = x[1];
	q[2] = x[2];
	return 0;
}

int
loft__pts_dim(const double *p, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (p[3 * i + 2] != 0)
			return 3;
	return 2;
}

void
loft__pts_put(struct loft_writer *w, const struct loft__echo *e,
    const double *p, size_t n, int dim)
{
	for (size_t i = 0; i < n; i++)
		loft__echo_row(e, w, p + 3 * i, dim);
}

/* Significant digits past which doubles no longer keep decimals apart
 * (DBL_DIG), and the most zeros after "0." that positional text has
 * (loft_format_num writes 0.0000x as x e-05). */
#define ECHO_DIGITS 15
#define ECHO_ZEROS 3

static int
is_digit(char c)
{
	return c >= '0' && c <= '9';
}

int
loft__echo_form(const char *s, size_t n)
{
	size_t i = 0, sig = 0, zeros = 0;

	if (n == 1 && s[0] == '0')
		return 1;
	if (n > 0 && s[0] == '-')
		i++;
	if (i == n)
		return 0;
	if (s[i] == '0') {                      /* 0.000ddd */
		if (i + 2 >= n || s[i + 1] != '.')
			return 0;
		for (i += 2; i < n && s[i] == '0'; i++)
			zeros++;
		if (zeros > ECHO_ZEROS || i == n)
			return 0;
	} else {                                /* ddd, ddd.ddd */
		for (; i < n && is_digit(s[i]); i++)
			sig++;
		if (sig == 0)
			return 0;
		if (i == n)
			return sig <= ECHO_DIGITS;
		if (s[i] != '.' || ++i == n)
			return 0;
	}
	for (; i < n; i++, sig++)
		if (!is_digit(s[i]))
			return 0;
	return sig <= ECHO_DIGITS && s[n - 1] != '0';
}

static size_t
echo_slot(double x)
{
	uint64_t b;

	memcpy(&b, &x, sizeof b);
	return (size_t)(((b ^ b >> 31) * 0x9e3779b97f4a7c15ULL) >> 32) %
	    LOFT__ECHO_SLOTS;
}

int
loft__echo_parse(struct loft__echo *e, const char *s, size_t n, double *x)
{
	size_t k;

	if (loft_parse_num(s, n, x, NULL) != 0)
		return -1;
	if (e != NULL && s >= e->doc && (size_t)(s - e->doc) < e->len &&
	    (size_t)(s - e->doc) <= UINT32_MAX - n && loft__echo_form(s, n)) {
		k = echo_slot(*x);
		memcpy(&e->slot[k].bits, x, sizeof *x);
		e->slot[k].at = (uint32_t)(s - e->doc);
		e->slot[k].n = (uint32_t)n;
	}
	return 0;
}

void
loft__echo_put(const struct loft__echo *e, struct loft_writer *w, double x)
{
	size_t k, n;
	uint64_t b;

	if (e == NULL || w->digits != 0 || w->bad) {
		loft_put_num(w, x);
		return;
	}
	k = echo_slot(x);
	memcpy(&b, &x, sizeof b);
	if ((n = e->slot[k].n) == 0 || e->slot[k].bits != b) {
		loft_put_num(w, x);
		return;
	}
	if (loft__grow((void **)&w->buf, &w->cap, w->len + n + 1, 1) != 0) {
		w->bad = LOFT_ENOMEM;
		return;
	}
	if (w->col++ > 0)
		w->buf[w->len++] = ' ';
	memcpy(w->buf + w->len, e->doc + e->slot[k].at, n);
	w->len += n;
}

void
loft__echo_row(const struct loft__echo *e, struct loft_writer *w,
    const double *v, int n)
{
	for (int k = 0; k < n; k++)
		loft__echo_put(e, w, v[k]);
	loft_end_line(w);
}

/* The tolerance of an arc of radius r in the output's units. */
static double
arc_tol(const struct loft_cadin *c, double r)
{
	return c->tol > 0 ? c->tol : LOFT_CADIN_ARC_REL * r;
}

/*
 * Chords: one spanning an angle t stands r (1 - cos(t/2)) off the arc
 * at its middle, so t = 2 acos(1 - tol/r); never more than a quarter
 * turn a chord, so that a coarse tolerance still keeps the arc's shape.
 */
long
loft__arc_chords(const struct loft_cadin *c, double r, double a)
{
	double tol = arc_tol(c, r), t, n;

	if (loft_tol_check(tol, r, 0, NULL) != 0)
		return -1;      /* t = 0 below rounding: was a square */
	a = fabs(a);
	/* 1 - cos(t/2) = 2 sin^2(t/4) = tol/r, solved without forming
	 * 1 - tol/r, which rounds to 1 below tol/r ~ 1e-16 (a square) */
	t = tol >= r ? M_PI / 2 : 4 * asin(sqrt(tol / (2 * r)));
	if (!(t > 0))
		return -1;      /* tol/r underflowed: endless chords */
	if (t > M_PI / 2)
		t = M_PI / 2;
	n = ceil(a / t - 1e-12);
	if (!(n <= LOFT_CADIN_ARC_MAX))
		return -1;
	return n < 1 ? 1 : (long)n;
}

/* The radial error of the cubic through an arc of radius r and angle t
 * with its inner control points at (4/3) tan(t/4) r along the end
 * tangents: r (2/27) sin^6(t/4) / cos^2(t/4), largest at the middle. */
static double
cubic_arc_error(double r, double t)
{
	double s = sin(t / 4), co = cos(t / 4);

	return r * (2.0 / 27) * s * s * s * s * s * s / (co * co);
}

long
loft__arc_cubics(const struct loft_cadin *c, double r, double a)
{
	double tol = arc_tol(c, r), n, t;

	if (loft_tol_check(tol, r, 0, NULL) != 0)
		return -1;
	a = fabs(a);
	/* sin^6(t/4) ~ (t/4)^6: a first guess from below, then step up */
	t = 4 * pow(27 * tol / (2 * r), 1.0 / 6);
	n = !(t > 0) ? LOFT_CADIN_ARC_MAX + 1.0 : ceil(a / t - 1e-12);
	if (n < ceil(a / (M_PI / 2) - 1e-12))
		n = ceil(a / (M_PI / 2) - 1e-12);
	if (n < 1)
		n = 1;
	while (n <= LOFT_CADIN_ARC_MAX && cubic_arc_error(r, a / n) > tol)
		n++;
	return n <= LOFT_CADIN_ARC_MAX ? (long)n : -1;
}

void
loft__bezier_hermite(const double *b, int dim, double *row)
{
	for (int k = 0; k < dim; k++) {
		row[k] = b[k];
		row[dim + k] = b[3 * dim + k];
		row[2 * dim + k] = 3 * (b[dim + k] - b[k]);
		row[3 * dim + k] = 3 * (b[3 * dim + k] - b[2 * dim + k]);
	}
}

void
loft__passed_add(struct loft__passed *p, const char *s, size_t n)
{
	int i;

	for (i = 0; i < p->nk; i++)
		if (loft__word_is(s, n, p->k[i].name))
			break;
	if (i == p->nk) {
		if (p->nk == LOFT__PASSED_KINDS) {
			p->other++;
			return;
		}
		loft__cadin_quote(p->k[i].name, sizeof p->k[i].name, s, n);
		if (strlen(p->k[i].name) != n) {        /* too long to keep */
			p->other++;
			return;
		}
		p->k[i].n = 0;
		p->nk++;
	}
	p->k[i].n++;
}

void
loft__passed_say(struct loft_cadin *c, const struct loft__passed *p,
    const char *why)
{
	char msg[1024];
	size_t k = 0;

	if ((p->nk == 0 && p->other == 0) || c->note == NULL)
		return;
	for (int i = 0; i < p->nk && k < sizeof msg - 200; i++)
		k += (size_t)snprintf(msg + k, sizeof msg - k, "%s%ld %s",
		    i > 0 ? ", " : "", p->k[i].n, p->k[i].name);
	if (p->other > 0)
		k += (size_t)snprintf(msg + k, sizeof msg - k, "%s%ld other",
		    k > 0 ? ", " : "", p->other);
	snprintf(msg + k, sizeof msg - k, " passed over %s", why);
	c->note(c->ctx, 0, msg);
}

void
loft__arc_unit(double a, double h, double e, double *u)
{
	double k = 4.0 / 3 * tan(h / 4);

	u[0] = cos(a);
	u[1] = sin(a);
	u[2] = cos(a) - k * sin(a);
	u[3] = sin(a) + k * cos(a);
	u[4] = cos(e) + k * sin(e);
	u[5] = sin(e) - k * cos(e);
	u[6] = cos(e);
	u[7] = sin(e);
}
