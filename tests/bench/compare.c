/*
 * compare.c: how fair splinefit's curves are beside other tools' through
 * the same uneven closed knots (issue 13).  Not a test: a measurement.
 *
 *   compare corpus N INSOLE   write N uneven knot sets: a third the
 *                             insole with knots dropped and jittered, a
 *                             third sparse blobs with uneven spacing, a
 *                             third spiky sets (issue 23: 5 to 13 knots,
 *                             one or two 2 to 4 times farther out than
 *                             their neighbours, spacing up to 1:50)
 *   compare run FILE          fit each set of FILE by loft's default,
 *                             -m manning, -m chord, Hobby's algorithm and
 *                             (built with -DHAVE_SPIRO) Spiro's G2 points,
 *                             and print the table
 *
 * For each method and set: the bending energy (loft_curve_energy of the
 * method's cubic pieces) over that of the fairest of the peers (Spiro,
 * Hobby, chord), a self-crossing (loft_fit_crosses) where the chord
 * spline has none, a failure.  Hobby's curves are made here from his
 * equations (Hobby 1986, as in Knuth's METAFONT: tension 1, the cyclic
 * system for the angles, his velocity function); Spiro's by libspiro.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../lib/loft.h"
#ifdef HAVE_SPIRO
#include <bezctx.h>
#include <spiroentrypoints.h>
#endif

#ifndef M_PI                    /* XSI, not C99 */
#define M_PI 3.14159265358979323846
#endif

#define MAXK 64                 /* knots a set */
#define MAXSEG 4096             /* pieces a curve (Spiro subdivides) */
enum { FAIR, MANNING, CHORD, HOBBY, SPIRO, NMETHOD };
static const char *const names[NMETHOD] = { "loft default", "-m manning",
    "-m chord", "Hobby", "Spiro G2" };

static unsigned long rng = 12345;

static double
uniform(void)
{
	rng = rng * 6364136223846793005UL + 1442695040888963407UL;
	return (double)(rng >> 11) / 9007199254740992.0;
}

/* ---- the corpus ---------------------------------------------------- */

static int
corpus(int n, const char *insole)
{
	double k[MAXK][2];
	int nk = 0;
	char line[256];
	FILE *fp = fopen(insole, "r");

	if (fp == NULL)
		return perror(insole), 1;
	while (nk < MAXK && fgets(line, sizeof line, fp))
		if (line[0] != '#' && sscanf(line, "%lf %lf", &k[nk][0],
		    &k[nk][1]) == 2)
			nk++;
	fclose(fp);
	for (int s = 0; s < n; s++) {
		printf("points set=%d\n", s + 1);
		if (s % 3 == 2) {       /* spiky: a toe, a heel tip, a stem */
			int m = 5 + (int)(9 * uniform()), spike = (int)(m *
			    uniform()), spike2 = uniform() < 0.5 ? (spike + m / 2) %
			    m : -1;
			double a = 0, step[16], tot = 0, sq = 0.5 + 0.5 * uniform();

			for (int i = 0; i < m; i++)
				tot += step[i] = exp(log(50) * uniform());
			for (int i = 0; i < m; i++) {
				double r = 1 + 0.2 * (uniform() - 0.5);

				if (i == spike || i == spike2)
					r *= 2 + 2 * uniform();
				printf("%.6f %.6f\n", r * cos(a), sq * r * sin(a));
				a += 2 * M_PI * step[i] / tot;
			}
		} else if (s % 3 == 0) {        /* the insole, knots dropped, jittered */
			int kept = 0;

			for (int i = 0; i < nk; i++) {
				if (uniform() < 0.35 && nk - i > 8 - kept)
					continue;
				printf("%.6f %.6f\n", k[i][0] + 3 * (uniform() -
				    0.5), k[i][1] + 3 * (uniform() - 0.5));
				kept++;
			}
		} else {                /* a blob: 5 to 10 knots, uneven */
			int m = 5 + (int)(6 * uniform());
			double a = 0, step[16], tot = 0;

			for (int i = 0; i < m; i++)
				tot += step[i] = 0.2 + uniform();
			for (int i = 0; i < m; i++) {
				double r = 50 * (1 + 0.35 * (uniform() - 0.5));

				printf("%.6f %.6f\n", r * cos(a), 0.7 * r * sin(a));
				a += 2 * M_PI * step[i] / tot;
			}
		}
		printf("\n");
	}
	return 0;
}

/* ---- Hobby's curve --------------------------------------------------- */

/* Dense Gaussian elimination with partial pivoting of the n x n system
 * a x = b (a row-major, spoiled); 0, or -1 when singular. */
static int
gauss(double *a, double *b, int n)
{
	for (int c = 0; c < n; c++) {
		int p = c;

		for (int r = c + 1; r < n; r++)
			if (fabs(a[r * n + c]) > fabs(a[p * n + c]))
				p = r;
		if (!(fabs(a[p * n + c]) > 1e-300))
			return -1;
		for (int j = 0; j < n; j++) {
			double t = a[c * n + j];

			a[c * n + j] = a[p * n + j];
			a[p * n + j] = t;
		}
		{
			double t = b[c];

			b[c] = b[p];
			b[p] = t;
		}
		for (int r = c + 1; r < n; r++) {
			double f = a[r * n + c] / a[c * n + c];

			for (int j = c; j < n; j++)
				a[r * n + j] -= f * a[c * n + j];
			b[r] -= f * b[c];
		}
	}
	for (int r = n - 1; r >= 0; r--) {
		for (int j = r + 1; j < n; j++)
			b[r] -= a[r * n + j] * b[j];
		b[r] /= a[r * n + r];
	}
	return 0;
}

/* Hobby's velocity function rho(theta, phi), tension 1. */
static double
velocity(double t, double f)
{
	double num = 2 + sqrt(2) * (sin(t) - sin(f) / 16) *
	    (sin(f) - sin(t) / 16) * (cos(t) - cos(f));
	double den = 1 + (sqrt(5) - 1) / 2 * cos(t) + (3 - sqrt(5)) / 2 *
	    cos(f);

	return num / (3 * den);
}

/* The closed Hobby curve through k[0..n) as Hermite rows; 0 or -1. */
static int
hobby(const double (*k)[2], int n, double *seg)
{
	double d[MAXK], ang[MAXK], psi[MAXK], a[MAXK * MAXK], th[MAXK];

	for (int i = 0; i < n; i++) {
		const double *p = k[i], *q = k[(i + 1) % n];

		d[i] = hypot(q[0] - p[0], q[1] - p[1]);
		ang[i] = atan2(q[1] - p[1], q[0] - p[0]);
	}
	for (int i = 0; i < n; i++) {       /* turn at knot i */
		double t = ang[i] - ang[(i + n - 1) % n];

		psi[i] = atan2(sin(t), cos(t));
	}
	/* A th_{i-1} + (B + C) th_i + D th_{i+1} = -B psi_i - D psi_{i+1},
	 * A = 1/d_{i-1}, B = 2/d_{i-1}, C = 2/d_i, D = 1/d_i */
	memset(a, 0, sizeof a);
	for (int i = 0; i < n; i++) {
		int h = (i + n - 1) % n, j = (i + 1) % n;

		a[i * n + h] += 1 / d[h];
		a[i * n + i] += 2 / d[h] + 2 / d[i];
		a[i * n + j] += 1 / d[i];
		th[i] = -2 / d[h] * psi[i] - 1 / d[i] * psi[j];
	}
	if (gauss(a, th, n) != 0)
		return -1;
	for (int i = 0; i < n; i++) {
		int j = (i + 1) % n;
		double t = th[i], f = -psi[j] - th[j], *s = seg + 8 * i;
		double rt = velocity(t, f) * d[i], rf = velocity(f, t) * d[i];

		s[0] = k[i][0], s[1] = k[i][1], s[2] = k[j][0], s[3] = k[j][1];
		/* Bezier arms rt, rf; Hermite tangents three times them */
		s[4] = 3 * rt * cos(ang[i] + t);
		s[5] = 3 * rt * sin(ang[i] + t);
		s[6] = 3 * rf * cos(ang[i] - f);
		s[7] = 3 * rf * sin(ang[i] - f);
	}
	return 0;
}

/* ---- Spiro ----------------------------------------------------------- */

#ifdef HAVE_SPIRO
struct ctx {
	bezctx base;
	double x, y, *seg;
	int n, max;
};

static void
b_moveto(bezctx *bc, double x, double y, int open)
{
	struct ctx *c = (struct ctx *)bc;

	(void)open;
	c->x = x, c->y = y;
}

static void
b_curveto(bezctx *bc, double x1, double y1, double x2, double y2, double x3,
    double y3)
{
	struct ctx *c = (struct ctx *)bc;

	if (c->n < c->max) {
		double *s = c->seg + 8 * c->n++;

		s[0] = c->x, s[1] = c->y, s[2] = x3, s[3] = y3;
		s[4] = 3 * (x1 - c->x), s[5] = 3 * (y1 - c->y);
		s[6] = 3 * (x3 - x2), s[7] = 3 * (y3 - y2);
	}
	c->x = x3, c->y = y3;
}

static void
b_lineto(bezctx *bc, double x, double y)
{
	struct ctx *c = (struct ctx *)bc;

	b_curveto(bc, c->x + (x - c->x) / 3, c->y + (y - c->y) / 3,
	    c->x + 2 * (x - c->x) / 3, c->y + 2 * (y - c->y) / 3, x, y);
}

static void
b_quadto(bezctx *bc, double x1, double y1, double x2, double y2)
{
	struct ctx *c = (struct ctx *)bc;

	b_curveto(bc, c->x + 2 * (x1 - c->x) / 3, c->y + 2 * (y1 - c->y) / 3,
	    x2 + 2 * (x1 - x2) / 3, y2 + 2 * (y1 - y2) / 3, x2, y2);
}

static void
b_mark(bezctx *bc, int i)
{
	(void)bc, (void)i;
}

static int
spiro(const double (*k)[2], int n, double *seg, int max)
{
	spiro_cp cp[MAXK];
	struct ctx c = { { b_moveto, b_lineto, b_quadto, b_curveto, b_mark },
	    0, 0, seg, 0, max };

	for (int i = 0; i < n; i++) {
		cp[i].x = k[i][0];
		cp[i].y = k[i][1];
		cp[i].ty = SPIRO_G2;
	}
	if (!SpiroCPsToBezier0(cp, n, 1, &c.base) || c.n == 0 || c.n >= max)
		return -1;
	return c.n;
}
#endif

/* ---- measures --------------------------------------------------------- */

static int
cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

static int
run(const char *file)
{
	static double seg[MAXSEG * 8], ratio[NMETHOD][1024];
	static double fam[3][NMETHOD][512];     /* by family: insole, blob,
	                                         * spike */
	double k[MAXK][2], e[NMETHOD], kmax[NMETHOD];
	int nfam[3] = { 0, 0, 0 }, sharper[NMETHOD] = { 0 };
	int twice[NMETHOD] = { 0 };    /* largest curvature over 2 Spiro's */
	long infl[NMETHOD] = { 0 };    /* inflexions, all sets */
	int nset = 0, loops[NMETHOD] = { 0 }, fails[NMETHOD] = { 0 };
	int best[NMETHOD] = { 0 }, nk = 0, have[NMETHOD];
	char line[256];
	FILE *fp = fopen(file, "r");

	if (fp == NULL)
		return perror(file), 1;
	for (int more = 1; more;) {
		more = fgets(line, sizeof line, fp) != NULL;
		if (more && line[0] != '\n' && line[0] != 'p') {
			if (nk < MAXK && sscanf(line, "%lf %lf", &k[nk][0],
			    &k[nk][1]) == 2)
				nk++;
			continue;
		}
		if (nk < 3 || nset >= 1024) {
			nk = 0;
			continue;
		}
		int chordloop = 0, ib = -1, looped[NMETHOD] = { 0 };
		double peer = HUGE_VAL;

		for (int m = 0; m < NMETHOD; m++) {
			struct loft_fit_opts o;
			struct loft_error err;
			struct loft_curve c;
			int ns = nk, ok = 1;

			e[m] = HUGE_VAL;
			have[m] = 1;
			loft_fit_defaults(&o);
			o.method = m == FAIR ? LOFT_FAIR : m == MANNING ?
			    LOFT_MANNING : LOFT_CHORD;
			o.split = m == FAIR;    /* splinefit's default */
			if (m <= CHORD) {
				struct loft_fit_info info;

				ok = loft_fit(&o, &k[0][0], nk, 2, seg, &info,
				    &err) == 0;
				ns = (int)info.nseg;
			}
			else if (m == HOBBY)
				ok = hobby((const double (*)[2])k, nk, seg) == 0;
			else {
#ifdef HAVE_SPIRO
				ns = spiro((const double (*)[2])k, nk, seg,
				    MAXSEG);
				ok = ns > 0;
#else
				have[m] = 0;
				continue;
#endif
			}
			loft_curve_cubic(&c, seg, ns, 2, 1);
			/* a crossing counts even where a cusp leaves no energy */
			looped[m] = ok && loft_fit_crosses(seg, ns, 1) == 1;
			if (m == CHORD)
				chordloop = looped[m];
			if (!ok || loft_curve_energy(&c, &e[m], &err) != 0 ||
			    !isfinite(e[m])) {
				fails[m]++;
				e[m] = HUGE_VAL;
				continue;
			}
			kmax[m] = 0;
			{
				double r, u;
				long ni;

				if (loft_curve_min_radius(&c, &r, &u, &err) == 0 &&
				    r > 0)
					kmax[m] = 1 / r;
				if (loft_curve_inflexions(&c, &ni, &err) == 0)
					infl[m] += ni;
			}
		}
		for (int m = 0; m < NMETHOD; m++) {
			loops[m] += looped[m] && !chordloop;
			/* the issue: never a curvature above the chord spline's
			 * largest (to rounding of the root finder) */
			sharper[m] += e[m] < HUGE_VAL && e[CHORD] < HUGE_VAL &&
			    kmax[m] > kmax[CHORD] * (1 + 1e-9);
			twice[m] += have[SPIRO] && e[SPIRO] < HUGE_VAL &&
			    kmax[m] > 2 * kmax[SPIRO];
		}
		for (int m = CHORD; m < NMETHOD; m++)
			if (have[m] && e[m] < peer)
				peer = e[m];
		for (int m = 0; m < NMETHOD; m++) {
			if (have[m] && (ib < 0 || e[m] < e[ib]))
				ib = m;
			ratio[m][nset] = e[m] / peer;
			if (nfam[nset % 3] < 512)
				fam[nset % 3][m][nfam[nset % 3]] = e[m] / peer;
		}
		if (nfam[nset % 3] < 512)
			nfam[nset % 3]++;
		best[ib]++;
		nset++;
		nk = 0;
	}
	fclose(fp);
	printf("%d uneven closed knot sets; energy over the fairest peer's "
	    "(Spiro, Hobby, chord)\n", nset);
	printf("%-14s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n",
	    "method", "median", "90%", "worst", "fairest", "loops", "sharper",
	    "2xSpiro", "inflex", "fails", "insoles", "blobs", "spikes", "spk90%",
	    "spkworst");
	for (int m = 0; m < NMETHOD; m++) {
		if (!have[m]) {
			printf("%-14s skipped: built without libspiro\n",
			    names[m]);
			continue;
		}
		qsort(ratio[m], nset, sizeof ratio[m][0], cmp);
		for (int f = 0; f < 3; f++)
			qsort(fam[f][m], nfam[f], sizeof fam[f][m][0], cmp);
		printf("%-14s %8.4f %8.4f %8.3g %8d %8d %8d %8d %8ld %8d %8.4f %8.4f "
		    "%8.4f %8.4f %8.3g\n", names[m], ratio[m][nset / 2],
		    ratio[m][(int)(0.9 * (nset - 1))], ratio[m][nset - 1],
		    best[m], loops[m], sharper[m], twice[m], infl[m], fails[m],
		    fam[0][m][nfam[0] / 2], fam[1][m][nfam[1] / 2],
		    fam[2][m][nfam[2] / 2], fam[2][m][(int)(0.9 * (nfam[2] - 1))],
		    fam[2][m][nfam[2] - 1]);
	}
	printf("(loops: curves that cross themselves where the chord spline "
	    "does not; sharper: sets where the largest curvature is above\n"
	    " the chord spline's; 2xSpiro: above twice Spiro's; inflex: the "
	    "inflexions of all sets;\n insoles, "
	    "blobs, spikes: the median of each family,\n spk90%%, spkworst: "
	    "the spiky family's 90th percentile and worst)\n");
	return 0;
}

int
main(int argc, char *argv[])
{
	if (argc == 4 && strcmp(argv[1], "corpus") == 0)
		return corpus(atoi(argv[2]), argv[3]);
	if (argc == 3 && strcmp(argv[1], "run") == 0)
		return run(argv[2]);
	fputs("usage: compare corpus N insole.knots | compare run FILE\n",
	    stderr);
	return 2;
}
