/*
 * corners.c: the corners of an outline given by dense noisy points
 * (splinefit -e finds them where the record names none).  As potrace
 * judges a corner by what a smooth curve could do within the pixel's
 * tube, a corner here is judged at a scale of a few tolerances: the
 * line through the points on either side of a point, each over that
 * length, turns by a sharp angle there.  A smooth bend turns the
 * lines by its length over its radius, so only a bend too tight for a
 * smooth curve to follow within the tolerance reads as a corner; noise
 * of the size of the tolerance tilts a line over that length by little.
 *
 * A turn found at that scale says where a corner is only to within
 * the scale, and one turn may be two corners: the end of a serif or a
 * stroke, narrower than the scale, turns twice.  So each is settled by
 * the points themselves, sharpest first: the split of the points near
 * it into two lines that fits them best, or three lines (two corners)
 * where that fits them better by more than the noise explains; a turn
 * that a cubic curve fits as well is a smooth bend after all, and so is
 * one that two straight runs joined by an arc fit better than the
 * corner, by more than the corner beats the cubic.
 * Other turns within the scale of a corner so settled are its echoes.
 * Each corner must turn by the sharp angle between the lines settled
 * either side of it.  A corner's knot goes where the lines either side
 * of it meet, which on sparse points is seldom a point, or at the point
 * beside where a corner pinned there fits better; so do the knots
 * of two corners close together, where the line through the points
 * between them fits better than the chord between two points, and
 * where one point lies between them each goes past its side's last
 * point by what the points' spacing leaves of the path.  Dense
 * points (hundreds within the scale) are first averaged in runs: a line
 * through the averages leans the same way, and the search then costs
 * as on sparser points.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

/* The scale: this many tolerances, or this many spacings of the
 * points, whichever is longer (a line needs a few points to lean on). */
#define CORNER_TOLS 3.0
#define CORNER_SPACINGS 6.0

/* A turn sharper than this (radians, 30 degrees) is a corner: noise
 * tilts a line over the scale by a few degrees at most, a smooth curve
 * turns this much over it only at a radius of twice the scale. */
#define CORNER_TURN 0.52

/* A corner turns about as much over twice the scale as over it; a
 * smooth bend, twice as much: a turn is a corner only where the turn
 * over twice the scale is at most this many times it. */
#define CORNER_CONCENTRATED 1.2

/* But a turn over twice the scale of this much (radians, 115 degrees)
 * and more, where half the scale turns about as much as the scale, is
 * two corners closer than twice the scale: see bend. */
#define CORNER_PAIR_TURN 2.0

/* A turn is a corner only where it is this many times its standard
 * error, from the scatter of the points about the two lines: noise
 * tilts a line through k points of scatter r over a length L by about
 * r sqrt(12 / k) / L, and the sharpest of hundreds of such tilts
 * reaches three or four of them. */
#define CORNER_SIGMAS 5.0

/* Two corners where one was found must fit the points better than one
 * by this many times the noise's variance: the second corner's two
 * more unknowns absorb about two of it from noise alone, and the best
 * of the few dozen pairs tried, up to about nine.  Where more are
 * tried (over 33), the best of N reaches about 2 + 2 ln N (the tail of
 * a chi-square with two degrees of freedom), and the margin is that:
 * 12 for the 150 or so a corner of dense points' averaged runs tries.
 * With nine there, 5 of 60 squares of 10,000 points (noise 0.3, -e
 * 1.2) got a chamfer of half a unit at a corner; now 1 does.  On the
 * noisy glyphs of make compare-approx (a few dozen pairs tried at
 * most corners) as many true corners were kept and false ones found as
 * before this margin came in (then 638 and 63), and 645 corners were
 * written in all, against 650; on the held-out faces of its second
 * table 2 fewer false corners were found (then 56). */
#define CORNER_SPLIT 9.0

/* A corner (or two) must fit the points near it better than the
 * polynomial curve of CORNER_DEGREE that fits them best, by
 * CORNER_SMOOTH times the noise's variance, or it is a smooth bend: a
 * bend tighter than the scale, or noise on a gentle one, turns the lines
 * by as much as a corner does, but a polynomial follows it.  The split,
 * the best of a dozen or so, gains about this much over the polynomial
 * from noise alone.  (Before the corners' knots went where lines meet,
 * this margin dropped corners at tight bends that the fit needed, where
 * it then looped; now it drops 6 false corners of the 93 on the noisy
 * glyphs of make compare-approx, 1 true one, and no curve crosses
 * itself.)  A quadratic follows a bend of even curvature only: where a
 * straight run goes into a bowl, two lines fitted it better, and 87
 * corners on those glyphs were false; against a cubic (as many unknowns
 * as the two lines) 76 are, and as many true ones are kept (636 of 665),
 * where a margin of 5 or 8 with the cubic keeps 631 or 626. */
#define CORNER_DEGREE 3
#define CORNER_SMOOTH 3.0

/* A cubic cannot follow a straight run into a bend tighter than the
 * scale and out into another run, which two lines fit better: so a
 * corner (or two) must also gain on the cubic by more than CORNER_ROUND
 * times what rounding the single corner gains on it, where the lines
 * through the points near it but the few nearest it are rounded by an
 * arc tangent to both (see rounds), or it is a bend.  An arc of radius
 * 0 is the corner, so rounding gains a little from noise alone, which
 * outweighs a gain on the cubic as small.  On the noisy glyphs of make
 * compare-approx this drops 11 of the 63 false corners, and 3 of the
 * 638 true ones kept; on its held-out faces 4 of 56 false and no true
 * one, and the 90th percentile of the curves' distance from the true
 * outline falls from 4.52 to 4.21 sigmas; on 800 contours of eight
 * other faces, 50 of 308 false corners and 7 of 3,976 true.  (At 0.7,
 * 7 false and 1 true on the first; at 1.5, 12 and 7.  Tested against
 * the rounding alone, with the arc kept 1 to 3 noises off the corner,
 * a third to a half of the true corners read as bends.)
 * The radii tried are CORNER_ROUND_RADII, a factor of sqrt 2 apart
 * down from the shorter line's extent; a turn over 2 CORNER_ROUND_HALF
 * (160 degrees) is not rounded, whose arc would run far along the
 * lines. */
#define CORNER_ROUND 1.0
#define CORNER_ROUND_RADII 24
#define CORNER_ROUND_HALF 1.4

/* A corner is placed among at most about this many points either side
 * of where its turn was found (every so many where the points are
 * denser): the search tries each pair of them. */
#define CORNER_PLACES 12

/* A single corner's knot goes where the lines through the points
 * either side of it meet, unless they are this near parallel (the
 * square of the sine of their angle), or meet off the path a corner
 * can lie on: the true corner lies on the outline between the point
 * and a neighbour, and a sparse outline's points miss it by up to half
 * their spacing, which a corner at the point would cut.  (Two corners
 * close together: see place_two.) */
#define CORNER_MEET 0.01

/* The path from a corner's point through its knot to a neighbour is
 * the outline between them, about as long as the points' spacing: so
 * the knot goes where the lines meet only where that path is no
 * longer than the spacing beyond the neighbours (the longer of the
 * gaps from each to the point after it), by more than CORNER_PATH
 * times the noise (the ends of the gap and of the path are each off
 * by the noise) and CORNER_PATH_PART of that spacing (lines through a
 * few points either side meet off the corner by a part of it: on a
 * square of side 100 with a point every 2.5, noise 0.05, the path
 * through the meet was up to 5 times the noise longer than the gap).
 * A meet farther off is out beyond the outline: where the outer lines
 * of a chamfer one spacing long, read as one corner, cross, or where
 * noise tilts the sides of a sharp tip.  It replaces a bound of the
 * knot's distance from the point by the distance to the point's
 * nearer neighbour, which let such meets through (the curves of
 * FreeSerif's u and W strayed 5.5 and 5.4 sigmas from the true outline
 * there, now 4.6 and 4.0).  On the noisy glyphs of make compare-approx
 * the median Hausdorff distance of a curve from the true outline falls
 * from 3.04 to 2.95 sigmas and the 90th percentile from 4.87 to 4.62,
 * and 639 true corners of 665 are kept (638); on the next 100 the
 * worst falls from 10.1 to 7.9 sigmas and 436 true corners of 480 are
 * kept (434). */
#define CORNER_PATH 3.0
#define CORNER_PATH_PART 0.2

/* Two corners found at neighbouring points are one between them, where
 * the lines either side meet; but a corner between two points lies no
 * farther from their chord than the apex of the isosceles triangle on
 * it whose sides turn by the lines' angle, (chord / 2) tan(turn / 2).
 * Where the lines meet farther than that, by more than CORNER_APEX
 * times the noise, the points bend round rather than turn between
 * them, and the knot goes at the nearer point.  On the noisy glyphs of
 * make compare-approx this moves one knot, at the bottom of a bowl
 * where three points turn 90 degrees: the worst Hausdorff distance of
 * a curve from the true outline falls from 8.8 to 8.1 sigmas; no other
 * contour's distance or corners change, of those 100 or the next 100. */
#define CORNER_APEX 1.0

/* Then the place so found is judged against the point and each of its
 * neighbours by how well a corner pinned there fits the CORNER_HINGE
 * points either side (each side the line through the place that fits
 * its points best), and a point is taken where it fits better by
 * CORNER_PIN times the noise's variance: where one side is short or
 * curved the lines meet off the corner, and the point the search
 * settled on may be the one beside the point at the corner.  The
 * margin keeps a point's own noise from choosing it (a corner pinned
 * at a point fits that point exactly): without it, the noisy b of
 * splinefit(1)'s figure had its top edge tilted to a point below the
 * corner.  On the noisy glyphs of make compare-approx this takes the
 * 90th percentile of the distance of a knot from its true corner from
 * 4.3 to 4.2 sigmas (36 beyond 5, from 42), and of the curve's from
 * the true outline from 5.1 to 4.9; it keeps 2 more true corners (638
 * of 665), and 4 fewer false ones are left (72). */
#define CORNER_HINGE 6
#define CORNER_PIN 2.0

/* The turns found within the scale of a corner settled are its echoes,
 * and are passed over, but for the outermost this many points either
 * side: the second corner of the end of a serif or a stroke, a scale
 * or less from the first, may settle there (and then must turn by
 * CORNER_TURN as any corner must). */
#define CORNER_ECHO 2

/* A corner settled alone that explains a turn this much (radians, 57
 * degrees) less than its candidate's over the scale (the angle between
 * the lines either side of it, against the candidate's turn) may hide
 * a second within the scale: a tip a few points from a shallower
 * corner, whose turns at the scale merge into one, sharpest between
 * them, where the settling finds the one that fits the points best.
 * So the candidates at CORNER_FINER of the scale within the scale of
 * it are settled too, where they turn by this much at least; each is
 * taken only where it adds one corner, within the scale of the first
 * (where it adds two, noise on a bend made them).  And such a corner is
 * settled after all the others: where its candidate lies off the
 * middle of two corners, its window holds one of them and a piece of
 * the other, and a later candidate between them may settle the two
 * (then the one, its points taken, is dropped).  On the noisy glyphs
 * of make compare-approx this finds the 129-degree tip of FreeSerif's
 * a, 26 units from a 42-degree corner (its curve's Hausdorff distance
 * from the true outline falls from 4.9 to 2.8 sigmas); 642 true
 * corners of 665 are kept (639) and 66 false ones found (67); on the
 * next 100, 446 of 480 are kept (443) and 343 false ones found (342).
 * With this bound at 0.7 or 1.3, 642 and 447 or 444 are kept.  (Before
 * such corners were settled last, the search at 0.4 or 0.67 of the
 * scale kept 640 on the first 100, at half of it 641.) */
#define CORNER_HIDDEN 1.0
#define CORNER_FINER 0.5

/* A candidate settled as a bend where its turn over twice the scale is
 * CORNER_PAIR_TURN or more is settled again from the tip of that U-turn
 * (u_tip), and the corners found there are taken where the lines
 * either side of them turn by this much at least (radians, 150
 * degrees): the end of a slab or a stroke, between parallel sides.  The
 * tip of a thin ellipse (200 by 24, noise 0.05, -e 0.2) also reads as
 * two corners from its tip, but its sides turn by 128 to 133 degrees
 * there; the ends of slabs 97 long and 3 to 10 across, by 169 to 180.
 * (Settled again also where the candidate gave one corner, the slabs
 * 7 to 10 across without noise have theirs placed at the corners, not
 * up to 1.7 off; but on make compare-approx's noisy glyphs the knot of
 * a corner of FreeSerif's e moves from 2.1 to 4.1 sigmas off it, and
 * the curve from 3.0 to 4.1 sigmas off the true outline: so only where
 * its split fits the points badly, CORNER_MISFIT.) */
#define CORNER_END_TURN 2.6

/* A split that fits the points of its window worse than this (the mean
 * squared distance from its lines, in the noise's variance) is not a
 * corner's: where points are sparse (a spacing of a few tolerances),
 * the scale of six spacings spans the whole end of a slab or a stroke,
 * every point there turns by nearly 180 degrees over it, and the
 * sharpest may lie a scale from the end, whose window then holds one
 * side and a piece of the other.  Such a candidate is settled again from
 * the tip of its U-turn, as a bend is (see CORNER_END_TURN), and the
 * corners found there are taken where they fit better.  On slabs 40 by
 * 1.44, a point every 0.8 (4 tolerances: one or two points on each
 * end), noise 0.05, -e 0.2, 100 seeds, 395 of the 400 corners are kept
 * (341 before), and 96 fits have the four and no other (63).  On the
 * noisy glyphs of make compare-approx 1 true corner more is kept (636 of
 * 665), and the 90th percentile of the curves' distance from the true
 * outline falls from 4.34 to 4.31 sigmas; on its held-out faces 1 false
 * corner fewer is found (50), and that percentile falls from 4.21 to
 * 4.17; on 800 contours of eight other faces, 7 true corners more are
 * kept and 6 false ones fewer found (4,012 of 4,323; 262).  At 8, 2
 * fewer are kept on the slabs, and 3 fewer on the eight faces, with 3
 * false ones more; at 2, that percentile on the held-out faces is 6%
 * higher than at 4. */
#define CORNER_MISFIT 4.0

/* A split that still fits worse than CORNER_MISFIT, from the tip or
 * not, is settled again with sides CORNER_SHORTER times shorter in
 * points, and taken so where it fits CORNER_SHORTER_FIT times better:
 * where points are sparse (a spacing of several tolerances), a side of
 * half the scale runs along the curved bracket of a serif or into a
 * bowl, which a line fits badly, and the best split of such lines puts
 * the corners a point or two off (a serif's end, two points across,
 * read as one corner a side away).  Where the sides are straight and
 * the split fits badly still, the shorter split gains little, and is
 * not taken: on rectangles 100 x 12 with a point every 2.5 (four on
 * each end), taking any better fit read a fifth corner on 2 of 3
 * seeds.  On the noisy glyphs of make compare-approx 645 of 665 true
 * corners are kept (639 before) and 51 false ones found (53); on its
 * held-out faces 533 of 564 (531), with 51 false ones (50); the
 * farthest curve from its true outline comes to 8.11 sigmas (10.22),
 * and on the held-out faces stays at 6.89.  With the knots placed by
 * the shorter sides too, corpus contour 33 strayed 5.55 sigmas, not
 * 4.89. */
#define CORNER_SHORTER 2
#define CORNER_SHORTER_FIT 2.0

/* A corner turns the lines of every window that reaches it, so the
 * turns near a sharp one (the end of a stroke) may outweigh a lesser
 * corner's within half the scale of its own, and that corner is never
 * a candidate: a serif's foot beside the end of a stem.  So once the
 * candidates are settled, the turns are measured again with no window
 * reaching past a corner found, those of points not taken that are
 * the sharpest within half the scale, and turn within half of it
 * nearly as much (CORNER_CONCENTRATED), are settled again, each
 * settling no nearer a corner found than half the points between, and
 * the corners found are taken where their split fits within
 * CORNER_MISFIT and gains this much on the cubic (in the noise's
 * variance): a second look at points passed over must be surer than the
 * first.  On a stem 4 by 10 with an arm 7.2 by 2.4 out of its top, a
 * point every 0.8 (nine spacings along the arm's underside, three
 * across its end), noise 0.05, -e 0.2, 100 seeds, 592 of the 600
 * corners are kept (556 before).  On the noisy glyphs of make
 * compare-approx 639 of 665 true corners are kept (636) and 53 false
 * ones found (52); on its held-out faces 531 of 564 (522), with 50 false
 * ones (50); on 800 contours of eight other faces 4,055 of 4,323
 * (4,012), with 264 false ones (262); the 90th percentile of the
 * held-out curves' distance from the true outline falls from 4.17 to
 * 3.80 sigmas.  With the cubic's margin alone (CORNER_SMOOTH), 533 are
 * kept on the held-out faces but 69 false corners found on the first;
 * at 10, 61 and at 25, 55 false ones; at 60, as at 40, 53, and 530 kept
 * on the held-out faces. */
#define CORNER_SHADOWED 40.0

/* A gentle corner (a turn under CORNER_GENTLE, radians, 57 degrees)
 * turns the lines of its window so little that a cubic follows it to
 * within the noise there, and it is settled as a bend.  So such a
 * candidate is settled again with sides CORNER_WIDER times as many
 * points (settle_wide), and the corner is taken where that split fits
 * the points within CORNER_WIDE_FIT (in the noise's variance: both
 * sides straight, to within the noise, over that length), gains
 * CORNER_WIDE_GAIN on the cubic (the longer look, like the second,
 * must be surer than the first: see CORNER_SHADOWED), and its outer
 * lines turn by at most CORNER_CONCENTRATED times the candidate's turn
 * (a bend's longer lines turn more, a corner's as much).  Sharper
 * candidates are not looked at so: their windows tell a corner from a
 * bend, and longer lines read a tight bend as corners (under 69
 * degrees, the apex of a house of tests/approx.sh, a turn of 70
 * degrees rounded at radius 10, read as two on 4 of its 10 seeds).  On
 * a polygon whose corners turn by 35 and 55 degrees beside sides 20
 * long, a point every 0.12 (0.6 TOL), noise 0.05, -e 0.2, 100 seeds,
 * 155 of those 200 corners are kept (130 before).  On the noisy glyphs
 * of make compare-approx as many true corners are kept (645 of 665) and
 * false ones found (51) as before; on its held-out faces 538 of 564
 * (533), with 51 false ones (51), and the 90th percentile of the
 * curves' distance from the true outline falls from 3.82 to 3.74
 * sigmas; on 800 contours of eight other faces 4,070 of 4,323 (4,066),
 * with 258 false ones (258).  Looked at so at all turns, 3 false
 * corners more are found on the first; under 46 degrees, as many are
 * kept.  With sides twice as long (not three times), 3 fewer are kept
 * on the held-out faces, four times as long, 1 fewer and 1 false one
 * more found.  There a gain of 15 keeps 2 more and finds 1 false corner
 * more, one of 40 keeps 3 fewer; a fit within 1 keeps 1 fewer, and
 * within 2 finds 1 false one more (and 1 on the first); outer lines
 * turning by at most 1.1 t keep 1 fewer. */
#define CORNER_GENTLE 1.0
#define CORNER_WIDER 3
#define CORNER_WIDE_FIT 1.3
#define CORNER_WIDE_GAIN 25.0

/* A corner's lead on the cubic grows with the points that lean on its
 * lines, noise's does not: over sides half as long again, a kink's
 * misfit to the cubic grows as the cube of their length, by 1.5^3, 3.4
 * times, so a corner that gains the least it may (CORNER_SMOOTH) gains
 * 10 there, where noise on a bend still gains a few, or the cubic
 * follows the bend better than the lines.  So a corner that gains less
 * than CORNER_FAINT on the cubic (a lead within noise's reach) is kept
 * only where, with sides of CORNER_FAINT_SIDES m points (not settle's
 * 2m), it gains CORNER_FAINT_WIDE (see faint).  On a noisy ellipse
 * of tests/approx.sh, 60 by 14 with a point every 0.07 (its tips read
 * as corners), 23 corners are found over 300 seeds (44 before).  On
 * the noisy glyphs of make compare-approx as many true corners are
 * kept (645 of 665) and 50 false ones found (51); on its held-out faces
 * 538 of 564 (538), with 43 false ones (51); on 800 contours of eight
 * other faces 4,070 of 4,323 (4,070), with 240 false ones (258); on the
 * corpus's next hundred 450 of 480 (450), with 313 (321).  Every
 * corner so checked, 7 fewer are kept on the held-out faces; those
 * gaining under 8, 2 fewer on the first and 4 on the eight faces.  A
 * wider gain of 12 keeps 1 fewer on the held-out faces, one of 8 finds
 * 6 false corners more on the eight faces; with a wider gain of 12,
 * sides of 2m keep 536 on the held-out faces, and 4m find 246 false
 * ones on the eight faces.  The longer sides stop short of the points
 * of the corners found before (the sharpest are settled first): a true
 * corner within them leaves the cubic far off, and the gain is its,
 * not this corner's.  Held-out contours 80 and 92 (Z003) so had false
 * corners 5 TOL from true ones, gaining 3.9 but 19.6 and 19.9 over
 * sides that reached them.  Stopping short finds 2 false corners fewer
 * on the held-out faces (41) and 2 fewer on the eight faces (238),
 * keeping 1 true corner fewer there (4,069); the first table and the
 * next hundred are unchanged.  (With the wider gain scaled to the
 * sides so shortened, 3 (s / 2m)^3, 1 false corner more is found on
 * the first table.) */
#define CORNER_FAINT 5.0
#define CORNER_FAINT_SIDES 3
#define CORNER_FAINT_WIDE 10.0

/* Power iterations for a principal axis (a 2 x 2 converges in a few). */
#define CORNER_POWER 32

/* The noise is taken as no less than this part of the tolerance, so
 * that points without noise still weigh a second corner. */
#define CORNER_NOISE_FLOOR 1e-3

/* Where more than this many points lie within the scale of a point,
 * runs of them are averaged into one first, leaving about half as
 * many: the lines at the scale lean on as many as a corner needs, and
 * ten times denser points cost no more.  The density is the median of
 * this many points' counts, spread round the outline. */
#define CORNER_DENSE 48
#define CORNER_PROBES 15

/* The outline: n points of dimension dim, closed or not. */
struct outline {
	const double *p;
	size_t n;
	int dim, closed;
};

/* Point j of o, counted round the end when closed; NULL where an open
 * outline has none. */
static const double *
pt(const struct outline *o, long j)
{
	long n = (long)o->n;

	if (o->closed)
		return o->p + ((j % n + n) % n) * o->dim;
	return j >= 0 && j < n ? o->p + j * o->dim : NULL;
}

/* A least-squares line: through c, unit direction d; the sum of the
 * squared distances of its points from it, and their extent along it. */
struct line {
	double c[LOFT_MAXDIM], d[LOFT_MAXDIM], ss, ext;
};

/* The principal axis of points a..a+k-1 of o about c (the largest
 * eigenvector of their scatter about it) into u, by power iteration
 * from u (a unit vector). */
static void
principal_axis(const struct outline *o, long a, long k, const double *c,
    double *u)
{
	double m[LOFT_MAXDIM][LOFT_MAXDIM] = { { 0 } }, v[LOFT_MAXDIM];
	int dim = o->dim;

	for (long t = 0; t < k; t++) {
		vsub(v, pt(o, a + t), c, dim);
		for (int i = 0; i < dim; i++)
			vaxpy(m[i], v[i], v, dim);
	}
	for (int it = 0; it < CORNER_POWER; it++) {
		for (int i = 0; i < dim; i++)
			v[i] = vdot(m[i], u, dim);
		if (!(vunit(v, dim) > 0))
			break;
		vcopy(u, v, dim);
	}
}

/* The least-squares line through points a..a+k-1 of o into *l, its
 * direction in the order of the points.  0 where the points are
 * missing or give no direction. */
static int
fit_line(const struct outline *o, long a, long k, struct line *l)
{
	double v[LOFT_MAXDIM], c[LOFT_MAXDIM] = { 0 }, u[LOFT_MAXDIM];
	double lo = HUGE_VAL, hi = -HUGE_VAL;
	int dim = o->dim;

	if (k < 2 || pt(o, a) == NULL || pt(o, a + k - 1) == NULL)
		return 0;
	for (long t = 0; t < k; t++)
		vaxpy(c, 1.0 / k, pt(o, a + t), dim);
	vsub(u, pt(o, a + k - 1), pt(o, a), dim);
	if (!(vunit(u, dim) > 0))
		return 0;
	principal_axis(o, a, k, c, u);
	vsub(v, pt(o, a + k - 1), pt(o, a), dim);
	if (vdot(u, v, dim) < 0)
		vscale(u, -1, u, dim);
	l->ss = 0;
	for (long t = 0; t < k; t++) {
		double x;

		vsub(v, pt(o, a + t), c, dim);
		x = vdot(v, u, dim);
		lo = fmin(lo, x);
		hi = fmax(hi, x);
		vaxpy(v, -x, u, dim);
		l->ss += vdot(v, v, dim);
	}
	vcopy(l->c, c, dim);
	vcopy(l->d, u, dim);
	l->ext = hi - lo;
	return 1;
}

/* The angle between unit vectors u and v. */
static double
angle(const double *u, const double *v, int dim)
{
	double c = vdot(u, v, dim);

	return acos(c > 1 ? 1 : c < -1 ? -1 : c);
}

/* How many points from point i the first one at least len from it
 * lies (straight, not along the polyline, whose length noise
 * inflates), backward (dir -1) or forward; 0 where none is. */
static long
reach(const struct outline *o, long i, int dir, double len)
{
	for (long t = 1; t < (long)o->n && pt(o, i + dir * t) != NULL; t++)
		if (vdist(pt(o, i + dir * t), pt(o, i), o->dim) >= len)
			return t;
	return 0;
}

/* The turn at point i between the lines through the a points before
 * it and the b after it (with it); 0 where none is measured, or (gate)
 * where it is within the noise's reach. */
static double
turn_over(const struct outline *o, long i, long a, long b, int gate)
{
	struct line u, v;
	double t, se;

	if (a == 0 || b == 0 || !fit_line(o, i - a, a + 1, &u) ||
	    !fit_line(o, i, b + 1, &v))
		return 0;
	t = angle(u.d, v.d, o->dim);
	/* the lines' tilts from the scatter of their points; a turn
	 * within the noise's reach counts as none */
	se = sqrt((a > 1 && u.ext > 0 ? u.ss / (a - 1) * 12 / (a + 1) /
	    (u.ext * u.ext) : HUGE_VAL) + (b > 1 && v.ext > 0 ?
	    v.ss / (b - 1) * 12 / (b + 1) / (v.ext * v.ext) : HUGE_VAL));
	return !gate || t >= CORNER_SIGMAS * se ? t : 0;
}

/* The turn at point i over the scale len (see turn_over). */
static double
turn_at(const struct outline *o, long i, double len, int gate)
{
	return turn_over(o, i, reach(o, i, -1, len), reach(o, i, 1, len),
	    gate);
}

static int
by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The noise of the points (standard deviation across the outline),
 * from the median distance of each point from its neighbours' chord
 * (a bend or a corner moves few of them); 0 where there is none.  r:
 * scratch, room for o->n. */
static double
noise(const struct outline *o, double *r)
{
	double s = 0;
	size_t k = 0;

	for (long i = 0; i < (long)o->n; i++) {
		double c[LOFT_MAXDIM], e[LOFT_MAXDIM];

		if (pt(o, i - 1) == NULL || pt(o, i + 1) == NULL)
			continue;
		vsub(c, pt(o, i + 1), pt(o, i - 1), o->dim);
		vsub(e, pt(o, i), pt(o, i - 1), o->dim);
		if (!(vunit(c, o->dim) > 0))
			continue;
		vaxpy(e, -vdot(e, c, o->dim), c, o->dim);
		if (isfinite(vnorm(e, o->dim)))
			r[k++] = vnorm(e, o->dim);
	}
	if (k > 0) {
		qsort(r, k, sizeof *r, by_value);
		/* the distance is normal with variance 1.5 s^2 across a
		 * plane curve; its median absolute value is 0.6745 of that */
		s = r[k / 2] / (0.6745 * sqrt(1.5));
	}
	return s;
}

/* The squared distances of points a+1..b-1 from the chord a-b; HUGE_VAL
 * where the chord is none. */
static double
chord_ss(const struct outline *o, long a, long b)
{
	double c[LOFT_MAXDIM], r[LOFT_MAXDIM], ss = 0;

	vsub(c, pt(o, b), pt(o, a), o->dim);
	if (!(vunit(c, o->dim) > 0))
		return HUGE_VAL;
	for (long j = a + 1; j < b; j++) {
		vsub(r, pt(o, j), pt(o, a), o->dim);
		vaxpy(r, -vdot(r, c, o->dim), c, o->dim);
		ss += vdot(r, r, o->dim);
	}
	return ss;
}

/* The squared distances of points lo..hi from two lines, lo..a and
 * b..hi: one corner (b == a) or two, a and b (the chord a-b between);
 * HUGE_VAL where the points are missing, or where two corners do not
 * both turn by CORNER_TURN. */
static double
corner_ss(const struct outline *o, long lo, long a, long b, long hi)
{
	struct line u, w;
	double v[LOFT_MAXDIM];

	if (!fit_line(o, lo, a - lo + 1, &u) || !fit_line(o, b, hi - b + 1, &w))
		return HUGE_VAL;
	if (a == b)
		return u.ss + w.ss;
	vsub(v, pt(o, b), pt(o, a), o->dim);
	if (!(vunit(v, o->dim) > 0) || angle(u.d, v, o->dim) < CORNER_TURN ||
	    angle(v, w.d, o->dim) < CORNER_TURN)
		return HUGE_VAL;
	return u.ss + w.ss + chord_ss(o, a, b);
}

/* The squared distances of points lo..hi of o from the cubic curve
 * that fits them best, as a function of their place along their
 * principal axis (a smooth bend, whose curvature may change along it:
 * a straight run into a bowl); HUGE_VAL where there is none.  The
 * normal equations in x scaled to about [-1, 1], solved by elimination
 * (the matrix is positive definite: no pivoting). */
static double
cubic_ss(const struct outline *o, long lo, long hi)
{
	struct line l;
	int dim = o->dim, n = CORNER_DEGREE + 1;
	double a[CORNER_DEGREE + 1][CORNER_DEGREE + 1 + LOFT_MAXDIM] = { { 0 } };
	double v[LOFT_MAXDIM], ss = 0, sc;

	if (hi - lo < n + 1 || !fit_line(o, lo, hi - lo + 1, &l))
		return HUGE_VAL;
	sc = l.ext > 0 ? 2 / l.ext : 1;
	for (long t = lo; t <= hi; t++) {
		double xp[CORNER_DEGREE + 1], x;

		vsub(v, pt(o, t), l.c, dim);
		x = vdot(v, l.d, dim) * sc;
		xp[0] = 1;
		for (int i = 1; i < n; i++)
			xp[i] = xp[i - 1] * x;
		for (int i = 0; i < n; i++) {
			for (int j = 0; j < n; j++)
				a[i][j] += xp[i] * xp[j];
			for (int k = 0; k < dim; k++)
				a[i][n + k] += xp[i] * v[k];
		}
	}
	for (int i = 0; i < n; i++) {
		if (!(a[i][i] > 0))
			return HUGE_VAL;
		for (int j = 0; j < n; j++)
			for (int k = n + dim - 1; j != i && k >= i; k--)
				a[j][k] -= a[j][i] / a[i][i] * a[i][k];
	}
	for (long t = lo; t <= hi; t++) {
		double x, xi = 1;

		vsub(v, pt(o, t), l.c, dim);
		x = vdot(v, l.d, dim) * sc;
		for (int i = 0; i < n; i++, xi *= x)
			vaxpy(v, -xi / a[i][i], a[i] + n, dim);
		ss += vdot(v, v, dim);
	}
	return ss;
}

/* Whether the lines through points lo..a and a..hi turn by CORNER_TURN
 * at least: a split that fits the points best, and a cubic curve
 * worse, may still turn by little (a bend beside a straight run). */
static int
turns(const struct outline *o, long lo, long a, long hi)
{
	struct line u, v;

	return fit_line(o, lo, a - lo + 1, &u) &&
	    fit_line(o, a, hi - a + 1, &v) &&
	    angle(u.d, v.d, o->dim) >= CORNER_TURN;
}

/* A split of the points: one corner (a == b) or two (a and b), and
 * how well it fits them. */
struct split {
	double ss;
	long a, b;
};

/* Try the splits with a in from..to (every step-th): one corner at a
 * into *one, and two with b up to last into *two, each where it fits
 * the points lo..hi better; *pairs counts the pairs tried. */
static void
search(const struct outline *o, long lo, long hi, long from, long to,
    long last, long step, struct split *one, struct split *two,
    long *pairs)
{
	double s;

	for (long a = from; a <= to; a += step) {
		if ((s = corner_ss(o, lo, a, a, hi)) < one->ss)
			*one = (struct split){ s, a, a };
		for (long b = a + step; b <= last; b += step, ++*pairs)
			if ((s = corner_ss(o, lo, a, b, hi)) < two->ss)
				*two = (struct split){ s, a, b };
	}
}

/* Where lines u and v come nearest each other (the middle of their
 * nearest points) into x; 0 where they are too near parallel. */
static int
meet(const struct line *u, const struct line *v, int dim, double *x)
{
	double r[LOFT_MAXDIM], b = vdot(u->d, v->d, dim), den = 1 - b * b;
	double e, f;

	if (!(den > CORNER_MEET))
		return 0;
	vsub(r, u->c, v->c, dim);
	e = vdot(u->d, r, dim);
	f = vdot(v->d, r, dim);
	/* u->c + s u->d and v->c + t v->d, with s and t that make the
	 * gap between them square to both lines */
	for (int i = 0; i < dim; i++)
		x[i] = (u->c[i] + (b * f - e) / den * u->d[i] +
		    v->c[i] + (f - b * e) / den * v->d[i]) / 2;
	return 1;
}

/* Two rays from a vertex x, in along d1 and out along d2 (unit
 * vectors), rounded by an arc tangent to both: the arc's plane (e1
 * the bisector b, pointing in, and e2) and half the turn, h. */
struct rounded {
	double x[LOFT_MAXDIM], d1[LOFT_MAXDIM], d2[LOFT_MAXDIM];
	double b[LOFT_MAXDIM], e2[LOFT_MAXDIM], h;
};

/* The rays along lines u and v from where they meet into *f; 0 where
 * they are near parallel, or turn by more than 2 CORNER_ROUND_HALF. */
static int
rounded_of(const struct line *u, const struct line *v, int dim,
    struct rounded *f)
{
	if (!meet(u, v, dim, f->x) ||
	    (f->h = angle(u->d, v->d, dim) / 2) > CORNER_ROUND_HALF)
		return 0;
	vcopy(f->d1, u->d, dim);
	vcopy(f->d2, v->d, dim);
	vsub(f->b, v->d, u->d, dim);
	vcopy(f->e2, u->d, dim);
	vaxpy(f->e2, 1, v->d, dim);
	return vunit(f->b, dim) > 0 && vunit(f->e2, dim) > 0;
}

/* The squared distance of p from the rays f rounded at radius r: the
 * arc's centre lies r / cos h along b from the vertex, and it meets
 * the rays r tan h from it. */
static double
rounded_d2(const struct rounded *f, double r, const double *p, int dim)
{
	double q[LOFT_MAXDIM], v[LOFT_MAXDIM], t = r * tan(f->h), s, best;
	double c1, c2, in;

	vsub(q, p, f->x, dim);
	s = -vdot(q, f->d1, dim);
	vcopy(v, q, dim);
	vaxpy(v, fmax(s, t), f->d1, dim);
	best = vdot(v, v, dim);
	s = vdot(q, f->d2, dim);
	vcopy(v, q, dim);
	vaxpy(v, -fmax(s, t), f->d2, dim);
	best = fmin(best, vdot(v, v, dim));
	vaxpy(q, -r / cos(f->h), f->b, dim);
	c1 = vdot(q, f->b, dim);
	c2 = vdot(q, f->e2, dim);
	in = sqrt(c1 * c1 + c2 * c2);
	if (r > 0 && in > 0 && -c1 >= in * cos(f->h))   /* within the arc */
		best = fmin(best, (in - r) * (in - r) +
		    fmax(vdot(q, q, dim) - in * in, 0));
	return best;
}

/* The squared distances of points lo..hi of o from the rays f rounded
 * at radius r. */
static double
rounded_ss(const struct outline *o, long lo, long hi,
    const struct rounded *f, double r)
{
	double ss = 0;

	for (long j = lo; j <= hi; j++)
		ss += rounded_d2(f, r, pt(o, j), o->dim);
	return ss;
}

/* Whether the corner at point a of o (the lines through points lo..a
 * and a..hi meeting there) fits those points worse, by more than
 * margin, than an arc tangent to two lines does (see CORNER_ROUND):
 * the lines through them but the k nearest a either side, for each k
 * from 0 that leaves two points a side, rounded at the radii whose
 * arcs meet them within the shorter line's extent (CORNER_ROUND_RADII
 * of them, a factor of sqrt 2 apart). */
static int
rounds(const struct outline *o, long lo, long a, long hi, double margin)
{
	struct line u, v;
	struct rounded f;
	double beat;

	if (!fit_line(o, lo, a - lo + 1, &u) ||
	    !fit_line(o, a, hi - a + 1, &v) || !rounded_of(&u, &v, o->dim, &f))
		return 0;
	beat = rounded_ss(o, lo, hi, &f, 0) - margin;
	for (long k = 0; a - k - lo >= 2 && hi - a - k >= 2; k++) {
		if (!fit_line(o, lo, a - k - lo + 1, &u) ||
		    !fit_line(o, a + k, hi - a - k + 1, &v) ||
		    !rounded_of(&u, &v, o->dim, &f))
			continue;
		for (int x = 0; x < CORNER_ROUND_RADII; x++) {
			double t = fmin(u.ext, v.ext) * pow(0.5, x / 2.0);

			if (rounded_ss(o, lo, hi, &f, t / tan(f.h)) < beat)
				return 1;
		}
	}
	return 0;
}

/* The margin by which two corners must fit the points better than one,
 * in the noise's variance, where that many pairs were tried (see
 * CORNER_SPLIT). */
static double
split_margin(long pairs)
{
	return fmax(CORNER_SPLIT, 2 + 2 * log((double)(pairs > 1 ? pairs : 1)));
}

/* How a split settled: how well the best split of one corner or two
 * fits the points (fit: the mean square of their distances from its
 * lines), and how much better than the cubic curve it fits them (gain:
 * the sum of squares the cubic leaves less the split's, the second
 * corner's margin added), both in the noise's variance. */
struct verdict {
	double fit, gain;
};

/* The corner or two within w points of point i: the split of the
 * points within w + m of it into two lines, or three, that fits them
 * best (each line m points at least).  Returns 1 (one corner, *a) or 2
 * (corners *a and *b), or 0 where a cubic curve fits those points
 * as well, to within CORNER_SMOOTH (a smooth bend); where it returns
 * 1 or 2 and v is not NULL, how it settled into *v.  Where w exceeds
 * CORNER_PLACES, every so many points are tried, then every point near
 * the best. */
static int
settle(const struct outline *o, long i, long w, long m, double sigma,
    long *a, long *b, struct verdict *v)
{
	struct split one = { HUGE_VAL, i, i }, two = { HUGE_VAL, i, i };
	long lo = i - w - m, hi = i + w + m, step = w / CORNER_PLACES + 1;
	long pairs = 0;
	double split, best, cubic;

	search(o, lo, hi, i - w, i + w, i + w, step, &one, &two, &pairs);
	if (step > 1) {
		struct split c1 = one, c2 = two;

		search(o, lo, hi, c1.a - step + 1, c1.a + step - 1,
		    c1.a - step, 1, &one, &two, &pairs);    /* singles only */
		if (c2.ss < HUGE_VAL)
			search(o, lo, hi, c2.a - step + 1, c2.a + step - 1,
			    c2.b + step - 1, 1, &one, &two, &pairs);
	}
	split = split_margin(pairs) * sigma * sigma;
	best = fmin(one.ss, two.ss + split);
	cubic = cubic_ss(o, lo, hi);
	if (best + CORNER_SMOOTH * sigma * sigma > cubic || (best < HUGE_VAL &&
	    rounds(o, lo, one.a, hi, CORNER_ROUND * (cubic - best))))
		return 0;
	if (v != NULL) {
		v->fit = fmin(one.ss, two.ss) / (double)(hi - lo + 1) /
		    (sigma * sigma);
		v->gain = (cubic - best) / (sigma * sigma);
	}
	if (two.ss + split < one.ss) {
		*a = two.a;
		*b = two.b;
		return 2;
	}
	*a = one.a;
	*b = one.b;
	return turns(o, lo, one.a, hi);
}

/* Where the lines through the m points up to point last and the m from
 * point first meet, into x, and the angle they turn by into *turn
 * (unless NULL); 0 where a line is missing or they are too near
 * parallel. */
static int
sides_meet(const struct outline *o, long last, long first, long m,
    double *x, double *turn)
{
	struct line u, v;

	if (!fit_line(o, last - m + 1, m, &u) || !fit_line(o, first, m, &v) ||
	    !meet(&u, &v, o->dim, x))
		return 0;
	if (turn != NULL)
		*turn = angle(u.d, v.d, o->dim);
	return 1;
}

/* The squared distances of points a..b of o (none where b < a) from
 * the line through x that fits them best (along their principal axis
 * about x).  Points missing (past the ends of an open outline) are left
 * out. */
static double
pinned_side(const struct outline *o, long a, long b, const double *x)
{
	int dim = o->dim;
	double r[LOFT_MAXDIM], u[LOFT_MAXDIM], ss = 0;

	for (; a <= b && pt(o, a) == NULL; a++)
		;
	for (; b >= a && pt(o, b) == NULL; b--)
		;
	if (b < a)
		return 0;
	vsub(u, pt(o, b), pt(o, a), dim);
	if (!(vunit(u, dim) > 0))
		vsub(u, pt(o, b), x, dim);
	if (!(vunit(u, dim) > 0))
		return 0;       /* the points all at x */
	principal_axis(o, a, b - a + 1, x, u);
	for (long t = a; t <= b; t++) {
		double d;

		vsub(r, pt(o, t), x, dim);
		d = vdot(r, u, dim);
		ss += fmax(vdot(r, r, dim) - d * d, 0);
	}
	return ss;
}

/* How well a corner pinned at x fits points lo..hi of o, split into
 * two sides at point j (j on the side where it fits better). */
static double
hinge_ss(const struct outline *o, long lo, long j, long hi, const double *x)
{
	return fmin(pinned_side(o, lo, j, x) + pinned_side(o, j + 1, hi, x),
	    pinned_side(o, lo, j - 1, x) + pinned_side(o, j, hi, x));
}

/* Whether x lies where the knot of a corner at point j of o can (see
 * CORNER_PATH): the path from the point through x to a neighbour no
 * longer than the spacing s beyond them, by CORNER_PATH times sigma
 * and CORNER_PATH_PART of s. */
static int
on_path(const struct outline *o, long j, const double *x, double sigma)
{
	double s = 0;

	for (long d = -1; d <= 1; d += 2)
		if (pt(o, j + d) != NULL && pt(o, j + 2 * d) != NULL)
			s = fmax(s, vdist(pt(o, j + d), pt(o, j + 2 * d),
			    o->dim));
	for (long d = -1; d <= 1; d += 2)
		if (pt(o, j + d) != NULL && vdist(pt(o, j), x, o->dim) +
		    vdist(x, pt(o, j + d), o->dim) <= (1 + CORNER_PATH_PART) *
		    s + CORNER_PATH * sigma)
			return 1;
	return 0;
}

/* The place of the knot of a single corner at point *j into x: where
 * the lines through the m points either side meet (not through *j,
 * which may lie on either side of the true corner), if a corner can
 * lie there (on_path), else the point itself; or *j or a neighbour,
 * where a corner pinned there fits better (see CORNER_HINGE), *j then
 * becoming that point.  sigma: the noise. */
static void
place(const struct outline *o, long *j, long m, double sigma, double *x)
{
	const double *p = pt(o, *j);
	long h = CORNER_HINGE, at = *j;
	double best;

	if (!sides_meet(o, at - 1, at + 1, m, x, NULL) ||
	    !on_path(o, at, x, sigma))
		vcopy(x, p, o->dim);
	best = hinge_ss(o, at - h, at, at + h, x) - CORNER_PIN * sigma * sigma;
	for (long d = -1; d <= 1; d++) {
		double s;

		if (pt(o, at + d) == NULL ||
		    !((s = hinge_ss(o, at - h, at, at + h, pt(o, at + d))) <
		    best))
			continue;
		best = s;
		vcopy(x, pt(o, at + d), o->dim);
		*j = at + d;
	}
}

/* Whether x lies near the gap between points j and j + 1 of o: the sum
 * of its distances from them at most twice the gap. */
static int
near_gap(const struct outline *o, long j, const double *x)
{
	return vdist(x, pt(o, j), o->dim) + vdist(x, pt(o, j + 1), o->dim) <=
	    2 * vdist(pt(o, j), pt(o, j + 1), o->dim);
}

/* The place of the knot of a corner between points *a and *a + 1 into
 * x: where the lines through the m points before and after the gap
 * meet, if near the gap (near_gap); *a becomes the point after it (the
 * points from a knot's on are fitted by the span it starts, and that
 * point lies on its line).  But where they meet farther from the gap
 * than a corner there could lie (see CORNER_APEX), the nearer of the
 * two points, *a becoming it.  0 where the lines do not meet near the
 * gap (then nothing changes).  Two corners at neighbouring points are
 * seldom two: the chord between them cuts one corner that lies between
 * them.  sigma: the noise. */
static int
place_gap(const struct outline *o, long *a, long m, double sigma, double *x)
{
	const double *p = pt(o, *a), *q = pt(o, *a + 1);
	double turn;

	if (!sides_meet(o, *a, *a + 1, m, x, &turn) || !near_gap(o, *a, x))
		return 0;
	if (sqrt(vsegdist2(p, q, x, o->dim)) > vdist(p, q, o->dim) / 2 *
	    tan(turn / 2) + CORNER_APEX * sigma) {
		if (vdist(x, p, o->dim) <= vdist(x, q, o->dim)) {
			vcopy(x, p, o->dim);
			return 1;
		}
		vcopy(x, q, o->dim);
	}
	++*a;
	return 1;
}

/* The places of the knots of two corners close together, first near
 * point *a and second near *b, into x and y: the meets of three lines,
 * through the points before the first, those between, and those after
 * the second (m of them either side), where the points split among them
 * best (by CORNER_SPLIT times the noise's variance better than with
 * the corners at the points), each split at most one point from where
 * the search put it; *a and *b become the points after the meets (as in
 * place_gap).  0 where no split does, with both meets near their gaps
 * (then nothing changes). */
static int
place_two(const struct outline *o, long *a, long *b, long m, double sigma,
    double *x, double *y)
{
	long lo = *a - m, hi = *b + m, ba = *a, bb = *b;
	double best = corner_ss(o, lo, *a, *b, hi) -
	    CORNER_SPLIT * sigma * sigma;
	int found = 0;

	for (long i = *a - 1; i <= *a + 1; i++)         /* last before */
		for (long j = *b - 1; j <= *b + 1; j++) {  /* first after */
			struct line u, v, w;
			double ss, p[LOFT_MAXDIM], q[LOFT_MAXDIM];

			if (j - i < 3 || !fit_line(o, lo, i - lo + 1, &u) ||
			    !fit_line(o, i + 1, j - i - 1, &v) ||
			    !fit_line(o, j, hi - j + 1, &w))
				continue;
			ss = u.ss + v.ss + w.ss;
			if (!(ss < best) || !meet(&u, &v, o->dim, p) ||
			    !meet(&v, &w, o->dim, q) || !near_gap(o, i, p) ||
			    !near_gap(o, j - 1, q))
				continue;
			best = ss;
			found = 1;
			vcopy(x, p, o->dim);
			vcopy(y, q, o->dim);
			ba = i + 1;
			bb = j;
		}
	if (!found)
		return 0;
	*a = ba;
	*b = bb;
	return 1;
}

/* The mean gap between neighbours among points a..b of o (those
 * there); 0 where no two are. */
static double
spacing(const struct outline *o, long a, long b)
{
	double s = 0;
	long k = 0;

	for (long t = a; t < b; t++)
		if (pt(o, t) != NULL && pt(o, t + 1) != NULL) {
			s += vdist(pt(o, t), pt(o, t + 1), o->dim);
			k++;
		}
	return k > 0 ? s / k : 0;
}

/* The corner on line l past point p, towards point q beyond it, into
 * x: the point of l on from p's foot f (dir 1 along l, -1 against it)
 * where the path p, x, q is h long, as on points evenly spaced along
 * the outline.  With x = f + t d, |x - f| + |q - x| = h gives
 * t = (h^2 - |q - f|^2) / 2 (h - d.(q - f)); at f where h is no longer
 * than |q - f|. */
static void
beyond(const struct line *l, int dir, const double *p, const double *q,
    double h, int dim, double *x)
{
	double d[LOFT_MAXDIM], r[LOFT_MAXDIM], e, t;

	vscale(d, dir, l->d, dim);
	vsub(r, p, l->c, dim);
	vcopy(x, l->c, dim);
	vaxpy(x, vdot(r, l->d, dim), l->d, dim);        /* the foot f */
	vsub(r, q, x, dim);
	e = vdot(r, r, dim);
	t = h * h > e ? (h * h - e) / (2 * (h - vdot(d, r, dim))) : 0;
	vaxpy(x, t, d, dim);
}

/* The places of the knots of two corners with one point between them,
 * at points *a and *b = *a + 2, into x and y, where place_two finds no
 * line through the points between: on the line through the m points up
 * to *a past it, and on that through those from *b before it, each
 * where the path from that point through the corner to the point
 * between is as long as the points' spacing (beyond).  A corner at a
 * point cuts the true one, which lies past it.  *a and *b become the
 * points after the knots.  0 where a line is missing. */
static int
place_cap(const struct outline *o, long *a, long *b, long m, double *x,
    double *y)
{
	struct line u, w;
	double h = (spacing(o, *a - m, *a) + spacing(o, *b, *b + m)) / 2;

	if (!fit_line(o, *a - m, m + 1, &u) || !fit_line(o, *b, m + 1, &w) ||
	    !(h > 0))
		return 0;
	beyond(&u, 1, pt(o, *a), pt(o, *a + 1), h, o->dim, x);
	beyond(&w, -1, pt(o, *b), pt(o, *a + 1), h, o->dim, y);
	++*a;
	return 1;
}

/* A corner found: its point and its knot's place. */
struct found {
	size_t i;
	double at[LOFT_MAXDIM];
};

static int
by_point(const void *a, const void *b)
{
	size_t x = ((const struct found *)a)->i;
	size_t y = ((const struct found *)b)->i;

	return (x > y) - (x < y);
}

/* The index of point j of o, counted round the end. */
static size_t
wrap(const struct outline *o, long j)
{
	return (size_t)((j % (long)o->n + (long)o->n) % (long)o->n);
}

/* The search's state: the points taken (turns there are echoes of a
 * corner settled), those that may hide a corner (see CORNER_HIDDEN),
 * and the corners found, nc of them. */
struct sought {
	unsigned char *taken, *hide;
	struct found *f;
	size_t nc;
};

/* The knots' places of the corner or two settled (k of them) at points
 * c into at (see place, place_gap and place_two), c moving with them;
 * returns how many corners are left (two at neighbouring points may
 * become one). */
static int
place_all(const struct outline *o, int k, long *c, long m, double sigma,
    double at[2][LOFT_MAXDIM])
{
	if (k == 2 && c[1] == c[0] + 1 && place_gap(o, &c[0], m, sigma,
	    at[0]))
		return 1;
	if (k == 1)
		place(o, &c[0], m, sigma, at[0]);
	else if (!place_two(o, &c[0], &c[1], m, sigma, at[0], at[1]) &&
	    (c[1] != c[0] + 2 || !place_cap(o, &c[0], &c[1], m, at[0],
	    at[1]))) {
		vcopy(at[0], pt(o, c[0]), o->dim);
		vcopy(at[1], pt(o, c[1]), o->dim);
	}
	return k;
}

/* Whether corner q of those at points c is new: at a point not taken,
 * and not the first's. */
static int
is_new(const struct outline *o, const long *c, int q,
    const unsigned char *taken)
{
	return !taken[wrap(o, c[q])] &&
	    !(q == 1 && wrap(o, c[1]) == wrap(o, c[0]));
}

/* How many of the k corners at points c are new (is_new), the last of
 * them into *q. */
static int
fresh(const struct outline *o, const long *c, int k,
    const unsigned char *taken, int *q)
{
	int nnew = 0;

	for (int x = 0; x < k; x++)
		if (is_new(o, c, x, taken)) {
			nnew++;
			*q = x;
		}
	return nnew;
}

/* Add the new ones (is_new) of the k corners at points c, their knots
 * at at, to s, and take the points within m of each, but the outermost
 * CORNER_ECHO either side. */
static void
take(const struct outline *o, const long *c, double at[2][LOFT_MAXDIM],
    int k, long m, struct sought *s)
{
	for (int q = 0; q < k; q++)
		if (is_new(o, c, q, s->taken)) {
			s->f[s->nc].i = wrap(o, c[q]);
			vcopy(s->f[s->nc].at, at[q], o->dim);
			s->nc++;
		}
	for (int q = 0; q < k; q++)
		for (long d = CORNER_ECHO - m; d <= m - CORNER_ECHO; d++)
			if (pt(o, c[q] + d) != NULL)
				s->taken[wrap(o, c[q] + d)] = 1;
}

/* The turn a single corner at point c, settled from the candidate at
 * point i with m points either side, explains: the angle between the
 * lines through the points of its window before and after it (0 where
 * a line is missing). */
static double
explained(const struct outline *o, long i, long m, long c)
{
	struct line u, v;

	return fit_line(o, i - 2 * m, c - i + 2 * m + 1, &u) &&
	    fit_line(o, c, i + 2 * m - c + 1, &v) ? angle(u.d, v.d, o->dim) :
	    0;
}

/* Mark the points within len of point c of o, either side, as ones
 * that may hide a corner. */
static void
may_hide(const struct outline *o, long c, double len, unsigned char *hide)
{
	for (long d = -reach(o, c, -1, len); d <= reach(o, c, 1, len); d++)
		hide[wrap(o, c + d)] = 1;
}

/* The tip of the U-turn whose turn over the scale len is sharpest at
 * point i: where the turn over twice the scale reaches
 * CORNER_PAIR_TURN, the point within len of i farthest along the
 * direction the two lines either side of it point in together; else i.
 * Where the U (the end of a slab, a stroke) is narrower than the scale,
 * every point within the scale of it turns by about 180 degrees, and
 * the sharpest of them, its window too, may lie far from the end. */
static long
u_tip(const struct outline *o, long i, double len)
{
	long a = reach(o, i, -1, len), b = reach(o, i, 1, len), best = i;
	struct line u, v;
	double d[LOFT_MAXDIM], x[LOFT_MAXDIM], far = 0;

	if (a == 0 || b == 0 || turn_at(o, i, 2 * len, 0) < CORNER_PAIR_TURN ||
	    !fit_line(o, i - a, a + 1, &u) || !fit_line(o, i, b + 1, &v))
		return i;
	vsub(d, u.d, v.d, o->dim);
	if (!(vunit(d, o->dim) > 0))
		return i;
	for (long j = i - a; j <= i + b; j++) {
		vsub(x, pt(o, j), pt(o, i), o->dim);
		if (vdot(x, d, o->dim) > far) {
			far = vdot(x, d, o->dim);
			best = j;
		}
	}
	return (long)wrap(o, best);
}

/* Whether the lines through points lo..a and b..hi of o turn by
 * CORNER_END_TURN at least: the end between them lies between parallel
 * sides, as a slab's or a stroke's does. */
static int
between_parallels(const struct outline *o, long lo, long a, long b,
    long hi)
{
	struct line u, v;

	return fit_line(o, lo, a - lo + 1, &u) &&
	    fit_line(o, b, hi - b + 1, &v) &&
	    angle(u.d, v.d, o->dim) >= CORNER_END_TURN;
}

/* Settle again from the tip of the U-turn at point *i (u_tip), its
 * scale len: the corners found there into c (their count returned),
 * where the lines either side of them turn as a slab's end does
 * (between_parallels) and their split fits no worse than v->fit (see
 * settle); *i and *m become the tip and the points within half the
 * scale of it, and *v how it settled there.  0 otherwise, nothing
 * changed. */
static int
settle_tip(const struct outline *o, long *i, long *m, double len,
    double sigma, const unsigned char *taken, long *c, struct verdict *v)
{
	long j = u_tip(o, *i, len), mj = reach(o, j, 1, len / 2), cj[2];
	struct verdict vj;
	int k;

	if (mj < 2)
		mj = 2;
	if (j == *i || taken[j] ||
	    (k = settle(o, j, mj, mj, sigma, &cj[0], &cj[1], &vj)) == 0 ||
	    vj.fit > v->fit ||
	    !between_parallels(o, j - 2 * mj, cj[0], cj[k - 1], j + 2 * mj))
		return 0;
	c[0] = cj[0];
	c[1] = cj[1];
	*i = j;
	*m = mj;
	*v = vj;
	return k;
}

/* Where the split of k corners c at point i, m points a side, fits
 * worse than CORNER_MISFIT (how it settled in *v), settle it again
 * with sides of CORNER_SHORTER times fewer points (two at least), and
 * take that split where it fits CORNER_SHORTER_FIT times better: its
 * corners into c, how it settled into *v (the knots are still placed
 * with sides of m points).  Returns the corners then. */
static int
settle_shorter(const struct outline *o, long i, long m, double sigma,
    long *c, struct verdict *v, int k)
{
	long cs[2], ms = m / CORNER_SHORTER;
	struct verdict vs;
	int ks;

	if (ms < 2)
		ms = 2;
	if (v->fit <= CORNER_MISFIT || ms >= m ||
	    (ks = settle(o, i, m, ms, sigma, &cs[0], &cs[1], &vs)) == 0 ||
	    !(vs.fit * CORNER_SHORTER_FIT < v->fit))
		return k;
	c[0] = cs[0];
	c[1] = cs[1];
	*v = vs;
	return ks;
}

/* The corner or two a gentle candidate at point i (its turn t, m
 * points either side within half the scale), settled as a bend, hides
 * from its window (see CORNER_GENTLE): the split with w = m and sides
 * of CORNER_WIDER m points, its corners into c and how it settled
 * into *v, where it fits within CORNER_WIDE_FIT, gains CORNER_WIDE_GAIN
 * on the cubic, and its outer lines turn by at most CORNER_CONCENTRATED
 * t.  Returns how many corners, 0 where none is so taken. */
static int
settle_wide(const struct outline *o, long i, long m, double t,
    double sigma, long *c, struct verdict *v)
{
	long mw = CORNER_WIDER * m;
	struct line u, w;
	int k;

	if (t >= CORNER_GENTLE ||
	    (k = settle(o, i, m, mw, sigma, &c[0], &c[1], v)) == 0 ||
	    v->fit > CORNER_WIDE_FIT || v->gain < CORNER_WIDE_GAIN ||
	    !fit_line(o, c[0] - m - mw, m + mw + 1, &u) ||
	    !fit_line(o, c[k - 1], m + mw + 1, &w))
		return 0;
	return angle(u.d, w.d, o->dim) <= CORNER_CONCENTRATED * t ? k : 0;
}

/* How many of the n points of o past point from, going by step (1 or
 * -1), lie before the first point taken (taken: the points of the
 * corners found); -1 where the outline ends among them. */
static long
free_side(const struct outline *o, long from, int step, long n,
    const unsigned char *taken)
{
	for (long j = 1; j <= n; j++) {
		const double *p = pt(o, from + step * j);

		if (p == NULL)
			return -1;
		if (taken[wrap(o, from + step * j)])
			return j - 1;
	}
	return n;
}

/* Whether the split of k corners c, settled with sides of m points as
 * v, is faint (see CORNER_FAINT): it gains less than CORNER_FAINT on
 * the cubic, and with sides of CORNER_FAINT_SIDES m points, short of
 * the points of the corners found (taken), less than
 * CORNER_FAINT_WIDE.  Not where those sides run past an end. */
static int
faint(const struct outline *o, const long *c, int k, long m, double sigma,
    const struct verdict *v, const unsigned char *taken)
{
	long more = (CORNER_FAINT_SIDES - 2) * m, lo, hi;
	long a = free_side(o, c[0] - 2 * m, -1, more, taken);
	long b = free_side(o, c[k - 1] + 2 * m, 1, more, taken);
	double split, cubic;

	if (v->gain >= CORNER_FAINT || a < 0 || b < 0)
		return 0;
	lo = c[0] - 2 * m - a;
	hi = c[k - 1] + 2 * m + b;
	split = corner_ss(o, lo, c[0], c[k - 1], hi);
	cubic = cubic_ss(o, lo, hi);
	return split < HUGE_VAL && cubic < HUGE_VAL &&
	    cubic - split < CORNER_FAINT_WIDE * sigma * sigma;
}

/* The passes that settle candidates: the first, where a corner that may
 * hide another is left to later; the later; and the second look at the
 * points the corners found shadowed (see CORNER_SHADOWED). */
enum pass { FIRST, LATER, SHADOWED };

/* Settle the candidate at point i (its turn t over the scale len, m
 * points either side of it within half that), or where that finds a
 * bend, or a split that fits worse than CORNER_MISFIT, at the tip of
 * its U-turn (settle_tip), a bend not so settled with longer sides
 * (settle_wide; not in the pass SHADOWED), and a split that still fits
 * that badly with shorter sides (settle_shorter), its corners and
 * their knots' places into s: not where the split is faint (see
 * CORNER_FAINT), and in the pass SHADOWED only where it gains
 * CORNER_SHADOWED on the cubic and fits within CORNER_MISFIT.  A corner
 * settled alone that explains CORNER_HIDDEN less than t is left to
 * later (returns -1, nothing changed) in the pass FIRST; else the
 * points within len of it may hide another (returns 1).  Returns 0
 * otherwise. */
static int
settle_one(const struct outline *o, long i, long m, double t, double len,
    double sigma, enum pass pass, struct sought *s)
{
	long c[2];
	double at[2][LOFT_MAXDIM];
	struct verdict v = { HUGE_VAL, 0 };
	int k, hides;

	if (m < 2)
		m = 2;
	if (s->taken[i])
		return 0;
	if ((k = settle(o, i, m, m, sigma, &c[0], &c[1], &v)) == 0) {
		if ((k = settle_tip(o, &i, &m, len, sigma, s->taken, c,
		    &v)) == 0 && (pass == SHADOWED ||
		    (k = settle_wide(o, i, m, t, sigma, c, &v)) == 0))
			return 0;       /* a bend: its points stay free */
	} else if (v.fit > CORNER_MISFIT) {
		int kt = settle_tip(o, &i, &m, len, sigma, s->taken, c, &v);

		k = settle_shorter(o, i, m, sigma, c, &v, kt > 0 ? kt : k);
	}
	if ((pass == SHADOWED && (v.gain < CORNER_SHADOWED ||
	    v.fit > CORNER_MISFIT)) || faint(o, c, k, m, sigma, &v, s->taken))
		return 0;
	hides = k == 1 && t - explained(o, i, m, c[0]) > CORNER_HIDDEN;
	if (hides && pass == FIRST)
		return -1;
	k = place_all(o, k, c, m, sigma, at);
	hides = hides && !s->taken[wrap(o, c[0])];
	if (hides)
		may_hide(o, c[0], len, s->hide);
	take(o, c, at, k, m, s);
	return hides;
}

/* Settle each candidate (their turns at the scale len in turn),
 * sharpest first, into s, those left to later (see settle_one) last;
 * cand is reordered.  Returns how many corners may hide another. */
static size_t
settle_all(const struct outline *o, size_t *cand, size_t ncand,
    const long *half, const double *turn, double len, double sigma,
    struct sought *s)
{
	size_t hiding = 0, later = 0;

	for (size_t x = 0; x < ncand; x++) {
		long i = (long)cand[x];
		int r = settle_one(o, i, half[i], turn[i], len, sigma, FIRST,
		    s);

		if (r < 0)
			cand[later++] = (size_t)i;
		hiding += r > 0;
	}
	for (size_t x = 0; x < later; x++) {
		long i = (long)cand[x];

		hiding += settle_one(o, i, half[i], turn[i], len, sigma,
		    LATER, s) > 0;
	}
	return hiding;
}

/* Settle the candidates at CORNER_FINER of the scale len (their turns
 * there in turn) that may hide a corner, and turn by CORNER_HIDDEN at
 * least, into s: each only where it adds one corner, at a point that
 * may hide one (see CORNER_HIDDEN). */
static void
settle_hidden(const struct outline *o, const size_t *cand, size_t ncand,
    const double *turn, double len, double sigma, struct sought *s)
{
	for (size_t x = 0; x < ncand; x++) {
		long i = (long)cand[x], m = reach(o, i, 1, CORNER_FINER * len);
		long c[2];
		double at[2][LOFT_MAXDIM];
		int k, q = 0;

		if (m < 2)
			m = 2;
		if (s->taken[i] || !s->hide[i] || turn[i] < CORNER_HIDDEN ||
		    (k = settle(o, i, m, m, sigma, &c[0], &c[1], NULL)) == 0)
			continue;
		k = place_all(o, k, c, m, sigma, at);
		if (fresh(o, c, k, s->taken, &q) == 1 &&
		    s->hide[wrap(o, c[q])])
			take(o, c, at, k, m, s);
	}
}

/* A candidate: its point and its turn. */
struct turn {
	double t;
	size_t i;
};

static int
by_turn(const void *a, const void *b)
{
	const struct turn *x = a, *y = b;

	if (x->t != y->t)
		return x->t < y->t ? 1 : -1;
	return (x->i > y->i) - (x->i < y->i);
}

/* Order the nc points cand by their turns, sharpest first (the first
 * point of equals first); t: room for nc. */
static void
sharpest_first(size_t *cand, size_t nc, const double *turn, struct turn *t)
{
	for (size_t x = 0; x < nc; x++)
		t[x] = (struct turn){ turn[cand[x]], cand[x] };
	qsort(t, nc, sizeof *t, by_turn);
	for (size_t x = 0; x < nc; x++)
		cand[x] = t[x].i;
}

/* Whether the turn t at point i of o over the scale len is a smooth
 * bend's: twice the length, twice the turn, where a corner's turn is
 * about the same.  Unless the turn over twice the scale is as sharp as
 * CORNER_PAIR_TURN and half the scale turns as much as the whole: then
 * two corners lie within twice the scale (the end of a slab, a serif),
 * and the longer lines turn at both.  The turn over half the scale is
 * weighed as measured, not taken as none where it is within the
 * noise's reach: t is a turn already, and the lines half as long are
 * within that reach at most noisy corners.  (Taken as none, the feet
 * of stems 1 to 2 scales wide were bends: DejaVu Sans's d.) */
static int
bend(const struct outline *o, long i, double len, double t)
{
	double t2 = turn_at(o, i, 2 * len, 0);

	return t2 > CORNER_CONCENTRATED * t && !(t2 >= CORNER_PAIR_TURN &&
	    CORNER_CONCENTRATED * turn_at(o, i, len / 2, 0) >= t);
}

/* The points of o whose turns (turn) are the sharpest within half the
 * scale len, and CORNER_TURN at least, into cand, sharpest first, and
 * the points after each within half the scale into half (t: scratch,
 * room for o->n); returns how many. */
static size_t
maxima(const struct outline *o, double len, const double *turn, long *half,
    size_t *cand, struct turn *t)
{
	size_t nc = 0;
	long n = (long)o->n;

	for (long i = 0; i < n; i++) {
		long a = reach(o, i, -1, len / 2), b = reach(o, i, 1, len / 2);
		int best = turn[i] >= CORNER_TURN && a > 0 && b > 0;

		/* the sharpest within half the scale (the first of equals) */
		for (long j = i - a; best && j <= i + b; j++)
			if (j != i && (turn[(j + n) % n] > turn[i] ||
			    (j < i && turn[(j + n) % n] == turn[i])))
				best = 0;
		if (best) {
			half[i] = b;
			cand[nc++] = (size_t)i;
		}
	}
	sharpest_first(cand, nc, turn, t);
	return nc;
}

/* The turns of o at the scale len into turn (0 where none is a
 * corner's), and its candidates (see maxima); returns how many. */
static size_t
candidates(const struct outline *o, double len, double *turn, long *half,
    size_t *cand, struct turn *t)
{
	for (long i = 0; i < (long)o->n; i++)
		if ((turn[i] = turn_at(o, i, len, 1)) > 0 && bend(o, i, len,
		    turn[i]))
			turn[i] = 0;
	return maxima(o, len, turn, half, cand, t);
}

/* How many points from point i the first one at least len from it lies
 * (see reach), or the first of the corners marked in corner, if that
 * is nearer; 0 where neither is. */
static long
reach_to(const struct outline *o, long i, int dir, double len,
    const unsigned char *corner)
{
	long r = reach(o, i, dir, len);

	for (long k = 1; k < r; k++)
		if (corner[wrap(o, i + dir * k)])
			return k;
	return r;
}

/* How many points either side of point i of o its settling may use:
 * m, or half as many as lie between it and the nearest corner marked
 * in corner, if fewer. */
static long
short_of(const struct outline *o, long i, long m, const unsigned char *corner)
{
	for (long k = 1; k < 2 * m; k++)
		if ((pt(o, i + k) != NULL && corner[wrap(o, i + k)]) ||
		    (pt(o, i - k) != NULL && corner[wrap(o, i - k)]))
			return k / 2;
	return m;
}

/* Settle the corners that those in s shadowed (see CORNER_SHADOWED) at
 * the scale len into s: none where s has none (a smooth outline costs
 * no second look); corner, turn, half, cand and t: scratch, room for
 * o->n each. */
static void
settle_shadowed(const struct outline *o, double len, double sigma,
    unsigned char *corner, double *turn, long *half, size_t *cand,
    struct turn *t, struct sought *s)
{
	size_t nc;

	if (s->nc == 0)
		return;
	memset(corner, 0, o->n);
	for (size_t x = 0; x < s->nc; x++)
		corner[s->f[x].i] = 1;
	for (long i = 0; i < (long)o->n; i++) {
		turn[i] = s->taken[i] ? 0 : turn_over(o, i,
		    reach_to(o, i, -1, len, corner),
		    reach_to(o, i, 1, len, corner), 1);
		if (turn[i] > 0 && (bend(o, i, len, turn[i]) ||
		    CORNER_CONCENTRATED * turn_at(o, i, len / 2, 0) < turn[i]))
			turn[i] = 0;
	}
	nc = maxima(o, len, turn, half, cand, t);
	for (size_t x = 0; x < nc; x++) {
		long i = (long)cand[x], m = short_of(o, i, half[i], corner);

		if (m >= 2)
			settle_one(o, i, m, turn[i], len, sigma, SHADOWED, s);
	}
}

/* The corners of the outline o at the scale len (its tolerance tol):
 * into f, their count into *nc.  0, or -1 out of memory. */
static int
find(const struct outline *o, double len, double tol, struct found *f,
    size_t *nc)
{
	size_t n = o->n, ncand;
	double *turn = malloc(n * sizeof *turn), sigma;
	long *half = malloc(n * sizeof *half);
	size_t *cand = malloc(n * sizeof *cand);
	struct sought s = { calloc(n, 1), calloc(n, 1), f, 0 };
	struct turn *t = malloc(n * sizeof *t);
	unsigned char *corner = malloc(n);
	int rc = -1;

	if (turn != NULL && half != NULL && cand != NULL && s.taken != NULL &&
	    s.hide != NULL && t != NULL && corner != NULL) {
		sigma = fmax(noise(o, turn), CORNER_NOISE_FLOOR * tol);
		ncand = candidates(o, len, turn, half, cand, t);
		if (settle_all(o, cand, ncand, half, turn, len, sigma, &s) > 0) {
			ncand = candidates(o, CORNER_FINER * len, turn, half,
			    cand, t);
			settle_hidden(o, cand, ncand, turn, len, sigma, &s);
		}
		settle_shadowed(o, len, sigma, corner, turn, half, cand, t,
		    &s);
		*nc = s.nc;
		rc = 0;
	}
	free(turn);
	free(half);
	free(cand);
	free(s.taken);
	free(s.hide);
	free(t);
	free(corner);
	return rc;
}

/* The scale of o at the tolerance tol: CORNER_TOLS of it, or
 * CORNER_SPACINGS mean spacings of the points, the longer. */
static double
scale(const struct outline *o, double tol)
{
	double len = 0;

	for (long i = 1; i <= (long)o->n; i++)
		if (i < (long)o->n || o->closed)
			len += vdist(pt(o, i), pt(o, i - 1), o->dim);
	return fmax(CORNER_TOLS * tol, CORNER_SPACINGS * len / (double)o->n);
}

/* How many points of o make a run averaged into one before corners are
 * sought: 1, or where the points within len of a point (the median of
 * CORNER_PROBES spread round o) are more than CORNER_DENSE, as many as
 * leave CORNER_DENSE / 2 of them. */
static size_t
run_length(const struct outline *o, double len)
{
	double k[CORNER_PROBES];
	size_t nk = 0;

	for (size_t i = 0; i < CORNER_PROBES; i++) {
		long r = reach(o, (long)(i * o->n / CORNER_PROBES), 1, len);

		if (r > 0)
			k[nk++] = (double)r;
	}
	if (nk == 0)
		return 1;
	qsort(k, nk, sizeof *k, by_value);
	return k[nk / 2] <= CORNER_DENSE ? 1 :
	    (size_t)(k[nk / 2] / (CORNER_DENSE / 2));
}

/* The points of o averaged in runs of g into q (room for o->n / g + 1
 * points; the last run may be shorter); returns their count. */
static size_t
coarsen(const struct outline *o, size_t g, double *q)
{
	size_t m = 0;

	for (size_t a = 0; a < o->n; a += g, m++) {
		size_t k = o->n - a < g ? o->n - a : g;

		for (int d = 0; d < o->dim; d++)
			q[m * o->dim + d] = 0;
		for (size_t j = a; j < a + k; j++)
			vaxpy(q + m * o->dim, 1.0 / (double)k, o->p + j * o->dim,
			    o->dim);
	}
	return m;
}

/* The point of o in runs c - 1 .. c + 1 of g nearest x: where a corner
 * found among the runs lies among the points. */
static size_t
uncoarsen(const struct outline *o, size_t g, size_t c, const double *x)
{
	long best = (long)(c * g);
	double d = HUGE_VAL;

	for (long j = ((long)c - 1) * (long)g; j < ((long)c + 2) * (long)g; j++)
		if (pt(o, j) != NULL && vdist(pt(o, j), x, o->dim) < d) {
			d = vdist(pt(o, j), x, o->dim);
			best = j;
		}
	return wrap(o, best);
}

/* The corners of o (its points in the unit box) at the tolerance tol,
 * into f, their count into *nc, in order along o; a run of dense points
 * is first averaged into one.  0, or -1 out of memory. */
static int
find_dense(const struct outline *o, double tol, struct found *f, size_t *nc)
{
	double len = scale(o, tol), *q;
	size_t g = run_length(o, len), k = 0;
	struct outline c = *o;
	int rc;

	if (g == 1)
		rc = find(o, len, tol, f, nc);
	else if ((q = malloc((o->n / g + 1) * o->dim * sizeof *q)) == NULL)
		return -1;
	else {
		c.p = q;
		c.n = coarsen(o, g, q);
		if ((rc = find(&c, len, tol, f, nc)) == 0)
			for (size_t x = 0; x < *nc; x++)
				f[x].i = uncoarsen(o, g, f[x].i, f[x].at);
		free(q);
	}
	qsort(f, *nc, sizeof *f, by_point);
	for (size_t x = 0; x < *nc; x++)        /* two runs, one point */
		if (k == 0 || f[x].i != f[k - 1].i)
			f[k++] = f[x];
	*nc = k;
	return rc;
}

/* The n points p (dimension dim) scaled by 2^-e (unit_exponent), in a
 * new array; NULL out of memory. */
static double *
scaled(const double *p, size_t n, int dim, int e)
{
	double *q = calloc(n, (size_t)dim * sizeof *q);

	for (size_t i = 0; q != NULL && i < n; i++)
		for (int k = 0; k < dim; k++)
			q[i * dim + k] = ldexp(p[i * dim + k], -e);
	return q;
}

size_t
loft_find_corners(const double *p, size_t n, int dim, int closed, double tol,
    size_t *corner, double *at)
{
	double *q;
	struct found *f;
	struct outline o = { NULL, n, dim, closed };
	size_t nc = 0;
	int e;

	if (n < 5 || dim < 1 || dim > LOFT_MAXDIM || !(tol > 0) ||
	    !isfinite(tol) || unit_exponent(p, n, dim, &e) != 0)
		return 0;
	/* scaled, so that the corners do not depend on the units */
	q = scaled(p, n, dim, e);
	f = malloc(n * sizeof *f);
	if (q == NULL || f == NULL) {
		free(q);
		free(f);
		return (size_t)-1;
	}
	o.p = q;
	if (find_dense(&o, ldexp(tol, -e), f, &nc) == 0)
		for (size_t c = 0; c < nc; c++) {
			corner[c] = f[c].i;
			for (int k = 0; at != NULL && k < dim; k++)
				at[c * dim + k] = ldexp(f[c].at[k], e);
		}
	else
		nc = (size_t)-1;
	free(q);
	free(f);
	return nc;
}

double
loft_points_noise(const double *p, size_t n, int dim, int closed)
{
	struct outline o = { NULL, n, dim, closed };
	double *q, *r, s = 0;
	int e;

	if (n < 3 || dim < 1 || dim > LOFT_MAXDIM ||
	    unit_exponent(p, n, dim, &e) != 0)
		return 0;
	q = scaled(p, n, dim, e);
	r = malloc(n * sizeof *r);
	if (q != NULL && r != NULL) {
		o.p = q;
		s = ldexp(noise(&o, r), e);
	}
	/* noise() reads the distance across a plane outline; in space it
	 * has two directions across, and its median is sqrt(2 ln 2) times
	 * the deviation in each, not 0.6745 times */
	if (dim == 3)
		s *= 0.6745 / sqrt(2 * log(2.0));
	free(q);
	free(r);
	return s;
}

/* The signed turn of the plane polyline o at point i (radians, left
 * positive); 0 where a side is missing or has no length. */
static double
signed_turn(const struct outline *o, long i)
{
	const double *a = pt(o, i - 1), *b = pt(o, i), *c = pt(o, i + 1);
	double u[2], v[2];

	if (a == NULL || c == NULL)
		return 0;
	vsub(u, b, a, 2);
	vsub(v, c, b, 2);
	if (!(vunit(u, 2) > 0) || !(vunit(v, 2) > 0))
		return 0;
	return atan2(u[0] * v[1] - u[1] * v[0], vdot(u, v, 2));
}

/* The turns of the plane points p (n, scaled to unit exponent so that
 * no product overflows) into t; 0 or -1 out of memory. */
static int
plane_turns(const double *p, size_t n, int closed, double *t)
{
	struct outline o = { NULL, n, 2, closed };
	int e;

	if (unit_exponent(p, n, 2, &e) != 0) {
		memset(t, 0, n * sizeof *t);
		return 0;
	}
	if ((o.p = scaled(p, n, 2, e)) == NULL)
		return -1;
	for (size_t i = 0; i < n; i++)
		t[i] = signed_turn(&o, (long)i);
	free((void *)o.p);
	return 0;
}

size_t
loft_sharp_points(const double *p, size_t n, int closed, double turn,
    size_t *corner, size_t *flex)
{
	double *t, last = 0;
	size_t nc = 0;

	*flex = 0;
	if (n < 3 || (t = malloc(n * sizeof *t)) == NULL)
		return n < 3 ? 0 : (size_t)-1;
	if (plane_turns(p, n, closed, t) != 0) {
		free(t);
		return (size_t)-1;
	}
	for (size_t i = n; closed && last == 0 && i-- > 0;)
		last = t[i];    /* round the end */
	for (size_t i = 0; i < n; i++) {
		if (t[i] != 0 && last != 0 && (t[i] > 0) != (last > 0))
			(*flex)++;
		last = t[i] != 0 ? t[i] : last;
		if (fabs(t[i]) >= turn)
			corner[nc++] = i;
	}
	free(t);
	return nc;
}
