/*
 * stream.c: the one reader and the one writer of loft streams (loft.5).
 * Program layer (loftprog.h): it reads a FILE.
 *
 * A stream is lines; '#' starts a comment; a line that is empty or white
 * space ends a record; a line whose first word begins with a letter (and
 * is not nan or inf) is a header, type word then key=value attributes,
 * and may only be a record's first line; any other line is a row of
 * numbers.  A comment-only line is ignored.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "loftprog.h"
#include "internal.h"

/*
 * Most attributes in one header.  Each new key is checked against those
 * before it, so the bound keeps a header's cost linear in its length (a
 * 1 MB header of 100000 attributes took seconds); the record types use a
 * handful.
 */
#define MAX_ATTR 64

struct loft_reader {
	FILE *fp;
	const char *name;
	long lineno;
	char *line;             /* the current line, NUL-terminated */
	size_t linecap;
	size_t linelen;
	int eof;
};

struct loft_reader *
loft_reader_new(FILE *fp, const char *name)
{
	struct loft_reader *rd = calloc(1, sizeof *rd);

	if (rd != NULL) {
		rd->fp = fp;
		rd->name = name;
	}
	return rd;
}

void
loft_reader_free(struct loft_reader *rd)
{
	if (rd != NULL)
		free(rd->line);
	free(rd);
}

static int
is_space(int c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

static int
is_letter(int c)
{
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

/* A name: a letter, then letters, digits, '-' or '_'. */
static int
is_name(const char *s, size_t len)
{
	if (len == 0 || !is_letter((unsigned char)s[0]))
		return 0;
	for (size_t i = 1; i < len; i++) {
		int c = (unsigned char)s[i];
		if (!is_letter(c) && !(c >= '0' && c <= '9') && c != '-' &&
		    c != '_')
			return 0;
	}
	return 1;
}

/* Whether s[0..len) is all printable ASCII (no space). */
static int
is_printable(const char *s, size_t len)
{
	for (size_t i = 0; i < len; i++)
		if ((unsigned char)s[i] <= ' ' || (unsigned char)s[i] >= 0x7f)
			return 0;
	return 1;
}

/* Whether s starts with the word nan, inf or infinity, in any case. */
static int
looks_nonfinite(const char *s)
{
	static const char *const words[] = { "nan", "infinity", "inf" };

	for (int i = 0; i < 3; i++) {
		size_t n = strlen(words[i]);

		if (strncasecmp(s, words[i], n) == 0 &&
		    (s[n] == '\0' || is_space((unsigned char)s[n])))
			return 1;
	}
	return 0;
}

size_t
loft_bom(const char *s, size_t n)
{
	return n >= 3 && memcmp(s, "\xef\xbb\xbf", 3) == 0 ? 3 : 0;
}

/* Kinds of line; L_NOMEM: a line too long for memory, skipped. */
enum { L_EOF, L_BLANK, L_COMMENT, L_HEADER, L_ROW, L_FAIL, L_NOMEM };

/*
 * Read the next line into rd->line, strip its comment, and classify it.
 * A NUL byte is reported as a bad line through *bad.
 */
static int
next_line(struct loft_reader *rd, struct loft_error *err, int *bad)
{
	ssize_t n;
	char *hash;
	size_t i;

	errno = 0;
	n = getline(&rd->line, &rd->linecap, rd->fp);
	if (n < 0 && errno == ENOMEM && !ferror(rd->fp)) {
		/* the line did not fit: read past it, a byte at a time */
		int c;

		while ((c = getc(rd->fp)) != EOF && c != '\n')
			;
		if (!ferror(rd->fp)) {
			rd->lineno++;
			err->line = rd->lineno;
			loft_fail(err, LOFT_ENOMEM, -1, "line too long for "
			    "memory");
			return L_NOMEM;
		}
	}
	if (n < 0) {
		if (ferror(rd->fp) || errno == ENOMEM) {
			err->line = rd->lineno;
			return loft_fail(err, LOFT_EIO, -1, "read error: %s",
			    strerror(errno ? errno : EIO)), L_FAIL;
		}
		rd->eof = 1;
		return L_EOF;
	}
	if (rd->lineno == 0 && loft_bom(rd->line, (size_t)n) > 0) {
		n -= 3;         /* the file's first bytes: a UTF-8 BOM */
		memmove(rd->line, rd->line + 3, (size_t)n + 1);
	}
	rd->lineno++;
	rd->linelen = (size_t)n;
	*bad = memchr(rd->line, '\0', (size_t)n) != NULL;
	hash = memchr(rd->line, '#', (size_t)n);
	if (hash != NULL)
		rd->linelen = (size_t)(hash - rd->line);
	rd->line[rd->linelen] = '\0';
	if (rd->linelen > 0 && rd->line[rd->linelen - 1] == '\n')
		rd->line[--rd->linelen] = '\0';
	for (i = 0; i < rd->linelen && is_space((unsigned char)rd->line[i]); i++)
		;
	if (i == rd->linelen)
		return hash != NULL ? L_COMMENT : L_BLANK;
	return is_letter((unsigned char)rd->line[i]) &&
	    !looks_nonfinite(rd->line + i) ? L_HEADER : L_ROW;
}

/* Next whitespace-separated word of s at *pos; its length, 0 at end. */
static size_t
next_word(const char *s, size_t len, size_t *pos, const char **word)
{
	size_t i = *pos, j;

	while (i < len && is_space((unsigned char)s[i]))
		i++;
	for (j = i; j < len && !is_space((unsigned char)s[j]); j++)
		;
	*word = s + i;
	*pos = j;
	return j - i;
}

static int
bad_line(struct loft_reader *rd, struct loft_error *err, const char *fmt,
    const char *arg, int len)
{
	err->line = rd->lineno;
	loft_fail(err, LOFT_EINPUT, -1, fmt, len, arg);
	return LOFT_EINPUT;
}

/* The hint for a line with a comma where a number or a type should be:
 * CSV, most likely, from a spreadsheet or a CAD export. */
#define CSV_HINT(what) what "? loft streams are whitespace-separated; " \
	"fromcad reads CSV"

/* The separator of CSV in the word w[0..n), as a spreadsheet writes it
 * (a semicolon where the decimal mark is a comma), or 0 if none. */
static int
csv_sep(const char *w, size_t n)
{
	return memchr(w, ',', n) != NULL ? ',' : memchr(w, ';', n) != NULL ?
	    ';' : 0;
}

/* Parse the header in rd->line into rec. */
static int
parse_header(struct loft_reader *rd, struct loft_record *rec,
    struct loft_error *err)
{
	size_t len = rd->linelen, pos = 0, wl;
	const char *w;
	char *t;

	if (loft__grow((void **)&rec->text, &rec->textcap, len + 1, 1) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	memcpy(rec->text, rd->line, len + 1);
	t = rec->text;
	wl = next_word(t, len, &pos, &w);
	if (!is_name(w, wl))
		return bad_line(rd, err, csv_sep(w, wl) != 0 ?
		    "bad record type '%.*s': " CSV_HINT("a CSV header") :
		    "bad record type '%.*s'", w, (int)(wl > 40 ? 40 : wl));
	rec->type = (char *)w;
	rec->type[wl] = '\0';   /* the word's end was white space or the end */
	pos = pos < len ? pos + 1 : pos;
	rec->nattr = 0;
	while ((wl = next_word(t, len, &pos, &w)) > 0) {
		char *key = (char *)w, *eq = memchr(key, '=', wl);
		size_t klen = eq ? (size_t)(eq - key) : 0;

		if (eq == NULL || !is_name(key, klen) || klen + 1 == wl ||
		    !is_printable(eq + 1, wl - klen - 1))
			return bad_line(rd, err, "bad attribute '%.*s' (want "
			    "key=value, the value printable ASCII)", key,
			    (int)(wl > 40 ? 40 : wl));
		key[klen] = '\0';
		key[wl] = '\0';
		pos = pos < len ? pos + 1 : pos;
		if (loft_attr(rec, key) != NULL)
			return bad_line(rd, err, "attribute '%.*s' given twice",
			    key, (int)klen);
		if (rec->nattr == MAX_ATTR) {
			err->line = rd->lineno;
			return loft_fail(err, LOFT_EINPUT, -1, "too many "
			    "attributes (at most %d)", MAX_ATTR);
		}
		if (loft__grow((void **)&rec->attr, &rec->attrcap,
		    rec->nattr + 1, sizeof *rec->attr) != 0)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		rec->attr[rec->nattr].key = key;
		rec->attr[rec->nattr].val = eq + 1;
		rec->nattr++;
	}
	return 0;
}

/* Parse the row of numbers in rd->line and append it to rec. */
static int
parse_row(struct loft_reader *rd, struct loft_record *rec,
    struct loft_error *err)
{
	size_t len = rd->linelen, pos = 0, wl, base = rec->nrows * rec->ncols;
	int k = 0, rc;
	const char *w;

	while ((wl = next_word(rd->line, len, &pos, &w)) > 0) {
		if (loft__grow((void **)&rec->num, &rec->numcap, base + k + 1,
		    sizeof *rec->num) != 0)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		if ((rc = loft_parse_num(w, wl, &rec->num[base + k], err)) !=
		    0) {
			if (rc == LOFT_EINPUT && csv_sep(w, wl) != 0)
				loft_fail(err, LOFT_EINPUT, -1, "'%.*s' is not a "
				    "number: %s-separated? loft streams are "
				    "whitespace-separated; fromcad reads CSV",
				    (int)(wl > 40 ? 40 : wl), w, csv_sep(w, wl) ==
				    ',' ? "comma" : "semicolon");
			err->line = rd->lineno;
			return LOFT_EINPUT;
		}
		k++;
		if (rec->nrows > 0 && k > rec->ncols)
			break;
	}
	if (rec->nrows > 0 && k != rec->ncols) {
		err->line = rd->lineno;
		return loft_fail(err, LOFT_EINPUT, -1,
		    "row has %s%d numbers where the record's first row "
		    "(line %ld) has %d", k > rec->ncols ? "more than " : "",
		    k > rec->ncols ? rec->ncols : k, rec->rowline[0],
		    rec->ncols);
	}
	if (loft__grow((void **)&rec->rowline, &rec->rowcap, rec->nrows + 1,
	    sizeof *rec->rowline) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	rec->ncols = k;
	rec->rowline[rec->nrows++] = rd->lineno;
	return 0;
}

/* Skip the rest of a bad record: up to a blank line or the end (a line
 * too long for memory is one of its lines). */
static void
skip_record(struct loft_reader *rd)
{
	struct loft_error ignored;
	int kind, bad;

	do
		kind = next_line(rd, &ignored, &bad);
	while (kind != L_BLANK && kind != L_EOF && kind != L_FAIL);
}

int
loft_read(struct loft_reader *rd, struct loft_record *rec,
    struct loft_error *err)
{
	int kind, bad = 0, started = 0, rc = 0;

	rec->type = NULL;
	rec->nattr = rec->nrows = 0;
	rec->ncols = 0;
	rec->file = rd->name;
	err->line = 0;
	err->row = -1;
	for (;;) {
		kind = rd->eof ? L_EOF : next_line(rd, err, &bad);
		if (kind == L_FAIL)
			return LOFT_READ_FAIL;
		if (kind == L_NOMEM) {
			if (!started)
				rec->line = rd->lineno;
			goto nomem;
		}
		if (kind == L_EOF || (kind == L_BLANK && started))
			return started ? 1 : 0;
		if (bad) {
			/* a NUL byte anywhere, even in a comment, is an
			 * error; it spoils the record it stands in */
			err->line = rd->lineno;
			loft_fail(err, LOFT_EINPUT, -1, "NUL byte in line");
			if (kind != L_BLANK && (started || kind != L_COMMENT))
				skip_record(rd);
			return LOFT_READ_BAD;
		}
		if (kind == L_BLANK || kind == L_COMMENT)
			continue;
		if (!started)
			rec->line = rd->lineno;
		if (kind == L_HEADER && started) {
			err->line = rd->lineno;
			rc = loft_fail(err, LOFT_EINPUT, -1, "header line inside "
			    "a record (a blank line must end the record before)");
		} else if (kind == L_HEADER) {
			rc = parse_header(rd, rec, err);
		} else {
			rc = parse_row(rd, rec, err);
		}
		started = 1;
		if (rc == LOFT_ENOMEM) {
			err->line = rd->lineno;
nomem:
			/*
			 * A record too large for memory is one bad record: the
			 * others, after it too, are still read (issue 12).
			 */
			loft_fail(err, LOFT_ENOMEM, -1, "record too large for "
			    "memory (out of memory at this line): skipped to "
			    "its end");
			skip_record(rd);
			return LOFT_READ_BAD;
		}
		if (rc != 0) {
			skip_record(rd);
			return LOFT_READ_BAD;
		}
	}
}

/* ------------------------------------------------------------------ */
/* The writer */

static void
put(struct loft_writer *w, const char *s, size_t n)
{
	if (w->bad)
		return;
	if (loft__grow((void **)&w->buf, &w->cap, w->len + n, 1) != 0) {
		w->bad = LOFT_ENOMEM;
		return;
	}
	memcpy(w->buf + w->len, s, n);
	w->len += n;
}

void
loft_put_type(struct loft_writer *w, const char *type)
{
	put(w, type, strlen(type));
	w->col = 1;
}

void
loft_put_attr(struct loft_writer *w, const char *key, const char *val)
{
	put(w, " ", 1);
	put(w, key, strlen(key));
	put(w, "=", 1);
	put(w, val, strlen(val));
}

void
loft_put_attrs_except(struct loft_writer *w, const struct loft_record *rec,
    const char *const *skip)
{
	for (size_t i = 0; i < rec->nattr; i++) {
		const char *const *s;

		for (s = skip; *s != NULL; s++)
			if (strcmp(*s, rec->attr[i].key) == 0)
				break;
		if (*s == NULL)
			loft_put_attr(w, rec->attr[i].key, rec->attr[i].val);
	}
}

void
loft_put_num(struct loft_writer *w, double x)
{
	if (!isfinite(x)) {
		w->bad = LOFT_EGEOM;
		return;
	}
	/* room for a space and the number: format it in place */
	if (w->bad || loft__grow((void **)&w->buf, &w->cap, w->len +
	    LOFT_NUMBUF + 1, 1) != 0) {
		w->bad = w->bad ? w->bad : LOFT_ENOMEM;
		return;
	}
	if (w->col++ > 0)
		w->buf[w->len++] = ' ';
	w->len += (size_t)loft_format_num(w->buf + w->len, x, w->digits);
}

void
loft_put_row(struct loft_writer *w, const double *v, int n)
{
	for (int k = 0; k < n; k++)
		loft_put_num(w, v[k]);
	loft_end_line(w);
}

void
loft_end_line(struct loft_writer *w)
{
	put(w, "\n", 1);
	w->col = 0;
}

void
loft_end_record(struct loft_writer *w)
{
	loft_end_line(w);
}

void
loft_writer_free(struct loft_writer *w)
{
	free(w->buf);
	w->buf = NULL;
	w->len = w->cap = 0;
}

void
loft_writer_cut(struct loft_writer *w, size_t mark)
{
	if (mark < w->len)
		w->len = mark;
	w->col = 0;
}

int
loft_grow(void **buf, size_t *cap, size_t need, size_t sz)
{
	return loft__grow(buf, cap, need, sz);
}

void
loft_put_record(struct loft_writer *w, const struct loft_record *rec)
{
	if (rec->type != NULL) {
		loft_put_type(w, rec->type);
		for (size_t i = 0; i < rec->nattr; i++)
			loft_put_attr(w, rec->attr[i].key, rec->attr[i].val);
		loft_end_line(w);
	}
	for (size_t i = 0; i < rec->nrows; i++)
		loft_put_row(w, rec->num + i * rec->ncols, rec->ncols);
	loft_end_record(w);
}
