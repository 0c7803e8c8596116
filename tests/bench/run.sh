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
	case_ pipeline "$B/splinefit $W/insoles.knots | $B/sample -n 20"
	case_ pipeline-p6 "$B/splinefit $W/insoles.knots | $B/sample -n 20 -p 6"
	[ $have_spline = 1 ] &&
	    case_ gnu-spline "$SPLINE -a -d 2 -p -n 440 $W/insoles.spline"
	[ $have_scipy = 1 ] &&
	    case_ scipy "$PYTHON tests/bench/scipy_spline.py 20 $W/insoles.knots"
	case_ outline-fit "$B/splinefit $W/outline.knots"
	case_ space "$B/splinefit $W/space.knots | $B/sample -n 20"
	case_ fromcad "$B/fromcad $W/insoles.dxf"
	case_ dxf-numbers "$W/numbers $W/insoles.dxf"
	case_ dxf-awk "awk '{ s += \$1 } END { print s }' $W/insoles.dxf"
	[ $have_spline = 1 ] &&
	    case_ space-gnu "$SPLINE -a -d 3 -p -n 400000 $W/space.spline"
	rep=$((rep + 1))
done
echo
echo "bench: insoles: $N outlines of 22 knots, 441 points each (sample" \
    "-n 20; GNU spline -n 440)"
$W/timeit -r $OUT pipeline/gnu-spline pipeline-p6/gnu-spline \
    pipeline/floor pipeline-p6/floor-p6 splinefit/floor sample/floor-sample \
    floor-printf/floor floor/gnu-spline scipy/gnu-spline \
    space/space-gnu
echo
echo "bench: fromcad of a 50 MB DXF against reading its bytes as numbers" \
    "(numbers: loft's converter on every line; awk: summing them)"
$W/timeit -r $OUT fromcad/dxf-numbers fromcad/dxf-awk
