/*
 * loft.h: the geometry core of libloft, the library behind the loft
 * programs.  loftprog.h, the program layer (streams over stdio, the
 * read-compute-write loop, reporting, options, designs from records,
 * writers), is written on this header alone; loftcad.h, the CAD formats,
 * on that one.  As Lua keeps lua.h apart from lauxlib.h.
 *
 * Conventions, for every function below:
 *  - Arrays are caller-owned.  Points are stored row by row: point i of a
 *    set of dimension dim starts at p[i * dim].
 *  - Functions that can fail return 0 on success and a nonzero LOFT_E*
 *    code on failure, and then fill the caller's struct loft_error with a
 *    message (no trailing newline) and, where the failure belongs to one
 *    row of the input, that row's index.
 *  - The core never prints, never touches a stdio stream and never
 *    exits; it has no run loop.  A record (struct loft_record) is plain data here: the
 *    core reads its type, attributes and rows, never a stream.
 *  - Preconditions are stated in each contract; those that are cheap to
 *    check are checked, and a broken one returns an error code (LOFT_EINPUT
 *    unless the contract says otherwise), never undefined behaviour.
 *    Throughout, dim is 2 or 3 (LOFT_MAXDIM) and pointers are not NULL
 *    unless a contract says a NULL is allowed.
 */
#ifndef LOFT_H
#define LOFT_H

#include <stddef.h>

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

/* Fill err with a printf-style message; row may be -1.  Returns code.
 * err may be NULL (nothing is filled).  (error.c) */
int loft_fail(struct loft_error *err, int code, long row, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 4, 5)))
#endif
	;
#ifdef __clang_analyzer__
/* For clang's static analyser only: it cannot see into error.c, so it
 * would not know that the result is code and would follow paths where a
 * failure returns 0.  code is a constant or a variable at every call. */
#define loft_fail(err, code, ...) \
	(loft_fail((err), (code), __VA_ARGS__), (code))
#endif

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
 * except where that would round past the largest double (then lossless);
 * any other digits is taken as 0.  Minus zero is written as 0.  x must
 * be finite (a NaN or infinity is written as printf's %g writes it).
 */
#define LOFT_NUMBUF 32
int loft_format_num(char *buf, double x, int digits);

/*
 * The one check of a tolerance tol, a distance (every program's -t), for
 * geometry of size size (its box's diagonal, or an arc's radius):
 * meaningful only from rel of size up, and never below LOFT_TOL_ROUNDING
 * of it, where the coordinates' own rounding (1.1e-16 of them, grown by
 * any method's arithmetic) and not tol would decide the result (issue
 * 28: a DXF circle at -t 1e-18 of its radius came out a square).
 * Returns 0, or LOFT_EINPUT with err (may be NULL) saying so; a tol or
 * size not finite, or tol not above 0, fails too.
 */
#define LOFT_TOL_ROUNDING 1e-12
int loft_tol_check(double tol, double size, double rel,
    struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Records (record.c): what a stream holds, as plain data              */

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

/*
 * Copy src into dst, which is zeroed or holds an earlier record (its
 * storage is reused).  Returns 0 or LOFT_ENOMEM.  Free dst with
 * loft_record_free.
 */
int loft_record_copy(struct loft_record *dst, const struct loft_record *src);

/* ------------------------------------------------------------------ */
/* Record types (types.c): what each can be, in one table              */

/*
 * What a record of a type can be, a set of these.  A program asks the
 * table (loft_record_is), never compares type names, so a new type is a
 * row of loft_types and the operations it names.
 */
enum {
	LOFT_KIND_KNOTS = 1,    /* knots a curve is fitted through (points) */
	LOFT_KIND_CURVE = 2,    /* a curve (loft_curve_from_record) */
	LOFT_KIND_SEGMENTS = 4, /* a curve of Hermite segments, one a row,
	                           with end derivatives (loft_curve_segments) */
	LOFT_KIND_CONTROL = 8,  /* its rows are Bezier control points */
	LOFT_KIND_SURFACE = 16, /* a surface (loft_surface_from_record) */
	LOFT_KIND_MEMBER = 32   /* a member of a design (loft_design_add) */
};

struct loft__curve_type;        /* curve.c's evaluation of a curve type */
struct loft__surface_type;      /* surface.c's of a surface type */

struct loft_type {
	const char *name;       /* the header's type word */
	int kinds;              /* LOFT_KIND_* */
	int degree;             /* of a curve's pieces (cubic 3); 0 when the
	                           record says (bezier) or it is no curve */
	const struct loft__curve_type *curve;           /* or NULL */
	const struct loft__surface_type *surface;       /* or NULL */
};

/* Every record type of loft.5, ended by one whose name is NULL. */
extern const struct loft_type loft_types[];

/* The type called name, or NULL when there is none; a NULL name (a
 * record of no header) is `points`. */
const struct loft_type *loft_type_named(const char *name);

/* The type of rec (loft_type_named of its type word), or NULL. */
const struct loft_type *loft_record_type(const struct loft_record *rec);

/* Whether rec's type can be every kind in kinds (LOFT_KIND_* or'd);
 * 0 for a type not in the table. */
int loft_record_is(const struct loft_record *rec, int kinds);


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
/* Fitting a spline through knots (fit.c, cspline.c, fair.c, knots.c)  */

enum loft_method { LOFT_MANNING, LOFT_FERGUSON, LOFT_CHORD, LOFT_FAIR };
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
	const size_t *corner;   /* corner knots (0-based, increasing), or NULL */
	size_t ncorner;
	int quick;              /* LOFT_FAIR: the quick descent alone */
	const size_t *straight; /* straight spans (knot i to i + 1, 0-based,
	                         * increasing), or NULL */
	size_t nstraight;
	int split;              /* LOFT_FAIR: a span may be several segments
	                         * (see loft_fit) */
	int flat_start, flat_end;       /* open curves: the given end tangent
	                         * is a straight run's, which the curve
	                         * meets with curvature 0 where it can */
	int untangle;           /* LOFT_FAIR, open: the centripetal start's
	                         * curve where it passes the checks (loft_fit
	                         * sets it where pieces cross each other) */
};

/* With loft_fit_opts.split, LOFT_FAIR may write a closed plane record
 * of at most LOFT_FIT_SPLIT_KNOTS knots, without corners or straight
 * spans, with a span split into as many as LOFT_FIT_SPLIT segments. */
#define LOFT_FIT_SPLIT 16
#define LOFT_FIT_SPLIT_KNOTS 64

/* The programs' defaults: the method LOFT_FAIR; for LOFT_MANNING the
 * paper's alpha and sign rule. */
void loft_fit_defaults(struct loft_fit_opts *o);

struct loft_fit_info {
	int iterations;         /* Manning's iteration; 0 for the baselines */
	double change;          /* last largest change of a unit tangent */
	int converged;
	size_t nseg;            /* the segments written */
};

/*
 * Fit a spline through n knots p (dimension dim, 2 or 3) by o->method and
 * write its segments to seg, 4 * dim numbers per segment in the row
 * layout of loft_cubic_eval: n segments for a closed curve, n - 1 for an
 * open one.  seg must hold 4 * dim * n doubles.  Open curves whose end
 * tangents are not given get loft_end_tangent's estimate.  With
 * o->split, a closed plane record of at most LOFT_FIT_SPLIT_KNOTS
 * knots and no corners or straight spans may have its spans split
 * (LOFT_FAIR, where one cubic cannot follow the fairest curve round a
 * span), and seg must then hold LOFT_FIT_SPLIT times as many; every
 * knot begins a segment, in order, and info->nseg (info not NULL)
 * says how many were written.  Returns 0, or
 * LOFT_EGEOM (too few knots, coincident consecutive knots (row: the
 * second), collinear knots on a closed curve, a zero end tangent, a
 * vanishing tangent), LOFT_ENOCONV (info->change says how far it got) or
 * LOFT_ENOMEM.  info may be NULL.
 */
int loft_fit(const struct loft_fit_opts *o, const double *p, size_t n, int dim,
    double *seg, struct loft_fit_info *info, struct loft_error *err);

/*
 * With o->ncorner > 0, loft_fit breaks the curve at the knots corner[0..
 * ncorner), each < n and each greater than the one before: the curve
 * between two corners (and, on an open curve, from an end to its nearest
 * corner) is fitted by o->method as an open curve whose end tangents at
 * the corners are estimated as loft_end_tangent does (the given ones at
 * the ends of an open curve), so the tangent direction breaks at a
 * corner, and a segment between corners at neighbouring knots is the
 * straight line between them.  A corner at an end of an open curve
 * changes nothing.  Errors name rows of p as without corners.
 *
 * With o->nstraight > 0, the spans straight[0.. nstraight) (span i from
 * knot i to knot i + 1, the last of a closed curve back to knot 0) are
 * straight lines, and the curve on either side of one is fitted as an
 * open curve whose end tangent there is the line's direction: the
 * tangent is continuous where a straight run meets a curve (G1).  A
 * span alone between a straight run and a corner (a stem's bracket into
 * a serif) meets the run with curvature 0 too (G2, as Spiro's `[' `]'
 * points) where the run's direction is within 60 degrees of the span's
 * chord, except under LOFT_MANNING; under LOFT_FAIR, in the plane, a
 * longer piece meets its runs so too where the cubics beside them can
 * without losing LOFT_FAIR's guarantees (see splinefit(1)); elsewhere
 * the curvature jumps from 0 to the curve's.  Corners go with them.
 * Under LOFT_FAIR (not o->quick) in the plane, where the pieces cross
 * one another, each is fitted again with o->untangle, and that curve is
 * written where it does not cross itself.
 */

/*
 * Merging knots that are one knot (merge.c).  loft_merge_distance: the
 * default merge distance of the n knots p, a fixed fraction of their
 * size.  loft_merge_knots: the knots to keep, their indices written in
 * increasing order to keep (n entries), their count returned: a knot
 * nearer than dist to the last kept one is dropped, and on a closed
 * curve (closed nonzero) so is a last kept knot nearer than dist to the
 * first.  With local nonzero (the default distance), two knots are one
 * only where they are also nearer than a tenth of the longer of the
 * chords on either side of them, so an even dense spacing is kept.  into, unless NULL, gets for each of the n knots the index (in
 * keep) of the kept knot it is, or merged into: the one kept before it,
 * or the first for the knots that close the curve.  dist 0 keeps every
 * knot.  n may be 0.
 */
double loft_merge_distance(const double *p, size_t n, int dim);
size_t loft_merge_knots(const double *p, size_t n, int dim, int closed,
    double dist, int local, size_t *keep, size_t *into);

/* Minimum count of knots for a closed and an open curve. */
#define LOFT_MIN_CLOSED 3
#define LOFT_MIN_OPEN   2

/*
 * Estimate the unit tangent at the first of the knots a, b, c (a curve
 * from a through b to c): the tangent at a of the circle through them,
 * or the direction a to b where they are collinear and in order.  With
 * c == NULL, the chord direction a to b.  Precondition, checked: dim 2
 * or 3.  Returns 0, LOFT_EINPUT (dim) or LOFT_EGEOM.
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

/*
 * Whether the plane curve of the nseg segments seg (rows of 8 numbers,
 * as loft_fit writes them; nseg > 0) crosses itself, closed or not: 1
 * where the polyline of 6 points a segment has two edges, not
 * neighbours, that cross, or where, at a joint the curve turns back
 * at, its two sides sampled finer (loft_fold_u) do; 0 where none do;
 * -1 when out of memory.
 */
int loft_fit_crosses(const double *seg, size_t nseg, int closed);

/*
 * The straight runs of a drawn outline (straight.c): of the nseg
 * segments seg (rows P_A P_B P'_A P'_B of dim 2 or 3 numbers, as
 * loft_fit writes them; closed: the last meets the first), the indices
 * of those that are straight lines (each tangent vector along the chord,
 * or zero) and meet a curved neighbour with its tangent (to 1e-5
 * radians), increasing, into out (room for nseg); returns their count.
 * Those are the spans splinefit's straight= keeps straight (loft.5).
 */
size_t loft_straight_spans(const double *seg, size_t nseg, int dim, int closed,
    size_t *out);

/* ------------------------------------------------------------------ */
/* Approximating noisy points by a fair curve (approx.c)               */

/*
 * The corners of an outline given by n dense points p (dimension dim,
 * in order along it; closed: the last joins the first), found at a
 * scale of a few tol (corners.c): where the least-squares lines
 * through the points either side, over that length, turn by 30 degrees
 * or more, the sharpest within it; each such turn is then placed at the
 * split of the points near it into two lines (or three: two corners,
 * the end of a serif) that fits them best.  Their indices, increasing,
 * into corner (room for n), and where at is not NULL (room for n * dim)
 * the places for their knots: for a single corner where the lines
 * either side meet, if the path from its point through there to a
 * neighbour is not much longer than the points' spacing, else the
 * point, or a neighbour where a corner pinned there fits the points
 * better.  A turn is kept only where the lines fit the points near it
 * better than a cubic curve does, and by more than an arc tangent to
 * the two lines gains on the corner (else it is a smooth bend).  Once
 * all are placed, the turns are measured again with no line reaching
 * past a corner found, and those the sharper turns beside it hid are
 * placed in the same way, kept only where they gain much more on the
 * cubic.  Returns their count, or (size_t)-1 out of memory.  A circle or a
 * gentle bend seldom gives one.  Points denser than the scale needs
 * are first averaged in runs, so the time grows with n, not with the
 * points' density.
 */
size_t loft_find_corners(const double *p, size_t n, int dim, int closed,
    double tol, size_t *corner, double *at);

/*
 * The points of n plane points p (2 numbers each, in order along an
 * outline; closed: the last joins the first) where the polyline through
 * them turns by turn radians or more, their indices increasing into
 * corner (room for n): the corners of points too sparse for
 * loft_find_corners, which needs several points either side of a
 * corner.  The number of times the polyline's turns change sign (round
 * the end where closed) into *flex: an outline's points turn one way
 * between its inflexions and reflex corners, noisy ones the other way
 * at about 2 points in 3.  Returns the count, or (size_t)-1 out of
 * memory.
 */
size_t loft_sharp_points(const double *p, size_t n, int closed, double turn,
    size_t *corner, size_t *flex);

/*
 * The noise of n points p (dimension dim, in order along an outline;
 * closed: the last joins the first): the standard deviation of their
 * scatter across it (in each direction across, in space), estimated
 * from the median distance of each point from the chord of its two
 * neighbours (corners.c).  A bend between
 * points farther apart than its radius reads as noise too.  0 where
 * there are fewer than 3 points, none off those chords, or no memory.
 */
double loft_points_noise(const double *p, size_t n, int dim, int closed);

/* Fewest points a closed and an open approximation take. */
#define LOFT_APPROX_MIN_CLOSED 4
#define LOFT_APPROX_MIN_OPEN   3

/* Rounds of splitting spans at most, by default: each round at most
 * doubles the knots, so 2^40 more than the first: the limit is reached
 * only by a tolerance below the points' noise, where the spans are
 * split down to single points. */
#define LOFT_APPROX_ROUNDS 40

struct loft_approx_opts {
	double tol;             /* every point within this of the curve, > 0 */
	int closed;
	int have_start, have_end;       /* open curves: given end tangents */
	double start[LOFT_MAXDIM], end[LOFT_MAXDIM];
	const size_t *corner;   /* corner points (0-based, increasing), or NULL */
	const double *corner_at;        /* their knots (ncorner rows), or
	                                 * NULL: the points themselves */
	size_t ncorner;
	int maxround;           /* rounds of splitting at most, >= 1 */
	unsigned char *astray;  /* NULL, or room for n flags (n points):
	                         * astray[j] set where segment j of the
	                         * curve fails the check both ways (see
	                         * loft_approx_info's astray) */
};

/* Closed, no corners, no end tangents, LOFT_APPROX_ROUNDS; tol is the
 * caller's to set. */
void loft_approx_defaults(struct loft_approx_opts *o);

struct loft_approx_info {
	size_t nknots, nseg;    /* the curve's knots and segments */
	double dist;            /* the largest distance of a point from it */
	size_t where;           /* that point (0-based) */
	int rounds;             /* rounds of splitting taken */
	size_t astray;          /* spans that stray from the points'
	                         * polyline or cross the curve: 0 where
	                         * the check both ways passes */
};

/*
 * Approximate the n points p (dimension dim, 2 or 3), samples in order
 * along an outline (closed when o->closed), by the fair spline of
 * loft_fit's LOFT_FAIR through knots of its own choosing, as few as
 * halving spans finds, placed so that every point is within o->tol of
 * the curve (the distance from the point to its nearest point on the
 * curve, in the points' units).  The knots are not the points: each is
 * where the residuals of the points on its two spans balance, so the
 * curve passes through the middle of the noise.  Corners
 * o->corner[0..ncorner), indices of points, each greater than the one
 * before, are knots at those very points where the tangent breaks (as
 * loft_fit's corners), or, where o->corner_at is not NULL, at its rows
 * (each no farther from its point than the diagonal of the points'
 * box, else LOFT_EINPUT); o->start, o->end (when have_start, have_end)
 * the end tangents of an open curve.  The result does not depend on the
 * points' units, nor on which point a closed outline starts at (the
 * knots are the same; the segments are rotated to start near p[0]).
 * Writes the segments to seg, 4 * dim numbers each in the row layout of
 * loft_cubic_eval, at most n of them: seg must hold 4 * dim * n
 * doubles.  info (may be NULL) gets the knots, segments, the largest
 * distance and its point, and how many spans fail the check both ways
 * (the fit that fails on fewest is written where none passes), and,
 * where o->astray is not NULL, which of its segments do.  Open
 * points all on a line, running one way along it, are the straight
 * segments between the first, the corners, and the last.
 * Returns 0, or LOFT_EINPUT (dim, tol not positive and finite, tol at
 * least half the diagonal of the points' box), LOFT_EGEOM (fewer than
 * LOFT_APPROX_MIN_CLOSED or LOFT_APPROX_MIN_OPEN points, points all on
 * a line where they are closed, have end tangents given, or turn back
 * along it, a fit that fails),
 * LOFT_ENOCONV (the tolerance not met in o->maxround rounds or with
 * every span too short to split: info->dist and info->where say what
 * was reached, err->row is that point; nothing in seg), LOFT_ENOMEM.
 */
int loft_approx(const struct loft_approx_opts *o, const double *p, size_t n,
    int dim, double *seg, struct loft_approx_info *info,
    struct loft_error *err);

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
	size_t npts;            /* control-point types: the record's rows */
	void (*eval_ctl)(const double *ctl, size_t npts, int dim, double u,
	    double *p, double *d1, double *d2);
	int (*bezier)(const double *piece, int dim, double *ctl);
	/* its type's quartic form of a piece, or NULL: it has none */
	void (*quartic)(const double *piece, int dim, double *q);
	int degree;             /* of its Bezier pieces (loft_curve_bezier) */
};

/*
 * Recognise rec as a curve record of a known type (`cubic`, `bezier`: a
 * bezier record is one piece) and fill
 * c, which points into rec.  Returns 0, or LOFT_EINPUT when rec is not a
 * curve record or its rows do not fit its type.
 */
int loft_curve_from_record(const struct loft_record *rec, struct loft_curve *c,
    struct loft_error *err);

/*
 * Fill c for the nseg > 0 cubic segments seg (the row layout of
 * loft_cubic_eval, 4 * dim numbers a segment, as loft_fit writes them),
 * closed or not, so that the curve functions take a fit without a
 * record.  c points into seg.
 */
void loft_curve_cubic(struct loft_curve *c, const double *seg, size_t nseg,
    int dim, int closed);

/*
 * Evaluate piece i at local parameter u in [0, 1]: point, first and
 * second derivatives with respect to u (any may be NULL).
 */
void loft_curve_eval(const struct loft_curve *c, size_t i, double u,
    double *p, double *d1, double *d2);

/*
 * The control points of piece i in the Bernstein basis (the piece as a
 * Bezier curve over its own [0, 1]), written to ctl, dim numbers a
 * point: exact conversions of the record's rows (a cubic's inner points
 * a third of its end tangents in, a quartic's from its ends, end
 * derivatives and (h)).  ctl must hold (c->degree + 1) * dim numbers.
 * Returns the degree, c->degree, 1 to LOFT_BEZIER_MAXPTS - 1.
 */
int loft_curve_bezier(const struct loft_curve *c, size_t i, double *ctl);

/*
 * The curvature of a curve with derivatives d1, d2: signed in the plane
 * (positive where the curve turns counter-clockwise), |eq. 2| in space.
 * Returns 0, or LOFT_EGEOM where d1 = 0.
 */
int loft_curvature(const double *d1, const double *d2, int dim, double *k);

/*
 * The unit tangent t (dim numbers) of a curve with first derivative d1,
 * by the library's scaled norm, so a curve of any size has one (a plain
 * sum of squares overflows above about 1e154 and underflows below
 * 1e-154).  Returns 0, or LOFT_EGEOM where d1 = 0 (t left alone).
 */
int loft_unit_tangent(const double *d1, int dim, double *t);

/*
 * The angle (radians, 0 to pi) by which a cubic record's tangent turns
 * at the joint where segment j of its nseg starts (rows P_A P_B P'_A
 * P'_B of dim numbers, as loft_fit writes them): between P'_B of the
 * segment before (the last, where closed and j is 0) and P'_A of j.
 * 0 at the start of an open curve and where either tangent is zero.
 */
double loft_joint_turn(const double *seg, size_t nseg, int dim, int closed,
    size_t j);

/* ------------------------------------------------------------------ */
/* Offsets of plane curves (offset.c)                                  */

/* How the outer side of a corner is joined (offset(1) -j). */
enum loft_join { LOFT_JOIN_ROUND, LOFT_JOIN_MITER, LOFT_JOIN_BEVEL };

/* A knot is a corner where the tangent direction turns by more than
 * this (radians), or by enough that the two offsets there are farther
 * apart than the tolerance: splinefit's curves turn by rounding only. */
#define LOFT_OFFSET_CORNER 1e-6
/* A miter join is used while the miter's tip is at most this many
 * times the distance from the corner (1 / cos(turn / 2), so up to a
 * turn of 151 degrees), else a bevel: SVG's default miter limit. */
#define LOFT_OFFSET_MITER_LIMIT 4.0
/* The default tolerance, relative to the distance. */
#define LOFT_OFFSET_TOL 1e-3

/* One curve of an offset: segments seg[first .. first + n) of it. */
struct loft_offset_part {
	size_t first, n;
	int closed;
};

/*
 * An offset: nseg cubic segments, 8 numbers each in the row layout of
 * loft_cubic_eval (P_A P_B P'_A P'_B), in npart curves.  Start it
 * zeroed; loft_offset_curve reuses its storage from record to record;
 * loft_offset_free releases it.
 */
struct loft_offset {
	double *seg;
	size_t nseg, segcap;
	struct loft_offset_part *part;
	size_t npart, partcap;
	struct loft_offset_work *work;  /* offset.c's scratch */
};

/*
 * The offset of the plane curve c at distance dist: outward for a
 * closed curve whichever way it runs (by the sign of its area), to the
 * left of travel for an open one; negative dist the other way.  The
 * segments written to out are within tol (in the curve's units; 0:
 * LOFT_OFFSET_TOL of |dist|) of the exact offset everywhere.  Where the curve bends more sharply than
 * |dist| on the offset's side, and where far parts of it come nearer
 * than 2 |dist|, the offset's loops are cut away: what is kept is
 * farther than |dist| - tol / 2 from the whole curve, except the joins.
 * A corner (LOFT_OFFSET_CORNER) gets a join of kind join on its outer
 * side: a circular arc of radius |dist| about it, a miter within
 * LOFT_OFFSET_MITER_LIMIT, or a bevel; on its inner side the two
 * offsets are cut where they cross.  The pieces of c must meet end to
 * end.  The result may be several curves (an inward offset across a
 * narrow waist), each closed when c is.  Returns 0, or LOFT_EINPUT (a
 * space curve, dist 0 or not finite, tol negative), LOFT_EGEOM (c
 * is a point, is broken, encloses no area, overflows; the offset
 * vanishes or cannot be made, with err saying where) or LOFT_ENOMEM.
 */
int loft_offset_curve(const struct loft_curve *c, double dist, double tol,
    enum loft_join join, struct loft_offset *out, struct loft_error *err);

void loft_offset_free(struct loft_offset *o);

/* ------------------------------------------------------------------ */
/* Measuring curves of any record type (arclen.c, measure.c, flatten.c) */

/*
 * Every function here takes a curve from loft_curve_from_record, of any
 * type, and works on its pieces in the Bernstein basis
 * (loft_curve_bezier); u is the curve's parameter over [0, npieces].
 * Results scale with the curve: lengths and coordinates as it does,
 * curvatures inversely, counts not at all.
 */

/*
 * Relative accuracy of arc lengths: the adaptive quadrature halves an
 * interval until Kronrod's and Gauss's rules agree to this fraction of
 * the integral of |P'|; doubles give about 1e-15, so this leaves room
 * for the sum over many pieces.
 */
#define LOFT_ARC_REL 1e-12

/*
 * The length of c over parameters u0 to u1 (either order; a negative
 * result when u1 < u0), clamped to [0, npieces]: adaptive Gauss-Kronrod
 * (7, 15) quadrature of |P'(u)| to LOFT_ARC_REL, piece by piece.
 * loft_curve_length is the whole curve's.  The result is not finite
 * only when the coefficients are near overflow.
 */
double loft_curve_arc(const struct loft_curve *c, double u0, double u1);
double loft_curve_length(const struct loft_curve *c);

/*
 * The parameter u where the length of c from u = 0 is s: 0 for s <= 0,
 * npieces for s at least the length.  Newton's method on the length
 * (its derivative is the speed), bisection where a step would leave the
 * bracket or the speed vanishes; accurate to 1e-13 of the length of
 * the piece it falls in.
 */
double loft_curve_at_length(const struct loft_curve *c, double s);

/*
 * Equal spacing: points at lengths 0, step, 2 step, ... along a curve of
 * length len, and its end (the last interval the short one); an
 * interior point within LOFT_SPACING_TIE of len of the end is dropped,
 * so a length that is a multiple of step ends exactly once.
 * loft_spaced_count is how many points that is (2 at least; (size_t)-1
 * when more than 1e15), and loft_curve_spaced writes their n parameters
 * to u, u[0] = 0 and u[n - 1] = npieces, in one sweep along the curve.
 * len must be loft_curve_length(c) and step > 0.
 */
#define LOFT_SPACING_TIE 1e-9
size_t loft_spaced_count(double len, double step);
void loft_curve_spaced(const struct loft_curve *c, double step, double *u,
    size_t n);

/*
 * Flattening: the parameters of as few points as this simple rule finds
 * whose polyline is within tol of c: each piece is halved in its
 * parameter until the chord of every part is within tol of the part,
 * proved by the part's Bezier control points (the part lies in their
 * convex hull; the bound uses the control points of its two halves,
 * which hug the curve closer), so the distance both ways, curve to
 * polyline and polyline to curve, is at most tol.  The knots are kept.
 * Writes at most max parameters to u, increasing from 0 to npieces, and
 * returns how many there are (more than max: call again with room for
 * them).  tol > 0, in the curve's units.  Parts are never halved below
 * 2^-30 of a piece.
 */
size_t loft_curve_flatten(const struct loft_curve *c, double tol, double *u,
    size_t max);

/*
 * The box [lo, hi] (dim numbers each) around c, exact: each piece's
 * coordinate extremes are at its ends or at the roots of that
 * coordinate's derivative, found by subdivision in the Bernstein basis.
 */
void loft_curve_bbox(const struct loft_curve *c, double *lo, double *hi);

/*
 * The area a plane curve bounds, by Green's theorem, exact per piece:
 * positive when it runs counter-clockwise.  An open curve is closed by
 * the chord from its end back to its start.  Returns 0, or LOFT_EINPUT
 * for a space curve.
 */
int loft_curve_area(const struct loft_curve *c, double *area,
    struct loft_error *err);

/*
 * The centroid (dim numbers): of the region a closed plane curve bounds
 * (Green's theorem); of the curve's length (the mean of its points by
 * arc length) for an open or a space curve.  Returns 0, LOFT_EINPUT for
 * a curve of no pieces, or LOFT_EGEOM when a closed plane curve bounds
 * no area (less than 1e-12 of the square of its size: a figure of eight
 * with equal lobes, a curve that runs back along itself).
 */
int loft_curve_centroid(const struct loft_curve *c, double *cen,
    struct loft_error *err);

/*
 * The smallest radius of curvature of c, 1 / max |k|, and the parameter
 * u where it is (the first such); the candidates are the pieces' ends
 * and the roots of dk/du.  A curve that does not bend (max |k| times its
 * size below 1e-10, a straight line) has *radius = 0 and *u = 0: no
 * finite radius.  Returns 0, or LOFT_EGEOM where the tangent vanishes
 * at a candidate (a cusp, row: the piece).
 */
int loft_curve_min_radius(const struct loft_curve *c, double *radius,
    double *u, struct loft_error *err);

/*
 * The number of inflexions of a plane curve: the sign changes of its
 * curvature along it, cyclically on a closed curve (so an even number
 * there), a straight stretch between curvatures of opposite sign
 * counting as one.  Curvature within 1e-10 of zero (relative to a
 * piece's length) has no sign.  Returns 0, or LOFT_EINPUT for a
 * space curve.
 */
int loft_curve_inflexions(const struct loft_curve *c, long *count,
    struct loft_error *err);

/*
 * The number of curvature extrema of c: the sign changes of dk/ds (of
 * the signed curvature in the plane, of |k| in space) along it,
 * cyclically on a closed curve, at knots too; the ends of an open curve
 * do not count, and a curvature whose rate of change times the
 * square of a piece's length is below 1e-10 (a line's) has none there.
 * A jump of the curvature at a knot is no extremum by itself.  Returns
 * 0 (err is not used).
 */
int loft_curve_extrema(const struct loft_curve *c, long *count,
    struct loft_error *err);

/*
 * The bending energy of c, the integral of k^2 ds, by adaptive
 * quadrature to 1e-10 relative.  Returns 0, or LOFT_EGEOM where it is
 * not finite (a vanishing tangent; row: the piece).
 */
int loft_curve_energy(const struct loft_curve *c, double *energy,
    struct loft_error *err);

/*
 * The largest jump |k_after - k_before| of the curvature vector across
 * a knot of c, interior knots of an open curve and every knot of a
 * closed one (the closing knot is u = 0), in 1 / the curve's units;
 * *u the knot, 0 when there is none.  Knots where a tangent vanishes are
 * skipped.  loft_curvature_jump is the scale-free form for fits.
 */
void loft_curve_jump(const struct loft_curve *c, double *jump, double *u);

/* ------------------------------------------------------------------ */
/* Expressions with exact derivatives (expr.c)                         */

/*
 * A value with its partial derivatives in up to two variables x0, x1:
 * d[k] = d/dx_k, h = { d2/dx0dx0, d2/dx0dx1, d2/dx1dx1 }.
 */
struct loft_jet {
	double v;
	double d[2];
	double h[3];
};

struct loft_expr;

/*
 * Compile the expression src (grammar in expr.c and bezapprox(1)) whose
 * variables are the letters of vars, one or two ("t", or "uv"; checked:
 * any other count is LOFT_EINPUT, *col 0).  Returns the expression, to
 * be freed with loft_expr_free; or NULL with err filled and *col set to
 * the 1-based column where the text went wrong.
 */
struct loft_expr *loft_expr_parse(const char *src, const char *vars, int *col,
    struct loft_error *err);

/*
 * Evaluate e where the variables take the values x[0], x[1], with exact
 * first and second derivatives.  Results may be NaN or infinite (log 0,
 * say): the caller checks what it uses.  Not reentrant: e holds its
 * evaluation stack.
 */
void loft_expr_eval(struct loft_expr *e, const double *x, struct loft_jet *out);
void loft_expr_free(struct loft_expr *e);

/* ------------------------------------------------------------------ */
/* Bezier curves and surfaces (bezier.c)                               */

#define LOFT_BEZIER_MAXPTS 64   /* control points along one direction */

/*
 * The Bezier curve of the npts <= LOFT_BEZIER_MAXPTS control points ctl
 * (dim numbers each) at t in [0, 1], by de Casteljau's algorithm: point,
 * first and second derivatives (any may be NULL).
 */
void loft_bezier_eval(const double *ctl, size_t npts, int dim, double t,
    double *p, double *d1, double *d2);

/*
 * Split the Bezier curve ctl of degree deg at t (de Casteljau): the
 * control points of the parts over [0, t] and [t, 1] into left and right
 * (deg + 1 points each; either may be NULL).  deg < LOFT_BEZIER_MAXPTS.
 */
void loft_bezier_split(const double *ctl, int deg, int dim, double t,
    double *left, double *right);

/*
 * The Bezier surface of degrees m in u and n in v (m, n < LOFT_BEZIER_MAXPTS)
 * with control points ctl, 3 numbers each, u-major (P_ij at
 * ctl[3 * (i * (n + 1) + j)]), at (u, v): point and the partial
 * derivatives in u and v (any may be NULL).
 */
void loft_bezier_surface_eval(const double *ctl, int m, int n, double u,
    double v, double *p, double *pu, double *pv);

/*
 * The Bernstein polynomials of degree n at t: b[i] = C(n, i) t^i
 * (1 - t)^(n - i), i = 0..n, by the stable triangular recurrence.
 */
void loft_bernstein(int n, double t, double *b);

/*
 * The integral over [0, 1] of B_i^n B_j^n: C(n, i) C(n, j) / ((2n + 1)
 * C(2n, i + j)).
 */
double loft_bernstein_gram(int n, int i, int j);

/* ------------------------------------------------------------------ */
/* Normal approximation by Bezier curves and surfaces (normal.c)       */

/*
 * A parametric curve over [0, 1] given by a function: eval fills the
 * point and its first and second derivatives at t (d1, d2 may be NULL).
 * The interval is made of npieces equal pieces (1 for a smooth curve; N
 * for N spline segments), and quadrature panels never straddle two.
 */
struct loft_pcurve {
	int dim;
	size_t npieces;
	void (*eval)(void *ctx, double t, double *p, double *d1, double *d2);
	void *ctx;
};

/*
 * A parametric surface in space over [0, 1]^2, made of npu by npv
 * pieces: eval fills the point, x_u, x_v, x_uu and x_vv (any of the
 * derivatives may be NULL).
 */
struct loft_psurface {
	size_t npu, npv;
	void (*eval)(void *ctx, double u, double v, double *p, double *pu,
	    double *pv, double *puu, double *pvv);
	void *ctx;
};

#define LOFT_NORMAL_MAXDEG 24   /* the Bernstein Gram matrix's condition
				   number passes 1e12 not far above this;
				   a surface's is about the product of its
				   two degrees': m + n up to about 30 */

/*
 * Carriazo, Marquez and Ugail's normal approximation (section 3): the
 * Bezier curve of degree n (1 <= n <= LOFT_NORMAL_MAXDEG) whose end points
 * are the curve's and whose control point i lies on the normal line at
 * t_i = i / n, chosen to minimise eq. 3.  With clamp (n >= 3) lambda_1
 * and lambda_n-1 come from eq. 4 instead.  Writes the n + 1 control
 * points to ctl, the lambdas to lambda[0..n] (lambda[0] = lambda[n] = 0;
 * lambda may be NULL), a flag per control point to nonormal (1 where a
 * space curve has no principal normal, zero curvature, so the point
 * stays on the curve; may be NULL) and F at the minimum to *error.
 * Returns 0, or LOFT_EINPUT / LOFT_EGEOM with err saying why (a value
 * not finite, a vanishing derivative, a singular system; a->npieces 0
 * or a->dim not 2 or 3, which break the preconditions), or LOFT_ENOMEM.
 * A curve whose size is outside [1e-50, 1e50] is solved scaled by a
 * power of two, so that the results scale with it; LOFT_EGEOM when F, in
 * its units squared, overflows even so.
 */
int loft_normal_curve(const struct loft_pcurve *a, int n, int clamp,
    double *ctl, double *lambda, int *nonormal, double *error,
    struct loft_error *err);

/*
 * The surface method of section 4: boundary curves by loft_normal_curve
 * (x(t, 0) and x(t, 1) of degree m, x(0, t) and x(1, t) of degree n, all
 * clamped when clamp), interior control points on the surface normals at
 * (i / m, j / n), least squares over the square.  Writes (m + 1)(n + 1)
 * control points, u-major, to ctl, and the double integral of
 * |x - B|^2 to *error.  Returns 0 or LOFT_E* with err filled (LOFT_EINPUT
 * for x->npu or x->npv 0: the precondition is at least one piece each).
 */
int loft_normal_surface(const struct loft_psurface *x, int m, int n, int clamp,
    double *ctl, double *error, struct loft_error *err);

/* ------------------------------------------------------------------ */
/* MacCallum's quartic curves (quartic.c)                              */

/*
 * A quartic segment (MacCallum 1970, section 4) is five vectors of dim
 * numbers: (0), (1), (0)_u, (1)_u, (h): its end points, its derivatives
 * there, and its point at u = 1/2.  A `quartic` record has one segment
 * a row.
 */

/* The paper's 5 x 5 matrix M over the basis [u^4 u^3 u^2 u 1]. */
extern const double loft_quartic_m[5][5];

/*
 * The blending functions H1..H5 at u (h[0..4]) and their first and
 * second derivatives; any of h, dh, d2h may be NULL.
 */
void loft_quartic_h(double u, double *h, double *dh, double *d2h);

/*
 * Evaluate a quartic segment q at u: point, first and second derivative
 * (any may be NULL).  Same signature as loft_cubic_eval.  At u = 0, 1/2
 * and 1 the point is exactly (0), (h) and (1).
 */
void loft_quartic_eval(const double *q, int dim, double u,
    double *p, double *d1, double *d2);

/*
 * The quartic form of the cubic segment P_A P_B P'_A P'_B: the same four
 * vectors, then (h) = the cubic's point at u = 1/2.  q (5 * dim numbers)
 * may be the cubic's own array if it has room.
 */
void loft_cubic_to_quartic(const double *cubic, int dim, double *q);

/* How a drag was done (section 4). */
enum {
	LOFT_DRAG_CENTRAL,      /* only (h), or (hh), changed */
	LOFT_DRAG_EDGE,         /* near an edge: this piece and its neighbour */
	LOFT_DRAG_FALLBACK      /* near an edge with no neighbour usable:
	                           the central rule, and why in why */
};

struct loft_drag_info {
	int rule;
	long piece;             /* the segment or patch index dragged */
	long other;             /* the neighbour that changed too, or -1 */
	int edge;               /* patches: the nearer edge (enum loft_edge) */
	double hd, hp;          /* H_d at the dragged point, H_p at the join */
	char why[160];          /* LOFT_DRAG_FALLBACK: the reason, or "" */
};

/*
 * Drag the point at parameter U of a curve of nseg quartic segments q
 * (segment i over [i, i + 1]) by delta (dim numbers).  A point whose
 * distance to the nearer end of its segment is at least edge (in the
 * segment's parameter) moves by the central rule, delta(h) = delta /
 * H5(u); nearer an end, that segment and the one across the end (the
 * first and last are neighbours on a closed curve) change together by
 * the two-segment rule, or, where there is none, the central rule
 * applies.  Preconditions, checked: nseg > 0, dim 2 or 3, U from 0 to
 * nseg.  Returns 0 and fills info, or LOFT_EINPUT (a precondition
 * broken) or LOFT_EGEOM (the point is an end of an open curve, which
 * cannot move).
 */
int loft_quartic_drag(double *q, size_t nseg, int dim, int closed, double U,
    const double *delta, double edge, struct loft_drag_info *info,
    struct loft_error *err);

/*
 * Section 4's first constraint: remove from delta its component along
 * the viewing direction view, so depth does not change.  Returns 0, or
 * LOFT_EGEOM when view is zero or nothing of delta is left (less than
 * LOFT_DRAG_ZERO of its length, or delta is zero to begin with).
 */
#define LOFT_DRAG_ZERO 1e-12
int loft_drag_project(double *delta, const double *view, int dim,
    struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Exact Bezier forms of the record types (bezform.c)                  */

/*
 * The quartic in MacCallum's form (0) (1) (0)_u (1)_u (h), its five
 * vectors of dim numbers in_step numbers apart in k, as its Bernstein
 * control points b0..b4, out_step apart in b: b0 = (0), b4 = (1), the
 * end derivatives 4 (b1 - b0) and 4 (b4 - b3), and the point at u = 1/2
 * (b0 + 4 b1 + 6 b2 + 4 b3 + b4) / 16 = (h), so
 * b2 = (16 (h) - 5 (0) - 5 (1) - (0)_u + (1)_u) / 6.  The one conversion
 * of a quartic to the Bernstein basis: curves, patches and their boxes
 * use it.  k and b do not overlap.
 */
void loft_quartic_bezier(const double *k, size_t in_step, double *b,
    size_t out_step, int dim);

/*
 * The bi-quartic patch b (loft_patch_eval's layout) as the 5 x 5 control
 * net of the same polynomial surface, u-major: P_ij, i the u index, at
 * ctl[(5 * i + j) * dim] (25 * dim numbers).
 */
void loft_patch_bezier(const double *b, int dim, double *ctl);

/*
 * The fewest equal parameter steps n that put the polyline through the
 * Bezier curve ctl of degree deg at t = j/n within tol of the curve (at
 * the same parameter, so every point of the curve is within tol of the
 * polyline): linear interpolation over steps h errs by at most
 * h^2/8 max |C''|, and |C''| <= deg (deg - 1) times the largest second
 * difference of the control points.  tol > 0.  Returns 1 to max, or 0
 * when more than max steps would be needed.
 */
long loft_bezier_steps(const double *ctl, int deg, int dim, double tol,
    long max);

/* ------------------------------------------------------------------ */
/* MacCallum's bi-quartic patches (patch.c)                            */

/*
 * A patch f(u, v) = u M B M^t v^t over [0,1] x [0,1] (section 4): B is
 * 5 x 5 vectors of dim numbers, b[(5 * i + j) * dim + k], row i for the
 * u-coefficient (0), (1), (0)_u, (1)_u, (h) and column j for the same in
 * v; a `patch` record's row i holds B[i][0..4].
 */
#define LOFT_PATCH_NUMS (25 * LOFT_MAXDIM)

/*
 * Evaluate the patch b at (u, v): the point and its u- and
 * v-derivatives (any of p, du, dv may be NULL).  At u, v in {0, 1/2, 1}
 * the point is exactly the corresponding coefficient.
 */
void loft_patch_eval(const double *b, int dim, double u, double v,
    double *p, double *du, double *dv);

/*
 * Section 5: the two patches b1 (parameter 0 to t) and b2 (t to 1) that
 * are b cut along u = t (dir 0) or v = t (dir 1), 0 < t < 1, each over
 * its own [0,1] x [0,1].  Every entry is recomputed from b, twists and
 * (h) entries included; the entries of the common edge are the same
 * numbers in both.
 */
void loft_patch_split_coef(const double *b, int dim, int dir, double t,
    double *b1, double *b2);

/* The edges of a patch: u = 0, u = 1, v = 0, v = 1. */
enum loft_edge { LOFT_U0, LOFT_U1, LOFT_V0, LOFT_V1 };

/*
 * A neighbour across an edge (loft.5): patch id shares the part of this
 * edge between edge parameters a and b (v on the u edges, u on the v
 * edges), which runs from a to b as the neighbour's own edge parameter
 * increases.
 */
struct loft_link {
	long id;
	double a, b;
};

/* One patch of a design, as patch.c reads and writes it. */
struct loft_patch {
	long id;
	int dim;
	double scale[2];        /* su, sv: scale factors (section 5) */
	double b[LOFT_PATCH_NUMS];
	struct loft_link *link[4];      /* by enum loft_edge, sorted */
	size_t nlink[4], linkcap[4];
	const struct loft_record *rec;  /* where it was read, or NULL */
};

/* A design: patches that name each other as neighbours. */
struct loft_design {
	struct loft_patch *p;
	size_t n, cap;
	long maxid;             /* the largest id in use */
	struct loft_design_index *index;        /* ids to patches, patch.c's */
};

/* The edge names of loft.5, "u0" "u1" "v0" "v1", by enum loft_edge. */
extern const char *const loft_edge_name[4];

/*
 * Read a `patch` record (loft.5) and append it to d, keeping a pointer
 * to rec for messages and for its other attributes.  Returns 0, or
 * LOFT_EINPUT (wrong rows or numbers, a bad or missing id=, scale factor
 * or neighbour list) or LOFT_ENOMEM.
 */
int loft_design_add(struct loft_design *d, const struct loft_record *rec,
    struct loft_error *err);

/* The id= of a patch record rec: 0 and *id, or LOFT_EINPUT (none, or not
 * a whole number from 1 to 1000000000) with err saying which. */
int loft_patch_id(const struct loft_record *rec, long *id,
    struct loft_error *err);

/*
 * Append a patch with coefficients b, id and no neighbours (scale
 * factors 1).  Preconditions, checked: dim 2 or 3, id from 1 to
 * 1000000000 (as loft_patch_id reads it); an id already in d is
 * loft_design_check's to find.  Returns 0, LOFT_EINPUT (a precondition
 * broken, d unchanged) or LOFT_ENOMEM.
 */
int loft_design_new(struct loft_design *d, const double *b, int dim,
    long id, struct loft_error *err);

void loft_design_free(struct loft_design *d);

/* The index of the patch with id, or -1; O(log n) (the first lookup
 * after patches were added out of order of id sorts d's index once). */
long loft_design_find(const struct loft_design *d, long id);

/*
 * Check that ids are unique, every patch has the same dim, and each
 * neighbour named exists and names the patch back with the same sense.
 * Returns 0, or LOFT_EINPUT with *bad the index of the patch at fault,
 * or LOFT_ENOMEM.  O(n log n) in the count of patches and links.
 */
int loft_design_check(const struct loft_design *d, size_t *bad,
    struct loft_error *err);

/*
 * Section 5: split patch i along u = t (dir 0) or v = t (dir 1) into
 * two patches with new ids (d->maxid + 1, + 2), the first (parameter
 * 0 to t) in its place at i, the second appended at d->n - 1; scale
 * factors multiplied by t and 1 - t, and neighbour links updated on
 * both sides, T-junctions included.  No other patch moves in d->p.
 * Preconditions, checked: i < d->n, dir 0 or 1, 0 < t < 1, and every
 * neighbour patch i names is in d (as loft_design_check ensures).
 * Returns 0, LOFT_EINPUT (a precondition broken, d unchanged; or the
 * ids are used up) or LOFT_ENOMEM.
 */
int loft_design_split(struct loft_design *d, size_t i, int dir, double t,
    struct loft_error *err);

/*
 * Section 4: drag the point (u, v) of patch i by delta.  Nearer than
 * edge to an edge with one neighbour sharing all of it, the two patches
 * change by one bi-quartic bump over both; otherwise (hh) alone changes
 * by delta / (H5(u) H5(v)).  Preconditions, checked: i < d->n, u and
 * v in [0, 1], delta finite.  Returns 0 and fills info, or LOFT_EINPUT
 * (a precondition broken, d unchanged) or LOFT_EGEOM when the point is
 * on an edge that the drag cannot move.
 */
int loft_design_drag(struct loft_design *d, size_t i, double u, double v,
    const double *delta, double edge, struct loft_drag_info *info,
    struct loft_error *err);

struct loft_join_info {
	int edge_p, edge_s;     /* the joined edges (enum loft_edge) */
	int reversed;           /* the edges run opposite ways */
	double gap;             /* largest distance between them before */
	double size;            /* the larger patch's size */
	double pos_after;       /* largest distance after */
	double slope_after;     /* largest slope mismatch after, relative */
};

/*
 * Section 6: join patch is (subsidiary) to patch ip (principal), which
 * does not change: the subsidiary's edge nearest an edge of the
 * principal becomes that edge, and its cross-boundary derivatives those
 * of the principal times the ratio of the scale factors, so slopes are
 * continuous; both are linked as neighbours.  Edges farther apart than
 * LOFT_JOIN_GAP of the larger patch's size do not meet.  Preconditions,
 * checked: ip and is < d->n, both of one dim.  Returns 0 and fills info,
 * or LOFT_EINPUT (a precondition broken, d unchanged), LOFT_EGEOM (the
 * same patch twice, no edge within reach, an edge already linked, or a
 * neighbour of the subsidiary that the join would break).
 */
#define LOFT_JOIN_GAP 0.05
int loft_design_join(struct loft_design *d, size_t ip, size_t is,
    struct loft_join_info *info, struct loft_error *err);

/*
 * The size of patch b: the diagonal of the box around its points on a
 * 5 x 5 grid.  Used to make tolerances scale-free.
 */
double loft_patch_size(const double *b, int dim);

/*
 * A patch from four corners p00, p10, p01, p11 (dim numbers each): the
 * bilinear patch through them, whose twist is the constant
 * p00 - p10 - p01 + p11.
 */
void loft_patch_bilinear(const double *corner, int dim, double *b);

/*
 * A patch from four boundary quartics (5 * dim numbers each): c[0] the
 * edge v = 0 and c[1] the edge v = 1, both running in u; c[2] the edge
 * u = 0 and c[3] the edge u = 1, both running in v; by Coons' bilinearly
 * blended construction.  Corners must agree within LOFT_CORNER_TOL of
 * the curves' size; the corners are taken from c[0] and c[1].
 * Precondition, checked: dim 2 or 3.  Returns 0, LOFT_EINPUT (dim), or
 * LOFT_EGEOM naming the corner that does not match, with row the index
 * of the curve whose end misses.
 */
#define LOFT_CORNER_TOL 1e-9
int loft_patch_coons(const double *const *c, int dim, double *b,
    struct loft_error *err);

/*
 * Recognise rec as a curve of cubic or quartic segments, the curves
 * patchnew's boundaries and patchdrag's dragged curves are, and fill c
 * as loft_curve_from_record does.  Returns 0, or LOFT_EINPUT when rec is
 * no curve or a curve of another kind (a bezier record's rows are
 * control points, not segments), or its type has no quartic form.
 */
int loft_curve_segments(const struct loft_record *rec, struct loft_curve *c,
    struct loft_error *err);

/* Segment i of c as a quartic: 5 * dim numbers, by its type's quartic
 * form.  c is from loft_curve_segments, or has c->quartic set. */
void loft_curve_quartic(const struct loft_curve *c, size_t i, double *q);

/* ------------------------------------------------------------------ */
/* Surfaces of any record type, for programs that evaluate them        */
/* (surface.c)                                                         */

struct loft_surface {
	const char *type;
	const double *coef;     /* the record's rows */
	int dim;
	int m, n;               /* the type's own shape, if it has one */
	void (*eval)(const struct loft_surface *s, double u, double v,
	    double *p, double *du, double *dv);
	void (*eval2)(const struct loft_surface *s, double u, double v,
	    double *p, double *du, double *dv, double *duu, double *dvv);
	void (*box)(const struct loft_surface *s, double *lo, double *hi);
	void (*bezier)(const struct loft_surface *s, double *ctl);
	const struct loft_surface *of;  /* loft_surface_scaled's: the one */
	int scale;                      /* this shows at 2^scale its size */
};

/* Whether rec's type is a surface type (`patch`, `bezier-surface`). */
int loft_is_surface(const struct loft_record *rec);

/*
 * Recognise rec as a surface record of a known type and fill s, which
 * points into rec.  Returns 0, or LOFT_EINPUT when it is not one or its
 * rows do not fit its type.
 */
int loft_surface_from_record(const struct loft_record *rec,
    struct loft_surface *s, struct loft_error *err);

/*
 * Evaluate s at (u, v) in [0,1] x [0,1]: point and the two partial
 * derivatives (any may be NULL).
 */
void loft_surface_eval(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv);

/* The same, with the second derivatives x_uu and x_vv (may be NULL). */
void loft_surface_eval2(const struct loft_surface *s, double u, double v,
    double *p, double *du, double *dv, double *duu, double *dvv);

/* Fill s for the patch of coefficients b (a patch of a design), which
 * s points into. */
void loft_surface_from_patch(const double *b, int dim, struct loft_surface *s);

/*
 * A box lo..hi (s->dim numbers each) that holds the whole surface: the
 * box of its Bezier control net (a patch's converted from MacCallum's
 * form), so a plane that misses the box misses the surface.
 */
void loft_surface_box(const struct loft_surface *s, double *lo, double *hi);

/*
 * The control net of s, of (s->m + 1)(s->n + 1) points of 3 numbers,
 * u-major (P_ij at ctl[3 * (i * (s->n + 1) + j)]), in space: a plane
 * surface's z is 0.  The same polynomial surface exactly: a patch's net
 * is loft_patch_bezier's.
 */
void loft_surface_bezier(const struct loft_surface *s, double *ctl);

/*
 * Fill out as a view of s at 2^e times its size (its points, derivatives,
 * box and net all times 2^e, exactly): a computation on a surface near
 * unit size squares its lengths without overflow or underflow, whatever
 * the units.  out points to s, which must outlive it.
 */
void loft_surface_scaled(const struct loft_surface *s, int e,
    struct loft_surface *out);

/* ------------------------------------------------------------------ */
/* Grading outlines into shoe sizes (grade.c)                          */

/*
 * A size system: the length and the insole width a size number adds,
 * in millimetres; the usual interval between sizes, in size numbers;
 * the range of sizes, lo to hi.  grade(1) says where each rule comes
 * from.
 */
struct loft_size_system {
	const char *name;       /* "english", "paris", "mondopoint" */
	double length, width;
	double interval;
	double lo, hi;
};

/* The systems, ended by one whose name is NULL. */
extern const struct loft_size_system loft_size_systems[];

/* The system called name, or NULL. */
const struct loft_size_system *loft_size_system(const char *name);

/*
 * The frame of an outline: its length runs along axis (0 x, 1 y), len
 * and wid are its bounding box's extents along and across that axis,
 * ref the point it grows about.
 */
struct loft_grade_frame {
	int axis;
	double len, wid;
	double ref[2];
};

/* Sides within this fraction of the longer are too near square to say
 * which is the length: an insole is about 2.8 to 1, and a box nearer
 * square than 5% could turn the other way with a knot moved a little. */
#define LOFT_GRADE_SQUARE 0.05

/*
 * The frame of the n plane knots p (n >= 1).  axis is 0 or 1, or -1 for
 * the longer side of the bounding box; ref is the reference point, or
 * NULL for the heel: the first knot of least coordinate along the
 * length axis.  Returns 0, or LOFT_EINPUT (no knots, an extent that
 * overflows) or LOFT_EGEOM (no extent along x or y; with axis -1, a
 * box square within LOFT_GRADE_SQUARE).
 */
int loft_grade_frame(const double *p, size_t n, int axis, const double *ref,
    struct loft_grade_frame *f, struct loft_error *err);

/* A size adds a few per cent to an outline (an English size is 3% of a
 * 265 mm insole, 8% of a 100 mm child's); a step of more than a quarter
 * of the outline is in other units than its knots. */
#define LOFT_GRADE_STEP_MAX 0.25

/*
 * Check the length and width steps of one size interval, in the knots'
 * units, against f: 0, or LOFT_EINPUT when one exceeds
 * LOFT_GRADE_STEP_MAX of the outline's length or width.
 */
int loft_grade_steps_fit(const struct loft_grade_frame *f, double lstep,
    double wstep, struct loft_error *err);

/*
 * Arithmetic grading: the n knots p made dl longer along f's axis and
 * dw wider across it about f->ref, exactly L + dl by W + dw, into q (2n
 * numbers; not p).  With mirror, q is instead the mirror image, about
 * the line through ref along the length axis, in reverse order, so it
 * turns the same way round.  Precondition, checked: q is not p.
 * Returns 0, LOFT_EINPUT (q is p), or LOFT_EGEOM when L + dl or W + dw
 * is not positive (the message starts "leaves the outline").
 */
int loft_grade_outline(const struct loft_grade_frame *f, const double *p,
    size_t n, double dl, double dw, int mirror, double *q,
    struct loft_error *err);

/*
 * A tangent direction t of the knots (start= or end=) as the grading
 * stretches it, into q; with mirror, reflected and reversed: the
 * mirror's tangent at the other end.
 */
void loft_grade_direction(const struct loft_grade_frame *f, double dl,
    double dw, int mirror, const double *t, double *q);

/* ------------------------------------------------------------------ */
/* Lofting: a design of patches through section curves (skin.c)         */

struct loft_skin_opts {
	int closed;             /* the sections form a ring */
	int have_start, have_end;       /* given slopes at the first and
	                                   last section (open lofts) */
	double start[LOFT_MAXDIM], end[LOFT_MAXDIM];
};

/*
 * The lofted surface: nu strips across the sections by nv segments
 * along them, patch (k, j) (between sections k and k + 1, over segment
 * j) at b + (k * nv + j) * 25 * dim, in loft_patch_eval's layout; su[k]
 * the scale factor in u of strip k.
 */
struct loft_skin_result {
	int dim;
	size_t nu, nv;
	int closed_u, closed_v; /* a closed loft; closed sections */
	double *b;
	double *su;
};

/*
 * Loft the ns section curves sec (cubic or quartic records, all of one
 * dimension, all open or all closed, in order) into out, as skin.c's
 * header and patchloft(1) describe: the sections are the patch edges
 * along v (refined to the union of their normalised breakpoints, split
 * exactly), the curves across at each breakpoint go through the
 * sections' points with loft_fit's (default method's) tangent
 * directions, and the surface is tangent-plane continuous across every
 * patch edge where the sections are smooth.  Returns 0 (free out with
 * loft_skin_free), or LOFT_EINPUT / LOFT_EGEOM with err->row the index
 * of the section at fault (a bezier record, no segment, another
 * dimension, open among closed, fewer than 2 sections (3 for a closed
 * loft), sections that cross, a curve across that loft_fit cannot fit),
 * or LOFT_ENOCONV, LOFT_ENOMEM.
 */
int loft_skin(const struct loft_skin_opts *o, const struct loft_curve *sec,
    size_t ns, struct loft_skin_result *out, struct loft_error *err);

void loft_skin_free(struct loft_skin_result *r);

/*
 * Append r's patches to the design d (empty, or ids will clash) with
 * ids 1, 2, .. (patch (k, j) is k * nv + j + 1), scale factors su, and
 * the neighbour links of the grid (each a whole edge, the same way;
 * around the ring of a closed loft or closed sections too).  Returns 0,
 * LOFT_EINPUT (more patches than ids) or LOFT_ENOMEM.
 */
int loft_skin_design(const struct loft_skin_result *r, struct loft_design *d,
    struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Cutting surfaces by planes (cut.c)                                  */

/* Surfaces to cut, each with the box of its Bezier net. */
struct loft_cutter {
	const struct loft_surface *s;
	size_t ns;
	int dim;
	double *box;            /* ns * 2 * dim: lo, hi of each */
	double size;            /* the diagonal of the box of them all */
};

/*
 * Prepare the ns surfaces s (caller-owned, all of one dim, ns >= 0)
 * for loft_cut_plane.  Returns 0 or LOFT_ENOMEM.  Free with
 * loft_cutter_free.
 */
int loft_cutter_init(struct loft_cutter *k, const struct loft_surface *s,
    size_t ns, struct loft_error *err);
void loft_cutter_free(struct loft_cutter *k);

/* A curve of a cut: n >= 1 points, dim each; closed: the last joins the
 * first (which it does not repeat). */
struct loft_cut_curve {
	double *p;
	size_t n;
	int closed;
};

/* Curves of cuts, appended; starts zeroed. */
struct loft_cut {
	int dim;
	struct loft_cut_curve *c;
	size_t n, cap;
};

/*
 * Cut k's surfaces by the plane normal . x = d (normal: k->dim numbers,
 * not all zero) and append to out one curve per connected piece:
 * pieces of different surfaces are joined where their ends meet within
 * 1e-9 of k->size (across shared edges); an edge lying in the plane is
 * a piece too, once.  Every point is on a surface as evaluated and on
 * the plane to rounding (solved in one parameter with the other fixed);
 * every chord is within tol of the cut (tol > 0, in the surfaces'
 * units; one below 1e-9 of k->size is taken as that).  Returns 0, or LOFT_EGEOM when the plane misses every
 * surface (nothing appended), LOFT_EINPUT (a zero normal) or
 * LOFT_ENOMEM.
 */
int loft_cut_plane(const struct loft_cutter *k, const double *normal, double d,
    double tol, struct loft_cut *out, struct loft_error *err);

void loft_cut_free(struct loft_cut *c);

/* ------------------------------------------------------------------ */
/* A grid of the plane, for what lies near a box or a segment (grid.c) */
/* ------------------------------------------------------------------ */

/*
 * Items (boxes, or segments by the cells they pass through), each filed
 * under every cell of a uniform grid it covers; a query looks at the
 * cells of its box, so its time grows with what is near, not with all.
 * Segments are x0 y0 x1 y1; boxes lo[2], hi[2].  Start with
 * loft_grid_init, end with loft_grid_free.
 */
struct loft_grid {
	double cw, ch, x0, y0;  /* a cell's size, and the origin of cells */
	size_t *head;           /* nbucket chains, (size_t)-1 at their end */
	size_t nbucket;
	struct loft_grid_entry {
		long cx, cy;    /* the cell */
		size_t id;      /* the item's, given when it was added */
		size_t next;
	} *e;
	size_t ne, ecap;
};

/* An empty grid of cells cw by ch (> 0) from origin[0..1], sized for
 * about n entries.  Returns 0, or LOFT_ENOMEM. */
int loft_grid_init(struct loft_grid *g, double cw, double ch,
    const double *origin, size_t n);
void loft_grid_free(struct loft_grid *g);

/* File item id by the box lo..hi, or by the segment sg.  Returns 0, or
 * LOFT_ENOMEM (the grid holds part of the item). */
int loft_grid_add(struct loft_grid *g, const double *lo, const double *hi,
    size_t id);
int loft_grid_add_segment(struct loft_grid *g, const double *sg, size_t id);

/* Call visit(ctx, id) for each entry in the cells of the box lo..hi (an
 * item covering several of them comes once for each), or in the cells
 * the segment sg passes through, until visit returns nonzero; returns
 * that, or 0. */
int loft_grid_each(const struct loft_grid *g, const double *lo,
    const double *hi, int (*visit)(void *ctx, size_t id), void *ctx);
int loft_grid_each_along(const struct loft_grid *g, const double *sg,
    int (*visit)(void *ctx, size_t id), void *ctx);

/* Whether the segments s and t cross: each one's ends lie strictly on
 * either side of the other's line (touching or in line is not). */
int loft_segments_cross(const double *s, const double *t);

/*
 * Whether two plane polylines from one point, a and b (n points each,
 * x y pairs, a[0] and b[0] that point), cross each other elsewhere: an
 * edge of one crosses an edge of the other, the two first edges (which
 * meet at that point) aside.  For a curve that turns back at a corner,
 * the two pieces beside it sampled finer than the edges a test of the
 * whole polyline skips there, as neighbours.
 */
int loft_fold_crosses(const double *a, const double *b, size_t n);

/*
 * The parameter, from the joint, of sample t (0 <= t <= LOFT_FOLD_FINE +
 * m) of a side of a fold for loft_fold_crosses: 0, then LOFT_FOLD_FINE
 * samples halving towards the joint below the first of m even steps up
 * to reach.  Two sides that cross at least reach / m / 2^LOFT_FOLD_FINE
 * from the joint are found crossing (where they leave it reversed, the
 * first edges hide a crossing however near).
 */
#define LOFT_FOLD_FINE 24
double loft_fold_u(size_t t, size_t m, double reach);

/*
 * Whether the two sides of a joint where a plane curve turns back cross
 * (loft_fold_crosses): segment pj, ending there, and segment j,
 * starting there, each sampled LOFT_FOLD_STEPS even steps up to reach
 * (in its parameter) from the joint and LOFT_FOLD_FINE more towards it
 * (loft_fold_u); eval(ctx, s, u, p) puts the point of segment s at u in
 * p.
 */
#define LOFT_FOLD_STEPS 64
int loft_sides_cross(void (*eval)(const void *ctx, size_t s, double u,
    double *p), const void *ctx, size_t pj, size_t j, double reach);

/* Whether the segment sg meets the closed box lo..hi. */
int loft_segment_meets_box(const double *sg, const double *lo,
    const double *hi);

/* ------------------------------------------------------------------ */
/* Labels of a picture, clear of its lines and each other (labels.c)  */
/* ------------------------------------------------------------------ */

/* A label tries these many points of its record's curve. */
#define LOFT_LABEL_ANCHORS 13

struct loft_label {
	/* the caller's */
	int rec;                /* the record it names, as its lines' */
	double width;           /* its text's, in the drawing's units */
	double anchor[2];       /* its record's rightmost point */
	double anc[LOFT_LABEL_ANCHORS][2];      /* points of its curve, the
	                                         * rightmost first */
	int nanc;               /* how many of anc are set, 1 at least */
	int centred;            /* a patch's: centred on anchor */
	/* loft_place_labels' */
	double at[2];           /* where its text begins; its centre when
	                         * centred or oncurve */
	int oncurve;            /* centred on a point of its own curve */
	int leader;             /* placed far: a line ties it to anchor */
	double lo[2], hi[2];    /* its box */
};

/*
 * Place the n labels lb, each clear of every line and of the labels
 * placed before it, a font high, trying in turn: (1) spots within a
 * line and a half of points along its record's curve that are within a
 * line of that curve and two of no other record's; (2) on its own
 * curve, clear of the others' lines; (3) spots out to the right of its
 * rightmost point two lines clear of every line, tied to it by a leader
 * that crosses no earlier label or leader (and that later labels keep
 * clear of); (4) the spots of (1) without their condition; (5) its
 * rightmost point, moved down a line at a time below the first label
 * placed before it that it overlaps (after LAST_MOVES of labels.c
 * moves, on rows below everything instead: linear time in a crowd).
 * All in units of a power of two near font: a drawing of any units.
 * A centred label (a patch's)
 * stays at its anchor, moved as in (5) only.  The lines are the nseg
 * segments seg (4 numbers each), segrec[k] the record of segment k.
 * The labels' boxes are added to the box lo..hi, whose lo is the
 * origin of the grids.  Returns 0, or LOFT_ENOMEM.
 */
int loft_place_labels(struct loft_label *lb, size_t n, const double *seg,
    const int *segrec, size_t nseg, double font, double *lo, double *hi);

/* The box of label l of height font; the leader of a placed label, from
 * its anchor to the nearest point of its box, into sg (4 numbers). */
void loft_label_box(const struct loft_label *l, double font, double *lo,
    double *hi);
void loft_label_leader(const struct loft_label *l, double *sg);

/* ------------------------------------------------------------------ */
/* B-splines as Bezier pieces (bspline.c)                              */

#define LOFT_BSPLINE_MAXDEG 63          /* as LOFT_BEZIER_MAXPTS - 1 */
#define LOFT_BSPLINE_MAXDIM 4           /* a point in space and a weight */
#define LOFT_BSPLINE_MAXCTL 100000000   /* control points in one direction */

/*
 * Check a B-spline of degree deg (1 to LOFT_BSPLINE_MAXDEG) with nctl
 * control points (deg + 1 to LOFT_BSPLINE_MAXCTL) and the nctl + deg + 1
 * knots t: finite, never decreasing, at least one span [t_i, t_i+1) of
 * positive length for i from deg to nctl - 1.  Returns 0, or LOFT_EINPUT
 * with err saying what is wrong (row: the knot's index).
 */
int loft_bspline_check(const double *t, size_t nctl, int deg,
    struct loft_error *err);

/* The count of spans of positive length, i from deg to nctl - 1. */
size_t loft_bspline_spans(const double *t, size_t nctl, int deg);

/*
 * The B-spline curve of degree deg, knots t and control points ctl (nctl
 * of dim numbers, 1 <= dim <= LOFT_BSPLINE_MAXDIM) as its Bezier pieces,
 * by knot insertion, clamped or not: piece k (of loft_bspline_spans) at
 * out[k (deg + 1) dim], the curve over its span, whose ends go into
 * range[2k], range[2k + 1] (range may be NULL).  Exact but for rounding.
 * A rational curve is converted in homogeneous form (w x, w y, w z, w).
 * Returns 0, or LOFT_EINPUT (loft_bspline_check, or dim).
 */
int loft_bspline_bezier(const double *t, size_t nctl, int deg,
    const double *ctl, int dim, double *out, double *range,
    struct loft_error *err);

/*
 * One piece of loft_bspline_bezier, for a caller that takes them one at
 * a time: the Bezier points b[0..deg] (dim numbers each) of span i
 * (deg <= i < nctl, t[i] < t[i + 1]) of a curve loft_bspline_check has
 * passed.  O(deg^2 dim) work, so a curve costs O(nctl deg^2 dim).
 */
void loft_bspline_span(const double *t, const double *ctl, int deg,
    size_t i, int dim, double *b);

/*
 * The tensor-product B-spline surface of degrees p in u and q in v,
 * knots tu (nu + p + 1) and tv (nv + q + 1), control points P_ij
 * u-major at ctl[(i nv + j) dim], as Bezier patches: patch (a, b), a
 * the u span and b the v span (of loft_bspline_spans), at
 * out[(a sv + b) (p + 1) (q + 1) dim], its points u-major.  Returns 0,
 * LOFT_EINPUT (as loft_bspline_bezier) or LOFT_ENOMEM.
 */
int loft_bspline_surface_bezier(const double *tu, size_t nu, int p,
    const double *tv, size_t nv, int q, const double *ctl, int dim,
    double *out, struct loft_error *err);

/*
 * The rational Bezier curve hw of degree deg (1 to 63), points of
 * dim + 1 numbers (w x, ..., w; dim 1 to 3, weights positive; a
 * polynomial one has all weights 1), as *n cubic Bezier pieces (4 points
 * of dim numbers each into out, which holds 4 max dim) over equal parts
 * of [0, 1], each the cubic that matches the curve's points and
 * derivatives at its ends, within tol of the curve at the same
 * parameter (checked at 15 inner points a piece with a margin of 2).
 * *n is a power of 2 no more than max.  Returns 0; LOFT_EGEOM where a
 * weight is not positive; LOFT_ENOCONV when more than max pieces would
 * be needed; LOFT_EINPUT for bad arguments.
 */
int loft_rational_cubics(const double *hw, int deg, int dim, double tol,
    size_t max, double *out, size_t *n, struct loft_error *err);

/*
 * The same for a rational tensor Bezier surface in space, degrees m and
 * n, points (w x, w y, w z, w) u-major: *ku by *kv bicubic patches (16
 * points of 3 numbers, u-major) into out (48 max max numbers), patch
 * (a, b) over [a/ku, (a+1)/ku] x [b/kv, (b+1)/kv] at out[48 (a kv + b)],
 * each Hermite-interpolating the corners' points, derivatives and
 * twists; ku and kv powers of 2, ku kv at most max max, the direction
 * that gains more halved first.  Returns as loft_rational_cubics.
 */
int loft_rational_bicubics(const double *hw, int m, int n, double tol,
    size_t max, double *out, size_t *ku, size_t *kv,
    struct loft_error *err);


/*
 * loft_rational_cubics and loft_rational_bicubics for polynomial Bezier
 * curves (ctl, dim 1 to 3) and surfaces (in space, u-major), all weights
 * 1: for a format that reads no degree as high.  Returns as they do.
 */
int loft_bezier_cubics(const double *ctl, int deg, int dim, double tol,
    size_t max, double *out, size_t *n, struct loft_error *err);
int loft_bezier_bicubics(const double *ctl, int m, int n, double tol,
    size_t max, double *out, size_t *ku, size_t *kv,
    struct loft_error *err);

/* ------------------------------------------------------------------ */
/* Triangle meshes of surfaces (mesh.c)                                */

/*
 * A mesh: nv vertices of 3 numbers (a plane surface's third is 0), each
 * with the (u, v) and the index of the surface it was evaluated on; nt
 * triangles of 3 vertex indices.  Starts zeroed; free with
 * loft_mesh_free.
 */
struct loft_mesh {
	double *v;
	size_t nv;
	size_t *t;
	size_t nt;
	double *uv;             /* 2 numbers a vertex */
	size_t *patch;          /* a vertex's surface, by index */
	size_t vcap, tcap, uvcap, pcap;
};

/*
 * The steps N along each side of the Bezier patch of degrees m, n
 * (control points ctl, 3 numbers each, u-major) for which the mesh's
 * triangles are within tol (> 0) of it: 1 to 256.
 */
long loft_mesh_steps(const double *ctl, int m, int n, double tol);

/*
 * Append the ns surfaces s to me, each on an N x N grid of cells (N >= 1,
 * the same for all so that shared edges match), two triangles a cell,
 * counter-clockwise in (u, v) (normals along f_u x f_v), vertices u-major.
 * With a design dz (or NULL), ip[i] (or ip NULL) the index in dz of
 * surface i or -1: where a neighbour covers only part of an edge, the
 * cells along it are fans through the neighbour's steps, so there is no
 * T-junction.  With weld_tol >= 0 vertices within weld_tol are then one
 * and the triangles oriented alike across every shared side; with
 * weld_tol < 0 the grids are left as made.  Returns 0 or LOFT_ENOMEM.
 */
int loft_mesh_surfaces(struct loft_mesh *me, const struct loft_surface *s,
    size_t ns, const long *ip, const struct loft_design *dz, long N,
    double weld_tol);

/*
 * The adjacency of me's triangles: nb[3 t + k] (nb holds 3 nt) is the
 * triangle across side k of triangle t (from its vertex k to k + 1), or
 * (size_t)-1 on the boundary or where more than two triangles meet;
 * same (may be NULL) whether the two run that side the same way.
 * Returns 0 or LOFT_ENOMEM.
 */
int loft_mesh_neighbours(const struct loft_mesh *me, size_t *nb,
    unsigned char *same);

/*
 * Weld me: vertices within tol (>= 0) of one another are one, triangles
 * that lose a side to it dropped, the rest renumbered in their order;
 * map (may be NULL; nv entries, the count before) gets each old
 * vertex's new index.  Returns 0 or LOFT_ENOMEM (me unchanged).
 */
int loft_mesh_weld(struct loft_mesh *me, double tol, size_t *map);

void loft_mesh_free(struct loft_mesh *me);

/* Fill s for the Bezier patch of degrees m, n (control points ctl of 3
 * numbers, u-major, as a bezier-surface record's rows); s points into
 * ctl.  (surface.c) */
void loft_surface_from_bezier(const double *ctl, int m, int n,
    struct loft_surface *s);

/* ------------------------------------------------------------------ */
/* Sparse symmetric systems (sparse.c)                                 */

/*
 * A sparse symmetric matrix of order n, its entries (i, j, a) in any
 * order, duplicates summed; both triangles are given or only one (the
 * other follows).  Built by loft_sparse_add, then loft_sparse_compress.
 */
struct loft_sparse {
	size_t n;
	size_t *row, *col;      /* triplets, then compressed rows: row[n + 1] */
	double *a;
	size_t nnz, cap;
	int compressed;
};

/* Add a to entry (i, j) and, off the diagonal, to (j, i).  i, j < n.
 * Returns 0 or LOFT_ENOMEM. */
int loft_sparse_add(struct loft_sparse *m, size_t i, size_t j, double a);

/* Sort and sum the entries into compressed rows.  0 or LOFT_ENOMEM. */
int loft_sparse_compress(struct loft_sparse *m);

/*
 * Solve m x = b (m compressed, symmetric positive definite) by conjugate
 * gradients with a Jacobi preconditioner, from the x given (a guess, or
 * zeros), until the residual is below tol times |b|, at most maxit
 * steps.  Returns 0, LOFT_ENOCONV (x holds the best reached) or
 * LOFT_ENOMEM.  *iters (may be NULL) gets the steps taken.
 */
int loft_sparse_solve(const struct loft_sparse *m, const double *b,
    double *x, double tol, long maxit, long *iters);

void loft_sparse_free(struct loft_sparse *m);

/*
 * A Cholesky factor L L^t = P m P^t of a compressed symmetric positive
 * definite m, held in its envelope, the rows in reverse Cuthill-McKee
 * order (P) so that a mesh's envelope stays narrow.  For many solves
 * with one matrix (unroll's rounds).
 */
struct loft_sparse_chol {
	size_t n;
	size_t *perm, *inv;     /* row i of the factor is m's row perm[i] */
	size_t *first, *start;  /* row i holds columns first[i]..i from */
	double *l;              /* l[start[i]] on */
};

/* Factor m into c.  Returns 0, LOFT_EGEOM (m is not positive definite)
 * or LOFT_ENOMEM (also when the envelope would pass 2^26 numbers). */
int loft_sparse_factor(const struct loft_sparse *m, struct loft_sparse_chol *c);

/* Solve m x = b with the factor c; work holds c->n numbers. */
void loft_sparse_chol_solve(const struct loft_sparse_chol *c, const double *b,
    double *x, double *work);

void loft_sparse_chol_free(struct loft_sparse_chol *c);


/* ------------------------------------------------------------------ */
/* The numbers of a surface (surfmeasure.c)                            */

/*
 * A surface is developable (unrolls without strain) when the integral
 * of |K| dA, its total absolute Gaussian curvature, a number without
 * units, is at most this: the quadrature of an exact cylinder or cone
 * gives 1e-10 or less, and a dome of 1 % rise already gives 1e-3.
 */
#define LOFT_DEVELOPABLE_TOL 1e-6

/* Where a curvature is greatest or least: its value, the surface (by
 * index) and (u, v). */
struct loft_surface_where {
	double value;
	size_t patch;
	double u, v;
};

struct loft_surface_numbers {
	double area;
	struct loft_surface_where kmin, kmax;   /* Gaussian curvature */
	struct loft_surface_where hmin, hmax;   /* mean curvature, signed */
	                                        /* as f_u x f_v points */
	double kint, kabs;      /* integral of K dA and of |K| dA */
	int developable;        /* kabs <= LOFT_DEVELOPABLE_TOL */
};

/*
 * The Gaussian curvature *k, mean curvature *h and area element
 * |f_u x f_v| *da of s at (u, v).  Returns 0, or LOFT_EGEOM where the
 * surface is degenerate there (*k = *h = 0).
 */
int loft_surface_curvature(const struct loft_surface *s, double u, double v,
    double *k, double *h, double *da);

/*
 * The numbers of the ns surfaces s taken as one: by Gauss-Legendre
 * quadrature of order 5 on cells x cells cells of each (cells >= 1; 8
 * holds the area of a cubic patch to 1e-12), the extremes among the
 * quadrature's points.
 */
void loft_surface_numbers(const struct loft_surface *s, size_t ns, long cells,
    struct loft_surface_numbers *m);

/* ------------------------------------------------------------------ */
/* Laying a surface flat (unroll.c)                                    */

struct loft_unroll_opts {
	double tol;             /* the mesh within this, in units, or 0: */
	                        /* LOFT_UNROLL_RELTOL of the sheet's size */
	long steps;             /* mesh steps a patch side, or 0: from tol */
	int arap;               /* 1: as-rigid-as-possible even when the */
	                        /* surface is developable */
	int rounds;             /* as-rigid-as-possible rounds at most */
};

/* The default tolerance: 1e-5 of the size, as a CAD polyline's. */
#define LOFT_UNROLL_RELTOL 1e-5

/* The default rounds of the as-rigid-as-possible iteration: each
 * lowers the energy; after 50 the largest strain moves by less than
 * 1e-4 of itself on a dome or a bow. */
#define LOFT_UNROLL_ROUNDS 50

/*
 * A surface laid flat.  The mesh is welded across shared edges; xy
 * its vertices in the plane.  grid[k] the welded vertex of node
 * (i, j) of patch p, k = (p (N + 1) + i) (N + 1) + j, at (u, v) =
 * (i / N, j / N); jac there the 2 x 2 derivative of the flat map
 * (d/du, d/dv; 4 numbers).  seg the outline: nseg cubic segments of
 * 8 numbers (loft.5's cubic rows), closed, counter-clockwise.
 */
struct loft_unroll {
	struct loft_mesh mesh;
	double *xy;
	size_t *grid;
	double *jac;
	long N;
	size_t npatch;
	double *seg;
	size_t nseg;
	int exact;              /* developed exactly; else least strain */
	long rounds;            /* as-rigid-as-possible rounds taken */
	double strain_max, strain_mean; /* of mesh edges, |flat|/|3-D| - 1 */
	double area3, area2;    /* of the mesh in space and flat */
	struct loft_surface_numbers num;
};

/*
 * Lay the ns surfaces s, one sheet (their shared edges found by
 * welding, as loft_mesh_surfaces does), flat.  Where the sheet is
 * developable (loft_surface_numbers) and o->arap is 0, each surface is
 * developed exactly: its edge u = 0 into the plane by its geodesic
 * curvature, then each line v = const from it, by Gauss-Legendre
 * quadrature, so lengths and angles are kept to rounding; the patches
 * are then placed on one another where they share vertices.  Otherwise
 * that development starts an as-rigid-as-possible iteration (Liu et al.
 * 2008: local rotations, then a global sparse least-squares solve) on
 * the mesh, and six passes reweighted towards the least largest
 * strain.  Returns 0 and fills r (free with loft_unroll_free), or
 * LOFT_EINPUT (no surface, tol negative or not finite), LOFT_EGEOM (a
 * surface that is a point or overflows, a sheet with no outline) or
 * LOFT_ENOMEM.
 */
int loft_unroll(const struct loft_unroll_opts *o, const struct loft_surface *s,
    size_t ns, struct loft_unroll *r, struct loft_error *err);

/*
 * The cubic segment (8 numbers, a cubic record's row) of the flat
 * image of patch p of r from grid node a to grid node b ((u, v) of
 * each, multiples of 1 / r->N, neighbours on the grid): their flat
 * points and the flat map's derivative along the step.
 */
void loft_unroll_hermite(const struct loft_unroll *r, size_t p,
    const double *a, const double *b, double *seg);

/*
 * The flat image of the cut of r's mesh by the plane normal . x = d:
 * curves of plane points appended to out (out->dim 2), each piece
 * chained across the triangles.  Returns 0 or LOFT_ENOMEM.
 */
int loft_unroll_cut(const struct loft_unroll *r, const double *normal,
    double d, struct loft_cut *out);

void loft_unroll_free(struct loft_unroll *r);
/* Surfaces clipped by planes, integrals below them (waterline.c)      */

#define LOFT_CLIP_MAX 2         /* planes of one clip */
#define LOFT_CLIP_MAXVAL 24     /* integrands of one clip */

/* The part of a surface where p[axis[k]] <= level[k] for k < n; tol[i]:
 * the absolute error allowed in integral i (> 0). */
struct loft_clip {
	int n;
	int axis[LOFT_CLIP_MAX];
	double level[LOFT_CLIP_MAX];
	double tol[LOFT_CLIP_MAXVAL];
};

/* An integrand: at the point p with partial derivatives pu, pv (the
 * surface's own), add w times its values to acc[0..nval-1]. */
typedef void (*loft_clip_fn)(void *ctx, const double *p, const double *pu,
    const double *pv, double w, double *acc);

/*
 * Add to acc[0..nval-1] the integrals of f over the parameters (u, v)
 * in [0,1]^2 where the surface s (dim 3, degrees s->m, s->n) is kept by
 * the clip c.  The kept part's curved edge is found to rounding at each
 * quadrature node, so a polynomial integrand whose degree in each
 * parameter is below 20 is integrated exactly to rounding where the
 * edge is a graph of one parameter, and any other within c->tol by
 * adaptive halving.  Returns 0, or LOFT_EINPUT (dim, n or nval out of
 * range; acc unchanged).
 */
int loft_clip_integrate(const struct loft_surface *s, const struct loft_clip *c,
    loft_clip_fn f, void *ctx, int nval, double *acc, struct loft_error *err);

/*
 * The extremes lo[k], hi[k] (k < 3) of the points of s on the plane
 * p[axis] = level (a waterline's ends and breadth): with refine, found
 * to rounding; without, the best of samples along the curve (cheaper,
 * to choose the surfaces worth refining).  Returns 0, or LOFT_EGEOM
 * when the plane misses s.
 */
int loft_clip_extremes(const struct loft_surface *s, int axis, double level,
    int refine, double *lo, double *hi);

/*
 * The largest p[k] over the points of s on both planes p[a] = la and
 * p[b] = lb (a half-breadth at a station and waterline: a = 0, b = 2,
 * k = 1), by Newton's method from a grid of seeds, to rounding.  a, b,
 * k in 0..2, a != b.  Returns 0 and *best, or LOFT_EGEOM when no point
 * of s is on both.
 */
int loft_surface_meet(const struct loft_surface *s, int a, double la, int b,
    double lb, int k, double *best);

/* ------------------------------------------------------------------ */
/* Hydrostatics of a hull of surfaces (hydro.c)                        */

/* A hull prepared by loft_hydro_init; its fields are hydro.c's. */
struct loft_hydro {
	const struct loft_surface *s;
	size_t ns;
	int whole;              /* 0: the starboard half, mirrored */
	double scale, o[3];     /* coordinates (p - o) / scale inside */
	double *box;            /* ns * 6: each surface's lo, hi */
	double *full;           /* each whole surface's moments */
	double zmin, zmax;      /* the hull's lowest and highest points */
};

/* The hydrostatics at one waterline, in the hull's units: the fields of
 * hydro(1), and am, the midship section's immersed area. */
struct loft_hydrostatics {
	double z, volume, lcb, tcb, vcb, awp, lcf, bmt, bml, kmt, kml;
	double lwl, bwl, t, cb, cp, cm, cwp, wetted, am;
};

/*
 * Prepare the ns >= 1 surfaces s (caller-owned, dim 3, x along, y
 * across, z up; whole: the whole hull, else its half y >= 0) for
 * loft_hydro_at.  Returns 0, LOFT_EINPUT (a surface not in space, or a
 * half reaching y < 0) or LOFT_ENOMEM.  Free with loft_hydro_free.
 */
int loft_hydro_init(struct loft_hydro *h, const struct loft_surface *s,
    size_t ns, int whole, struct loft_error *err);
void loft_hydro_free(struct loft_hydro *h);

/*
 * The hydrostatics of h floating at the waterline z = wl into *out: the
 * divergence theorem turns the volume, its centre and the waterplane's
 * moments into integrals over the hull below the waterline (clipped by
 * loft_clip_integrate), exact to rounding on polynomial surfaces.
 * Returns 0, or LOFT_EGEOM (the waterline at or below the hull's lowest
 * point or above its top, or the hull open below it other than at the
 * centreplane of a half) with err saying which.  Where the hull is
 * open, err->row is the index of the first surface with a side below the
 * waterline that no other surface shares (-1: none found).
 */
int loft_hydro_at(const struct loft_hydro *h, double wl,
    struct loft_hydrostatics *out, struct loft_error *err);

/* The ends x0 <= x1 of the waterline z = wl of h: 0, or LOFT_EGEOM when
 * it is below or above the hull or meets no surface. */
int loft_hydro_ends(const struct loft_hydro *h, double wl, double *x0,
    double *x1, struct loft_error *err);

/*
 * The immersed areas area[i] of the sections x = xs[i], i < n, of h
 * floating at z = wl (both sides for a half), exact to rounding on
 * polynomial surfaces: minus the integral of the x-component of the
 * normal over the hull below the waterline and aft of xs[i].  Returns 0
 * or LOFT_EGEOM as loft_hydro_at.
 */
int loft_hydro_sections(const struct loft_hydro *h, double wl,
    const double *xs, size_t n, double *area, struct loft_error *err);

#endif
