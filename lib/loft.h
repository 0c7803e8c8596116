/*
 * loft.h: the one public header of libloft, the geometry and stream
 * library behind the loft programs.
 *
 * Conventions, for every function below:
 *  - Arrays are caller-owned.  Points are stored row by row: point i of a
 *    set of dimension dim starts at p[i * dim].
 *  - Functions that can fail return 0 on success and a nonzero LOFT_E*
 *    code on failure, and then fill the caller's struct loft_error with a
 *    message (no trailing newline) and, where the failure belongs to one
 *    row of the input, that row's index.
 *  - The library never prints on its own and never exits.  The functions
 *    that write (the writer, loft_run) write only to the streams they are
 *    handed.
 */
#ifndef LOFT_H
#define LOFT_H

#include <stddef.h>
#include <stdio.h>

#define LOFT_MAXDIM 3           /* curves live in the plane or in space */

/* Error codes. */
enum {
	LOFT_OK = 0,
	LOFT_EINPUT,            /* malformed input: syntax, counts, values */
	LOFT_EGEOM,             /* a geometric degeneracy named in the message */
	LOFT_ENOCONV,           /* an iteration did not converge */
	LOFT_ENOMEM,            /* out of memory */
	LOFT_EIO                /* a read or write failed */
};

struct loft_error {
	long line;              /* input line, or 0 when unknown */
	long row;               /* offending row of the record, or -1 */
	char msg[256];
};

/* Fill err with a printf-style message; row may be -1.  Returns code. */
int loft_fail(struct loft_error *err, int code, long row, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 4, 5)))
#endif
	;

/* ------------------------------------------------------------------ */
/* Numbers (num.c)                                                     */

/*
 * Parse one strict decimal number: [+-]digits[.digits][(e|E)[+-]digits],
 * with at least one digit in the mantissa, from s[0..len).  No hex, no
 * "nan" or "inf", no leading or trailing characters.  Finite results
 * only: overflow is an error, underflow to a subnormal or zero is not.
 * Returns 0 and stores *x, or LOFT_EINPUT with a message in err.
 */
int loft_parse_num(const char *s, size_t len, double *x,
    struct loft_error *err);

/*
 * Parse a comma-separated list of at most max numbers ("1,0" or
 * "0.5,2,-1") into v.  Returns 0 and stores the count in *n.
 */
int loft_parse_list(const char *s, double *v, int max, int *n,
    struct loft_error *err);

/*
 * Parse a whole decimal number from lo to hi (an option's argument).
 * Returns 0 and stores *v, or LOFT_EINPUT with a message in err.
 */
int loft_parse_int(const char *s, long lo, long hi, long *v,
    struct loft_error *err);

/* Parse a number from lo to hi, all of s (an option's argument). */
int loft_parse_real(const char *s, double lo, double hi, double *x,
    struct loft_error *err);

/* Find s in the NULL-terminated list words; store its index in *i. */
int loft_parse_word(const char *s, const char *const *words, int *i,
    struct loft_error *err);

/*
 * Format x into buf (at least LOFT_NUMBUF bytes) and return the length.
 * digits == 0 writes the shortest text that reads back to the same double
 * (lossless); digits 1..17 rounds to that many significant digits,
 * except where that would round past the largest double (then lossless).
 * Minus zero is written as 0.  x must be finite.
 */
#define LOFT_NUMBUF 32
int loft_format_num(char *buf, double x, int digits);

/* ------------------------------------------------------------------ */
/* Stream records (stream.c)                                           */

struct loft_attr {
	char *key;
	char *val;
};

/*
 * One record of a stream, as loft.5 defines it: an optional header (type
 * word and key=value attributes) and rows of numbers, every row with the
 * same count of numbers.  All storage belongs to the record and is reused
 * by the next loft_read into it; loft_record_free releases it.
 */
struct loft_record {
	char *type;             /* header's type word, or NULL: no header */
	struct loft_attr *attr;
	size_t nattr;
	double *num;            /* nrows * ncols numbers, row-major */
	size_t nrows;
	int ncols;
	long line;              /* line where the record starts */
	long *rowline;          /* line of each row */
	const char *file;       /* name of the stream it came from */
	/* storage */
	size_t numcap, rowcap, attrcap;
	char *text;
	size_t textcap;
};

void loft_record_free(struct loft_record *rec);

/* The value of attribute key, or NULL when the header lacks it. */
const char *loft_attr(const struct loft_record *rec, const char *key);

/* The input line of row (for messages); the record's line if row < 0. */
long loft_row_line(const struct loft_record *rec, long row);

struct loft_reader;

/* A reader over fp, whose messages call it name.  NULL: out of memory. */
struct loft_reader *loft_reader_new(FILE *fp, const char *name);
void loft_reader_free(struct loft_reader *rd);

/*
 * Read the next record into rec.  Returns 1 when a record was read, 0 at
 * the end of the stream, LOFT_READ_BAD when a malformed record was read
 * and skipped (err says what and where; the next call goes on after it),
 * LOFT_READ_FAIL on a read error or out of memory (err says which).
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

/* Write "prog: FILE:LINE: msg" for rec and err to run->msg; set status. */
void loft_report(struct loft_run *run, const struct loft_record *rec,
    const struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Cubic segments (cubic.c)                                            */

/*
 * A cubic segment, Manning's eq. 7: rows of a `cubic` record hold
 * P_A, P_B, P'_A, P'_B, dim numbers each, u in [0, 1].
 * Evaluate the point and its first and second u-derivatives at u; any of
 * p, d1, d2 may be NULL.
 */
void loft_cubic_eval(const double *seg, int dim, double u,
    double *p, double *d1, double *d2);

/*
 * The curvature vector d2P/ds2 of a curve from its first and second
 * parameter derivatives (eq. 2).  Returns 0, or LOFT_EGEOM where d1 = 0.
 */
int loft_curvature_vector(const double *d1, const double *d2, int dim,
    double *kn);

/*
 * Normalised tangent magnitudes of a segment from A to B (eq. 9 and 11):
 * chord = P_B - P_A, unit tangents ta at A and tb at B, alpha the weight
 * (2/3 in the paper).  Stores |P'_A| in *ma and |P'_B| in *mb.  Returns 0,
 * or LOFT_EGEOM where a denominator vanishes (both tangents point back
 * along the chord) or the chord is zero.
 */
int loft_normalise(const double *chord, const double *ta, const double *tb,
    int dim, double alpha, double *ma, double *mb);

/* ------------------------------------------------------------------ */
/* Fitting a spline through knots (fit.c, cspline.c)                   */

enum loft_method { LOFT_MANNING, LOFT_FERGUSON, LOFT_CHORD };
enum loft_sign { LOFT_SIGN_POSITIVE, LOFT_SIGN_TURN };

struct loft_fit_opts {
	enum loft_method method;
	enum loft_sign sign;    /* Manning only: the rule for the sign of K_i */
	double alpha;           /* eq. 9 weight, 0.5..1; the paper uses 2/3 */
	double tol;             /* stop when no unit tangent moves more */
	int maxiter;
	int closed;
	int have_start, have_end;       /* open curves: given end tangents */
	double start[LOFT_MAXDIM], end[LOFT_MAXDIM];
};

/* The paper's and the programs' defaults. */
void loft_fit_defaults(struct loft_fit_opts *o);

struct loft_fit_info {
	int iterations;         /* Manning's iteration; 0 for the baselines */
	double change;          /* last largest change of a unit tangent */
	int converged;
};

/*
 * Fit a spline through n knots p (dimension dim, 2 or 3) by o->method and
 * write its segments to seg, 4 * dim numbers per segment in the row
 * layout of loft_cubic_eval: n segments for a closed curve, n - 1 for an
 * open one.  seg must hold 4 * dim * n doubles.  Open curves whose end
 * tangents are not given get loft_end_tangent's estimate.  Returns 0, or
 * LOFT_EGEOM (too few knots, coincident consecutive knots (row: the
 * second), collinear knots on a closed curve, a zero end tangent, a
 * vanishing tangent), LOFT_ENOCONV (info->change says how far it got) or
 * LOFT_ENOMEM.  info may be NULL.
 */
int loft_fit(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    double *seg, struct loft_fit_info *info, struct loft_error *err);

/* Minimum count of knots for a closed and an open curve. */
#define LOFT_MIN_CLOSED 3
#define LOFT_MIN_OPEN   2

/*
 * Estimate the unit tangent at the first of the knots a, b, c (a curve
 * from a through b to c): the tangent at a of the circle through them,
 * or the direction a to b where they are collinear and in order.  With
 * c == NULL, the chord direction a to b.  Returns 0 or LOFT_EGEOM.
 */
int loft_end_tangent(const double *a, const double *b, const double *c, int dim,
    double *t, struct loft_error *err);

/*
 * The largest jump of the curvature vector across the joins of the
 * segments seg[0..nseg) (and across the closing join when closed),
 * divided by the largest curvature at any knot or, if larger, by the
 * curvature of a circle whose radius is the curve's extent: a scale-free
 * measure of curvature continuity, near 0 for a straight line.
 */
double loft_curvature_jump(const double *seg, size_t nseg, int dim, int closed);

/*
 * The largest distance between the unit tangents at the knots of two
 * fits of the same knots (same segment count): 0 when they agree, up to
 * 2 when they point opposite ways.
 */
double loft_tangent_distance(const double *a, const double *b, size_t nseg,
    int dim);

/* ------------------------------------------------------------------ */
/* Curves of any record type, for programs that evaluate them (curve.c) */

/*
 * A curve record as evaluation sees it: pieces over the whole parameter
 * range [0, npieces), piece i over [i, i + 1).
 */
struct loft_curve {
	const char *type;
	const double *coef;     /* the record's rows */
	size_t npieces;
	int dim;
	int closed;
	void (*eval)(const double *piece, int dim, double u,
	    double *p, double *d1, double *d2);
	int rowlen;             /* numbers per piece */
};

/*
 * Recognise rec as a curve record of a known type (`cubic` now) and fill
 * c, which points into rec.  Returns 0, or LOFT_EINPUT when rec is not a
 * curve record or its rows do not fit its type.
 */
int loft_curve_from_record(const struct loft_record *rec, struct loft_curve *c,
    struct loft_error *err);

/*
 * Evaluate piece i at local parameter u in [0, 1]: point, first and
 * second derivatives with respect to u (any may be NULL).
 */
void loft_curve_eval(const struct loft_curve *c, size_t i, double u,
    double *p, double *d1, double *d2);

/*
 * The curvature of a curve with derivatives d1, d2: signed in the plane
 * (positive where the curve turns counter-clockwise), |eq. 2| in space.
 * Returns 0, or LOFT_EGEOM where d1 = 0.
 */
int loft_curvature(const double *d1, const double *d2, int dim, double *k);

#endif
