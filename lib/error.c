/*
 * error.c: filling a struct loft_error, the one way every function of
 * the library says what went wrong.  Core (loft.h).
 */
#include <stdarg.h>
#include <stdio.h>

#include "internal.h"

#undef loft_fail        /* the analyser's macro (loft.h), not here */

int
loft_fail(struct loft_error *err, int code, long row, const char *fmt, ...)
{
	va_list ap;

	if (err == NULL)
		return code;
	err->row = row;
	va_start(ap, fmt);
	vsnprintf(err->msg, sizeof err->msg, fmt, ap);
	va_end(ap);
	return code;
}
