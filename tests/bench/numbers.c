/*
 * numbers: the floor of fromcad's benchmark: read a file's bytes and
 * convert every line that is a number, as a DXF reader must at the
 * least, with loft's own converter, and print their count and sum.
 *
 *   numbers FILE
 *
 * It reads the file whole, as fromcad does, and splits it into lines
 * the same way; it writes nothing else, so fromcad's time over this is
 * what its entities, geometry and output cost.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "loft.h"

int
main(int argc, char *argv[])
{
	FILE *fp;
	char *buf, *p, *end;
	size_t len = 0, cap = 1 << 20, got;
	double sum = 0, x;
	long n = 0;

	if (argc != 2 || (fp = fopen(argv[1], "rb")) == NULL) {
		fputs("usage: numbers FILE\n", stderr);
		return 2;
	}
	if ((buf = malloc(cap)) == NULL)
		return 1;
	while ((got = fread(buf + len, 1, cap - len, fp)) > 0)
		if ((len += got) == cap && (buf = realloc(buf, cap *= 2)) ==
		    NULL)
			return 1;
	fclose(fp);
	for (p = buf, end = buf + len; p < end;) {
		char *e = memchr(p, '\n', (size_t)(end - p)), *a = p;

		if (e == NULL)
			e = end;
		p = e + 1;
		while (a < e && (*a == ' ' || *a == '\t'))
			a++;
		while (e > a && (e[-1] == ' ' || e[-1] == '\r'))
			e--;
		if (loft_parse_num(a, (size_t)(e - a), &x, NULL) == 0) {
			sum += x;
			n++;
		}
	}
	printf("%ld numbers, sum %.17g\n", n, sum);
	free(buf);
	return 0;
}
