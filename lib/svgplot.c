/*
 * svgplot.c: the SVG picture of loftplot(1), a format of loftcad.h's
 * writer interface: a frame of opts.frame, opts.picture_px pixels on
 * its larger side, whatever the drawing's units; each record a path styled
 * by its item's class (a comb's teeth faint, tangents dashed, markers
 * filled, control points hollow), in its colour and stroke width; then
 * the labels' grounds (box) and the labels (label) over everything.
 * The points are the program's, already in the plane of its view, y up;
 * the picture flips y.  Every coordinate is written to RESOLUTION of the
 * frame's larger side.
 * Program layer (loftcad.h, on loftprog.h): a format.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"

/* Coordinates are written to this fraction of the picture's larger side,
 * 1/1600 of a pixel of a 640-pixel picture: below anything a screen or
 * printer shows, yet short text. */
#define RESOLUTION 1e-6
/* Coordinates are written in the drawing's units while the place of
 * their last digit, 10^-decimals, lies between these powers of ten: a
 * frame from about 1e-6 to 1e9 units.  Beyond, fixed notation would
 * write 80 or 300 digits, and a browser, whose coordinates are single
 * precision (to about 1e38), would show nothing: they are written in
 * units of 10^unit, a power of ten that makes the frame's larger side
 * 100 to 1000 of them, named by the svg element's data-unit attribute;
 * the digits are printf's %e of each number, the point moved, so that
 * the picture of a drawing of 1e80 or 1e-300 units is the picture of the
 * same drawing in units of 1, exactly (issue 28). */
#define FIXED_MIN_DECIMALS (-3)
#define FIXED_MAX_DECIMALS 12
/* Marker radius of points and control points, in pixels. */
#define KNOT_PX 2.5
/* The halo of the background's colour under each letter, in pixels of
 * the font. */
#define HALO_PX 3

/* How a class is styled beyond its colour and width. */
enum look {
	L_STROKE,       /* a line in the colour */
	L_FAINT,        /* and translucent (a comb's teeth) */
	L_DASHED,       /* and dashed (tangents) */
	L_HOLLOW,       /* markers drawn in the colour, white inside */
	L_FILLED        /* markers filled with the colour, no line */
};

static const struct style {
	const char *cls;
	enum look look;
} styles[] = {
	{ "comb", L_FAINT },
	{ "tangents", L_DASHED },
	{ "control-points", L_HOLLOW },
	{ "points", L_FILLED },
	{ "knots", L_FILLED },
};

enum part { IN_LINES, AFTER_LINES, IN_LABELS };

struct plot {
	double px;              /* one pixel in the drawing's units */
	int decimals;           /* of every coordinate: its last digit is */
	                        /* at 10^-decimals (may be negative) */
	int fixed;              /* decimals in the fixed range */
	int unit;               /* otherwise lengths are in 10^unit */
	const char *ground;     /* the background's colour */
	enum part part;         /* of the picture being written */
	const struct loft_cad_item *it;        /* the record being written */
	int open;               /* its path element is begun */
};

/* Powers of ten exact in a double, for fixed_fast. */
#define EXACT_POW10 22

/*
 * What put_fixed writes of x, into buf (at least 40 bytes), as printf's
 * "%.*f" would write it and then cut: the whole number nearest x times
 * 10^decimals, with the point put back, when that product is below
 * 2^52 and not within its own rounding error of a tie (then the nearest
 * whole number is printf's too).  Returns the length, or 0 where printf
 * must decide.  A picture's coordinates take millions of conversions,
 * and printf's exact one is slow (in WebAssembly, through a software
 * long double, it was most of the time of a drag with the comb).
 */
static int
fixed_fast(char *buf, double x, int decimals)
{
	static const double p10[EXACT_POW10 + 1] = { 1e0, 1e1, 1e2, 1e3, 1e4,
	    1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
	    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
	double y, r, f;
	char dig[24];
	int n = 0, k = 0;
	uint64_t v;

	if (decimals < 0 || decimals > EXACT_POW10)
		return 0;
	y = fabs(x) * p10[decimals];
	if (!(y < 0x1p52))
		return 0;
	r = floor(y);
	f = y - r;
	/* y's error is at most half an ulp of y, and |f - 1/2| must exceed
	 * it with room: 2^-50 of y */
	if (fabs(f - 0.5) <= 0x1p-50 * y + 0x1p-60)
		return 0;
	v = (uint64_t)r + (f > 0.5);
	if (x < 0 && v > 0)
		buf[n++] = '-';
	do
		dig[k++] = (char)('0' + v % 10);
	while ((v /= 10) > 0);
	while (k <= decimals)                   /* a leading 0 */
		dig[k++] = '0';
	/* dig[] holds the digits backwards: cut trailing zeros first */
	int lo = 0;
	while (lo < decimals && dig[lo] == '0')
		lo++;
	for (int i = k - 1; i >= decimals; i--)
		buf[n++] = dig[i];
	if (lo < decimals) {
		buf[n++] = '.';
		for (int i = decimals - 1; i >= lo; i--)
			buf[n++] = dig[i];
	}
	return n;
}

/*
 * x in fixed notation to p->decimals places (0 <= decimals <=
 * FIXED_MAX_DECIMALS), without trailing zeros or "-0", into buf (at
 * least 64 bytes); returns the length.
 */
static int
fixed_text(char *buf, double x, int decimals)
{
	int n;

	if ((n = fixed_fast(buf, x, decimals)) > 0)
		return n;
	n = snprintf(buf, 64, "%.*f", decimals, x);
	if (n < 0 || n >= 64)           /* far from the origin: every digit */
		return snprintf(buf, 64, "%.17g", x);
	if (memchr(buf, '.', (size_t)n) != NULL) {
		while (buf[n - 1] == '0')
			n--;
		if (buf[n - 1] == '.')
			n--;
	}
	return n;
}

/* The significant digits a double has (more would be noise). */
#define MAX_DIGITS 17

/*
 * x to the place 10^-decimals as a mantissa and a power of ten, printf's
 * %e made short: no trailing zeros, no '+' or leading zeros in the
 * exponent ("-1.5e82", "2e-300"), "0" where x rounds to 0 at that place.
 * Every double, subnormals too, by printf's exact conversion: nothing is
 * multiplied by a power of ten that could overflow.  Into buf (at least
 * 64 bytes); returns the length.
 */
static int
sci_text(char *buf, double x, int decimals)
{
	char tmp[64], *e;
	int ex, sig, n;

	if (x == 0)
		return snprintf(buf, 64, "0");
	snprintf(tmp, sizeof tmp, "%.*e", MAX_DIGITS - 1, x);
	ex = atoi(strchr(tmp, 'e') + 1);        /* |x| = d.ddd 10^ex */
	sig = ex + decimals + 1;                /* digits down to the place */
	if (sig <= 0) {
		/* 0, or one unit of the place where |x| is half of it */
		if (sig < 0 || tmp[x < 0] < '5')
			return snprintf(buf, 64, "0");
		return snprintf(buf, 64, "%s1e%d", x < 0 ? "-" : "",
		    -decimals);
	}
	snprintf(tmp, sizeof tmp, "%.*e", (sig < MAX_DIGITS ? sig :
	    MAX_DIGITS) - 1, x);
	e = strchr(tmp, 'e');
	n = (int)(e - tmp);
	if (memchr(tmp, '.', (size_t)n) != NULL) {
		while (tmp[n - 1] == '0')
			n--;
		if (tmp[n - 1] == '.')
			n--;
	}
	return snprintf(buf, 64, "%.*se%d", n, tmp, atoi(e + 1));
}

/* Where a number in units of 10^unit is written in fixed notation: its
 * leading digit from 10^-7 to 10^15 (the frame is 100 to 1000 units; a
 * number far beyond is a drawing far from the origin). */
#define SHIFT_MIN (-7)
#define SHIFT_MAX 15

/*
 * The number sci, as sci_text or printf's %e writes it ("-1.25e82",
 * "1e-300", "0"), divided by 10^unit, exactly: its point moved, in fixed
 * notation where its exponent is from SHIFT_MIN to SHIFT_MAX, else with
 * the exponent less unit.  Into buf (at least 64 bytes); the length.
 */
static int
shift_text(char *buf, const char *sci, int unit)
{
	char dig[MAX_DIGITS + 2];
	const char *e = strchr(sci, 'e');
	int nd = 0, n = 0, ex, neg = sci[0] == '-';

	if (e == NULL)                          /* "0" */
		return snprintf(buf, 64, "%s", sci);
	ex = atoi(e + 1) - unit;
	for (const char *c = sci + neg; c < e && nd <= MAX_DIGITS; c++)
		if (*c >= '0' && *c <= '9')
			dig[nd++] = *c;
	if (nd == 0)                            /* no digit: not a number */
		return snprintf(buf, 64, "0");
	while (nd > 1 && dig[nd - 1] == '0')
		nd--;
	if (ex < SHIFT_MIN || ex > SHIFT_MAX)
		return snprintf(buf, 64, "%s%c%s%.*se%d", neg ? "-" : "",
		    dig[0], nd > 1 ? "." : "", nd - 1, dig + 1, ex);
	if (neg)
		buf[n++] = '-';
	if (ex < 0) {                           /* 0.000ddd */
		buf[n++] = '0';
		buf[n++] = '.';
		for (int i = 0; i < -ex - 1; i++)
			buf[n++] = '0';
		for (int i = 0; i < nd; i++)
			buf[n++] = dig[i];
	} else {                                /* ddd[.ddd] */
		for (int i = 0; i <= ex; i++)
			buf[n++] = i < nd ? dig[i] : '0';
		if (nd > ex + 1) {
			buf[n++] = '.';
			for (int i = ex + 1; i < nd; i++)
				buf[n++] = dig[i];
		}
	}
	buf[n] = '\0';
	return n;
}

/* A length x to the place 10^-p->decimals, without trailing zeros or
 * "-0": in fixed notation in the drawing's units (p->fixed), or in
 * units of 10^p->unit (shift_text). */
static void
put_fixed(struct loft_cad_doc *d, double x)
{
	const struct plot *p = d->state;
	char buf[64], sci[64];
	int n;

	if (!isfinite(x)) {
		d->out.bad = LOFT_EGEOM;
		return;
	}
	if (p->fixed) {
		n = fixed_text(buf, x, p->decimals);
	} else {
		sci_text(sci, x, p->decimals);
		n = shift_text(buf, sci, p->unit);
	}
	if (n == 2 && memcmp(buf, "-0", 2) == 0)
		loft_cad_put(d, "0", 1);
	else if (n > 0 && n < (int)sizeof buf)
		loft_cad_put(d, buf, (size_t)n);
}

/* A plane point after cmd, y down the page. */
static void
put_point(struct loft_cad_doc *d, const char *cmd, const double *q)
{
	loft_cad_puts(d, cmd);
	put_fixed(d, q[0]);
	loft_cad_put(d, " ", 1);
	put_fixed(d, -q[1]);
}

/* x as printf's format fmt writes it (one conversion of a double). */
static void
put_printf(struct loft_cad_doc *d, const char *fmt, double x)
{
	char buf[64];
	int n = snprintf(buf, sizeof buf, fmt, x);

	if (n > 0 && n < (int)sizeof buf)
		loft_cad_put(d, buf, (size_t)n);
}

static void
attr(struct loft_cad_doc *d, const char *key, const char *val)
{
	loft_cad_puts(d, " ");
	loft_cad_puts(d, key);
	loft_cad_puts(d, "=\"");
	loft_cad_puts(d, val);
	loft_cad_puts(d, "\"");
}

static int
plot_begin(struct loft_cad_doc *d)
{
	const double *vb = d->o.frame;
	double big = fmax(vb[2], vb[3]), dec;
	long picture = d->o.picture_px;
	struct plot *p;

	if (!isfinite(big) || !(big > 0) || !isfinite(vb[0]) ||
	    !isfinite(vb[1]) || picture <= 0)
		return LOFT_EGEOM;
	if ((p = d->state = calloc(1, sizeof *p)) == NULL)
		return LOFT_ENOMEM;
	p->px = big / (double)picture;
	dec = ceil(-log10(RESOLUTION * big));
	/* a drawing of less than 1e-302: RESOLUTION * big underflows */
	if (!(RESOLUTION * big >= DBL_MIN))
		dec = ceil(-log10(RESOLUTION) - log10(big));
	p->fixed = dec <= FIXED_MAX_DECIMALS && dec >= FIXED_MIN_DECIMALS;
	p->decimals = p->fixed && dec < 0 ? 0 : (int)dec;
	/* the frame's larger side 100 to 1000 units of 10^unit */
	p->unit = p->fixed ? 0 : (int)floor(log10(big)) - 2;
	p->ground = d->o.background ? d->o.background : "#fff";
	loft_cad_puts(d, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
	    "width=\"");
	put_printf(d, "%.1f", (double)picture * (vb[2] / big));
	loft_cad_puts(d, "\" height=\"");
	put_printf(d, "%.1f", (double)picture * (vb[3] / big));
	if (!p->fixed) {
		loft_cad_puts(d, "\" data-unit=\"1e");
		put_printf(d, "%.0f", (double)p->unit);
	}
	loft_cad_puts(d, "\" viewBox=\"");
	for (int k = 0; k < 4; k++) {
		loft_cad_puts(d, k ? " " : "");
		put_fixed(d, vb[k]);
	}
	loft_cad_puts(d, "\">\n<g fill=\"none\" stroke-linecap=\"round\" "
	    "stroke-linejoin=\"round\" stroke-width=\"");
	put_fixed(d, LOFT_PLOT_CURVE_PX * p->px);
	loft_cad_puts(d, "\">\n");
	if (d->o.background != NULL) {
		loft_cad_puts(d, "<rect class=\"background\"");
		attr(d, "fill", d->o.background);
		loft_cad_puts(d, " stroke=\"none\" x=\"");
		put_fixed(d, vb[0]);
		loft_cad_puts(d, "\" y=\"");
		put_fixed(d, vb[1]);
		loft_cad_puts(d, "\" width=\"");
		put_fixed(d, vb[2]);
		loft_cad_puts(d, "\" height=\"");
		put_fixed(d, vb[3]);
		loft_cad_puts(d, "\"/>\n");
	}
	return 0;
}

/* Go on to part of the picture: out of the group of the lines (for
 * the labels' grounds), and for IN_LABELS into the group of the labels. */
static void
to_part(struct loft_cad_doc *d, enum part part)
{
	struct plot *p = d->state;

	if (p->part == IN_LINES)
		loft_cad_puts(d, "</g>\n");
	if (part == IN_LABELS && p->part != IN_LABELS) {
		/* font sizes of a small fraction of a unit do not render
		 * everywhere: the text is set at LOFT_PLOT_FONT_PX and
		 * scaled; a halo of the background's colour under each
		 * letter keeps a label over a line legible */
		loft_cad_puts(d, "<g font-family=\"sans-serif\" font-size=\"");
		put_printf(d, "%.0f", LOFT_PLOT_FONT_PX);
		loft_cad_puts(d, "\"");
		attr(d, "stroke", p->ground);
		loft_cad_puts(d, " stroke-width=\"");
		put_printf(d, "%.0f", HALO_PX);
		loft_cad_puts(d, "\" stroke-linejoin=\"round\" "
		    "paint-order=\"stroke\">\n");
	}
	p->part = part;
}

static int
plot_end(struct loft_cad_doc *d)
{
	struct plot *p = d->state;

	if (p->part != AFTER_LINES)
		loft_cad_puts(d, "</g>\n");
	loft_cad_puts(d, "</svg>\n");
	return 0;
}

static int
plot_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	struct plot *p = d->state;

	p->it = it;
	p->open = 0;
	return 0;
}

/* Begin the record's path element, its style by its class, if it is
 * not begun; then cmd, " M" for a path already begun. */
static void
path(struct loft_cad_doc *d, const char *cmd, const double *q)
{
	struct plot *p = d->state;
	const struct loft_cad_item *it = p->it;
	enum look look = L_STROKE;

	if (p->open) {
		put_point(d, " M", q);
		return;
	}
	p->open = 1;
	for (size_t i = 0; i < sizeof styles / sizeof styles[0]; i++)
		if (strcmp(styles[i].cls, it->cls) == 0)
			look = styles[i].look;
	loft_cad_puts(d, "<path");
	attr(d, "class", it->cls);
	if (look == L_FILLED) {
		attr(d, "fill", it->colour);
		loft_cad_puts(d, " stroke=\"none\"");
	} else {
		attr(d, "stroke", it->colour);
	}
	if (look != L_FILLED && it->width_px > 0) {
		loft_cad_puts(d, " stroke-width=\"");
		put_fixed(d, it->width_px * p->px);
		loft_cad_puts(d, "\"");
	}
	if (look == L_FAINT)
		loft_cad_puts(d, " stroke-opacity=\"0.55\"");
	if (look == L_DASHED) {
		loft_cad_puts(d, " stroke-dasharray=\"");
		put_fixed(d, 5 * p->px);
		loft_cad_puts(d, " ");
		put_fixed(d, 2.5 * p->px);
		loft_cad_puts(d, "\"");
	}
	if (look == L_HOLLOW)
		loft_cad_puts(d, " fill=\"#fff\"");
	loft_cad_puts(d, " d=\"");
	put_point(d, cmd, q);
}

static int
plot_end_record(struct loft_cad_doc *d)
{
	struct plot *p = d->state;

	if (p->open)
		loft_cad_puts(d, "\"/>\n");
	p->open = 0;
	return 0;
}

static int
same_point(const double *a, const double *b)
{
	return a[0] == b[0] && a[1] == b[1];
}

/* Cubic pieces, exactly; a piece that does not begin where the one
 * before ended begins a new subpath. */
static int
plot_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	const double *q = c->ctl, *start = q;
	int dim = c->dim;

	if (c->deg != 3 || dim < 2 || c->npieces == 0)
		return LOFT_EINPUT;
	for (size_t i = 0; i < c->npieces; i++, q += 4 * dim) {
		if (i == 0 || !same_point(q - dim, q))
			path(d, "M", start = q);
		put_point(d, " C", q + dim);
		put_point(d, " ", q + 2 * dim);
		put_point(d, " ", q + 3 * dim);
	}
	if (c->closed && same_point(q - dim, start))
		loft_cad_puts(d, " Z");
	return 0;
}

static int
plot_polyline(struct loft_cad_doc *d, const double *q, size_t n, int dim,
    int closed)
{
	if (n == 0)
		return 0;
	path(d, "M", q);
	for (size_t i = 1; i < n; i++)
		put_point(d, " L", q + i * dim);
	if (closed && same_point(q + (n - 1) * dim, q))
		loft_cad_puts(d, " Z");
	return 0;
}

/* Markers: small discs, each two half-circle arcs. */
static int
plot_points(struct loft_cad_doc *d, const double *q, size_t n, int dim)
{
	const struct plot *p = d->state;
	double r = KNOT_PX * p->px, c[2];

	for (size_t j = 0; j < n; j++) {
		c[0] = q[j * dim] - r;
		c[1] = q[j * dim + 1];
		path(d, "M", c);
		loft_cad_puts(d, " a");
		put_fixed(d, r);
		loft_cad_puts(d, " ");
		put_fixed(d, r);
		loft_cad_puts(d, " 0 1 0 ");
		put_fixed(d, 2 * r);
		loft_cad_puts(d, " 0 a");
		put_fixed(d, r);
		loft_cad_puts(d, " ");
		put_fixed(d, r);
		loft_cad_puts(d, " 0 1 0 ");
		put_fixed(d, -2 * r);
		loft_cad_puts(d, " 0Z");
	}
	return 0;
}

static int
plot_box(struct loft_cad_doc *d, const double *lo, const double *hi)
{
	const struct plot *p = d->state;

	to_part(d, p->part == IN_LINES ? AFTER_LINES : p->part);
	loft_cad_puts(d, "<rect");
	attr(d, "class", p->it->cls);
	attr(d, "fill", p->it->colour);
	loft_cad_puts(d, " stroke=\"none\" x=\"");
	put_fixed(d, lo[0]);
	loft_cad_puts(d, "\" y=\"");
	put_fixed(d, -hi[1]);
	loft_cad_puts(d, "\" width=\"");
	put_fixed(d, hi[0] - lo[0]);
	loft_cad_puts(d, "\" height=\"");
	put_fixed(d, hi[1] - lo[1]);
	loft_cad_puts(d, "\"/>\n");
	return 0;
}

static int
plot_label(struct loft_cad_doc *d, const double *at, double size, int middle,
    const char *text)
{
	const struct plot *p = d->state;

	to_part(d, IN_LABELS);
	loft_cad_puts(d, "<text");
	attr(d, "class", p->it->cls);
	attr(d, "fill", p->it->colour);
	if (middle)
		loft_cad_puts(d, " text-anchor=\"middle\" dy=\"0.35em\"");
	put_point(d, " transform=\"translate(", at);
	if (p->fixed) {
		put_printf(d, ") scale(%.6g)\">", size / LOFT_PLOT_FONT_PX);
	} else {                /* 6 digits, in units of 10^unit */
		char sci[64], buf[64];

		snprintf(sci, sizeof sci, "%.5e", size / LOFT_PLOT_FONT_PX);
		loft_cad_puts(d, ") scale(");
		loft_cad_put(d, buf, (size_t)shift_text(buf, sci, p->unit));
		loft_cad_puts(d, ")\">");
	}
	for (const char *s = text; *s; s++)
		switch (*s) {
		case '&': loft_cad_puts(d, "&amp;"); break;
		case '<': loft_cad_puts(d, "&lt;"); break;
		case '>': loft_cad_puts(d, "&gt;"); break;
		case '"': loft_cad_puts(d, "&quot;"); break;
		default: loft_cad_put(d, s, 1);
		}
	loft_cad_puts(d, "</text>\n");
	return 0;
}

static void
plot_free(struct loft_cad_doc *d)
{
	free(d->state);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_svgplot = {
	.name = "svgplot",
	.title = "SVG picture",
	.begin = plot_begin,
	.end = plot_end,
	.begin_record = plot_begin_record,
	.end_record = plot_end_record,
	.curve = plot_curve,
	.polyline = plot_polyline,
	.points = plot_points,
	.box = plot_box,
	.label = plot_label,
	.free = plot_free,
};
