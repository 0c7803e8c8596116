/*
 * stream.c: libFuzzer harness of the stream reader and writer.  Every
 * record the reader accepts must hold what loft.5 promises (rows of one
 * length, finite numbers, names and printable values), and written out
 * again must read back the same: bit for bit losslessly, and as a good
 * record with -p digits (here 1 + size % 17).  Every bad record must
 * come with a message naming its line.
 */
#include <math.h>

#include "fuzz.h"

static int
is_name(const char *s)
{
	if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z')))
		return 0;
	for (s++; *s != '\0'; s++)
		if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') ||
		    (*s >= '0' && *s <= '9') || *s == '-' || *s == '_'))
			return 0;
	return 1;
}

static void
check_record(const struct loft_record *rec)
{
	FUZZ_ASSERT(rec->type == NULL || is_name(rec->type), "bad type");
	FUZZ_ASSERT(rec->nattr <= 64, "too many attributes");
	for (size_t i = 0; i < rec->nattr; i++) {
		const char *v = rec->attr[i].val;

		FUZZ_ASSERT(is_name(rec->attr[i].key), "bad key");
		FUZZ_ASSERT(*v != '\0', "empty value");
		for (; *v != '\0'; v++)
			FUZZ_ASSERT(*v > ' ' && *v < 0x7f && *v != '#',
			    "value not printable");
	}
	FUZZ_ASSERT(rec->nrows == 0 || rec->ncols >= 1, "row of no numbers");
	FUZZ_ASSERT(rec->nrows > 0 || rec->type != NULL, "empty record");
	for (size_t i = 0; i < rec->nrows * rec->ncols; i++)
		FUZZ_ASSERT(isfinite(rec->num[i]), "number not finite");
	for (size_t i = 0; i < rec->nrows; i++)
		FUZZ_ASSERT(rec->rowline[i] > (i ? rec->rowline[i - 1] :
		    rec->line - (rec->type == NULL)), "row lines out of order");
}

/* rec written with digits (0: lossless), into w */
static void
write_record(struct loft_writer *w, const struct loft_record *rec, int digits)
{
	static const char *const none[] = { NULL };

	w->len = 0;
	w->bad = 0;
	w->col = 0;
	w->digits = digits;
	if (rec->type != NULL) {
		loft_put_type(w, rec->type);
		loft_put_attrs_except(w, rec, none);
		loft_end_line(w);
	}
	for (size_t i = 0; i < rec->nrows; i++)
		loft_put_row(w, rec->num + i * rec->ncols, rec->ncols);
	loft_end_record(w);
	FUZZ_ASSERT(!w->bad, "writer refused a record the reader accepted");
}

/* The text in w must read back as one record; lossless: equal to rec. */
static void
read_back(const struct loft_writer *w, const struct loft_record *rec,
    int lossless)
{
	struct loft_record back = { 0 };
	struct loft_error err;
	struct loft_reader *rd;
	char *copy;
	FILE *fp = fuzz_open((const uint8_t *)w->buf, w->len, &copy);
	int r;

	FUZZ_ASSERT(fp != NULL, "fmemopen");
	rd = loft_reader_new(fp, "back");
	FUZZ_ASSERT(rd != NULL, "out of memory");
	r = loft_read(rd, &back, &err);
	if (r != 1)
		fprintf(stderr, "fuzz: read back: %s\n", err.msg);
	FUZZ_ASSERT(r == 1, "a written record does not read back");
	FUZZ_ASSERT(back.nrows == rec->nrows && back.nattr == rec->nattr &&
	    (rec->nrows == 0 || back.ncols == rec->ncols), "shape changed");
	FUZZ_ASSERT((back.type == NULL) == (rec->type == NULL) &&
	    (rec->type == NULL || strcmp(back.type, rec->type) == 0),
	    "type changed");
	for (size_t i = 0; i < rec->nattr; i++)
		FUZZ_ASSERT(strcmp(back.attr[i].key, rec->attr[i].key) == 0 &&
		    strcmp(back.attr[i].val, rec->attr[i].val) == 0,
		    "attribute changed");
	for (size_t i = 0; lossless && i < rec->nrows * rec->ncols; i++)
		FUZZ_ASSERT(back.num[i] == rec->num[i], "number not lossless");
	FUZZ_ASSERT(loft_read(rd, &back, &err) == 0, "more than one record");
	loft_record_free(&back);
	loft_reader_free(rd);
	fuzz_close(fp, copy);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct loft_record rec = { 0 };
	struct loft_writer w = { 0 };
	struct loft_error err;
	struct loft_reader *rd;
	char *copy;
	FILE *fp = fuzz_open(data, size, &copy);
	int r;

	if (fp == NULL)
		return 0;
	rd = loft_reader_new(fp, "fuzz");
	FUZZ_ASSERT(rd != NULL, "out of memory");
	while ((r = loft_read(rd, &rec, &err)) != 0) {
		FUZZ_ASSERT(r != LOFT_READ_FAIL, "read error on memory");
		if (r == LOFT_READ_BAD) {
			FUZZ_ASSERT(err.msg[0] != '\0' && err.line >= 1,
			    "bad record without message or line");
			continue;
		}
		check_record(&rec);
		write_record(&w, &rec, 0);
		read_back(&w, &rec, 1);
		write_record(&w, &rec, 1 + (int)(size % 17));
		read_back(&w, &rec, 0);
	}
	loft_writer_free(&w);
	loft_record_free(&rec);
	loft_reader_free(rd);
	fuzz_close(fp, copy);
	return 0;
}
