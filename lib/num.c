/*
 * num.c: strict decimal numbers in, round-tripping numbers out.
 * Every number any loft program reads or writes passes through here.
 */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

static int
isdigit_(int c)
{
	return c >= '0' && c <= '9';
}

/*
 * A strict decimal's value as (w + f) 10^e: w the integer of its first 19
 * significant digits (any more are counted into e; *inexact says whether
 * they were not all zeros, 0 < f < 1).  Returns the length of the longest
 * prefix of s[0..len) that is a strict decimal (0: none).
 */
static size_t
scan_decimal(const char *s, size_t len, int *neg, uint64_t *w, long *e,
    int *inexact)
{
	size_t i = 0, mant = 0;
	int sig = 0;

	*neg = 0;
	*w = 0;
	*e = 0;
	*inexact = 0;
	if (i < len && (s[i] == '+' || s[i] == '-'))
		*neg = s[i++] == '-';
	for (int frac = 0; i < len; i++) {
		int d = s[i] - '0';

		if (s[i] == '.' && !frac) {
			frac = 1;
			continue;
		}
		if (!isdigit_(s[i]))
			break;
		mant++;
		if (sig < 19 && (sig > 0 || d != 0)) {
			*w = 10 * *w + (uint64_t)d;
			sig++;
			*e -= frac;
		} else if (sig == 0) {
			*e -= frac;     /* a leading zero */
		} else {
			*e += !frac;    /* a digit past the 19th */
			*inexact |= d != 0;
		}
	}
	if (mant == 0)
		return 0;
	if (i < len && (s[i] == 'e' || s[i] == 'E')) {
		size_t j = i + 1, exp = 0;
		long x = 0;
		int eneg = 0;

		if (j < len && (s[j] == '+' || s[j] == '-'))
			eneg = s[j++] == '-';
		for (; j < len && isdigit_(s[j]); j++, exp++)
			if (x < 100000)         /* far past any double */
				x = 10 * x + (s[j] - '0');
		if (exp == 0)
			return 0;
		*e += eneg ? -x : x;
		i = j;
	}
	return i;
}

/* Longest number token we convert; longer ones are refused, not cut. */
#define NUM_MAXLEN 400

/* Powers of ten that doubles hold exactly. */
static const double exact10[] = {
	1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
	1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
};

/*
 * The double nearest (w + f) 10^e without the C library: Clinger's fast
 * path where w and 10^e are exact doubles (one rounding, the right one),
 * else dtoa.c's product; where some digits were dropped, w and w + 1
 * must give the same double.  Returns 0, or -1 to ask strtod.
 */
static int
decimal_value(uint64_t w, long e, int inexact, double *x)
{
	double hi;

	if (w == 0) {
		*x = 0;
		return 0;
	}
	if (!inexact && w <= (uint64_t)1 << 53 && e >= -22 && e <= 22) {
		*x = e < 0 ? (double)w / exact10[-e] : (double)w * exact10[e];
		return 0;
	}
	if (e < INT_MIN / 2 || e > INT_MAX / 2 ||
	    loft__decimal_to_double(w, (int)e, x) != 0)
		return -1;
	if (inexact && (loft__decimal_to_double(w + 1, (int)e, &hi) != 0 ||
	    hi != *x))
		return -1;
	return 0;
}

int
loft_parse_num(const char *s, size_t len, double *x, struct loft_error *err)
{
	char tmp[NUM_MAXLEN + 1];
	uint64_t w;
	long e;
	int neg, inexact;
	double v;

	if (len == 0 ||
	    scan_decimal(s, len, &neg, &w, &e, &inexact) != len)
		return loft_fail(err, LOFT_EINPUT, -1, "'%.*s' is not a number",
		    (int)(len > 40 ? 40 : len), s);
	if (len > NUM_MAXLEN)
		return loft_fail(err, LOFT_EINPUT, -1,
		    "number of %zu characters is too long", len);
	if (decimal_value(w, e, inexact, &v) == 0) {
		*x = neg ? -v : v;
		return 0;
	}
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
	int big = 0;            /* above hi: no more arithmetic, it could wrap */

	for (; s[i] >= '0' && s[i] <= '9'; i++) {
		if (big || x > (hi - (s[i] - '0')) / 10) {
			big = 1;        /* keep scanning the digits */
			continue;
		}
		x = 10 * x + (s[i] - '0');
	}
	if (i == 0 || s[i] != '\0' || big || x < lo || x > hi)
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
 * The C library's digits, where dtoa.c cannot decide (the tests never
 * saw it happen): printf's %e rounding to the precision asked, or else
 * the fewest digits of it that read back to x > 0.  Laid out as usual.
 */
static int
format_slow(char *buf, double x, int digits)
{
	char tmp[48], *p;
	uint64_t d = 0;
	int prec = digits, e;

	for (prec = digits ? digits : 1; digits == 0 && prec < 17; prec++) {
		snprintf(tmp, sizeof tmp, "%.*e", prec - 1, x);
		if (strtod(tmp, NULL) == x)
			break;
	}
	snprintf(tmp, sizeof tmp, "%.*e", prec - 1, x);
	for (p = tmp; *p != 'e'; p++)
		if (isdigit_(*p))
			d = 10 * d + (uint64_t)(*p - '0');
	e = atoi(p + 1) - (prec - 1);
	return loft__decimal_text(buf, d, e, digits ? digits : 17);
}

/*
 * Lossless output: the fewest significant digits that read back to x
 * (the nearest to x of those), from dtoa.c; or x rounded to digits
 * significant digits.  Laid out as printf's %.17g (or %.{digits}g) lays
 * out digits: positional for decimal exponents from -4 up to the
 * precision less one, else d.ddde+XX; no trailing zeros.
 */
int
loft_format_num(char *buf, double x, int digits)
{
	uint64_t d;
	int e, n, rc, sign = 0;

	if (digits < 0 || digits > 17)
		digits = 0;
	if (x == 0 || !isfinite(x)) {
		if (x == 0)
			x = 0;  /* minus zero prints as 0 */
		return snprintf(buf, LOFT_NUMBUF, "%g", x);
	}
	if (x < 0) {
		buf[sign++] = '-';
		x = -x;
	}
	rc = digits > 0 ? loft__round_digits(x, digits, &d, &e) :
	    loft__shortest(x, &d, &e);
	if (rc != 0)
		n = format_slow(buf + sign, x, digits);
	else
		n = loft__decimal_text(buf + sign, d, e, digits > 0 ? digits :
		    17);
	/* rounding may carry a number near the largest double past it, and
	 * such text would not read back: those few go out lossless */
	if (digits > 0 && x >= 1e308 && !isfinite(strtod(buf + sign, NULL)))
		return loft_format_num(buf, sign ? -x : x, 0);
	return sign + n;
}

int
loft_tol_check(double tol, double size, double rel, struct loft_error *err)
{
	double floor = fmax(rel, LOFT_TOL_ROUNDING);

	if (!(tol > 0) || !isfinite(tol) || !isfinite(size))
		return loft_fail(err, LOFT_EINPUT, -1, "tolerance %g: want a "
		    "distance above 0, for a size that is finite", tol);
	if (tol >= floor * size)
		return 0;
	return loft_fail(err, LOFT_EINPUT, -1, "tolerance %g is below %g of "
	    "the size %g%s", tol, floor, size, floor > LOFT_TOL_ROUNDING ? "" :
	    ": the coordinates' rounding, not the tolerance, would decide the "
	    "result");
}
