/*
 * internal.h: helpers shared by the modules of libloft and not part of
 * its interface (never installed).  Vectors have dim <= LOFT_MAXDIM.
 */
#ifndef LOFT_INTERNAL_H
#define LOFT_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "loft.h"

#ifndef M_PI                    /* XSI, not C99 */
#define M_PI 3.14159265358979323846
#endif
#ifndef M_E
#define M_E 2.7182818284590452354
#endif

static inline double
vdot(const double *a, const double *b, int dim)
{
	double s = 0;

	for (int k = 0; k < dim; k++)
		s += a[k] * b[k];
	return s;
}

static inline double
vnorm(const double *a, int dim)
{
	return sqrt(vdot(a, a, dim));
}

/* d = a - b */
static inline void
vsub(double *d, const double *a, const double *b, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = a[k] - b[k];
}

/* d += s * a */
static inline void
vaxpy(double *d, double s, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] += s * a[k];
}

static inline void
vscale(double *d, double s, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = s * a[k];
}

static inline void
vcopy(double *d, const double *a, int dim)
{
	for (int k = 0; k < dim; k++)
		d[k] = a[k];
}

/* |a - b| */
static inline double
vdist(const double *a, const double *b, int dim)
{
	double d[LOFT_MAXDIM];

	vsub(d, a, b, dim);
	return vnorm(d, dim);
}

/* Scale a to unit length; returns its former length (0: left alone). */
static inline double
vunit(double *a, int dim)
{
	double n = vnorm(a, dim);

	if (n > 0)
		vscale(a, 1 / n, a, dim);
	return n;
}

/* cubic.c: eq. 9 from the chord's length w and the cosines ca, cb of the
 * angles the unit tangents at A and B make with it; as loft_normalise. */
int loft__normalise_cos(double w, double ca, double cb, double alpha,
    double *ma, double *mb);

/* fit.c: 0, or LOFT_E* with err filled, for knots no method can fit. */
int loft__check_knots(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, struct loft_error *err);

/* fit.c: unit end tangents t0, tn of an open curve, given or estimated. */
int loft__open_ends(const struct loft_fit_opts *o, const double *p, size_t n,
    int dim, double *t0, double *tn, struct loft_error *err);

/* cspline.c: the Ferguson and chord-length baselines of loft_fit. */
int loft__fit_cspline(const struct loft_fit_opts *o, const double *p,
    size_t n, int dim, double *seg, struct loft_error *err);

/*
 * dtoa.c: exact decimal conversion.  Each returns 0, or -1 in a rare
 * case its 128-bit arithmetic cannot decide; the caller then asks the C
 * library.  x is finite and positive.
 * loft__shortest: the fewest significant digits d (maybe with trailing
 * zeros) with d 10^e reading back to x, the nearest such to x.
 * loft__round_digits: x rounded to p (1..17) significant digits, ties to
 * even, as printf rounds: d has p digits.
 * loft__decimal_to_double: w 10^e rounded to the nearest double, normal
 * doubles only (-1 for subnormal or overflowing results).
 * loft__decimal_text: d 10^e (d > 0) laid out as printf's %.{prec}g lays
 * out those digits, trailing zeros dropped; returns the length written.
 */
int loft__shortest(double x, uint64_t *d, int *e);
int loft__round_digits(double x, int p, uint64_t *d, int *e);
int loft__decimal_to_double(uint64_t w, int e, double *x);
int loft__decimal_text(char *buf, uint64_t d, int e, int prec);
/* floor(log10(2^q)) and floor(log10(3/4 2^q)), for |q| <= 1200 */
int loft__floor_log10_pow2(int q);
int loft__floor_log10_3q_pow2(int q);

/* Grow *buf to hold at least need elements of size sz; 0 or -1. */
int loft__grow(void **buf, size_t *cap, size_t need, size_t sz);

/* quartic.c: the quartic with coefficient vectors k[0..4] at u (any of
 * p, d1, d2 may be NULL); loft_quartic_eval over pointers. */
void loft__quartic_combine(const double *const *k, int dim, double u,
    double *p, double *d1, double *d2);

/* quartic.c: H5(u) = 16 u^2 (1 - u)^2, the bump of section 4. */
double loft__h5(double u);

/* quartic.c: the quartic coefficients, over x in [0, 1], of
 * H5(a + b x): the restriction of the bump to a piece of it. */
void loft__bump(double a, double b, double *coef);

/* patch.c: 0, or LOFT_EINPUT with err filled, unless rec has the five
 * rows of 10 or 15 numbers of a patch. */
int loft__patch_shape(const struct loft_record *rec, struct loft_error *err);

/* cadread.c: the parts the CAD readers share. */
struct loft__pts {              /* a growing list of points, 3 numbers each */
	double *p;
	size_t n, cap;
};
/* Append x[0..3); 0, or -1 when out of memory. */
int loft__pts_add(struct loft__pts *s, const double *x);
/* 3 when any point's z is not 0, else 2: a record's dimension. */
int loft__pts_dim(const double *p, size_t n);
/* Write the n points p (3 numbers each) as rows of dim numbers. */
void loft__pts_put(struct loft_writer *w, const double *p, size_t n, int dim);
/* Complain about line of the document, printf-style; counts it. */
void loft__cad_say(struct loft_cad *c, long line, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;
/* A record was written to c->w from mark on: 0 when it is whole and
 * finite, else -1 after taking it out and complaining at line. */
int loft__cad_done(struct loft_cad *c, size_t mark, long line);
/* Write " key=VALUE", s[0..n) with '%', '#' and bytes outside 33..126
 * as %XX (loft.5's attribute values); nothing for n == 0. */
void loft__cad_put_name(struct loft_writer *w, const char *key, const char *s,
    size_t n);
/* The pieces an arc of radius r and sweep angle a (radians) needs for
 * c->tol: chords, or cubic pieces; -1 when more than LOFT_CAD_ARC_MAX. */
long loft__arc_chords(const struct loft_cad *c, double r, double a);
long loft__arc_cubics(const struct loft_cad *c, double r, double a);
/* The cubic row P_A P_B P'_A P'_B of the Bezier b[0..4) (dim each). */
void loft__bezier_hermite(const double *b, int dim, double *row);
/* s[0..n) for a message: at most size - 1 bytes of it into buf, each
 * control byte as '?', so that a message stays one line; returns buf. */
const char *loft__cad_quote(char *buf, size_t size, const char *s, size_t n);
/* Whether s[0..n) is word, ignoring ASCII case. */
int loft__word_is(const char *s, size_t n, const char *word);

#endif
