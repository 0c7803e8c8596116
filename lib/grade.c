/*
 * grade.c: grading a plane outline into shoe sizes (Manning 1973,
 * Fig. 16): the size systems' steps, the outline's frame (which axis is
 * its length, the reference point it grows about), and the arithmetic
 * grading formula, with the mirror image for the other foot.
 */
#include <math.h>
#include <string.h>

#include "internal.h"

/*
 * The size systems, in millimetres per size number.
 *  English: a size is a barleycorn, a third of an inch, of last length;
 *  the joint girth grows a quarter of an inch a size, and an insole's
 *  width at the joint is about the girth over GIRTH_PER_WIDTH.
 *  Paris point: two thirds of a centimetre of last length a size; the
 *  continental joint girth grows 5 mm a size, the same ratio gives the
 *  width.
 *  Mondopoint (ISO 9407): the size is the foot's length in millimetres,
 *  so a size number is 1 mm and sizes go in 5 mm intervals.  Its width
 *  is a measured foot width with no grading rule; the step here is a
 *  choice: 3/10 of the length step, the ratio of the other two systems
 *  (2.54 / (25.4 / 3) = 2 / (20 / 3) = 3/10).
 * The ranges are the sizes one meets in shoes: English adult sizes
 * (the children's scale is a separate count), Paris points of small
 * children to large adults, Mondopoint foot lengths likewise.
 */
#define GIRTH_PER_WIDTH 2.5
const struct loft_size_system loft_size_systems[] = {
	{ "english", 25.4 / 3, 25.4 / 4 / GIRTH_PER_WIDTH, 1, 1, 18 },
	{ "paris", 20.0 / 3, 5 / GIRTH_PER_WIDTH, 1, 15, 56 },
	{ "mondopoint", 1, 3.0 / 10, 5, 100, 350 },
	{ NULL, 0, 0, 0, 0, 0 }
};

const struct loft_size_system *
loft_size_system(const char *name)
{
	for (const struct loft_size_system *s = loft_size_systems; s->name;
	    s++)
		if (strcmp(s->name, name) == 0)
			return s;
	return NULL;
}

int
loft_grade_frame(const double *p, size_t n, int axis, const double *ref,
    struct loft_grade_frame *f, struct loft_error *err)
{
	double lo[2], hi[2], ext[2];
	size_t heel = 0;

	if (n == 0)
		return loft_fail(err, LOFT_EINPUT, -1, "record has no knots");
	lo[0] = hi[0] = p[0];
	lo[1] = hi[1] = p[1];
	for (size_t i = 1; i < n; i++)
		for (int k = 0; k < 2; k++) {
			if (p[2 * i + k] < lo[k])
				lo[k] = p[2 * i + k];
			if (p[2 * i + k] > hi[k])
				hi[k] = p[2 * i + k];
		}
	ext[0] = hi[0] - lo[0];
	ext[1] = hi[1] - lo[1];
	if (!isfinite(ext[0]) || !isfinite(ext[1]))
		return loft_fail(err, LOFT_EINPUT, -1, "the outline is too "
		    "large to grade");
	if (!(ext[0] > 0) || !(ext[1] > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "the knots have no "
		    "extent along %s: no outline to grade", ext[0] > 0 ? "y" :
		    "x");
	if (axis < 0) {
		double big = fmax(ext[0], ext[1]);

		if (fabs(ext[0] - ext[1]) <= LOFT_GRADE_SQUARE * big)
			return loft_fail(err, LOFT_EGEOM, -1, "the outline is "
			    "%g by %g, square within %g%%: no long axis to "
			    "grade along", ext[0], ext[1],
			    100 * LOFT_GRADE_SQUARE);
		axis = ext[1] > ext[0];
	}
	for (size_t i = 1; i < n; i++)
		if (p[2 * i + axis] < p[2 * heel + axis])
			heel = i;
	f->axis = axis;
	f->len = ext[axis];
	f->wid = ext[1 - axis];
	f->ref[0] = ref ? ref[0] : p[2 * heel];
	f->ref[1] = ref ? ref[1] : p[2 * heel + 1];
	return 0;
}

int
loft_grade_steps_fit(const struct loft_grade_frame *f, double lstep,
    double wstep, struct loft_error *err)
{
	if (lstep > LOFT_GRADE_STEP_MAX * f->len)
		return loft_fail(err, LOFT_EINPUT, -1, "a length step of %g a "
		    "size is more than %g of the outline's length %g: are the "
		    "steps in the knots' units?", lstep, LOFT_GRADE_STEP_MAX,
		    f->len);
	if (wstep > LOFT_GRADE_STEP_MAX * f->wid)
		return loft_fail(err, LOFT_EINPUT, -1, "a width step of %g a "
		    "size is more than %g of the outline's width %g: are the "
		    "steps in the knots' units?", wstep, LOFT_GRADE_STEP_MAX,
		    f->wid);
	return 0;
}

/*
 * The formula.  With a the length axis and c the other, L and W the
 * outline's length and width and r the reference point, a change dl of
 * length and dw of width moves each knot to
 *   q_a = p_a + (p_a - r_a) dl / L,   q_c = p_c + (p_c - r_c) dw / W,
 * so the outline becomes exactly L + dl long and W + dw wide.  The
 * mirror reflects q_c about r_c.
 */
int
loft_grade_outline(const struct loft_grade_frame *f, const double *p,
    size_t n, double dl, double dw, int mirror, double *q,
    struct loft_error *err)
{
	int a = f->axis, c = 1 - a;
	double sl = dl / f->len, sw = dw / f->wid;

	if (q == p)
		return loft_fail(err, LOFT_EINPUT, -1, "the graded knots "
		    "would overwrite the knots they are made from");
	if (!(f->len + dl > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "leaves the outline no "
		    "length (%g %+g)", f->len, dl);
	if (!(f->wid + dw > 0))
		return loft_fail(err, LOFT_EGEOM, -1, "leaves the outline no "
		    "width (%g %+g)", f->wid, dw);
	for (size_t i = 0; i < n; i++) {
		const double *s = p + 2 * (mirror ? n - 1 - i : i);
		double along = s[a] - f->ref[a], across = s[c] - f->ref[c];

		q[2 * i + a] = s[a] + along * sl;
		q[2 * i + c] = mirror ? f->ref[c] - across - across * sw :
		    s[c] + across * sw;
	}
	return 0;
}

void
loft_grade_direction(const struct loft_grade_frame *f, double dl, double dw,
    int mirror, const double *t, double *q)
{
	int a = f->axis, c = 1 - a;

	q[a] = t[a] * ((f->len + dl) / f->len);
	q[c] = t[c] * ((f->wid + dw) / f->wid);
	if (mirror)
		q[a] = -q[a];
}
