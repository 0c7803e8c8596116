/*
 * tandiff: the largest distance between the unit tangents at the knots
 * of two streams of cubic records, record by record (the same knots fitted
 * two ways), as loft_tangent_distance measures it.
 *
 *   tandiff A B   ->   "records N, largest tangent difference D"
 */
#include <stdio.h>

#include "loftprog.h"

int
main(int argc, char *argv[])
{
	struct loft_record ra = { 0 }, rb = { 0 };
	struct loft_reader *a, *b;
	struct loft_error err;
	FILE *fa, *fb;
	double most = 0;
	long n = 0;

	if (argc != 3 || (fa = fopen(argv[1], "r")) == NULL ||
	    (fb = fopen(argv[2], "r")) == NULL) {
		fputs("usage: tandiff A B\n", stderr);
		return 2;
	}
	a = loft_reader_new(fa, argv[1]);
	b = loft_reader_new(fb, argv[2]);
	while (loft_read(a, &ra, &err) == 1 && loft_read(b, &rb, &err) == 1) {
		double d;

		if (ra.nrows != rb.nrows || ra.ncols != rb.ncols ||
		    ra.ncols % 4 != 0) {
			fprintf(stderr, "tandiff: record %ld differs in shape\n",
			    n + 1);
			return 1;
		}
		d = loft_tangent_distance(ra.num, rb.num, ra.nrows,
		    ra.ncols / 4);
		if (d > most)
			most = d;
		n++;
	}
	printf("records %ld, largest tangent difference %.3g\n", n, most);
	return 0;
}
