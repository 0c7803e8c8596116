/*
 * record.c: a record as plain data (loft.5): its attributes, the lines
 * its rows came from, copies, and freeing.  Core (loft.h): stream.c
 * reads and writes records; the core only looks at them.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

void
loft_record_free(struct loft_record *rec)
{
	free(rec->attr);
	free(rec->num);
	free(rec->rowline);
	free(rec->text);
	memset(rec, 0, sizeof *rec);
}

const char *
loft_attr(const struct loft_record *rec, const char *key)
{
	for (size_t i = 0; i < rec->nattr; i++)
		if (strcmp(rec->attr[i].key, key) == 0)
			return rec->attr[i].val;
	return NULL;
}

long
loft_row_line(const struct loft_record *rec, long row)
{
	if (row >= 0 && (size_t)row < rec->nrows)
		return rec->rowline[row];
	return rec->line;
}

int
loft_record_copy(struct loft_record *dst, const struct loft_record *src)
{
	size_t nnum = src->nrows * (size_t)src->ncols, tlen = 0;

	if (src->type != NULL) {
		/* the header text: type and attributes, NUL-separated */
		tlen = src->nattr > 0 ? (size_t)(src->attr[src->nattr - 1].val -
		    src->text) + strlen(src->attr[src->nattr - 1].val) + 1 :
		    (size_t)(src->type - src->text) + strlen(src->type) + 1;
	}
	if (loft__grow((void **)&dst->text, &dst->textcap, tlen + 1, 1) != 0 ||
	    loft__grow((void **)&dst->attr, &dst->attrcap, src->nattr + 1,
	    sizeof *dst->attr) != 0 ||
	    loft__grow((void **)&dst->num, &dst->numcap, nnum + 1,
	    sizeof *dst->num) != 0 ||
	    loft__grow((void **)&dst->rowline, &dst->rowcap, src->nrows + 1,
	    sizeof *dst->rowline) != 0)
		return LOFT_ENOMEM;
	if (tlen > 0)
		memcpy(dst->text, src->text, tlen);
	dst->type = src->type ? dst->text + (src->type - src->text) : NULL;
	for (size_t i = 0; i < src->nattr; i++) {
		dst->attr[i].key = dst->text + (src->attr[i].key - src->text);
		dst->attr[i].val = dst->text + (src->attr[i].val - src->text);
	}
	dst->nattr = src->nattr;
	if (nnum > 0)           /* a record of no rows may have no arrays */
		memcpy(dst->num, src->num, nnum * sizeof *dst->num);
	if (src->nrows > 0)
		memcpy(dst->rowline, src->rowline, src->nrows *
		    sizeof *dst->rowline);
	dst->nrows = src->nrows;
	dst->ncols = src->ncols;
	dst->line = src->line;
	dst->file = src->file;
	return 0;
}
