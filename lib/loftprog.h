/*
 * loftprog.h: the program layer of libloft, written only on the core's
 * public interface (loft.h): streams of records read from a FILE and
 * written whole, the read-compute-write loop every program shares and
 * its manners of reporting, the option helpers, the table of record
 * types (what each can be), designs from records and back, output split
 * into files, and reading CAD documents into records.  loft.h's
 * conventions hold here too; unlike the core, the functions here write
 * to the streams they are handed.
 */
#ifndef LOFTPROG_H
#define LOFTPROG_H

#include <stdio.h>

#include "loft.h"

/* ------------------------------------------------------------------ */
/* Streams: reading records from a FILE, writing them (stream.c)       */

struct loft_reader;

/* The length of the UTF-8 byte order mark that text s[0..n) begins
 * with: 3, or 0 when none.  Every reader of text skips it (issue 24). */
size_t loft_bom(const char *s, size_t n);

/* A reader over fp, whose messages call it name.  NULL: out of memory. */
struct loft_reader *loft_reader_new(FILE *fp, const char *name);
void loft_reader_free(struct loft_reader *rd);

/*
 * Read the next record into rec.  Returns 1 when a record was read, 0 at
 * the end of the stream, LOFT_READ_BAD when a malformed record, or one
 * too large for memory, was read and skipped (err says what and where;
 * the next call goes on after it), LOFT_READ_FAIL on a read error or
 * when memory ran out otherwise (err says which).
 */
#define LOFT_READ_BAD  (-1)
#define LOFT_READ_FAIL (-2)
int loft_read(struct loft_reader *rd, struct loft_record *rec,
    struct loft_error *err);

/*
 * The writer collects the text of the records a program makes from one
 * input record, so that they go out whole or not at all.  digits is as
 * for loft_format_num.  A writer starts zeroed, with digits set.
 */
struct loft_writer {
	char *buf;
	size_t len, cap;
	int digits;
	int bad;                /* a number was not finite, or out of memory */
	int col;                /* numbers written on the current line */
};

void loft_put_type(struct loft_writer *w, const char *type);
void loft_put_attr(struct loft_writer *w, const char *key, const char *val);
void loft_put_num(struct loft_writer *w, double x);
void loft_put_row(struct loft_writer *w, const double *v, int n);
void loft_end_line(struct loft_writer *w);
void loft_end_record(struct loft_writer *w);   /* the blank line */
void loft_writer_free(struct loft_writer *w);
/*
 * Take back what w holds after mark, a w->len read at the start of a
 * record (or 0: everything): w->len is mark again (kept when it is
 * already below), and w is at the start of a line.  w->bad is the
 * caller's to clear.  The one way a record is taken out of a writer.
 */
void loft_writer_cut(struct loft_writer *w, size_t mark);

/*
 * Grow the malloc'd array *buf of *cap elements of sz bytes (NULL and 0
 * at first) to hold at least need, by the library's rule (capacities
 * double): 0, or -1 when memory ran out or need * sz overflows, *buf
 * and *cap as they were.  sz > 0.
 */
int loft_grow(void **buf, size_t *cap, size_t need, size_t sz);

/*
 * Copy the record's attributes to w's current header line, except those
 * whose keys appear in the NULL-terminated list skip.
 */
void loft_put_attrs_except(struct loft_writer *w, const struct loft_record *rec,
    const char *const *skip);

/* ------------------------------------------------------------------ */
/* The read-compute-write loop shared by every program (run.c)         */

struct loft_run;

/*
 * A program's record handler.  It reads rec, writes what it makes to
 * run->w, and returns 0; or returns a LOFT_E* code with err filled, and
 * then whatever it wrote is dropped.
 */
typedef int (*loft_handler)(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err);

struct loft_run {
	const char *prog;       /* for messages: "prog: FILE:LINE: ..." */
	FILE *out, *msg;        /* standard output and standard error */
	struct loft_writer w;
	loft_handler handle;
	void *ctx;              /* the program's options */
	int status;             /* 0, or 1 once anything went wrong */
};

/*
 * Read every named file ("-" is standard input; no names: standard
 * input), hand each record to run->handle, and write what it made to
 * run->out, one input record's output whole at a time.  Bad records and
 * unreadable files get one message on run->msg each and set status 1;
 * the loop goes on.  Returns the exit status: 0, or 1 when anything was
 * reported or a write failed.
 */
int loft_run_files(struct loft_run *run, int nfiles, char **files);

/*
 * For a program that makes its output from its options, not from input:
 * write what run->w holds to run->out, whole or (when it holds a number
 * that is not finite) not at all with a message, flush, free the writer,
 * and return the exit status as loft_run_files does.
 */
int loft_run_made(struct loft_run *run);

/*
 * For programs that write one document from all the records (loftplot):
 * after loft_run_files has handed every record to a handler that kept
 * what it needs and wrote nothing, write doc[0..len) to run->out and
 * flush it, with loft_run_files' manners for a failed write (a message
 * on run->msg, none for a closed pipe).  Returns the exit status:
 * run->status, or 1 when the write failed.
 */
int loft_run_write(struct loft_run *run, const char *doc, size_t len);

/*
 * A program's usage text ("usage: prog ...") and exit: with status 0 (-h)
 * the text goes to standard output, and a failed write makes it "prog:
 * write error: reason" on standard error (none for a closed pipe) and
 * exit 1; with another status (a usage error) it goes to standard error.
 */
void loft_usage(const char *text, int status)
#if defined(__GNUC__)
	__attribute__((noreturn))
#endif
	;

/*
 * A usage text whose option takes the names of a table: head, the names
 * joined by '|', then tail, into buf (n bytes, cut to fit, always
 * ended), so that a new entry in the table needs no edit of the
 * program.  name points at the first entry's name; the next is stride
 * bytes on (the entries' size), and a NULL name ends them.  Returns buf.
 */
const char *loft_usage_words(char *buf, size_t n, const char *head,
    const char *const *name, size_t stride, const char *tail);

/*
 * A usage error and exit 2: "prog: -opt msg" (or "prog: msg" when opt is
 * 0) on standard error, then the usage text there (loft_usage).  Every
 * option a program cannot take ends here.
 */
void loft_usage_error(const char *usage, int opt, const char *msg)
#if defined(__GNUC__)
	__attribute__((noreturn))
#endif
	;

/*
 * The long options of every program, called first in main: when
 * argv[1] is --help, loft_usage(usage, 0); when it is --version, the
 * line "prog (loft) VERSION" on standard output and exit 0 (1 with a
 * message when the write fails, as loft_usage).  Returns otherwise, with
 * argv unchanged.  Precondition: usage is "usage: prog ...".
 */
void loft_opt_long(int argc, char *argv[], const char *usage);

/*
 * The option -p DIGITS of every program that writes numbers: a whole
 * number 1 to 17, the significant digits w writes (loft_put_num).
 * Returns 0, or LOFT_EINPUT with err saying why (w unchanged).
 */
int loft_opt_digits(const char *arg, struct loft_writer *w,
    struct loft_error *err);

/*
 * The option -f NAME,NAME,... of measure and hydro: each name's index in
 * names (NULL-ended, as loft_parse_word) into field[0..*n), at most max
 * of them.  Returns 0, or LOFT_EINPUT with err saying why (a name not
 * among names, or more than max).
 */
int loft_opt_fields(const char *arg, const char *const *names, int *field,
    int max, int *n, struct loft_error *err);

/*
 * Option opt's levels: "v", or "from:to:step" (from <= to, step > 0; the
 * steps in 15 decimal digits, to itself included where they reach it
 * within rounding), or a comma-separated list of those, appended to the
 * malloc'd *v of *n (capacity *cap).  A bad arg is a usage error
 * (loft_usage_error with usage); when memory runs out, "prog: out of
 * memory" and exit 1.  (optrange.c)
 */
void loft_opt_range(const char *usage, int opt, const char *arg, double **v,
    size_t *n, size_t *cap);

/* Write "prog: FILE:LINE: msg" for rec and err to run->msg; set status. */
void loft_report(struct loft_run *run, const struct loft_record *rec,
    const struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Whole records, and whole designs (stream.c, run.c)                  */

/* Write rec to w as it was read: header, attributes, rows, blank line. */
void loft_put_record(struct loft_writer *w, const struct loft_record *rec);

/*
 * A handler of a whole design: all n records of the input at once.  It
 * writes what it makes to run->w and returns 0, or reports each problem
 * with loft_report (or on run->msg) and returns nonzero; then nothing is
 * written.
 */
typedef int (*loft_design_handler)(struct loft_run *run,
    const struct loft_record *recs, size_t n);

/*
 * Read every record of the named files (as loft_run_files does: "-" is
 * standard input, no names: standard input) and hand them all, in
 * order, to design, once.  When any record was bad or any file
 * unreadable, each gets its message as in loft_run_files, design is not
 * called, and nothing is written.  Otherwise what design wrote goes out
 * whole, or nothing when it failed.  run->handle is not used.  Returns
 * the exit status: 0, or 1 when anything was reported or a write failed.
 */
int loft_run_design(struct loft_run *run, int nfiles, char **files,
    loft_design_handler design);

/* ------------------------------------------------------------------ */
/* Designs from records, and back (design.c)                          */

/*
 * Read the `patch` records among recs[0..n) into d, in order (other
 * records are left to the caller), and check the design.  Each bad
 * record or link gets its message through loft_report.  Returns 0, or
 * nonzero after reporting.
 */
int loft_design_from_records(struct loft_run *run,
    const struct loft_record *recs, size_t n, struct loft_design *d);

/*
 * For programs that read patches only: report each record of recs[0..n)
 * that is not a `patch` ("TYPE record: PROG reads patch records").
 * Returns 0 if there is none, else nonzero after reporting them all.
 */
int loft_design_only_patches(struct loft_run *run,
    const struct loft_record *recs, size_t n);

/* Write patch i of d as a `patch` record, keeping its other attributes. */
void loft_design_put(struct loft_writer *w, const struct loft_design *d,
    size_t i);

/*
 * The surfaces of recs[0..n) (patch, bezier-surface, in space), for
 * programs that take a set of surfaces whole: each other record, or bad
 * one, is reported through loft_report.  Returns 0 with *out (malloc'd,
 * pointing into recs; the caller frees it) and *ns, or nonzero after
 * reporting (*out NULL).  (surfrecs.c)
 */
int loft_surfaces_from_records(struct loft_run *run,
    const struct loft_record *recs, size_t n, struct loft_surface **out,
    size_t *ns);

/* ------------------------------------------------------------------ */
/* Output split into files, each written whole (outfiles.c)            */

struct loft_outfile {
	char *name;
	char *buf;
	size_t len, cap;
};

/* Files by name, in the order first named.  Starts zeroed. */
struct loft_outfiles {
	struct loft_outfile *f;
	size_t n, cap;
};

/*
 * Append text[0..len) to the file called name in s (a new one at the
 * end if s has none).  Returns 0 or LOFT_ENOMEM.
 */
int loft_outfiles_add(struct loft_outfiles *s, const char *name,
    const char *text, size_t len, struct loft_error *err);

/*
 * Write f whole: to a new temporary file beside it, then renamed over
 * f->name.  Returns 0, or LOFT_EIO or LOFT_ENOMEM with a message that
 * starts with the file's name ("NAME: cannot create: reason"); then no
 * file is left behind and an old one of that name is untouched.
 */
int loft_outfile_write(const struct loft_outfile *f, struct loft_error *err);

void loft_outfiles_free(struct loft_outfiles *s);

/* ------------------------------------------------------------------ */
/* Reading CAD documents into records (cadread.c, dxfread.c,          */
/* svgread.c, csvread.c)                                               */

struct loft_cadin;

/*
 * A reader of a CAD format: its name (fromcad -f's word), whether a
 * document buf[0..len) looks like one of its (sniff: 1 or 0), and its
 * reading (as loft_cadin_read).  loft_cadin_readers (cadreaders.c) is
 * the table of them, in the order they are sniffed, ended by a NULL
 * name: a new reader is its module and one line there.
 */
struct loft_cadin_reader {
	const char *name;
	int (*sniff)(const char *buf, size_t len);
	int (*read)(const char *buf, size_t len, struct loft_cadin *c);
};
extern const struct loft_cadin_reader loft_cadin_readers[];

/* loft_parse_word of name among the readers' names (fromcad -f): 0 and
 * the reader's index in *i, or an error naming the choices. */
#define LOFT_CADIN_MAXREADERS 32
int loft_cadin_find(const char *name, int *i, struct loft_error *err);

/*
 * Circular and elliptic arcs are not polynomial, so the readers
 * approximate them: DXF arcs (bulges, ARC, CIRCLE) by chords, SVG arcs
 * by cubic pieces, each within a distance of the true arc.  That
 * distance is tol (in the output's units) when tol > 0, else
 * LOFT_CADIN_ARC_REL times the arc's radius (its larger semi-axis): a
 * hundredth of a millimetre on a 100 mm radius, finer than a cutter's
 * kerf, and scale-free.  An arc that would need more than
 * LOFT_CADIN_ARC_MAX pieces for tol is refused (a tol far below the
 * arc's size is a mistake, not a request for a million points).
 */
#define LOFT_CADIN_ARC_REL 1e-4
#define LOFT_CADIN_ARC_MAX 100000

/*
 * A reading: the records go to w, each whole (a record that fails is
 * taken back out of w); each problem found is handed to complain with
 * the document's line (1-based) and a message of no newline, and
 * counted in nbad.  The reader goes on after each problem.
 */
struct loft_cadin {
	double tol;             /* arcs: see LOFT_CADIN_ARC_REL; 0: relative */
	struct loft_writer *w;
	void (*complain)(void *ctx, long line, const char *msg);
	void *ctx;
	long nbad;
	/* fromcad -S: an annotation (text, dimension, image...) or a fill
	 * is a complaint too; 0: they are passed over, counted in a note */
	int strict;
	/* fromcad -H: geometry hidden (DXF layers off or frozen, SVG
	 * display:none, visibility:hidden) is read; 0: passed over */
	int hidden;
	/* fromcad -F: DXF HATCH boundaries are read as closed curves */
	int fills;
	/* Where notes go (what was passed over; line 0): NULL, nowhere.
	 * A note is no complaint: it is not counted in nbad. */
	void (*note)(void *ctx, long line, const char *msg);
};

/*
 * The format of the document buf[0..len), told from its content: a
 * binary or ASCII DXF, an XML document (SVG), or a text whose first line
 * names columns (CSV): the first reader of loft_cadin_readers whose
 * sniff takes it.  Returns its index there, or -1 when no reader takes
 * it (len 0 included).
 */
int loft_cadin_sniff(const char *buf, size_t len);

/*
 * Read the whole document buf[0..len) of the given format into records
 * (fromcad(1) and loft(5) say which records each element becomes).
 * Returns 0 when all of it was read; LOFT_EINPUT when anything was
 * complained about (the rest was read); LOFT_ENOMEM when memory ran out
 * (complained about too; what was read before may be in w).
 */
int loft_cadin_read(int format, const char *buf, size_t len, struct loft_cadin *c);
/* The readers of loft_cadin_readers, and their sniffs (cadread.c). */
int loft_dxf_read(const char *buf, size_t len, struct loft_cadin *c);
int loft_svg_read(const char *buf, size_t len, struct loft_cadin *c);
int loft_csv_read(const char *buf, size_t len, struct loft_cadin *c);
int loft_step_read(const char *buf, size_t len, struct loft_cadin *c);
int loft_iges_read(const char *buf, size_t len, struct loft_cadin *c);

#endif
