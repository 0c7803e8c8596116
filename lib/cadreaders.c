/*
 * cadreaders.c: the table of CAD readers, fromcad -f's words, in a file
 * of its own (as Lua's linit.c holds its libraries): a new reader is
 * its module (lib/FORMATread.c, with a read and a sniff function) and
 * one line here.  Readers are sniffed in this order; a document that
 * two could take goes to the first.
 * Program layer (loftprog.h, cadread.h).
 */
#include "cadread.h"

const struct loft_cadin_reader loft_cadin_readers[] = {
	{ "dxf", loft__dxf_sniff, loft_dxf_read },
	{ "svg", loft__svg_sniff, loft_svg_read },
	{ "csv", loft__csv_sniff, loft_csv_read },
	{ "step", loft__step_sniff, loft_step_read },
	{ "iges", loft__iges_sniff, loft_iges_read },
	{ NULL, NULL, NULL }
};
