#!/bin/sh
# unroll.sh: unroll(1) against closed forms and quadrature, and against
# an independent least-squares conformal map (scipy, when installed).
#  - a swept cubic (a general cylinder) and a cone frustum: the pattern's
#    perimeter and area (measured by measure(1) on the written outline)
#    equal the surface's by Gauss-Legendre quadrature in awk, to 1e-7;
#  - the diagonal of the unrolled parameter rectangle (corners from -e)
#    equals the surface's geodesic between those corners: sqrt(L^2 + H^2)
#    on the cylinder, the cosine rule in the developed sector on the cone;
#  - a dome whose projection loses 2.7 % of its area keeps its area to
#    0.5 %, and a hull bow's and the dome's largest edge strain is no
#    worse than a least-squares conformal map's computed in the test;
#  - a design of two patches unrolls as the one patch it was split from.
T=${TMPDIR:-/tmp}/loft-unroll.$$
. tests/lib.sh

usage_ok unroll

# the base curve of both: a cubic Bezier in the plane z = 0
cat >"$T/cyl" <<'EOF'
bezier-surface m=1 n=3
0 0 0
1 2 0
3 -1 0
4 1 0
0 0 5
1 2 5
3 -1 5
4 1 5

EOF
# the cone: apex (1, 2, 10), the base curve scaled about it by 0.3 and 1
awk 'BEGIN {
	split("0 0 0 3 4 0 6 -2 0 9 1 0", c, " ")
	print "bezier-surface m=1 n=3"
	for (s = 0; s < 2; s++) {
		f = s ? 1 : 0.3
		for (j = 0; j < 4; j++)
			printf "%.17g %.17g %.17g\n", 1 + f * (c[3*j+1] - 1),
			    2 + f * (c[3*j+2] - 2), 10 + f * (c[3*j+3] - 10)
	}
	print ""
}' >"$T/cone"

# quadrature of the base curves: length L, and for the cone the angle
# Phi the generator sweeps, int |(c - A) x c'| / |c - A|^2 dv, and the
# distances rho0, rho1 of the base curve's ends from the apex
QUAD='
function gl() {
	X[1] = 0.046910077030668004; W[1] = 0.11846344252809454
	X[2] = 0.23076534494715845; W[2] = 0.23931433524968324
	X[3] = 0.5; W[3] = 0.28444444444444444
	X[4] = 0.76923465505284155; W[4] = 0.23931433524968324
	X[5] = 0.95308992296933200; W[5] = 0.11846344252809454
}
# point and derivative of the cubic Bezier P[0..3][1..3] at t
function bez(t,   k, a, b, c, d) {
	a = (1-t)^3; b = 3*(1-t)^2*t; c = 3*(1-t)*t*t; d = t^3
	for (k = 1; k <= 3; k++) {
		Q[k] = a*P[0,k] + b*P[1,k] + c*P[2,k] + d*P[3,k]
		D[k] = 3*(1-t)^2*(P[1,k]-P[0,k]) + 6*(1-t)*t*(P[2,k]-P[1,k]) \
		    + 3*t*t*(P[3,k]-P[2,k])
	}
}
function integrate(   M, i, q, t, dl, r, cx, cy, cz, rr) {
	M = 400; L = 0; PHI = 0
	for (i = 0; i < M; i++)
		for (q = 1; q <= 5; q++) {
			t = (i + X[q]) / M; bez(t)
			dl = sqrt(D[1]^2 + D[2]^2 + D[3]^2)
			L += W[q] * dl / M
			r[1] = Q[1]-A[1]; r[2] = Q[2]-A[2]; r[3] = Q[3]-A[3]
			cx = r[2]*D[3]-r[3]*D[2]; cy = r[3]*D[1]-r[1]*D[3]
			cz = r[1]*D[2]-r[2]*D[1]
			rr = r[1]^2 + r[2]^2 + r[3]^2
			PHI += W[q] * sqrt(cx^2 + cy^2 + cz^2) / rr / M
			AREA2 += W[q] * sqrt(cx^2 + cy^2 + cz^2) / M
		}
}
function rel(a, b) { return (a - b) / b < 0 ? (b - a) / b : (a - b) / b }
'
# closed forms: "perimeter area diagonal" of each surface
awk "$QUAD"'BEGIN {
	gl(); split("0 0 0 1 2 0 3 -1 0 4 1 0", c, " ")
	for (j = 0; j < 4; j++) for (k = 1; k <= 3; k++) P[j,k] = c[3*j+k]
	A[1] = 1; A[2] = 2; A[3] = 10; integrate()
	H = 5
	printf "%.17g %.17g %.17g\n", 2*L + 2*H, L*H, sqrt(L*L + H*H)
	# the cone x = A + s (c(v) - A), s from 0.3 to 1
	split("0 0 0 3 4 0 6 -2 0 9 1 0", c, " ")
	for (j = 0; j < 4; j++) for (k = 1; k <= 3; k++) P[j,k] = c[3*j+k]
	AREA2 = 0; integrate()
	r0 = sqrt((P[0,1]-1)^2 + (P[0,2]-2)^2 + (P[0,3]-10)^2)
	r1 = sqrt((P[3,1]-1)^2 + (P[3,2]-2)^2 + (P[3,3]-10)^2)
	a = 0.3 * r0; b = r1
	printf "%.17g %.17g %.17g\n", 1.3*L + 0.7*(r0 + r1), (1 - 0.09)/2 * AREA2,
	    sqrt(a*a + b*b - 2*a*b*cos(PHI))
}' >"$T/ref"

# the pattern's numbers: perimeter, area, and the distance from the
# image of (0, 0) (edge u0's start) to that of (1, 1) (edge u1's end)
pattern() {
	$B/unroll -e "$1" >"$T/pat" 2>"$T/err" || return 1
	$B/measure -f length,area "$T/pat" | head -1 | tr '\n' ' '
	awk '/^cubic/ { e = $0; first = 1; next }
	    NF == 8 && e ~ /edge=0:u0/ && first { x0 = $1; y0 = $2 }
	    NF == 8 && e ~ /edge=0:u1/ { x1 = $3; y1 = $4 }
	    NF == 8 { first = 0 }
	    END { printf "%.17g\n", sqrt((x1-x0)^2 + (y1-y0)^2) }' "$T/pat"
}
n=0
for s in cyl cone; do
	n=$((n + 1))
	got=$(pattern "$T/$s")
	ref=$(sed -n "${n}p" "$T/ref")
	echo "$got $ref" | awk -v s=$s "$QUAD"'{
		split("perimeter area diagonal", w, " ")
		for (i = 1; i <= 3; i++)
			if (!(rel($i, $(i+3)) <= 1e-7)) {
				printf "%s: %s %.12g, want %.12g\n", s, w[i], $i,
				    $(i+3); bad = 1
			}
		exit bad }' >"$T/cmp" && ok || no "$(cat "$T/cmp")"
done

# the same cylinder a million times larger: its area a million million
# times (results do not depend on the units)
awk '/^[0-9-]/ { print $1 * 1e6, $2 * 1e6, $3 * 1e6; next } { print }' \
    "$T/cyl" >"$T/big"
a=$($B/unroll "$T/cyl" | $B/measure -f area)
b=$($B/unroll "$T/big" | $B/measure -f area)
echo "$a $b" | awk '{ r = $2 / ($1 * 1e12) - 1; exit !(r < 1e-9 && r > -1e-9) }' &&
    ok || no "unroll of the cylinder times 1e6: area $b, want $a e12"

# measure of a surface: the cylinder's area (field 1) is L H, its
# Gaussian curvature 0 (fields 2 and 5), developable (field 16); the
# dome's area the quadrature's below, not developable
set -- $($B/measure "$T/cyl")
echo "$1 $2 $5 ${16} $(sed -n 1p "$T/ref")" | awk "$QUAD"'{
	exit !(rel($1, $6) <= 1e-9 && $2 == 0 && $3 == 0 && $4 == 1) }' && ok ||
    no "measure of the cylinder: $*"

# -v says which way
run "$B/unroll -v $T/cyl"
says "developable, developed exactly"

# the dome: a bicubic over [-1, 1]^2, inner control points raised 0.355,
# z = 0.355 g(u) g(v), g(t) = 3t(1 - t): its projection, the square of
# area 4, loses 2.7 % of its area (quadrature below)
awk 'BEGIN { print "bezier-surface m=3 n=3"
	for (i = 0; i < 4; i++) for (j = 0; j < 4; j++)
		printf "%.17g %.17g %s\n", i/3*2 - 1, j/3*2 - 1,
		    (i % 3 && j % 3) ? 0.355 : 0
	print "" }' >"$T/dome"
area=$(awk "$QUAD"'BEGIN { gl(); h = 0.355; M = 40
	for (a = 0; a < M; a++) for (p = 1; p <= 5; p++)
	for (b = 0; b < M; b++) for (q = 1; q <= 5; q++) {
		u = (a + X[p]) / M; v = (b + X[q]) / M
		gu = 3*u*(1-u); gv = 3*v*(1-v); du = 3 - 6*u; dv = 3 - 6*v
		s += W[p] * W[q] * sqrt(4*h*h*(du*gv)^2 + 4*h*h*(gu*dv)^2 + 16)
	}
	printf "%.17g\n", s / (M * M) }')
echo "$area" | awk '{ exit !(1 - 4 / $1 > 0.026) }' && ok ||
    no "the dome's projection loses less than 2.6 %: area $area"
set -- $($B/measure "$T/dome")
echo "$1 ${16} $area" | awk "$QUAD"'{ exit !(rel($1, $3) <= 1e-9 && $2 == 0) }' &&
    ok || no "measure of the dome: area $1 developable ${16}, want $area 0"
got=$($B/unroll "$T/dome" | $B/measure -f area)
echo "$got $area" | awk '{ r = $1 / $2 - 1; exit !(r < 0.005 && r > -0.005) }' &&
    ok || no "the dome unrolled: area $got, surface $area (want 0.5 %)"
run "$B/unroll -v $T/dome"
says "doubly curved, least strain"

# a bow plate of a hull: twisted and flared, doubly curved
cat >"$T/bow" <<'EOF'
bezier-surface m=3 n=3
0 0 0
0.1 0.05 0.4
0.2 0.1 0.8
0.35 0.15 1.2
1 0.3 0
1 0.5 0.4
1 0.65 0.8
1 0.8 1.2
2 0.5 0
2 0.8 0.35
2 1 0.8
2 1.1 1.2
3 0.6 0
3 0.95 0.3
3 1.15 0.75
3 1.2 1.2

EOF
if /usr/bin/python3 -c 'import scipy, numpy' 2>/dev/null; then
	for s in dome bow; do
		lscm=$(/usr/bin/python3 tests/unroll_lscm.py "$T/$s" 16)
		$B/unroll -v -n 16 "$T/$s" 2>"$T/err" >/dev/null
		mine=$(sed -n 's/.*edge strain largest \([^ ]*\) mean \([^,]*\),.*/\1 \2/p' \
		    "$T/err")
		echo "$mine $lscm" | awk '{ exit !($1 > 0 && $1 <= $3) }' && ok ||
		    no "$s: largest edge strain $mine (largest, mean), LSCM's $lscm"
	done
else
	echo "unroll: skip: the LSCM comparison (no /usr/bin/python3 with scipy)"
fi

# the dome a millionth the size: the same strain (units do not matter)
awk '/^[0-9-]/ { printf "%.17g %.17g %.17g\n", $1 * 1e-6, $2 * 1e-6, $3 * 1e-6; next }
    { print }' "$T/dome" >"$T/small"
a=$($B/unroll -v -n 8 "$T/dome" 2>&1 >/dev/null | sed 's/.*largest \([^ ]*\) .*/\1/')
b=$($B/unroll -v -n 8 "$T/small" 2>&1 >/dev/null | sed 's/.*largest \([^ ]*\) .*/\1/')
[ -n "$a" ] && [ "$a" = "$b" ] && ok ||
    no "the dome's largest strain $a, a millionth of it $b"

# the dome 2^-300 and 2^300 times the size (about 1e-90 and 1e90): the
# same numbers of measure that do not depend on the size (K dA, fields
# 14 to 16: doubly curved), and the same pattern unrolled, 2^-300 and
# 2^300 times as large, to the digits written: the products of four
# lengths in the curvature under- and overflowed, and both read the dome
# as developable
m=$($B/measure "$T/dome" | awk 'NF == 16 { print $14, $15, $16 }')
$B/unroll -n 8 "$T/dome" >"$T/flat"
for e in -300 300; do
	awk -v e=$e 'BEGIN { f = 2 ^ e } /^[0-9-]/ { printf "%.17g %.17g %.17g\n",
	    $1 * f, $2 * f, $3 * f; next } { print }' "$T/dome" >"$T/scaled"
	got=$($B/measure "$T/scaled" | awk 'NF == 16 { print $14, $15, $16 }')
	[ -n "$m" ] && [ "$got" = "$m" ] && ok ||
	    no "measure of the dome times 2^$e: K dA $got, want $m"
	$B/unroll -n 8 "$T/scaled" | awk -v e=$e 'BEGIN { f = 2 ^ e }
	    NR == FNR { x[FNR] = $0; next }
	    { if (NF != split(x[FNR], a, " ")) bad = 1
	      for (i = 1; i <= NF; i++) {
		d = $i / f - a[i]
		if ($i !~ /^[a-z]/ && d * d > 1e-24 * (a[i] * a[i] + 1))
			bad = 1
	      } }
	    END { exit bad || FNR != NR - FNR || FNR < 2 }' "$T/flat" - &&
	    ok || no "the dome times 2^$e unrolled: not the pattern times 2^$e"
done
# past what a double holds (2^-600 and 2^600, about 1e-180 and 1e180):
# the area or the curvature is no double, which both say
for e in -600 600; do
	awk -v e=$e 'BEGIN { f = 2 ^ e } /^[0-9-]/ { printf "%.17g %.17g %.17g\n",
	    $1 * f, $2 * f, $3 * f; next } { print }' "$T/dome" >"$T/scaled$e"
done
fails 1 ":1: the sheet's area underflows: coefficients too small" \
    "$B/unroll -v $T/scaled-600"
fails 1 ":1: the surface's curvature overflows: coefficients too small" \
    "$B/measure $T/scaled-600"
fails 1 ":1: the sheet's area overflows: coefficients too large" \
    "$B/unroll -v $T/scaled600"
fails 1 ":1: the surface's numbers overflow: coefficients too large" \
    "$B/measure $T/scaled600"

# -m: loftplot draws each edge in the colour unroll gave it
$B/unroll -m -n 4 "$T/dome" >"$T/map"
c=$(sed -n 's/^cubic .*colour=\([0-9a-f]*\).*/\1/p' "$T/map" | sort -u)
$B/loftplot "$T/map" >"$T/map.svg"
n=0
for x in $c; do grep -q "#$x" "$T/map.svg" || n=$((n + 1)); done
[ -n "$c" ] && [ $n -eq 0 ] && ok ||
    no "unroll -m | loftplot: $n of the colours not drawn"

# a design: the example patch split in two unrolls as the patch
a=$($B/unroll man/examples/hull.patch | $B/measure -f area)
b=$($B/unroll man/examples/split.patch | $B/measure -f area)
echo "$a $b" | awk '{ r = $2 / $1 - 1; exit !(r < 1e-4 && r > -1e-4) }' &&
    ok || no "split.patch unrolled: area $b, hull.patch's $a"

# -x: a station's image on the cylinder's pattern is a straight line
# across it, H = 5 long
$B/unroll -x 2 "$T/cyl" | awk '/^points/ { on = 1; next } on && NF == 2 {
	if (n++ == 0) { x0 = $1; y0 = $2 } x1 = $1; y1 = $2 }
	END { d = sqrt((x1-x0)^2 + (y1-y0)^2); exit !(d > 5 - 1e-6 && d < 5 + 1e-6) }' &&
    ok || no "unroll -x 2: the station's image is not 5 long"

# bad input
fails 1 "unroll lays surface records flat" "printf '1 2\n3 4\n' | $B/unroll"
fails 2 "-t" "$B/unroll -t 0 $T/cyl"

rm -rf "$T"
finish unroll
