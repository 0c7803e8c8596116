/*
 * page.h: loftplot -i's page (issue 27), made at build time by
 * lib/wasm/embed.c: the HTML before and after the page's data, and the
 * WebAssembly module in base64, each a NULL-ended list of pieces.  The
 * module's list is empty when it was not built (no toolchain).
 */
#ifndef LOFT_PAGE_H
#define LOFT_PAGE_H
#include <stddef.h>

extern const char *const loft_page_head[];
extern const char *const loft_page_tail[];
extern const char *const loft_page_wasm[];
extern const size_t loft_page_wasm_bytes;       /* before base64 */

#include <stdio.h>

#include "loftprog.h"

/*
 * What loftplot -i puts in its page: the view and whether the comb is
 * on, and the text of the records it kept, in four streams: the knot
 * records of -K (the curves the designer edits), the curve records
 * (the i-th the fit of the i-th knots), the point records, and the
 * surfaces (the design patchdrag drags).
 */
struct loft_page {
	const char *view;
	int comb;
	const char *args[24];   /* loftplot's other options, for the page's
	                         * picture: -b -m -t -B -C -g -l -n, NULL
	                         * ended */
	int nargs;
	struct loft_writer knots, curves, points, design;
};

/*
 * Write the page of pg to out: one HTML document with the module and
 * the records in it, needing no other file and no network.  Returns 0,
 * or -1 when the module was not built (nothing is written) or writing
 * failed.
 */
int loft_page_write(FILE *out, const struct loft_page *pg);
#endif
