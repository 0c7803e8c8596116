#!/bin/sh
# roundtrip.sh: curves through tocad and back through fromcad (issue 15).
# Exact where the format is exact (a DXF SPLINE, an SVG path: the rows
# come back equal to the ones written, to the rounding of P'/3 and back,
# a few units in the last place: 1e-15 of the record's size), within the
# tolerance
# where it is sampled (a DXF polyline: every point on the curve, and the
# curve within -t of the polyline, both measured here in awk against a
# dense sampling of the original).  Last line "roundtrip: N passed, M
# failed".

T=bin/test/roundtrip
. tests/lib.sh

$B/splinefit man/figures/insole.knots >"$T/insole.cubic"
$B/grade -r -2:2 man/figures/insole.knots | $B/splinefit >"$T/graded.cubic"

# same_rows A B REL: the numeric rows of A and B equal, each number to
# REL of the record's largest coordinate (0: exactly), and as many
same_rows() {
	awk -v rel="$3" '
	function abs(x) { return x < 0 ? -x : x }
	FNR == 1 { f++ }
	$1 ~ /^[-0-9.]/ { n[f]++; for (i = 1; i <= NF; i++) { v[f, n[f], i] = $i
		if (abs($i) > big) big = abs($i) }; nf[f, n[f]] = NF }
	END { if (n[1] != n[2] || n[1] == 0) { print "rows " n[1] " and " n[2]; exit 1 }
		for (r = 1; r <= n[1]; r++) { if (nf[1, r] != nf[2, r]) { print "row " r; exit 1 }
			for (i = 1; i <= nf[1, r]; i++) { d = abs(v[1, r, i] - v[2, r, i])
				if (rel == 0 ? d != 0 : d > rel * big) {
					print "row " r " number " i ": " v[1, r, i] " and " v[2, r, i]; exit 1 } } } }' "$1" "$2"
}

# exact: DXF SPLINE (-s) and SVG paths give back the fitted rows
for f in "dxf -s" svg; do
	what="fit, tocad -f $f, fromcad"
	$B/tocad -f $f "$T/insole.cubic" >"$T/doc" && $B/fromcad "$T/doc" >"$T/back"
	e=$(same_rows "$T/insole.cubic" "$T/back" 1e-15) && ok || no "$what: $e"
	[ "$(sed -n 1p "$T/back" | grep -c 'closed=1')" = 1 ] && ok ||
	    no "$what: not closed: $(sed -n 1p "$T/back")"
done
# a graded set: each size a record, in order, each exact
what="a graded set through tocad -f dxf -s and fromcad"
$B/tocad -f dxf -s "$T/graded.cubic" | $B/fromcad >"$T/back"
[ "$(grep -c '^cubic' "$T/back")" = 5 ] && ok || no "$what: $(grep -c '^cubic' "$T/back") records"
e=$(same_rows "$T/graded.cubic" "$T/back" 1e-15) && ok || no "$what: $e"
# units: the insole in metres comes back in millimetres, as loft(5) says
# fromcad writes (tocad -u m says the stream is in metres)
what="tocad -u m, fromcad: millimetres"
awk '/^[-0-9.]/ { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i / 1000) } { print }' \
    "$T/insole.cubic" >"$T/metres.cubic"
$B/tocad -f dxf -s -u m "$T/metres.cubic" | $B/fromcad >"$T/back"
e=$(same_rows "$T/insole.cubic" "$T/back" 2e-15) && ok || no "$what: $e"

# sampled: a DXF polyline within -t
for tol in 0.01 0.001; do
	what="fit, tocad -f dxf -t $tol, fromcad"
	$B/tocad -f dxf -t $tol "$T/insole.cubic" | $B/fromcad >"$T/pts"
	$B/sample -n 2000 "$T/insole.cubic" >"$T/dense"
	# every polyline point on the curve (to the dense chords' sag,
	# k h^2 / 8 <= 1.2e-6 here: k <= 1 / 23, h <= 0.015); every dense
	# point within tol of the
	# polyline; both by a window walking along the two in order
	e=$(awk -v tol=$tol '
	function d2seg(px, py, ax, ay, bx, by,   dx, dy, t, l) {
		dx = bx - ax; dy = by - ay; l = dx * dx + dy * dy
		t = l > 0 ? ((px - ax) * dx + (py - ay) * dy) / l : 0
		t = t < 0 ? 0 : t > 1 ? 1 : t
		dx = ax + t * dx - px; dy = ay + t * dy - py
		return dx * dx + dy * dy }
	function near(px, py, n, X, Y,   j, best, d) {
		best = 1e300
		for (j = 1; j < n; j++) { d = d2seg(px, py, X[j], Y[j], X[j + 1], Y[j + 1])
			if (d < best) best = d }
		return sqrt(best) }
	FNR == 1 { f++ }
	f == 1 && /closed=1/ { closed = 1 }
	f == 1 && $1 ~ /^[-0-9.]/ { n1++; X1[n1] = $1; Y1[n1] = $2 }
	f == 2 && $1 ~ /^[-0-9.]/ { n2++; X2[n2] = $1; Y2[n2] = $2 }
	END { if (n1 < 10) { print "only " n1 " points"; exit 1 }
		# a closed record holds its first point once: the closing chord
		if (closed) { n1++; X1[n1] = X1[1]; Y1[n1] = Y1[1] }
		for (i = 1; i <= n1; i += 7) { d = near(X1[i], Y1[i], n2, X2, Y2)
			if (d > 1e-5) { print "point " i " is " d " off the curve"; exit 1 } }
		for (i = 1; i <= n2; i += 37) { d = near(X2[i], Y2[i], n1, X1, Y1)
			if (d > tol * (1 + 1e-6)) { print "the curve is " d " from the polyline"; exit 1 } } }' \
	    "$T/pts" "$T/dense") && ok || no "$what: $e"
done

# ASTM D6673 turn points: a graded set of knots with corners, fitted,
# to DXF as polylines and as SPLINEs and back; every record's corners=
# names vertices (of a knot record) or joints (of a cubic: joint j
# starts row j, n + 1 ends an open curve) at its corner knots' own
# coordinates, exactly, and no turn point is left over as a record of
# its own.  corner_points STREAM: "x y" of each corner, record by record.
corner_points() {
	awk 'function flush(   k, c, j) {
		if (nr == 0 || ncs == 0) return
		for (k = 1; k <= ncs; k++) { j = cs[k] + 0
			if (type == "cubic") c = j <= nr ? X[j] " " Y[j] : XE " " YE
			else c = X[j] " " Y[j]
			print c }
	}
	/^[a-z]/ { flush(); type = $1; nr = ncs = 0
		for (i = 2; i <= NF; i++) if ($i ~ /^corners=/) {
			sub(/^corners=/, "", $i); ncs = split($i, cs, ",") }
		next }
	NF == 0 { flush(); nr = ncs = 0; next }
	{ nr++; X[nr] = $1; Y[nr] = $2; XE = $3; YE = $4 }
	END { flush() }' "$1"
}
{ echo "points corners=3,9,15"; grep '^[-0-9]' man/figures/insole.knots; } |
    $B/grade -r -1:1 >"$T/turn.knots"
corner_points "$T/turn.knots" >"$T/turn.want"
$B/splinefit "$T/turn.knots" >"$T/turn.cubic"
for s in "" "-s"; do
	what="knots with corners through splinefit, tocad -f dxf $s, fromcad"
	$B/tocad -f dxf $s "$T/turn.cubic" | $B/fromcad >"$T/back"
	corner_points "$T/back" >"$T/turn.got"
	e=$(paste -d ' ' "$T/turn.want" "$T/turn.got" | awk 'NF != 4 || $1 != $3 || $2 != $4 {
	    print "corner " NR ": " $0; exit 1 } END { if (NR != 9) { print NR " corners, want 9"; exit 1 } }') &&
	    ok || no "$what: $e"
	[ "$(grep -c '^points layer=2' "$T/back")" = 0 ] && ok ||
	    no "$what: turn points left as records of their own"
done
# the SPLINE's joints are the fitted knots: the same numbers as the knots'
[ "$(grep -c '^cubic .*corners=3,9,15$' "$T/back")" = 3 ] && ok ||
    no "$what: $(grep '^cubic' "$T/back" | head -1)"

# CSV: points out (awk) and back, exactly
what="points as CSV through fromcad"
$B/sample -n 4 "$T/insole.cubic" >"$T/s.pts"
{ echo "x,y"; awk 'NF { printf "%s,%s\n", $1, $2 }' "$T/s.pts"; } >"$T/s.csv"
$B/fromcad "$T/s.csv" >"$T/back"
e=$(same_rows "$T/s.pts" "$T/back" 0) && ok || no "$what: $e"

# a hull lofted through its stations is a design tocad takes as it is
# (issue 17): one exact surface a patch in STEP and IGES (an IGES entity
# is two lines of the D section), a mesh in STL
what="a lofted hull through tocad"
$B/splinefit -o man/figures/hull.knots | $B/patchloft >"$T/hull.design"
np=$(grep -c '^patch' "$T/hull.design")
ns=$($B/tocad -f step "$T/hull.design" | grep -c 'B_SPLINE_SURFACE_WITH_KNOTS')
ni=$($B/tocad -f iges "$T/hull.design" |
    awk 'substr($0, 73, 1) == "D" && substr($0, 1, 8) + 0 == 128' | wc -l)
nt=$($B/tocad -f stl -n 4 "$T/hull.design" | grep -c 'facet normal')
[ "$np" -gt 1 ] && [ "$ns" -eq "$np" ] && [ "$ni" -eq $((2 * np)) ] &&
    [ "$nt" -eq $((np * 4 * 4 * 2)) ] && ok ||
    no "$what: $np patches; $ns STEP surfaces, $ni IGES lines, $nt STL facets"

finish roundtrip
