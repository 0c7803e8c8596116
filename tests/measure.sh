#!/bin/sh
# measure.sh: command tests of measure and of sample -s and -t, run from
# the top of the tree.  Every reference is computed here, outside the
# code under test: closed forms derived in the comments, series, dense
# polylines from sample -n with stated error bounds, counts by hand.  The
# last line is "measure: N passed, M failed".

T=bin/test/measure
. tests/lib.sh

# field NAME... : measure -f NAME,... on the last run's input file
# near WHAT GOT WANT TOL: |GOT - WANT| <= TOL (an absolute tolerance),
# WANT and TOL finite (a reference that overflowed proves nothing)
near() {
	awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN {
		if ((w " " t) ~ /[nN][aA][nN]|[iI][nN][fF]/) exit 1
		d = g - w; if (d < 0) d = -d; exit !(d <= t) }' && ok ||
	    no "$1: got $2, want $3 within $4"
}
# rel WHAT GOT WANT TOL: |GOT - WANT| <= TOL |WANT|
rel() {
	t=$(awk -v w="$3" -v t="$4" 'BEGIN { printf "%.17g", (w < 0 ? -w : w) * t }')
	near "$1" "$2" "$3" "$t"
}
# row FIELDS FILE: measure's row of FIELDS (comma list) for FILE's one record
row() { "$B/measure" -f "$1" "$2" | awk NF; }
# dense FILE N: points of FILE's records, N a segment, blank lines kept
dense() { "$B/sample" -n "$2" "$1"; }
# poly: length and shoelace area of the closed or open polylines on
# standard input (records separated by blank lines), and the sum of
# c^3 over its chords c, which bounds the error of both (see below)
poly() {
	awk 'function flush() { if (n) printf "%.17g %.17g %.17g\n", len, area / 2, c3; n = 0 }
	NF == 0 { flush(); next }
	{ if (n) { dx = $1 - px; dy = $2 - py; dz = NF > 2 ? $3 - pz : 0
		c = sqrt(dx * dx + dy * dy + dz * dz); len += c; c3 += c * c * c
		area += px * $2 - $1 * py }
	  else { len = 0; area = 0; c3 = 0 }
	  px = $1; py = $2; pz = $3; n++ }
	END { flush() }'
}
# kmax FILE: the largest |k| along FILE's first record, from sample -k
kmax() {
	"$B/sample" -n 400 -k "$1" | awk -v col="$2" 'NF {
		k = $col < 0 ? -$col : $col; if (k > m) m = k }
		END { printf "%.17g\n", m }'
}

# ---- usage -------------------------------------------------------------
usage_ok measure
fails 2 "-f 'size': want" "$B/measure -f length,size /dev/null"
fails 2 "-p '0'" "$B/measure -p 0 /dev/null"
fails 2 "-s '0': want a number greater than 0" "$B/sample -s 0 /dev/null"
fails 2 "-t '-1'" "$B/sample -t -1 /dev/null"
fails 2 "-n, -s and -t are three ways" "$B/sample -n 4 -s 1 /dev/null"
fails 2 "-n, -s and -t are three ways" "$B/sample -s 1 -t 1 /dev/null"

# ---- a straight segment, unevenly parametrised -----------------------
# P_A (0,0), P_B (3,4), tangents (6,8) and (1.5,2): the line of length 5,
# its length centroid the midpoint (the mean of points by arc length,
# whatever the speed), box by hand, no curvature anywhere: minradius 0
# by definition, no inflexions, no extrema, energy 0, no knots.
printf 'cubic closed=0\n0 0 3 4 6 8 1.5 2\n' >"$T/line.cubic"
set -- $(row length,cx,cy,xmin,ymin,xmax,ymax,area "$T/line.cubic")
rel "line: length" "$1" 5 1e-14
rel "line: cx" "$2" 1.5 1e-12
rel "line: cy" "$3" 2 1e-12
[ "$4 $5 $6 $7" = "0 0 3 4" ] && ok || no "line: box $4 $5 $6 $7"
near "line: area" "$8" 0 1e-14
run "$B/measure -f minradius,minradius_u,inflexions,extrema,energy,jump $T/line.cubic"
out_is "0 0 0 0 0 0
"

# ---- the parabola y = x^2, 0 <= x <= 2, as bezier, cubic and quartic ---
# As x = 2t, y = 4t^2: Bezier points (0,0) (1,0) (2,4); Hermite ends
# (0,0) (2,4) with tangents (2,0) (2,8); quartic the same and (h) =
# P(1/2) = (1,1).  Closed forms, with w = sqrt(1 + 4x^2):
#   length  int_0^2 w dx = [x w / 2 + asinh(2x) / 4] = sqrt(17) + asinh(4)/4
#   area    closed by the chord y = 2x: int_0^2 (2x - x^2) dx = 4/3,
#           counter-clockwise (out along the parabola, back above it)
#   cx      int x w dx / length = (17^1.5 - 1) / 12 / length
#   energy  k = 2 / w^3, ds = w dx: int 4 / w^5 dx; x = tan(a) / 2
#           gives 2 int cos^3 a da = 2 (s - s^3 / 3), s = sin(atan 4)
#   minradius 1/2 at the vertex, u = 0; k falls monotonically: no
#   extrema, no inflexions; box (0,0)-(2,4).
printf 'bezier\n0 0\n1 0\n2 4\n' >"$T/par.bezier"
printf 'cubic closed=0\n0 0 2 4 2 0 2 8\n' >"$T/par.cubic"
printf 'quartic closed=0\n0 0 2 4 2 0 2 8 1 1\n' >"$T/par.quartic"
set -- $(awk 'BEGIN { L = sqrt(17) + log(4 + sqrt(17)) / 4; s = 4 / sqrt(17)
	printf "%.17g %.17g %.17g %.17g\n", L, 4 / 3, (17 ^ 1.5 - 1) / 12 / L,
	    2 * (s - s ^ 3 / 3) }')
pl=$1 pa=$2 pcx=$3 pe=$4
for f in par.bezier par.cubic par.quartic; do
	set -- $(row length,area,cx,energy,minradius,minradius_u,xmin,ymin,xmax,ymax "$T/$f")
	rel "$f: length" "$1" "$pl" 1e-12
	rel "$f: area" "$2" "$pa" 1e-12
	rel "$f: cx" "$3" "$pcx" 1e-11
	rel "$f: energy" "$4" "$pe" 1e-9
	rel "$f: minradius" "$5" 0.5 1e-12
	near "$f: minradius_u" "$6" 0 1e-9
	near "$f: box" "$(echo "$7 $8 $9 ${10}" | awk '{ print ($1 < 0 ? -$1 : $1) + ($2 < 0 ? -$2 : $2) + ($3 - 2 < 0 ? 2 - $3 : $3 - 2) + ($4 - 4 < 0 ? 4 - $4 : $4 - 4) }')" 0 1e-14
	run "$B/measure -f inflexions,extrema $T/$f"
	out_is "0 0
"
done
# the equally spaced points of the parabola sit at lengths k S by the
# closed form s(x) = x w / 2 + asinh(2x) / 4, the last interval shorter
for f in par.bezier par.cubic par.quartic; do
	run "$B/sample -s 0.3 $T/$f"
	status 0
	e=$(awk -v L="$pl" 'NF { x = $1; w = sqrt(1 + 4 * x * x)
		s = x * w / 2 + log(2 * x + w) / 4
		want = n * 0.3; if (want > L) want = L
		if (NF != 2 || (y = $2 - x * x) > 1e-12 || y < -1e-12) { print "off the parabola"; exit }
		d = s - want; if (d < 0) d = -d; if (d > worst) worst = d; n++; last = s }
		END { if (n != int(L / 0.3) + 2) print n " points"
		else if (worst > 1e-11) print "off by " worst
		else if (last != last + 0 || L - last > 1e-11) print "does not end at the end" }' "$T/out")
	[ -z "$e" ] && ok || no "sample -s 0.3 $f: $e"
done

# ---- an S curve: box and inflexion by hand ----------------------------
# Bezier (0,0) (1,1) (2,-1) (3,0): x = 3t, y = 3t (1 - t)(1 - 2t).
# y' = 3 (1 - 6t + 6t^2) = 0 at t = (3 -+ sqrt 3) / 6, where t (1 - t) =
# 1/6 and 1 - 2t = +-1/sqrt 3: y = +-sqrt(3) / 6.  y'' = 18 (2t - 1)
# changes sign once: one inflexion.  The area closed along the x axis,
# 3 int y dt, is 0: y is odd about t = 1/2.
printf 'bezier\n0 0\n1 1\n2 -1\n3 0\n' >"$T/s.bezier"
set -- $(row xmin,ymin,xmax,ymax,inflexions,area "$T/s.bezier")
near "S: xmin" "$1" 0 0
rel "S: ymin" "$2" "$(awk 'BEGIN { printf "%.17g", -sqrt(3) / 6 }')" 1e-14
near "S: xmax" "$3" 3 0
rel "S: ymax" "$4" "$(awk 'BEGIN { printf "%.17g", sqrt(3) / 6 }')" 1e-14
near "S: inflexions" "$5" 1 0
near "S: area" "$6" 0 1e-15
# ---- a box near the largest double (issue 28) --------------------------
# The cubic from (0,0) to (1,0), tangents (D,2) and (0,0.2), D the
# largest double: Bezier x values 0, D/3, 1, 1, whose largest, D/3 times
# max 3t(1 - t)^2 = 4/9 (at t = 1/3), dwarfs the rest.  Its derivative's
# control values, formed before scaling, overflowed: the box ended at
# x = 1, and sample -t flattened it for seconds instead of refusing the
# tolerance (found by make fuzz).
printf 'cubic\n0 0 1 0 1.7976931348623157e308 2 0 .2\n' >"$T/huge.cubic"
set -- $(row xmin,xmax "$T/huge.cubic")
near "largest double: xmin" "$1" 0 0
rel "largest double: xmax" "$2" \
    "$(awk 'BEGIN { printf "%.17g", 1.7976931348623157e308 / 27 * 4 }')" 1e-12
# the extrema: sign changes of the differences of k along dense points
# (an independent count from sample -k): two, one a side of t = 1/2
want=$("$B/sample" -n 4000 -k "$T/s.bezier" | awk 'NF { if (n > 0) { d = $3 - k
	s = d > 1e-12 ? 1 : d < -1e-12 ? -1 : 0
	if (s && last && s != last) c++; if (s) last = s } k = $3; n++ }
	END { print c + 0 }')
set -- $(row extrema "$T/s.bezier")
near "S: extrema (dense count $want)" "$1" "$want" 0
near "S: the dense count is 2" "$want" 2 0

# a spline through 25 knots of y = sin x, x from pi/2 to 7 pi/2: it
# turns at x = pi, 2 pi, 3 pi: three inflexions, by hand
awk 'BEGIN { for (k = 0; k <= 24; k++) { x = 3.141592653589793 * (0.5 + k / 8)
	printf "%.17g %.17g\n", x, sin(x) } }' | "$B/splinefit" -o >"$T/sine.cubic"
set -- $(row inflexions "$T/sine.cubic")
near "sine: inflexions" "$1" 3 0

# ---- a circle of cubics: against its dense polyline and 2 pi r --------
# 16 knots on the circle of radius 10, fitted closed.  The polyline of
# sample -n 2000 has chords c on arcs of curvature at most K: each arc
# exceeds its chord by at most K^2 c^3 / 24 and the segment between them
# has area at most K c^3 / 12 (to leading order; the bounds below take
# twice that), and the polyline is inscribed: length and area from
# below.  Against the true circle: the fit lies within e of radius 10
# (e from the dense points) and is convex (every k > 0), so its length
# is within 2 pi e of 20 pi and its area between pi (10 -+ e)^2.
awk 'BEGIN { for (k = 0; k < 16; k++) { a = 2 * 3.141592653589793 * k / 16
	printf "%.17g %.17g\n", 10 * cos(a), 10 * sin(a) } }' |
    "$B/splinefit" -m manning >"$T/circle.cubic"
K=$(kmax "$T/circle.cubic" 3)
set -- $(dense "$T/circle.cubic" 2000 | poly)
plen=$1 parea=$2 c3=$3
set -- $(row length,area,cx,cy,inflexions "$T/circle.cubic")
d=$(awk -v a="$1" -v b="$plen" 'BEGIN { printf "%.17g", a - b }')
bound=$(awk -v k="$K" -v c="$c3" 'BEGIN { printf "%.17g", 2 * k * k * c / 24 }')
awk -v d="$d" -v b="$bound" 'BEGIN { exit !(d >= -1e-12 && d <= b) }' && ok ||
    no "circle: length $1 - polyline $plen = $d, want 0 to $bound"
d=$(awk -v a="$2" -v b="$parea" 'BEGIN { printf "%.17g", a - b }')
bound=$(awk -v k="$K" -v c="$c3" 'BEGIN { printf "%.17g", 2 * k * c / 12 }')
awk -v d="$d" -v b="$bound" 'BEGIN { exit !(d >= -1e-10 && d <= b) }' && ok ||
    no "circle: area $2 - polyline $parea = $d, want 0 to $bound"
near "circle: cx" "$3" 0 1e-12
near "circle: cy" "$4" 0 1e-12
near "circle: inflexions" "$5" 0 0
circ_l=$1 circ_a=$2
e=$(dense "$T/circle.cubic" 2000 | awk 'NF { d = sqrt($1 * $1 + $2 * $2) - 10
	if (d < 0) d = -d; if (d > m) m = d } END { printf "%.17g", m * 1.1 }')
"$B/sample" -n 400 -k "$T/circle.cubic" | awk 'NF && $3 <= 0 { exit 1 }' && ok ||
    no "circle: the fit is not convex"
near "circle: length vs 20 pi (fit within $e)" "$circ_l" \
    "$(awk 'BEGIN { printf "%.17g", 20 * 3.141592653589793 }')" \
    "$(awk -v e="$e" 'BEGIN { printf "%.17g", 2 * 3.141592653589793 * e }')"
near "circle: area vs 100 pi" "$circ_a" \
    "$(awk 'BEGIN { printf "%.17g", 100 * 3.141592653589793 }')" \
    "$(awk -v e="$e" 'BEGIN { printf "%.17g", 3.141592653589793 * (20 * e + e * e) }')"
# energy: k^2 summed by the trapezoid rule over the dense points' chords
# (error of the order of the chord squared, below 1e-7 here); and within
# the range of k: between L min k^2 and L max k^2, around L / r^2
"$B/sample" -n 2000 -k "$T/circle.cubic" | awk 'NF { if (n) {
	dx = $1 - px; dy = $2 - py; c = sqrt(dx * dx + dy * dy)
	e += c * (k * k + $3 * $3) / 2 } px = $1; py = $2; k = $3; n++
	if (!lo || $3 < lo) lo = $3; if ($3 > hi) hi = $3 }
	END { printf "%.17g %.17g %.17g\n", e, lo, hi }' >"$T/ek"
set -- $(cat "$T/ek")
te=$1 klo=$2 khi=$3
set -- $(row energy,length "$T/circle.cubic")
rel "circle: energy vs trapezoid" "$1" "$te" 1e-7
awk -v e="$1" -v l="$2" -v a="$klo" -v b="$khi" 'BEGIN {
	exit !(e >= l * a * a * (1 - 1e-9) && e <= l * b * b * (1 + 1e-9)) }' &&
    ok || no "circle: energy $1 not within length * k^2 for k in $klo..$khi"
rel "circle: energy vs length / r^2" "$1" "$(awk -v l="$2" 'BEGIN { printf "%.17g", l / 100 }')" \
    "$(awk -v a="$klo" -v b="$khi" 'BEGIN { printf "%.17g", (b * b - a * a) * 100 }')"

# ---- an ellipse: the Gauss-Kummer series ----------------------------------
# Semi-axes 20 and 10, 32 knots equally spaced in angle, fitted closed.
# Perimeter pi (a + b) sum_n C(1/2, n)^2 h^n, h = ((a - b) / (a + b))^2,
# C(1/2, n) = C(1/2, n - 1) (3/2 - n) / n; 40 terms leave < 1e-30.  The
# fit lies within e of the ellipse (e from the dense points' distance
# |F| / |grad F|, F = x^2/a^2 + y^2/b^2 - 1, times 1.1) and is convex,
# so its perimeter is within 2 pi e and its area within P e + pi e^2.
awk 'BEGIN { for (k = 0; k < 32; k++) { a = 2 * 3.141592653589793 * k / 32
	printf "%.17g %.17g\n", 20 * cos(a), 10 * sin(a) } }' |
    "$B/splinefit" >"$T/ellipse.cubic"
set -- $(awk 'BEGIN { a = 20; b = 10; h = ((a - b) / (a + b)) ^ 2; c = 1; s = 1
	for (n = 1; n <= 40; n++) { c *= (1.5 - n) / n; s += c * c * h ^ n }
	printf "%.17g %.17g\n", 3.141592653589793 * (a + b) * s, 3.141592653589793 * a * b }')
eper=$1 earea=$2
e=$(dense "$T/ellipse.cubic" 2000 | awk 'NF { x = $1; y = $2
	f = x * x / 400 + y * y / 100 - 1; g = sqrt((x / 200) ^ 2 + (y / 50) ^ 2)
	d = f / g; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.17g", m * 1.1 }')
"$B/sample" -n 400 -k "$T/ellipse.cubic" | awk 'NF && $3 <= 0 { exit 1 }' && ok ||
    no "ellipse: the fit is not convex"
set -- $(row length,area "$T/ellipse.cubic")
near "ellipse: perimeter vs Gauss-Kummer (fit within $e)" "$1" "$eper" \
    "$(awk -v e="$e" 'BEGIN { printf "%.17g", 2 * 3.141592653589793 * e }')"
near "ellipse: area vs pi a b" "$2" "$earea" \
    "$(awk -v e="$e" -v p="$eper" 'BEGIN { printf "%.17g", p * e + 3.141592653589793 * e * e }')"
awk -v e="$e" 'BEGIN { exit !(e < 0.01) }' && ok ||
    no "ellipse: the fit is $e off: the tolerances above mean little"
# and against its own dense polyline, as the circle
K=$(kmax "$T/ellipse.cubic" 3)
set -- $(dense "$T/ellipse.cubic" 2000 | poly) $(row length,area "$T/ellipse.cubic")
awk -v pl="$1" -v pa="$2" -v c3="$3" -v k="$K" -v l="$4" -v a="$5" 'BEGIN {
	dl = l - pl; da = a - pa
	exit !(dl >= -1e-12 && dl <= 2 * k * k * c3 / 24 && da >= -1e-10 &&
	    da <= 2 * k * c3 / 12) }' && ok ||
    no "ellipse: length $4 area $5 vs polyline $1 $2"

# ---- a space curve: the helix of man/figures ------------------------------
# 16 Hermite segments of (cos 2 pi t, sin 2 pi t, t): z is linear, and
# Hermite interpolation of a linear function is exact, so zmin 0, zmax 1,
# and cz of the length centroid is 1/2 for a curve symmetric about its
# middle (this one is, knot for knot).  Length from the polyline.
H=man/figures/carriazo-helix.cubic
run "$B/measure $H"
status 0
awk 'NF { exit NF != 15 }' "$T/out" && ok || no "helix: default row not 15 fields"
set -- $(row length,cz,zmin,zmax "$H")
K=$(kmax "$H" 4)
set -- "$@" $(dense "$H" 2000 | poly)
awk -v l="$1" -v pl="$5" -v c3="$7" -v k="$K" 'BEGIN { d = l - pl
	exit !(d >= -1e-12 && d <= 2 * k * k * c3 / 24) }' && ok ||
    no "helix: length $1 vs polyline $5"
near "helix: cz" "$2" 0.5 1e-12
near "helix: zmin" "$3" 0 1e-15
near "helix: zmax" "$4" 1 1e-15
fails 1 "a space curve bounds no plane area" "$B/measure -f area $H"
fails 1 "inflexions are for plane curves" "$B/measure -f inflexions $H"
fails 1 "field cz: a plane curve has no z" "$B/measure -f cz $T/s.bezier"

# ---- records measure refuses --------------------------------------------
fails 1 ":1: a point record is no curve" "printf '0 0\n1 1\n' | $B/measure"
awk 'BEGIN { print "patch id=1"; for (i = 0; i < 5; i++) { s = i
	for (j = 1; j < 10; j++) s = s " " i + j; print s } }' >"$T/one.patch"
fails 1 ":1: -f names curve fields; a patch record is a surface" \
    "$B/measure -f length $T/one.patch"
# a zero start tangent that bends: no cusp, but k ~ 1/u toward the end
# (y ~ x^1.5), and the energy diverges like log u (issue 24)
printf 'cubic\n0 0 1 0 0 0 1 1\n' >"$T/cusp.cubic"
fails 1 "curvature grows without bound toward u = 0 of piece 1" "$B/measure -f minradius $T/cusp.cubic"
fails 1 "bending energy of piece 1 is unbounded" "$B/measure -f energy $T/cusp.cubic"
# a true cusp inside a piece: x'(1/2) = y'(1/2) = 0 and the tangent
# turns back there
printf 'bezier\n0 0\n1 1\n1 0\n0 1\n' >"$T/cusp2.bezier"
fails 1 "tangent vanishes in piece 1 at u = 0.5: a cusp" "$B/measure -f minradius $T/cusp2.bezier"
# retracted handles (issue 24): a line drawn as a cubic with both
# handles on their ends is straight (k = 0); one handle retracted
# along a straight piece, likewise
for h in '0 0\n3 0' '0 0\n2 0' '1 0\n3 0'; do
	printf "bezier\n0 0\n$h\n3 0\n" >"$T/line.bezier"
	run "$B/measure -f minradius,minradius_u,energy,inflexions,extrema $T/line.bezier"
	status 0
	out_is "0 0 0 0 0
"
done
# one retracted handle on a degree-4 piece whose limit is finite: P =
# (4u^2, u^4) has P' = 0 at u = 0 and k -> |P'' x P''''| / (3 |P''|^3)
# = (8 * 24) / (3 * 8^3) = 1/8 there: the smallest radius is 8 at u = 0
# (k = 64 / (64 + 16 u^4)^(3/2) falls from 1/8 as u grows)
printf 'bezier\n0 0\n0 0\n0.6666666666666666 0\n2 0\n4 1\n' >"$T/quart.bezier"
run "$B/measure -f minradius,minradius_u $T/quart.bezier"
status 0
awk 'NF { exit !($1 > 8 * (1 - 1e-9) && $1 < 8 * (1 + 1e-9) && $2 == 0) }' "$T/out" &&
    ok || no "measure: radius at a retracted handle of (4u^2, u^4): $(cat "$T/out"), want 8 at 0"
run "$B/measure -f length $T/cusp.cubic"
status 0
# a closed curve that runs out and back along a line has no area
printf 'cubic closed=1\n0 0 1 0 1 0 1 0\n1 0 0 0 -1 0 -1 0\n' >"$T/flat.cubic"
fails 1 "encloses no area" "$B/measure -f cx $T/flat.cubic"
fails 1 "-s and -t need a curve" "$B/sample -s 1 $T/one.patch"
fails 1 "-s and -t need a curve" "$B/sample -t 1 $T/one.patch"

# ---- the insole: counts, equal spacing, tolerance, units --------------------
"$B/splinefit" man/figures/insole.knots >"$T/insole.cubic"

# inflexions and extrema against an independent count along dense points
# of sample -k: sign changes of k, and of the differences of k, round a
# closed curve (its last point repeats the first).  The circle's k has 4
# extrema a segment (a minimum at each knot and mid-segment, maxima
# between), the ellipse's 4, the sine's 2 maxima of |k| inside.
for f in insole sine ellipse circle; do
	closed=$(head -n 1 "$T/$f.cubic" | grep -c 'closed=1')
	want=$("$B/sample" -n 2000 -k "$T/$f.cubic" | awk -v closed="$closed" '
	NF { k[n++] = $3 }
	END { m = closed ? n - 1 : n
		for (i = 0; i < m; i++) { s = k[i] > 1e-9 ? 1 : k[i] < -1e-9 ? -1 : 0
			if (s) { if (!f) f = s; else if (s != l) c++; l = s } }
		if (closed && f && f != l) c++
		for (i = 1; i < m + closed; i++) { d = k[i % m] - k[i - 1]
			s = d > 1e-13 ? 1 : d < -1e-13 ? -1 : 0
			if (s) { if (!F) F = s; else if (s != L) e++; L = s } }
		if (closed && F && F != L) e++
		print c + 0, e + 0 }')
	run "$B/measure -f inflexions,extrema $T/$f.cubic"
	out_is "$want
"
done
run "$B/measure -f extrema $T/circle.cubic"
out_is "64
"
# sample -s 7: the arc length between consecutive points, from the
# cumulative chord length of sample -n 5000 -u interpolated linearly at
# the points' parameters (chords miss the arc by (k c)^2 / 24, 1e-9 of
# it here), is 7 but for the last, which is 0 to 7.
"$B/sample" -n 5000 -u "$T/insole.cubic" | awk NF >"$T/fine"
run "$B/sample -s 7 -u $T/insole.cubic"
status 0
e=$(awk 'NR == FNR { if (FNR > 1) { dx = $1 - px; dy = $2 - py; s += sqrt(dx * dx + dy * dy) }
	u[FNR] = $3; cum[FNR] = s; px = $1; py = $2; m = FNR; next }
	NF { while (j < m && u[j + 1] <= $3) j++
		if (j >= m) at = cum[m]
		else at = cum[j] + (cum[j + 1] - cum[j]) * ($3 - u[j]) / (u[j + 1] - u[j])
		if (n) d[n] = at - prev; prev = at; n++ }
	END { for (i = 1; i < n - 1; i++) { x = d[i] - 7; if (x < 0) x = -x; if (x > w) w = x }
		if (n != int(cum[m] / 7) + 2) print n " points for length " cum[m]
		else if (w > 1e-6) print "spacing off by " w
		else if (!(d[n - 1] > 0 && d[n - 1] <= 7 + 1e-6)) print "last interval " d[n - 1] }' \
    "$T/fine" "$T/out")
[ -z "$e" ] && ok || no "insole -s 7: $e"
# the closed curve ends where it starts
awk 'NF { if (!n++) f = $1 " " $2; l = $1 " " $2 } END { exit f != l }' "$T/out" && ok ||
    no "insole -s 7: does not end at its start"

# sample -t 0.05: every dense point within 0.05 of the polyline (and,
# with as few points as halving gives, some dense point farther than a
# tenth of it)
dense "$T/insole.cubic" 200 | awk NF >"$T/fine"
for tol in 0.05 0.5; do
	run "$B/sample -t $tol $T/insole.cubic"
	status 0
	e=$(awk -v tol=$tol 'NR == FNR { if (NF) { x[n] = $1; y[n] = $2; n++ } next }
	{ best = 1e300
	  for (i = 0; i + 1 < n; i++) { ax = x[i]; ay = y[i]; bx = x[i + 1] - ax; by = y[i + 1] - ay
		px = $1 - ax; py = $2 - ay; l = bx * bx + by * by
		t = l > 0 ? (px * bx + py * by) / l : 0; t = t < 0 ? 0 : t > 1 ? 1 : t
		dx = px - t * bx; dy = py - t * by; d = dx * dx + dy * dy; if (d < best) best = d }
	  if (best > worst) worst = best }
	END { worst = sqrt(worst); if (worst > tol * (1 + 1e-9)) print "a point " worst " away"
		else if (worst < tol / 10) print "farthest only " worst ": too many points" }' \
	    "$T/out" "$T/fine")
	[ -z "$e" ] && ok || no "insole -t $tol: $e"
done

# -f obj: the same points as vertices, one line through them all
for o in "-s 7" "-t 0.5"; do
	n=$("$B/sample" $o "$T/insole.cubic" | awk NF | wc -l)
	run "$B/sample $o -f obj $T/insole.cubic"
	status 0
	awk -v n="$n" '$1 == "v" { v++ } $1 == "l" { l = NF - 1; last = $NF }
	    END { exit !(v == n && l == n && last == n) }' "$T/out" && ok ||
	    no "sample $o -f obj: not $n vertices on one line"
done

# units: the insole scaled by 1e-3 and 1e3 (every number of a cubic row
# scales): lengths scale, areas by the square, the energy and the jump
# inversely, counts and parameters not at all; -s and -t scaled with it
# give the same points scaled.
"$B/measure" "$T/insole.cubic" | awk NF >"$T/m0"
"$B/sample" -s 7 "$T/insole.cubic" | awk NF >"$T/s0"
"$B/sample" -t 0.05 "$T/insole.cubic" | awk NF >"$T/t0"
for s in 1e-3 1e3; do
	awk -v s=$s '/^[-0-9]/ { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * s) } { print }' \
	    "$T/insole.cubic" >"$T/scaled"
	"$B/measure" "$T/scaled" | awk NF >"$T/m1"
	e=$(awk -v s=$s 'NR == FNR { for (i = 1; i <= NF; i++) a[i] = $i; next }
	{ split("1 2 1 1 1 1 1 1 1 0 0 0 -1 -1", p)
	  for (i = 1; i <= NF; i++) { w = a[i] * s ^ p[i]; d = $i - w; d = d < 0 ? -d : d
		tol = i == 14 ? 1e-9 / a[9] * s ^ -1 : i == 10 ? 1e-9 : 1e-10 * (w < 0 ? -w : w)
		if (p[i] == 0 && i != 10) tol = 0
		if (!(d <= tol)) printf "field %d: %s, want %s; ", i, $i, w } }' "$T/m0" "$T/m1")
	[ -z "$e" ] && ok || no "measure, insole times $s: $e"
	for o in "-s 7" "-t 0.05"; do
		set -- $o
		v=$(awk -v a="$2" -v s=$s 'BEGIN { printf "%.17g", a * s }')
		"$B/sample" "$1" "$v" "$T/scaled" | awk NF >"$T/p1"
		e=$(awk -v s=$s 'NR == FNR { x[FNR] = $1 * s; y[FNR] = $2 * s; n = FNR; next }
		{ d = $1 - x[FNR]; d = d < 0 ? -d : d; if (d > w) w = d
		  d = $2 - y[FNR]; d = d < 0 ? -d : d; if (d > w) w = d; m = FNR }
		END { if (m != n) print m " points, want " n
			else if (w > 1e-9 * 300 * s) print "off by " w }' \
		    "$T/$([ "$1" = -s ] && echo s0 || echo t0)" "$T/p1")
		[ -z "$e" ] && ok || no "sample $1, insole times $s: $e"
	done
done

finish measure
