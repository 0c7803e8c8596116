/*
 * tables.c: the library's registries, one line each entry, "type NAME",
 * "format NAME" and "reader NAME", in table order, for
 * tests/registry.sh to check the lists kept elsewhere (the pages, the
 * usage texts, the tests) against.
 */
#include <stdio.h>

#include "loftcad.h"

int
main(void)
{
	for (const struct loft_type *t = loft_types; t->name != NULL; t++)
		printf("type %s\n", t->name);
	for (const struct loft_cad_entry *f = loft_cad_formats; f->name != NULL;
	    f++)
		printf("format %s\n", f->name);
	for (const struct loft_cadin_reader *r = loft_cadin_readers;
	    r->name != NULL; r++)
		printf("reader %s\n", r->name);
	return ferror(stdout) != 0;
}
