/*
 * timeit: time a shell command line, and sum up many such timings.
 *
 *   timeit 'command line'   prints "wall cpu": the wall-clock seconds it
 *                           took and the user + system seconds its
 *                           processes used; its own standard output goes
 *                           to /dev/null.  Exit status: the command's.
 *   timeit -r FILE A/B|C ...
 *                           reads FILE, lines "rep case wall cpu", and
 *                           prints the median wall and cpu seconds of
 *                           each case named (A, B or C), then for each
 *                           pair A/B the median over the reps of A's
 *                           time over B's, the two measured in the same
 *                           rep.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double
seconds(struct timeval tv)
{
	return (double)tv.tv_sec + (double)tv.tv_usec / 1e6;
}

#define MAXROWS 4096

struct row {
	int rep;
	char name[32];
	double wall, cpu;
};

static struct row rows[MAXROWS];
static int nrows;

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

static double
median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof *v, cmp_double);
	return n == 0 ? 0 : n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

static const struct row *
find(int rep, const char *name)
{
	for (int i = 0; i < nrows; i++)
		if (rows[i].rep == rep && strcmp(rows[i].name, name) == 0)
			return &rows[i];
	return NULL;
}

/* Whether name is one of the arguments "a/b" (either side) or "a". */
static int
in_pairs(const char *name, int npairs, char **pairs)
{
	size_t n = strlen(name);

	for (int k = 0; k < npairs; k++) {
		const char *b = strchr(pairs[k], '/');

		if (b == NULL ? strcmp(pairs[k], name) == 0 :
		    strcmp(b + 1, name) == 0 || ((size_t)(b - pairs[k]) == n &&
		    strncmp(pairs[k], name, n) == 0))
			return 1;
	}
	return 0;
}

/* Each case the pairs name, once: its median wall and cpu seconds.
 * w, c: scratch for MAXROWS numbers each. */
static void
print_cases(int npairs, char **pairs, double *w, double *c)
{
	printf("%-14s %9s %9s %5s\n", "case", "wall s", "cpu s", "runs");
	for (int i = 0; i < nrows; i++) {
		int n = 0, seen = 0;

		for (int j = 0; j < i; j++)
			seen |= strcmp(rows[j].name, rows[i].name) == 0;
		if (seen || !in_pairs(rows[i].name, npairs, pairs))
			continue;
		for (int j = i; j < nrows; j++)
			if (strcmp(rows[j].name, rows[i].name) == 0) {
				w[n] = rows[j].wall;
				c[n++] = rows[j].cpu;
			}
		printf("%-14s %9.3f %9.3f %5d\n", rows[i].name, median(w, n),
		    median(c, n), n);
	}
}

static int
report(const char *file, int npairs, char **pairs)
{
	static double w[MAXROWS], c[MAXROWS];
	FILE *fp = fopen(file, "r");

	if (fp == NULL) {
		perror(file);
		return 2;
	}
	while (nrows < MAXROWS && fscanf(fp, "%d %31s %lf %lf",
	    &rows[nrows].rep, rows[nrows].name, &rows[nrows].wall,
	    &rows[nrows].cpu) == 4)
		nrows++;
	fclose(fp);
	print_cases(npairs, pairs, w, c);
	for (int k = 0; k < npairs; k++)
		if (strchr(pairs[k], '/') != NULL) {
			printf("\n%-30s %9s %9s\n",
			    "ratio (median of each rep's)", "wall", "cpu");
			break;
		}
	for (int k = 0; k < npairs; k++) {
		char a[32], *b;
		int n = 0;

		snprintf(a, sizeof a, "%s", pairs[k]);
		if ((b = strchr(a, '/')) == NULL)
			continue;
		*b++ = '\0';
		for (int i = 0; i < nrows; i++) {
			const struct row *rb;

			if (strcmp(rows[i].name, a) != 0 ||
			    (rb = find(rows[i].rep, b)) == NULL || rb->wall <= 0 ||
			    rb->cpu <= 0)
				continue;
			w[n] = rows[i].wall / rb->wall;
			c[n++] = rows[i].cpu / rb->cpu;
		}
		if (n > 0)
			printf("%-30s %9.2f %9.2f\n", pairs[k], median(w, n),
			    median(c, n));
	}
	return 0;
}

int
main(int argc, char *argv[])
{
	struct timespec t0, t1;
	struct rusage ru;
	pid_t pid;
	int st;

	if (argc >= 3 && strcmp(argv[1], "-r") == 0)
		return report(argv[2], argc - 3, argv + 3);
	if (argc != 2) {
		fputs("usage: timeit 'command line' | timeit -r file "
		    "[a/b | c ...]\n", stderr);
		return 2;
	}
	fflush(stdout);
	clock_gettime(CLOCK_MONOTONIC, &t0);
	if ((pid = fork()) == 0) {
		if (freopen("/dev/null", "w", stdout) == NULL)
			_exit(127);
		execl("/bin/sh", "sh", "-c", argv[1], (char *)NULL);
		_exit(127);
	}
	if (pid < 0 || waitpid(pid, &st, 0) != pid)
		return 2;
	clock_gettime(CLOCK_MONOTONIC, &t1);
	getrusage(RUSAGE_CHILDREN, &ru);
	printf("%.3f %.3f\n", (double)(t1.tv_sec - t0.tv_sec) +
	    (double)(t1.tv_nsec - t0.tv_nsec) / 1e9, seconds(ru.ru_utime) +
	    seconds(ru.ru_stime));
	return WIFEXITED(st) ? WEXITSTATUS(st) : 2;
}
