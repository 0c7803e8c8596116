/*
 * pow10gen: write lib/pow10.h, the table of powers of ten that lib/dtoa.c
 * multiplies by, from exact big-integer arithmetic; with -c FILE, check
 * that FILE is what it would write, line by line.
 *
 * For each e from POW10_MIN to POW10_MAX the table holds g and b with
 *   g = ceil(10^e / 2^b),  2^127 <= g < 2^128,
 * so g * 2^b is 10^e rounded up to 128 significant bits (exact for
 * 0 <= e <= 55, where 5^e fits in 128 bits).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define POW10_MIN (-330)
#define POW10_MAX 340
#define LIMBS 80                /* 2560 bits: 10^340 * 2^128 fits */

/* A big natural number, little-endian 32-bit limbs. */
struct big {
	uint32_t d[LIMBS];
};

static void
big_set(struct big *a, uint32_t v)
{
	memset(a, 0, sizeof *a);
	a->d[0] = v;
}

static void
big_mul_small(struct big *a, uint32_t m)
{
	uint64_t carry = 0;

	for (int i = 0; i < LIMBS; i++) {
		uint64_t t = (uint64_t)a->d[i] * m + carry;
		a->d[i] = (uint32_t)t;
		carry = t >> 32;
	}
	if (carry != 0) {
		fputs("pow10gen: overflow\n", stderr);
		exit(1);
	}
}

static int
big_bits(const struct big *a)
{
	for (int i = LIMBS - 1; i >= 0; i--)
		for (int b = 31; b >= 0; b--)
			if (a->d[i] >> b & 1)
				return 32 * i + b + 1;
	return 0;
}

static int
big_bit(const struct big *a, int i)
{
	return i >= 0 && i < 32 * LIMBS ? a->d[i / 32] >> (i % 32) & 1 : 0;
}

static int
big_cmp(const struct big *a, const struct big *b)
{
	for (int i = LIMBS - 1; i >= 0; i--)
		if (a->d[i] != b->d[i])
			return a->d[i] < b->d[i] ? -1 : 1;
	return 0;
}

static void
big_sub(struct big *a, const struct big *b)
{
	int64_t borrow = 0;

	for (int i = 0; i < LIMBS; i++) {
		int64_t t = (int64_t)a->d[i] - b->d[i] - borrow;
		borrow = t < 0;
		a->d[i] = (uint32_t)(t + (borrow ? (int64_t)1 << 32 : 0));
	}
}

static void
big_shl1(struct big *a, int bit)
{
	for (int i = LIMBS - 1; i > 0; i--)
		a->d[i] = a->d[i] << 1 | a->d[i - 1] >> 31;
	a->d[0] = a->d[0] << 1 | (uint32_t)bit;
}

/* g and b for 10^e. */
static void
entry(int e, uint64_t *hi, uint64_t *lo, int *b)
{
	struct big p;
	int n, exact = 1;

	big_set(&p, 1);
	for (int i = 0; i < (e < 0 ? -e : e); i++)
		big_mul_small(&p, 10);
	n = big_bits(&p);
	*hi = *lo = 0;
	if (e >= 0) {
		/* the top 128 bits of 10^e, rounded up */
		*b = n - 128;
		for (int i = n - 1; i >= n - 128; i--) {
			int bit = big_bit(&p, i);
			if (i >= n - 64)
				*hi = *hi << 1 | (uint64_t)bit;
			else
				*lo = *lo << 1 | (uint64_t)bit;
		}
		for (int i = n - 129; i >= 0; i--)
			if (big_bit(&p, i))
				exact = 0;
	} else {
		/* 2^(n+127) / 10^-e by long division, one bit at a time */
		struct big r;

		*b = -(n + 127);
		big_set(&r, 0);
		for (int i = n + 127; i >= 0; i--) {
			int q;

			big_shl1(&r, i == n + 127);
			q = big_cmp(&r, &p) >= 0;
			if (q)
				big_sub(&r, &p);
			*hi = *hi << 1 | *lo >> 63;
			*lo = *lo << 1 | (uint64_t)q;
		}
		big_set(&p, 0);
		exact = big_cmp(&r, &p) == 0;
	}
	if (!exact && ++*lo == 0)
		++*hi;
	if (*hi >> 63 != 1) {
		fprintf(stderr, "pow10gen: 10^%d: g out of [2^127, 2^128)\n",
		    e);
		exit(1);
	}
}

/* Line number k of the table file, without its newline, into buf. */
static void
line(int k, char *buf, size_t size)
{
	static const char *const head[] = {
		"/* pow10.h: written by tests/pow10gen.c; do not edit. */",
		("/* 10^e = g * 2^b rounded up: g = ceil(10^e / 2^b) in "
		    "[2^127, 2^128). */"),
		"#define POW10_MIN (-330)",
		"#define POW10_MAX 340",
		"static const uint64_t pow10_g[][2] = {",
	};
	int nhead = sizeof head / sizeof head[0];
	int count = POW10_MAX - POW10_MIN + 1;
	uint64_t hi, lo;
	int b;

	if (k < nhead) {
		snprintf(buf, size, "%s", head[k]);
	} else if (k < nhead + count) {
		entry(POW10_MIN + k - nhead, &hi, &lo, &b);
		snprintf(buf, size, "\t{ 0x%016llxU, 0x%016llxU },",
		    (unsigned long long)hi, (unsigned long long)lo);
	} else if (k == nhead + count) {
		snprintf(buf, size, "};");
	} else if (k == nhead + count + 1) {
		snprintf(buf, size, "static const short pow10_b[] = {");
	} else if (k < nhead + 2 * count + 2) {
		entry(POW10_MIN + k - nhead - count - 2, &hi, &lo, &b);
		snprintf(buf, size, "\t%d,", b);
	} else if (k == nhead + 2 * count + 2) {
		snprintf(buf, size, "};");
	} else {
		buf[0] = '\0';
	}
}

int
main(int argc, char *argv[])
{
	char want[128], have[256];
	int k, failed = 0;
	FILE *fp;

	if (argc == 1) {
		for (k = 0; line(k, want, sizeof want), want[0]; k++)
			puts(want);
		return ferror(stdout) != 0;
	}
	if (argc != 3 || strcmp(argv[1], "-c") != 0) {
		fputs("usage: pow10gen [-c file]\n", stderr);
		return 2;
	}
	if ((fp = fopen(argv[2], "r")) == NULL) {
		perror(argv[2]);
		return 1;
	}
	for (k = 0; line(k, want, sizeof want), want[0]; k++) {
		if (fgets(have, sizeof have, fp) == NULL)
			have[0] = '\0';
		have[strcspn(have, "\n")] = '\0';
		if (strcmp(want, have) != 0) {
			failed++;
			fprintf(stderr, "FAIL %s:%d: '%s', want '%s'\n",
			    argv[2], k + 1, have, want);
		}
	}
	if (fgets(have, sizeof have, fp) != NULL) {
		failed++;
		fprintf(stderr, "FAIL %s: lines after the table\n", argv[2]);
	}
	fclose(fp);
	/* one check: the file is what the generator writes */
	printf("powtable: %d passed, %d failed\n", !failed, !!failed);
	return failed != 0;
}
