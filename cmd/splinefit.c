/*
 * splinefit: fit a fair spline through each record of knots (Manning 1973)
 * and write it as a cubic record.
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

/* Two fits whose unit tangents differ by less than this at every knot are
 * the same curve; sign-rule alternatives differ by order 1. */
#define SAME_CURVE 1e-6

/* -e: a corner splinefit found where the fit turns by less than this
 * (radians, 10 degrees) is dropped, and the points fitted without it.
 * The lines through the points either side turned by 30 degrees or
 * more, but the points bend there, and the fair curve through them is
 * all but smooth.  On the noisy glyphs of make compare-approx this drops
 * 5 of the 72 false corners and no true one; on the next 100 contours,
 * 5 of 346 false ones and 1 of the 435 true ones kept.  The fit without
 * them can leave another corner that flat (one of FreeSerif's M turned
 * by 1.4 degrees), and the drop repeats until none is, while the fit
 * passes: where spans stray (most often a tolerance below the points'
 * noise), each refit costs as much as the first and seldom mends them
 * (400 points of a random walk at a tolerance of 1.6 times their noise
 * took 5 refits and 21 s; with one, 8 s). */
#define APPROX_FLAT_TURN 0.1745

struct opts {
	struct loft_fit_opts fit;
	int start_dim, end_dim;         /* coordinates given with -S, -E */
	int verbose;
	double merge;                   /* -d, or -1: the default distance */
	double approx;                  /* -e: the tolerance, or 0 */
	int rounds;                     /* -i with -e: rounds of splitting */
	int nocorner;                   /* -C: -e finds no corners itself */
	int open_set, method_set;       /* -o, -m given: the record's closed=
	                                 * and method= are not read */
	double *seg, *other;            /* scratch, grown as records need */
	double *knots;                  /* the knots kept after merging */
	double *cornerat;               /* -e: the corners' knots found */
	unsigned char *astray;          /* -e: the segments astray */
	unsigned char *blame;           /* -e: the joints of corners to
	                                 * leave out (blame) */
	size_t *keep, *into, *corner;   /* their rows, where each row went,
	                                 * the corners */
	size_t *straight, nstraight;    /* the straight spans, 0-based */
	size_t segcap, rowcap;          /* numbers in seg; rows in keep */
};

/* -m's words, and a record's method=, in the order of enum loft_method */
static const char *const methods[] = { "manning", "ferguson", "chord",
    "fair", NULL };

static const char usage_text[] =
    "usage: splinefit [-1o] [-S tx,ty[,tz]] [-E tx,ty[,tz]] [-a alpha] "
    "[-k positive|turn]\n"
    "                 [-m fair|manning|ferguson|chord] [-t tol] [-i maxiter] "
    "[-p digits]\n"
    "                 [-v] [-d dist] [file ...]\n"
    "       splinefit -e tol [-C | -K] [-o] [-S tx,ty[,tz]] [-E tx,ty[,tz]]\n"
    "                 [-i rounds] [-p digits] [-v] [file ...]\n";

/*
 * The end tangent named key ("start" or "end"): the one -S or -E gave,
 * which must have the knots' dim (given_dim) coordinates, or else the
 * record's attribute, if it has one.
 */
static int
record_tangent(const struct loft_record *rec, const char *key, int dim,
    int given_dim, int *have, double *t, struct loft_error *err)
{
	const char *v = loft_attr(rec, key);
	int n;

	if (*have && given_dim != dim)
		return loft_fail(err, LOFT_EINPUT, -1, "the %s tangent has %d "
		    "coordinates but the knots have %d", key, given_dim, dim);
	if (*have || v == NULL)
		return 0;
	if (loft_parse_list(v, t, dim, &n, err) != 0 || n != dim)
		return loft_fail(err, LOFT_EINPUT, -1, "attribute %s=%s: want "
		    "%d numbers separated by commas", key, v, dim);
	*have = 1;
	return 0;
}

/* Room for the segments of n knots of dim coordinates, twice, and for
 * the knots, their rows and corners: each grown by its own need (a
 * record of fewer coordinates but more knots than the last needs more
 * rows, not more numbers). */
static int
grow_scratch(struct opts *o, size_t n, int dim, struct loft_error *err)
{
	size_t need = 4 * (size_t)dim * n * (n <= LOFT_FIT_SPLIT_KNOTS ?
	    LOFT_FIT_SPLIT : 1), rows = n;
	void *v;

	if (need <= o->segcap && n <= o->rowcap)
		return 0;
	need = need > o->segcap ? need : o->segcap;
	rows = rows > o->rowcap ? rows : o->rowcap;
	if ((v = realloc(o->seg, need * sizeof *o->seg)) != NULL)
		o->seg = v;
	if (v && (v = realloc(o->other, need * sizeof *o->other)) != NULL)
		o->other = v;
	if (v && (v = realloc(o->knots, LOFT_MAXDIM * rows *
	    sizeof *o->knots)) != NULL)
		o->knots = v;
	if (v && (v = realloc(o->keep, rows * sizeof *o->keep)) != NULL)
		o->keep = v;
	if (v && (v = realloc(o->into, rows * sizeof *o->into)) != NULL)
		o->into = v;
	if (v && (v = realloc(o->corner, rows * sizeof *o->corner)) != NULL)
		o->corner = v;
	if (v && (v = realloc(o->cornerat, LOFT_MAXDIM * rows *
	    sizeof *o->cornerat)) != NULL)
		o->cornerat = v;
	if (v && (v = realloc(o->straight, rows * sizeof *o->straight)) != NULL)
		o->straight = v;
	if (v && (v = realloc(o->astray, rows)) != NULL)
		o->astray = v;
	if (v && (v = realloc(o->blame, rows)) != NULL)
		o->blame = v;
	if (v == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	o->segcap = need;
	o->rowcap = rows;
	return 0;
}

/* Free what grow_scratch allocated. */
static void
free_scratch(struct opts *o)
{
	free(o->seg);
	free(o->other);
	free(o->knots);
	free(o->keep);
	free(o->into);
	free(o->corner);
	free(o->cornerat);
	free(o->astray);
	free(o->blame);
	free(o->straight);
}

/*
 * The attribute name=i,j,...: 1-based numbers from 1 to max, in
 * increasing order, into list as 0-based; their count in *nc.  what
 * names the numbers in messages, item the things they name.
 */
static int
record_list(const struct loft_record *rec, const char *name, const char *what,
    const char *item, size_t max, size_t *list, size_t *nc,
    struct loft_error *err)
{
	const char *v = loft_attr(rec, name), *s = v;
	char word[32];

	*nc = 0;
	while (v != NULL) {
		size_t len = strcspn(s, ",");
		long k;

		if (len == 0 || len >= sizeof word)
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "%s=%s: want %s numbers separated by commas", name,
			    v, what);
		memcpy(word, s, len);
		word[len] = '\0';
		if (max < 1 || loft_parse_int(word, 1, (long)max, &k, err) != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "%s=%s: '%s' is not a %s number from 1 to %zu",
			    name, v, word, what, max);
		if (*nc > 0 && (size_t)k - 1 <= list[*nc - 1])
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "%s=%s: %s %ld %s%ss in order", name, v, item, k,
			    (size_t)k - 1 == list[*nc - 1] ? "is repeated: list " :
			    "comes after a later one: list ", item);
		list[(*nc)++] = (size_t)k - 1;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	return 0;
}

/* The corners=: knot numbers. */
static int
record_corners(struct opts *o, const struct loft_record *rec, size_t *nc,
    struct loft_error *err)
{
	return record_list(rec, "corners", "knot", "corner", rec->nrows,
	    o->corner, nc, err);
}

/* The straight spans after merging: each span's first knot goes to the
 * knot it merged into, a span merged away goes. */
static void
merge_straight(struct opts *o, size_t n, size_t m, int closed)
{
	size_t c = 0;

	for (size_t j = 0; j < o->nstraight; j++) {
		size_t s = o->straight[j], a = o->into[s];
		size_t b = o->into[(s + 1) % n];

		if (a == b || (c > 0 && a <= o->straight[c - 1]) ||
		    (!closed && a + 1 >= m))
			continue;
		o->straight[c++] = a;
	}
	o->nstraight = c;
}

/*
 * Merge the knots nearer than dist into o->knots, the rows kept in
 * o->keep, the kept knot each row is in o->into; the corners follow
 * their knots.  Returns the count kept.
 */
static size_t
merge(struct opts *o, const struct loft_record *rec, int closed, double dist,
    size_t *nc)
{
	int dim = rec->ncols;
	size_t m = loft_merge_knots(rec->num, rec->nrows, dim, closed, dist,
	    o->merge < 0, o->keep, o->into), c = 0;

	for (size_t i = 0; i < m; i++)
		memcpy(o->knots + i * dim, rec->num + o->keep[i] * dim,
		    dim * sizeof *o->knots);
	/* in order but for the knots that close the curve, now knot 1 */
	for (size_t j = 0; j < *nc; j++) {
		size_t to = o->into[o->corner[j]];

		if (c == 0 || to > o->corner[c - 1]) {
			o->corner[c++] = to;
		} else if (to == 0 && o->corner[0] != 0) {
			memmove(o->corner + 1, o->corner, c * sizeof *o->corner);
			o->corner[0] = 0;
			c++;
		}
	}
	*nc = c;
	return m;
}

/*
 * The corners as the cubic's corners=: the joints, counted from 1 as the
 * knots kept (joint i is the start of segment i; an open curve's end is
 * joint nseg + 1).  Returns 0, or LOFT_ENOMEM.
 */
static int
put_list(struct loft_writer *w, const char *name, const size_t *corner,
    size_t nc, struct loft_error *err)
{
	char *buf, *p;

	if (nc == 0)
		return 0;
	if ((buf = malloc(nc * 21 + 1)) == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	p = buf;
	for (size_t j = 0; j < nc; j++)
		p += sprintf(p, "%s%zu", j > 0 ? "," : "", corner[j] + 1);
	loft_put_attr(w, name, buf);
	free(buf);
	return 0;
}

/* The notes on the knots merged, once the record is fitted. */
static void
merge_notes(struct loft_run *run, const struct loft_record *rec, size_t m,
    double dist)
{
	struct opts *o = run->ctx;

	for (size_t i = 0, k = 0; i < rec->nrows; i++) {
		size_t to = o->into[i];

		if (k < m && o->keep[k] == i) {
			k++;
			continue;
		}
		fprintf(run->msg, "splinefit: %s:%ld: knot %zu is nearer than "
		    "%.3g to knot %zu (line %ld)%s: merged into it\n", rec->file,
		    loft_row_line(rec, (long)i), i + 1, dist, o->keep[to] + 1,
		    loft_row_line(rec, (long)o->keep[to]), to == 0 && i > 0 &&
		    (k == m) ? ", closing the curve" : "");
	}
}

/* -v: the curve's bending energy, smallest radius of curvature and
 * where, and its inflexions (of a plane curve). */
static void
measures(FILE *msg, const double *seg, size_t nseg, int dim, int closed)
{
	struct loft_curve c;
	struct loft_error err;
	double energy, radius, u;
	long count;

	loft_curve_cubic(&c, seg, nseg, dim, closed);
	if (loft_curve_energy(&c, &energy, &err) == 0)
		fprintf(msg, ", bending energy %.6g", energy);
	else
		fprintf(msg, ", bending energy: %s", err.msg);
	if (loft_curve_min_radius(&c, &radius, &u, &err) != 0)
		fprintf(msg, ", smallest radius: %s", err.msg);
	else if (radius == 0)
		fprintf(msg, ", no curvature");
	else
		fprintf(msg, ", smallest radius %.6g at u = %.6g", radius, u);
	if (dim == 2 && loft_curve_inflexions(&c, &count, &err) == 0)
		fprintf(msg, ", %ld inflexion%s", count, count == 1 ? "" : "s");
}

/* -v: how the fit went, and whether the other sign rule agrees. */
static void
report(struct loft_run *run, const struct loft_record *rec, size_t n,
    const struct loft_fit_opts *fit, const struct loft_fit_info *info,
    size_t nseg)
{
	struct opts *o = run->ctx;
	struct loft_fit_opts alt = *fit;
	struct loft_fit_info ainfo;
	struct loft_error aerr;
	int dim = rec->ncols;
	char other[320] = "";

	fprintf(run->msg, "splinefit: %s:%ld: %zu knots, %d iteration%s, "
	    "converged (tangent change %.2g), curvature jump %.2g",
	    rec->file, rec->line, n, info->iterations,
	    info->iterations == 1 ? "" : "s", info->change,
	    loft_curvature_jump(o->seg, nseg, dim, fit->closed));
	measures(run->msg, o->seg, nseg, dim, fit->closed);
	if (fit->method == LOFT_MANNING) {
		alt.sign = fit->sign == LOFT_SIGN_POSITIVE ?
		    LOFT_SIGN_TURN : LOFT_SIGN_POSITIVE;
		if (loft_fit(&alt, o->knots, n, dim, o->other,
		    &ainfo, &aerr) != 0)
			snprintf(other, sizeof other, "fails (%s)", aerr.msg);
		else if (loft_tangent_distance(o->seg, o->other, nseg, dim) >
		    SAME_CURVE)
			snprintf(other, sizeof other, "reaches a DIFFERENT "
			    "curve: the knots do not decide where it goes");
		else
			snprintf(other, sizeof other, "reaches the same curve");
		fprintf(run->msg, "; the other sign rule (-k %s) %s",
		    alt.sign == LOFT_SIGN_TURN ? "turn" : "positive", other);
	}
	fputc('\n', run->msg);
}

/*
 * The cubic record of the nseg segments in o->seg, with the nc joints
 * corner[] (0-based, increasing) as its corners=.  Returns 0, or
 * LOFT_ENOMEM with nothing written.
 */
static int
put_curve(struct loft_run *run, const struct loft_record *rec, size_t nseg,
    int closed, const size_t *corner, size_t nc, struct loft_error *err)
{
	static const char *const consumed[] = { "start", "end", "closed",
	    "method", "corners", "straight", NULL };
	struct opts *o = run->ctx;
	size_t mark = run->w.len;

	loft_put_type(&run->w, "cubic");
	loft_put_attr(&run->w, "closed", closed ? "1" : "0");
	if (put_list(&run->w, "corners", corner, nc, err) != 0 ||
	    put_list(&run->w, "straight", o->straight, o->nstraight, err) !=
	    0) {
		loft_writer_cut(&run->w, mark);
		return LOFT_ENOMEM;
	}
	loft_put_attrs_except(&run->w, rec, consumed);
	loft_end_line(&run->w);
	for (size_t i = 0; i < nseg; i++)
		loft_put_row(&run->w, o->seg + i * 4 * rec->ncols,
		    4 * rec->ncols);
	loft_end_record(&run->w);
	return 0;
}

/*
 * -e: the joints of the nseg segments in o->seg that are the nc corners
 * o->corner[] of rec (loft_approx keeps each corner a knot: at the point
 * itself, or where found, at its row of o->cornerat), in o->corner as
 * joints, increasing; their count.
 */
static size_t
approx_corners(struct opts *o, const struct loft_record *rec, size_t nseg,
    size_t nc, int found)
{
	int dim = rec->ncols;
	size_t c = 0;

	for (size_t j = 0; j < nseg && nc > 0; j++)
		for (size_t k = 0; k < nc; k++)
			if (memcmp(o->seg + j * 4 * dim, found ? o->cornerat +
			    k * dim : rec->num + o->corner[k] * dim,
			    dim * sizeof *rec->num) == 0) {
				o->keep[c++] = j;
				break;
			}
	memcpy(o->corner, o->keep, c * sizeof *o->corner);
	return c;
}

/* The joint of the nseg segments in o->seg at x (a corner's knot, dim
 * numbers): the segment that starts there, or nseg where none does. */
static size_t
joint_at(const struct opts *o, size_t nseg, const double *x, int dim)
{
	size_t j = 0;

	while (j < nseg && memcmp(o->seg + j * 4 * dim, x, dim * sizeof *x))
		j++;
	return j;
}

/*
 * -e: the points fitted again with the k corners corner[] (points) at
 * at[] (their knots) only, into o->seg and *info in place of the fit
 * there, the corners into o->corner and o->cornerat and k into *nc,
 * where no more than most of the new fit's spans are astray; else
 * nothing changed.  Returns 0, or LOFT_ENOMEM.
 */
static int
approx_refit(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, const size_t *corner,
    const double *at, size_t k, size_t most,
    struct loft_approx_info *info, size_t *nc, struct loft_error *err)
{
	struct loft_approx_opts ro = *ao;
	struct loft_approx_info ri;
	struct loft_error re;
	int dim = rec->ncols, rc;
	double *seg = malloc(4 * (size_t)dim * rec->nrows * sizeof *seg);
	unsigned char *astray = malloc(rec->nrows + 1);

	if (seg == NULL || astray == NULL) {
		free(seg);
		free(astray);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	ro.astray = astray;
	ro.corner = k > 0 ? corner : NULL;
	ro.corner_at = k > 0 ? at : NULL;
	ro.ncorner = k;
	rc = loft_approx(&ro, rec->num, rec->nrows, dim, seg, &ri, &re);
	if (rc == 0 && ri.astray <= most) {
		memcpy(o->seg, seg, 4 * (size_t)dim * ri.nseg * sizeof *seg);
		memcpy(o->astray, astray, rec->nrows);
		*info = ri;
		if (k > 0) {
			memcpy(o->corner, corner, k * sizeof *corner);
			memcpy(o->cornerat, at, k * dim * sizeof *at);
		}
		*nc = k;
	}
	free(seg);
	free(astray);
	if (rc == LOFT_ENOMEM)
		return loft_fail(err, rc, -1, "out of memory");
	return 0;
}

/* Whether the corner at joint j of the nseg segments in o->seg is flat:
 * the fit turns by less than APPROX_FLAT_TURN there. */
static int
flat_at(const struct opts *o, size_t nseg, int dim, int closed, size_t j)
{
	return loft_joint_turn(o->seg, nseg, dim, closed, j) < APPROX_FLAT_TURN;
}

/* Whether the corner at joint j of the nseg segments in o->seg is at an
 * end of a segment astray (o->astray). */
static int
astray_at(const struct opts *o, size_t nseg, int dim, int closed, size_t j)
{
	(void)dim;
	return o->astray[j] || o->astray[j > 0 ? j - 1 : closed ? nseg - 1 :
	    j];
}

/* Whether joint j is marked in o->blame. */
static int
blamed_at(const struct opts *o, size_t nseg, int dim, int closed, size_t j)
{
	(void)nseg, (void)dim, (void)closed;
	return o->blame[j];
}

/* The joints between segment s of nseg and joint j: 0 where j is one
 * of its ends (s or s + 1), the shorter way round a closed curve. */
static size_t
joints_off(size_t s, size_t j, size_t nseg, int closed)
{
	size_t d = j <= s ? s - j : j - s - 1;

	return closed && nseg - 1 - d < d ? nseg - 1 - d : d;
}

/* Mark in o->blame the joints of those of the nc corners found (their
 * knots at o->cornerat) nearest each segment astray of the nseg, the
 * joints along the curve between them fewest; returns how many
 * segments astray have none at their ends. */
static size_t
blame(struct opts *o, size_t nseg, int dim, int closed, size_t nc)
{
	size_t *at = o->keep, off = 0;  /* free here: the corners' joints */

	memset(o->blame, 0, nseg);
	for (size_t c = 0; c < nc; c++)
		at[c] = joint_at(o, nseg, o->cornerat + c * dim, dim);
	for (size_t s = 0; s < nseg; s++) {
		size_t least = (size_t)-1;

		for (size_t c = 0; o->astray[s] && c < nc; c++)
			if (at[c] < nseg &&
			    joints_off(s, at[c], nseg, closed) < least)
				least = joints_off(s, at[c], nseg, closed);
		for (size_t c = 0; o->astray[s] && c < nc; c++)
			if (at[c] < nseg &&
			    joints_off(s, at[c], nseg, closed) == least)
				o->blame[at[c]] = 1;
		off += least > 0 && least != (size_t)-1;
	}
	return off;
}

/*
 * -e: the fit with those of the nc corners splinefit found where drop()
 * says so (at their joints) left out, or where pin is set kept with
 * their knots at their points (not where the lines either side meet),
 * in place of the fit there (approx_refit), where no more than most of
 * its spans are astray.  A corner that is no joint, or at an open
 * curve's start, is kept as it is.  No fit is tried where fewer than
 * fewest corners are left, or where nothing changes.  Returns 0, or
 * LOFT_ENOMEM.
 */
static int
approx_without(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, int (*drop)(const struct opts *,
    size_t, int, int, size_t), int pin, size_t fewest, size_t most,
    struct loft_approx_info *info, size_t *nc, struct loft_error *err)
{
	int dim = rec->ncols, rc = 0;
	size_t k = 0, moved = 0, *corner = malloc((*nc + 1) * sizeof *corner);
	double *at = malloc((*nc + 1) * dim * sizeof *at);

	for (size_t c = 0; corner != NULL && at != NULL && c < *nc; c++) {
		size_t j = joint_at(o, info->nseg, o->cornerat + c * dim, dim);
		const double *x = o->cornerat + c * dim;

		if (j < info->nseg && (j > 0 || ao->closed) &&
		    drop(o, info->nseg, dim, ao->closed, j)) {
			if (!pin)
				continue;
			x = rec->num + o->corner[c] * dim;
			moved += memcmp(x, o->cornerat + c * dim,
			    dim * sizeof *x) != 0;
		}
		corner[k] = o->corner[c];
		memcpy(at + k++ * dim, x, dim * sizeof *at);
	}
	if (corner == NULL || at == NULL)
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	else if ((k < *nc || moved > 0) && k >= fewest)
		rc = approx_refit(o, rec, ao, corner, at, k, most, info, nc,
		    err);
	free(corner);
	free(at);
	return rc;
}

/* A corner found falsely pins a knot the curve may loop about, astray
 * on the spans either side; where more spans than this many for each
 * corner are astray, the corners are not what leaves the fit astray
 * (most often the tolerance is below the points' noise), and no fit
 * without some of them is tried: none would pass, and they cost as
 * much as the first (7 s of 14 on 400 points off a pentagon, with
 * noise of 1.25 times the tolerance). */
#define APPROX_BLAME 2

/*
 * -e, where the corners splinefit found leave a fit that strays from the
 * points or crosses itself (info->astray spans fail the check both
 * ways): the first that passes both checks, in its stead, of the fit
 * with the knots of those at the ends of the segments astray at their
 * points (among sparse noisy points the lines either side of a true
 * corner can meet off it, by more than the curve can follow), the fit
 * without those corners (approx_without), the fit without those
 * nearest each segment astray (where a segment astray has none at its
 * ends), and the fit without any (a false corner among sparse noisy
 * points can pin a knot the curve loops about; the others are most
 * often true).  Returns 0, or LOFT_ENOMEM.
 */
static int
approx_smooth(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, struct loft_approx_info *info,
    size_t *nc, struct loft_error *err)
{
	size_t n0 = *nc;

	if (info->astray > APPROX_BLAME * n0)
		return 0;
	if (approx_without(o, rec, ao, astray_at, 1, 1, 0, info, nc,
	    err) != 0)
		return LOFT_ENOMEM;
	if (info->astray == 0)
		return 0;
	if (approx_without(o, rec, ao, astray_at, 0, 1, 0, info, nc,
	    err) != 0)
		return LOFT_ENOMEM;
	if (*nc < n0)
		return 0;
	if (blame(o, info->nseg, rec->ncols, ao->closed, n0) > 0) {
		if (approx_without(o, rec, ao, blamed_at, 0, 1, 0, info, nc,
		    err) != 0)
			return LOFT_ENOMEM;
		if (*nc < n0)
			return 0;
	}
	return approx_refit(o, rec, ao, NULL, NULL, 0, 0, info, nc, err);
}

/* Where the fit written has spans astray, the points' noise (about
 * the standard deviation) is named when the tolerance is below this
 * many times it: 4 or 5 times suits. */
#define APPROX_NOISE_HINT 3

/* -e: a fit written with spans astray (info) says so, and names the
 * points' noise where the tolerance is below APPROX_NOISE_HINT times
 * it. */
static void
astray_note(struct loft_run *run, const struct loft_record *rec,
    const struct loft_approx_info *info, double tol, int closed)
{
	double s = loft_points_noise(rec->num, rec->nrows, rec->ncols,
	    closed);

	fprintf(run->msg, "splinefit: %s:%ld: %zu span%s astray: the curve "
	    "strays from the points or crosses itself there", rec->file,
	    rec->line, info->astray, info->astray == 1 ? "" : "s");
	if (tol < APPROX_NOISE_HINT * s)
		fprintf(run->msg, "; the tolerance %g is less than %d times "
		    "the points' noise (about %.3g)", tol, APPROX_NOISE_HINT, s);
	fputc('\n', run->msg);
}

/* -e: the fit without corners, into o->seg and *info, where the fit
 * with those splinefit found fails the tolerance (*rc LOFT_ENOCONV,
 * *err its error): on sparse clean points a bend can read as corners,
 * their knots out where the lines either side meet, off the points (20
 * points round a circle of radius 50 gave four, 10 off it).  *rc
 * becomes 0 where it meets it, LOFT_ENOMEM (and *err says so) where
 * memory ran out; the first error stands otherwise.  Returns whether
 * the fit without corners is taken. */
static int
approx_cornerless(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, struct loft_approx_info *info,
    int *rc, struct loft_error *err)
{
	struct loft_approx_opts no = *ao;
	struct loft_error e;
	int r;

	no.corner = NULL;
	no.corner_at = NULL;
	no.ncorner = 0;
	r = loft_approx(&no, rec->num, rec->nrows, rec->ncols, o->seg, info,
	    &e);
	if (r == 0 || r == LOFT_ENOMEM) {
		*rc = r;
		if (r != 0)
			*err = e;
	}
	return r == 0;
}

/* A corner of sparse points (approx_sharp) is where their polyline
 * turns by this much at a point (radians, 40 degrees): more than ten
 * points round a circle turn at each (36). */
#define APPROX_SHARP_TURN 0.698

/* The fit with those corners is taken where it has at most this many
 * inflexions more than the points' polyline: a smooth curve through
 * points turning one way between two reflex corners may swing once
 * between them; one through points noisier than the tolerance swings
 * at every few (30 points round an ellipse 86 by 34, noise 0.58,
 * tolerance 0.3: 16 against the points' 6). */
#define APPROX_SHARP_FLEX 2

/* The inflexions of the nseg segments in o->seg (plane). */
static long
fit_inflexions(const struct opts *o, size_t nseg, int closed)
{
	struct loft_curve c;
	struct loft_error err;
	long count = 0;

	loft_curve_cubic(&c, o->seg, nseg, 2, closed);
	return loft_curve_inflexions(&c, &count, &err) == 0 ? count : -1;
}

/* The points of the plane record rec where its polyline turns by
 * APPROX_SHARP_TURN or more (loft_sharp_points) into corner, the points
 * themselves into at (room for rec->nrows each), and how often its
 * turns change sign into *flex; returns how many, or (size_t)-1 out of
 * memory. */
static size_t
sharp_corners(const struct loft_record *rec, int closed, size_t *corner,
    double *at, size_t *flex)
{
	size_t k = loft_sharp_points(rec->num, rec->nrows, closed,
	    APPROX_SHARP_TURN, corner, flex);

	for (size_t c = 0; k != (size_t)-1 && c < k; c++)
		memcpy(at + 2 * c, rec->num + 2 * corner[c], 2 * sizeof *at);
	return k;
}

/*
 * -e in the plane, where the fits with and without the corners found
 * fail the tolerance: the fit with a corner at each point where the
 * points' polyline turns sharply (loft_sharp_points), at the point.
 * Among sparse points (a few a stroke of a letter) a corner lies
 * between two of them, where the search for corners, which needs
 * several points either side, finds none, and a smooth curve rounds it
 * with a swing the tolerance does not allow: 7 of 51 glyph contours of
 * 14 to 50 points failed so.  Not where the polyline's turns change
 * sign at more than half the points (noise turns them), and taken
 * only where the fit has at most APPROX_SHARP_FLEX inflexions more than
 * the polyline.  As approx_cornerless (*rc and *err); returns the
 * corners (into o->corner, their points into o->cornerat), 0 where
 * none is taken.
 */
static size_t
approx_sharp(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, struct loft_approx_info *info,
    int *rc, struct loft_error *err)
{
	struct loft_approx_opts so = *ao;
	struct loft_error e;
	size_t flex, k;
	int r;

	if (rec->ncols != 2)
		return 0;
	k = sharp_corners(rec, ao->closed, o->corner, o->cornerat, &flex);
	if (k == (size_t)-1) {
		*rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		return 0;
	}
	if (k == 0 || 2 * flex > rec->nrows)
		return 0;
	so.corner = o->corner;
	so.corner_at = o->cornerat;
	so.ncorner = k;
	r = loft_approx(&so, rec->num, rec->nrows, 2, o->seg, info, &e);
	if (r == LOFT_ENOMEM) {
		*rc = r;
		*err = e;
	}
	if (r != 0 || fit_inflexions(o, info->nseg, ao->closed) >
	    (long)flex + APPROX_SHARP_FLEX)
		return 0;
	*rc = 0;
	return k;
}

/* -e: the corners found (*nc of them) where the fit (info) turns by less
 * than APPROX_FLAT_TURN dropped, one round after another, while the
 * fit without them has no more spans astray (approx_without); not past
 * a round whose fit has spans astray.  Returns 0, or LOFT_ENOMEM. */
static int
drop_flat(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, struct loft_approx_info *info,
    size_t *nc, struct loft_error *err)
{
	for (size_t was = *nc + 1; *nc > 0 && *nc < was;) {
		was = *nc;
		if (approx_without(o, rec, ao, flat_at, 0, 0, info->astray, info,
		    nc, err) != 0)
			return LOFT_ENOMEM;
		if (info->astray > 0)    /* see APPROX_FLAT_TURN */
			break;
	}
	return 0;
}

/*
 * -e in the plane, where the fit to be written still strays from the
 * points or crosses itself (info->astray spans) after approx_smooth:
 * the fit with a corner at each point where the points' polyline turns
 * sharply (loft_sharp_points, at the point), in its stead where fewer
 * of its spans are astray (approx_refit).  Among sparse points (a few
 * a serif) the corners found, or none, leave a smooth curve to swing
 * round a serif's end between two points, far out past the others:
 * 13 of make compare-approx's 100 glyph contours sampled at 120 points
 * were written astray so, 11 crossing themselves; none is now.  No
 * test of the turns' signs, as approx_sharp makes: a loop is worse
 * than a corner too many.  Returns 0, or LOFT_ENOMEM.
 */
static int
approx_sharp_astray(struct opts *o, const struct loft_record *rec,
    const struct loft_approx_opts *ao, struct loft_approx_info *info,
    size_t *nc, struct loft_error *err)
{
	size_t flex, k = 0, *corner = malloc(rec->nrows * sizeof *corner);
	double *at = malloc(2 * rec->nrows * sizeof *at);
	int rc = 0;

	if (corner == NULL || at == NULL ||
	    (k = sharp_corners(rec, ao->closed, corner, at, &flex)) ==
	    (size_t)-1)
		rc = loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	else if (k > 0)
		rc = approx_refit(o, rec, ao, corner, at, k, info->astray - 1,
		    info, nc, err);
	free(corner);
	free(at);
	return rc;
}

/* -e: the fair curve within o->approx of the points (loft_approx). */
static int
approx_record(struct loft_run *run, const struct loft_record *rec,
    const struct loft_fit_opts *fit, size_t nc, struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_approx_opts ao;
	struct loft_approx_info info;
	int rc, dim = rec->ncols, found = nc == 0 && !o->nocorner;
	size_t astray;

	loft_approx_defaults(&ao);
	ao.tol = o->approx;
	ao.closed = fit->closed;
	ao.have_start = fit->have_start;
	ao.have_end = fit->have_end;
	memcpy(ao.start, fit->start, sizeof ao.start);
	memcpy(ao.end, fit->end, sizeof ao.end);
	if (found) {    /* none given: its own, at their places */
		nc = loft_find_corners(rec->num, rec->nrows, dim, fit->closed,
		    o->approx, o->corner, o->cornerat);
		if (nc == (size_t)-1)
			return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		ao.corner_at = o->cornerat;
	}
	ao.corner = o->corner;
	ao.ncorner = nc;
	ao.astray = o->astray;
	if (o->rounds > 0)
		ao.maxround = o->rounds;
	if ((rc = loft_approx(&ao, rec->num, rec->nrows, dim, o->seg, &info,
	    err)) == LOFT_ENOCONV && found && nc > 0 &&
	    approx_cornerless(o, rec, &ao, &info, &rc, err))
		nc = 0;
	if (rc == LOFT_ENOCONV && found)
		nc = approx_sharp(o, rec, &ao, &info, &rc, err);
	if (rc != 0)
		return rc;
	if (found && drop_flat(o, rec, &ao, &info, &nc, err) != 0)
		return LOFT_ENOMEM;
	if (found && nc > 0 && info.astray > 0 &&
	    approx_smooth(o, rec, &ao, &info, &nc, err) != 0)
		return LOFT_ENOMEM;
	if (found && dim == 2 && (astray = info.astray) > 0 &&
	    (approx_sharp_astray(o, rec, &ao, &info, &nc, err) != 0 ||
	    (info.astray < astray &&
	    drop_flat(o, rec, &ao, &info, &nc, err) != 0)))
		return LOFT_ENOMEM;
	if (o->verbose) {
		fprintf(run->msg, "splinefit: %s:%ld: %zu points, %zu knots "
		    "kept, largest distance %.3g (tolerance %g) from the point "
		    "of line %ld", rec->file, rec->line, rec->nrows,
		    info.nknots, info.dist, o->approx,
		    loft_row_line(rec, (long)info.where));
		if (info.astray > 0)
			fprintf(run->msg, ", %zu span%s astray", info.astray,
			    info.astray == 1 ? "" : "s");
		measures(run->msg, o->seg, info.nseg, dim, fit->closed);
		fputc('\n', run->msg);
	}
	if (info.astray > 0)
		astray_note(run, rec, &info, o->approx, fit->closed);
	nc = approx_corners(o, rec, info.nseg, nc, found);
	return put_curve(run, rec, info.nseg, fit->closed, o->corner, nc, err);
}

/*
 * A knot record's closed= and method= (loftplot -i saves its knots with
 * them), where -o and -m did not say: into fit.  0, or LOFT_EINPUT.
 */
static int
record_fit(const struct opts *o, const struct loft_record *rec,
    struct loft_fit_opts *fit, struct loft_error *err)
{
	const char *c = loft_attr(rec, "closed"), *m = loft_attr(rec, "method");
	int word;

	if (!o->open_set && c != NULL) {
		if (strcmp(c, "0") != 0 && strcmp(c, "1") != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "closed=%s: want 0 or 1", c);
		fit->closed = c[0] == '1';
	}
	if (!o->method_set && o->approx == 0 && m != NULL) {
		if (loft_parse_word(m, methods, &word, err) != 0)
			return loft_fail(err, LOFT_EINPUT, -1, "attribute "
			    "method=%s: want fair, manning, ferguson or chord", m);
		fit->method = word;
	}
	return 0;
}

static int
fit_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct opts *o = run->ctx;
	struct loft_fit_opts fit = o->fit;
	struct loft_fit_info info;
	int dim = rec->ncols, rc;
	size_t n = rec->nrows, nseg, m, nc;
	double dist;

	if (!loft_record_is(rec, LOFT_KIND_KNOTS))
		return loft_fail(err, LOFT_EINPUT, -1, "%s record: splinefit "
		    "reads knots (point records)", rec->type);
	if (n == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "record has no knots");
	if (dim < 2 || dim > LOFT_MAXDIM)
		return loft_fail(err, LOFT_EINPUT, 0, "knots have %d "
		    "coordinate%s; 2 or 3 are needed", dim, dim == 1 ? "" : "s");
	if (record_fit(o, rec, &fit, err) != 0)
		return LOFT_EINPUT;
	if (!fit.closed &&
	    (record_tangent(rec, "start", dim, o->start_dim, &fit.have_start,
	    fit.start, err) != 0 ||
	    record_tangent(rec, "end", dim, o->end_dim, &fit.have_end,
	    fit.end, err) != 0))
		return LOFT_EINPUT;
	if (grow_scratch(o, n, dim, err) != 0)
		return LOFT_ENOMEM;
	if (record_corners(o, rec, &nc, err) != 0)
		return LOFT_EINPUT;
	o->nstraight = 0;
	if (o->approx > 0)
		return approx_record(run, rec, &fit, nc, err);
	dist = o->merge >= 0 ? o->merge : loft_merge_distance(rec->num, n, dim);
	m = merge(o, rec, fit.closed, dist, &nc);
	if (m < n && m < (fit.closed ? LOFT_MIN_CLOSED : LOFT_MIN_OPEN))
		return loft_fail(err, LOFT_EGEOM, -1, "%zu knot%s left after "
		    "merging knots nearer than %.3g: a%s curve needs at least "
		    "%d", m, m == 1 ? "" : "s", dist, fit.closed ? " closed" :
		    "n open", fit.closed ? LOFT_MIN_CLOSED : LOFT_MIN_OPEN);
	if (record_list(rec, "straight", "span", "straight span", fit.closed ?
	    n : n - 1, o->straight, &o->nstraight, err) != 0)
		return LOFT_EINPUT;
	merge_straight(o, n, m, fit.closed);
	fit.corner = o->corner;
	fit.ncorner = nc;
	fit.straight = o->straight;
	fit.nstraight = o->nstraight;
	fit.split = fit.split && n <= LOFT_FIT_SPLIT_KNOTS; /* seg's room */
	if ((rc = loft_fit(&fit, o->knots, m, dim, o->seg, &info, err)) != 0) {
		if (err->row >= 0 && (size_t)err->row < m)
			err->row = (long)o->keep[err->row];
		return rc;
	}
	nseg = info.nseg;
	merge_notes(run, rec, m, dist);
	if (o->verbose)
		report(run, rec, m, &fit, &info, nseg);
	if (put_curve(run, rec, nseg, fit.closed, o->corner, nc, err) != 0)
		return LOFT_ENOMEM;
	return 0;
}

static void
parse_vector(int c, const char *arg, double *v, int *have, int *dim)
{
	struct loft_error err;

	if (loft_parse_list(arg, v, LOFT_MAXDIM, dim, &err) != 0)
		loft_usage_error(usage_text, c, err.msg);
	if (*dim >= 2 && v[0] == 0 && v[1] == 0 && (*dim == 2 || v[2] == 0)) {
		snprintf(err.msg, sizeof err.msg, "'%s': a direction cannot be "
		    "zero", arg);
		loft_usage_error(usage_text, c, err.msg);
	}
	if (*dim < 2) {
		snprintf(err.msg, sizeof err.msg, "'%s': want 2 or 3 numbers "
		    "separated by commas", arg);
		loft_usage_error(usage_text, c, err.msg);
	}
	*have = 1;
}

/* -e TOL: a positive number */
static int
parse_tolerance(const char *arg, double *tol, struct loft_error *err)
{
	if (loft_parse_real(arg, 0, DBL_MAX, tol, err) != 0)
		return LOFT_EINPUT;
	if (*tol > 0)
		return 0;
	return loft_fail(err, LOFT_EINPUT, -1, "'%s': want a positive "
	    "number (the largest distance from a point to the curve)", arg);
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	static const char *const signs[] = { "positive", "turn", NULL };
	struct opts o = { .merge = -1 };
	struct loft_run run = { .prog = "splinefit", .out = stdout,
	    .msg = stderr, .handle = fit_record, .ctx = &o };
	struct loft_error err;
	int c, status, rc = 0, word, fitting = 0, corners = 0;
	long whole;

	loft_fit_defaults(&o.fit);
	o.fit.split = 1;
	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "1oS:E:a:k:m:t:i:p:d:e:CKvh")) != -1) {
		switch (c) {
		case '1': o.fit.split = 0; fitting = c; break;
		case 'o': o.fit.closed = 0; o.open_set = 1; break;
		case 'S': parse_vector(c, optarg, o.fit.start,
		    &o.fit.have_start, &o.start_dim); break;
		case 'E': parse_vector(c, optarg, o.fit.end, &o.fit.have_end,
		    &o.end_dim); break;
		case 'a': rc = loft_parse_real(optarg, 0.5, 1, &o.fit.alpha,
		    &err); fitting = c; break;
		case 'k': rc = loft_parse_word(optarg, signs, &word, &err);
		    o.fit.sign = word; fitting = c; break;
		case 'm': rc = loft_parse_word(optarg, methods, &word, &err);
		    o.fit.method = word; o.method_set = 1; fitting = c; break;
		case 't': rc = loft_parse_real(optarg, 1e-15, 1, &o.fit.tol,
		    &err); break;
		case 'i': rc = loft_parse_int(optarg, 1, 1000000, &whole, &err);
		    o.fit.maxiter = o.rounds = whole; break;
		case 'p': rc = loft_opt_digits(optarg, &run.w, &err); break;
		case 'd': rc = loft_parse_real(optarg, 0, DBL_MAX, &o.merge,
		    &err); fitting = c; break;
		case 'e': rc = parse_tolerance(optarg, &o.approx, &err); break;
		case 'C': o.nocorner = 1; corners = c; break;
		case 'K': o.nocorner = 0; corners = c; break;
		case 'v': o.verbose = 1; break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
		if (rc != 0)
			loft_usage_error(usage_text, c, err.msg);
	}
	if (o.fit.closed && (o.fit.have_start || o.fit.have_end))
		loft_usage_error(usage_text, 0, "-S and -E give the ends of "
		    "an open curve: use them with -o");
	if (o.approx > 0 && fitting)
		loft_usage_error(usage_text, fitting, "chooses how to fit through "
		    "knots: -e approximates, by the fair curve");
	if (corners && !(o.approx > 0))
		loft_usage_error(usage_text, corners, "says whether -e finds "
		    "corners in the points: use it with -e");
	status = loft_run_files(&run, argc - optind, argv + optind);
	free_scratch(&o);
	return status;
}
#endif
