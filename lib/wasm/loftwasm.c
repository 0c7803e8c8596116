/*
 * loftwasm.c: the entry points of the WebAssembly module that loftplot
 * -i embeds in its page (issue 27).  The page runs loft's own programs
 * in it, the same C as the commands: splinefit refits the knots,
 * patchdrag drags a patch, loftplot draws; their standard input and
 * output are the page's text, through the page's WASI imports.  Built
 * by clang for wasm32-wasi only (lib/wasm/build.sh), never by cc.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"
#include "wasm/page.h"

#define EXPORT(name) __attribute__((export_name(name)))

/* The grid of a surface the page picks points on: this many intervals
 * of u and of v (a point within half a cell of a click is found, and
 * the page refines nothing: the pick is a choice of (U, V), not a
 * measurement). */
#define GRID_MAX 64

int loft_main_splinefit(int argc, char *argv[]);
int loft_main_patchdrag(int argc, char *argv[]);
int loft_main_loftplot(int argc, char *argv[]);

/*
 * splinefit -e (loft_approx, approx.c) is not in the module: the page
 * fits through knots only, and leaving it out keeps the module under
 * 200 KB.  splinefit's -e then says so.
 */
void
loft_approx_defaults(struct loft_approx_opts *o)
{
	memset(o, 0, sizeof *o);
}

int
loft_approx(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_approx_info *info,
    struct loft_error *err)
{
	(void)o, (void)p, (void)n, (void)dim, (void)seg, (void)info;
	return loft_fail(err, LOFT_EINPUT, -1, "splinefit -e is not in the "
	    "page: run it on the saved knots");
}

/* loftplot -i is not in the page: the page is not made again inside
 * itself. */
const size_t loft_page_wasm_bytes = 0;

int
loft_page_write(FILE *out, const struct loft_page *pg)
{
	(void)out, (void)pg;
	return -1;
}

/*
 * grid N: for each surface record of standard input, counted from 0
 * among all its records, the lines "r u v x y z" of its points at
 * u, v = i/N (N from 1 to GRID_MAX).  The page picks the point of a
 * patch to drag from them.  Exit status 0, or 1 on a bad record.
 */
static int
grid_main(int argc, char *argv[])
{
	struct loft_reader *rd;
	struct loft_record rec = { 0 };
	struct loft_surface sf;
	struct loft_error err;
	int n = argc > 1 ? atoi(argv[1]) : 0, rc, status = 0;
	long r = 0;

	if (n < 1 || n > GRID_MAX || (rd = loft_reader_new(stdin, "-")) ==
	    NULL)
		return 2;
	while ((rc = loft_read(rd, &rec, &err)) != 0) {
		if (rc < 0) {
			status = 1;
			if (rc == LOFT_READ_FAIL)
				break;
			continue;
		}
		if (loft_is_surface(&rec) &&
		    loft_surface_from_record(&rec, &sf, &err) == 0)
			for (int i = 0; i <= n; i++)
				for (int j = 0; j <= n; j++) {
					double p[LOFT_MAXDIM] = { 0 };

					loft_surface_eval(&sf, (double)i / n,
					    (double)j / n, p, NULL, NULL);
					printf("%ld %.17g %.17g %.17g %.17g "
					    "%.17g\n", r, (double)i / n,
					    (double)j / n, p[0], p[1],
					    sf.dim > 2 ? p[2] : 0.0);
				}
		r++;
	}
	loft_record_free(&rec);
	loft_reader_free(rd);
	return status;
}

static const struct {
	const char *name;
	int (*main)(int, char **);
} progs[] = {
	{ "splinefit", loft_main_splinefit },
	{ "patchdrag", loft_main_patchdrag },
	{ "loftplot", loft_main_loftplot },
	{ "grid", grid_main },
};

/* Room of n bytes for the page to write arguments into. */
EXPORT("loftw_alloc") void *
loftw_alloc(size_t n)
{
	return malloc(n);
}

EXPORT("loftw_free") void
loftw_free(void *p)
{
	free(p);
}

/*
 * Run the program argv[0] with its arguments, reading the page's input
 * as its standard input; its exit status, or 127 when it is no program
 * of the module.  Each run starts getopt afresh and leaves its output
 * flushed.
 */
EXPORT("loftw_run") int
loftw_run(int argc, char **argv)
{
	int rc = 127;

	optind = 0;             /* musl's getopt: a full reset */
	clearerr(stdin);
	for (size_t i = 0; i < sizeof progs / sizeof progs[0]; i++)
		if (strcmp(argv[0], progs[i].name) == 0)
			rc = progs[i].main(argc, argv);
	fflush(stdout);
	fflush(stderr);
	return rc;
}
