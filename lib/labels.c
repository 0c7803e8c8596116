/*
 * labels.c: where a picture's labels go, clear of its lines and of each
 * other (loftplot -l; issue 22 moved it here from cmd/loftplot.c, on the
 * grid of grid.c).  The caller gives each label its record, its width,
 * and points of its record's curve; the lines as segments, each with
 * its record.  Each look is at a few cells of two grids, the labels'
 * and the lines', so the time grows with the number of labels and
 * segments, not with their product (issue 28).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "loft.h"

/* Where a label may move from a point of its curve, in half font
 * heights across and up, nearest first: NEAR_REACH of them each way (a
 * line and a half), near enough to read as that curve's label. */
#define NEAR_REACH 3
#define NSPOT ((2 * NEAR_REACH + 1) * (2 * NEAR_REACH + 1))
/* A label tied by a leader line goes out to the right of its rightmost
 * point, up to LEADER_REACH half heights (24 lines: past a graded set's
 * other outlines) and LEADER_RISE up or down. */
#define LEADER_REACH 48
#define LEADER_RISE 6
#define NLEADSPOT ((LEADER_REACH + 1) * (2 * LEADER_RISE + 1))
/* The gap a label keeps from every line: 0.15 of its height, 2 pixels
 * of loftplot's 13. */
#define GAP 0.15

/* A label of the last resort moved down this many lines is in a crowd
 * (thousands of records over one spot): walking down past every label
 * of the crowd would make the placement quadratic in the labels.  It
 * goes instead on a shelf below the picture, where labels stand left to
 * right in rows: found in constant time, and the picture grows by a
 * line per row of them, not per label (issue 28). */
#define LAST_MOVES 32

/* Any record, for lines_meet. */
#define ANYREC (-2)

struct box {
	double lo[2], hi[2];
};

/* What the labels keep clear of: the lines, then the leaders placed
 * (from nlines on), as segments with their records, in a grid of cells
 * a font high each way.  A line drawn again by another record (a pile
 * of the same outline) is filed once, marked multi: a cell of a
 * thousand copies would make every look at it a thousand. */
struct lines {
	double (*seg)[4];
	int *rec;
	unsigned char *multi;   /* the line is other records' too */
	size_t n, cap, nlines;
	struct loft_grid g;
};

/* The state of one placement. */
struct place {
	struct loft_label *lb;
	size_t n;
	double font;
	struct box *placed;     /* the boxes of labels 0..i-1 */
	struct loft_grid g;     /* their grid */
	struct lines o;
	const double *seg;      /* the caller's lines */
	const int *segrec;
	size_t nseg;
	struct byrec { int rec; size_t k; } *byrec;     /* their indices by
	                                                 * record, then index */
	struct loft_grid own;   /* the lines of the label being placed */
	double origin[2];       /* of the grids */
	struct stack { double x, y, at; } *stack;       /* last_resort's */
	size_t nstack;          /* a power of two */
	double bottom;          /* the lowest of the frame and the labels */
	double left, right;     /* the frame's sides */
	double shelf_y, shelf_x;        /* the shelf's row and next spot */
	int shelf;              /* a shelf is begun */
	int spot[NSPOT][2], lead[NLEADSPOT][2];
};

void
loft_label_box(const struct loft_label *l, double font, double *lo, double *hi)
{
	lo[0] = l->centred || l->oncurve ? l->at[0] - l->width / 2 :
	    l->at[0] + font / 2;
	lo[1] = l->at[1] - font / 2;
	hi[0] = lo[0] + l->width;
	hi[1] = lo[1] + font;
}

void
loft_label_leader(const struct loft_label *l, double *sg)
{
	for (int k = 0; k < 2; k++) {
		sg[k] = l->anchor[k];
		sg[2 + k] = fmin(fmax(l->anchor[k], l->lo[k]), l->hi[k]);
	}
}

static void
set_box(struct place *p, struct loft_label *l, struct box *b)
{
	loft_label_box(l, p->font, b->lo, b->hi);
}

static int
overlap(const struct box *a, const struct box *b)
{
	return a->lo[0] < b->hi[0] && b->lo[0] < a->hi[0] &&
	    a->lo[1] < b->hi[1] && b->lo[1] < a->hi[1];
}

static void
widen(struct box *b, const struct box *a, double by)
{
	*b = *a;
	b->lo[0] -= by;
	b->lo[1] -= by;
	b->hi[0] += by;
	b->hi[1] += by;
}

/* ---- queries ---------------------------------------------------------- */

struct first_q {
	const struct place *p;
	const struct box *b;
	size_t first;
};

static int
first_visit(void *ctx, size_t id)
{
	struct first_q *q = ctx;

	if (id < q->first && overlap(q->b, &q->p->placed[id]))
		q->first = id;
	return 0;
}

/* The first label placed (lowest index) whose box overlaps b, or
 * (size_t)-1 if none does. */
static size_t
first_label(const struct place *p, const struct box *b)
{
	struct first_q q = { p, b, (size_t)-1 };

	loft_grid_each(&p->g, b->lo, b->hi, first_visit, &q);
	return q.first;
}

struct hit_q {
	const struct lines *o;
	const struct box *b;
	int rec, own;
};

static int
hit_visit(void *ctx, size_t id)
{
	const struct hit_q *q = ctx;

	return (q->o->rec[id] != q->rec || q->o->multi[id]) &&
	    loft_segment_meets_box(q->o->seg[id], q->b->lo, q->b->hi);
}

/* Whether a segment of another record than rec meets b; any segment:
 * rec = ANYREC. */
static int
lines_meet(const struct lines *o, const struct box *b, int rec)
{
	struct hit_q q = { o, b, rec, 0 };

	return loft_grid_each(&o->g, b->lo, b->hi, hit_visit, &q);
}

struct own_q {
	const double *seg;
	const struct box *b;
};

static int
own_visit(void *ctx, size_t id)
{
	const struct own_q *q = ctx;

	return loft_segment_meets_box(q->seg + 4 * id, q->b->lo, q->b->hi);
}

/* Whether a line of the label being placed meets b (p->own). */
static int
own_meets(const struct place *p, const struct box *b)
{
	struct own_q q = { p->seg, b };

	return loft_grid_each(&p->own, b->lo, b->hi, own_visit, &q);
}

struct cross_q {
	const struct place *p;
	const double *sg;
};

static int
label_visit(void *ctx, size_t id)
{
	const struct cross_q *q = ctx;

	return loft_segment_meets_box(q->sg, q->p->placed[id].lo,
	    q->p->placed[id].hi);
}

static int
leader_visit(void *ctx, size_t id)
{
	const struct cross_q *q = ctx;

	return id >= q->p->o.nlines &&
	    loft_segments_cross(q->sg, q->p->o.seg[id]);
}

/* Whether the leader sg crosses a placed label's box or an earlier
 * leader: crossed leaders tangle a row of labels out of the order of
 * their curves. */
static int
leader_blocked(const struct place *p, const double *sg)
{
	struct cross_q q = { p, sg };

	return loft_grid_each_along(&p->g, sg, label_visit, &q) ||
	    loft_grid_each_along(&p->o.g, sg, leader_visit, &q);
}

static int
add_line(struct lines *o, const double *sg, int rec)
{
	if (o->n == o->cap) {
		size_t cap = o->cap ? 2 * o->cap : 256;
		void *s = realloc(o->seg, cap * sizeof *o->seg), *r;

		if (s == NULL)
			return LOFT_ENOMEM;
		o->seg = s;
		if ((r = realloc(o->rec, cap * sizeof *o->rec)) == NULL)
			return LOFT_ENOMEM;
		o->rec = r;
		if ((r = realloc(o->multi, cap)) == NULL)
			return LOFT_ENOMEM;
		o->multi = r;
		o->cap = cap;
	}
	memcpy(o->seg[o->n], sg, sizeof o->seg[0]);
	o->rec[o->n] = rec;
	o->multi[o->n] = 0;
	return loft_grid_add_segment(&o->g, sg, o->n++);
}

/* ---- the same line twice ---------------------------------------------- */

/* A table of the lines filed, by their four numbers: slot + 1, 0 empty. */
struct seen {
	size_t *slot, size;
};

static size_t
seen_hash(const double *sg, size_t size)
{
	uint64_t h = 1469598103934665603u;

	for (int k = 0; k < 4; k++) {
		double x = sg[k] + 0.0;         /* -0 as 0: the same point */
		uint64_t b;

		memcpy(&b, &x, sizeof b);
		h = (h ^ b) * 1099511628211u;
		h ^= h >> 29;
	}
	return (size_t)h & (size - 1);
}

/* The line filed before with the four numbers of sg, or (size_t)-1
 * (and sg's index k is noted). */
static size_t
seen_before(struct seen *t, const struct lines *o, const double *sg,
    size_t k)
{
	size_t h = seen_hash(sg, t->size);

	for (; t->slot[h] != 0; h = (h + 1) & (t->size - 1)) {
		const double *q = o->seg[t->slot[h] - 1];

		if (q[0] == sg[0] && q[1] == sg[1] && q[2] == sg[2] &&
		    q[3] == sg[3])
			return t->slot[h] - 1;
	}
	t->slot[h] = k + 1;
	return (size_t)-1;
}

/* File the caller's nseg lines, each distinct one once. */
static int
file_lines(struct place *p)
{
	struct seen t = { NULL, 64 };
	int rc = 0;

	while (t.size < 2 * p->nseg)
		t.size *= 2;
	if ((t.slot = calloc(t.size, sizeof *t.slot)) == NULL)
		return LOFT_ENOMEM;
	for (size_t k = 0; k < p->nseg && rc == 0; k++) {
		const double *sg = p->seg + 4 * k;
		size_t r = seen_before(&t, &p->o, sg, p->o.n);

		if (r == (size_t)-1)
			rc = add_line(&p->o, sg, p->segrec[k]);
		else if (p->o.rec[r] != p->segrec[k])
			p->o.multi[r] = 1;
	}
	free(t.slot);
	return rc;
}

/* ---- placing ---------------------------------------------------------- */

/*
 * Try to put label l by one of its first nanc anchors, at a spot of
 * spot[0..nspot) (nearest first): its box, widened by the gap, must
 * meet no line and no label placed before it; with strict 1, its own
 * record's line must come within near of it and no other record's
 * within far (twice as far), so that it reads as its own record's even
 * where the curves converge (a graded set at its heel); with strict 2,
 * no line at all within far, for a label in the open, tied to its
 * curve by a leader.  1: placed (box in *b).  *open is set where a
 * spot meets no line and no label (one strict 0 would take).
 */
static int
try_spots(struct place *p, struct loft_label *l, int nanc,
    const int (*spot)[2], int nspot, int strict, struct box *b, int *open)
{
	double font = p->font, near = font, far = 2 * near, sg[4];
	struct box w;

	for (int a = 0; a < nanc; a++)
		for (int k = 0; k < nspot; k++) {
			l->at[0] = l->anc[a][0] + spot[k][0] * font / 2;
			l->at[1] = l->anc[a][1] + spot[k][1] * font / 2;
			set_box(p, l, b);
			if (first_label(p, b) != (size_t)-1)
				continue;
			widen(&w, b, GAP * font);
			if (lines_meet(&p->o, &w, ANYREC))
				continue;
			*open = 1;      /* a spot strict 0 would take */
			if (strict == 0)
				return 1;
			widen(&w, b, far);
			if (lines_meet(&p->o, &w, strict == 1 ? l->rec : ANYREC))
				continue;
			memcpy(l->lo, b->lo, sizeof l->lo);
			memcpy(l->hi, b->hi, sizeof l->hi);
			if (strict == 2 && (loft_label_leader(l, sg),
			    leader_blocked(p, sg)))
				continue;
			widen(&w, b, near);
			if (strict == 1 && !own_meets(p, &w))
				continue;
			return 1;
		}
	return 0;
}

/*
 * Try to put label l on its own curve, centred on one of its anchors,
 * as a contour line's height sits in a gap of its line: its box,
 * widened by the gap, must meet no other record's line and no label
 * placed before it.  1: placed (box in *b).
 */
static int
try_on_curve(struct place *p, struct loft_label *l, struct box *b)
{
	struct box w;

	l->oncurve = 1;
	for (int a = 0; a < l->nanc; a++) {
		l->at[0] = l->anc[a][0];
		l->at[1] = l->anc[a][1];
		set_box(p, l, b);
		widen(&w, b, GAP * p->font);
		if (first_label(p, b) == (size_t)-1 &&
		    !lines_meet(&p->o, &w, l->rec))
			return 1;
	}
	l->oncurve = 0;
	return 0;
}

static int
nearer(const void *pa, const void *pb)
{
	const int *a = pa, *b = pb;
	int da = a[0] * a[0] + a[1] * a[1], db = b[0] * b[0] + b[1] * b[1];

	if (da != db)
		return da < db ? -1 : 1;
	if (a[1] != b[1])       /* below before above */
		return a[1] < b[1] ? -1 : 1;
	return a[0] > b[0] ? -1 : a[0] < b[0];  /* right before left */
}

/* The spots of try_spots, nearest first. */
static void
make_spots(struct place *p)
{
	int n = 0;

	for (int i = -NEAR_REACH; i <= NEAR_REACH; i++)
		for (int j = -NEAR_REACH; j <= NEAR_REACH; j++) {
			p->spot[n][0] = i;
			p->spot[n++][1] = j;
		}
	qsort(p->spot, NSPOT, sizeof p->spot[0], nearer);
	n = 0;
	for (int i = 0; i <= LEADER_REACH; i++)
		for (int j = -LEADER_RISE; j <= LEADER_RISE; j++) {
			p->lead[n][0] = i;
			p->lead[n++][1] = j;
		}
	qsort(p->lead, NLEADSPOT, sizeof p->lead[0], nearer);
}

/* The slot of last_resort's stack of labels at point (x, y) in
 * p->stack, an open hash table: the point's, or the empty one where it
 * goes. */
static size_t
stack_slot(const struct place *p, double x, double y)
{
	double q[4] = { x, y, x, y };
	size_t h = seen_hash(q, p->nstack);

	while (p->stack[h].at == p->stack[h].at &&     /* not NaN: taken */
	    (p->stack[h].x != x || p->stack[h].y != y))
		h = (h + 1) & (p->nstack - 1);
	return h;
}

/*
 * Label i on the shelf: the row of labels below everything placed and
 * drawn, each a gap right of the one before it; a new row, a line
 * below the lowest box, where the row is full.  It overlaps no label:
 * every other lies above the row or left of its next spot.
 */
static void
on_shelf(struct place *p, size_t i)
{
	struct loft_label *l = &p->lb[i];
	struct box *b = &p->placed[i];
	int full = !p->shelf || (p->shelf_x > p->left &&
	    p->shelf_x + l->width > p->right);

	/* (a label placed near its curve since the row began may stand in
	 * its way: then a new row, below it too) */
	for (int row = 0; row < 2; row++) {
		if (full || row > 0) {
			p->shelf = 1;
			p->shelf_x = p->left;
			p->shelf_y = p->bottom - 0.6 * p->font;
		}
		l->at[0] = 0;
		l->at[1] = p->shelf_y;
		set_box(p, l, b);
		l->at[0] = p->shelf_x - b->lo[0];       /* the box from shelf_x */
		set_box(p, l, b);
		if (first_label(p, b) == (size_t)-1)
			break;
	}
	p->shelf_x = b->hi[0] + p->font / 2;
}

/* Where all spots are taken: label i at its rightmost point, moved down
 * a line at a time while it overlaps a label placed before it, below
 * the first (in input order) it overlaps.  A pile of records with one
 * rightmost point stacks its labels there: each starts where the one
 * before it at that point ended, so a pile of n takes n moves, not
 * n^2 / 2 (issue 28). */
static void
last_resort(struct place *p, size_t i)
{
	struct loft_label *l = &p->lb[i];
	size_t j, h = stack_slot(p, l->anchor[0], l->anchor[1]);
	int moves = 0;

	l->at[0] = l->anchor[0];
	l->at[1] = p->stack[h].at == p->stack[h].at ? p->stack[h].at :
	    l->anchor[1];
	set_box(p, l, &p->placed[i]);
	while ((j = first_label(p, &p->placed[i])) != (size_t)-1) {
		if (++moves > LAST_MOVES) {
			on_shelf(p, i);
			return;
		}
		l->at[1] = p->placed[j].lo[1] - 0.6 * p->font;
		set_box(p, l, &p->placed[i]);
	}
	p->stack[h] = (struct stack){ l->anchor[0], l->anchor[1], l->at[1] };
}

static int
by_record(const void *pa, const void *pb)
{
	const struct byrec *a = pa, *b = pb;

	if (a->rec != b->rec)
		return a->rec < b->rec ? -1 : 1;
	return (a->k > b->k) - (a->k < b->k);
}

/* The grid p->own of the lines of record rec: a label's own, looked up
 * in p->byrec, so that finding its own line near a spot looks at its
 * own lines alone (in a pile of records, at one of thousands). */
static int
own_lines(struct place *p, int rec)
{
	size_t lo = 0, hi = p->nseg;
	int rc;

	loft_grid_free(&p->own);
	while (lo < hi) {               /* the first of rec */
		size_t mid = lo + (hi - lo) / 2;

		if (p->byrec[mid].rec < rec)
			lo = mid + 1;
		else
			hi = mid;
	}
	for (hi = lo; hi < p->nseg && p->byrec[hi].rec == rec; hi++)
		;
	if ((rc = loft_grid_init(&p->own, p->font, p->font, p->origin,
	    hi - lo)) != 0)
		return rc;
	for (size_t i = lo; i < hi; i++)
		if ((rc = loft_grid_add_segment(&p->own, p->seg + 4 *
		    p->byrec[i].k, p->byrec[i].k)) != 0)
			return rc;
	return 0;
}

/* Place label i, file its box, and its leader as a line. */
static int
place_one(struct place *p, size_t i)
{
	struct loft_label *l = &p->lb[i];
	struct box *b = &p->placed[i];
	int rc, open = 0, lead = 0;

	if (!l->centred && (rc = own_lines(p, l->rec)) != 0)
		return rc;
	/* (where (1) found no spot clear of lines and labels, (4), which
	 * tries the same spots for that alone, finds none either: in a
	 * crowd, a third of the looks saved) */
	if (l->centred || !(try_spots(p, l, l->nanc, p->spot, NSPOT, 1, b,
	    &open) || try_on_curve(p, l, b) ||
	    (l->leader = try_spots(p, l, 1, p->lead, NLEADSPOT, 2, b,
	    &lead)) || (open && try_spots(p, l, l->nanc, p->spot, NSPOT, 0,
	    b, &open))))
		last_resort(p, i);
	memcpy(l->lo, b->lo, sizeof l->lo);
	memcpy(l->hi, b->hi, sizeof l->hi);
	p->bottom = fmin(p->bottom, b->lo[1]);
	if ((rc = loft_grid_add(&p->g, b->lo, b->hi, i)) == 0 && l->leader) {
		double sg[4];

		loft_label_leader(l, sg);
		rc = add_line(&p->o, sg, l->rec);
	}
	return rc;
}

/* The grids, and the lines filed: 0, or LOFT_ENOMEM. */
static int
setup(struct place *p, const double *seg, const int *segrec, size_t nseg,
    const double *origin)
{
	double width = 0, cw;

	for (size_t i = 0; i < p->n; i++)
		width += p->lb[i].width;
	cw = fmax(p->font, width / (double)(p->n > 0 ? p->n : 1));
	p->seg = seg;
	p->segrec = segrec;
	p->nseg = nseg;
	memcpy(p->origin, origin, sizeof p->origin);
	if ((p->placed = malloc((p->n > 0 ? p->n : 1) *
	    sizeof *p->placed)) == NULL ||
	    (p->byrec = malloc((nseg > 0 ? nseg : 1) *
	    sizeof *p->byrec)) == NULL ||
	    /* (a label's box covers about 2 by 2 cells: 4 entries each) */
	    loft_grid_init(&p->g, cw, p->font, origin, 4 * p->n) != 0 ||
	    loft_grid_init(&p->o.g, p->font, p->font, origin, nseg) != 0 ||
	    file_lines(p) != 0)
		return LOFT_ENOMEM;
	p->o.nlines = p->o.n;
	for (p->nstack = 64; p->nstack < 2 * p->n; p->nstack *= 2)
		;
	if ((p->stack = malloc(p->nstack * sizeof *p->stack)) == NULL)
		return LOFT_ENOMEM;
	for (size_t k = 0; k < p->nstack; k++)
		p->stack[k].at = NAN;
	for (size_t k = 0; k < nseg; k++)
		p->byrec[k] = (struct byrec){ segrec[k], k };
	qsort(p->byrec, nseg, sizeof *p->byrec, by_record);
	make_spots(p);
	return 0;
}

/* Every length of the placement times 2^e: exact, so a placement in
 * units scaled by a power of two is the placement scaled (the labels'
 * own numbers, the frame lo..hi and the lines seg). */
static void
scale_all(struct loft_label *lb, size_t n, double *seg, size_t nseg,
    double *lo, double *hi, int e)
{
	for (size_t i = 0; i < n; i++) {
		struct loft_label *l = &lb[i];

		l->width = ldexp(l->width, e);
		for (int k = 0; k < 2; k++) {
			l->anchor[k] = ldexp(l->anchor[k], e);
			l->at[k] = ldexp(l->at[k], e);
			l->lo[k] = ldexp(l->lo[k], e);
			l->hi[k] = ldexp(l->hi[k], e);
			for (int a = 0; a < l->nanc && a < LOFT_LABEL_ANCHORS;
			    a++)
				l->anc[a][k] = ldexp(l->anc[a][k], e);
		}
	}
	for (size_t k = 0; k < 4 * nseg; k++)
		seg[k] = ldexp(seg[k], e);
	for (int k = 0; k < 2; k++) {
		lo[k] = ldexp(lo[k], e);
		hi[k] = ldexp(hi[k], e);
	}
}

static int place_labels(struct loft_label *lb, size_t n, const double *seg,
    const int *segrec, size_t nseg, double font, double *lo, double *hi);

/*
 * The placement is made in units of a power of two near the font's
 * height (issue 28): in the drawing's own units, a drawing of 1e160
 * squares its lengths past the largest double when it asks whether two
 * segments cross (grid.c), and one of 1e-160 to 0; in these, the same
 * question of any drawing is asked of the same numbers, and a power of
 * two scales them exactly both ways.
 */
int
loft_place_labels(struct loft_label *lb, size_t n, const double *seg,
    const int *segrec, size_t nseg, double font, double *lo, double *hi)
{
	double *own = malloc((nseg > 0 ? 4 * nseg : 1) * sizeof *own);
	int e = font > 0 && isfinite(font) ? ilogb(font) : 0, rc;

	if (own == NULL)
		return LOFT_ENOMEM;
	if (nseg > 0)
		memcpy(own, seg, 4 * nseg * sizeof *own);
	scale_all(lb, n, own, nseg, lo, hi, -e);
	rc = place_labels(lb, n, own, segrec, nseg, ldexp(font, -e), lo, hi);
	scale_all(lb, n, own, 0, lo, hi, e);
	free(own);
	return rc;
}

static int
place_labels(struct loft_label *lb, size_t n, const double *seg,
    const int *segrec, size_t nseg, double font, double *lo, double *hi)
{
	struct place *p = calloc(1, sizeof *p);
	double cw = 0;
	int rc = 0;

	if (p == NULL)
		return LOFT_ENOMEM;
	p->lb = lb;
	p->n = n;
	p->font = font;
	p->bottom = lo[1];
	p->left = lo[0];
	p->right = hi[0];
	for (size_t i = 0; i < n; i++) {
		lb[i].at[0] = lb[i].anchor[0];
		lb[i].at[1] = lb[i].anchor[1];
		lb[i].leader = lb[i].oncurve = 0;
		cw += lb[i].width;
	}
	cw = fmax(font, cw / (double)(n > 0 ? n : 1));
	if (!(cw > 0 && font > 0) || !isfinite(cw))
		goto done;
	rc = setup(p, seg, segrec, nseg, lo);
	for (size_t i = 0; i < n && rc == 0; i++) {
		rc = place_one(p, i);
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], p->placed[i].lo[k]);
			hi[k] = fmax(hi[k], p->placed[i].hi[k]);
		}
	}
done:
	loft_grid_free(&p->g);
	loft_grid_free(&p->o.g);
	loft_grid_free(&p->own);
	free(p->o.seg);
	free(p->o.rec);
	free(p->o.multi);
	free(p->byrec);
	free(p->stack);
	free(p->placed);
	free(p);
	return rc;
}
