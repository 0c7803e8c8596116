/*
 * cadread.h: the parts the CAD readers (cadread.c, dxfread.c,
 * svgread.c, csvread.c) share; not part of libloft's interface (never
 * installed).  Program layer: the readers write records (loftprog.h).
 */
#ifndef LOFT_CADREAD_H
#define LOFT_CADREAD_H

#include <stdint.h>

#include "loftprog.h"
#include "internal.h"

struct loft__pts {              /* a growing list of points, 3 numbers each */
	double *p;
	size_t n, cap;
};
/* Append x[0..3); 0, or -1 when out of memory. */
int loft__pts_add(struct loft__pts *s, const double *x);
/* 3 when any point's z is not 0, else 2: a record's dimension. */
int loft__pts_dim(const double *p, size_t n);
/*
 * Echo: numbers a reader writes unchanged go out as the document's own
 * text, not formatted again, where that text is already what
 * loft_format_num(x, 0) would write (see loft__echo_form).  A slot per
 * hash of a double's bits: a number read is noted in its slot (over any
 * other), and a number written finds its text there only if the slot
 * holds the same bits, so output is byte for byte what formatting gives.
 * The texts are in the document doc[0..len) (its first 4 GB), which
 * must outlive the echo.  An echo zeroed but for doc and len is empty.
 */
#define LOFT__ECHO_SLOTS 16384
struct loft__echo {
	const char *doc;                /* the document the texts are in */
	size_t len;
	struct {
		uint64_t bits;
		uint32_t at, n;         /* doc[at..at+n); n 0: empty */
	} slot[LOFT__ECHO_SLOTS];
};
/* Whether s[0..n), read as the number x, is the text loft_format_num(x,
 * 0) writes: "0", or an optional '-', no leading zeros, no trailing
 * zeros after a point, no exponent, at most 3 zeros after "0.", and at
 * most 15 digits after those (decimals of 15 significant digits or
 * fewer read as distinct doubles, DBL_DIG, so such a text is the
 * shortest that reads back, and the only one of its length). */
int loft__echo_form(const char *s, size_t n);
/* loft_parse_num of s[0..n) into *x, noting its text in e (may be NULL)
 * when it has the form; 0, or -1 when s is not a finite number. */
int loft__echo_parse(struct loft__echo *e, const char *s, size_t n, double *x);
/* loft_put_num(w, x), with x's noted text from e when there is one and
 * w writes shortest digits (w->digits 0); e may be NULL. */
void loft__echo_put(const struct loft__echo *e, struct loft_writer *w, double x);
/* loft_put_row of v[0..n) through loft__echo_put. */
void loft__echo_row(const struct loft__echo *e, struct loft_writer *w,
    const double *v, int n);
/* Write the n points p (3 numbers each) as rows of dim numbers, with
 * the texts of e (may be NULL; see struct loft__echo). */
void loft__pts_put(struct loft_writer *w, const struct loft__echo *e,
    const double *p, size_t n, int dim);
/* The sniffs of loft_cadin_readers: whether buf[0..len) is a binary or
 * ASCII DXF (a group code alone on its first line), an XML document
 * (SVG), or a text whose first line names an x and a y column (CSV). */
int loft__dxf_sniff(const char *buf, size_t len);
int loft__svg_sniff(const char *buf, size_t len);
int loft__step_sniff(const char *buf, size_t len);
int loft__csv_sniff(const char *buf, size_t len);
/* Complain about line of the document, printf-style; counts it. */
void loft__cadin_say(struct loft_cadin *c, long line, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;
/* A record was written to c->w from mark on: 0 when it is whole and
 * finite, else -1 after taking it out and complaining at line. */
int loft__cadin_done(struct loft_cadin *c, size_t mark, long line);
/* Write " key=VALUE", s[0..n) with '%', '#' and bytes outside 33..126
 * as %XX (loft.5's attribute values); nothing for n == 0. */
void loft__cadin_put_name(struct loft_writer *w, const char *key, const char *s,
    size_t n);
/* Write " key=i,j,..." of the indices v[0..n) counted from 1 (loft.5's
 * corners= and straight=); nothing for n == 0; w->bad set when out of
 * memory. */
void loft__cadin_put_list(struct loft_writer *w, const char *key,
    const size_t *v, size_t n);
/* Write " straight=..." naming the segments of seg (nseg rows of 4 dim
 * numbers, as a cubic record's; closed: the last meets the first) that
 * are straight lines meeting a curved neighbour with its tangent
 * (loft_straight_spans), as splinefit's straight= on a cubic record. */
void loft__cadin_put_straight(struct loft_writer *w, const double *seg,
    size_t nseg, int dim, int closed);
/* The pieces an arc of radius r and sweep angle a (radians) needs for
 * c->tol: chords, or cubic pieces; -1 when more than LOFT_CADIN_ARC_MAX. */
long loft__arc_chords(const struct loft_cadin *c, double r, double a);
long loft__arc_cubics(const struct loft_cadin *c, double r, double a);
/* The control points u[0..8) (x, y each) of the cubic piece of the unit
 * circle from angle a to a + h (radians): its inner control points
 * (4/3) tan(h/4) along the end tangents (the error of loft__arc_cubics);
 * the last is at angle e (a + h, or the arc's exact end). */
void loft__arc_unit(double a, double h, double e, double *u);
/* The cubic row P_A P_B P'_A P'_B of the Bezier b[0..4) (dim each). */
void loft__bezier_hermite(const double *b, int dim, double *row);
/* s[0..n) for a message: at most size - 1 bytes of it into buf, each
 * control byte as '?', so that a message stays one line; returns buf. */
const char *loft__cadin_quote(char *buf, size_t size, const char *s, size_t n);
/* Whether s[0..n) is word, ignoring ASCII case. */
int loft__word_is(const char *s, size_t n, const char *word);


/* B-splines read from STEP and IGES (bsplineread.c).  A record's name=
 * (the document's name of the entity, may be empty) and entity= (its
 * number in the document, or 0: none). */
struct loft__bsname {
	const char *name;
	size_t nname;
	long entity;
};
/* A B-spline curve: degree, n control points of 3 numbers (z 0 for a
 * plane curve), n + deg + 1 knots, n weights or NULL. */
struct loft__bs {
	int deg;
	size_t n;
	const double *t, *ctl, *w;
};
/* A B-spline surface: degrees p, q; nu by nv points of 3 numbers,
 * u-major; knots; nu nv weights, u-major, or NULL. */
struct loft__bsurf {
	int p, q;
	size_t nu, nv;
	const double *tu, *tv, *ctl, *w;
};
/* Write the curve b as records (see bsplineread.c), whole or not at
 * all; 0, or -1 after complaining at line. */
int loft__bs_curve(struct loft_cadin *c, const struct loft__bs *b,
    const struct loft__bsname *nm, long line);
/* The same for the surface s. */
int loft__bs_surface(struct loft_cadin *c, const struct loft__bsurf *s,
    const struct loft__bsname *nm, long line);
/* One bezier-surface record of degrees m, n and control points net
 * (u-major); 0, or -1 after complaining at line. */
int loft__bs_patch(struct loft_cadin *c, const double *net, int m, int n,
    const struct loft__bsname *nm, long line);
/* The knot vector t of want knots from distinct values val and their
 * multiplicities mult (nval each); 0, or -1 when they do not add up. */
int loft__bs_knots(const double *val, const long *mult, size_t nval,
    size_t want, double *t);

/* Whether buf[0..len) begins as an IGES file: a line of 80 columns
 * whose 73rd is S (igesread.c). */
int loft__iges_sniff(const char *buf, size_t len);
/*
 * What a reader passed over by design (annotations, fills, hidden
 * geometry), counted by kind, for one note per document: "12 TEXT, 3
 * DIMENSION passed over".  Kinds beyond LOFT__PASSED_KINDS are counted
 * together as "other".
 */
#define LOFT__PASSED_KINDS 24
struct loft__passed {
	struct {
		char name[24];
		long n;
	} k[LOFT__PASSED_KINDS];
	int nk;
	long other;
};
/* Count one of kind s[0..n) (compared ignoring ASCII case). */
void loft__passed_add(struct loft__passed *p, const char *s, size_t n);
/* The note "N KIND, ... passed over" and why (e.g. "(annotations; -S
 * makes them errors)") through c->note; nothing when none was counted. */
void loft__passed_say(struct loft_cadin *c, const struct loft__passed *p,
    const char *why);

#endif
