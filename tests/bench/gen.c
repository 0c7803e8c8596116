/*
 * gen: the benchmark corpora, as loft point streams on standard output.
 *
 *   gen insoles N FILE   N outlines graded from the knots of FILE (one
 *                        record), each scaled to a shoe size and jittered
 *   gen outline N        one closed outline of N knots
 *   gen space N          one closed space curve (a trefoil knot), N knots
 *   gen spline FILE      the records of FILE in GNU spline's layout: each
 *                        closed outline repeats its first knot, records
 *                        separated by blank lines
 *
 * Everything is deterministic: the same arguments give the same bytes.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define MAXKNOTS 1000

static unsigned long long rng = 0x9e3779b97f4a7c15ULL;

/* A uniform number in [-1, 1) (xorshift64*). */
static double
jitter(void)
{
	rng ^= rng >> 12, rng ^= rng << 25, rng ^= rng >> 27;
	return (double)((rng * 2685821657736338717ULL) >> 11) * 0x1p-52 - 1;
}

static void
usage(void)
{
	fputs("usage: gen insoles N FILE | gen outline N | gen space N | "
	    "gen spline FILE\n", stderr);
	exit(2);
}

/* The knots of the first record of FILE: rows of two numbers. */
static int
read_knots(const char *file, double (*k)[2])
{
	char line[256];
	FILE *fp = fopen(file, "r");
	int n = 0;

	if (fp == NULL) {
		perror(file);
		exit(1);
	}
	while (fgets(line, sizeof line, fp) != NULL && n < MAXKNOTS) {
		if (line[0] == '#')
			continue;
		if (sscanf(line, "%lf %lf", &k[n][0], &k[n][1]) != 2) {
			if (n > 0)
				break;
			continue;
		}
		n++;
	}
	fclose(fp);
	return n;
}

/*
 * Grading: sizes run through 21 steps from 0.85 to 1.15 of the pattern,
 * the width growing at 0.6 the rate of the length, as a last does; each
 * knot then moves by up to 0.3 mm, as a digitiser's hand does.  Two
 * decimals, as a pattern cutter's file has.
 */
static void
insoles(long count, const char *file)
{
	static double k[MAXKNOTS][2];
	int n = read_knots(file, k);

	for (long r = 0; r < count; r++) {
		double len = 0.85 + 0.015 * (double)(r % 21);
		double wid = 1 + 0.6 * (len - 1);

		for (int i = 0; i < n; i++)
			printf("%.2f %.2f\n", k[i][0] * len + 0.3 * jitter(),
			    k[i][1] * wid + 0.3 * jitter());
		putchar('\n');
	}
}

/*
 * A closed outline, r(t) = 100 (1 + 0.25 cos 2t + 0.05 sin 5t), its knots
 * unevenly spaced in t (denser where cos 3t is large), six decimals.
 */
static void
outline(long n)
{
	for (long i = 0; i < n; i++) {
		double u = 2 * M_PI * (double)i / (double)n;
		double t = u + 0.1 * sin(3 * u) / 3;
		double r = 100 * (1 + 0.25 * cos(2 * t) + 0.05 * sin(5 * t));

		printf("%.6f %.6f\n", r * cos(t), r * sin(t));
	}
	putchar('\n');
}

/* A trefoil knot, closed, in space. */
static void
space(long n)
{
	for (long i = 0; i < n; i++) {
		double t = 2 * M_PI * (double)i / (double)n;

		printf("%.6f %.6f %.6f\n", sin(t) + 2 * sin(2 * t),
		    cos(t) - 2 * cos(2 * t), -sin(3 * t));
	}
	putchar('\n');
}

/* Copy records, repeating each record's first row at its end. */
static void
spline_layout(const char *file)
{
	char line[512], first[512] = "";
	FILE *fp = strcmp(file, "-") == 0 ? stdin : fopen(file, "r");

	if (fp == NULL) {
		perror(file);
		exit(1);
	}
	while (fgets(line, sizeof line, fp) != NULL) {
		if (line[0] == '#')
			continue;
		if (line[0] == '\n') {
			if (first[0] != '\0')
				printf("%s\n", first);
			first[0] = '\0';
			continue;
		}
		if (first[0] == '\0')
			strcpy(first, line);
		fputs(line, stdout);
	}
	if (first[0] != '\0')
		printf("%s", first);
}

int
main(int argc, char *argv[])
{
	long n;

	if (argc < 3)
		usage();
	if (strcmp(argv[1], "spline") == 0) {
		spline_layout(argv[2]);
		return 0;
	}
	n = strtol(argv[2], NULL, 10);
	if (n < 1)
		usage();
	if (strcmp(argv[1], "insoles") == 0 && argc == 4)
		insoles(n, argv[3]);
	else if (strcmp(argv[1], "outline") == 0)
		outline(n);
	else if (strcmp(argv[1], "space") == 0)
		space(n);
	else
		usage();
	return ferror(stdout) ? 1 : 0;
}
