/*
 * cholesky.c: dense symmetric positive definite systems, solved in place
 * by the Cholesky factor.  Core; shared by normal.c (the least-squares
 * control points of Carriazo et al.) and approx.c (the fairing steps of
 * splinefit -e).
 */
#include <math.h>

#include "internal.h"

int
loft__cholesky_solve(double *a, double *b, size_t n, double rel,
    size_t *at, double *pivot)
{
	double big = 0;

	for (size_t i = 0; i < n; i++)
		if (a[i * n + i] > big)
			big = a[i * n + i];
	for (size_t j = 0; j < n; j++) {
		double d = a[j * n + j];

		for (size_t k = 0; k < j; k++)
			d -= a[j * n + k] * a[j * n + k];
		if (!(d > rel * big)) {
			if (at != NULL)
				*at = j;
			if (pivot != NULL)
				*pivot = big > 0 ? d / big : 0;
			return -1;
		}
		d = sqrt(d);
		a[j * n + j] = d;
		for (size_t i = j + 1; i < n; i++) {
			double s = a[i * n + j];

			for (size_t k = 0; k < j; k++)
				s -= a[i * n + k] * a[j * n + k];
			a[i * n + j] = s / d;
		}
	}
	for (size_t i = 0; i < n; i++) {
		for (size_t k = 0; k < i; k++)
			b[i] -= a[i * n + k] * b[k];
		b[i] /= a[i * n + i];
	}
	for (size_t i = n; i-- > 0;) {
		for (size_t k = i + 1; k < n; k++)
			b[i] -= a[k * n + i] * b[k];
		b[i] /= a[i * n + i];
	}
	return 0;
}
