/*
 * types.c: the one table of record types (loft.5) and what each can be.
 * Core.  The evaluation of a curve or a surface type is curve.c's or
 * surface.c's, named from its row here.
 */
#include <string.h>

#include "internal.h"

#ifdef LOFT_TEST_LINE
/* tests/linetype.c: a degree-1 segment type, built into make check's
 * copies of the programs in bin/test/line only, to see every program
 * take a type it was not written for or refuse it with a message. */
extern const struct loft__curve_type loft__test_line_type;
#endif

const struct loft_type loft_types[] = {
	{ "points", LOFT_KIND_KNOTS, 0, NULL, NULL },
	{ "cubic", LOFT_KIND_CURVE | LOFT_KIND_SEGMENTS, 3,
	    &loft__cubic_type, NULL },
	{ "quartic", LOFT_KIND_CURVE | LOFT_KIND_SEGMENTS, 4,
	    &loft__quartic_type, NULL },
	{ "bezier", LOFT_KIND_CURVE | LOFT_KIND_CONTROL, 0,
	    &loft__bezier_type, NULL },
	{ "patch", LOFT_KIND_SURFACE | LOFT_KIND_MEMBER, 0,
	    NULL, &loft__patch_type },
	{ "bezier-surface", LOFT_KIND_SURFACE | LOFT_KIND_CONTROL, 0,
	    NULL, &loft__bezier_surface_type },
#ifdef LOFT_TEST_LINE
	{ "line", LOFT_KIND_CURVE | LOFT_KIND_SEGMENTS, 1,
	    &loft__test_line_type, NULL },
#endif
	{ NULL, 0, 0, NULL, NULL }
};

const struct loft_type *
loft_type_named(const char *name)
{
	if (name == NULL)
		return &loft_types[0];
	for (const struct loft_type *t = loft_types; t->name != NULL; t++)
		if (strcmp(t->name, name) == 0)
			return t;
	return NULL;
}

const struct loft_type *
loft_record_type(const struct loft_record *rec)
{
	return loft_type_named(rec->type);
}

int
loft_record_is(const struct loft_record *rec, int kinds)
{
	const struct loft_type *t = loft_record_type(rec);

	return t != NULL && (t->kinds & kinds) == kinds;
}
