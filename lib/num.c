/*
 * num.c: strict decimal numbers in, round-tripping numbers out.
 * Every number any loft program reads or writes passes through here.
 */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

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

static int
isdigit_(int c)
{
	return c >= '0' && c <= '9';
}

/* Length of the longest prefix of s[0..len) that is a strict decimal. */
static size_t
scan_decimal(const char *s, size_t len)
{
	size_t i = 0, mant = 0;

	if (i < len && (s[i] == '+' || s[i] == '-'))
		i++;
	while (i < len && isdigit_(s[i]))
		i++, mant++;
	if (i < len && s[i] == '.') {
		i++;
		while (i < len && isdigit_(s[i]))
			i++, mant++;
	}
	if (mant == 0)
		return 0;
	if (i < len && (s[i] == 'e' || s[i] == 'E')) {
		size_t j = i + 1, exp = 0;

		if (j < len && (s[j] == '+' || s[j] == '-'))
			j++;
		while (j < len && isdigit_(s[j]))
			j++, exp++;
		if (exp == 0)
			return 0;
		i = j;
	}
	return i;
}

/* Longest number token we convert; longer ones are refused, not cut. */
#define NUM_MAXLEN 400

int
loft_parse_num(const char *s, size_t len, double *x, struct loft_error *err)
{
	char tmp[NUM_MAXLEN + 1];
	double v;

	if (len == 0 || scan_decimal(s, len) != len)
		return loft_fail(err, LOFT_EINPUT, -1, "'%.*s' is not a number",
		    (int)(len > 40 ? 40 : len), s);
	if (len > NUM_MAXLEN)
		return loft_fail(err, LOFT_EINPUT, -1,
		    "number of %zu characters is too long", len);
	memcpy(tmp, s, len);
	tmp[len] = '\0';
	errno = 0;
	v = strtod(tmp, NULL);
	if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1))
		return loft_fail(err, LOFT_EINPUT, -1,
		    "'%.*s' is out of range", (int)(len > 40 ? 40 : len), s);
	*x = v;
	return 0;
}

int
loft_parse_list(const char *s, double *v, int max, int *n,
    struct loft_error *err)
{
	int k = 0;

	for (;;) {
		size_t len = strcspn(s, ",");

		if (k == max)
			return loft_fail(err, LOFT_EINPUT, -1,
			    "more than %d numbers", max);
		if (loft_parse_num(s, len, &v[k], err) != 0)
			return LOFT_EINPUT;
		k++;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	*n = k;
	return 0;
}

int
loft_parse_int(const char *s, long lo, long hi, long *v,
    struct loft_error *err)
{
	long x = 0;
	size_t i = 0;

	for (; s[i] >= '0' && s[i] <= '9'; i++) {
		if (x > (hi - (s[i] - '0')) / 10) {
			x = hi + 1;     /* too big; keep scanning the digits */
			continue;
		}
		x = 10 * x + (s[i] - '0');
	}
	if (i == 0 || s[i] != '\0' || x < lo || x > hi)
		return loft_fail(err, LOFT_EINPUT, -1, "'%s': want a whole "
		    "number from %ld to %ld", s, lo, hi);
	*v = x;
	return 0;
}

int
loft_parse_real(const char *s, double lo, double hi, double *x,
    struct loft_error *err)
{
	if (loft_parse_num(s, strlen(s), x, err) != 0)
		return LOFT_EINPUT;
	if (!(*x >= lo && *x <= hi))
		return loft_fail(err, LOFT_EINPUT, -1,
		    "'%s': want a number from %g to %g", s, lo, hi);
	return 0;
}

int
loft_parse_word(const char *s, const char *const *words, int *i,
    struct loft_error *err)
{
	size_t len = 0;

	for (*i = 0; words[*i] != NULL; ++*i)
		if (strcmp(s, words[*i]) == 0)
			return 0;
	len = snprintf(err->msg, sizeof err->msg, "'%s': want", s);
	for (int k = 0; words[k] != NULL && len < sizeof err->msg; k++)
		len += snprintf(err->msg + len, sizeof err->msg - len, "%s %s",
		    k == 0 ? "" : (words[k + 1] ? "," : " or"), words[k]);
	err->row = -1;
	return LOFT_EINPUT;
}

/*
 * Lossless output: the shortest of %.15g, %.16g and %.17g that reads back
 * to x.  17 significant digits always do (DBL_DECIMAL_DIG); numbers read
 * from a person's file usually round-trip at 15.  Where the shorter
 * precision switched to exponent form, %.17g may still be shorter (a
 * 17-digit integer), so it is tried too.  One place, so a faster
 * shortest-digits algorithm can replace it.
 */
int
loft_format_num(char *buf, double x, int digits)
{
	char alt[LOFT_NUMBUF];
	int len = 0, alen;

	if (x == 0)
		x = 0;          /* minus zero prints as 0 */
	if (digits > 0) {
		len = snprintf(buf, LOFT_NUMBUF, "%.*g", digits, x);
		/* rounding may pass the largest double, and such text would
		 * not read back: those few numbers go out lossless */
		if (fabs(x) < 1e308 || isfinite(strtod(buf, NULL)))
			return len;
	}
	for (int d = DBL_DIG; d < 17; d++) {
		len = snprintf(buf, LOFT_NUMBUF, "%.*g", d, x);
		if (strtod(buf, NULL) == x) {
			if (memchr(buf, 'e', (size_t)len) == NULL)
				return len;
			break;
		}
		len = 0;
	}
	alen = snprintf(alt, sizeof alt, "%.17g", x);
	if (len == 0 || alen < len) {
		memcpy(buf, alt, (size_t)alen + 1);
		len = alen;
	}
	return len;
}
