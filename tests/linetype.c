/*
 * linetype.c: the operations of a record type the programs were not
 * written for, `line`: a curve of straight segments, one a row, P_A P_B
 * (2 dim numbers), of degree 1, with no quartic form.  Linked, with
 * lib/types.c built with -DLOFT_TEST_LINE (its table then has a row
 * naming these), into copies of every program in bin/test/line, which
 * tests/linetype.sh runs: each must take a line record (sample,
 * measure, tocad ...: as the same straight curve given as a cubic) or
 * refuse it with a message (patchnew -b, patchdrag: no quartic form),
 * never read past its rows.
 */
#include "internal.h"

/* P = (1 - u) P_A + u P_B, P' = P_B - P_A, P'' = 0. */
static void
line_eval(const double *seg, int dim, double u, double *p, double *d1,
    double *d2)
{
	for (int k = 0; k < dim; k++) {
		if (p != NULL)
			p[k] = (1 - u) * seg[k] + u * seg[dim + k];
		if (d1 != NULL)
			d1[k] = seg[dim + k] - seg[k];
		if (d2 != NULL)
			d2[k] = 0;
	}
}

/* The segment is its own Bezier form of degree 1. */
static int
line_bezier(const double *seg, int dim, double *ctl)
{
	for (int k = 0; k < 2 * dim; k++)
		ctl[k] = seg[k];
	return 1;
}

const struct loft__curve_type loft__test_line_type =
	{ "line", 2, line_eval, NULL, line_bezier, NULL };
