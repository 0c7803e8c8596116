/*
 * numtest.c: loft's number conversion against the C library's, on
 * millions of doubles and decimals, random and chosen at the edges.
 *
 * References: strtod (correctly rounded in glibc) for reading; printf's
 * %.{n}e and %.{n}g (exact in glibc) for digits, for rounding to n
 * digits, and for the shortest length: the fewest digits n at which
 * printf's correctly rounded %.{n-1}e reads back (the shortest decimal
 * may be shorter still at a power of two, never longer).
 * Deterministic: a fixed xorshift seed.
 */
#include <errno.h>
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"
#include "check.h"

static uint64_t rng = 0x2545f4914f6cdd1dULL;

static uint64_t
next(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return rng;
}

static double
from_bits(uint64_t b)
{
	double x;

	memcpy(&x, &b, sizeof x);
	return x;
}

static uint64_t
to_bits(double x)
{
	uint64_t b;

	memcpy(&b, &x, sizeof b);
	return b;
}

/* ------------------------------------------------------------------ */
/* floor(log10(2^q)) by integer arithmetic */

static void
test_log10(void)
{
	int bad = 0, unsure = 0;

	for (int q = -1200; q <= 1200; q++) {
		long double a = q * log10l(2.0L);
		long double b = a + log10l(0.75L);

		/* long double is good to 1e-16 here; an integer within 1e-9
		 * of either value would leave the reference unsure */
		if (q != 0 && (fabsl(a - roundl(a)) < 1e-9L ||
		    fabsl(b - roundl(b)) < 1e-9L))
			unsure++;
		if (loft__floor_log10_pow2(q) != (int)floorl(a) ||
		    loft__floor_log10_3q_pow2(q) != (int)floorl(b))
			bad++;
	}
	CHECK(unsure == 0, "%d exponents too near an integer to check", unsure);
	CHECK(bad == 0, "floor(log10 2^q) wrong for %d exponents", bad);
}

/* ------------------------------------------------------------------ */
/* shortest output */

struct tally {
	long n, unread, unparsed, longer, notshortest, notnearest, layout;
	long refused;
};

/* Significant digits of printf's %.{n-1}e of x > 0, and its exponent. */
static void
printf_digits(double x, int n, char *dig, int *exp10)
{
	char buf[64], *p, *o = dig;

	snprintf(buf, sizeof buf, "%.*e", n - 1, x);
	for (p = buf; *p != 'e'; p++)
		if (*p >= '0' && *p <= '9')
			*o++ = *p;
	*o = '\0';
	*exp10 = atoi(p + 1);
}

static int
reads_back(double x, int n)
{
	char buf[64];

	snprintf(buf, sizeof buf, "%.*e", n - 1, x);
	return strtod(buf, NULL) == x;
}

/* The fewest digits at which printf's rounding reads back (1..17);
 * reading back is monotone in n, so a binary search finds it. */
static int
printf_shortest(double x)
{
	int lo = 1, hi = 17;

	while (lo < hi) {
		int mid = (lo + hi) / 2;

		if (reads_back(x, mid))
			hi = mid;
		else
			lo = mid + 1;
	}
	return lo;
}

/* The digits and exponent of loft's text s (sign, point, exponent form). */
static void
text_digits(const char *s, char *dig, int *exp10)
{
	const char *p = s, *e;
	char *o = dig;
	int point = -1, k = 0;

	if (*p == '-')
		p++;
	for (; *p && *p != 'e'; p++) {
		if (*p == '.') {
			point = k;
			continue;
		}
		if (o == dig && *p == '0') {    /* a leading zero */
			k++;
			continue;
		}
		*o++ = *p;
		k++;
	}
	*o = '\0';
	/* strip trailing zeros of an integer written out */
	while (o > dig + 1 && o[-1] == '0')
		*--o = '\0';
	e = strchr(s, 'e');
	if (point < 0)
		point = k;
	/* the first significant digit's place in the string */
	{
		int lead = 0;

		for (p = s + (*s == '-'); *p && *p != 'e'; p++) {
			if (*p == '.')
				continue;
			if (*p != '0')
				break;
			lead++;
		}
		*exp10 = point - lead - 1 + (e ? atoi(e + 1) : 0);
	}
}

/* Format x > 0 or < 0 both ways and check all the claims. */
static void
check_shortest(double x, struct tally *t)
{
	char out[LOFT_NUMBUF], ref[64], dig[40], rdig[40];
	double y;
	struct loft_error err;
	uint64_t d;
	int e, len, n, m, xe, re;

	if (!isfinite(x) || x == 0)
		return;
	t->n++;
	len = loft_format_num(out, x, 0);
	if (strtod(out, NULL) != x || to_bits(strtod(out, NULL)) != to_bits(x))
		t->unread++;
	if (loft_parse_num(out, (size_t)len, &y, &err) != 0 ||
	    to_bits(y) != to_bits(x))
		t->unparsed++;
	if (len > snprintf(ref, sizeof ref, "%.17g", x))
		t->longer++;
	if (loft__shortest(fabs(x), &d, &e) != 0)
		t->refused++;
	/* positional exactly where %.17g is */
	if ((strchr(out, 'e') != NULL) != (strchr(ref, 'e') != NULL))
		t->layout++;
	text_digits(out, dig, &xe);
	m = (int)strlen(dig);
	n = printf_shortest(fabs(x));
	if (m > n) {
		t->notshortest++;
	} else if (m == n) {
		printf_digits(fabs(x), n, rdig, &re);
		if (strcmp(dig, rdig) != 0 || xe != re)
			t->notnearest++;
	}
}

static void
report_shortest(const char *what, const struct tally *t)
{
	CHECK(t->unread == 0, "%s: %ld of %ld do not read back with strtod",
	    what, t->unread, t->n);
	CHECK(t->unparsed == 0, "%s: %ld of %ld do not read back with "
	    "loft_parse_num", what, t->unparsed, t->n);
	CHECK(t->longer == 0, "%s: %ld of %ld longer than %%.17g", what,
	    t->longer, t->n);
	CHECK(t->notshortest == 0, "%s: %ld of %ld have more digits than "
	    "printf needs", what, t->notshortest, t->n);
	CHECK(t->notnearest == 0, "%s: %ld of %ld not printf's digits where as "
	    "short", what, t->notnearest, t->n);
	CHECK(t->layout == 0, "%s: %ld of %ld laid out unlike %%.17g", what,
	    t->layout, t->n);
	CHECK(t->refused == 0, "%s: the 128-bit product left %ld of %ld "
	    "undecided", what, t->refused, t->n);
}

static void
test_shortest_random(void)
{
	struct tally t = { 0 };

	for (int i = 0; i < 400000; i++)
		check_shortest(from_bits(next()), &t);
	report_shortest("random bits", &t);
}

static void
test_shortest_edges(void)
{
	struct tally t = { 0 };
	double x;

	/* every power of two (the uneven intervals), and its neighbours */
	for (int k = -1074; k <= 1023; k++) {
		x = ldexp(1, k);
		check_shortest(x, &t);
		check_shortest(nextafter(x, 0), &t);
		check_shortest(nextafter(x, INFINITY), &t);
		check_shortest(-x, &t);
	}
	/* every power of ten a double comes near, and its neighbours */
	for (int k = -323; k <= 308; k++) {
		char s[16];

		snprintf(s, sizeof s, "1e%d", k);
		x = strtod(s, NULL);
		check_shortest(x, &t);
		check_shortest(nextafter(x, 0), &t);
		check_shortest(nextafter(x, INFINITY), &t);
	}
	/* subnormals: the smallest ones, and random ones */
	for (uint64_t c = 1; c <= 20000; c++)
		check_shortest(from_bits(c), &t);
	for (int i = 0; i < 50000; i++)
		check_shortest(from_bits(next() & 0xfffffffffffffULL), &t);
	/* the largest and smallest normal doubles, whole numbers, 2^53 */
	check_shortest(DBL_MAX, &t);
	check_shortest(nextafter(DBL_MAX, 0), &t);
	check_shortest(DBL_MIN, &t);
	for (int i = 1; i <= 100000; i++)
		check_shortest(i, &t);
	for (int i = -100; i <= 100; i++)
		check_shortest(9007199254740992.0 + 2 * i, &t);
	report_shortest("edge doubles", &t);
}

/* Decimals as people write them: up to 8 digits, point anywhere. */
static void
test_shortest_decimals(void)
{
	struct tally t = { 0 };
	char s[64];

	for (int i = 0; i < 200000; i++) {
		uint64_t r = next();
		int digits = 1 + (int)(r % 8), shift = (int)(r >> 8 & 31) - 12;
		long m = (long)(r >> 16 & 0x7fffffff) % 100000000;

		for (int k = digits; k < 8; k++)
			m /= 10;
		snprintf(s, sizeof s, "%lde%d", m, shift - digits);
		check_shortest(strtod(s, NULL), &t);
	}
	report_shortest("short decimals", &t);
}

/* A few outputs worked out by hand. */
static void
test_shortest_text(void)
{
	static const struct { double x; int digits; const char *want; } c[] = {
		{ 0.1, 0, "0.1" }, { -1.5, 0, "-1.5" }, { 100, 0, "100" },
		{ 0.0001, 0, "0.0001" },        /* exponent -4: positional */
		{ 0.00001, 0, "1e-05" },        /* -5: exponent form */
		{ 1e16, 0, "10000000000000000" },       /* 16: positional */
		{ 1e17, 0, "1e+17" }, { 1e21, 0, "1e+21" },
		{ 123456789012345680.0, 0, "1.2345678901234568e+17" },
		{ 4.9406564584124654e-324, 0, "5e-324" },
		{ DBL_MAX, 0, "1.7976931348623157e+308" },
		{ 2.2250738585072014e-308, 0, "2.2250738585072014e-308" },
		{ 1.0 / 3, 0, "0.3333333333333333" },
		{ 2.0 / 3, 0, "0.6666666666666666" },
		{ 9007199254740993.0, 0, "9007199254740992" },
		{ -0.0, 0, "0" }, { 0, 0, "0" }, { -0.0, 6, "0" },
		{ 1.0 / 3, 6, "0.333333" }, { 123456, 3, "1.23e+05" },
		{ 2.5, 1, "2" }, { 3.5, 1, "4" },       /* ties to even */
		{ 0.125, 2, "0.12" }, { 0.375, 2, "0.38" },
		{ 9.5, 1, "1e+01" }, { 99999.95, 6, "99999.9" },
		{ 1e-5, 6, "1e-05" }, { 1234567, 6, "1.23457e+06" },
		{ 100, 6, "100" }, { 0.1, 17, "0.10000000000000001" },
	};
	char buf[LOFT_NUMBUF];

	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		loft_format_num(buf, c[i].x, c[i].digits);
		CHECK(strcmp(buf, c[i].want) == 0, "%.17g with %d digits: "
		    "'%s', want '%s'", c[i].x, c[i].digits, buf, c[i].want);
	}
}

/* ------------------------------------------------------------------ */
/* rounding to p digits: byte for byte printf's %.{p}g */

static void
test_digits(void)
{
	char out[LOFT_NUMBUF], ref[64];
	long n = 0, differ = 0, refused = 0;
	uint64_t d;
	int e;

	for (int i = 0; i < 500000; i++) {
		uint64_t r = next();
		int p = 1 + (int)(r % 17);
		double x;

		switch (i % 4) {
		case 0:         /* random bits */
			x = from_bits(next());
			break;
		case 1:         /* a short binary fraction: exact ties */
			x = ldexp((double)(next() % 100000), -(int)(r >> 8 & 15));
			break;
		case 2:         /* the size of coordinates */
			x = (double)(next() % 2000000) / 1000 - 1000;
			break;
		default:        /* p + 1 digits ending in 5: near ties */
			snprintf(ref, sizeof ref, "%llu5e%d",
			    (unsigned long long)(next() % 100000000000000000ULL),
			    (int)(r >> 8 & 63) - 40);
			x = strtod(ref, NULL);
			break;
		}
		if (!isfinite(x) || x == 0)
			continue;
		n++;
		loft_format_num(out, x, p);
		snprintf(ref, sizeof ref, "%.*g", p, x);
		/* rounded past the largest double, printf's text does not read
		 * back; loft writes those lossless instead */
		if (!isfinite(strtod(ref, NULL))) {
			n--;
			CHECK(strtod(out, NULL) == x, "-p %d of %.17g: '%s' does "
			    "not read back", p, x, out);
			continue;
		}
		if (strcmp(out, ref) != 0) {
			if (differ++ < 5)
				fprintf(stderr, "-p %d of %.17g: '%s', printf "
				    "'%s'\n", p, x, out, ref);
		}
		if (loft__round_digits(fabs(x), p, &d, &e) != 0)
			refused++;
	}
	CHECK(differ == 0, "%ld of %ld differ from printf's %%.{p}g", differ, n);
	/* and the cases near the largest double are met: DBL_MAX at -p 3
	 * rounds to 1.80e308 */
	loft_format_num(out, DBL_MAX, 3);
	CHECK(strtod(out, NULL) == DBL_MAX, "-p 3 of DBL_MAX: '%s'", out);
	loft_format_num(out, -DBL_MAX, 1);
	CHECK(strtod(out, NULL) == -DBL_MAX, "-p 1 of -DBL_MAX: '%s'", out);
	/* the exact ties are settled exactly: only near misses may be left
	 * to printf, at most a handful in a million */
	CHECK(refused <= 10, "%ld of %ld left to printf", refused, n);
}

/* ------------------------------------------------------------------ */
/* reading: bit for bit strtod */

struct rtally {
	long n, differ;
};

static void
check_parse(const char *s, struct rtally *t)
{
	struct loft_error err;
	double x = 0, ref;
	int rc = loft_parse_num(s, strlen(s), &x, &err), bad;

	errno = 0;
	ref = strtod(s, NULL);
	bad = !isfinite(ref) || (errno == ERANGE && fabs(ref) > 1);
	t->n++;
	if (bad ? rc == 0 : (rc != 0 || to_bits(x) != to_bits(ref))) {
		if (t->differ++ < 5)
			fprintf(stderr, "'%s': loft %.17g (rc %d), strtod "
			    "%.17g\n", s, x, rc, ref);
	}
}

/* Write odd 5^j in decimal (j <= 40): with e-j after it, the exact
 * halfway point odd 2^-j between two doubles when odd = 2c + 1. */
static void
odd_times_pow5(uint64_t odd, int j, char *out)
{
	uint32_t limb[8] = { 0 };       /* base 10^9, little-endian */
	int n = 3;

	limb[0] = (uint32_t)(odd % 1000000000);
	limb[1] = (uint32_t)(odd / 1000000000 % 1000000000);
	limb[2] = (uint32_t)(odd / 1000000000 / 1000000000);
	for (int k = 0; k < j; k++) {
		uint64_t carry = 0;

		for (int i = 0; i < 8; i++) {
			uint64_t v = (uint64_t)limb[i] * 5 + carry;
			limb[i] = (uint32_t)(v % 1000000000);
			carry = v / 1000000000;
		}
	}
	for (n = 7; n > 0 && limb[n] == 0; n--)
		;
	out += sprintf(out, "%u", limb[n]);
	while (--n >= 0)
		out += sprintf(out, "%09u", limb[n]);
}

static void
test_parse(void)
{
	static const char *const edges[] = {
		"4.9406564584124654e-324", "2.4703282292062327e-324",
		"2.4703282292062328e-324", "1e-323", "2.2250738585072011e-308",
		"2.2250738585072014e-308", "1.7976931348623157e308",
		"1.7976931348623158e308", "1.797693134862315807e308",
		"1.7976931348623159e308", "1e308", "1e309", "1e-400",
		"9007199254740993", "9007199254740992.5", "0.1", "1e22",
		"1e23", "123456789012345678901234567890", "0.000000000000000000000001",
		"7.2057594037927933e16", "3.0517578125e-05",
		("179769313486231580793728971405303415079934132710037826936173778"
		    "98076217602437378063125469300512350000000000000000"), "0",
		"-0", "00000000000000000000000000001.5",
		"1.00000000000000011102230246251565404236316680908203125",
		"1.00000000000000011102230246251565404236316680908203124",
		"1.00000000000000011102230246251565404236316680908203126",
	};
	struct rtally t = { 0 };
	char s[128];

	for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++)
		check_parse(edges[i], &t);
	for (int i = 0; i < 300000; i++) {
		double x = from_bits(next());
		int p = 1 + (int)(next() % 25);

		if (!isfinite(x))
			continue;
		snprintf(s, sizeof s, "%.*e", p - 1, x);      /* 1..25 digits */
		check_parse(s, &t);
	}
	for (int i = 0; i < 300000; i++) {
		/* random digit strings, point and exponent anywhere */
		uint64_t r = next();
		int nd = 1 + (int)(r % 24), point = (int)(r >> 8 & 31) % (nd + 1);
		char *o = s;

		if (r >> 40 & 1)
			*o++ = '-';
		for (int k = 0; k < nd; k++) {
			if (k == point)
				*o++ = '.';
			*o++ = (char)('0' + next() % 10);
		}
		sprintf(o, "e%d", (int)((r >> 16) % 700) - 350);
		check_parse(s, &t);
	}
	for (int i = 0; i < 240000; i++) {
		/* halfway between two doubles, exactly, and a hair either
		 * side: (2c + 1) 2^(q-1) with q - 1 = -j, as (2c+1) 5^j e-j */
		uint64_t c = next() >> 11 | (uint64_t)1 << 52;
		int j = (int)(next() % 41), len;
		const char *tail = i % 3 == 1 ? "0001" : "";

		odd_times_pow5(2 * c + 1, j, s);
		len = (int)strlen(s);
		if (i % 3 == 2) {       /* just below: ...4999 */
			int k = len - 1;

			while (s[k] == '0')
				s[k--] = '9';
			s[k]--;
			strcat(s, "9999");
		}
		sprintf(s + strlen(s), "%se-%d", tail, j + (i % 3 ? 4 : 0));
		check_parse(s, &t);
	}
	CHECK(t.differ == 0, "%ld of %ld strings read unlike strtod", t.differ,
	    t.n);
}

/* ------------------------------------------------------------------ */
/* echo (cadread.c): a reader's text stands for the number only where
 * it is what loft_format_num writes.  References: strtod for the value,
 * printf's shortest length for the digits, and the writer itself for
 * the bytes; forms worked out by hand. */

/* A random decimal text, echo-able or not: sign, integer digits (with
 * leading zeros at times), point, fraction (trailing zeros at times),
 * an exponent at times. */
static void
random_text(char *s)
{
	static const char *const sign[] = { "", "", "", "-", "+" };
	int ni = (int)(next() % 19), nf = (int)(next() % 19), k = 0;

	k += sprintf(s + k, "%s", sign[next() % 5]);
	for (int i = 0; i < ni; i++)
		s[k++] = (char)('0' + (i == 0 && next() % 4 ? 1 + next() % 9 :
		    next() % 10));
	if (ni == 0 || nf > 0 || next() % 8 == 0)
		s[k++] = '.';
	for (int i = 0; i < nf; i++)
		s[k++] = (char)('0' + (i < 5 && ni == 0 && next() % 3 == 0 ? 0 :
		    next() % 10));
	if (ni + nf == 0)
		s[k++] = '7';
	if (next() % 16 == 0)
		k += sprintf(s + k, "e%d", (int)(next() % 40) - 20);
	s[k] = '\0';
}

/* Significant digits of a positional text: first to last nonzero. */
static int
sig_digits(const char *s)
{
	int first = -1, last = -1, k = 0;

	for (const char *p = s; *p; p++) {
		if (*p < '0' || *p > '9')
			continue;
		if (*p != '0') {
			if (first < 0)
				first = k;
			last = k;
		}
		k++;
	}
	return first < 0 ? 0 : last - first + 1;
}

static void
test_echo_form(void)
{
	static const char *const yes[] = { "0", "1", "-1", "0.5", "-0.1",
	    "1200", "0.0001234", "-0.000999", "123456789012345",
	    "0.123456789012345", "99999999999999.9", "-3.14159265358979" };
	static const char *const no[] = { "", "-", "+1", "01", "00.5", "1.0",
	    "1.", ".5", "-.5", "0.", "0.00001", "0.0000123", "-0", "0.0",
	    "1e3", "1E+03", "1234567890123456", "0.1234567890123456",
	    "1 ", " 1", "1,5", "0x10", "inf", "nan", "--1", "1.2.3" };
	long n = 0, echoed = 0, wrong = 0;
	char s[64], out[LOFT_NUMBUF];

	for (size_t i = 0; i < sizeof yes / sizeof yes[0]; i++)
		CHECK(loft__echo_form(yes[i], strlen(yes[i])), "'%s' is written "
		    "as it stands, but is not taken as such", yes[i]);
	for (size_t i = 0; i < sizeof no / sizeof no[0]; i++)
		CHECK(!loft__echo_form(no[i], strlen(no[i])), "'%s' is not "
		    "how loft writes its number, but is taken as such", no[i]);
	for (; n < 2000000; n++) {
		double x;

		random_text(s);
		if (!loft__echo_form(s, strlen(s)))
			continue;
		echoed++;
		x = strtod(s, NULL);
		loft_format_num(out, x, 0);
		if (strcmp(out, s) != 0 || (x != 0 && printf_shortest(fabs(x)) !=
		    sig_digits(s))) {
			if (wrong++ < 5)
				fprintf(stderr, "echo: '%s' is written '%s'\n",
				    s, out);
		}
	}
	CHECK(wrong == 0, "%ld of %ld texts taken as written are not",
	    wrong, echoed);
	/* the generator must reach the form often, or this proves little */
	CHECK(echoed > n / 20, "only %ld of %ld random texts had the form",
	    echoed, n);
}

/* Numbers through an echo come out byte for byte as through the
 * writer alone: noted, overwritten in their slots, never noted (minus
 * zero, a sum), and with -p digits. */
static void
test_echo_put(void)
{
	static struct loft__echo e;
	static char doc[1 << 20];
	struct loft_writer a = { 0 }, b = { 0 };
	size_t k = 0;
	long n = 0;

	for (int digits = 0; digits <= 6; digits += 6) {
		memset(&e, 0, sizeof e);
		e.doc = doc;
		e.len = sizeof doc;
		a.digits = b.digits = digits;
		a.len = b.len = 0;
		k = 0;
		for (int rec = 0; rec < 200; rec++) {
			double v[400];
			int m = 1 + (int)(next() % 400);

			for (int i = 0; i < m; i++) {
				char *s = doc + k;

				random_text(s);
				if (loft__echo_parse(&e, s, strlen(s), &v[i]) != 0)
					v[i] = -0.0;
				k += strlen(s) + 1;
				if (k > sizeof doc - 64)
					k = 0;
				if (i % 7 == 3)
					v[i] += v[i - 1];
			}
			for (int i = 0; i < m; i++) {
				loft__echo_put(&e, &a, v[i]);
				loft_put_num(&b, v[i]);
				if (i % 3 == 2) {
					loft_end_line(&a);
					loft_end_line(&b);
				}
			}
			n += m;
		}
		CHECK(a.len == b.len && memcmp(a.buf, b.buf, a.len) == 0,
		    "-p %d: %ld numbers through the echo differ from the "
		    "writer's", digits, n);
	}
	loft_writer_free(&a);
	loft_writer_free(&b);
}

int
main(void)
{
	test_log10();
	test_shortest_text();
	test_shortest_edges();
	test_shortest_decimals();
	test_shortest_random();
	test_digits();
	test_parse();
	test_echo_form();
	test_echo_put();
	return check_done("numtest");
}
