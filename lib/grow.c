/*
 * grow.c: the one growth rule of the library's arrays (internal.h's
 * loft__grow): capacities double, from 16, and never overflow a size_t.
 * Core.
 */
#include <stdlib.h>

#include "internal.h"

int
loft__grow(void **buf, size_t *cap, size_t need, size_t sz)
{
	size_t n = *cap ? *cap : 16;
	void *p;

	if (need <= *cap)
		return 0;
	while (n < need) {
		if (n > ((size_t)-1 / 2) / sz)
			return -1;
		n *= 2;
	}
	if ((p = realloc(*buf, n * sz)) == NULL)
		return -1;
	*buf = p;
	*cap = n;
	return 0;
}
