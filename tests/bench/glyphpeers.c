/*
 * glyphpeers.c: the peers of `make compare`'s glyph table (issue 23),
 * run by tests/bench/glyphs_cmp.py.  Not a test: a measurement.
 *
 *   glyphpeers hobby KNOTS   Hobby's curve through each knot record of
 *                            KNOTS (as tests/glyphs.py writes them)
 *   glyphpeers spiro KNOTS   Spiro's (built with -DHAVE_SPIRO)
 *   glyphpeers cross FILE    for each point record of FILE (a sampled
 *                            closed curve), 1 where the polyline crosses
 *                            itself, else 0, one a line
 *
 * hobby and spiro write each curve sampled, 50 points a segment, as
 * `sample -n 50` does.  Both honour the record's corners= and straight=:
 * a straight span is a line; Spiro gets its `[` `]` points beside it and
 * corner points at corners; Hobby's curve is cut at corners (curl 1 at
 * each end, as METAFONT's default) and at the ends of straight spans
 * (the line's direction given).  The closed Hobby curve of a record with
 * neither, the gauss() it and the open one solve with, Spiro's closed G2
 * curve and libspiro's Bezier callbacks are compare.c's, included here
 * so that they are written once.
 */
#define main compare_main
#include "compare.c"
#undef main

#define PER 50                  /* samples a segment, as sample -n 50 */
#define MAXPT 400000            /* polyline points a record */

struct rec {
	double k[MAXK][2];
	int n, corner[MAXK], straight[MAXK];   /* straight[i]: span i..i+1 */
};

/* Reads the next knot record of fp into r (corners= and straight= of its
 * header, 1-based, as loft.5 says); 1, or 0 at the end. */
static int
next_rec(FILE *fp, struct rec *r)
{
	char line[4096];

	memset(r, 0, sizeof *r);
	while (fgets(line, sizeof line, fp)) {
		if (line[0] == '\n') {
			if (r->n > 0)
				return 1;
			continue;
		}
		if (line[0] == 'p') {
			char *a = strstr(line, " corners="), *b = strstr(line,
			    " straight="), *e;
			int *to[2] = { r->corner, r->straight };
			char *at[2] = { a ? a + 9 : NULL, b ? b + 10 : NULL };

			for (int w = 0; w < 2; w++)
				for (char *p = at[w]; p != NULL;) {
					long i = strtol(p, &e, 10);

					if (e == p)
						break;
					if (i >= 1 && i <= MAXK)
						to[w][i - 1] = 1;
					p = *e == ',' ? e + 1 : NULL;
				}
			continue;
		}
		if (r->n < MAXK && sscanf(line, "%lf %lf", &r->k[r->n][0],
		    &r->k[r->n][1]) == 2)
			r->n++;
	}
	return r->n > 0;
}

/* Writes the closed curve of ns Hermite rows seg sampled. */
static void
put_curve(const double *seg, int ns)
{
	puts("points");
	for (int i = 0; i < ns; i++) {
		const double *s = seg + 8 * i;

		for (int j = 0; j < PER; j++) {
			double t = (double)j / PER, t2 = t * t, t3 = t2 * t;
			double h0 = 2 * t3 - 3 * t2 + 1, h1 = t3 - 2 * t2 + t;
			double h2 = -2 * t3 + 3 * t2, h3 = t3 - t2;

			printf("%.17g %.17g\n", h0 * s[0] + h1 * s[4] + h2 * s[2] +
			    h3 * s[6], h0 * s[1] + h1 * s[5] + h2 * s[3] + h3 * s[7]);
		}
	}
	if (ns > 0)
		printf("%.17g %.17g\n", seg[0], seg[1]);
	puts("");
}

/* ---- Hobby's open curve ------------------------------------------------ */

static double
wrap(double a)
{
	return atan2(sin(a), cos(a));
}

/* The Hermite row of Hobby's segment from p to q leaving at angle th to
 * the chord and arriving at ph (Hobby's velocity, tension 1), into s. */
static void
hobby_row(const double *p, const double *q, double th, double ph, double *s)
{
	double d = hypot(q[0] - p[0], q[1] - p[1]), a = atan2(q[1] - p[1],
	    q[0] - p[0]), rt = velocity(th, ph) * d, rf = velocity(ph, th) * d;

	s[0] = p[0], s[1] = p[1], s[2] = q[0], s[3] = q[1];
	s[4] = 3 * rt * cos(a + th), s[5] = 3 * rt * sin(a + th);
	s[6] = 3 * rf * cos(a - ph), s[7] = 3 * rf * sin(a - ph);
}

/*
 * Hobby's open curve through z[0..n] (n segments) into seg, n rows.  At
 * each end the direction is given (dir0, dir1: an angle) or, NAN, curl 1.
 * Unknowns x_i = theta_i (i < n), x_n = phi_n; rows: at each inner knot
 * the mock curvatures agree, (2 phi_i - theta_{i-1}) / d_{i-1} = (2
 * theta_i - phi_{i+1}) / d_i with phi_i = -psi_i - theta_i (Hobby 1986,
 * eq. of METAFONT's sec. 276, tension 1); at an end, the direction, or
 * curl 1: theta_0 = phi_1, phi_n = theta_{n-1}.  0, or -1.
 */
static int
hobby_open(const double (*z)[2], int n, double dir0, double dir1, double *seg)
{
	static double a[(MAXK + 1) * (MAXK + 1)];
	double d[MAXK + 1], ang[MAXK + 1], psi[MAXK + 1], x[MAXK + 1];
	int m = n + 1;

	if (n < 1 || n > MAXK)
		return -1;
	for (int i = 0; i < n; i++) {
		d[i] = hypot(z[i + 1][0] - z[i][0], z[i + 1][1] - z[i][1]);
		ang[i] = atan2(z[i + 1][1] - z[i][1], z[i + 1][0] - z[i][0]);
		if (!(d[i] > 0))
			return -1;
	}
	for (int i = 1; i < n; i++)
		psi[i] = wrap(ang[i] - ang[i - 1]);
	if (n == 1 && isnan(dir0) && isnan(dir1))
		return hobby_row(z[0], z[1], 0, 0, seg), 0;
	memset(a, 0, sizeof a[0] * m * m);
	/* phi_i as a row: -psi_i - x_i (i < n), or x_n; coefficient c */
#define PHI(r, i, c) ((i) < n ? (a[(r) * m + (i)] -= (c), x[r] += (c) * \
	psi[i]) : (a[(r) * m + (i)] += (c), 0))
	if (isnan(dir0))
		a[0] = 1, x[0] = 0, PHI(0, 1, -1);
	else
		a[0] = 1, x[0] = wrap(dir0 - ang[0]);
	for (int i = 1; i < n; i++) {
		x[i] = 0;
		PHI(i, i, 2 / d[i - 1]);
		a[i * m + i - 1] -= 1 / d[i - 1];
		a[i * m + i] -= 2 / d[i];
		PHI(i, i + 1, 1 / d[i]);
	}
	x[n] = 0;
	if (isnan(dir1))
		a[n * m + n] = 1, a[n * m + n - 1] = -1;
	else
		a[n * m + n] = 1, x[n] = wrap(ang[n - 1] - dir1);
#undef PHI
	if (gauss(a, x, m) != 0)
		return -1;
	for (int i = 0; i < n; i++) {
		double ph = i + 1 < n ? -psi[i + 1] - x[i + 1] : x[n];

		hobby_row(z[i], z[i + 1], x[i], ph, seg + 8 * i);
	}
	return 0;
}

/* Whether knot i of r is a corner for the curve: a corner of the header,
 * or between two straight spans. */
static int
is_corner(const struct rec *r, int i)
{
	return r->corner[i] || (r->straight[i] && r->straight[(i + r->n - 1) %
	    r->n]);
}

/* Whether knot i of r ends the curved stretch it is on. */
static int
is_break(const struct rec *r, int i)
{
	return is_corner(r, i) || r->straight[i] || r->straight[(i + r->n - 1)
	    % r->n];
}

/* Hobby's closed curve through record r, its corners and straight spans
 * honoured, into seg (r->n rows); 0 or -1. */
static int
hobby_rec(const struct rec *r, double *seg)
{
	int n = r->n, first = -1;

	for (int i = 0; i < n && first < 0; i++)
		if (is_break(r, i))
			first = i;
	if (first < 0)
		return hobby((const double (*)[2])r->k, n, seg);
	for (int s = 0; s < n;) {       /* s: spans done from first */
		int i = (first + s) % n, j = (i + 1) % n, len = 1;
		double z[MAXK + 1][2], dir0 = NAN, dir1 = NAN;

		if (r->straight[i]) {
			hobby_row(r->k[i], r->k[j], 0, 0, seg + 8 * i);
			s++;
			continue;
		}
		while (!is_break(r, (i + len) % n))
			len++;
		for (int q = 0; q <= len; q++)
			memcpy(z[q], r->k[(i + q) % n], sizeof z[q]);
		if (!is_corner(r, i)) {         /* a line before it */
			int h = (i + n - 1) % n;

			dir0 = atan2(r->k[i][1] - r->k[h][1], r->k[i][0] -
			    r->k[h][0]);
		}
		j = (i + len) % n;
		if (!is_corner(r, j))           /* a line after it */
			dir1 = atan2(r->k[(j + 1) % n][1] - r->k[j][1],
			    r->k[(j + 1) % n][0] - r->k[j][0]);
		if (i + len <= n) {
			if (hobby_open((const double (*)[2])z, len, dir0, dir1,
			    seg + 8 * i) != 0)
				return -1;
		} else {                        /* wraps past knot 0 */
			double tmp[8 * MAXK];

			if (hobby_open((const double (*)[2])z, len, dir0, dir1,
			    tmp) != 0)
				return -1;
			for (int q = 0; q < len; q++)
				memcpy(seg + 8 * ((i + q) % n), tmp + 8 * q,
				    8 * sizeof tmp[0]);
		}
		s += len;
	}
	return 0;
}

/* ---- Spiro with corners and straight runs ------------------------------ */

#ifdef HAVE_SPIRO
/* Spiro's curve through r: a corner point at corners, `[` `]` beside a
 * straight span, G2 points elsewhere; rows into seg, their count or -1. */
static int
spiro_rec(const struct rec *r, double *seg, int max)
{
	spiro_cp cp[MAXK], rot[MAXK];
	int n = r->n, plain = 1;

	for (int i = 0; i < n; i++) {
		cp[i].x = r->k[i][0];
		cp[i].y = r->k[i][1];
		cp[i].ty = SPIRO_G2;
		if (is_corner(r, i))
			cp[i].ty = SPIRO_CORNER;
		else if (r->straight[i])        /* curve in, line out */
			cp[i].ty = SPIRO_LEFT;
		else if (r->straight[(i + n - 1) % n])  /* line in, curve out */
			cp[i].ty = SPIRO_RIGHT;
		plain = plain && cp[i].ty == SPIRO_G2;
	}
	if (plain)
		return spiro((const double (*)[2])r->k, n, seg, max);
	/* libspiro fails on some closed contours by where they start
	 * (seen after a `[` or a corner); the same contour started at
	 * another knot is the same curve */
	for (int start = 0; start < n; start++) {
		struct ctx c = { { b_moveto, b_lineto, b_quadto, b_curveto,
		    b_mark }, 0, 0, seg, 0, max };

		for (int i = 0; i < n; i++)
			rot[i] = cp[(start + i) % n];
		if (SpiroCPsToBezier0(rot, n, 1, &c.base) && c.n > 0 && c.n <
		    max)
			return c.n;
	}
	return -1;
}
#endif

/* ---- self-crossings of a polyline --------------------------------------- */

static double (*pt)[2];

static int
by_xmin(const void *a, const void *b)
{
	int i = *(const int *)a, j = *(const int *)b;
	double x = fmin(pt[i][0], pt[i + 1][0]), y = fmin(pt[j][0],
	    pt[j + 1][0]);

	return x < y ? -1 : x > y;
}

static double
orient(const double *a, const double *b, const double *c)
{
	return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Whether the closed polyline pt[0..n) (pt[n] = pt[0]) crosses itself:
 * two segments not neighbours cross properly.  A sweep by x. */
static int
crosses(int n)
{
	static int ord[MAXPT];

	for (int i = 0; i < n; i++)
		ord[i] = i;
	qsort(ord, n, sizeof ord[0], by_xmin);
	for (int a = 0; a < n; a++) {
		int i = ord[a];
		double xmax = fmax(pt[i][0], pt[i + 1][0]);

		for (int b = a + 1; b < n; b++) {
			int j = ord[b], gap = abs(i - j);

			if (fmin(pt[j][0], pt[j + 1][0]) > xmax)
				break;
			if (gap <= 1 || gap == n - 1)
				continue;
			if (orient(pt[i], pt[i + 1], pt[j]) * orient(pt[i],
			    pt[i + 1], pt[j + 1]) < 0 && orient(pt[j], pt[j + 1],
			    pt[i]) * orient(pt[j], pt[j + 1], pt[i + 1]) < 0)
				return 1;
		}
	}
	return 0;
}

static int
cross_file(FILE *fp)
{
	char line[256];
	int n = 0, more = 1;

	pt = malloc(sizeof *pt * (MAXPT + 1));
	if (pt == NULL)
		return 1;
	while (more) {
		double x, y;

		more = fgets(line, sizeof line, fp) != NULL;
		if (more && sscanf(line, "%lf %lf", &x, &y) == 2) {
			if (n < MAXPT && (n == 0 || x != pt[n - 1][0] || y !=
			    pt[n - 1][1]))
				pt[n][0] = x, pt[n][1] = y, n++;
			continue;
		}
		if (more && line[0] != '\n')
			continue;
		if (n > 1 && pt[n - 1][0] == pt[0][0] && pt[n - 1][1] ==
		    pt[0][1])
			n--;
		if (n > 0) {
			pt[n][0] = pt[0][0], pt[n][1] = pt[0][1];
			printf("%d\n", n > 3 && crosses(n));
		}
		n = 0;
	}
	free(pt);
	return 0;
}

int
main(int argc, char *argv[])
{
	static double seg[MAXSEG * 8];
	struct rec r;
	FILE *fp;

	if (argc != 3 || (fp = fopen(argv[2], "r")) == NULL) {
		fputs("usage: glyphpeers hobby|spiro|cross FILE\n", stderr);
		return 2;
	}
	if (strcmp(argv[1], "cross") == 0)
		return cross_file(fp);
	while (next_rec(fp, &r)) {
		int ns = -1;

		if (strcmp(argv[1], "hobby") == 0)
			ns = hobby_rec(&r, seg) == 0 ? r.n : -1;
#ifdef HAVE_SPIRO
		else if (strcmp(argv[1], "spiro") == 0)
			ns = spiro_rec(&r, seg, MAXSEG);
#endif
		else
			return fputs("glyphpeers: no such peer here\n", stderr), 2;
		if (ns > 0)
			put_curve(seg, ns);
		else            /* a failure: a record of no number */
			puts("points\nnan nan\n");
	}
	fclose(fp);
	return 0;
}
