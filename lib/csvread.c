/*
 * csvread.c: points in CSV into knot records, CSV as spreadsheets write
 * it (RFC 4180).  The first row names the columns; x and y are needed,
 * z is read where it is named, any other column is passed over.  A name
 * may carry its unit, "X (mm)" or "x [in]", and the unit is honoured:
 * the output is in millimetres, as fromcad's is.  Fields are separated
 * by the character a first line "sep=;" names (Excel's), or else by
 * commas, or, where the header has none, by semicolons, tabs, or blanks;
 * where that is not a comma, a comma in a number is its decimal mark.
 * A field in double quotes may hold separators, line ends and doubled
 * quotes.  A row of empty fields is a blank line, and a blank line ends
 * a record: each block of rows becomes one point record.  Empty fields
 * at the end of a row are passed over; a row with more fields than its
 * header is an error (its numbers would be guessed).  Every row is split
 * once, so the time is linear in the columns.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

/* A field: s[0..n), its quotes taken off (doubled quotes stay doubled). */
struct span {
	const char *s;
	size_t n;
};

struct csv {
	char sep;               /* ',', ';', '\t', or ' ': runs of blanks */
	int col[3];             /* the columns of x, y, z; -1: none */
	double mm[3];           /* the millimetres of each one's unit */
	size_t ncol;            /* fields the header has, empty ones at its
	                           end left out */
	struct span *f;         /* the fields of the row being read */
	size_t nf, cap;
	const char *row;        /* that row's text, for the header test */
	size_t rown;
	long lines;             /* the lines it takes, 1 or more */
};

static int
blank(char ch)
{
	return ch == ' ' || ch == '\t' || ch == '\r';
}

static int
is_sep(const struct csv *cv, char ch)
{
	return cv->sep == ' ' ? ch == ' ' || ch == '\t' : ch == cv->sep;
}

/* Add a field; 0, or -1 when memory runs out. */
static int
add(struct csv *cv, const char *s, size_t n)
{
	if (cv->nf == cv->cap && loft_grow((void **)&cv->f, &cv->cap,
	    cv->nf + 1, sizeof *cv->f) != 0)
		return -1;
	cv->f[cv->nf].s = s;
	cv->f[cv->nf++].n = n;
	return 0;
}

/* Whether ch is passed over before a field: blanks, but for a
 * separator of tabs; for blanks as separators, every blank. */
static int
lead(const struct csv *cv, char ch)
{
	return cv->sep == ' ' ? blank(ch) : blank(ch) && ch != cv->sep;
}

/*
 * Split the row that starts at *p (before end) into cv->f, by RFC 4180,
 * and move *p past it.  Returns 0, 1 for a quote never closed (the rest
 * of the text is then that field), 2 for a comment line (no fields), or
 * -1 when memory runs out.
 */
static int
split(struct csv *cv, const char **p, const char *end)
{
	const char *s = *p;
	int open = 0;

	cv->nf = 0;
	cv->row = s;
	cv->lines = 1;
	while (s < end && blank(*s))
		s++;
	if (s < end && *s == '#')
		open = 2;       /* a comment */
	else
		s = *p;
	for (; open == 0;) {
		const char *a, *b;

		while (s < end && lead(cv, *s))
			s++;
		if (s < end && *s == '"') {
			a = ++s;
			while (s < end && !(*s == '"' && (s + 1 == end ||
			    s[1] != '"'))) {
				cv->lines += *s == '\n';
				s += *s == '"' ? 2 : 1;
			}
			open = s >= end;
			b = s < end ? s++ : end;
			while (s < end && *s != '\n' && !is_sep(cv, *s))
				s++;        /* after the closing quote */
		} else {
			a = s;
			while (s < end && *s != '\n' && !is_sep(cv, *s))
				s++;
			b = s;
			while (b > a && blank(b[-1]))
				b--;
		}
		if (add(cv, a, (size_t)(b - a)) != 0)
			return -1;
		if (cv->sep == ' ')
			while (s < end && (*s == ' ' || *s == '\t'))
				s++;
		if (s >= end || *s == '\n')
			break;
		if (is_sep(cv, *s))
			s++;
	}
	while (s < end && *s != '\n')
		s++;
	cv->rown = (size_t)(s - cv->row);
	*p = s < end ? s + 1 : end;
	while (cv->nf > 0 && cv->f[cv->nf - 1].n == 0)
		cv->nf--;       /* empty fields at the end: none */
	return open;
}

/* The separator of the header, the first row of s[0..n) that is not
 * blank or a comment: the first of ',', ';' and tab found in it outside
 * quotes, or ' ' when none. */
static char
guess_sep(const char *s, size_t n)
{
	static const char order[] = ",;\t";
	int have[3] = { 0, 0, 0 }, quoted = 0;
	size_t i = 0;

	while (i < n) {
		size_t j = i;

		while (j < n && blank(s[j]))
			j++;
		if (j < n && s[j] != '\n' && s[j] != '#')
			break;
		while (j < n && s[j] != '\n')
			j++;
		i = j + 1;
	}
	for (; i < n && (quoted || s[i] != '\n'); i++) {
		const char *q = strchr(order, s[i]);

		if (s[i] == '"')
			quoted = !quoted;
		else if (!quoted && s[i] != '\0' && q != NULL)
			have[q - order] = 1;
	}
	for (int k = 0; k < 3; k++)
		if (have[k])
			return order[k];
	return ' ';
}

/*
 * The millimetres of the unit that ends the column name f[0..*fn) as
 * "(mm)" or "[in]", which is cut off *fn; 1 where it has none, 0 for a
 * unit loft does not know (its name is then in *u, *un).
 */
static double
unit_of(const char *f, size_t *fn, const char **u, size_t *un)
{
	static const struct { const char *name; double mm; } units[] = {
		{ "mm", 1 }, { "cm", 10 }, { "m", 1000 }, { "in", 25.4 },
		{ "inch", 25.4 }, { "inches", 25.4 }, { "ft", 304.8 },
	};
	size_t n = *fn, a;
	char close = n > 0 ? f[n - 1] : 0;

	if (close != ')' && close != ']')
		return 1;
	for (a = n - 1; a > 0 && f[a - 1] != (close == ')' ? '(' : '['); a--)
		;
	if (a == 0)
		return 1;
	*u = f + a;
	*un = n - 1 - a;
	for (*fn = a - 1; *fn > 0 && blank(f[*fn - 1]); (*fn)--)
		;
	while (*un > 0 && blank(**u)) {
		(*u)++;
		(*un)--;
	}
	while (*un > 0 && blank((*u)[*un - 1]))
		(*un)--;
	for (size_t i = 0; i < sizeof units / sizeof *units; i++)
		if (loft__word_is(*u, *un, units[i].name))
			return units[i].mm;
	return 0;
}

/* Read the header row in cv->f: 0, or -1 after complaining. */
static int
header(struct csv *cv, struct loft_cadin *c, long line)
{
	static const char *const names[3] = { "x", "y", "z" };

	cv->col[0] = cv->col[1] = cv->col[2] = -1;
	cv->ncol = cv->nf;
	for (size_t i = 0; i < cv->nf; i++) {
		const char *f = cv->f[i].s, *u = NULL;
		size_t fn = cv->f[i].n, un = 0;
		double mm = unit_of(f, &fn, &u, &un);

		for (int q = 0; q < 3; q++) {
			char t[31];

			if (!loft__word_is(f, fn, names[q]))
				continue;
			if (cv->col[q] >= 0) {
				loft__cadin_say(c, line, "the header names "
				    "column %s twice", names[q]);
				return -1;
			}
			if (mm == 0) {
				loft__cadin_say(c, line, "column %s: unit '%s' "
				    "is none loft knows: want mm, cm, m, in or ft",
				    names[q], loft__cadin_quote(t, sizeof t, u,
				    un));
				return -1;
			}
			cv->col[q] = (int)(i < 1000000000 ? i : 1000000000);
			cv->mm[q] = mm;
		}
	}
	if (cv->col[0] < 0 || cv->col[1] < 0) {
		loft__cadin_say(c, line, "the header line names no x and y "
		    "columns: want a first line such as 'x,y' or 'x,y,z'");
		return -1;
	}
	return 0;
}

/* The number in field f, a comma as its decimal mark where the
 * separator is not one: 0, or -1. */
static int
number(const struct csv *cv, const struct span *f, double *x)
{
	char t[64];

	if (cv->sep == ',' || f->n >= sizeof t || memchr(f->s, ',', f->n) ==
	    NULL)
		return loft_parse_num(f->s, f->n, x, NULL) != 0 ? -1 : 0;
	for (size_t i = 0; i < f->n; i++)
		t[i] = f->s[i] == ',' ? '.' : f->s[i];
	return loft_parse_num(t, f->n, x, NULL) != 0 ? -1 : 0;
}

/* The numbers of the row in cv->f into x: 0, or -1 after complaining. */
static int
row(const struct csv *cv, struct loft_cadin *c, long line, int dim,
    double *x)
{
	char t[31];

	if (cv->nf > cv->ncol) {
		loft__cadin_say(c, line, "the row has %zu fields and the "
		    "header %zu%s: the record is not read", cv->nf, cv->ncol,
		    cv->sep == ',' ? " (decimal commas want ';' between "
		    "fields)" : "");
		return -1;
	}
	for (int q = 0; q < dim; q++) {
		const struct span *f = cv->f + cv->col[q];

		if ((size_t)cv->col[q] >= cv->nf) {
			loft__cadin_say(c, line, "the row has no column %c "
			    "(field %d): the record is not read", "xyz"[q],
			    cv->col[q] + 1);
			return -1;
		}
		if (number(cv, f, &x[q]) != 0 || !isfinite(x[q] *= cv->mm[q])) {
			loft__cadin_say(c, line, "%c '%s' is not a finite "
			    "number: the record is not read", "xyz"[q],
			    loft__cadin_quote(t, sizeof t, f->s, f->n));
			return -1;
		}
	}
	return 0;
}

/* A first line "sep=X": X, else 0. */
static char
sep_line(const char *p, const char *end)
{
	const char *s = p;

	if (s < end && *s == '"')
		s++;
	if (end - s >= 5 && memcmp(s, "sep=", 4) == 0 && s[4] != '\n' &&
	    s[4] != '\r')
		return s[4];
	return 0;
}

/* Per block: where its record began in the output, its first line, and
 * whether it has rows and whether one was bad. */
struct block {
	size_t mark;
	long first;
	int have, bad;
};

/* End the block b: its record written whole, or nothing of it. */
static void
end_block(struct block *b, struct loft_cadin *c)
{
	if (b->have && !b->bad) {
		loft_end_record(c->w);
		loft__cadin_done(c, b->mark, b->first);
	} else if (b->bad) {
		loft_writer_cut(c->w, b->mark);
	}
	b->mark = c->w->len;
	b->have = b->bad = 0;
}

/* Read the rows from p on; 0, or LOFT_ENOMEM. */
static int
rows(struct csv *cv, struct loft_cadin *c, const char *p, const char *end,
    long line)
{
	struct block b = { c->w->len, 0, 0, 0 };
	const char *hdr = NULL;
	size_t hn = 0;
	int dim = 2;

	while (p < end) {
		long at = line;
		int rc = split(cv, &p, end);
		double x[3] = { 0, 0, 0 };

		line += cv->lines;
		if (rc < 0)
			return LOFT_ENOMEM;
		if (rc == 1)
			loft__cadin_say(c, at, "a quote is never closed: the "
			    "rest of the text is one field");
		if (rc == 2)
			continue;                       /* a comment */
		if (cv->nf == 0) {
			end_block(&b, c);               /* a blank row */
			continue;
		}
		if (hdr == NULL) {
			if (header(cv, c, at) != 0)
				return 0;
			hdr = cv->row;
			hn = cv->rown;
			dim = cv->col[2] >= 0 ? 3 : 2;
			continue;
		}
		if (!b.have && cv->rown == hn && memcmp(cv->row, hdr, hn) == 0)
			continue;       /* the header again, over a block */
		if (!b.have) {
			b.first = at;
			b.have = 1;
		}
		if (!b.bad && row(cv, c, at, dim, x) != 0)
			b.bad = 1;
		if (!b.bad)
			loft_put_row(c->w, x, dim);
	}
	end_block(&b, c);
	if (hdr == NULL)
		loft__cadin_say(c, line - 1, "no header line: want a first "
		    "line such as 'x,y' or 'x,y,z'");
	return 0;
}

int
loft_csv_read(const char *buf, size_t len, struct loft_cadin *c)
{
	struct csv cv = { 0, { -1, -1, -1 }, { 1, 1, 1 }, 0, NULL, 0, 0, NULL,
	    0, 0 };
	const char *p = buf + loft_bom(buf, len), *end = buf + len;
	long nbad = c->nbad, line = 1;
	int rc;

	if ((cv.sep = sep_line(p, end)) != 0) {
		p = memchr(p, '\n', (size_t)(end - p));
		p = p != NULL ? p + 1 : end;
		line++;
	} else
		cv.sep = guess_sep(p, (size_t)(end - p));
	rc = rows(&cv, c, p, end, line);
	free(cv.f);
	if (rc != 0) {
		loft__cadin_say(c, 0, "out of memory");
		return LOFT_ENOMEM;
	}
	return c->nbad > nbad ? LOFT_EINPUT : 0;
}
