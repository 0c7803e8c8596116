/*
 * check.h: the smallest test harness that does the job.  CHECK counts a
 * pass or a failure (and says where it failed); check_done prints the
 * suite's "N passed, M failed" line that tests/run.sh adds up.
 */
#ifndef CHECK_H
#define CHECK_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static int check_passed, check_failed;

static void
check_at(int ok, const char *file, int line, const char *fmt, ...)
{
	va_list ap;

	if (ok) {
		check_passed++;
		return;
	}
	check_failed++;
	fprintf(stderr, "FAIL %s:%d: ", file, line);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}

#define CHECK(cond, ...) \
	check_at((cond) ? 1 : 0, __FILE__, __LINE__, __VA_ARGS__)

/* |a - b| <= tol, with both values in the failure message */
#define NEAR(a, b, tol, what) do { \
	double a_ = (a), b_ = (b); \
	CHECK(fabs(a_ - b_) <= (tol), "%s: %.17g vs %.17g (tol %g)", \
	    (what), a_, b_, (double)(tol)); \
} while (0)

static int
check_done(const char *suite)
{
	printf("%s: %d passed, %d failed\n", suite, check_passed, check_failed);
	return check_failed != 0;
}

#endif
