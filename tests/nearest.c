/*
 * nearest: the distance of points from a polyline, by brute force over
 * its edges, for tests/approx.sh to measure splinefit -e's curves by
 * a method of its own (no part of libloft).
 *
 *   nearest [-o] POLY POINTS
 *
 * POLY and POINTS hold rows of two numbers (other lines are skipped);
 * POLY is a closed polyline unless -o.  Prints "max D row I mean M": the
 * largest distance of a point of POINTS from POLY, the row of POINTS it
 * is (from 1, counting the rows of numbers only) and the mean distance.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double *
load(const char *file, size_t *n)
{
	char line[512];
	size_t cap = 1024;
	double *p = malloc(2 * cap * sizeof *p), x, y;
	FILE *fp = fopen(file, "r");

	if (fp == NULL || p == NULL) {
		perror(file);
		exit(2);
	}
	*n = 0;
	while (fgets(line, sizeof line, fp) != NULL) {
		if (sscanf(line, "%lf %lf", &x, &y) != 2)
			continue;
		if (*n == cap) {
			cap *= 2;
			if ((p = realloc(p, 2 * cap * sizeof *p)) == NULL)
				exit(2);
		}
		p[2 * *n] = x;
		p[2 * *n + 1] = y;
		++*n;
	}
	fclose(fp);
	return p;
}

/* The distance from (x, y) to the edge a b. */
static double
edge(const double *a, const double *b, double x, double y)
{
	double ex = b[0] - a[0], ey = b[1] - a[1], ee = ex * ex + ey * ey;
	double t = ee > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / ee : 0;

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return hypot(x - a[0] - t * ex, y - a[1] - t * ey);
}

int
main(int argc, char *argv[])
{
	int open = argc > 1 && strcmp(argv[1], "-o") == 0;
	size_t np, nq, at = 0;
	double *p, *q, big = -1, sum = 0;

	if (argc != 3 + open) {
		fputs("usage: nearest [-o] POLY POINTS\n", stderr);
		return 2;
	}
	p = load(argv[1 + open], &np);
	q = load(argv[2 + open], &nq);
	if (np < 2 || nq < 1) {
		fputs("nearest: too few points\n", stderr);
		return 2;
	}
	for (size_t i = 0; i < nq; i++) {
		double d = HUGE_VAL;

		for (size_t j = 0; j + 1 < np + !open; j++)
			d = fmin(d, edge(p + 2 * j, p + 2 * ((j + 1) % np),
			    q[2 * i], q[2 * i + 1]));
		sum += d;
		if (d > big) {
			big = d;
			at = i;
		}
	}
	printf("max %.9g row %zu mean %.9g\n", big, at + 1, sum / nq);
	free(p);
	free(q);
	return 0;
}
