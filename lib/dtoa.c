/*
 * dtoa.c: exact conversion between doubles and decimals, with 128-bit
 * powers of ten (pow10.h) instead of big numbers.
 *
 * Every product here carries an error bound, and every decision that the
 * bound cannot settle is either settled exactly (is the value an integer,
 * a half-integer?) or refused with -1, so that the caller can fall back
 * to the C library.  The papers behind it prove that with 128 bits the
 * refusals do not happen for the shortest digits; the tests count them.
 *
 * The shortest digits follow R. Giulietti, "The Schubfach way to render
 * doubles" (2020): scale the rounding interval of x by the power of ten
 * that makes its width between 1 and 10; then the shortest decimal in it
 * is the one multiple of 10 it holds, if any, else the integer nearest x.
 * Parsing follows the idea of D. Lemire, "Number parsing at a gigabyte
 * per second" (2021): one 64 x 128-bit product gives the 54 leading bits
 * of w * 10^e, and the exact answer unless w * 10^e lies within the
 * product's error of a halfway point.
 */
#include <string.h>

#include "internal.h"
#include "pow10.h"

/* floor(log10(2)) * 2^32 and floor(-log10(3/4) * 2^32), rounded; with
 * them floor_div below gives floor(q log10 2) and floor(log10(3/4 2^q))
 * exactly for |q| <= 1200 (checked for every such q by tests/numtest.c). */
#define LOG10_2_32      1292913986LL
#define LOG10_4_3_32    536607788LL

#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 u128;

/* The 128-bit product a * b: low half returned, high half in *hi. */
static inline uint64_t
mul64(uint64_t a, uint64_t b, uint64_t *hi)
{
	u128 p = (u128)a * b;

	*hi = (uint64_t)(p >> 64);
	return (uint64_t)p;
}
#else
static inline uint64_t
mul64(uint64_t a, uint64_t b, uint64_t *hi)
{
	uint64_t al = a & 0xffffffff, ah = a >> 32;
	uint64_t bl = b & 0xffffffff, bh = b >> 32;
	uint64_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
	uint64_t mid = (ll >> 32) + (lh & 0xffffffff) + (hl & 0xffffffff);

	*hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
	return (mid << 32) | (ll & 0xffffffff);
}
#endif

static inline int
count_trailing_zeros(uint64_t c)
{
#if defined(__GNUC__)
	return __builtin_ctzll(c);
#else
	int n = 0;

	while (!(c & 1))
		c >>= 1, n++;
	return n;
#endif
}

static inline int
count_leading_zeros(uint64_t c)
{
#if defined(__GNUC__)
	return __builtin_clzll(c);
#else
	int n = 0;

	while (!(c >> 63))
		c <<= 1, n++;
	return n;
#endif
}

/* floor(a / 2^32), for a of either sign */
static inline int
floor_div32(long long a)
{
	return a >= 0 ? (int)(a >> 32) : -(int)((-a - 1) >> 32) - 1;
}

int
loft__floor_log10_pow2(int q)
{
	return floor_div32(q * LOG10_2_32);
}

int
loft__floor_log10_3q_pow2(int q)
{
	return floor_div32(q * LOG10_2_32 - LOG10_4_3_32);
}

/* The 192-bit product c * g(e) as three words, least significant first. */
static inline void
mul192(uint64_t c, int e, uint64_t w[3])
{
	const uint64_t *g = pow10_g[e - POW10_MIN];
	uint64_t a1, b1, b0, a0 = mul64(c, g[1], &a1);

	b0 = mul64(c, g[0], &b1);
	w[0] = a0;
	w[1] = a1 + b0;
	w[2] = b1 + (w[1] < b0);
}

/* (w >> s) mod 2^64, for 0 <= s < 192 */
static inline uint64_t
bits64(const uint64_t w[3], int s)
{
	int i = s / 64, r = s % 64;
	uint64_t hi = i < 2 ? w[i + 1] : 0;

	return r ? w[i] >> r | hi << (64 - r) : w[i];
}

/* Whether c * 2^q * 10^e is an integer. */
static int
is_integer(uint64_t c, int q, int e)
{
	uint64_t five = 1;

	if (count_trailing_zeros(c) + q + e < 0)
		return 0;
	if (e >= 0)
		return 1;
	if (e < -27)            /* 5^28 > 2^64 > c */
		return 0;
	for (int i = 0; i < -e; i++)
		five *= 5;
	return c % five == 0;
}

/*
 * T = c * 2^q * 10^e for c < 2^56, where T < 2^64 and c g 2^(q + b) has
 * its binary point at least 64 + 56 bits up (true wherever it is used
 * below).  Stores floor(U) in *ip and the 64 bits after U's binary point
 * in *fp, where U = c g 2^(q + b) >= T, U - T < c 2^(q + b) < 2^-64 as g
 * is 10^e 2^-b rounded up.  So T - *ip lies strictly between
 * (*fp - 1) 2^-64 and (*fp + 1) 2^-64.
 */
static inline void
scale(uint64_t c, int q, int e, uint64_t *ip, uint64_t *fp)
{
	uint64_t w[3];
	int sh = -(q + pow10_b[e - POW10_MIN]);

	mul192(c, e, w);
	*ip = bits64(w, sh);
	*fp = bits64(w, sh - 64);
}

/*
 * Where T = c 2^q 10^e lies against *ip (scale's integer part), given
 * f (its fraction bits): 1 when T = *ip exactly, 0 when *ip < T < *ip + 1,
 * -1 when the product cannot tell.
 */
static int
where(uint64_t c, int q, int e, uint64_t f)
{
	if (f != 0)
		return 0;
	return is_integer(c, q, e) ? 1 : -1;
}

/*
 * Whether T (as scale left it, f its fraction bits) rounds up to the next
 * integer, ties to an even integer part ip: 1 up, 0 down, -1 undecided.
 */
static int
rounds_up(uint64_t c, int q, int e, uint64_t ip, uint64_t f)
{
	const uint64_t half = (uint64_t)1 << 63;

	if (f != half)
		return f > half;
	/* T within 2^-64 of ip + 1/2: a tie only if 2T is an integer */
	if (!is_integer(c, q + 1, e))
		return -1;
	return (int)(ip & 1);
}

int
loft__shortest(double x, uint64_t *digits, int *exp10)
{
	uint64_t bits, c, s, sl, sr, fb, fl, fr, pick;
	int be, q, k, boundary, wl, wr, closed;

	memcpy(&bits, &x, sizeof bits);
	be = (int)(bits >> 52 & 0x7ff);
	c = bits & (((uint64_t)1 << 52) - 1);
	if (be != 0) {
		c |= (uint64_t)1 << 52;
		q = be - 1075;
	} else {
		q = -1074;
	}
	/*
	 * x = c 2^q reads back from anything in the interval between the
	 * midpoints to its neighbours, [4c - 2, 4c + 2] 2^(q-2), ends
	 * included when c is even (ties read back to even).  Where c is a
	 * power of two the neighbour below is twice as close: 4c - 1.
	 */
	boundary = c == (uint64_t)1 << 52 && be > 1;
	closed = !(c & 1);
	/* 10^k <= the interval's width < 10^(k+1) */
	k = boundary ? loft__floor_log10_3q_pow2(q) : loft__floor_log10_pow2(q);
	scale(4 * c, q - 2, -k, &s, &fb);
	scale(4 * c - 2 + boundary, q - 2, -k, &sl, &fl);
	scale(4 * c + 2, q - 2, -k, &sr, &fr);
	/* In units of 10^k the interval runs from L to R, x is at s + frac. */
	if ((wl = where(4 * c - 2 + boundary, q - 2, -k, fl)) < 0 ||
	    (wr = where(4 * c + 2, q - 2, -k, fr)) < 0 ||
	    where(4 * c, q - 2, -k, fb) < 0)
		return -1;
	/* An integer z is in the interval when it passes both ends: */
#define ABOVE_L(z) (wl ? ((z) > sl || (closed && (z) == sl)) : (z) > sl)
#define BELOW_R(z) (wr ? ((z) < sr || (closed && (z) == sr)) : (z) <= sr)
	/*
	 * The width is under 10, so it holds at most one multiple of 10,
	 * the one below or the one above x; if it does, that is the answer.
	 * Otherwise the width is at least 1, so it holds s or s + 1 (or
	 * both): the shortest decimals, pick the one nearest x.
	 */
	pick = s - s % 10;
	if (ABOVE_L(pick))
		goto done;
	if (BELOW_R(pick + 10)) {
		pick += 10;
		goto done;
	}
	pick = s;
	if (!ABOVE_L(s)) {
		pick = s + 1;
	} else if (BELOW_R(s + 1)) {
		int up = rounds_up(4 * c, q - 2, -k, s, fb);

		if (up < 0)
			return -1;
		pick = s + (uint64_t)up;
	}
#undef ABOVE_L
#undef BELOW_R
done:
	*digits = pick;
	*exp10 = k;
	return 0;
}

/* 10^0 to 10^19 */
static const uint64_t pow10_64[] = {
	1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000,
	1000000000, 10000000000, 100000000000, 1000000000000,
	10000000000000, 100000000000000, 1000000000000000,
	10000000000000000, 100000000000000000, 1000000000000000000,
	10000000000000000000U
};

int
loft__round_digits(double x, int p, uint64_t *digits, int *exp10)
{
	uint64_t bits, c, top = pow10_64[p], n, f;
	int be, q, lz, e, up, big;
	memcpy(&bits, &x, sizeof bits);
	be = (int)(bits >> 52 & 0x7ff);
	c = bits & (((uint64_t)1 << 52) - 1);
	q = be ? be - 1075 : -1074;
	if (be != 0)
		c |= (uint64_t)1 << 52;
	/* make c a 53-bit number: 2^(q+52) <= x < 2^(q+53) */
	lz = count_leading_zeros(c) - 11;
	c <<= lz;
	q -= lz;
	/* x's decimal exponent is big or big + 1 */
	big = loft__floor_log10_pow2(q + 52);
	e = p - 1 - big;
	scale(c, q, e, &n, &f);
	if (n >= top) {
		big++;
		e--;
		scale(c, q, e, &n, &f);
	}
	/* n + f is x 10^e, from 10^(p-1) to 10^p: round it to an integer */
	if ((up = rounds_up(c, q, e, n, f)) < 0)
		return -1;
	n += (uint64_t)up;
	if (n == top) {
		n /= 10;
		e--;
	}
	*digits = n;
	*exp10 = -e;
	return 0;
}

int
loft__decimal_to_double(uint64_t w, int e, double *x)
{
	uint64_t m[3], mant, low, bits;
	int lz, top, be;

	if (w == 0 || e < POW10_MIN || e > POW10_MAX)
		return -1;
	lz = count_leading_zeros(w);
	w <<= lz;
	mul192(w, e, m);
	/* now w 10^e ~ m 2^(b - lz), m in [2^190, 2^192); the error of m
	 * is under w < 2^64: less than 2 units of m[1] */
	top = (int)(m[2] >> 63);
	if (!top) {
		m[2] = m[2] << 1 | m[1] >> 63;
		m[1] = m[1] << 1 | m[0] >> 63;
		m[0] <<= 1;
	}
	/* m[2] holds the 53 bits of the double, a rounding bit and 10
	 * more bits; the rounding bit and those 10 are "low" */
	mant = m[2] >> 11;
	low = m[2] & 0x7ff;
	be = pow10_b[e - POW10_MIN] - lz + top + 139 + 52 + 1023 - 1;
	if (low == 0x400 && m[1] < 2) {
		/* within the error of a halfway point: exact only where g is
		 * (10^e = 5^e 2^e with 5^e < 2^128) and then a true tie */
		if (e < 0 || e > 55)
			return -1;
		if (m[1] != 0 || m[0] != 0)
			mant++;
		else
			mant += mant & 1;
	} else if (low >= 0x400) {
		mant++;
	}
	if (mant >> 53) {
		mant >>= 1;
		be++;
	}
	/* normal doubles only: subnormals and overflow go to the library */
	if (be < 1 || be > 2046)
		return -1;
	bits = (uint64_t)be << 52 | (mant & (((uint64_t)1 << 52) - 1));
	memcpy(x, &bits, sizeof *x);
	return 0;
}

/* "00".."99" */
static const char pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233"
    "34353637383940414243444546474849505152535455565758596061626364656667"
    "68697071727374757677787980818283848586878889909192939495969798999";

/* The number of decimal digits of d > 0.  With b its bits, t = b log10 2
 * rounded down (1233 / 4096 is a hair under log10 2; t <= 19): d has t
 * digits, or t + 1 where it reaches 10^t. */
static int
digit_count(uint64_t d)
{
	int t = (64 - count_leading_zeros(d)) * 1233 >> 12;

	return t + (d >= pow10_64[t]);
}

/* v < 10^4 as exactly four digits at p, and v < 10^8 as eight: halves
 * taken apart independently, not one digit pair after another. */
static void
put4(char *p, uint32_t v)
{
	memcpy(p, pairs + 2 * (v / 100), 2);
	memcpy(p + 2, pairs + 2 * (v % 100), 2);
}

static void
put8(char *p, uint32_t v)
{
	put4(p, v / 10000);
	put4(p + 4, v % 10000);
}

/* d's digits, written backwards so that the last ends just before end:
 * eight at a time, then the leading ones. */
static inline void
put_digits(char *end, uint64_t d)
{
	uint32_t v;

	for (; d >= 100000000; d /= 100000000)
		put8(end -= 8, (uint32_t)(d % 100000000));
	for (v = (uint32_t)d; v >= 100; v /= 100)
		memcpy(end -= 2, pairs + 2 * (v % 100), 2);
	if (v >= 10)
		memcpy(end - 2, pairs + 2 * v, 2);
	else
		end[-1] = (char)('0' + v);
}

/* Drop d's trailing zeros into e: at most 17, so each step once.  The
 * divisors are constants, which the compiler turns into products. */
static void
strip_zeros(uint64_t *d, int *e)
{
#define STRIP(p, k) if (*d % (p) == 0) *d /= (p), *e += (k)
	STRIP(10000000000000000U, 16);
	STRIP(100000000, 8);
	STRIP(10000, 4);
	STRIP(100, 2);
	STRIP(10, 1);
#undef STRIP
}

/* The exponent x as printf writes it: e, a sign, two digits or three. */
static char *
put_exponent(char *o, int x)
{
	*o++ = 'e';
	*o++ = x < 0 ? '-' : '+';
	x = x < 0 ? -x : x;
	if (x >= 100)
		*o++ = (char)('0' + x / 100), x %= 100;
	*o++ = pairs[2 * x];
	*o++ = pairs[2 * x + 1];
	return o;
}

/*
 * The digits are written once, straight into buf.  Where a point goes
 * among them, they are written one place to the right, and the ones
 * before the point moved back a place (one digit, in the commonest
 * layouts) to leave a gap for it.
 */
int
loft__decimal_text(char *buf, uint64_t d, int e, int prec)
{
	char *o = buf;
	int n, x;

	if (d % 10 == 0)
		strip_zeros(&d, &e);
	n = digit_count(d);
	x = e + n - 1;          /* the decimal exponent: d.ddd 10^x */
	if (x < -4 || x >= prec) {
		put_digits(o + 1 + n, d);
		o[0] = o[1];
		if (n > 1) {
			o[1] = '.';
			o += n + 1;
		} else {
			o++;
		}
		o = put_exponent(o, x);
	} else if (x < 0) {
		*o++ = '0';
		*o++ = '.';
		for (int i = -1; i > x; i--)
			*o++ = '0';
		put_digits(o + n, d);
		o += n;
	} else if (n <= x + 1) {
		put_digits(o + n, d);
		for (o += n; n <= x; n++)
			*o++ = '0';
	} else {
		put_digits(o + 1 + n, d);
		for (int i = 0; i <= x; i++)
			o[i] = o[i + 1];
		o[x + 1] = '.';
		o += n + 1;
	}
	*o = '\0';
	return (int)(o - buf);
}
