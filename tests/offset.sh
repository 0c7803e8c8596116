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
printf 'cubic closed=1 size=7\n0 0 4 0 4 0 4 0\n4 0 4 2 0 2 0 2\n4 2 0 2 -4 0 -4 0\n0 2 0 0 0 -2 0 -2\n' \
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
run "$B/grade -s 3:3 man/figures/insole.knots | $B/splinefit | $B/offset -d -4 -d 15"
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
# a swallowtail smaller than the tolerance (its fitted pieces do not
# cross) once condemned the whole outline: "vanishes" at -25
cat >"$T/tinytail.cubic" <<'END'
cubic closed=1
0.28 -0.23 4.12 -18 -0.7898213239152684 -18.609568186362246 9.666141927075097 -15.83557831480497
4.12 -18 16.02 -28.21 8.339935510615971 -13.662917730274303 14.536685956949013 -6.778460566012889
16.02 -28.21 35.52 -32.42 18.220585984394347 -8.496264138238713 20.107793491144484 -1.3404326980806596
35.52 -32.42 71.23 -30.07 35.87209154108969 -2.3913177978178264 35.21262845155809 7.233790101770955
71.23 -30.07 106.64 -24.06 35.45538465483764 7.283659921141097 36.02262199710497 -1.6620441016558025
106.64 -24.06 147.2 -36.58 42.639974265841325 -1.9673614466207476 40.49844820632734 -14.181798533117853
147.2 -36.58 182.65 -44.18 34.32446709157774 -12.019785908076742 36.17282180593263 -3.9104350526574114
182.65 -44.18 208.05 -45.11 25.31095359500539 -2.7362211520324693 25.423896863583362 1.2332374093448333
208.05 -45.11 233.66 -40.29 26.202806738017248 1.2710200042323962 24.524221849589335 9.243632325970225
233.66 -40.29 253.55 -28.16 21.990547954519492 8.288643822621374 17.4528684615787 15.739055006035121
253.55 -28.16 265.75 -12.09 15.145209846325834 13.658000767840837 8.554214507176384 18.491784186276714
265.75 -12.09 268.99 1.88 6.10050658715129 13.18756399455755 -0.17220627428473537 14.510626300801386
268.99 1.88 263.87 18.11 -0.20572547489218096 17.335056455489145 -9.30401109987125 14.660382615453045
263.87 18.11 248.75 32.48 -11.315440426502605 17.82980311762407 -18.01312309619915 11.077646181628184
248.75 32.48 225.26 42.54 -21.829359726177536 13.424541770277655 -24.320941666259213 8.17842691178637
225.26 42.54 192.88 50.48 -31.73731645333304 10.672338536542457 -33.302987101595946 3.0329454307036636
192.88 50.48 121.52 38.45 -72.48669499761013 6.6014555904288885 -71.63022447173111 -14.993956087494434
121.52 38.45 81.42 33.11 -39.63119793396784 -8.295778016879261 -40.36642713980493 -3.2834954934693226
81.42 33.11 40.77 30.39 -40.60747939224883 -3.303103222978028 -40.651178037302444 -2.723337807388267
40.77 30.39 13.92 24.25 -28.00013580774219 -1.8758085777307134 -23.91596970682011 -14.344839007310519
13.92 24.25 2.97 12.24 -14.267536936022584 -8.557692742006441 -6.884917742143189 -15.126461694575454
2.97 12.24 0.28 -0.23 -5.33072594108492 -11.711835169580407 -0.5464291827213055 -12.87482475715132
END
run "$B/offset -d -25 $T/tinytail.cubic"
status 0
ref "$T/tinytail.cubic" "$T/out" -25 0.025
# three branches nearly meeting at the waist left a short kept run that
# led into a part without closing it: "do not close up" at -30
cat >"$T/nearpinch.cubic" <<'END'
cubic closed=1
-0.12 0.23 4.03 -18.15 -1.4810087118002258 -19.31954013270783 10.453836286097898 -16.25034926966153
4.03 -18.15 16.23 -28.42 8.794125835883435 -13.670351480872776 14.757348156564905 -6.880031360350481
16.23 -28.42 35.96 -32.74 18.447431711886395 -8.600387234155049 20.352740232500093 -1.3795891367205424
35.96 -32.74 71.91 -30.37 36.09828055631199 -2.4468840628277877 35.50408049300524 6.987198438460374
71.91 -30.37 108.34 -24.53 36.446577665887204 7.172681759903147 36.9946858920425 -1.5170747674556733
108.34 -24.53 149.46 -36.39 42.986003977696384 -1.7627662031951354 40.82228942937087 -14.192031773084716
149.46 -36.39 185.14 -44.76 34.70454847932772 -12.065174726207617 36.42919279280027 -4.807852471398338
185.14 -44.76 211.22 -46.04 25.942445147967707 -3.423832356873496 26.13094910516592 1.2632252573951115
211.22 -46.04 237.11 -41 26.526060175455854 1.282325760842496 24.765280714544815 9.528419720789318
237.11 -41 257.39 -28.64 22.339746357439004 8.595197534935979 17.959189440336495 15.829648806099742
257.39 -28.64 269.88 -12.41 15.560194507343226 13.715118670814045 8.362241742121205 18.942355025041106
269.88 -12.41 272.85 2.21 6.098975337378379 13.815548472805272 -0.34760301523121767 15.093370701772999
272.85 2.21 267.99 18.59 -0.40038240237130257 17.38511968153314 -9.14151374597417 14.79337968421962
267.99 18.59 252.62 32.78 -11.1507863040558 18.044912490137555 -18.345416521450314 10.745810518128676
252.62 32.78 228.8 42.7 -22.316749595086204 13.072015140616863 -24.53775406890061 8.265266111759505
228.8 42.7 195.76 51 -32.42591332278077 10.92230371928407 -34.016959254771706 3.205883816046065
195.76 51 123.31 38.48 -73.64208756269493 6.9403021865916426 -72.84268470623945 -15.12836626589619
123.31 38.48 82.54 33.29 -40.2772836719565 -8.36500606810508 -41.027082525636615 -3.169073974321175
82.54 33.29 40.91 30.37 -41.60887075852687 -3.2140133127756387 -41.608373389665765 -3.2203478348361574
40.91 30.37 14.58 24.22 -27.414823143514816 -2.1218148935031778 -23.62307801918812 -13.774212944216963
14.58 24.22 3 12.02 -14.847271384564575 -8.657190122534255 -7.6522405021981275 -15.37625468938388
3 12.02 -0.12 0.23 -5.482776228129555 -11.016977794203253 -0.9412244959108725 -12.278134677907724
END
run "$B/offset -d -30 $T/nearpinch.cubic"
status 0
ref "$T/nearpinch.cubic" "$T/out" -30 0.03
# an open outline whose ends nearly meet: its offset passes the curve's
# other end without crossing itself, and is cut where it comes nearer
# than the distance (once kept whole: "forward" 0.06 off at 30)
cat >"$T/nearends.cubic" <<'END'
cubic closed=0
-0.12 0.25 4.1 -18.67 -2.985750879026849 -19.87775265788048 11.414109547240487 -16.51984027842391
4.1 -18.67 17.18 -28.99 9.644288418901997 -13.9583472210351 15.559598977499403 -6.851806101718407
17.18 -28.99 37.3 -33.37 18.96873852672231 -8.353050651706742 20.7030593506179 -1.5753670879165074
37.3 -33.37 73.9 -31.12 36.73301211184038 -2.7951414011332902 36.1302090142516 7.201313372839479
73.9 -31.12 111.21 -24.97 37.353971568668676 7.445228309640088 37.91934365521347 -1.6654259672144405
111.21 -24.97 153.62 -37.44 44.387878523123675 -1.9495254504967297 42.35404768370288 -14.114499167692797
153.62 -37.44 190.77 -45.3 36.10537769581845 -12.032128009171425 37.78009604358698 -4.736468529904368
190.77 -45.3 217.58 -46.67 26.701345188230945 -3.3475320190891122 26.850770579081793 1.557255919671607
217.58 -46.67 243.87 -41.21 26.954509164162527 1.5632724146261756 25.32144733586611 9.365781013883389
243.87 -41.21 265.12 -28.99 23.194935661262225 8.579236611281402 18.589767415985968 16.27647377954583
265.12 -28.99 277.49 -12.52 15.686194447051209 13.7342187723517 8.46280522279859 19.039049126302665
277.49 -12.52 280.69 1.78 6.022079392623585 13.548068563574937 -0.06654005402010453 14.81213126432057
280.69 1.78 275.8 18.37 -0.07914972663532965 17.61910412791924 -9.264764907219611 15.00158057157571
275.8 18.37 259.72 33.35 -11.703639328746917 18.950625313119705 -19.159518501581214 11.457120143599644
259.72 33.35 235.42 43.76 -22.746215306357765 13.601913928871364 -25.1301313583278 8.501032172985195
235.42 43.76 201.63 51.87 -33.06562529574126 11.185454642115085 -34.73976041595289 2.936462271708481
201.63 51.87 127.33 39.6 -75.43408263481837 6.376248281676821 -74.67670447583173 -14.584898404398038
127.33 39.6 85.08 34.43 -41.80362392068125 -8.164548932607527 -42.45766330671058 -3.5549573258996623
85.08 34.43 42.64 31.18 -42.41655928966317 -3.5515157086474125 -42.4674921193087 -2.877830985522043
42.64 31.18 15.01 24.92 -28.836127937875027 -1.9540947284797063 -24.453227432806536 -15.025157405519929
15.01 24.92 3.09 12.37 -14.9524598525167 -9.187460571456999 -9.014775928282681 -15.089394282843983
END
run "$B/offset -d 30 $T/nearends.cubic"
status 0
ref "$T/nearends.cubic" "$T/out" 30 0.03

finish offset
