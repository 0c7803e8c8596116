/*
 * cadread.h: the parts the CAD readers (cadread.c, dxfread.c,
 * svgread.c, csvread.c) share; not part of libloft's interface (never
 * installed).  Program layer: the readers write records (loftprog.h).
 */
#ifndef LOFT_CADREAD_H
#define LOFT_CADREAD_H

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
/* Write the n points p (3 numbers each) as rows of dim numbers. */
void loft__pts_put(struct loft_writer *w, const double *p, size_t n, int dim);
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
/* The pieces an arc of radius r and sweep angle a (radians) needs for
 * c->tol: chords, or cubic pieces; -1 when more than LOFT_CADIN_ARC_MAX. */
long loft__arc_chords(const struct loft_cadin *c, double r, double a);
long loft__arc_cubics(const struct loft_cadin *c, double r, double a);
/* The cubic row P_A P_B P'_A P'_B of the Bezier b[0..4) (dim each). */
void loft__bezier_hermite(const double *b, int dim, double *row);
/* s[0..n) for a message: at most size - 1 bytes of it into buf, each
 * control byte as '?', so that a message stays one line; returns buf. */
const char *loft__cadin_quote(char *buf, size_t size, const char *s, size_t n);
/* Whether s[0..n) is word, ignoring ASCII case. */
int loft__word_is(const char *s, size_t n, const char *word);

#endif
