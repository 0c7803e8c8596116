/*
 * noisy: noisy samples of known smooth outlines, for splinefit -e's
 * tests (tests/approx.sh) and its comparison with scipy
 * (tests/bench/approx_scipy.py).  The truth is exact: a formula, or the
 * fair curve through the knots of a file.
 *
 *   noisy [-n N] [-s SIGMA] [-r SEED] [-a START] SHAPE ARGS...
 *       N points (default 300) evenly spaced along the length of SHAPE,
 *       from the fraction START of it (closed shapes), each moved by
 *       Gaussian noise of standard deviation SIGMA in every coordinate
 *       (default 0), the same for the same SEED (default 1)
 *   noisy -t [-n N] SHAPE ARGS...   N points of the truth (default 20000)
 *   noisy -i SHAPE ARGS...          the truth's length, bending energy
 *       (the integral of curvature squared along it), inflexions and
 *       largest curvature, on one line, by dense quadrature of the formula
 *
 * SHAPE is one of
 *   ellipse A B      closed: (A cos 2 pi t, B sin 2 pi t)
 *   blob R A K       closed: radius R (1 + A cos K th + A/2 sin (K+1) th)
 *   insole FILE      closed: the fair curve (loft_fit) through the knots
 *                    of FILE, one knot a line
 *   wave W H K       open: (W t, H sin K pi t), t in [0, 1]
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loft.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Samples of the parameter for the length table and the quadratures:
 * the length comes out to 1e-10 and the energy to 1e-8. */
#define DENSE 200000
#define MAXKNOTS 4096

struct shape {
	int kind, closed;       /* 'e', 'b', 'i', 'w' */
	double a, b, c;
	double *seg;            /* the insole's cubic segments */
	size_t nseg;
};

static void
usage(void)
{
	fputs("usage: noisy [-t | -i] [-n N] [-s SIGMA] [-r SEED] [-a START] "
	    "ellipse A B | blob R A K | insole FILE | wave W H K\n", stderr);
	exit(2);
}

/* The point and its first and second derivatives at t in [0, 1]. */
static void
eval(const struct shape *s, double t, double *p, double *d1, double *d2)
{
	double w = 2 * M_PI, th = w * t;

	switch (s->kind) {
	case 'e':
		p[0] = s->a * cos(th), p[1] = s->b * sin(th);
		d1[0] = -w * s->a * sin(th), d1[1] = w * s->b * cos(th);
		d2[0] = -w * w * p[0], d2[1] = -w * w * p[1];
		break;
	case 'b': {
		double k = s->c, A = s->b, R = s->a;
		double r = R * (1 + A * cos(k * th) + A / 2 * sin((k + 1) * th));
		double r1 = R * (-A * k * sin(k * th) +
		    A / 2 * (k + 1) * cos((k + 1) * th));
		double r2 = R * (-A * k * k * cos(k * th) -
		    A / 2 * (k + 1) * (k + 1) * sin((k + 1) * th));
		double c = cos(th), sn = sin(th);

		p[0] = r * c, p[1] = r * sn;
		d1[0] = w * (r1 * c - r * sn), d1[1] = w * (r1 * sn + r * c);
		d2[0] = w * w * (r2 * c - 2 * r1 * sn - r * c);
		d2[1] = w * w * (r2 * sn + 2 * r1 * c - r * sn);
		break;
	}
	case 'w': {
		double k = s->c * M_PI;

		p[0] = s->a * t, p[1] = s->b * sin(k * t);
		d1[0] = s->a, d1[1] = s->b * k * cos(k * t);
		d2[0] = 0, d2[1] = -s->b * k * k * sin(k * t);
		break;
	}
	default: {
		double x = t * s->nseg;
		size_t i = x >= s->nseg ? s->nseg - 1 : (size_t)x;
		double n = (double)s->nseg;

		loft_cubic_eval(s->seg + 8 * i, 2, x - i, p, d1, d2);
		for (int k = 0; k < 2; k++)
			d1[k] *= n, d2[k] *= n * n;
	}
	}
}

static void
read_insole(struct shape *s, const char *file)
{
	static double k[2 * MAXKNOTS];
	struct loft_fit_opts o;
	struct loft_error err;
	char line[256];
	size_t n = 0;
	FILE *fp = fopen(file, "r");

	if (fp == NULL) {
		perror(file);
		exit(1);
	}
	while (n < MAXKNOTS && fgets(line, sizeof line, fp) != NULL)
		if (sscanf(line, "%lf %lf", &k[2 * n], &k[2 * n + 1]) == 2)
			n++;
	fclose(fp);
	s->seg = malloc(8 * n * sizeof *s->seg);
	loft_fit_defaults(&o);
	if (s->seg == NULL || loft_fit(&o, k, n, 2, s->seg, NULL, &err) != 0) {
		fprintf(stderr, "noisy: %s: cannot fit its knots\n", file);
		exit(1);
	}
	s->nseg = n;
}

/* splitmix64, then Box and Muller: a standard normal number. */
static double
gauss(uint64_t *state)
{
	double u[2];

	for (int i = 0; i < 2; i++) {
		uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);

		z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
		z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
		z ^= z >> 31;
		u[i] = ((z >> 11) + 0.5) * 0x1p-53;
	}
	return sqrt(-2 * log(u[0])) * cos(2 * M_PI * u[1]);
}

static double
speed(const struct shape *s, double t)
{
	double p[2], d1[2], d2[2];

	eval(s, t, p, d1, d2);
	return hypot(d1[0], d1[1]);
}

/* The length from t = 0 to each of DENSE + 1 even parameters
 * (Simpson's rule on each interval). */
static double *
length_table(const struct shape *s)
{
	double *len = malloc((DENSE + 1) * sizeof *len), h = 1.0 / DENSE;

	if (len == NULL)
		exit(1);
	len[0] = 0;
	for (int i = 1; i <= DENSE; i++) {
		double a = (i - 1) * h;

		len[i] = len[i - 1] + h / 6 * (speed(s, a) +
		    4 * speed(s, a + h / 2) + speed(s, a + h));
	}
	return len;
}

/* The parameter at length x along the table (linear between samples). */
static double
at_length(const double *len, double x)
{
	size_t lo = 0, hi = DENSE;

	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;

		if (len[mid] <= x)
			lo = mid;
		else
			hi = mid;
	}
	if (len[hi] == len[lo])
		return (double)lo / DENSE;
	return (lo + (x - len[lo]) / (len[hi] - len[lo])) / DENSE;
}

static double
curvature(const struct shape *s, double t)
{
	double p[2], d1[2], d2[2], v;

	eval(s, t, p, d1, d2);
	v = hypot(d1[0], d1[1]);
	return (d1[0] * d2[1] - d1[1] * d2[0]) / (v * v * v);
}

/* -i: length, energy (Simpson on k^2 |P'|), inflexions, largest |k|. */
static void
info(const struct shape *s)
{
	double h = 1.0 / DENSE, e = 0, kmax = 0, len = 0;
	int sign = 0, first = 0, flips = 0;

	for (int i = 0; i < DENSE; i++) {
		double a = i * h, m = a + h / 2, b = a + h;
		double ka = curvature(s, a), km = curvature(s, m);
		double kb = curvature(s, b);

		e += h / 6 * (ka * ka * speed(s, a) + 4 * km * km * speed(s, m) +
		    kb * kb * speed(s, b));
		len += h / 6 * (speed(s, a) + 4 * speed(s, m) + speed(s, b));
		kmax = fmax(kmax, fabs(ka));
	}
	for (int i = 0; i <= DENSE; i++) {
		double k = curvature(s, (double)i / DENSE);
		int sg = fabs(k) * len < 1e-9 ? 0 : (k > 0 ? 1 : -1);

		if (sg == 0)
			continue;
		if (sign != 0 && sg != sign)
			flips++;
		if (first == 0)
			first = sg;
		sign = sg;
	}
	if (s->closed && sign != 0 && sign != first)
		flips++;
	printf("length %.10g energy %.10g inflexions %d kmax %.10g\n", len, e,
	    flips, kmax);
}

int
main(int argc, char *argv[])
{
	struct shape s = { 0 };
	int c, mode = 'p';
	long n = -1;
	double sigma = 0, start = 0, *len;
	uint64_t seed = 1;

	while ((c = getopt(argc, argv, "tin:s:r:a:")) != -1) {
		switch (c) {
		case 't': case 'i': mode = c; break;
		case 'n': n = atol(optarg); break;
		case 's': sigma = atof(optarg); break;
		case 'r': seed = strtoull(optarg, NULL, 10); break;
		case 'a': start = atof(optarg); break;
		default: usage();
		}
	}
	argv += optind;
	argc -= optind;
	if (argc < 1)
		usage();
	s.closed = 1;
	if (strcmp(argv[0], "ellipse") == 0 && argc == 3)
		s.kind = 'e';
	else if (strcmp(argv[0], "blob") == 0 && argc == 4)
		s.kind = 'b';
	else if (strcmp(argv[0], "wave") == 0 && argc == 4)
		s.kind = 'w', s.closed = 0;
	else if (strcmp(argv[0], "insole") == 0 && argc == 2)
		s.kind = 'i', read_insole(&s, argv[1]);
	else
		usage();
	if (s.kind != 'i') {
		s.a = atof(argv[1]);
		s.b = atof(argv[2]);
		s.c = argc > 3 ? atof(argv[3]) : 0;
	}
	if (mode == 'i') {
		info(&s);
		free(s.seg);
		return 0;
	}
	if (n < 0)
		n = mode == 't' ? 20000 : 300;
	if (n < 2)
		usage();
	len = length_table(&s);
	printf("# noisy %s: %ld points%s, sigma %g, seed %llu\n", argv[0], n,
	    mode == 't' ? " of the truth" : "", mode == 't' ? 0 : sigma,
	    (unsigned long long)seed);
	for (long i = 0; i < n; i++) {
		double f = s.closed ? (i + start) / n : (double)i / (n - 1);
		double p[2], d1[2], d2[2];

		f -= floor(f);
		if (!s.closed && i == n - 1)
			f = 1;
		eval(&s, at_length(len, f * len[DENSE]), p, d1, d2);
		if (mode == 'p')
			for (int k = 0; k < 2; k++)
				p[k] += sigma * gauss(&seed);
		printf("%.17g %.17g\n", p[0], p[1]);
	}
	free(len);
	free(s.seg);
	return 0;
}
