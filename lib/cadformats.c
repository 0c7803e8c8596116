/*
 * cadformats.c: the table of CAD output formats, tocad -f's words, in a
 * file of its own (as Lua's linit.c holds its libraries): a new format
 * is its module (lib/FORMAT.c, defining its struct loft_cad_format) and
 * one line here.  cad.c, the document protocol, names no format, so the
 * formats depend on it and only this table on them.
 * Program layer (loftcad.h).
 */
#include <string.h>

#include "loftcad.h"

extern const struct loft_cad_format loft_cad_dxf, loft_cad_svg, loft_cad_step,
    loft_cad_iges, loft_cad_stl, loft_cad_obj;

const struct loft_cad_entry loft_cad_formats[] = {
	{ "dxf", &loft_cad_dxf },
	{ "svg", &loft_cad_svg },
	{ "step", &loft_cad_step },
	{ "iges", &loft_cad_iges },
	{ "stl", &loft_cad_stl },
	{ "obj", &loft_cad_obj },
	{ NULL, NULL }
};

const struct loft_cad_format *
loft_cad_format_named(const char *name)
{
	for (const struct loft_cad_entry *e = loft_cad_formats; e->name != NULL;
	    e++)
		if (strcmp(e->name, name) == 0)
			return e->format;
	return NULL;
}

int
loft_cad_format_find(const char *name, int *i, struct loft_error *err)
{
	const char *words[LOFT_CAD_MAXFORMATS + 1];
	int n = 0;

	for (const struct loft_cad_entry *e = loft_cad_formats; e->name != NULL;
	    e++)
		if (n < LOFT_CAD_MAXFORMATS)
			words[n++] = e->name;
	words[n] = NULL;
	return loft_parse_word(name, words, i, err);
}
