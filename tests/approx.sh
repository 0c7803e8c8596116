#!/bin/sh
# approx.sh: command tests of splinefit -e, run from the top of the tree.
# The points come from bin/test/noisy (known outlines, seeded noise), so
# every reference is the truth or the tolerance: distances measured by
# bin/test/nearest (brute force over a dense polyline from sample, no
# part of approx.c), the truth's energy and inflexions by noisy -i
# (quadrature of the formula), the curve's by awk over sample -k.  The
# last line is "approx: N passed, M failed".

T=bin/test/approx
. tests/lib.sh
N=bin/test/noisy
D=bin/test/nearest
PY=/usr/bin/python3

# fit NAME TOL [OPTS]: splinefit -e TOL OPTS $T/NAME.pts > $T/NAME.cubic,
# its -v line in $T/NAME.v, and the curve densely in $T/NAME.dense
fit() {
	n=$1 tol=$2
	shift 2
	"$B/splinefit" -v -e "$tol" "$@" "$T/$n.pts" >"$T/$n.cubic" \
	    2>"$T/$n.v" && ok || no "splinefit -e $tol $* $n: $(cat "$T/$n.v")"
	"$B/sample" -n 128 "$T/$n.cubic" >"$T/$n.dense"
}
# le WHAT GOT BOUND: GOT <= BOUND (no GOT, as from a curve not written,
# fails)
le() {
	awk -v g="$2" -v b="$3" 'BEGIN { exit !(g != "" && g + 0 <= b + 0) }' && ok ||
	    no "$1: got $2, want at most $3"
}
# field WORD TEXT: the word after WORD in TEXT
field() { printf '%s\n' "$2" | awk -v w="$1" '{ for (i = 1; i < NF; i++)
	if ($i == w) { print $(i + 1); exit } }'; }
# within NAME TOL [-o]: every point of NAME.pts within TOL of the curve
# (the polyline of 128 points a segment lies within 1e-4 of it here)
within() {
	r=$($D $3 "$T/$1.dense" "$T/$1.pts")
	le "$1: largest distance of a point" "$(field max "$r")" \
	    "$(awk -v t="$2" 'BEGIN { print t + 1e-4 }')"
}
# shape NAME: inflexions and bending energy of NAME.cubic from sample -k:
# sign changes of the curvature (cyclic when closed; below 1e-9 / mm no
# sign), and the trapezoid sum of k^2 over the chords
shape() {
	"$B/sample" -n 256 -k "$T/$1.cubic" | awk -v closed="$2" '
	NF == 3 { if (n++) { c = sqrt(($1 - x) ^ 2 + ($2 - y) ^ 2)
		e += c * (k * k + $3 * $3) / 2 }
	    x = $1; y = $2; k = $3
	    s = k > 1e-9 ? 1 : k < -1e-9 ? -1 : 0
	    if (s) { if (last && s != last) f++; if (!first) first = s; last = s } }
	END { if (closed && first && last != first) f++
	    printf "inflexions %d energy %.10g\n", f, e }'
}
# truth ARGS: noisy -i's line for the shape
truth() { $N -i "$@"; }
# hausdorff A B [-o]: the larger distance either way between two dense
# polylines
hausdorff() {
	a=$(field max "$($D $3 "$T/$1.dense" "$T/$2.dense")")
	b=$(field max "$($D $3 "$T/$2.dense" "$T/$1.dense")")
	awk -v a="$a" -v b="$b" 'BEGIN { print (a > b ? a : b) }'
}
# checks NAME TOL CLOSED TRUTHARGS...: within TOL, inflexions at most the
# truth's, energy within 10% of the truth's, truth within TOL / 2 (TOL
# on an open curve: its ends rest on the few points past the last knot)
checks() {
	n=$1 tol=$2 closed=$3
	shift 3
	within "$n" "$tol" "$([ "$closed" = 1 ] || echo -o)"
	got=$(shape "$n" "$closed")
	want=$(truth "$@")
	le "$n: inflexions (the truth has $(field inflexions "$want"))" \
	    "$(field inflexions "$got")" "$(field inflexions "$want")"
	awk -v g="$(field energy "$got")" -v w="$(field energy "$want")" \
	    'BEGIN { exit !(g > 0.9 * w && g < 1.1 * w) }' && ok ||
	    no "$n: energy $(field energy "$got"), truth $(field energy "$want")"
	$N -t "$@" >"$T/$n-truth.dense"
	le "$n: distance to the truth" \
	    "$(hausdorff "$n" "$n-truth" "$([ "$closed" = 1 ] || echo -o)")" \
	    "$(awk -v t="$tol" -v c="$closed" 'BEGIN { print c ? t / 2 : t }')"
}

# same_inflexions NAME WHAT SHAPE...: NAME's curve has exactly the
# inflexions of the truth of SHAPE (noisy -i)
same_inflexions() {
	n=$1 what=$2
	shift 2
	[ "$(field inflexions "$(shape $n 1)")" = \
	    "$(field inflexions "$(truth "$@")")" ] && ok ||
	    no "$what: inflexions $(shape $n 1), the truth $(truth "$@")"
}

# ---- usage ---------------------------------------------------------------
fails 2 "-e '0': want a positive number" "$B/splinefit -e 0 /dev/null"
fails 2 "-e '-1'" "$B/splinefit -e -1 /dev/null"
fails 2 "-e 'abc' is not a number" "$B/splinefit -e abc /dev/null"
fails 2 "-m chooses how to fit through knots" \
    "$B/splinefit -e 1 -m chord /dev/null"
fails 2 "-d chooses how to fit through knots" \
    "$B/splinefit -d 0.1 -e 1 /dev/null"
run "$B/splinefit -h"
grep -q "splinefit -e tol" "$T/out" && ok || no "usage lacks -e"

# ---- an ellipse, 250 x 90 mm, 300 points, 0.3 mm of noise ---------------
# The issue's case: interpolating gives 230 inflexions.  Within 1.2 mm
# (4 sigma) of every point, no inflexion, the truth's energy to 10%.
E="ellipse 125 45"
$N -n 300 -s 0.3 -r 1 $E >"$T/e.pts"
fit e 1.2
checks e 1.2 1 $E
r=$($D "$T/e.dense" "$T/e.pts")
v=$(cat "$T/e.v")
# -v: the knots kept (the segments written), the largest distance (as
# nearest measures it, to 1e-3) and the line of its point (the file's
# line: the row after noisy's comment line), the energy
k=$(grep -c '^[-0-9]' "$T/e.cubic")
printf '%s\n' "$v" | grep -q ": 300 points, $k knots kept, largest distance" &&
    ok || no "-v: want '300 points, $k knots kept': $v"
d=$(printf '%s\n' "$v" | sed -n 's/.*largest distance \([^ ]*\) .*/\1/p')
awk -v a="$d" -v b="$(field max "$r")" 'BEGIN { d = a - b
    exit !(d < 1e-3 && d > -1e-3) }' && ok ||
    no "-v: largest distance $d, nearest measures $(field max "$r")"
line=$(printf '%s\n' "$v" | sed -n 's/.*of line \([0-9]*\).*/\1/p')
[ "$line" = "$(($(field row "$r") + 1))" ] && ok ||
    no "-v: the farthest point at line $line, nearest says row $(field row "$r")"
printf '%s\n' "$v" | grep -q "bending energy" && ok || no "-v: no energy: $v"
# as few knots as a fair ellipse needs: fewer than 20 (scipy's smoothing
# spline takes some 200 for such points, see make compare-approx)
le "ellipse: knots" "$k" 20

# determinism: the same bytes again
"$B/splinefit" -e 1.2 "$T/e.pts" | cmp -s - "$T/e.cubic" && ok ||
    no "ellipse: a second run writes other bytes"

# start: the same points from the 137th on, then the first 136; the
# curve is the same to within TOL / 100
awk '/^[-0-9]/' "$T/e.pts" | awk 'NR > 136' >"$T/e2.pts"
awk '/^[-0-9]/' "$T/e.pts" | awk 'NR <= 136' >>"$T/e2.pts"
fit e2 1.2
le "ellipse started elsewhere: distance between the curves" \
    "$(hausdorff e e2)" 0.012
# units: in inches (every number / 25.4, the tolerance too), then back
awk '/^[-0-9]/ { printf "%.17g %.17g\n", $1 / 25.4, $2 / 25.4 }' \
    "$T/e.pts" >"$T/e3.pts"
"$B/splinefit" -e "$(awk 'BEGIN { printf "%.17g", 1.2 / 25.4 }')" \
    "$T/e3.pts" >"$T/e3.cubic" && ok || no "ellipse in inches fails"
"$B/sample" -n 128 "$T/e3.cubic" |
    awk 'NF { printf "%.17g %.17g\n", $1 * 25.4, $2 * 25.4 }' >"$T/e3.dense"
le "ellipse in inches: distance to the curve in mm" "$(hausdorff e e3)" 0.012
"$B/sample" -n 128 "$T/e3.cubic" >"$T/e3in.dense"
le "ellipse in inches: distance of its points, in inches" \
    "$(field max "$($D "$T/e3in.dense" "$T/e3.pts")")" \
    "$(awk 'BEGIN { print 1.2 / 25.4 + 1e-5 }')"
# units near the ends of the doubles: 1e-300 and 1e300 times, the same
# knots (squares of distances there would underflow or overflow)
for f in 1e-300 1e300; do
	awk -v f=$f '/^[-0-9]/ { printf "%.17g %.17g\n", $1 * f, $2 * f }' \
	    "$T/e.pts" >"$T/e4.pts"
	"$B/splinefit" -e "$(awk -v f=$f 'BEGIN { printf "%.17g", 1.2 * f }')" \
	    "$T/e4.pts" >"$T/e4.cubic" && ok || no "ellipse times $f fails"
	[ "$(grep -c '^[-0-9]' "$T/e4.cubic")" = "$k" ] && ok ||
	    no "ellipse times $f: $(grep -c '^[-0-9]' "$T/e4.cubic") knots, not $k"
done

# ---- the insole of man/figures/insole.knots, fitted: the truth ----------
I="insole man/figures/insole.knots"
$N -n 600 -s 0.1 -r 2 $I >"$T/i.pts"
fit i 0.45
checks i 0.45 1 $I
$N -n 400 -s 0.3 -r 3 $I >"$T/i2.pts"
fit i2 1.2
checks i2 1.2 1 $I

# ---- blobs: a convex one and one with inflexions ---------------------------
B1="blob 50 0.03 3"
$N -n 500 -s 0.15 -r 4 $B1 >"$T/b1.pts"
fit b1 0.6
checks b1 0.6 1 $B1
B2="blob 60 0.12 4"
$N -n 800 -s 0.1 -r 5 $B2 >"$T/b2.pts"
fit b2 0.4
checks b2 0.4 1 $B2
same_inflexions b2 "blob" $B2

# case 45 of make compare-approx (4 sigma): a blob whose points lie along
# a chord for a stretch, where a straight span beside bends of one sign
# brought in two reverse bends; a straight run is kept only without them
B3="blob 60.784 0.064 3"
$N -n 618 -s 0.062 -r 45 $B3 >"$T/b3.pts"
fit b3 0.248
checks b3 0.248 1 $B3
same_inflexions b3 "blob 45" $B3

# ---- nearly straight stretches: a wiggle the points leave no room to drop
# Cases 59 and 22 of make compare-approx (4 sigma): the knots that fit
# the points best there bend the curve the wrong way for a few mm, two
# inflexions the truth lacks, and no removal of a knot keeps every point
# within the tolerance; the curve must have the truth's inflexions
E5="ellipse 79.867 24.215"
$N -n 740 -s 0.489 -r 59 $E5 >"$T/e5.pts"
fit e5 1.956
checks e5 1.956 1 $E5
same_inflexions e5 "ellipse 59" $E5
$N -n 629 -s 0.07 -r 22 $I >"$T/i3.pts"
fit i3 0.28
checks i3 0.28 1 $I
same_inflexions i3 "insole 22" $I

# ---- open curves: an arch, and a wave with one inflexion ----------------
W1="wave 200 30 1"
$N -n 300 -s 0.2 -r 6 $W1 >"$T/w1.pts"
fit w1 0.8 -o
checks w1 0.8 0 $W1
W2="wave 200 20 2"
$N -n 300 -s 0.2 -r 7 $W2 >"$T/w2.pts"
fit w2 0.8 -o
checks w2 0.8 0 $W2
[ "$(field inflexions "$(shape w2 0)")" = 1 ] && ok ||
    no "wave: inflexions $(shape w2 0), want 1"

# -S and -E: the arch's end tangents, given, are the curve's (the first
# row's P'_A and the last's P'_B point along them); within TOL still
cp "$T/w1.pts" "$T/w3.pts"
fit w3 0.8 -o -S 1,2 -E 1,-1
within w3 0.8 -o
awk '/^[-0-9]/ { if (!n++) { ax = $5; ay = $6 } bx = $7; by = $8 }
    END { ca = (ax * 2 - ay * 1) / sqrt(ax * ax + ay * ay) / sqrt(5)
	  cb = (bx * -1 - by * 1) / sqrt(bx * bx + by * by) / sqrt(2)
	  da = (ax * 1 + ay * 2); db = (bx * 1 - by * 1)
	  exit !(ca < 1e-9 && ca > -1e-9 && cb < 1e-9 && cb > -1e-9 &&
	      da > 0 && db > 0) }' "$T/w3.cubic" && ok ||
    no "-S 1,2 -E 1,-1: end tangents $(sed -n 2p "$T/w3.cubic")"

# ---- corners: a half disc of radius 50, its corners the diameter's ends --
# The arc from (50, 0) round to (-50, 0) in 200 points, the diameter
# back in 80; noise 0.1 from awk's own generator; the corners are points
# 1 and 201.  Within TOL; knots at the very corner points; the tangent
# turns there by a right angle (within 10 degrees).
awk 'BEGIN { srand(8); pi = atan2(0, -1)
    print "points corners=1,201"
    for (i = 0; i <= 200; i++) { a = pi * i / 200
	printf "%.9f %.9f\n", 50 * cos(a) + (i % 200 ? g() : 0),
	    50 * sin(a) + (i % 200 ? g() : 0) }
    for (i = 1; i < 80; i++)
	printf "%.9f %.9f\n", -50 + 100 * i / 80, g() }
    function g() { return 0.1 * sqrt(-2 * log(1 - rand())) * cos(2 * atan2(0, -1) * rand()) }' \
    >"$T/h.pts"
fit h 0.4
within h 0.4
awk 'NF == 8 { n++; for (i = 1; i <= 8; i++) s[n, i] = $i }
    END { hits = 0
	for (j = 1; j <= n; j++) {
	    p = j > 1 ? j - 1 : n
	    if ((s[j, 1] == 50 && s[j, 2] == 0) || (s[j, 1] == -50 && s[j, 2] == 0)) {
		ax = s[p, 7]; ay = s[p, 8]; bx = s[j, 5]; by = s[j, 6]
		c = (ax * bx + ay * by) / sqrt(ax * ax + ay * ay) / sqrt(bx * bx + by * by)
		if (c < 0.174 && c > -0.174) hits++ } }
	exit !(hits == 2) }' "$T/h.cubic" && ok ||
    no "half disc: no right-angled breaks at (50, 0) and (-50, 0): $(head -3 "$T/h.cubic")"
# the cubic's corners= names the joints at the two corner points (loft.5:
# joint i starts the segment of row i)
awk 'NR == 1 { for (f = 2; f <= NF; f++) if ($f ~ /^corners=/) {
	    n = split(substr($f, 9), c, ","); for (k = 1; k <= n; k++) want[c[k]] = 1 } }
    NF == 8 { j++; if ((($1 == 50 || $1 == -50) && $2 == 0) != (j in want)) bad = 1 }
    END { exit !(n == 2 && !bad) }' "$T/h.cubic" && ok ||
    no "half disc: corners= does not name the joints at the corners: $(head -1 "$T/h.cubic")"

# ---- bad records: a message naming the line, exit 1, the others fitted ---
{ printf '0 0\n1 1\n2 0\n\n'; cat "$T/e.pts"; } >"$T/bad1.pts"
run "$B/splinefit -e 1.2 $T/bad1.pts"
status 1
says "bad1.pts:1: 3 points: a closed approximation needs at least 4"
[ "$(grep -c '^cubic' "$T/out")" = 1 ] && ok || no "bad1: want the good record"
fails 1 "x.pts:2: 2 points: an open approximation needs at least 3" \
    "printf '# x\n0 0\n1 1\n' >$T/x.pts; $B/splinefit -o -e 0.1 $T/x.pts"
fails 1 "line.pts:1: the points all lie on a line" \
    "printf '0 0\n1 1\n2 2\n3 3\n5 5\n' >$T/line.pts; $B/splinefit -e 0.1 $T/line.pts"
# open points on a line (a ruler's edge, a CAD line's vertices) are
# the straight segment from the first to the last, not an error; a
# corner named among them is a knot; points that turn back along the
# line have no outline
run "printf '0 0\n1 1\n2 2\n3 3\n5 5\n' | $B/splinefit -o -e 0.1"
status 0
[ "$(sed -n 2p "$T/out")" = "0 0 5 5 5 5 5 5" ] &&
    [ "$(grep -c '^[0-9-]' "$T/out")" = 1 ] && ok ||
    no "open points on a line: want one straight segment: $(cat "$T/out")"
run "printf 'points corners=3\n0 0 0\n1 2 3\n2 4 6\n4 8 12\n' |
    $B/splinefit -o -e 0.1"
status 0
[ "$(sed -n 1p "$T/out")" = "cubic closed=0 corners=2" ] &&
    [ "$(sed -n 3p "$T/out")" = "2 4 6 4 8 12 2 4 6 2 4 6" ] && ok ||
    no "open points on a line with a corner: $(cat "$T/out")"
fails 1 "line2.pts:1: the points all lie on a line and turn back along it" \
    "printf '0 0\n1 1\n3 3\n2 2\n5 5\n' >$T/line2.pts; $B/splinefit -o -e 0.1 $T/line2.pts"
# the same in units of 1e-200: the steps' product underflows to 0
fails 1 "line3.pts:1: the points all lie on a line and turn back along it" \
    "printf '0 0\n1e-200 1e-200\n3e-200 3e-200\n2e-200 2e-200\n5e-200 5e-200\n' >$T/line3.pts; $B/splinefit -o -e 1e-201 $T/line3.pts"
fails 1 "e.pts:2: tolerance 200 is larger than the outline" \
    "$B/splinefit -e 200 $T/e.pts"
# a tolerance no curve meets: below the noise, one round of splitting
fails 1 "tolerance 0.5 not met: the largest distance reached is" \
    "$B/splinefit -e 0.5 -i 1 $T/e.pts"
says "with "
# the line named is the farthest point's
l=$(sed -n 's/^splinefit: [^:]*:\([0-9]*\): tolerance.*from point \([0-9]*\),.*/\1 \2/p' "$T/err")
set -- $l
[ "$#" = 2 ] && [ "$1" = "$(($2 + 1))" ] && ok ||
    no "unmet tolerance: line and point disagree: $(cat "$T/err")"

# a record of fewer coordinates and more rows than the one before: its
# rows got the room of the numbers (found by tests/fuzz/splinefit; shows
# under make check-san and check-valgrind)
run "printf 'points\n0 0 1\n2 1 0\n\npoints\n0 0\n1 1\n3 30\n' | $B/splinefit -o"
status 0
[ "$(grep -c '^cubic' "$T/out")" = 2 ] && ok || no "two records: $(cat "$T/out")"

# ---- corners found by -e (issue 23): a noisy square keeps its four, a
# noisy circle has none; with -C none are found, -K names the default --
# noisy SHAPE N SIGMA SEED: a square of side 100 (corners at 0 0, 100 0,
# 100 100, 0 100) or a circle of radius 50, N points even in length,
# Gaussian noise (Box-Muller on awk's rand)
shape() {
	awk -v s="$1" -v n="$2" -v g="$3" -v r="$4" 'BEGIN { srand(r)
	pi = atan2(0, -1)
	for (i = 0; i < n; i++) {
		t = i / n
		if (s == "square") {
			e = int(4 * t); f = 4 * t - e
			x = e == 0 ? 100 * f : e == 1 ? 100 : e == 2 ? 100 - 100 * f : 0
			y = e == 0 ? 0 : e == 1 ? 100 * f : e == 2 ? 100 : 100 - 100 * f
		} else {
			x = 50 * cos(2 * pi * t); y = 50 * sin(2 * pi * t)
		}
		u = 1 - rand(); v = rand(); m = g * sqrt(-2 * log(u))
		printf "%.6f %.6f\n", x + m * cos(2 * pi * v), y + m * sin(2 * pi * v)
	} }'
}
# twoway CUBIC PTS TOL: every point of the curve (sample -n 64) within
# TOL plus half the mean spacing of the points of their closed polyline
twoway() {
	"$B/sample" -n 64 "$1" | awk -v tol="$3" 'FNR == 1 { f++ }
	    !/^[-0-9.]/ { next }
	    f == 1 { n++; px[n] = $1; py[n] = $2; next }
	    { c++; cx[c] = $1; cy[c] = $2 }
	    END { for (i = 1; i <= n; i++) { j = i % n + 1
		    len += sqrt((px[j] - px[i]) ^ 2 + (py[j] - py[i]) ^ 2) }
		room = tol + len / n / 2; worst = 0
		for (k = 1; k <= c; k++) { best = 1e300
		    for (i = 1; i <= n; i++) { j = i % n + 1
			ex = px[j] - px[i]; ey = py[j] - py[i]
			l2 = ex * ex + ey * ey
			t = l2 > 0 ? ((cx[k] - px[i]) * ex + (cy[k] - py[i]) * ey) / l2 : 0
			t = t < 0 ? 0 : t > 1 ? 1 : t
			d = (cx[k] - px[i] - t * ex) ^ 2 + (cy[k] - py[i] - t * ey) ^ 2
			if (d < best) best = d }
		    if (best > worst) worst = best }
		worst = sqrt(worst); print worst, room; exit !(worst <= room) }' \
	    "$2" - >"$T/twoway" && ok ||
	    no "two-way: a curve point $(cat "$T/twoway") (distance, room) from the points of $2"
}
# corner_hits CUBIC R "X Y ...": how many of the places have a joint of
# the curve's corners= within R, and how many joints corners= names
corner_hits() {
	awk -v R="$2" -v V="$3" 'BEGIN { nv = split(V, v, " ") / 2 }
	    NR == 1 { n = split($0, w, "corners="); split(w[2], c, /[ ,]/)
		for (k in c) if (c[k] != "") { want[c[k] + 0] = 1; nc++ }; next }
	    { j++; if (j in want) for (q = 0; q < nv; q++)
		if (sqrt(($1 - v[2 * q + 1]) ^ 2 + ($2 - v[2 * q + 2]) ^ 2) <= R)
		    hit[q] = 1 }
	    END { for (q in hit) h++; print h + 0, nc + 0 }' "$1"
}
# corners_at CUBIC R "X Y ...": the curve's corners= name as many joints
# as there are places, one within R of each
corners_at() {
	set -- "$(corner_hits "$1" "$2" "$3")" "$(echo "$3" | awk '{ print NF / 2 }')"
	[ "$1" = "$2 $2" ]
}
# at_square CUBIC: each true corner of shape's square has a corner joint
# of CUBIC within 2.4 (2 tol), and there is no other
at_square() { corners_at "$1" 2.4 "0 0 100 0 100 100 0 100"; }
for seed in 1 2 3; do
	shape square 400 0.3 $seed >"$T/sq.pts"
	"$B/splinefit" -e 1.2 "$T/sq.pts" >"$T/sq.cubic" 2>"$T/sq.err" &&
	    ! [ -s "$T/sq.err" ] && ok ||
	    no "square $seed: $(cat "$T/sq.err")"
	"$B/splinefit" -C -K -e 1.2 "$T/sq.pts" | cmp -s - "$T/sq.cubic" && ok ||
	    no "square $seed: -C -K is not the default"
	at_square "$T/sq.cubic" && ok ||
	    no "square $seed: want 4 corners at the square's: $(head -1 "$T/sq.cubic")"
	"$B/splinefit" -C -e 1.2 "$T/sq.pts" >"$T/sqk.cubic" 2>&1 &&
	    ! grep -q corners= "$T/sqk.cubic" && ok ||
	    no "square $seed, -C: want no corners: $(head -1 "$T/sqk.cubic")"
	twoway "$T/sq.cubic" "$T/sq.pts" 1.2
	# straight runs: two sides at least are exact lines (both tangents
	# along the chord, to rounding)
	awk '/^[-0-9.]/ { cx = $3 - $1; cy = $4 - $2; c = sqrt(cx * cx + cy * cy)
	    a = ($5 * cy - $6 * cx) / c; b = ($7 * cy - $8 * cx) / c
	    if (c > 0 && a * a + b * b < 1e-18 * c * c && $5 * cx + $6 * cy > 0) l++ }
	    END { exit !(l >= 2) }' "$T/sq.cubic" && ok ||
	    no "square $seed: want 2 straight segments at least: $(cat "$T/sq.cubic")"
	twoway "$T/sqk.cubic" "$T/sq.pts" 1.2
	shape circle 400 0.3 $seed >"$T/ci.pts"
	"$B/splinefit" -e 1.2 "$T/ci.pts" >"$T/ci.cubic" 2>&1 &&
	    ! grep -q corners= "$T/ci.cubic" && ok ||
	    no "circle $seed: want no corner: $(head -1 "$T/ci.cubic")"
done
# A tolerance below the noise: 200 points round the square with noise
# of sigma 5 (in each coordinate), fitted within 4.  The fit follows
# the noise and strays from the points between them; it is written,
# with status 0, and says how many spans are astray and what the
# points' noise is (the estimate within 30% of 5 either way)
shape square 200 5 3 >"$T/sqn.pts"
"$B/splinefit" -e 4 "$T/sqn.pts" >"$T/sqn.cubic" 2>"$T/sqn.err" &&
    grep -q '^cubic' "$T/sqn.cubic" &&
    awk '{ n++ }
	/: [0-9]+ spans astray: the curve strays from the points/ &&
	match($0, /points. noise \(about [0-9.]+\)$/) {
		s = substr($0, RSTART + 21, RLENGTH - 22); ok = s >= 3.5 && s <= 6.5 }
	END { exit !(n == 1 && ok) }' "$T/sqn.err" && ok ||
    no "tolerance below the noise: want a note of spans astray and a noise near 5: $(cat "$T/sqn.err")"
# 20 clean points round a circle of radius 50, fitted within 0.01:
# their bend reads as four corners, whose knots (where the lines either
# side meet) lie 10 off the circle, so no fit within 0.01 goes through
# them.  The fit without them is written, with nothing on standard
# error, within 0.02 of the circle (sample -n 16: between the points
# the curve may stray a little past the tolerance)
shape circle 20 0 1 >"$T/c20.pts"
"$B/splinefit" -e 0.01 "$T/c20.pts" >"$T/c20.cubic" 2>"$T/c20.err" &&
    grep -q '^cubic' "$T/c20.cubic" && ! [ -s "$T/c20.err" ] &&
    "$B/sample" -n 16 "$T/c20.cubic" | awk '/^[-0-9.]/ {
	d = sqrt($1 * $1 + $2 * $2) - 50; if (d > 0.02 || d < -0.02) bad++ }
	END { exit bad > 0 }' && ok ||
    no "20 clean points round a circle: want the fit written, within 0.02 of the circle, and no note: $(cat "$T/c20.err")"
# A few clean points round an ellipse (A by B half axes, N points even
# in angle, tolerance TOL): the correction sweeps left the knots off the
# points, and with a knot at every point the fit failed "no span left
# to split" at any tolerance.  The curve through every point is now
# written where it has no more inflexions than that fit: exit 0, no
# note, every point within TOL of the curve (sample -n 256, distance to
# its polyline), the curve within TOL plus the mean spacing of the
# points' polyline (twoway)
for e in "10 86.2 33.6 0.431" "19 56.2 19.4 0.0281" "13 88.7 28.1 0.0444"; do
	set -- $e
	awk -v n="$1" -v a="$2" -v b="$3" 'BEGIN { pi = atan2(0, -1)
	    for (i = 0; i < n; i++)
		printf "%.6f %.6f\n", a * cos(2 * pi * i / n), b * sin(2 * pi * i / n) }' \
	    >"$T/el.pts"
	"$B/splinefit" -e "$4" "$T/el.pts" >"$T/el.cubic" 2>"$T/el.err" &&
	    ! [ -s "$T/el.err" ] &&
	    "$B/sample" -n 256 "$T/el.cubic" | awk -v tol="$4" 'FNR == 1 { f++ }
		!/^[-0-9.]/ { next }
		f == 1 { n++; px[n] = $1; py[n] = $2; next }
		{ c++; cx[c] = $1; cy[c] = $2 }
		END { for (i = 1; i <= n; i++) { best = 1e300
			for (k = 1; k <= c; k++) { j = k % c + 1
			    ex = cx[j] - cx[k]; ey = cy[j] - cy[k]; l2 = ex * ex + ey * ey
			    t = l2 > 0 ? ((px[i] - cx[k]) * ex + (py[i] - cy[k]) * ey) / l2 : 0
			    t = t < 0 ? 0 : t > 1 ? 1 : t
			    d = (px[i] - cx[k] - t * ex) ^ 2 + (py[i] - cy[k] - t * ey) ^ 2
			    if (d < best) best = d }
			if (sqrt(best) > tol) bad++ }
		    exit bad > 0 }' "$T/el.pts" - && ok ||
	    no "$1 clean points round an ellipse $2 by $3, -e $4: want the fit written, every point within TOL, no note: $(cat "$T/el.err")"
	twoway "$T/el.cubic" "$T/el.pts" "$4"
done
# Dense points (issue 23): 10000 or 20000 round the square, some 80 or
# 160 within the scale of each, are averaged in runs before the corners
# are sought; the corners found among the runs are the square's, and a
# circle as dense has none.  (Seeds 12, 14 and 18 put a fifth or sixth
# corner, a chamfer of a millimetre, when every point was searched;
# seeds 20, 22, 35 and 50 a chamfer of half a unit among the runs while
# two corners had to fit them better than one by nine times the noise's
# variance however many pairs of places were tried.)
for seed in 12 14 18 20 22 35 50; do
	shape square 10000 0.3 $seed >"$T/sq.pts"
	"$B/splinefit" -e 1.2 "$T/sq.pts" >"$T/sq.cubic" 2>&1 &&
	    at_square "$T/sq.cubic" && ok ||
	    no "dense square $seed: want 4 corners at the square's: $(head -1 "$T/sq.cubic")"
done
shape square 20000 0.3 1 >"$T/sq.pts"
"$B/splinefit" -e 1.2 "$T/sq.pts" >"$T/sq.cubic" 2>&1 && at_square "$T/sq.cubic" &&
    ok || no "dense square: want 4 corners at the square's: $(head -1 "$T/sq.cubic")"
shape circle 20000 0.3 1 >"$T/ci.pts"
"$B/splinefit" -e 1.2 "$T/ci.pts" >"$T/ci.cubic" 2>&1 &&
    ! grep -q corners= "$T/ci.cubic" && ok ||
    no "dense circle: want no corner: $(head -1 "$T/ci.cubic")"
for o in -C -K; do
	run "$B/splinefit $o $T/sq.pts"
	status 2
done

# A thin noisy ellipse (200 by 24, its tips of radius 1.44, 400 points,
# noise 0.05, -e 0.2): each tip turns 180 degrees within the scale, as
# the end of a stroke does, and the lines either side read it as two
# corners; but a quadratic follows the points there, so it is a smooth
# bend (issue 23).  Before that test every one of these five seeds had
# four corners, two on each tip; now two at most.
for seed in 1 3 4 5 6; do
	awk -v r=$seed 'BEGIN { srand(r); pi = atan2(0, -1)
	    for (i = 0; i < 400; i++) { t = 2 * pi * i / 400
		m = 0.05 * sqrt(-2 * log(1 - rand())); v = 2 * pi * rand()
		printf "%.6f %.6f\n", 100 * cos(t) + m * cos(v), 12 * sin(t) + m * sin(v) } }' \
	    >"$T/el.pts"
	"$B/splinefit" -e 0.2 "$T/el.pts" >"$T/el.cubic" 2>&1 &&
	    awk 'NR == 1 { n = split($0, w, "corners="); k = 0
		if (n > 1) k = split(w[2], c, ","); exit !(k <= 2) }' "$T/el.cubic" &&
	    ok || no "thin ellipse $seed: want 2 corners at most: $(head -1 "$T/el.cubic")"
done
# A noisy ellipse 60 by 14 (its tips of radius 1.63, 8 TOL), a point
# every 0.07 (1.4 noises), noise 0.05, -e 0.2, seeds 1 to 300: every
# corner found is false.  Among points this dense the noise tilts the
# lines of the scale's window near a tip by 30 degrees, and the best
# split there may beat the cubic by its margin; 44 corners were found.
# A corner that gains that little must gain again with sides half as
# long again (issue 23): 23 are.
seed=1 found=0
while [ "$seed" -le 300 ]; do
	awk -v r="$seed" 'BEGIN { srand(r); pi = atan2(0, -1)
	    for (t = 0; t < 2 * pi; t += 0.07 / sqrt(dx * dx + dy * dy)) {
		dx = 30 * sin(t); dy = 7 * cos(t)
		m = 0.05 * sqrt(-2 * log(1 - rand())); v = 2 * pi * rand()
		printf "%.6f %.6f\n", 30 * cos(t) + m * cos(v), 7 * sin(t) + m * sin(v) } }' \
	    >"$T/el.pts"
	"$B/splinefit" -e 0.2 "$T/el.pts" >"$T/el.cubic" 2>&1
	found=$((found + $(awk 'NR == 1 { n = split($0, w, "corners=")
	    print (n > 1 ? split(w[2], c, ",") : 0); exit }' "$T/el.cubic")))
	seed=$((seed + 1))
done
[ "$found" -le 32 ] && ok ||
    no "dense ellipse: want 32 corners at most over 300 seeds, got $found"

# house_pts R SEED: points 2 apart round the house 0 0, 100 0, 100 40,
# 50 75, 0 40, its apex (a turn of 70 degrees) rounded by an arc of
# radius R tangent to its sides (0: sharp), Gaussian noise of 0.2
house_pts() {
	awk -v R="$1" -v r="$2" 'BEGIN { srand(r); pi = atan2(0, -1)
	    split("0 0 100 0 100 40 50 75 0 40", v, " ")
	    for (i = 0; i < 5; i++) { X[i] = v[2 * i + 1]; Y[i] = v[2 * i + 2] }
	    for (i = 0; i < 5; i++) {       # the path, the apex an arc
		if (i != 3 || R == 0) { px[m] = X[i]; py[m++] = Y[i]; continue }
		ux = X[3] - X[2]; uy = Y[3] - Y[2]; l = sqrt(ux * ux + uy * uy)
		ux /= l; uy /= l; wx = X[4] - X[3]; wy = Y[4] - Y[3]
		l = sqrt(wx * wx + wy * wy); wx /= l; wy /= l
		th = atan2(ux * wy - uy * wx, ux * wx + uy * wy)
		t = R * sin(th) / (1 + cos(th))
		cx = X[3] - t * ux - uy * R; cy = Y[3] - t * uy + ux * R
		a = atan2(Y[3] - t * uy - cy, X[3] - t * ux - cx)
		for (k = 0; k <= 64; k++) {
			px[m] = cx + R * cos(a + th * k / 64)
			py[m++] = cy + R * sin(a + th * k / 64) } }
	    px[m] = px[0]; py[m] = py[0]
	    for (k = 0; k < m; k++) {
		d[k] = sqrt((px[k + 1] - px[k]) ^ 2 + (py[k + 1] - py[k]) ^ 2)
		per += d[k] }
	    n = int(per / 2 + 0.5); k = 0
	    for (i = 0; i < n; i++) { s = i * per / n
		while (acc + d[k] < s) acc += d[k++]
		f = (s - acc) / d[k]; q = 0.2 * sqrt(-2 * log(1 - rand()))
		w = 2 * pi * rand()
		printf "%.6f %.6f\n", px[k] + f * (px[k + 1] - px[k]) + q * cos(w),
		    py[k] + f * (py[k + 1] - py[k]) + q * sin(w) } }'
}

# ---- a tight bend between straight runs is no corner (issue 23): the
# house's apex rounded at radius 10, six spacings of its points long,
# -e 0.8.  The cubic cannot follow a run into the arc and out, and two
# lines, or three, fit the points better; but the runs joined by an arc
# fit them better still.  Before that test 7 of these 10 seeds had two
# corners there (a chamfer); now none has, and the sharp apex keeps its
# own.  (Seed 12 misses a corner of the sharp house, before and after.)
for seed in 1 2 3 4 5 6 7 8 9 10; do
	house_pts 10 $seed >"$T/house.pts"
	"$B/splinefit" -e 0.8 "$T/house.pts" >"$T/house.cubic" 2>&1 &&
	    corners_at "$T/house.cubic" 1.6 "0 0 100 0 100 40 0 40" && ok ||
	    no "rounded house $seed: want the 4 corners of its base only: $(head -1 "$T/house.cubic")"
	house_pts 0 $seed >"$T/house.pts"
	"$B/splinefit" -e 0.8 "$T/house.pts" >"$T/house.cubic" 2>&1 &&
	    corners_at "$T/house.cubic" 1.6 "0 0 100 0 100 40 0 40 50 75" && ok ||
	    no "sharp house $seed: want its 5 corners: $(head -1 "$T/house.cubic")"
done

# poly_pts "X Y ..." SPACING FIRST SEED: points round the closed
# polygon of those corners (from the first towards the second), SPACING
# apart along it, the first FIRST from the first corner, with Gaussian
# noise of 0.05 (awk's generator from SEED)
poly_pts() {
	awk -v V="$1" -v sp="$2" -v first="$3" -v r="$4" 'BEGIN {
	    srand(r); pi = atan2(0, -1); nv = split(V, v, " ") / 2; per = 0
	    for (q = 0; q < nv; q++) {
		x0[q] = v[2 * q + 1]; y0[q] = v[2 * q + 2]
		dx[q] = v[(2 * q + 2) % (2 * nv) + 1] - x0[q]
		dy[q] = v[(2 * q + 3) % (2 * nv) + 1] - y0[q]
		l[q] = sqrt(dx[q] ^ 2 + dy[q] ^ 2); start[q] = per; per += l[q]
	    }
	    q = 0
	    for (s = first; s < per - 1e-9; s += sp) {
		while (q < nv - 1 && s >= start[q] + l[q]) q++
		f = (s - start[q]) / l[q]
		m = 0.05 * sqrt(-2 * log(1 - rand())); a = 2 * pi * rand()
		printf "%.6f %.6f\n", x0[q] + f * dx[q] + m * cos(a),
		    y0[q] + f * dy[q] + m * sin(a) } }'
}
# rect_pts W H SPACING FIRST SEED: poly_pts round the rectangle 0 0 to
# W H, from 0 0 along the x axis
rect_pts() { poly_pts "0 0 $1 0 $1 $2 0 $2" "$3" "$4" "$5"; }
# rect_corners CUBIC W H R: the curve's corners= name four joints and no
# more, one within R of each corner of the rectangle 0 0 to W H
rect_corners() { corners_at "$1" "$4" "0 0 $2 0 $2 $3 0 $3"; }

# rect_case NAME W H SPACING FIRST R: for seeds 1 to 3, splinefit -e 0.2
# of rect_pts W H SPACING FIRST (into $T/NAME.pts and NAME.cubic) has
# four corner knots, each within R of a corner of the rectangle
rect_case() {
	for seed in 1 2 3; do
		rect_pts "$2" "$3" "$4" "$5" "$seed" >"$T/$1.pts"
		"$B/splinefit" -e 0.2 "$T/$1.pts" >"$T/$1.cubic" 2>&1 &&
		    rect_corners "$T/$1.cubic" "$2" "$3" "$6" && ok ||
		    no "$1 $seed: want 4 corner knots within $6 of the rectangle's: $(head -1 "$T/$1.cubic")"
	done
}

# poly_kept NAME "X Y ..." SPACING ["X Y ..."]: how many corners of
# poly_pts of that polygon (into $T/NAME.pts) splinefit -e 0.2 keeps
# (corner_hits within 2 TOL) over seeds 1 to 100, the first point a
# golden-ratio step along the first spacing for each; the corners
# counted are the last argument's places, else all the polygon's
poly_kept() {
	seed=1 kept=0 at=${4:-$2}
	while [ "$seed" -le 100 ]; do
		poly_pts "$2" "$3" "$(awk -v s="$seed" -v sp="$3" \
		    'BEGIN { print sp * ((s * 0.618034) % 1) }')" "$seed" \
		    >"$T/$1.pts"
		"$B/splinefit" -e 0.2 "$T/$1.pts" >"$T/$1.cubic" 2>&1
		set -- "$1" "$2" "$3" "$at" \
		    $(corner_hits "$T/$1.cubic" 0.4 "$at")
		kept=$((kept + ${5:-0}))
		seed=$((seed + 1))
	done
	echo "$kept"
}
# rect_kept NAME W H SPACING: poly_kept of the rectangle 0 0 to W H
rect_kept() { poly_kept "$1" "0 0 $2 0 $2 $3 0 $3" "$4"; }

# ---- true corners among sparse noisy points (issue 23): a rectangle
# 8 x 4.8, a point every 0.64 (3.2 TOL: 12 and 7 a side), noise 0.05,
# -e 0.2, seeds 1 to 100 (rect_kept).  The lines through a side's few
# points, tilted by the noise, can meet off the corner by more than the
# curve can follow there, and the fit with the corner's knot there
# strays: the fit with the knot at the corner's point is tried before
# the corner is dropped.  Each of the 400 corners has a corner joint
# within 2 TOL (before that try, five seeds lost one: 395)
kept=$(rect_kept pin 8 4.8 0.64)
[ "$kept" -eq 400 ] && ok ||
    no "sparse rectangles: want all 400 corners kept, got $kept"

# ---- the feet of stems (issue 23): a rectangle 1.16 x 9.8, its ends
# 5.8 TOL across (1.9 times the scale of 3 TOL the corners are judged
# over, as the foot of DejaVu Sans's d), a point every 0.082, noise
# 0.05, -e 0.2, seeds 1 to 100 (rect_kept).  Each end turns twice
# within twice the scale, which the turn over half the scale tells from
# a bend; its lines, half as long, are within the noise's reach, and
# that turn was taken as none: 352 of the 400 corners were kept (88%).
# At least 95% (issue 23's target) must be.
kept=$(rect_kept stem 1.16 9.8 0.082)
[ "$kept" -ge 380 ] && ok ||
    no "stems: want 380 of 400 corners kept at least, got $kept"

# ---- the ends of slabs among sparse points (issue 23): a slab 40 x
# 1.44, a point every 0.8 (4 TOL: one or two points on each end),
# noise 0.05, -e 0.2, seeds 1 to 100 (rect_kept).  The scale of six
# spacings spans the whole end, every point near it turns by nearly 180
# degrees over it, and the sharpest could lie a scale from the end: the
# lines of its window, one side and a piece of the other, fitted the
# points badly, and an end read as one corner or none (341 of the 400
# kept).  Such a window is settled again from the tip of the U-turn.
# At least 95% (issue 23's target) must be kept.
kept=$(rect_kept slabend 40 1.44 0.8)
[ "$kept" -ge 380 ] && ok ||
    no "sparse slab ends: want 380 of 400 corners kept at least, got $kept"

# ---- a corner beside the end of an arm (issue 23): a stem 4 x 10 with
# an arm 7.2 x 2.4 out of its top to the left, a point every 0.8 (4 TOL:
# nine spacings along the arm's underside, three across its end), noise
# 0.05, -e 0.2, seeds 1 to 100 (poly_kept).  The windows that reach the
# arm's end turn by nearly 180 degrees, more than the corner where its
# underside meets the stem, within half the scale of it: that corner
# was never a candidate, and 556 of the 600 corners were kept (92.7%).
# The turns are measured again with no window reaching past a corner
# found.  At least 95% (issue 23's target) must be kept.
kept=$(poly_kept arm "0 0 0 10 -7.2 10 -7.2 12.4 4 12.4 4 0" 0.8)
[ "$kept" -ge 570 ] && ok ||
    no "arm beside a stem: want 570 of 600 corners kept at least, got $kept"

# ---- the end of a serif beside its bracket (issue 23): a bar 8 long
# whose end, 1 high, meets a bracket curving away from it (an arc of
# radius 4 over 60 degrees), a point every 0.8 (4 TOL: one or two on
# the end), noise 0.05, -e 0.2, seeds 1 to 100 (poly_kept), the two
# corners of the end counted.  The lines of the end's split, half the
# scale long (three spacings), run along the bracket, which they fit
# badly, and their best split put the corners a point off or read the
# end as one: 107 of the 200 were kept.  A split that fits badly is
# settled again with sides half as long, and taken where it fits twice
# as well: 142 are.  The rest are still read as one corner, the tip of
# the end.
serif=$(awk 'BEGIN { pi = atan2(0, -1); s = "0 1 8 1 8 0"
    for (k = 1; k <= 40; k++)
	s = s " " (8 - 4 * sin(pi / 3 * k / 40)) " " \
	    (4 * cos(pi / 3 * k / 40) - 4)
    print s " 0 -2" }')
kept=$(poly_kept serif "$serif" 0.8 "8 1 8 0")
[ "$kept" -ge 135 ] && ok ||
    no "serif's end beside its bracket: want 135 of 200 corners kept at least, got $kept"

# ---- gentle corners among dense points (issue 23): a side 20 long
# turns by 35 degrees into another 20 long, which turns by 55 into the
# rest of a quadrilateral 25 high, a point every 0.12 (0.6 TOL), noise
# 0.05, -e 0.2, seeds 1 to 100 (poly_kept), those two corners counted.
# Over the scale's window such a turn bends the lines so little that a
# cubic follows it to within the noise, and it read as a bend: 130 of
# the 200 were kept.  A gentle candidate so read is settled again with
# sides three times as long: 155 are.
gentle=$(awk 'BEGIN { a = atan2(0, -1) * 35 / 180
    x = 20 + 20 * cos(a); y = 20 * sin(a)
    print "0 0 20 0 " x " " y " " x " 25 0 25" }')
kept=$(poly_kept gentle "$gentle" 0.12 "$(echo "$gentle" | cut -d' ' -f3-6)")
[ "$kept" -ge 145 ] && ok ||
    no "gentle corners: want 145 of 200 corners kept at least, got $kept"

# ---- two corners closer than the scale (issue 23): a slab 100 x 2.5, its
# ends shorter than the six point spacings the corners are judged over
# (as a serif's end is).  Each end turns twice: the four corners are kept,
# each within 2 tol of the slab's, and there is no other; the curve does
# not cross itself (its polyline, sample -n 16, against every other edge)
for seed in 1 2 3; do
	rect_pts 100 2.5 0.5125 0 "$seed" >"$T/slab.pts"
	"$B/splinefit" -e 0.2 "$T/slab.pts" >"$T/slab.cubic" 2>&1 &&
	    rect_corners "$T/slab.cubic" 100 2.5 0.4 && ok ||
	    no "slab $seed: want its 4 corners: $(head -1 "$T/slab.cubic")"
	"$B/sample" -n 16 "$T/slab.cubic" | awk '/^[-0-9.]/ { n++; x[n] = $1; y[n] = $2 }
	    function o(a, b, c,   u) {
		u = (x[b] - x[a]) * (y[c] - y[a])
		return u - (y[b] - y[a]) * (x[c] - x[a]) }
	    END { for (i = 1; i <= n; i++) for (j = i + 2; j <= n; j++) {
		if (i == 1 && j == n) continue
		a = i; b = i % n + 1; c = j; d = j % n + 1
		if (o(a, b, c) * o(a, b, d) < 0 && o(c, d, a) * o(c, d, b) < 0)
		    bad++ }
		exit bad > 0 }' && ok ||
	    no "slab $seed: the curve crosses itself"
done

# ---- a corner off the points (issue 23): a square of side 100 with a
# point every 2.5 along it, the first 0.6 past a corner, so that the
# point nearest each corner is 0.6 past it along a side; noise 0.05.
# The knot of each corner found goes where the lines either side meet:
# within 0.3 of the square's corner (a knot at a point would be 0.6 off
# at least, and cut the corner)
rect_case between 100 100 2.5 0.6 0.3
# the same corners in any units, huge or tiny
for s in 1e300 1e-300; do
	awk -v s="$s" '{ printf "%.17g %.17g\n", $1 * s, $2 * s }' \
	    "$T/between.pts" >"$T/scaled.pts"
	"$B/splinefit" -e "$(awk -v s="$s" 'BEGIN { printf "%.17g", 0.2 * s }')" \
	    "$T/scaled.pts" 2>&1 | head -1 >"$T/scaled.head"
	head -1 "$T/between.cubic" | cmp -s - "$T/scaled.head" && ok ||
	    no "between scaled by $s: $(cat "$T/scaled.head"), want $(head -1 "$T/between.cubic")"
done

# ---- a slab whose ends are shorter than twice the scale (issue 23): a
# rectangle 100 x 20, a point every 2 along it (the first 1 along), noise
# 0.05, -e 0.2: the scale is 12 (six spacings), and the lines over twice
# it either side of each corner reach round the end to the next corner.
# They turn twice as much as over the scale, as a smooth bend's do, and
# no corner was found at all.  Each corner lies between two points, a
# point 1 from it either side; its knot goes where the sides meet, and
# takes the place of the point after it (a knot in the place of the
# nearer point, where that was the one before, left it behind the
# corner: the fit went astray, and was written without corners).  So:
# the four corners, each within 0.3 of the rectangle's.
rect_case short 100 20 2 1 0.3
# ---- narrow slabs (issue 23): rectangles 97 long and 3, 4 or 5 across,
# a point every 2.5 (the first 0.7 along), noise 0.05, -e 0.2.  The ends
# are narrower than the scale (15, six spacings), so every point within
# 15 of an end turns by nearly 180 degrees over it, and the sharpest of
# them lay up to 17 from the end, where its points (a bend there) were
# settled; 0 to 3 of the 4 corners were found.  Now the end is settled
# from its tip: the four corners, each within 0.3 of the rectangle's.
# An end 3 across holds one point, and each knot goes on its side's line
# a spacing's path from it (see splinefit(1)): within a third of a
# spacing, 0.8.
rect_case narrow4 97 4 2.5 0.7 0.3
rect_case narrow5 97 5 2.5 0.7 0.3
rect_case narrow3 97 3 2.5 0.7 0.8
# ---- the two corners of an end shorter than the scale, off the points:
# a rectangle 100 x 12, a point every 2.5 (the first 1.25 along), so that
# each end holds four points, none nearer a corner than 1.25.  The knots
# of each end's two corners go where its line, through its own points,
# meets the sides; at the points they were 1.25 off at least
rect_case ends 100 12 2.5 1.25 0.6

# ---- a corner beside a sparse run: the span over it has too few points
# to split at its middle.  A rectangle 100 x 60, a point a mm along its
# bottom, top and left sides, one every 30 mm along its right side, which
# starts at the corner (100, 0); noise 0.05 from awk's generator.  The
# span that rounds that corner is far from the corner's point and holds
# it alone: without a knot put on the points there (split_far) the fit
# ends "no span left to split".  With -C (no corners found) the fit is
# written and every point is within TOL of it (nearest).  Not checked
# yet, a defect left: the other way (twoway) that smooth curve passes
# TOL plus the mean spacing of the points' polyline, by some mm, between
# two points of the sparse side, where the stray check gives up after
# its rounds.  By default the rectangle's four corners are found, and
# the curve passes both ways.
awk 'BEGIN { srand(3); pi = atan2(0, -1)
    side(0, 0, 100, 0, 1); side(100, 0, 100, 60, 30)
    side(100, 60, 0, 60, 1); side(0, 60, 0, 0, 1) }
    function side(x0, y0, x1, y1, sp,   k, i, t) {
	k = int(sqrt((x1 - x0) ^ 2 + (y1 - y0) ^ 2) / sp + 0.5)
	for (i = 0; i < k; i++) { t = i / k
	    printf "%.6f %.6f\n", x0 + t * (x1 - x0) + g(), y0 + t * (y1 - y0) + g() } }
    function g() { return 0.05 * sqrt(-2 * log(1 - rand())) * cos(2 * pi * rand()) }' \
    >"$T/sparse.pts"
cp "$T/sparse.pts" "$T/sparsec.pts"
fit sparsec 1 -C
within sparsec 1
fit sparse 1
within sparse 1
twoway "$T/sparse.cubic" "$T/sparse.pts" 1
rect_corners "$T/sparse.cubic" 100 60 2 && ok ||
    no "sparse side: want the rectangle's 4 corners: $(head -1 "$T/sparse.cubic")"

# ---- corners between sparse points: 14 points round a hexagon (a fuzz
# case, noise 0.001), two or three a side, none at a corner.  The search
# for corners needs several points either side and finds none, and the
# smooth fits swing past the tolerance of 0.004 round the corners ("no
# span left to split" before).  With a corner at each point where the
# points' polyline turns by 40 degrees or more, the fit is written: every
# point within TOL, the curve within TOL plus half the spacing of the
# points, and its corners are those points (found here by awk).
printf '%s\n' '-0.1320 0.7444' '-0.6031 0.7776' '-0.7464 0.6121' \
    '-0.8936 0.4441' '-0.9278 0.3639' '-0.9545 0.2885' '-0.9148 0.0275' \
    '-0.8322 -0.3578' '-0.5742 -0.6083' '0.1541 -0.4977' '0.8806 -0.3883' \
    '0.8836 0.0003' '0.8385 0.4079' '0.4626 0.6364' >"$T/hexa.pts"
fit hexa 0.004
within hexa 0.004
twoway "$T/hexa.cubic" "$T/hexa.pts" 0.004
awk 'FNR == 1 { f++ }
    f == 1 { n++; x[n] = $1; y[n] = $2; next }
    FNR == 1 { sub(/.*corners=/, ""); m = split($1, c, ","); next }
    { r++; sx[r] = $1; sy[r] = $2 }
    END { pi = atan2(0, -1)
	for (i = 1; i <= n; i++) { a = (i + n - 2) % n + 1; b = i % n + 1
	    ux = x[i] - x[a]; uy = y[i] - y[a]; vx = x[b] - x[i]; vy = y[b] - y[i]
	    t = atan2(ux * vy - uy * vx, ux * vx + uy * vy)
	    if (t < 0) t = -t
	    if (t >= 40 * pi / 180) want[sprintf("%.4f %.4f", x[i], y[i])] = 1 }
	for (k in want) w++
	for (j = 1; j <= m; j++) {
	    p = sprintf("%.4f %.4f", sx[c[j]], sy[c[j]])
	    if (p in want) got++ }
	exit !(m == w && got == w) }' "$T/hexa.pts" "$T/hexa.cubic" && ok ||
    no "sparse hexagon: want its corners at the points turning 40 degrees: $(head -1 "$T/hexa.cubic")"
# the same in other units: the same corners
for s in 1e-300 1e300; do
	awk -v s=$s '{ printf "%.17g %.17g\n", $1 * s, $2 * s }' "$T/hexa.pts" |
	    "$B/splinefit" -e "$(awk -v s=$s 'BEGIN { printf "%.17g", 0.004 * s }')" |
	    head -1 >"$T/hexa.s"
	[ "$(cat "$T/hexa.s")" = "$(head -1 "$T/hexa.cubic")" ] && ok ||
	    no "sparse hexagon scaled by $s: $(cat "$T/hexa.s"), want $(head -1 "$T/hexa.cubic")"
done

# ---- every point a corner: nine points round a closed outline, each
# named in corners=.  Each piece between two corners is the chord, its
# tangent vectors equal to it, from one point to the next.  The fit
# wrote one piece's end past its scratch array there (a closed
# outline's n corners and the first again), which check-san's
# AddressSanitizer reported.
awk 'BEGIN { printf "points closed=1 corners=1"
	for (i = 2; i <= 9; i++) printf ",%d", i
	printf "\n"
	for (i = 0; i < 9; i++)
		printf "%.6f %.6f\n", cos(6.283185307 * i / 9) * (1 + 0.1 * (i % 2)),
		    sin(6.283185307 * i / 9) }' >"$T/allc.pts"
"$B/splinefit" -e 0.01 "$T/allc.pts" >"$T/allc.cubic" 2>&1 &&
    awk 'function d(a, b) { return a - b < 0 ? b - a : a - b }
	NR == FNR { if (FNR > 1) { n++; x[n] = $1; y[n] = $2 }; next }
	FNR == 1 || NF == 0 { next }
	{ k++; j = k % n + 1
	  if (d($1, x[k]) > 1e-9 || d($2, y[k]) > 1e-9 ||
	      d($3, x[j]) > 1e-9 || d($4, y[j]) > 1e-9 ||
	      d($5, $3 - $1) > 1e-9 || d($6, $4 - $2) > 1e-9 ||
	      d($7, $3 - $1) > 1e-9 || d($8, $4 - $2) > 1e-9) bad++ }
	END { exit !(k == 9 && !bad) }' "$T/allc.pts" "$T/allc.cubic" && ok ||
    no "every point a corner: want the 9 chords: $(cat "$T/allc.cubic")"

# ---- against scipy's smoothing spline, on the first 6 outlines ----------
if [ -x "$PY" ] && "$PY" -c 'import scipy, numpy' 2>/dev/null; then
	"$PY" tests/bench/approx_scipy.py -q -n 6 >"$T/scipy" 2>&1 && ok ||
	    no "against scipy: $(cat "$T/scipy")"
else
	echo "skip: splinefit -e against scipy's splprep (no python3 with scipy)"
fi

# ---- folds on real outlines (issue 23): three noisy glyph contours of
# make compare-approx's corpus (tests/glyphs.py, fontTools) on which the
# few first knots settled on both sides of a thin stroke or a ball
# terminal, and the fit, every point within TOL, folded between them:
# its curve crossed itself and strayed 20 to 72 sigmas from the true
# outline.  Now each is within 1.5 TOL (6 sigmas) of it and no curve
# crosses itself (tests/bench/glyphs_noisy.py --check).  The corpus is
# made once, 200 contours: the first 100 are compare-approx's, the next
# 100 the test below's (a contour's noise depends on those before it).
glyphs=
if [ -x "$PY" ] && "$PY" -c 'import scipy, numpy, fontTools' 2>/dev/null &&
    "$PY" tests/glyphs.py "$T/g.knots" "$T/g.truth" 200 2>"$T/g.err" &&
    [ -s "$T/g.truth" ]; then
	glyphs=$(grep -c '^points' "$T/g.knots")
	"$PY" tests/bench/glyphs_noisy.py --check 48,73,98 "$T/g.truth" \
	    >"$T/gfold" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= 6)) bad++ }
	    END { exit !(n == 3 && !bad) }' "$T/gfold" && ok ||
	    no "folds on glyphs (contour, crosses, sigmas): $(cat "$T/gfold")"
	# contour 53, FreeSerif's O (no corner), noise 0.5% of its size: a
	# tight bend read as a corner, its lines fitting the points better
	# than a quadratic by less than the noise explains; now it has none
	"$PY" tests/bench/glyphs_noisy.py --check 53 "$T/g.truth" >"$T/gO" 2>&1
	awk '{ n++; if ($5 != "0") bad++ } END { exit !(n == 1 && !bad) }' \
	    "$T/gO" && ok ||
	    no "O without corners (contour, crosses, sigmas, astray, corners): $(cat "$T/gO")"
	# contour 92, the counter of Linux Libertine's d (no corner: a
	# straight side running into the bowl), noise 0.5% of its size:
	# two lines fitted the run into the bowl better than a quadratic
	# did, and a corner was found there; a cubic follows it, and now
	# there is none
	"$PY" tests/bench/glyphs_noisy.py --check 92 "$T/g.truth" >"$T/gd" 2>&1
	awk '{ n++; if ($5 != "0") bad++ } END { exit !(n == 1 && !bad) }' \
	    "$T/gd" && ok ||
	    no "d's counter without corners (contour, crosses, sigmas, astray, corners): $(cat "$T/gd")"
	# contours 7 and 23, FreeSerif's e and p: a corner's knot went where
	# the lines either side met, off the corner (one side short or
	# curved), or at the point the search settled on where the point
	# beside it lay at the corner; the curves strayed 6.2 and 4.6 sigmas
	# from the true outline there.  Now the place a corner pinned there
	# fits best is taken: each within 4 sigmas
	"$PY" tests/bench/glyphs_noisy.py --check 7,23 "$T/g.truth" >"$T/gpin" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= 4)) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gpin" && ok ||
	    no "corners placed (contour, crosses, sigmas, astray, corners): $(cat "$T/gpin")"
	# contour 33, FreeSerif's x, noise 0.1% of its size: at the foot of
	# a stroke three points turn 90 degrees round a bend, and the two
	# corners found at neighbouring points became one where the lines
	# either side met, farther from the chord between the points than
	# a corner between them can lie (at most half the chord times
	# tan(turn / 2)).  The curve strayed 8.8 sigmas from the true
	# outline there; with the knot at the nearer point, within 7
	"$PY" tests/bench/glyphs_noisy.py --check 33 "$T/g.truth" >"$T/gx" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= 7)) bad++ }
	    END { exit !(n == 1 && !bad) }' "$T/gx" && ok ||
	    no "a bend's meet (contour, crosses, sigmas, astray, corners): $(cat "$T/gx")"
	# contours 46 and 51, FreeSerif's H and M, noise 0.25% and 0.1% of
	# their size: corners found where a serif's top bends into its
	# bracket, the lines either side turning by 30 degrees, but the fit
	# through the points all but smooth there (its tangent turned by
	# 4.6 and 5.8 degrees).  A
	# corner found where the fit turns by less than 10 degrees is now
	# dropped and the points fitted again: every corner left turns by
	# 10 degrees at least (measured here from the curve written), and
	# no curve crosses itself
	"$PY" tests/bench/glyphs_noisy.py --check 46,51 "$T/g.truth" >"$T/gflat" 2>&1
	awk '{ n++; if ($2 != "0" || !($6 == "-" || $6 >= 10)) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gflat" && ok ||
	    no "flat corners (contour, crosses, sigmas, astray, corners, least turn): $(cat "$T/gflat")"
	# contours 30 and 65, FreeSerif's u and W: a single corner's knot
	# went where the lines either side met, past the outline (beyond a
	# chamfer read as one corner, and beyond a sharp tip whose sides
	# the noise tilted), while that meet was no farther from the point
	# than its nearer neighbour; the curves strayed 5.5 and 5.4 sigmas
	# from the true outline.  The path from the point through the meet
	# to a neighbour must now be about the points' spacing: each within
	# 5 sigmas, not crossing itself
	"$PY" tests/bench/glyphs_noisy.py --check 30,65 "$T/g.truth" >"$T/gtip" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= 5)) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gtip" && ok ||
	    no "meets past the outline (contour, crosses, sigmas, astray, corners): $(cat "$T/gtip")"
	# contours 33 and 72, FreeSerif's x and 2: the end
	# of a stroke holds one point, and the knots of its two corners were
	# the points either side of it, cutting both corners; the curves
	# strayed 6.25 and 4.62 sigmas from the true outline.  Each knot now
	# goes past its point on the line through its side, where the path
	# through it to the point between is the points' spacing: within
	# 5.5 and 4 sigmas, not crossing itself
	"$PY" tests/bench/glyphs_noisy.py --check 33,72 "$T/g.truth" >"$T/gcap" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= ($1 == 33 ? 5.5 : 4))) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gcap" && ok ||
	    no "one point between two corners (contour, crosses, sigmas, astray, corners): $(cat "$T/gcap")"
	# contour 76 with the noise of seed 1 and 67 with that of seed 2:
	# the ends of strokes whose corners were not found, where the curve
	# ran on past the points in a tip, 5.9 and 6.7 sigmas from the true
	# outline, yet within the tolerance plus the points' whole spacing of
	# their polyline.  Within half of it (the outline between two points
	# lies within half their spacing of one), the tips are split: within
	# 4 and 5 sigmas, not crossing themselves
	{ "$PY" tests/bench/glyphs_noisy.py --check 76 "$T/g.truth" --seed 1 &&
	    "$PY" tests/bench/glyphs_noisy.py --check 67 "$T/g.truth" \
	    --seed 2; } >"$T/gend" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= ($1 == 76 ? 4 : 5))) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gend" && ok ||
	    no "tips past a stroke's end (contour, crosses, sigmas, astray, corners): $(cat "$T/gend")"
	# contours 12, 46 and 63 (FreeSerif's h, H and U) at 1,600 points:
	# the true corners were found, but the fit with them strayed, since
	# the first knots sat on a moving average taken across two corners
	# closer together than its window (a serif's), off the points
	# between them; the fit without corners was written, keeping 0 of
	# 14, 0 of 20 and 2 of 8 true corners, 4.3, 5.0 and 4.0 sigmas from
	# the true outline.  Between such corners the average now stops at
	# the nearer: 40 of the 42 kept at least, each curve within 4
	# sigmas, none crossing itself
	"$PY" tests/bench/glyphs_noisy.py --check 12,46,63 "$T/g.truth" \
	    --knots "$T/g.knots" --points 1600 >"$T/gdense" 2>&1
	awk '{ n++; kept += $7; if ($2 != "0" || !($3 <= 4)) bad++ }
	    END { exit !(n == 3 && !bad && kept >= 40) }' "$T/gdense" && ok ||
	    no "dense glyphs' corners (contour, crosses, sigmas, astray, corners, least turn, kept, true): $(cat "$T/gdense")"
	# sparse glyphs: the 13 of those 100 contours whose fits at 120
	# points a contour (not 400) went astray after every try, 11
	# crossing themselves, up to 27 sigmas from the true outline: a
	# smooth curve swung round a serif's end between two points.  With
	# a corner at each point where the points turn by 40 degrees, none
	# is astray or crosses itself, and each is within 20 sigmas
	"$PY" tests/bench/glyphs_noisy.py --check \
	    9,17,19,20,31,34,43,44,49,64,65,66,76 "$T/g.truth" --points 120 \
	    >"$T/gsparse" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0" || !($3 <= 20)) bad++ }
	    END { exit !(n == 13 && !bad) }' "$T/gsparse" && ok ||
	    no "sparse glyphs astray (contour, crosses, sigmas, astray, corners): $(cat "$T/gsparse")"
else
	echo "skip: splinefit -e on noisy glyphs (no python3 with scipy and fontTools, or no fonts)"
fi

# ---- a fit whose corners found leave it astray (issue 23): contour 15
# of the next 100 of that corpus (a Linux Libertine w, 400 points,
# sigma 0.73).  With the 23 corners found the fit once crossed itself
# and strayed 84.6 sigmas from the true outline after every try, and
# the fit without them was written.  The finder has since come to
# place 22 corners where the fit with them passes both checks; held:
# within 6.5 sigmas, not crossing itself (5.65 until splits that fit
# badly were settled again with shorter sides, 6.17 since: the knot of
# the corner atop the right stroke goes where the lines meet, past the
# curved side below it).  Contour 3 (an m) crossed itself
# after every try, with its corners found and without: two stretches of
# curve folded over the same two points, a loop no point asks for.  Such
# a loop's knots are now cut, and the m passes both checks, not
# crossing itself.  With -C it still crosses itself, and -v must say
# that spans are astray (the count once missed the spans an earlier
# round had marked, and took a fit that crossed itself for one that
# passed).
if [ "$glyphs" = 200 ]; then
	awk -v RS= -v ORS='\n\n' 'NR > 100' "$T/g.truth" >"$T/h2.truth"
	{ "$PY" tests/bench/glyphs_noisy.py --check 3,15 "$T/h2.truth" &&
	    "$PY" tests/bench/glyphs_noisy.py --check 3 "$T/h2.truth" -C |
	    sed 's/^/C/'; } >"$T/hstray" 2>&1
	awk '$1 == 15 { n++; if ($2 != "0" || !($3 <= 6.5)) bad++ }
	    $1 == 3 { n++; if ($2 != "0" || $4 != "0") bad++ }
	    $1 == "C3" { n++; if ($2 == "1" && !($4 > 0)) bad++ }
	    END { exit !(NR == 3 && n == 3 && !bad) }' "$T/hstray" && ok ||
	    no "astray (contour, crosses, sigmas, spans): $(cat "$T/hstray")"
	# contour 144 of the corpus, a Linux Libertine T: a false corner
	# found left the fit astray after every try, and the fit without
	# all 10 corners found was written, keeping none of the T's 8 true
	# ones.  The fit without only the corners at the ends of the spans
	# astray came to keep 7; with the finder as it is now the fit does
	# not stray, and keeps all 8.  Held: 6 of the 8 at least, no
	# span astray, not crossing itself.  FreeSerif's 4 (contour 74),
	# with the noise drawn from seed 4, still goes astray with its 10
	# corners found: the fit without those at the spans astray keeps 9
	# (7 of its 11 true ones at least), where the fit without any, as
	# before, kept none
	"$PY" tests/bench/glyphs_noisy.py --check 144 "$T/g.truth" \
	    --knots "$T/g.knots" >"$T/gT" 2>&1
	"$PY" tests/bench/glyphs_noisy.py --check 74 "$T/g.truth" \
	    --knots "$T/g.knots" --seed 4 >>"$T/gT" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0") bad++ }
	    $1 == 144 { t++; if (!($7 >= 6) || $8 != 8) bad++ }
	    $1 == 74 { t++; if (!($7 >= 7) || $8 != 11) bad++ }
	    END { exit !(n == 2 && t == 2 && !bad) }' "$T/gT" && ok ||
	    no "corners at spans astray (contour, crosses, sigmas, spans, corners, least turn, kept, true): $(cat "$T/gT")"
	# contours 8 and 25 (FreeSerif's f and q) with the noise of seed 4,
	# and 19 (its m) with that of seed 2: the fits with their corners
	# found went astray, with no corner at the ends of some span
	# astray, and the fit without any corner was tried next.  The f and
	# the q passed so, keeping none of their 12 and 8 true corners; the
	# m crossed itself even so (7.6 sigmas off, spans astray).  The fit
	# without the corners nearest each span astray comes first now:
	# none astray or crossing, within 6 sigmas, and 9 of 12, 6 of 8
	# and 15 of 20 true corners kept at least.  (Once the knots of two
	# corners with one point between went past their points, the m
	# folded at the end of a stroke whose corners were not found, from
	# 48 first spans as from the first; it passes from 96.)
	{ "$PY" tests/bench/glyphs_noisy.py --check 8,25 "$T/g.truth" \
	    --knots "$T/g.knots" --seed 4 &&
	    "$PY" tests/bench/glyphs_noisy.py --check 19 "$T/g.truth" \
	    --knots "$T/g.knots" --seed 2; } >"$T/gnear" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0" || !($3 <= 6)) bad++ }
	    $1 == 8 { t++; if (!($7 >= 9) || $8 != 12) bad++ }
	    $1 == 25 { t++; if (!($7 >= 6) || $8 != 8) bad++ }
	    $1 == 19 { t++; if (!($7 >= 15) || $8 != 20) bad++ }
	    END { exit !(n == 3 && t == 3 && !bad) }' "$T/gnear" && ok ||
	    no "corners nearest spans astray (contour, crosses, sigmas, spans, corners, least turn, kept, true): $(cat "$T/gnear")"
	# contours 8 and 59 (FreeSerif's f and R) with the noise of seed 8:
	# a stroke's end about one tolerance wide was read as one corner,
	# a needle tip, and its two sides crossed within a sixteenth and a
	# ninth of their spans from it: in the two edges at the tip of the
	# polyline the crossing test follows (neighbours, never compared)
	# and in edges near it that did not cross.  Where the curve turns
	# back at a joint its sides are now sampled finer: neither
	# crosses itself, none astray, within 5 sigmas, keeping 10 of the
	# 12 true corners of each at least
	"$PY" tests/bench/glyphs_noisy.py --check 8,59 "$T/g.truth" \
	    --knots "$T/g.knots" --seed 8 >"$T/gfold" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0" || !($3 <= 5) ||
	    !($7 >= 10) || $8 != 12) bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/gfold" && ok ||
	    no "needle tips (contour, crosses, sigmas, spans, corners, least turn, kept, true): $(cat "$T/gfold")"
	# contours 8 and 110 (FreeSerif's f, Linux Libertine's r): once
	# faint corners were dropped, each fit passed a knot backwards, the
	# curve running on past it and turning back: a hook, which strays
	# less than the spacing past the points and crosses nothing.  The
	# f's was a cusp, its least radius 0.002 TOL (the last column); the
	# r's, at the foot of its stem, 6.5 sigmas from the true outline.
	# Such a knot is now cut where the fit without it still passes:
	# the f's least radius is 0.1 TOL at least, the r within 4 sigmas,
	# neither crossing itself nor astray
	"$PY" tests/bench/glyphs_noisy.py --check 8,110 "$T/g.truth" \
	    >"$T/ghook" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0") bad++ }
	    $1 == 8 && !($NF >= 0.1) { bad++ }
	    $1 == 110 && !($3 <= 4) { bad++ }
	    END { exit !(n == 2 && !bad) }' "$T/ghook" && ok ||
	    no "hooks (contour, crosses, sigmas, spans, corners, least turn, least radius): $(cat "$T/ghook")"
	# contour 71, FreeSerif's 1, with the noise of seed 1: a faint
	# corner (gaining 4.9 noise variances on the cubic) on the gentle
	# bend 6 TOL from the foot's corner gained 10.5 over sides 3m long,
	# just enough to be kept, because those sides ran into the true
	# corner.  They now stop short of the corners found before it: no
	# false corner (the ninth column), all 8 true ones kept, not
	# crossing, none astray
	"$PY" tests/bench/glyphs_noisy.py --check 71 "$T/g.truth" \
	    --knots "$T/g.knots" --seed 1 >"$T/gfaint" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0" || $7 != 8 || $8 != 8 ||
	    $9 != 0) bad++ } END { exit !(n == 1 && !bad) }' "$T/gfaint" &&
	    ok || no "faint corner beside a true one (contour, crosses, sigmas, spans, corners, least turn, kept, true, false): $(cat "$T/gfaint")"
	# contour 0, FreeSerif's a: its 129-degree tip, 26 units from a
	# 42-degree corner, hid within the scale of that corner, and the
	# curve rounded it, 4.87 sigmas from the true outline with 3 of its
	# 4 true corners.  The candidates at half the scale beside a corner
	# that explains too little of its turn find it: all 4 kept, within
	# 4 sigmas of the outline (2.81 here), no crossing, none astray
	"$PY" tests/bench/glyphs_noisy.py --check 0 "$T/g.truth" \
	    --knots "$T/g.knots" >"$T/ga" 2>&1
	awk '{ n++; if ($2 != "0" || !($3 <= 4) || $4 != "0" || $7 != 4 ||
	    $8 != 4) bad++ } END { exit !(n == 1 && !bad) }' "$T/ga" && ok ||
	    no "hidden tip (contour, crosses, sigmas, spans, corners, least turn, kept, true): $(cat "$T/ga")"
	# contour 72, FreeSerif's 2: the turn of the two corners at the
	# end of its hook, 21 units apart, was sharpest on the side above
	# them, where the window held one corner and a piece of the other;
	# the one corner settled there explained 33 of its 163 degrees, its
	# knot at the next point up the side, 9 units from the corner, and
	# took the point of the true corner from the pair the turn between
	# them settled.  Settled
	# last, it yields to the pair: all 8 true corners kept (7 before),
	# no crossing, none astray
	"$PY" tests/bench/glyphs_noisy.py --check 72 "$T/g.truth" \
	    --knots "$T/g.knots" >"$T/gp" 2>&1
	awk '{ n++; if ($2 != "0" || $4 != "0" || $7 != 8 || $8 != 8) bad++ }
	    END { exit !(n == 1 && !bad) }' "$T/gp" && ok ||
	    no "pair after a single (contour, crosses, sigmas, spans, corners, least turn, kept, true): $(cat "$T/gp")"
else
	echo "skip: splinefit -e on noisy glyphs astray (no python3 with scipy and fontTools, or fewer than 200 contours)"
fi

finish approx
