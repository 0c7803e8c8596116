#!/bin/sh
# run.sh: the benchmark behind `make bench`, run from the top of the tree.
# It makes the corpora, then times every case once per rep, the cases
# interleaved, REPS reps (default 5), and prints each case's median time
# and the median of the per-rep ratios.  Cases whose tool is missing are
# skipped with a line saying so.  Not a test: times depend on the machine.
#
#   REPS=5 N=10000 PYTHON=python3 SPLINE=spline sh tests/bench/run.sh
#
# Needs sh, the programs in bin/ and bin/bench/ (make bench builds them),
# and optionally GNU plotutils spline and Python with scipy.  fromcad's
# case reads a DXF of the N insoles (50 MB for N=10000) against the
# time to read its bytes as numbers (bin/bench/numbers, and awk).

B=bin
W=bin/bench
REPS=${REPS:-5}
N=${N:-10000}
PYTHON=${PYTHON:-python3}
SPLINE=${SPLINE:-spline}
OUT=$W/times

echo "bench: making the corpora in $W: $N insoles, an outline of 10^6" \
    "knots, a space curve of 20000 knots"
$W/gen insoles "$N" man/figures/insole.knots >$W/insoles.knots || exit 1
$W/gen spline $W/insoles.knots >$W/insoles.spline || exit 1
$W/gen outline 1000000 >$W/outline.knots || exit 1
$W/gen space 20000 >$W/space.knots || exit 1
$W/gen spline $W/space.knots >$W/space.spline || exit 1
$B/splinefit $W/insoles.knots >$W/insoles.cubic || exit 1
# an SVG path of 10^5 and of 10^6 cubic segments: fromcad in linear time
for n in 100000 1000000; do
	awk -v n=$n 'BEGIN { printf "<svg><path d=\"M0 0"; for (i = 0; i < n; i++)
	    printf "c1 0 1 1 1 1"; printf "\"/></svg>\n" }' >$W/path$n.svg
done
# 20,000 labelled records crowded on a grid (loftplot -l placed them in cubic
# time once), and a bezier-surface of 64 x 64 control points
awk 'BEGIN { for (i = 0; i < 20000; i++) printf "points id=%d\n%d %d\n%d %d\n\n",
    i, i % 140, int(i / 140), i % 140 + 1, int(i / 140) }' >$W/labels.pts
# issue 28: 10^4 and 10^3 labelled segments placed at random on a
# square (one seed), a crowd on loftplot's 640 pixels either way
for n in 1000 10000; do
	awk -v n=$n 'BEGIN { srand(28); side = sqrt(n); for (i = 0; i < n; i++) {
	    x = rand() * side; y = rand() * side
	    printf "points id=%d\n%.4f %.4f\n%.4f %.4f\n\n", i, x, y, x + rand(), y + rand() } }' \
	    >$W/labels$n.pts
done
awk 'BEGIN { print "bezier-surface m=63 n=63"; for (i = 0; i < 64; i++)
    for (j = 0; j < 64; j++) printf "%d %d %.6f\n", i, j, sin(i / 9) * cos(j / 7) }' \
    >$W/surface63.bez
# issue 17: 100 sections of 100 segments (patchloft under 1 s); 101 of
# them lofted, 10000 patches, cut by 50 planes (patchcut under 2 s)
awk -v n=101 'BEGIN { for (k = 0; k < n; k++) { print "points"
	for (i = 0; i <= 100; i++) { t = i / 100
	    x = (1 + 0.3 * sin(k / 10)) * sin(1.5 * t) + 0.01 * k * t
	    printf "%d %.17g %.17g\n", k, x, 0.5 * cos(2 * t) + 0.002 * k }
	print "" } }' >$W/sections.knots || exit 1
$B/splinefit -o $W/sections.knots >$W/sections101.cubic || exit 1
# issue 14: the insole of man/figures/insole.knots, 10^5 and 10^4
# points with 0.3 mm of noise, for splinefit -e 1.6 (5.3 sigma)
bin/test/noisy -n 100000 -s 0.3 -r 14 insole man/figures/insole.knots \
    >$W/noisy100000.pts || exit 1
bin/test/noisy -n 10000 -s 0.3 -r 14 insole man/figures/insole.knots \
    >$W/noisy10000.pts || exit 1
awk '/^points/ && ++n == 101 { exit } { print }' $W/sections.knots |
    $B/splinefit -o >$W/sections.cubic || exit 1
$B/patchloft $W/sections101.cubic >$W/hull.design || exit 1
# issue 26: a plate of 100 patches (11 sections of 10 segments, lofted),
# doubly curved, for unroll (under 1 s), against tocad -f stl's mesh of it
awk -v n=11 'BEGIN { for (k = 0; k < n; k++) { print "points"
	for (i = 0; i <= 10; i++) { t = i / 10
	    x = (1 + 0.3 * sin(k / 3)) * sin(1.5 * t) + 0.1 * k * t
	    printf "%d %.17g %.17g\n", k, x, 0.5 * cos(2 * t) + 0.02 * k }
	print "" } }' | $B/splinefit -o | $B/patchloft >$W/plate100.design ||
    exit 1
# issue 25: a half hull of 1000 patches, 41 stations of 26 knots (the
# end stations on the centreplane), for a 20-waterline hydro table
awk 'BEGIN { for (i = 0; i < 41; i++) { x = 2.5 * i; f = 1 - (x / 50 - 1)^2
	print "points"; for (j = 0; j < 26; j++) { t = j / 25
	    printf "%.6f %.6f %.6f\n", x, 6 * f * (1 - (1 - t)^4), 8 * t }
	print "" } }' | $B/splinefit -o | $B/patchloft >$W/hull1000.design || exit 1
# fromcad's corpus: the fitted insoles sampled 8 points a segment, each a
# closed LWPOLYLINE of 177 vertices on layer 1, in millimetres: 50 MB
echo "bench: making $W/insoles.dxf: the insoles as 10^4 LWPOLYLINEs, 50 MB"
$B/sample -n 8 -p 10 $W/insoles.cubic | awk '
function flush() {
	if (n) printf "0\nLWPOLYLINE\n5\n%X\n8\n1\n90\n%d\n70\n1\n%s", ++h, n, v
	n = 0; v = ""
}
BEGIN { printf "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" }
NF { v = v sprintf("10\n%s\n20\n%s\n", $1, $2); n++; next }
{ flush() }
END { flush(); printf "0\nENDSEC\n0\nEOF\n" }' >$W/insoles.dxf || exit 1

have_spline=0
if command -v "$SPLINE" >/dev/null 2>&1 &&
    echo "0 0" | "$SPLINE" -a -d 2 -n 1 >/dev/null 2>&1; then
	have_spline=1
else
	echo "bench: GNU spline ($SPLINE) not installed: its cases skipped"
fi
have_scipy=0
if "$PYTHON" -c 'import scipy.interpolate, numpy' >/dev/null 2>&1; then
	have_scipy=1
else
	echo "bench: scipy not installed for $PYTHON: its case skipped"
fi

# case NAME COMMAND: time COMMAND for this rep
case_() {
	t=$($W/timeit "$2") || echo "bench: $1 failed: $2" >&2
	echo "$rep $1 $t" >>$OUT
}

: >$OUT
rep=1
while [ "$rep" -le "$REPS" ]; do
	echo "bench: rep $rep of $REPS"
	case_ floor "$W/floor -n 20 $W/insoles.knots"
	case_ floor-printf "$W/floor -f -n 20 $W/insoles.knots"
	case_ floor-p6 "$W/floor -p 6 -n 20 $W/insoles.knots"
	case_ splinefit "$B/splinefit $W/insoles.knots"
	case_ sample "$B/sample -n 20 $W/insoles.cubic"
	case_ floor-sample "$W/floor -n 20 $W/insoles.cubic"
	case_ offset "$B/offset -d 15 $W/insoles.cubic"
	case_ offset-lining "$B/offset -d -5 $W/insoles.cubic"
	case_ measure "$B/measure $W/insoles.cubic"
	case_ sample-s "$B/sample -s 1.4 $W/insoles.cubic"
	case_ pipeline "$B/splinefit $W/insoles.knots | $B/sample -n 20"
	case_ pipeline-p6 "$B/splinefit $W/insoles.knots | $B/sample -n 20 -p 6"
	[ $have_spline = 1 ] &&
	    case_ gnu-spline "$SPLINE -a -d 2 -p -n 440 $W/insoles.spline"
	[ $have_scipy = 1 ] &&
	    case_ scipy "$PYTHON tests/bench/scipy_spline.py 20 $W/insoles.knots"
	case_ fromcad-path "$B/fromcad $W/path1000000.svg"
	case_ fromcad-path-small "$B/fromcad $W/path100000.svg"
	case_ loftplot-labels "$B/loftplot -l id $W/labels.pts"
	case_ labels-1e4 "$B/loftplot -l id $W/labels10000.pts"
	case_ labels-1e3 "$B/loftplot -l id $W/labels1000.pts"
	case_ surface-63 "$B/sample -n 100 $W/surface63.bez"
	case_ outline-fit "$B/splinefit $W/outline.knots"
	case_ space "$B/splinefit $W/space.knots | $B/sample -n 20"
	case_ fromcad "$B/fromcad $W/insoles.dxf"
	case_ dxf-numbers "$W/numbers $W/insoles.dxf"
	case_ dxf-awk "awk '{ s += \$1 } END { print s }' $W/insoles.dxf"
	[ $have_spline = 1 ] &&
	    case_ space-gnu "$SPLINE -a -d 3 -p -n 400000 $W/space.spline"
	case_ tocad-dxf "$B/tocad -f dxf -n 20 $W/insoles.cubic"
	case_ tocad-dxf-tol "$B/tocad -f dxf $W/insoles.cubic"
	case_ sample-n25 "$B/sample -n 25 $W/insoles.cubic"
	case_ patchloft "$B/patchloft $W/sections.cubic"
	case_ patchcut "$B/patchcut -x 0.5:98.5:2 $W/hull.design"
	case_ unroll "$B/unroll $W/plate100.design"
	case_ stl-plate "$B/tocad -f stl -n 6 $W/plate100.design"
	case_ hydro "$B/hydro -z 1:6.7:0.3 $W/hull1000.design"
	case_ patchcut-wl "$B/patchcut -z 1:6.7:0.3 $W/hull1000.design"
	case_ approx "$B/splinefit -e 1.6 $W/noisy100000.pts"
	case_ approx-small "$B/splinefit -e 1.6 $W/noisy10000.pts"
	case_ interp-noisy "$B/splinefit -d 0 $W/noisy100000.pts"
	rep=$((rep + 1))
done
echo
echo "bench: insoles: $N outlines of 22 knots, 441 points each (sample" \
    "-n 20; GNU spline -n 440; sample -s 1.4 about as many); offset -d 15" \
    "and -d -5 of their curves"
$W/timeit -r $OUT pipeline/gnu-spline pipeline-p6/gnu-spline \
    pipeline/floor pipeline-p6/floor-p6 splinefit/floor sample/floor-sample \
    floor-printf/floor floor/gnu-spline scipy/gnu-spline \
    space/space-gnu offset/sample offset-lining/sample measure/sample \
    sample-s/sample
echo
echo "bench: tocad -f dxf of the insoles: -n 20, the points of sample -n 20" \
    "(440 a closed outline, 441); and at its default tolerance, about 540," \
    "against sample -n 25 (551)"
$W/timeit -r $OUT tocad-dxf/sample tocad-dxf-tol/sample-n25
echo
echo "bench: fromcad of a 50 MB DXF against reading its bytes as numbers" \
    "(numbers: loft's converter on every line; awk: summing them)"
$W/timeit -r $OUT fromcad/dxf-numbers fromcad/dxf-awk
echo "bench: fromcad of an SVG path of 10^6 segments over one of 10^5" \
    "(linear: about 10)"
$W/timeit -r $OUT fromcad-path/fromcad-path-small
echo "bench: splinefit -e 1.6 of 10^5 noisy points of the insole (under" \
    "1 s), over interpolating them (-d 0: every point a knot), and over" \
    "10^4 of them (linear: about 10)"
$W/timeit -r $OUT approx/interp-noisy approx/approx-small
echo "bench: unroll of a doubly curved plate of 100 patches (under 1 s)," \
    "over tocad -f stl -n 6 meshing it"
$W/timeit -r $OUT unroll/stl-plate
echo "bench: hydro's table of 20 waterlines of a 1000-patch hull (under" \
    "1 s), over patchcut's 20 waterlines of it"
$W/timeit -r $OUT hydro/patchcut-wl
echo "bench: loftplot -l of 10^4 labelled segments at random over 10^3 of" \
    "them (linear: about 10)"
$W/timeit -r $OUT labels-1e4/labels-1e3
echo "bench: on their own: splinefit of the 10^6-knot outline (under 2 s)," \
    "patchloft of 100 sections (under 1 s), patchcut of 10^4 patches by 50" \
    "planes (under 2 s), sample -n 100 of a 64 x 64 Bezier surface," \
    "loftplot -l of 20,000 records on a grid"
$W/timeit -r $OUT outline-fit patchloft patchcut surface-63 loftplot-labels
