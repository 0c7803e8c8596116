/*
 * csvread.c: points in CSV into knot records.  The first line names the
 * columns; x and y are needed, z is read where it is named, any other
 * column is passed over.  The fields are separated by commas (or, where
 * the header has none, by semicolons, tabs, or blanks).  A blank line
 * ends a record: each block of rows becomes one point record.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <string.h>

#include "cadread.h"

struct csv {
	char sep;               /* ',', ';', '\t', or ' ': runs of blanks */
	int col[3];             /* the columns of x, y, z; -1: none */
	int ncol;               /* fields the header has */
};

/* Field k of line s[0..n) without blanks and quotes: 0, or -1 when the
 * line has fewer fields. */
static int
field(const struct csv *cv, const char *s, size_t n, int k, const char **f,
    size_t *fn)
{
	size_t i = 0, a, b;

	for (int j = 0;; j++) {
		if (cv->sep == ' ')
			while (i < n && (s[i] == ' ' || s[i] == '\t'))
				i++;
		a = i;
		while (i < n && (cv->sep == ' ' ? s[i] != ' ' && s[i] != '\t' :
		    s[i] != cv->sep))
			i++;
		b = i;
		if (j == k)
			break;
		if (i >= n)
			return -1;
		i++;
	}
	while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r'))
		a++;
	while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' ||
	    s[b - 1] == '\r'))
		b--;
	if (b - a >= 2 && (s[a] == '"' || s[a] == '\'') && s[b - 1] == s[a]) {
		a++;
		b--;
	}
	*f = s + a;
	*fn = b - a;
	return 0;
}

/* Read the header line: 0, or -1 after complaining. */
static int
header(struct csv *cv, struct loft_cadin *c, const char *s, size_t n, long line)
{
	static const char *const names[3] = { "x", "y", "z" };
	const char *f;
	size_t fn;

	cv->sep = memchr(s, ',', n) ? ',' : memchr(s, ';', n) ? ';' :
	    memchr(s, '\t', n) ? '\t' : ' ';
	cv->col[0] = cv->col[1] = cv->col[2] = -1;
	for (cv->ncol = 0; field(cv, s, n, cv->ncol, &f, &fn) == 0; cv->ncol++)
		for (int q = 0; q < 3; q++)
			if (loft__word_is(f, fn, names[q])) {
				if (cv->col[q] >= 0) {
					loft__cadin_say(c, line, "the header "
					    "names column %s twice", names[q]);
					return -1;
				}
				cv->col[q] = cv->ncol;
			}
	if (cv->col[0] < 0 || cv->col[1] < 0) {
		loft__cadin_say(c, line, "the header line names no x and y "
		    "columns: want a first line such as 'x,y' or 'x,y,z'");
		return -1;
	}
	return 0;
}

int
loft_csv_read(const char *buf, size_t len, struct loft_cadin *c)
{
	struct loft_writer *w = c->w;
	struct csv cv = { 0, { -1, -1, -1 }, 0 };
	const char *p = buf, *end = buf + len, *hdr = NULL;
	size_t hn = 0, mark = w->len;
	long line = 0, first = 0, nbad = c->nbad;
	int have = 0, bad = 0, dim = 2;

	if (len >= 3 && memcmp(buf, "\xef\xbb\xbf", 3) == 0)
		p += 3;
	while (p <= end) {
		const char *e = p < end ? memchr(p, '\n', (size_t)(end - p)) :
		    NULL, *s = p, *f;
		size_t n = (size_t)((e ? e : end) - p), i = 0, fn;
		double x[3] = { 0, 0, 0 };

		p = e ? e + 1 : end + 1;
		line++;
		while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r'))
			i++;
		if (i == n || s[i] == '#') {
			if (i < n)
				continue;       /* a comment */
			/* a blank line (or the end): the record ends */
			if (have && !bad) {
				loft_end_record(w);
				loft__cadin_done(c, mark, first);
			}
			w->len = bad ? mark : w->len;
			mark = w->len;
			have = bad = 0;
			continue;
		}
		if (hdr == NULL) {
			if (header(&cv, c, s, n, line) != 0)
				return LOFT_EINPUT;
			hdr = s;
			hn = n;
			dim = cv.col[2] >= 0 ? 3 : 2;
			continue;
		}
		if (!have && n == hn && memcmp(s, hdr, n) == 0)
			continue;       /* the header again, over a block */
		if (!have) {
			first = line;
			have = 1;
		}
		if (bad)
			continue;
		for (int q = 0; q < dim && !bad; q++) {
			if (field(&cv, s, n, cv.col[q], &f, &fn) != 0) {
				loft__cadin_say(c, line, "the row has no column "
				    "%c (field %d): the record is not read",
				    "xyz"[q], cv.col[q] + 1);
				bad = 1;
			} else if (loft_parse_num(f, fn, &x[q], NULL) != 0) {
				char t[31];

				loft__cadin_say(c, line, "%c '%s' is not a "
				    "finite number: the record is not read",
				    "xyz"[q], loft__cadin_quote(t, sizeof t, f,
				    fn));
				bad = 1;
			}
		}
		if (!bad)
			loft_put_row(w, x, dim);
	}
	if (have && !bad) {     /* the last record, with no blank line after */
		loft_end_record(w);
		loft__cadin_done(c, mark, first);
	} else if (bad) {
		w->len = mark;
		w->col = 0;
	}
	if (hdr == NULL)
		loft__cadin_say(c, line, "no header line: want a first line "
		    "such as 'x,y' or 'x,y,z'");
	return c->nbad > nbad ? LOFT_EINPUT : 0;
}
