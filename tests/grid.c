/*
 * grid.c: tests of lib/grid.c and lib/labels.c against independent
 * answers: the segment tests against exact integer arithmetic (small
 * whole coordinates make every product exact), the grid's queries
 * against looking at every item, and the labels' placement against its
 * invariants (no two labels overlap, none meets a line where room was
 * left).  Prints "grid: N passed, M failed".
 */
#include <stdlib.h>
#include <string.h>

#include "loft.h"
#include "check.h"

/* A pseudo-random whole number in [0, n), the same on every machine. */
static unsigned long seed = 12345;
static long
rnd(long n)
{
	seed = seed * 6364136223846793005UL % 0xffffffffUL + 1442695041UL;
	return (long)((seed >> 7) % (unsigned long)n);
}

/* The sign of the turn a -> b -> c in whole numbers. */
static int
iturn(const long *a, const long *b, const long *c)
{
	long t = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

	return (t > 0) - (t < 0);
}

/* Crossing at a point inside both, by the book: the ends of each
 * strictly on either side of the other's line. */
static void
test_cross(void)
{
	int bad = 0, crossings = 0;

	for (int i = 0; i < 20000; i++) {
		long s[4], t[4];
		double ds[4], dt[4];
		int want;

		for (int k = 0; k < 4; k++) {
			s[k] = rnd(21) - 10;
			t[k] = rnd(21) - 10;
			ds[k] = (double)s[k];
			dt[k] = (double)t[k];
		}
		want = iturn(s, s + 2, t) * iturn(s, s + 2, t + 2) < 0 &&
		    iturn(t, t + 2, s) * iturn(t, t + 2, s + 2) < 0;
		crossings += want;
		bad += loft_segments_cross(ds, dt) != want ||
		    loft_segments_cross(dt, ds) != want;
	}
	CHECK(bad == 0 && crossings > 1000, "segments_cross: %d of 20000 "
	    "wrong (%d crossings)", bad, crossings);
	/* touching at an end, or in line, is not crossing */
	CHECK(!loft_segments_cross((double[]){ 0, 0, 2, 0 },
	    (double[]){ 1, 0, 1, 5 }), "a T is not a crossing");
	CHECK(!loft_segments_cross((double[]){ 0, 0, 2, 0 },
	    (double[]){ 1, 0, 3, 0 }), "overlapping in line is not a crossing");
}

/* Whether the whole-number segment s meets the box lo..hi: an end
 * inside, or the segment crosses or touches one of its sides. */
static int
imeets(const long *s, const long *lo, const long *hi)
{
	long c[4][2] = { { lo[0], lo[1] }, { hi[0], lo[1] },
	    { hi[0], hi[1] }, { lo[0], hi[1] } };

	for (int e = 0; e < 2; e++)
		if (s[2 * e] >= lo[0] && s[2 * e] <= hi[0] &&
		    s[2 * e + 1] >= lo[1] && s[2 * e + 1] <= hi[1])
			return 1;
	for (int k = 0; k < 4; k++) {
		const long *a = c[k], *b = c[(k + 1) % 4];
		int d1 = iturn(s, s + 2, a), d2 = iturn(s, s + 2, b);
		int d3 = iturn(a, b, s), d4 = iturn(a, b, s + 2);

		if (d1 * d2 <= 0 && d3 * d4 <= 0 &&
		    /* in line: the intervals must overlap */
		    !(d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0 &&
		    (fmax(s[0], s[2]) < fmin(a[0], b[0]) ||
		    fmin(s[0], s[2]) > fmax(a[0], b[0]) ||
		    fmax(s[1], s[3]) < fmin(a[1], b[1]) ||
		    fmin(s[1], s[3]) > fmax(a[1], b[1]))))
			return 1;
	}
	return 0;
}

static void
test_meets(void)
{
	int bad = 0, met = 0;

	for (int i = 0; i < 20000; i++) {
		long s[4], lo[2], hi[2];
		double ds[4], dlo[2], dhi[2];

		for (int k = 0; k < 4; k++)
			ds[k] = (double)(s[k] = rnd(21) - 10);
		for (int k = 0; k < 2; k++) {
			lo[k] = rnd(15) - 7;
			hi[k] = lo[k] + rnd(6);
			dlo[k] = (double)lo[k];
			dhi[k] = (double)hi[k];
		}
		met += imeets(s, lo, hi);
		bad += loft_segment_meets_box(ds, dlo, dhi) != imeets(s, lo, hi);
	}
	CHECK(bad == 0 && met > 1000, "segment_meets_box: %d of 20000 wrong "
	    "(%d meet)", bad, met);
}

struct seen {
	unsigned char *hit;
};

static int
mark(void *ctx, size_t id)
{
	((struct seen *)ctx)->hit[id] = 1;
	return 0;
}

/* Every box that overlaps a query box is among those the grid visits
 * for it (a grid may visit more: those in the same cells). */
static void
test_grid(void)
{
	enum { N = 3000 };
	static double lo[N][2], hi[N][2];
	struct loft_grid g;
	struct seen s = { calloc(N, 1) };
	double origin[2] = { -50, -50 };
	int missed = 0, found = 0;

	CHECK(s.hit != NULL && loft_grid_init(&g, 3, 2, origin, N) == 0,
	    "grid_init");
	for (int i = 0; i < N; i++) {
		lo[i][0] = (double)rnd(10000) / 100 - 50;
		lo[i][1] = (double)rnd(10000) / 100 - 50;
		hi[i][0] = lo[i][0] + (double)rnd(800) / 100;
		hi[i][1] = lo[i][1] + (double)rnd(300) / 100;
		CHECK(loft_grid_add(&g, lo[i], hi[i], (size_t)i) == 0, "add");
	}
	for (int q = 0; q < 200; q++) {
		double a[2], b[2];

		a[0] = (double)rnd(12000) / 100 - 60;
		a[1] = (double)rnd(12000) / 100 - 60;
		b[0] = a[0] + (double)rnd(1000) / 100;
		b[1] = a[1] + (double)rnd(1000) / 100;
		memset(s.hit, 0, N);
		loft_grid_each(&g, a, b, mark, &s);
		for (int i = 0; i < N; i++)
			if (lo[i][0] <= b[0] && a[0] <= hi[i][0] &&
			    lo[i][1] <= b[1] && a[1] <= hi[i][1]) {
				found++;
				missed += !s.hit[i];
			}
	}
	CHECK(missed == 0 && found > 200, "grid: %d of %d overlapping boxes "
	    "missed", missed, found);
	loft_grid_free(&g);
	free(s.hit);
}

/* A pile of n labels of records drawn over each other, and a row of
 * them on separate lines: no two boxes overlap. */
static void
test_labels(void)
{
	enum { N = 400 };
	static struct loft_label lb[N];
	static double seg[3 * N][4];
	static int rec[3 * N];
	double lo[2] = { 0, 0 }, hi[2] = { 5, 5 };
	int overlaps = 0;

	for (int i = 0; i < N; i++) {
		double sq[4][2] = { { 0, 0 }, { 5, 0 }, { 5, 5 }, { 0, 0 } };

		memset(&lb[i], 0, sizeof lb[i]);
		lb[i].rec = i;
		lb[i].width = 0.1 * (1 + i % 3);
		lb[i].anchor[0] = lb[i].anc[0][0] = 5;
		lb[i].anchor[1] = lb[i].anc[0][1] = 5;
		lb[i].nanc = 1;
		for (int k = 0; k < 3; k++) {
			memcpy(seg[3 * i + k], sq[k], sizeof sq[k]);
			memcpy(seg[3 * i + k] + 2, sq[k + 1], sizeof sq[k]);
			rec[3 * i + k] = i;
		}
	}
	CHECK(loft_place_labels(lb, N, seg[0], rec, 3 * N, 0.1, lo, hi) == 0,
	    "place_labels");
	for (int i = 0; i < N; i++)
		for (int j = 0; j < i; j++)
			overlaps += lb[i].lo[0] < lb[j].hi[0] &&
			    lb[j].lo[0] < lb[i].hi[0] &&
			    lb[i].lo[1] < lb[j].hi[1] && lb[j].lo[1] < lb[i].hi[1];
	CHECK(overlaps == 0, "a pile of %d labels: %d overlap", N, overlaps);
	CHECK(lo[1] <= lb[N - 1].lo[1] && hi[0] >= lb[0].hi[0],
	    "the frame holds the labels");
}

int
main(void)
{
	test_cross();
	test_meets();
	test_grid();
	test_labels();
	return check_done("grid");
}
