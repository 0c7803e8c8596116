#!/bin/sh
# offset.sh: command tests of offset(1), run from the top of the tree.
# The references are independent of lib/offset.c: awk's own Hermite
# evaluation of the rows (eq. 7) against circles, straight lines and
# quarter circles worked out by hand, and bin/test/offsetref, which
# reads the records itself and finds distances by Newton projection.
# The last line is "offset: N passed, M failed".

T=bin/test/offset
. tests/lib.sh
R=bin/test/offsetref

# pts N FILE: N + 1 points of each cubic row of FILE, u = 0, 1/N, .. 1,
# by the Hermite form P = h00 A + h01 B + h10 A' + h11 B'
pts() {
	awk -v n="$1" 'NF == 8 { for (j = 0; j <= n; j++) { u = j / n
		h00 = 2*u^3 - 3*u^2 + 1; h01 = 3*u^2 - 2*u^3
		h10 = u^3 - 2*u^2 + u; h11 = u^3 - u^2
		printf "%.17g %.17g\n", h00*$1 + h01*$3 + h10*$5 + h11*$7,
		    h00*$2 + h01*$4 + h10*$6 + h11*$8 } }' "$2"
}
# ref CURVE OUT DIST TOL [-n]: offsetref's verdict
ref() {
	r=$("$R" "$@" 2>&1) && ok || no "offsetref $*: $r"
}

# ---- usage -----------------------------------------------------------
usage_ok offset
fails 2 "-d is missing" "$B/offset /dev/null"
fails 2 "-d '0': the offset at distance 0 is the curve" "$B/offset -d 0 /dev/null"
fails 2 "-d 'x' is not a number" "$B/offset -d x /dev/null"
fails 2 "-t '0': want a positive tolerance" "$B/offset -d 1 -t 0 /dev/null"
fails 2 "want round, miter or bevel" "$B/offset -d 1 -j square /dev/null"
fails 2 "-p '0'" "$B/offset -d 1 -p 0 /dev/null"

# ---- a circle: the offset points are r + d from the centre ----------------
# 16 knots on a circle of radius 10 about (3, -2), fitted; dev is how far
# the fit itself strays from radius 10 (awk, 400 points a segment), so the
# offset at d must be within tol + dev of radius 10 + d.
awk 'BEGIN { for (i = 0; i < 16; i++) { a = 2 * 3.141592653589793 * i / 16
    printf "%.17g %.17g\n", 3 + 10 * cos(a), -2 + 10 * sin(a) } }' >"$T/circle.knots"
$B/splinefit "$T/circle.knots" >"$T/circle.cubic"
awk '{ k[NR] = $0 } END { for (i = NR; i > 0; i--) print k[i] }' \
    "$T/circle.knots" | $B/splinefit >"$T/circle-cw.cubic"
dev=$(pts 400 "$T/circle.cubic" | awk '{ e = sqrt(($1 - 3)^2 + ($2 + 2)^2) - 10
    e = e < 0 ? -e : e; if (e > m) m = e } END { printf "%.17g", m }')
for f in circle circle-cw; do
	for d in 3 -4 -9.5 0.01; do
		run "$B/offset -d $d $T/$f.cubic"
		status 0
		grep -q '^cubic closed=1 offset='"$d"'$' "$T/out" && ok ||
		    no "$f -d $d: header $(head -1 "$T/out")"
		pts 50 "$T/out" | awk -v d="$d" -v dev="$dev" '{
		    e = sqrt(($1 - 3)^2 + ($2 + 2)^2) - 10 - d; e = e < 0 ? -e : e
		    if (e > m) m = e } END { t = (d < 0 ? -d : d) * 1e-3 + dev
		    if (!(m <= t) || NR < 100) { printf "off by %g > %g (%d points)\n", m, t, NR; exit 1 } }' \
		    >"$T/why" && ok || no "$f -d $d: not at radius 10 + d: $(cat "$T/why")"
	done
	# inward beyond the radius: nothing is left
	fails 1 "offset: $T/$f.cubic:1: the offset vanishes: 10.5 inward is more than the outline's inradius" \
	    "$B/offset -d -10.5 $T/$f.cubic"
done
echo "dev $dev" >"$T/circle.dev"

# ---- a rectangle of four straight segments, corners at its knots --------
# [0,4] x [0,2], counter-clockwise; each row's tangents are its chord.
printf 'cubic closed=1 size=7 straight=1,2,3,4\n0 0 4 0 4 0 4 0\n4 0 4 2 0 2 0 2\n4 2 0 2 -4 0 -4 0\n0 2 0 0 0 -2 0 -2\n' \
    >"$T/rect.cubic"
# by hand, at distance 0.5 outward: points beside a side are on the line
# 0.5 from it exactly (|y + 0.5| etc. at rounding); points beyond a corner
# are on the quarter circle of radius 0.5 about it, within tol = 5e-4.
run "$B/offset -d 0.5 $T/rect.cubic"
status 0
pts 40 "$T/out" | awk '{ x = $1; y = $2
    if (x >= 0 && x <= 4) e = (y < 1 ? -0.5 - y : y - 2.5)
    else if (y >= 0 && y <= 2) e = (x < 2 ? -0.5 - x : x - 4.5)
    else { cx = x < 2 ? 0 : 4; cy = y < 1 ? 0 : 2
	    e = sqrt((x - cx)^2 + (y - cy)^2) - 0.5; arc++
	    if (e < -5e-4 || e > 5e-4) { print "corner " x " " y ": " e; exit 1 }
	    next }
    if (e < -1e-12 || e > 1e-12) { print "side " x " " y ": " e; exit 1 }; side++ }
    END { if (arc < 40 || side < 100) { print arc " arc, " side " side points"; exit 1 } }' \
    >"$T/why" && ok || no "round: $(cat "$T/why")"
grep -q '^cubic closed=1 size=7 offset=0.5$' "$T/out" && ok || no "round: header $(head -1 "$T/out")"
ref "$T/rect.cubic" "$T/out" 0.5 5e-4
# miter: every point on the box [-0.5, 4.5] x [-0.5, 2.5], its corners rows'
# ends (the turn is 90 degrees, the miter 1.41 times d, within the limit)
run "$B/offset -d 0.5 -j miter $T/rect.cubic"
status 0
pts 40 "$T/out" | awk '{ a = ($1 < 2 ? 2 - $1 : $1 - 2) - 2.5; b = ($2 < 1 ? 1 - $2 : $2 - 1) - 1.5
    e = a > b ? a : b; if (e < -1e-12 || e > 1e-12) { print $0 ": " e; exit 1 } }' \
    >"$T/why" && ok || no "miter: off the box: $(cat "$T/why")"
for c in "4.5 -0.5" "4.5 2.5" "-0.5 2.5" "-0.5 -0.5"; do
	awk -v c="$c" 'NF == 8 && $1 " " $2 == c { f = 1 } END { exit !f }' "$T/out" &&
	    ok || no "miter: no sharp corner at $c"
done
# bevel: on the octagon |x-2| <= 2.5, |y-1| <= 1.5, |x-2| + |y-1| <= 3.5,
# with a straight chamfer from (4, -0.5) to (4.5, 0) and so on
run "$B/offset -d 0.5 -j bevel $T/rect.cubic"
status 0
pts 40 "$T/out" | awk '{ a = ($1 < 2 ? 2 - $1 : $1 - 2); b = ($2 < 1 ? 1 - $2 : $2 - 1)
    e = a - 2.5; if (b - 1.5 > e) e = b - 1.5; if (a + b - 3.5 > e) e = a + b - 3.5
    if (e < -1e-12 || e > 1e-12) { print $0 ": " e; exit 1 }
    if (a > 2 + 1e-9 && b > 1 + 1e-9) n++ } END { if (n < 40) { print n " chamfer points"; exit 1 } }' \
    >"$T/why" && ok || no "bevel: off the octagon: $(cat "$T/why")"
[ "$(grep -c '^[-0-9]' "$T/out")" = 8 ] && ok || no "bevel: not 4 sides and 4 chamfers"
# inward: the rectangle [0.5, 3.5] x [0.5, 1.5] with sharp corners, the
# offsets of the sides trimmed where they cross, whatever the join
for j in round miter bevel; do
	run "$B/offset -d -0.5 -j $j -p 12 $T/rect.cubic"
	status 0
	out_is "cubic closed=1 size=7 offset=-0.5
0.5 0.5 3.5 0.5 3 0 3 0
3.5 0.5 3.5 1.5 0 1 0 1
3.5 1.5 0.5 1.5 -3 0 -3 0
0.5 1.5 0.5 0.5 0 -1 0 -1
"
done
fails 1 "the offset vanishes: 1.2 inward" "$B/offset -d -1.2 $T/rect.cubic"
# a miter beyond the limit (4): a turn of 170 degrees falls back to a bevel
printf 'cubic\n0 0 10 0 10 0 10 0\n10 0 0.151922 1.736482 -9.848078 1.736482 -9.848078 1.736482\n' \
    >"$T/spike.cubic"
run "$B/offset -d -1 -j miter $T/spike.cubic"
status 0
pts 8 "$T/out" | awk '{ if ($1 > m) m = $1 } END { exit !(m > 10 && m < 11.2) }' && ok ||
    no "miter past the limit: not a bevel: $(cat "$T/out")"

# ---- the insole: distance |d| from the whole outline, both ways --------
$B/splinefit man/figures/insole.knots >"$T/insole.cubic"
for d in -5 15 4; do
	run "$B/offset -d $d $T/insole.cubic"
	status 0
	ref "$T/insole.cubic" "$T/out" "$d" "$(echo "$d" | awk '{ print ($1 < 0 ? -$1 : $1) * 1e-3 }')"
done
# far outward the arch's concave side turns the raw offset back in a
# swallowtail; what is left is one curve (the dilated insole has no hole)
run "$B/offset -d 200 $T/insole.cubic"
status 0
[ "$(grep -c '^cubic' "$T/out")" = 1 ] && ok || no "-d 200: not one curve: $(grep -c '^cubic' "$T/out")"
ref "$T/insole.cubic" "$T/out" 200 0.2
# a tighter tolerance holds too
run "$B/offset -d 15 -t 1e-6 $T/insole.cubic"
ref "$T/insole.cubic" "$T/out" 15 1e-6
# run backwards, the same outline has the same outward offset
awk '/^cubic/ { print; next } NF == 8 { r[n++] = $3 " " $4 " " $1 " " $2 " " \
    (-$7) " " (-$8) " " (-$5) " " (-$6) } END { for (i = n - 1; i >= 0; i--) print r[i] }' \
    "$T/insole.cubic" >"$T/insole-back.cubic"
run "$B/offset -d 15 $T/insole-back.cubic"
status 0
ref "$T/insole.cubic" "$T/out" 15 0.015
cp "$T/out" "$T/back15"
run "$B/offset -d 15 $T/insole.cubic"
ref "$T/insole-back.cubic" "$T/out" 15 0.015
# lining and lasting lines in one call: one record each, in order
run "$B/grade -r 3:3 man/figures/insole.knots | $B/splinefit | $B/offset -d -4 -d 15"
status 0
[ "$(grep '^cubic' "$T/out" | tr '\n' '|')" = "cubic closed=1 size=+3 offset=-4|cubic closed=1 size=+3 offset=15|" ] &&
    ok || no "two distances: $(grep '^cubic' "$T/out")"

# ---- units: scaled by 1e-3 and 1e3, input and distance alike ----------------
run "$B/offset -d -5 $T/insole.cubic"
cp "$T/out" "$T/unit"
for s in 1e-3 1e3; do
	awk -v s=$s 'NF == 8 { for (i = 1; i <= 8; i++) $i = sprintf("%.17g", $i * s) } { print }' \
	    "$T/insole.cubic" >"$T/scaled"
	run "$B/offset -d $(awk -v s=$s 'BEGIN { print -5 * s }') $T/scaled"
	status 0
	awk -v s=$s 'NR == FNR { if (NF == 8) for (i = 1; i <= 8; i++) a[FNR, i] = $i * s; n = FNR; next }
	    { m = FNR; if (NF == 8) for (i = 1; i <= 8; i++) { e = $i - a[FNR, i]; e = e < 0 ? -e : e
		if (e > w) w = e } }
	    END { if (m != n || !(w <= 1e-9 * 300 * s)) { print "off by " w " rows " n " " m; exit 1 } }' \
	    "$T/unit" "$T/out" >"$T/why" && ok || no "scaled by $s: $(cat "$T/why")"
done

# ---- an open curve: to the left of travel ------------------------------------
# the quarter of the unit circle clockwise from (0, 1): left is outward,
# so at d the points are at radius 1 + d from the origin
$B/splinefit -o -S 1,0 -E 0,-1 man/figures/arc.knots >"$T/arc.cubic"
adev=$(pts 400 "$T/arc.cubic" | awk '{ e = sqrt($1^2 + $2^2) - 1; e = e < 0 ? -e : e
    if (e > m) m = e } END { printf "%.17g", m }')
for d in 0.5 -0.5; do
	run "$B/offset -d $d $T/arc.cubic"
	status 0
	grep -q '^cubic closed=0 offset=' "$T/out" && ok || no "arc: $(head -1 "$T/out")"
	pts 50 "$T/out" | awk -v d=$d -v dev="$adev" '{ e = sqrt($1^2 + $2^2) - 1 - d; e = e < 0 ? -e : e
	    if (e > m) m = e } END { exit !(m <= (d < 0 ? -d : d) * 1e-3 + dev) }' && ok ||
	    no "arc -d $d: not at radius 1 + d"
	ref "$T/arc.cubic" "$T/out" $d 5e-4
done
$B/splinefit -o man/figures/insole.knots >"$T/open.cubic"
for d in 6 30 -60; do
	run "$B/offset -d $d $T/open.cubic"
	status 0
	ref "$T/open.cubic" "$T/out" $d "$(echo "$d" | awk '{ print ($1 < 0 ? -$1 : $1) * 1e-3 }')"
done

# ---- loops cut away ----------------------------------------------------------
# an ellipse of semi-axes 4 and 1: its radius of curvature is 1/4 at the
# ends, so at 0.6 inward the raw offset has swallowtails there
awk 'BEGIN { for (i = 0; i < 12; i++) { a = 2 * 3.141592653589793 * i / 12
    printf "%.17g %.17g\n", 4 * cos(a), sin(a) } }' | $B/splinefit >"$T/ellipse.cubic"
for d in -0.6 -0.9; do
	run "$B/offset -d $d $T/ellipse.cubic"
	status 0
	[ "$(grep -c '^cubic' "$T/out")" = 1 ] && ok || no "ellipse $d: not one curve"
	ref "$T/ellipse.cubic" "$T/out" $d "$(echo "$d" | awk '{ print -$1 * 1e-3 }')"
done
# a dumbbell whose waist is 0.6 wide: at 0.4 inward the offset falls into
# two closed curves, one in each lobe (crossings between far parts)
awk 'BEGIN { for (i = 0; i < 24; i++) { a = 2 * 3.141592653589793 * i / 24
    printf "%.17g %.17g\n", 3 * cos(a), sin(a) * (0.3 + 1.2 * cos(a)^2) } }' |
    $B/splinefit >"$T/dumbbell.cubic"
run "$B/offset -d -0.4 $T/dumbbell.cubic"
status 0
[ "$(grep -c '^cubic closed=1 offset=-0.4$' "$T/out")" = 2 ] && ok ||
    no "dumbbell: not two curves: $(grep '^cubic' "$T/out")"
ref "$T/dumbbell.cubic" "$T/out" -0.4 4e-4
run "$B/offset -d -0.2 $T/dumbbell.cubic"
[ "$(grep -c '^cubic' "$T/out")" = 1 ] && ok || no "dumbbell -0.2: not one curve"
ref "$T/dumbbell.cubic" "$T/out" -0.2 2e-4

# a wavy outline, 14 waves of amplitude 4 on a circle of radius 50: the
# radius of curvature at each crest and trough is about 3.2, so at 5
# either way every wave's offset has a swallowtail to cut away
awk 'BEGIN { for (i = 0; i < 168; i++) { a = 2 * 3.141592653589793 * i / 168
    r = 50 + 4 * sin(14 * a); printf "%.17g %.17g\n", r * cos(a), r * sin(a) } }' |
    $B/splinefit >"$T/wavy.cubic"
for d in -5 5; do
	run "$B/offset -d $d $T/wavy.cubic"
	status 0
	ref "$T/wavy.cubic" "$T/out" $d 0.005
done

# ---- every curve type: the same curve as quartic and bezier rows -------------
# a quartic row is the cubic's A B A' B' and its point at u = 1/2,
# (A + B)/2 + (A' - B')/8; a bezier record of one cubic segment is A,
# A + A'/3, B - B'/3, B
awk '/^cubic/ { print "quartic closed=1"; next } NF == 8 { printf "%s %.17g %.17g\n", $0,
    ($1 + $3) / 2 + ($5 - $7) / 8, ($2 + $4) / 2 + ($6 - $8) / 8 }' "$T/insole.cubic" \
    >"$T/insole.quartic"
run "$B/offset -d 15 $T/insole.quartic"
status 0
ref "$T/insole.cubic" "$T/out" 15 0.015
printf 'cubic\n0 0 10 0 0 30 0 -30\n' >"$T/hump.cubic"
awk 'NR == 1 { print "bezier"; next } { printf "%s %s\n%.17g %.17g\n%.17g %.17g\n%s %s\n",
    $1, $2, $1 + $5 / 3, $2 + $6 / 3, $3 - $7 / 3, $4 - $8 / 3, $3, $4 }' \
    "$T/hump.cubic" >"$T/hump.bezier"
run "$B/offset -d 1 $T/hump.bezier"
status 0
ref "$T/hump.cubic" "$T/out" 1 1e-3

# ---- records it cannot offset: a message each, the others written ------------
{ cat "$T/rect.cubic"; printf '\n0 0\n1 1\n\ncubic\n0 0 0 1 0 0 1 0 0 1 0 0\n\n'
  printf 'patch id=1\n0 0 1 0 1 0 1 0 0.5 0\n0 1 1 1 1 0 1 0 0.5 1\n0 1 0 1 0 0 0 0 0 1\n0 1 0 1 0 0 0 0 0 1\n0 0.5 1 0.5 1 0 1 0 0.5 0.5\n\n'
  cat "$T/rect.cubic"; } >"$T/mixed"
run "$B/offset -d -0.5 $T/mixed"
status 1
says "offset: $T/mixed:7: a point record is no curve"
says "offset: $T/mixed:10: a space curve (3 coordinates)"
says "offset: $T/mixed:13: a patch record is a surface"
[ "$(grep -c '^cubic closed=1 size=7 offset=-0.5$' "$T/out")" = 2 ] && ok ||
    no "mixed: the good records' offsets not both written"
# one distance of several vanishes: nothing for that record
fails 1 "-d -1.5: the offset vanishes" "$B/offset -d 1 -d -1.5 $T/rect.cubic"
fails 1 "segment 2 does not start where segment 1 ends" \
    "printf 'cubic\n0 0 1 0 1 0 1 0\n2 0 3 0 1 0 1 0\n' | $B/offset -d 1"
fails 1 "the closed curve encloses no area" \
    "printf 'cubic closed=1\n0 0 1 0 1 0 1 0\n1 0 0 0 -1 0 -1 0\n' | $B/offset -d 1"

# ---- regressions, from a sweep of jittered insoles (tests/bench/gen) ------
# the outlines are in tests/ref/offset-*.cubic
# a swallowtail smaller than the tolerance (its fitted pieces do not
# cross) once condemned the whole outline: "vanishes" at -25
run "$B/offset -d -25 tests/ref/offset-tinytail.cubic"
status 0
ref tests/ref/offset-tinytail.cubic "$T/out" -25 0.025
# three branches nearly meeting at the waist left a short kept run that
# led into a part without closing it: "do not close up" at -30
run "$B/offset -d -30 tests/ref/offset-nearpinch.cubic"
status 0
ref tests/ref/offset-nearpinch.cubic "$T/out" -30 0.03
# an open outline whose ends nearly meet: its offset passes the curve's
# other end without crossing itself, and is cut where it comes nearer
# than the distance (once kept whole: "forward" 0.06 off at 30)
run "$B/offset -d 30 tests/ref/offset-nearends.cubic"
status 0
ref tests/ref/offset-nearends.cubic "$T/out" 30 0.03

finish offset
