#!/bin/sh
# fit.sh: splinefit's merging of knots that are one knot and its corners
# (issue 13), run from the top of the tree.  References are derived by
# hand in the comments or are invariants checked in awk; the last line is
# "fit: N passed, M failed".

T=bin/test/fit
. tests/lib.sh

# same_as FILE: standard output is that of FILE, number for number
same_as() {
	cmp -s "$1" "$T/out" && ok || no "$what: output differs from $1"
}

# ---- merging ---------------------------------------------------------
# The insole as a CAD system exports it: the first knot repeated at the
# end, 0.5 micrometre off, and a double click 0.011 mm after knot 5.
grep -v '^#' man/figures/insole.knots >"$T/insole.knots"
awk 'NR == 5 { print; print $1 + 0.011, $2; next } { print }
    END { print "0.0005 0" }' "$T/insole.knots" >"$T/cad.knots"
for m in "" "-m manning" "-m chord" "-m ferguson"; do
	$B/splinefit $m "$T/insole.knots" >"$T/plain.cubic"
	run "$B/splinefit $m $T/cad.knots"
	status 0
	same_as "$T/plain.cubic"
	says "splinefit: $T/cad.knots:6: knot 6 is nearer than 0.0265 to knot 5 (line 5): merged into it"
	says "splinefit: $T/cad.knots:24: knot 24 is nearer than 0.0265 to knot 1 (line 1), closing the curve: merged into it"
	[ "$(wc -l <"$T/err")" -eq 2 ] && ok || no "$what: two notes"
done
# scaled to metres the knots merge the same (the distance is relative)
awk '{ print $1 / 1000, $2 / 1000 }' "$T/cad.knots" >"$T/cadm.knots"
run "$B/splinefit $T/cadm.knots"
status 0
[ "$(wc -l <"$T/err")" -eq 2 ] && ok || no "$what: two notes in metres"
# an open curve keeps a last knot on its first: it ends where it began
run "$B/splinefit -o $T/cad.knots"
status 0
[ "$(grep -c . "$T/out")" -eq 23 ] && ok || no "$what: 22 segments open"
# -d 0 merges nothing: the double click is a knot again
run "$B/splinefit -d 0 $T/cad.knots"
status 0
[ ! -s "$T/err" ] && [ "$(grep -c . "$T/out")" -eq 25 ] && ok ||
    no "$what: 24 segments, no note"
# -d sets the distance in the knots' units: 0.01 keeps the double click
run "$B/splinefit -d 0.01 $T/cad.knots"
says "knot 24 is nearer than 0.01 to knot 1"
[ "$(wc -l <"$T/err")" -eq 1 ] && ok || no "$what: only the closing knot"
fails 2 "-d '-1': want a number from 0" "$B/splinefit -d -1 $T/cad.knots"
# designer's spacing kept: knots 0.3 mm apart at a toe are not merged
awk 'NR == 12 { print; print $1 + 0.3, $2 + 0.3; next } { print }' \
    "$T/insole.knots" >"$T/toe.knots"
run "$B/splinefit $T/toe.knots"
[ ! -s "$T/err" ] && [ "$(grep -c . "$T/out")" -eq 24 ] && ok ||
    no "$what: 0.3 mm spacing merged"

# ---- corners -----------------------------------------------------------
# A 4 by 1 rectangle with its four corners: every side a straight line in
# every method, so sampled points lie on x = 0, x = 4, y = 0 or y = 1 to
# rounding, and each side's points run between its two corners.
printf 'points corners=1,2,3,4\n0 0\n4 0\n4 1\n0 1\n' >"$T/rect.knots"
for m in "" "-m manning" "-m chord" "-m ferguson"; do
	run "$B/splinefit $m $T/rect.knots | $B/sample -n 10"
	status 0
	awk 'function a(x) { return x < 0 ? -x : x }
	    NF == 2 { n++; s = int((n - 1) / 10); if (s > 3) s = 3
	        d = s == 0 ? a($2) : s == 1 ? a($1 - 4) : s == 2 ? a($2 - 1) : a($1)
	        if (d > 4e-15) bad = 1
	        if ($1 < -4e-15 || $1 > 4 + 4e-15 || $2 < -4e-15 || $2 > 1 + 4e-15) bad = 1 }
	    END { exit bad || n != 41 }' "$T/out" && ok ||
	    no "$what: the rectangle's sides are not straight"
done
# A D: five knots on the unit circle from (0,-1) round through (1,0) to
# (0,1), corners at the ends of the arc.  The closing side is the line
# x = 0, its row P_A P_B P'_A P'_B = (0,1) (0,-1) and the chord (0,-2)
# twice; the arc leaves (0,-1) along (1,0) and arrives at (0,1) along
# (-1,0), the tangents of the circle through the first and last three
# knots, and stays near the circle (see below).
printf 'points corners=1,5\n0 -1\n%s -%s\n1 0\n%s %s\n0 1\n' \
    0.70710678118654752 0.70710678118654752 0.70710678118654752 \
    0.70710678118654752 >"$T/d.knots"
for m in "" "-m manning" "-m chord" "-m ferguson"; do
	run "$B/splinefit -p 12 $m $T/d.knots"
	status 0
	awk 'function a(x) { return x < 0 ? -x : x }
	    NR == 2 { if (a($1) > 1e-12 || a($2 + 1) > 1e-12 || a($6) > 1e-12 || !($5 > 0)) bad = 1 }
	    NR == 5 { if (a($3) > 1e-12 || a($4 - 1) > 1e-12 || a($8) > 1e-12 || !($7 < 0)) bad = 1 }
	    NR == 6 { if ($0 != "0 1 0 -1 0 -2 0 -2") bad = 1 }
	    END { exit bad || NR != 7 }' "$T/out" && ok ||
	    no "$what: the D's corners: $(cat "$T/out")"
done
# Manning's curve stays within 1e-4 of the circle on the arc: a cubic per
# 45 degrees with the circle's end tangents is off it by 4.2e-6 at best
# (the best Bezier arc), and by far more if the corners' tangents were
# wrong.  The default trades closeness to the circle for less energy
# (fit.sh's fair cases): within 1e-3.
for m in "1e-3" "1e-4 -m manning"; do
	set -- $m
	run "$B/splinefit $2 $3 $T/d.knots | $B/sample -n 20"
	awk -v tol=$1 'NF == 2 && NR <= 81 { r = sqrt($1 * $1 + $2 * $2) - 1
	    if (r < 0) r = -r; if (r > m) m = r } END { exit !(m < tol) }' \
	    "$T/out" && ok || no "$what: the D's arc leaves the circle"
done
# An open L, corner at the bend: two straight segments, P' the chords.
printf 'points corners=2\n0 0\n1 0\n1 1\n' >"$T/l.knots"
run "$B/splinefit -o $T/l.knots"
out_is "cubic closed=0 corners=2
0 0 1 0 1 0 1 0
1 0 1 1 0 1 0 1
"
# With -S 0,1 the first piece, two knots, starts up and reaches the
# corner as the circular arc that leaves so: down, -S mirrored in its
# chord.  Manning's eq. 11 with cos A = cos B = 0 gives r = l = 2 (with
# alpha = 2/3, r = 2/(1 + alpha cos B + (1 - alpha) cos A)); -E changes
# the second piece alone the same way: it leaves the corner along -x.
run "$B/splinefit -m manning -o -S 0,1 -E 1,0 -p 6 $T/l.knots"
out_is "cubic closed=0 corners=2
0 0 1 0 0 2 0 -2
1 0 1 1 -2 0 2 0
"
# a corner at an end of an open curve changes nothing but the header,
# which names the joints: 1 and n + 1 = 3 (loft.5)
printf 'points corners=1,3\n0 0\n1 0\n1 1\n' >"$T/ends.knots"
printf 'points\n0 0\n1 0\n1 1\n' >"$T/noends.knots"
$B/splinefit -o "$T/noends.knots" | sed '1s/$/ corners=1,3/' >"$T/noends.cubic"
run "$B/splinefit -o $T/ends.knots"
same_as "$T/noends.cubic"
# a corner on a knot merged away moves to the knot it merged into
printf 'points corners=3\n0 0\n4 0\n4 1e-9\n4 1\n0 1\n' >"$T/mc.knots"
printf 'points corners=2\n0 0\n4 0\n4 1\n0 1\n' >"$T/mc2.knots"
$B/splinefit "$T/mc2.knots" >"$T/mc2.cubic"
run "$B/splinefit $T/mc.knots"
same_as "$T/mc2.cubic"
# the attribute is the cubic's own (joints), others pass
run "printf 'points id=4 corners=1\n0 0\n1 0\n1 1\n' | $B/splinefit"
head -1 "$T/out" | grep -q '^cubic closed=1 corners=1 id=4$' && ok ||
    no "$what: header $(head -1 "$T/out")"

# ---- the fair default ---------------------------------------------------
# E: tests/energy.awk's energy, largest curvature, length, jumps of the
# curvature and the unit tangent at the knots, by its own formulas.
E="awk -f tests/energy.awk"
# EF: the same at 20000 intervals a segment, for curves that bend
# sharply within one (at 400 energy.awk misses a hairpin's energy)
EF="awk -v N=20000 -f tests/energy.awk"
# Twelve knots on a circle of radius 50: the fair curve bends like the
# circle, E within 1e-3 of 2 pi / 50; and E >= 4 pi^2 / L for any closed
# convex curve of length L (Cauchy-Schwarz on the integral of the
# curvature, 2 pi), which it must not beat by more than the quadrature's
# rounding.
awk 'BEGIN { for (i = 0; i < 12; i++) { a = i * atan2(1, 1) * 8 / 12
    printf "%.17g %.17g\n", 50 * cos(a), 50 * sin(a) } }' >"$T/circle.knots"
run "$B/splinefit $T/circle.knots | $E"
awk '{ pi = atan2(1, 1) * 4; c = 2 * pi / 50; lo = 4 * pi * pi / $3
    exit !($1 > c * (1 - 1e-3) && $1 < c * (1 + 1e-3) && $1 >= lo * (1 - 1e-9)) }' \
    "$T/out" && ok || no "$what: circle energy $(cat "$T/out")"
# Uneven knots: the insole, every third knot of it dropped and the rest
# jittered, a sparse blob and the uneven chords of bad.sh.  On each the
# default is G2 (curvature and tangent continuous at every knot, to
# rounding), no more bent than the chord-length spline (by 1%: this
# samples 400 points a segment, the fit checks its quadrature points),
# and its energy no more than the chord spline's (the start of its
# descent); on the insole, open or closed, no more than Manning's either
# (not a promise on every set: on the uneven chords Manning's is 0.2%
# lower).
awk 'NR % 3 != 0 { srand(NR); print $1 + 2 * rand() - 1, $2 + 2 * rand() - 1 }' \
    "$T/insole.knots" >"$T/dropped.knots"
printf '0 0\n10 1\n11 6\n3 9\n-4 12\n-6 5\n' >"$T/blob.knots"
printf '0 0\n1 0\n1.001 0.001\n2 1\n3 1\n3.001 1.001\n3 5\n' >"$T/uneven.knots"
for k in insole dropped blob uneven; do
	for c in "" -o; do
		$B/splinefit $c "$T/$k.knots" | $E >"$T/fair.e"
		$B/splinefit -m chord $c "$T/$k.knots" | $E >"$T/chord.e"
		$B/splinefit -m manning $c "$T/$k.knots" 2>/dev/null | $E >"$T/manning.e"
		what="fair $c $k"
		paste "$T/fair.e" "$T/chord.e" | awk '{ exit !($4 <= 1e-9 * $2 &&
		    $5 <= 1e-9 && $2 <= 1.01 * $7 && $1 <= $6 * (1 + 1e-9)) }' &&
		    ok || no "$what: $(cat "$T/fair.e") against chord $(cat "$T/chord.e")"
		[ $k = insole ] || continue
		paste "$T/fair.e" "$T/manning.e" "$T/chord.e" |
		    awk '{ exit !($1 <= $6 * (1 + 1e-9) || $7 > $12) }' &&
		    ok || no "$what: $(cat "$T/fair.e") against Manning $(cat "$T/manning.e")"
	done
done

# Nor does it cross itself where the chord spline does not: the polyline
# of 16 points a segment, every pair of edges but neighbours, in awk.
crossings() {
	$B/sample -n 16 | awk 'NF == 2 { x[n] = $1; y[n] = $2; n++ }
	function o(a, b, c) { return (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]) }
	END { n--   # the last point repeats the first
		for (i = 0; i < n; i++) for (j = i + 2; j < n; j++) {
			if (i == 0 && j == n - 1) continue
			a = o(i, i + 1, j); b = o(i, i + 1, (j + 1) % n)
			c = o(j, (j + 1) % n, i); d = o(j, (j + 1) % n, i + 1)
			if (a * b < 0 && c * d < 0) k++ }
		print k + 0 }'
}
for k in insole dropped blob uneven; do
	f=$($B/splinefit "$T/$k.knots" | crossings)
	c=$($B/splinefit -m chord "$T/$k.knots" | crossings)
	[ "$f" -eq 0 ] || [ "$c" -gt 0 ] && ok ||
	    no "fair $k: $f crossings where the chord spline has $c"
done

# Co-circular knots give the circle (issue 23): for n = 3..12 knots at
# uneven angles on the unit circle, the default's curve keeps within
# 1e-4 of the radius: it splits a span that turns more than 45 degrees,
# and a G2 cubic over 45 degrees of a circle is off it by some 1e-6.
# With -1 (a cubic a span), within 1e-3 where no gap is wider than 95
# degrees, else within 3 times the radial error of the usual single
# cubic over the widest gap (the arc of Bezier arms 4/3 tan(theta/4),
# sampled here by its closed form): one cubic a span can do no better
# by much (that arc's error passes 1e-3 at 113 degrees).  E L may not
# reward growth: on a circle the scale-free energy is 4 pi^2, and the
# fit's is within 1% of it (both ways).
for seed in 1 2 3 4 5 6; do
	for n in 3 4 5 6 7 8 9 10 11 12; do
		awk -v n=$n -v seed=$seed -v out="$T/cc.ref" 'BEGIN { srand(seed * 100 + n); pi = atan2(0, -1)
		    for (i = 0; i < n; i++) a[i] = 2 * pi * (i + 0.35 * (rand() - 0.5)) / n
		    for (i = 0; i < n; i++) printf "%.17g %.17g\n", cos(a[i]), sin(a[i])
		    g = 0; for (i = 0; i < n; i++) { d = (i + 1 < n ? a[i + 1] : a[0] + 2 * pi) - a[i]
			if (d > g) g = d }
		    k = 4 / 3 * sin(g / 4) / cos(g / 4); m = 0
		    for (j = 0; j <= 200; j++) { u = j / 200; v = 1 - u
			x = v^3 + 3 * v * v * u + 3 * v * u * u * (cos(g) + k * sin(g)) + u^3 * cos(g)
			y = 3 * v * v * u * k + 3 * v * u * u * (sin(g) - k * cos(g)) + u^3 * sin(g)
			r = sqrt(x * x + y * y) - 1; if (r < 0) r = -r; if (r > m) m = r }
		    printf "%.17g %.17g\n", m, (g > pi * 95 / 180 ? 3 * m : 1e-3) >out }' \
		    >"$T/cc.knots"
		for one in "" -1; do
			what="fair fit $one of $n co-circular knots (seed $seed)"
			$B/splinefit $one "$T/cc.knots" >"$T/cc.cubic"
			$E "$T/cc.cubic" >"$T/cc.e"
			[ -z "$one" ] && cap=1e-4 || cap=$(cut -d' ' -f2 "$T/cc.ref")
			$B/sample -n 40 "$T/cc.cubic" | awk -v cap="$cap" '
			    NF == 2 { r = sqrt($1 * $1 + $2 * $2) - 1; if (r < 0) r = -r
				if (r > m) m = r }
			    END { exit !(m <= cap + 0) }' &&
			    ok || no "$what: off the circle by more than $cap"
			awk '{ pi = atan2(0, -1); exit !($1 * $3 < 4 * pi * pi * 1.01 &&
			    $1 * $3 > 4 * pi * pi * (1 - 1e-9)) }' "$T/cc.e" &&
			    ok || no "$what: E L $(cat "$T/cc.e")"
		done
	done
done
# A knot that sticks out (issue 23's example, a toe): rounded, radius at
# least 0.1 everywhere by energy.awk's own sampling, where the chord
# spline's is under 0.002; less energy than Manning's (87.6) and the
# chord spline's.
printf '2.327 0.227\n2.434 0.695\n-0.188 0.836\n-0.560 0.809\n-0.905 0.693
-3.036 0.350\n-1.004 -0.519\n-0.964 -0.749\n-0.556 -0.849\n0.590 -1.186
1.773 -0.407\n1.935 -0.038\n' >"$T/toe.knots"
$B/splinefit "$T/toe.knots" | $E >"$T/toe.e"
$B/splinefit -m manning "$T/toe.knots" | $E >"$T/toem.e"
paste "$T/toe.e" "$T/toem.e" | awk '{ exit !($2 < 10 && $1 < $6) }' && ok ||
    no "the toe: $(cat "$T/toe.e") against Manning $(cat "$T/toem.e")"

# Straight runs (issue 23): straight=1,3 makes spans 1 and 3 straight
# lines (both tangent vectors along the chord), and the curve meets each
# with its tangent (energy.awk's unit-tangent jump 0 at every knot);
# the header keeps the list.  Open too, the end span straight.
printf 'points straight=1,3\n0 0\n4 0\n5 1\n4 2\n0 2\n-1 1\n' >"$T/st.knots"
for c in "" -o; do
	what="straight=1,3 $c"
	$B/splinefit $c "$T/st.knots" >"$T/st.cubic"
	head -1 "$T/st.cubic" | grep -q "^cubic closed=[01] straight=1,3$" && ok ||
	    no "$what: header $(head -1 "$T/st.cubic")"
	awk 'NR == 2 || NR == 4 { cx = $3 - $1; cy = $4 - $2
	    if (($5 * cy - $6 * cx)^2 + ($7 * cy - $8 * cx)^2 > 1e-24 ||
		$5 * cx + $6 * cy <= 0 || $7 * cx + $8 * cy <= 0) bad = 1 }
	    END { exit bad }' "$T/st.cubic" && ok || no "$what: not straight"
	$E "$T/st.cubic" | awk '{ exit !($5 < 1e-9) }' && ok ||
	    no "$what: tangent jumps: $($E "$T/st.cubic")"
done
# A span alone between a straight run and a corner (a stem's bracket
# into a serif) meets the run G2, as Spiro's [ ] points do: tangent
# along the line and curvature 0 there.  The curvature of the cubic at
# u = 0 is |P'(0) x P''(0)| / |P'(0)|^3, P''(0) = 6 (B - A) - 4 P'(0) -
# 2 P'(1); the G1 join loft made before had it 1.4 here.  The span
# from corner 5 meets its run at 90 degrees to its chord, where no tame
# cubic is G2, and stays G1: its end tangent along the run.
printf 'points corners=3,4,5 straight=1\n0 0\n0 4\n1 5\n-2 5\n-2 0\n' |
    $B/splinefit >"$T/br.cubic"
awk 'NR == 3 { ax = 6 * ($3 - $1) - 4 * $5 - 2 * $7
	ay = 6 * ($4 - $2) - 4 * $6 - 2 * $8; v = sqrt($5 * $5 + $6 * $6)
	k = ($5 * ay - $6 * ax) / (v * v * v)
	exit !($5 == 0 && $6 > 0 && k * k < 1e-20) }' "$T/br.cubic" && ok ||
    no "the bracket does not meet its run G2: $(sed -n 3p "$T/br.cubic")"
awk 'NR == 6 { exit !($7 == 0 && $8 > 0) }' "$T/br.cubic" && ok ||
    no "the span at 90 degrees: not G1: $(sed -n 6p "$T/br.cubic")"
# Pieces of several spans between straight runs meet them G2 too where
# the cubics beside the runs can: a racetrack, two straight sides and
# two ends of three knots each, gentle where they leave the sides.  The
# largest jump of the curvature across any knot (energy.awk's fourth
# number, the runs' 0 included) is within rounding of none, at two
# scales; loft's G1 joins before had it 0.10 at the first.  And the
# energy stays within the chord spline's (-m chord: the guarantee).
printf 'points straight=1,6\n0 0\n10 0\n14 1\n16 4\n14 7\n10 8\n0 8\n-4 7\n-6 4\n-4 1\n' \
    >"$T/track.knots"
for s in 1 1e-7; do
	awk -v s=$s 'NR > 1 { $1 *= s; $2 *= s } 1' "$T/track.knots" |
	    $B/splinefit | $E >"$T/track.e"
	awk -v s=$s 'NR > 1 { $1 *= s; $2 *= s } 1' "$T/track.knots" |
	    $B/splinefit -m chord | $E >>"$T/track.e"
	awk 'NR == 1 { e = $1; k = $2; j = $4; t = $5 }
	    END { exit !(j < 1e-9 * k && t < 1e-9 && e <= $1) }' \
	    "$T/track.e" && ok ||
	    no "racetrack at $s: not G2, or above the chord spline: $(cat "$T/track.e")"
done
# The cubics made again keep no speed floor, and may bend sharply
# between the samples of the fit's checks: they are judged by the exact
# least radius.  On these random knots (a fuzz case, open) they nearly
# cusped at knot 3 before, with twice the chord spline's energy.
# By EF: at 400 intervals energy.awk reads both 16% low.
printf 'points straight=3,8,9\n0.3345 0.1702\n-0.8551 0.8617\n0.4073 -0.1685
-0.0461 0.1254\n-0.4464 0.9827\n-0.5961 -0.9713\n0.7621 0.1017
-0.7272 0.0329\n-0.0513 -0.1549\n-0.6582 0.7402\n0.5993 -0.2157
-0.8782 0.6361\n' >"$T/fz.knots"
$B/splinefit -o "$T/fz.knots" | $EF >"$T/fz.e"
$B/splinefit -o -m chord "$T/fz.knots" | $EF >>"$T/fz.e"
awk 'NR == 1 { e = $1 } END { exit !(e <= $1) }' "$T/fz.e" && ok ||
    no "random open knots: energy above the chord spline's: $(cat "$T/fz.e")"
# A closed curve that turns back in a hairpin at each end of a spike
# spends most of its energy between the points of the judge's Gauss
# quadrature: there it is judged by the exact energies.  On these knots
# (a fuzz case) the default had 12350 against the chord spline's 12100
# before; by EF.
printf 'points corners=1,6\n0 0.005141\n1 0.005945\n2 -0.022054\n3 0.001413
4 0.002892\n5 4.990098\n6 -0.003618\n7 -0.013519\n8 -0.014746\n9 -0.002734
' >"$T/pin.knots"
$B/splinefit "$T/pin.knots" | $EF >"$T/pin.e"
$B/splinefit -m chord "$T/pin.knots" | $EF >>"$T/pin.e"
awk 'NR == 1 { e = $1 } END { exit !(e <= $1) }' "$T/pin.e" && ok ||
    no "spike with hairpins: energy above the chord spline's: $(cat "$T/pin.e")"
# Nor where the run points away from the span's chord (135 degrees):
# the corner's tangent is the run's mirrored in the chord, (-1, 0),
# as the chord spline has it, never turned back.
printf 'points corners=3,4,5 straight=1\n0 0\n0 4\n1 3\n-2 5\n-2 0\n' |
    $B/splinefit >"$T/br2.cubic"
awk 'NR == 3 { exit !($5 == 0 && $6 > 0 && $7 < 0 && $8 * $8 < 1e-20) }' \
    "$T/br2.cubic" && ok ||
    no "the span back from its run: $(sed -n 3p "$T/br2.cubic")"
# A stem 40 wide and 400 tall between knots 45 degrees off it at either
# end, its foot straight: the chord spline leans each long side's
# tangents to the short span beside it, and the two sides bulge across
# each other.  The default must not cross itself (as a glyph's stem
# between a sparse pair of knots did; splinefit before this check
# crossed here), and the chord spline must, or the case tests nothing.
printf 'points straight=1\n0 0\n80 0\n60 20\n40 40\n40 440\n30 455\n10 455
0 440\n0 40\n-20 20\n' >"$T/stem.knots"
f=$($B/splinefit "$T/stem.knots" | crossings)
c=$($B/splinefit -m chord "$T/stem.knots" | crossings)
[ "$f" -eq 0 ] && [ "$c" -gt 0 ] && ok ||
    no "the stem: $f crossings (the chord spline $c)"
# The same, 60 wide, its top straight too: each side is a piece of its
# own between two straight runs, and neither crosses itself, but the
# chord spline's sides cross each other (as did the default's before
# loft_fit refitted such pieces together).
printf 'points straight=1,6\n0 0\n100 0\n80 20\n60 40\n60 440\n50 455
10 455\n0 440\n0 40\n-20 20\n' >"$T/stem2.knots"
f=$($B/splinefit "$T/stem2.knots" | crossings)
c=$($B/splinefit -m chord "$T/stem2.knots" | crossings)
[ "$f" -eq 0 ] && [ "$c" -gt 0 ] && ok ||
    no "the stem in two pieces: $f crossings (the chord spline $c)"
# A straight span whose knot is a corner too gives the piece beyond the
# corner no direction (a Z's diagonal between its corners stays the
# straight line between them, as any span between neighbouring corners
# is): span 1, corner to corner, beside straight span 2 from corner 2
for m in fair manning chord; do
	what="-m $m: a span between corners beside a straight span"
	printf 'points corners=1,2,3 straight=2\n0 0\n4 4\n0 4\n-1 2\n' |
	    $B/splinefit -m $m >"$T/z.cubic"
	awk 'NR == 2 { cx = $3 - $1; cy = $4 - $2; c = cx * cx + cy * cy
	    a = ($5 * cy - $6 * cx)^2 / (c * ($5 * $5 + $6 * $6))
	    b = ($7 * cy - $8 * cx)^2 / (c * ($7 * $7 + $8 * $8))
	    exit !(a <= 1e-24 && b <= 1e-24 && $5 * cx > 0 && $7 * cx > 0) }' \
	    "$T/z.cubic" &&
	    ok || no "$what: not straight: $(sed -n 2p "$T/z.cubic")"
done
for bad in 0 7 2,2 3,1 x; do
	run "printf 'points straight=$bad\n0 0\n4 0\n5 1\n4 2\n0 2\n-1 1\n' | $B/splinefit"
	status 1
done

# Beside Spiro (libspiro) and Hobby on make compare's corpus of 300
# uneven closed sets, a third spiky, issue 23's targets: energy over the
# fairest peer's (Spiro, Hobby, chord; loft_curve_energy) at most 1.00 at
# the median, 1.05 at the 90th percentile and 1.5 at worst; never a
# largest curvature above twice Spiro's; no more inflexions in all than
# Spiro's curves have; and never a loop where the chord spline has none,
# a bend sharper than it, or a failure (a cusp, unbounded energy, on a
# set the chord spline fits).  Built only where libspiro is.
if [ -f /usr/include/spiroentrypoints.h ] && ${CC:-cc} -std=c99 -O2 -DHAVE_SPIRO \
    -o "$T/compare" tests/bench/compare.c bin/libloft.a -lspiro -lm 2>/dev/null; then
	"$T/compare" corpus 300 man/figures/insole.knots >"$T/uneven.knots"
	"$T/compare" run "$T/uneven.knots" >"$T/compare.out"
	what="beside Spiro"
	awk '$1 == "Spiro" { spiro = $10 }
	    $1 == "loft" && $2 == "default" { found = 1; m = $3; p = $4; w = $5
		loops = $7; sharp = $8; twice = $9; inf = $10; fails = $11 }
	    END { exit !(found && m <= 1.00 && p <= 1.05 && w <= 1.5 &&
		loops == 0 && sharp == 0 && twice == 0 && fails == 0 &&
		spiro != "" && inf <= spiro) }' "$T/compare.out" && ok ||
	    no "$what: $(grep '^loft default\|^Spiro' "$T/compare.out")"
else
	echo "fit: libspiro not found: the comparison with Spiro skipped"
fi

# Real outlines (issue 23): glyph contours of Debian's typefaces, read
# by tests/glyphs.py with fontTools at run time, their on-curve points
# with corners= and straight= as the designer's outline has them.  Every
# contour fits, and every span straight= names is a straight line, its
# tangent vectors along its chord.
if /usr/bin/python3 tests/glyphs.py "$T/glyphs.knots" "$T/glyphs.truth" 300 \
    2>"$T/glyphs.err" && [ -s "$T/glyphs.knots" ]; then
	what="glyph contours"
	run "$B/splinefit $T/glyphs.knots"
	status 0
	awk '/^cubic/ { n = 0; delete st; s = $0; sub(/.*straight=/, "", s)
		if (s != $0) { sub(/ .*/, "", s); k = split(s, a, ","); for (i = 1; i <= k; i++) st[a[i]] = 1 }
		recs++; next }
	    NF == 8 { n++; if (!(n in st)) next; cx = $3 - $1; cy = $4 - $2; c = cx * cx + cy * cy
		if (($5 * cy - $6 * cx)^2 > 1e-18 * c * ($5 * $5 + $6 * $6) ||
		    ($7 * cy - $8 * cx)^2 > 1e-18 * c * ($7 * $7 + $8 * $8) ||
		    $5 * cx + $6 * cy <= 0 || $7 * cx + $8 * cy <= 0) bad++; lines++ }
	    END { exit !(recs >= 100 && lines >= 50 && bad == 0) }' "$T/out" && ok ||
	    no "$what: straight spans not straight, or too few records"
	# beside corners no span swells from its chord past 1.1 times the
	# chord spline's, or a circle's through its knots where that is
	# more (tests/swell.awk; before issue 23, 321 of 3540 spans did)
	$B/splinefit -m chord "$T/glyphs.knots" >"$T/gchord.cubic" 2>/dev/null
	awk -f tests/swell.awk "$T/out" "$T/gchord.cubic" >"$T/swell"
	awk '{ exit !($1 == 0 && $2 >= 1000) }' "$T/swell" && ok ||
	    no "$what: spans past the chord spline's swell: $(cat "$T/swell")"
	# two of issue 23's targets, against Spiro's and Hobby's curves
	# through the same knots (tests/bench/glyphs_cmp.py): the distance
	# to the designer's outline at the 90th percentile no more than the
	# better peer's, and fewer inflexions the outline lacks than Spiro's
	$B/sample -n 50 "$T/out" >"$T/g-def.pts"
	/usr/bin/python3 tests/bench/glyphs_cmp.py "$T/glyphs.truth" default \
	    "$T/g-def.pts" >"$T/gcmp" 2>&1
	if grep -q '^targets (issue 23) for default: ' "$T/gcmp"; then
		grep -q '90% [0-9.]* <= [0-9.]* pass;.*xinflex [0-9]* < Spiro.s [0-9]* pass$' \
		    "$T/gcmp" && ok || no "$what: $(grep '^targets' "$T/gcmp")"
	else
		echo "fit: glyphs beside Spiro and Hobby skipped: $(tail -1 "$T/gcmp")"
	fi
else
	echo "fit: glyph contours skipped: $(head -1 "$T/glyphs.err")"
fi

# ---- -v: the measures -----------------------------------------------------
# The circle of radius 50: energy 2 pi / 50 = 0.125664 (to 1e-3, as
# above), smallest radius 50 (to 3%: cubics through 12 knots of a circle
# bend up to 2% more than it between them), no inflexions.
run "$B/splinefit -v $T/circle.knots"
sed 's/.*bending energy \([^,]*\), smallest radius \([^ ]*\) at u = [^,]*, \([0-9]*\) inflexions$/\1 \2 \3/' \
    "$T/err" | awk '{ exit !($1 > 0.125664 * (1 - 1e-3) && $1 < 0.125664 * (1 + 1e-3) &&
    $2 > 48.5 && $2 < 51.5 && $3 == 0 && NF == 3) }' && ok ||
    no "$what: $(cat "$T/err")"
# the rectangle with corners: no energy, no curvature, no inflexions
run "$B/splinefit -v $T/rect.knots"
says "bending energy 0, no curvature, 0 inflexions"
# the insole's energy is energy.awk's (Simpson, 400 a segment), to 1e-5
run "$B/splinefit -v man/figures/insole.knots"
$B/splinefit man/figures/insole.knots | $E >"$T/insole.e"
sed 's/.*bending energy \([^,]*\),.*/\1/' "$T/err" | paste - "$T/insole.e" |
    awk '{ d = $1 - $2; exit !(d < 1e-5 * $2 && -d < 1e-5 * $2) }' && ok ||
    no "$what: $(cat "$T/err") against $(cat "$T/insole.e")"
# a dart, four knots with a reflex one at (2,1): a simple closed curve
# that bends the other way once has two inflexions
printf '0 0\n2 1\n4 0\n2 3\n' >"$T/dart.knots"
run "$B/splinefit -v $T/dart.knots"
says ", 2 inflexions"

# a space curve in the plane y = 0 (the keel line of man/figures/hull.knots):
# the fair fit's last check took the plane crossing test to 3-D segments,
# read them as plane ones, and so fell back to the chord spline or not by
# where the knots were; moved by D in x and z, the fit must be the same
# curve moved (end points by D, tangents not), to 1e-9 of its size 6
printf '0 0 0.96\n1.5 0 0.16\n3 0 0\n4.5 0 0.128\n6 0 0.8\n' >"$T/keel.knots"
$B/splinefit -o "$T/keel.knots" >"$T/keel0"
for d in 1 1000 1e6; do
	what="the fair fit of a space curve moved by $d"
	awk -v d=$d '{ printf "%.17g %.17g %.17g\n", $1 + d, $2, $3 + d }' \
	    "$T/keel.knots" | $B/splinefit -o >"$T/keel1"
	paste -d' ' "$T/keel0" "$T/keel1" | awk -v d=$d '
	    NF == 24 { for (i = 1; i <= 12; i++) { x = $(i + 12)
		if (i <= 6 && i % 3 != 2) x -= d
		e = $i - x; if (e < 0) e = -e; if (e > m) m = e }; n++ }
	    END { exit !(n == 4 && m < 6e-9) }' && ok ||
	    no "$what: $(paste -d' ' "$T/keel0" "$T/keel1" | sed -n 2p)"
done

# ---- the record's closed= and method= (issue 27: loftplot -i saves them)
# A record that says closed=0 method=manning is the curve of -o -m
# manning on the bare knots; -o and -m override the record; a bad value
# is refused at the header's line.
printf '0 0\n3 1\n5 -1\n8 0.5\n10 0\n' >"$T/bare.knots"
{ echo "points closed=0 method=manning"; cat "$T/bare.knots"; } >"$T/said.knots"
$B/splinefit -o -m manning "$T/bare.knots" >"$T/ref.cubic"
run "$B/splinefit $T/said.knots"
status 0
same_as "$T/ref.cubic"
{ echo "points closed=1 method=chord"; cat "$T/bare.knots"; } >"$T/said.knots"
$B/splinefit -m chord "$T/bare.knots" >"$T/ref.cubic"
run "$B/splinefit $T/said.knots"
same_as "$T/ref.cubic"
$B/splinefit -o "$T/bare.knots" >"$T/ref.cubic"
run "$B/splinefit -o -m fair $T/said.knots"
same_as "$T/ref.cubic"
fails 1 ":1: attribute closed=yes: want 0 or 1" \
    "printf 'points closed=yes\n0 0\n1 1\n2 0\n' | $B/splinefit"
fails 1 ":1: attribute method=spiro: want fair, manning, ferguson or chord" \
    "printf 'points method=spiro\n0 0\n1 1\n2 0\n' | $B/splinefit"

finish fit
