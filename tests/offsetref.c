/*
 * offsetref: an independent check of offset(1), sharing no code with
 * it.  Usage: offsetref CURVE OFFSETS DIST TOL [-n]
 *
 * CURVE holds one plane `cubic` record (Manning's eq. 7 rows), OFFSETS
 * the records offset wrote for it at DIST.  Both are read here with
 * sscanf and evaluated in the Hermite form.  The distance from a point
 * to a curve is found from scratch: the nearest of 64 samples of each
 * segment, then Newton's iteration on (P(u) - q) . P'(u) = 0 from it,
 * the least over all segments.  Checks:
 *   forward  every offset point (32 a segment) is |DIST| from CURVE,
 *            within TOL (skipped with -n: joins that are not arcs);
 *   reverse  every point c + D n of the exact offset (D = DIST, to the
 *            left of an open curve, outward of a closed one by the sign
 *            of its area) that is |DIST| from the whole curve (to 1e-7
 *            of it: these points are exact, and one a little nearer
 *            the curve is past a crossing, cut away) is within TOL of
 *            OFFSETS: nothing is missing.
 * Prints the worst of each and exits 1 when a check fails.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct set {
	double (*s)[8];
	size_t n, cap;
	int closed;
};

static void
add(struct set *c, const double *r)
{
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 64;
		c->s = realloc(c->s, c->cap * sizeof *c->s);
		if (c->s == NULL)
			exit(2);
	}
	memcpy(c->s[c->n++], r, sizeof *c->s);
}

static void
load(const char *name, struct set *c)
{
	char line[4096];
	FILE *fp = fopen(name, "r");
	double r[8];

	if (fp == NULL) {
		perror(name);
		exit(2);
	}
	while (fgets(line, sizeof line, fp) != NULL) {
		if ((line[0] >= 'a' && line[0] <= 'z')) {
			if (strstr(line, "closed=1") != NULL)
				c->closed = 1;
			continue;
		}
		if (sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %lf", &r[0], &r[1],
		    &r[2], &r[3], &r[4], &r[5], &r[6], &r[7]) == 8)
			add(c, r);
	}
	fclose(fp);
}

/* Hermite form: P = h00 A + h01 B + h10 A' + h11 B', and P', P''. */
static void
eval(const double *s, double u, double *p, double *d, double *dd)
{
	double h[4] = { 2*u*u*u - 3*u*u + 1, 3*u*u - 2*u*u*u, u*u*u - 2*u*u + u,
	    u*u*u - u*u };
	double g[4] = { 6*u*u - 6*u, 6*u - 6*u*u, 3*u*u - 4*u + 1, 3*u*u - 2*u };
	double f[4] = { 12*u - 6, 6 - 12*u, 6*u - 4, 6*u - 2 };

	for (int k = 0; k < 2; k++) {
		p[k] = d[k] = dd[k] = 0;
		for (int j = 0; j < 4; j++) {
			p[k] += h[j] * s[2 * j + k];
			d[k] += g[j] * s[2 * j + k];
			dd[k] += f[j] * s[2 * j + k];
		}
	}
}

/* The distance from q to the box of the segment's Bezier control points
 * A, A + A'/3, B - B'/3, B, whose hull holds the segment. */
static double
boxdist(const double *s, const double *q)
{
	double e = 0;

	for (int k = 0; k < 2; k++) {
		double v[4] = { s[k], s[k] + s[4 + k] / 3, s[2 + k] - s[6 + k] / 3,
		    s[2 + k] }, lo = v[0], hi = v[0];

		for (int j = 1; j < 4; j++) {
			lo = fmin(lo, v[j]);
			hi = fmax(hi, v[j]);
		}
		e = fmax(e, fmax(lo - q[k], q[k] - hi));
	}
	return e;
}

struct near {
	double d;
	size_t i;
};

static int
cmp_near(const void *a, const void *b)
{
	const struct near *p = a, *q = b;

	return (p->d > q->d) - (p->d < q->d);
}

/* Segments in order of their boxes' distance, until a box is farther
 * than the best point found. */
static double
dist(const struct set *c, const double *q)
{
	static struct near *ord;
	static size_t cap;
	double best = INFINITY;

	if (cap < c->n) {
		cap = c->n;
		if ((ord = realloc(ord, cap * sizeof *ord)) == NULL)
			exit(2);
	}
	for (size_t i = 0; i < c->n; i++) {
		ord[i].d = boxdist(c->s[i], q);
		ord[i].i = i;
	}
	qsort(ord, c->n, sizeof *ord, cmp_near);
	for (size_t o = 0; o < c->n && ord[o].d < best; o++) {
		size_t i = ord[o].i;
		double p[2], d[2], dd[2], u0 = 0, b = INFINITY, u;

		for (int j = 0; j <= 64; j++) {
			eval(c->s[i], j / 64.0, p, d, dd);
			if (hypot(p[0] - q[0], p[1] - q[1]) < b) {
				b = hypot(p[0] - q[0], p[1] - q[1]);
				u0 = j / 64.0;
			}
		}
		u = u0;
		for (int it = 0; it < 30; it++) {
			double e[2], f, fp, step;

			eval(c->s[i], u, p, d, dd);
			e[0] = p[0] - q[0];
			e[1] = p[1] - q[1];
			f = e[0] * d[0] + e[1] * d[1];
			fp = d[0] * d[0] + d[1] * d[1] + e[0] * dd[0] + e[1] * dd[1];
			if (!(fp > 0))
				break;
			step = f / fp;
			if (step > 1.0 / 64) step = 1.0 / 64;
			if (step < -1.0 / 64) step = -1.0 / 64;
			u -= step;
			u = u < 0 ? 0 : u > 1 ? 1 : u;
			eval(c->s[i], u, p, d, dd);
			b = fmin(b, hypot(p[0] - q[0], p[1] - q[1]));
			if (fabs(step) < 1e-15)
				break;
		}
		best = fmin(best, b);
	}
	return best;
}

int
main(int argc, char *argv[])
{
	struct set in = { 0 }, out = { 0 };
	double d, tol, area = 0, fwd = 0, rev = 0, D;
	int nofwd = argc > 5 && strcmp(argv[5], "-n") == 0;
	long nrev = 0;

	if (argc < 5) {
		fputs("usage: offsetref CURVE OFFSETS DIST TOL [-n]\n", stderr);
		return 2;
	}
	load(argv[1], &in);
	load(argv[2], &out);
	d = atof(argv[3]);
	tol = atof(argv[4]);
	if (in.n == 0 || out.n == 0) {
		fprintf(stderr, "offsetref: no segments in %s\n",
		    in.n ? argv[2] : argv[1]);
		free(in.s);
		free(out.s);
		return 1;
	}
	/* twice the area, by the trapezium rule on 256 steps a segment */
	for (size_t i = 0; i < in.n; i++)
		for (int j = 0; j < 256; j++) {
			double p[2], q[2], t[2];

			eval(in.s[i], j / 256.0, p, t, t);
			eval(in.s[i], (j + 1) / 256.0, q, t, t);
			area += p[0] * q[1] - p[1] * q[0];
		}
	D = in.closed && area > 0 ? -d : d;
	if (!nofwd)
		for (size_t i = 0; i < out.n; i++)
			for (int j = 0; j < 32; j++) {
				double p[2], t[2];

				eval(out.s[i], (j + 0.5) / 32, p, t, t);
				fwd = fmax(fwd, fabs(dist(&in, p) - fabs(d)));
			}
	for (size_t i = 0; i < in.n; i++)
		for (int j = 1; j < 64; j++) {
			double p[2], t[2], dd[2], o[2], L;

			eval(in.s[i], j / 64.0, p, t, dd);
			L = hypot(t[0], t[1]);
			if (!(L > 0))
				continue;
			o[0] = p[0] - D * t[1] / L;
			o[1] = p[1] + D * t[0] / L;
			if (dist(&in, o) < fabs(d) * (1 - 1e-7))
				continue;
			nrev++;
			rev = fmax(rev, dist(&out, o));
		}
	printf("offsetref: %zu segments, %zu out; forward %.3g, reverse %.3g "
	    "(%ld points), tol %.3g\n", in.n, out.n, fwd, rev, nrev, tol);
	free(in.s);
	free(out.s);
	return fwd <= tol && rev <= tol && nrev > 0 ? 0 : 1;
}
