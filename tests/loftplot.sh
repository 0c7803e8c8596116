#!/bin/sh
# loftplot.sh: command tests of loftplot and grade, and the figures of
# man/figures, run from the top of the tree.  Expected values are
# derived by hand in the comments; the last line is
# "loftplot: N passed, M failed".

B=bin
T=bin/test/loftplot
. tests/lib.sh

# ---- an XML well-formedness checker, independent of loftplot --------------
# Elements nest and close, one root, attributes name="value" given once,
# '&' only in entities, no text outside the root.  Stricter than XML
# (no single quotes, no CDATA), which loftplot never needs.
XMLCHECK='
function bad(m) { print FILENAME ": " m > "/dev/stderr"; failed = 1; exit 1 }
function entities(s,   t) {
	t = s
	gsub(/&(amp|lt|gt|quot|apos|#[0-9]+|#x[0-9a-fA-F]+);/, "", t)
	return index(t, "&") == 0 && index(t, "<") == 0
}
{ doc = doc $0 "\n" }
END {
	if (failed)
		exit 1
	s = doc
	while ((i = index(s, "<")) > 0) {
		text = substr(s, 1, i - 1)
		if (!entities(text)) bad("bad & in text")
		if (depth == 0 && text ~ /[^ \t\r\n]/) bad("text outside the root")
		s = substr(s, i)
		if (substr(s, 1, 4) == "<!--") {
			j = index(s, "-->")
			if (!j) bad("comment not closed")
			s = substr(s, j + 3)
			continue
		}
		j = index(s, ">")
		if (!j) bad("tag not closed")
		tag = substr(s, 1, j)
		s = substr(s, j + 1)
		if (tag ~ /^<\?/) {
			if (tag !~ /\?>$/ || roots) bad("bad processing instruction")
			continue
		}
		if (tag ~ /^<\//) {
			name = substr(tag, 3, length(tag) - 3)
			if (depth == 0 || name != stack[depth])
				bad("</" name "> closes <" stack[depth] ">")
			depth--
			continue
		}
		if (!match(tag, /^<[A-Za-z_][-A-Za-z0-9_.:]*/)) bad("bad tag " tag)
		name = substr(tag, 2, RLENGTH - 1)
		rest = substr(tag, RLENGTH + 1)
		empty = rest ~ /\/>$/
		sub(/\/?>$/, "", rest)
		split("", seen)
		while (match(rest, /^[ \t\r\n]+[A-Za-z_:][-A-Za-z0-9_.:]*="[^"<]*"/)) {
			a = substr(rest, 1, RLENGTH)
			rest = substr(rest, RLENGTH + 1)
			an = a
			sub(/^[ \t\r\n]+/, "", an)
			sub(/=.*/, "", an)
			if (an in seen) bad("attribute " an " given twice")
			seen[an] = 1
			v = a
			sub(/^[^"]*"/, "", v)
			if (!entities(v)) bad("bad & in attribute " an)
		}
		if (rest ~ /[^ \t\r\n]/) bad("bad attributes in " tag)
		if (depth == 0 && roots++) bad("two root elements")
		if (!empty)
			stack[++depth] = name
	}
	if (depth) bad("<" stack[depth] "> not closed")
	if (!roots) bad("no root element")
	if (s ~ /[^ \t\r\n]/) bad("text after the root")
}'
xml_ok() {
	awk "$XMLCHECK" "$1" 2>>"$T/xmlerr"
}
# svg_ok FILE: well-formed (and to xmllint, where there is one), an svg
# root with a viewBox, at least one path, nothing that runs or fetches
svg_ok() {
	if ! xml_ok "$1"; then
		no "$1: not well-formed: $(tail -1 "$T/xmlerr")"
		return
	fi
	if command -v xmllint >/dev/null 2>&1 &&
	    ! xmllint --noout "$1" 2>>"$T/xmlerr"; then
		no "$1: xmllint: $(tail -1 "$T/xmlerr")"
		return
	fi
	grep -q '^<svg xmlns="http://www.w3.org/2000/svg" version="1.1" .*viewBox="' "$1" &&
	    grep -q '<path ' "$1" && ! grep -q -i 'script\|href\|url(' "$1" &&
	    ok || no "$1: no svg root with a viewBox, no path, or a script or link"
}

# The checker must be able to fail.
for bad in '<svg><g></svg>' '<svg a="1" a="2"/>' '<svg>&</svg>' \
    '<svg/><svg/>' '<svg x=1/>' '<svg><g>' 'text<svg/>'; do
	printf '%s\n' "$bad" >"$T/bad.xml"
	xml_ok "$T/bad.xml" && no "checker passes $bad" || ok
done
printf '<?xml version="1.0"?>\n<svg a="&amp;&#38;"><g/><!-- x --></svg>\n' \
    >"$T/good.xml"
xml_ok "$T/good.xml" && ok || no "checker fails a good document"

# The d attribute of each path of class $1 in file $2, one a line.
path_d() {
	sed -n 's/.*<path class="'"$1"'"[^>]* d="\([^"]*\)".*/\1/p' "$2"
}
# The value of attribute $1 of the svg element of file $2.
svg_attr() {
	sed -n 's/^<svg .* '"$1"'="\([^"]*\)".*/\1/p' "$2"
}

printf 'cubic closed=0\n0 0 1 0 0 2 0 -2\n' >"$T/seg.cubic"
printf 'points name=rect\n0 0\n0 -20\n100 -20\n100 20\n0 20\n' \
    >"$T/rect.knots"

# ---- usage -------------------------------------------------------------
for p in loftplot grade; do
	usage_ok "$p"
done
fails 2 "-v 'zx': want xy, yz, xz or iso" "$B/loftplot -v zx $T/seg.cubic"
fails 2 "-n '0'" "$B/loftplot -n 0 $T/seg.cubic"
fails 2 "-C '0'" "$B/loftplot -C 0 $T/seg.cubic"
fails 2 "-s sizes or -r steps is needed" "$B/grade $T/rect.knots"
fails 2 "-r '3:1': want SIZE or FROM:TO[:STEP]" "$B/grade -r 3:1 $T/rect.knots"
fails 2 "-r '-1:x'" "$B/grade -r -1:x $T/rect.knots"
fails 2 "-r '0:1001'" "$B/grade -r 0:1001 $T/rect.knots"
fails 2 "-l '-1'" "$B/grade -r 0:1 -l -1 $T/rect.knots"
fails 2 "-o '1': want 2 numbers" "$B/grade -r 0:1 -o 1 $T/rect.knots"

# ---- loftplot: the Bezier conversion and the frame, by hand ---------------
# The segment P_A = (0,0), P_B = (1,0), P'_A = (0,2), P'_B = (0,-2):
# B1 = P_A + P'_A/3 = (0, 2/3), B2 = P_B - P'_B/3 = (1, 2/3); SVG's y
# runs down, so y is written negated.  The curve's top is P(1/2) =
# (0.5, 0.5) (its control polygon reaches 2/3, the frame must not), so
# the frame is [0,1] x [0,0.5] with a margin of 4% of 1: viewBox
# -0.04 -0.54 1.08 0.58, coordinates to 1e-6 of 1.08, 6 decimals; the
# picture is 640 wide and 640 x 0.58/1.08 = 343.7 high (equal scales).
run "$B/loftplot $T/seg.cubic"
status 0
cp "$T/out" "$T/seg.svg"
svg_ok "$T/seg.svg"
[ "$(path_d curve "$T/seg.svg")" = "M0 0 C0 -0.666667 1 -0.666667 1 0" ] &&
    ok || no "Bezier of the segment: $(path_d curve "$T/seg.svg")"
[ "$(svg_attr viewBox "$T/seg.svg")" = "-0.04 -0.54 1.08 0.58" ] && ok ||
    no "viewBox of the segment: $(svg_attr viewBox "$T/seg.svg")"
[ "$(svg_attr width "$T/seg.svg") $(svg_attr height "$T/seg.svg")" = \
    "640.0 343.7" ] && ok || no "size of the segment's picture"

# A 3-D segment and the views: P_A = (0,0,0), P_B = (0,0,3),
# P'_A = (3,0,0), P'_B = (0,3,0): B1 = (1,0,0), B2 = (0,-1,3).
# -v xz: (0,0) (1,0) (0,3) (0,3); -v yz: (0,0) (0,0) (-1,3) (0,3).
printf 'cubic\n0 0 0 0 0 3 3 0 0 0 3 0\n' >"$T/space.cubic"
run "$B/loftplot -v xz $T/space.cubic"
[ "$(path_d curve "$T/out")" = "M0 0 C1 0 0 -3 0 -3" ] && ok ||
    no "-v xz: $(path_d curve "$T/out")"
run "$B/loftplot -v yz $T/space.cubic"
[ "$(path_d curve "$T/out")" = "M0 0 C0 0 -1 -3 0 -3" ] && ok ||
    no "-v yz: $(path_d curve "$T/out")"
# Points at the origin and on the axes, -v iso (the view from (1,1,1)):
# (x,y,z) -> ((y-x)/sqrt 2, (2z-x-y)/sqrt 6): (0,0), (-0.707107,
# -0.408248), (0.707107, -0.408248), (0, 0.816497); y negated.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' >"$T/axes.pts"
run "$B/loftplot -v iso $T/axes.pts"
status 0
[ "$(path_d curve "$T/out")" = \
    "M0 0 L-0.707107 0.408248 L0.707107 0.408248 L0 -0.816497" ] && ok ||
    no "-v iso: $(path_d curve "$T/out")"
run "$B/loftplot $T/axes.pts"
[ "$(path_d curve "$T/out")" = "M0 0 L1 0 L0 -1 L0 0" ] && ok ||
    no "3-D points, default xy: $(path_d curve "$T/out")"

# ---- loftplot's Bezier curve is sample's curve ------------------------------
# Evaluate every Bezier segment of the insole's path at u = j/8 by the
# Bernstein form and compare with sample -n 8 (the same parameters).
# Coordinates are written to 1e-6 of the 356 mm frame: within 1e-3 mm.
$B/splinefit man/figures/insole.knots >"$T/insole.cubic"
$B/loftplot -K man/figures/insole.knots "$T/insole.cubic" >"$T/insole.svg"
svg_ok "$T/insole.svg"
$B/sample -n 8 "$T/insole.cubic" >"$T/insole.pts"
path_d curve "$T/insole.svg" | awk -v n=8 '
NR == FNR {
	gsub(/[MCLZ]/, " & ")
	m = split($0, w, " ")
	for (i = 1; i <= m; i++) {
		if (w[i] == "M") { x0 = w[i + 1]; y0 = w[i + 2]; i += 2 }
		else if (w[i] == "C") {
			x1 = w[i + 1]; y1 = w[i + 2]; x2 = w[i + 3]; y2 = w[i + 4]
			x3 = w[i + 5]; y3 = w[i + 6]; i += 6
			for (j = 0; j < n; j++) {
				u = j / n; s = 1 - u
				bx[++k] = s*s*s*x0 + 3*s*s*u*x1 + 3*s*u*u*x2 + u*u*u*x3
				by[k] = -(s*s*s*y0 + 3*s*s*u*y1 + 3*s*u*u*y2 + u*u*u*y3)
			}
			x0 = x3; y0 = y3
		}
	}
	bx[++k] = x0; by[k] = -y0
	next
}
NF == 2 {
	r++
	d = sqrt((bx[r] - $1) ^ 2 + (by[r] - $2) ^ 2)
	if (d > worst) worst = d
}
END {
	if (r != k || r != 22 * n + 1 || worst > 1e-3) {
		printf "%d points of sample, %d of the path, apart by %g\n",
		    r, k, worst
		exit 1
	}
}' - "$T/insole.pts" >"$T/msg" && ok || no "Bezier vs sample: $(cat "$T/msg")"

# The frame holds every point of the curve and every knot, and is tight:
# on each side the margin is 4% of the larger extent (265 mm), give or
# take 0.5 mm that sampling misses of the extremes.
$B/sample -n 64 "$T/insole.cubic" | cat - man/figures/insole.knots |
    awk -v vb="$(svg_attr viewBox "$T/insole.svg")" '
BEGIN { split(vb, v, " "); x0 = v[1]; y0 = v[2]; x1 = x0 + v[3]; y1 = y0 + v[4]
	lo = 1e300; hi = -1e300; ylo = 1e300; yhi = -1e300 }
NF == 2 && $1 !~ /#/ {
	x = $1; y = -$2
	if (x < x0 || x > x1 || y < y0 || y > y1) { print "outside: " $0; bad = 1 }
	if (x < lo) lo = x; if (x > hi) hi = x
	if (y < ylo) ylo = y; if (y > yhi) yhi = y
}
END {
	m = 0.04 * (hi - lo)
	if (bad || (lo - x0 - m) ^ 2 > 0.25 || (x1 - hi - m) ^ 2 > 0.25 ||
	    (ylo - y0 - m) ^ 2 > 0.25 || (y1 - yhi - m) ^ 2 > 0.25) {
		print "frame " vb " about " lo " " hi " " ylo " " yhi; exit 1 }
}' >"$T/msg" && ok || no "viewBox: $(cat "$T/msg")"
# equal scales: width/height = the viewBox's, to the 0.05 px rounding
awk -v vb="$(svg_attr viewBox "$T/insole.svg")" \
    -v w="$(svg_attr width "$T/insole.svg")" \
    -v h="$(svg_attr height "$T/insole.svg")" 'BEGIN { split(vb, v, " ")
	d = w / v[3] - h / v[4]; exit !((w == 640 || h == 640) &&
	d * d < (0.05 / v[4]) ^ 2) }' && ok || no "unequal scales"
# the knots: 22 markers
[ "$(grep -c 'class="knots"' "$T/insole.svg")" = 1 ] &&
    [ "$(grep -o ' a[0-9.]* [0-9.]* 0 1 0 [0-9.]* 0 ' "$T/insole.svg" |
    wc -l)" -eq 22 ] && ok || no "22 knot markers"

# ---- the comb ----------------------------------------------------------
# The segment above at u = 0, 1/2, 1 (-n 2): P' = (0,2), (1.5,0), (0,-2),
# P'' = (6,-4), (0,-4), (-6,-4); eq. 2, kn = (P'' - (P'.P''/P'.P') P') /
# P'.P', gives (1.5,0), (0,-1.777778), (-1.5,0).  With -C 0.2 each tooth
# is -0.2 kn, away from the centre of curvature: (0,0)-(-0.3,0),
# (0.5,0.5)-(0.5,0.855556), (1,0)-(1.3,0).  The frame, [-0.3,1.3] x
# [0,0.86] and 4% of 1.6, is 1.73 wide: 6 decimals.
run "$B/loftplot -C 0.2 -n 2 $T/seg.cubic"
status 0
[ "$(path_d comb "$T/out")" = \
    "M0 0 L-0.3 0 M0.5 -0.5 L0.5 -0.855556 M1 0 L1.3 0" ] && ok ||
    no "comb of the segment: $(path_d comb "$T/out")"
[ "$(path_d comb-envelope "$T/out")" = "M-0.3 0 L0.5 -0.855556 L1.3 0" ] &&
    ok || no "comb envelope: $(path_d comb-envelope "$T/out")"
# The cap: with -C 1 the teeth would be 1.5, 1.78 and 1.5 long on a
# curve 1 wide; each is cut to half the curve's larger side, 0.5, along
# its own direction: (0,0)-(-0.5,0), (0.5,0.5)-(0.5,1), (1,0)-(1.5,0),
# and the frame stays [-0.5,1.5] x [0,1] and its margin, 2.16 x 1.16.
run "$B/loftplot -C 1 -n 2 $T/seg.cubic"
status 0
[ "$(path_d comb "$T/out")" = "M0 0 L-0.5 0 M0.5 -0.5 L0.5 -1 M1 0 L1.5 0" ] &&
    ok || no "comb cap: $(path_d comb "$T/out")"
grep -q 'viewBox="-0.58 -1.08 2.16 1.16"' "$T/out" && ok ||
    no "comb cap frame: $(grep -o 'viewBox="[^"]*"' "$T/out")"
# On the insole every tooth is normal to the curve (sample -d's unit
# tangent), on the side away from the centre of curvature (opposite
# the sign of sample -k's curvature), and 600 times the curvature long.
# Teeth come at u = j/8, j = 0..8, per segment; sample's rows at
# j = 0..7.  Coordinates are good to 1e-4 mm.
$B/loftplot -C 600 -n 8 "$T/insole.cubic" >"$T/comb.svg"
svg_ok "$T/comb.svg"
$B/sample -n 8 -d -k "$T/insole.cubic" >"$T/insole.dk"
path_d comb "$T/comb.svg" | awk '
NR == FNR {
	gsub(/[ML]/, " & ")
	m = split($0, w, " ")
	for (i = 1; i <= m; i += 3) {
		if (w[i] == "M") { t++; bx[t] = w[i + 1]; by[t] = -w[i + 2] }
		else { dx[t] = w[i + 1] - bx[t]; dy[t] = -w[i + 2] - by[t] }
	}
	next
}
NF == 5 {
	r++
	if (r > 22 * 8) next
	t = int((r - 1) / 8) * 9 + (r - 1) % 8 + 1
	if ((bx[t] - $1) ^ 2 + (by[t] - $2) ^ 2 > 1e-8) {
		print "tooth " t " is not at point " r; exit 1 }
	cross = $3 * dy[t] - $4 * dx[t]
	along = $3 * dx[t] + $4 * dy[t]
	len = sqrt(dx[t] ^ 2 + dy[t] ^ 2)
	k = $5 < 0 ? -$5 : $5
	if (along ^ 2 > 1e-7 || cross * $5 > 0 || (len - 600 * k) ^ 2 > 1e-7) {
		print "tooth " t ": along " along ", cross " cross ", length " \
		    len " for curvature " $5; exit 1 }
	n++
}
END { if (n != 22 * 8) { print n " teeth checked"; exit 1 } }
' - "$T/insole.dk" >"$T/msg" && ok || no "comb on the insole: $(cat "$T/msg")"
# a 3-D curve's comb: Fig. 14's seam in each view, well-formed
for v in xy yz xz iso; do
	run "$B/splinefit man/figures/manning-fig14.knots | $B/loftplot -c -v $v"
	status 0
	cp "$T/out" "$T/seam-$v.svg"
	svg_ok "$T/seam-$v.svg"
done

# ---- tangents, labels, several records --------------------------------
# LABELS_CLEAR: from the SVG's own numbers, no label's box meets a drawn
# line (the polylines of class curve, mesh, control-polygon, tangents,
# comb-envelope: M and L only) or another label's box, and a leader line
# ends on a label's box and crosses no other.  A label of class on-curve
# sits on its own record's line (one of its colour meets its box), on a
# ground (a rect of class label-ground) that hides that line: lines of
# other colours must keep clear of it.  A label's box is
# the estimate loftplot promises in loftplot(1): 0.62 em a character wide, from
# its point (or centred on it with text-anchor), 1 em high with the
# baseline 0.15 em above its foot; em = 12 times the scale.  Each line
# is walked in steps of a tenth of an em, so a line crossing a box is
# seen however it crosses.
LABELS_CLEAR='
function inside(x, y, k) {
	return x > bx0[k] && x < bx1[k] && y > by0[k] && y < by1[k]
}
/<path class="(curve|mesh|control-polygon|tangents|comb-envelope)"/ {
	d = $0
	sub(/.* d="/, "", d)
	sub(/".*/, "", d)
	if (d ~ /[^-ML0-9. e]/) { print "not a polyline: " d; bad = 1 }
	c = $0
	sub(/.* stroke="/, "", c)
	sub(/".*/, "", c)
	gsub(/[ML]/, " & ", d)
	n = split(d, w, " ")
	for (i = 1; i <= n; i += 3) {
		if (w[i] == "L") {
			nseg++
			sx0[nseg] = px; sy0[nseg] = py
			sx1[nseg] = w[i + 1]; sy1[nseg] = w[i + 2]
			scol[nseg] = c
		}
		px = w[i + 1]; py = w[i + 2]
	}
}
/<path class="leader"/ {
	d = $0
	sub(/.* d="M/, "", d)
	sub(/".*/, "", d)
	sub(/ L/, " ", d)
	split(d, w, " ")
	nld++
	lx0[nld] = w[1]; ly0[nld] = w[2]; lx1[nld] = w[3]; ly1[nld] = w[4]
}
/<text / {
	t = $0
	sub(/.*translate\(/, "", t)
	split(t, v, /[ )(]/)
	tx = v[1]; ty = v[2]; sc = v[5]
	s = $0
	sub(/<\/text>.*/, "", s)
	sub(/.*>/, "", s)
	gsub(/&[a-z]+;/, "x", s)
	em = 12 * sc
	wd = 0.62 * em * length(s)
	nl++
	c = $0
	sub(/.* fill="/, "", c)
	sub(/".*/, "", c)
	tcol[nl] = c
	on[nl] = $0 ~ /class="label on-curve"/
	non += on[nl]
	bx0[nl] = $0 ~ /text-anchor="middle"/ ? tx - wd / 2 : tx
	bx1[nl] = bx0[nl] + wd
	by0[nl] = ty - 0.85 * em
	by1[nl] = ty + 0.15 * em
	if ($0 ~ /dy="0.35em"/) { by0[nl] += 0.35 * em; by1[nl] += 0.35 * em }
	e[nl] = em
}
/<rect class="label-ground"/ { ngr++ }
END {
	if (ngr != non) { print ngr " grounds for " non " labels on curves"; bad = 1 }
	for (k = 1; k <= nl; k++) {
		for (j = 1; j < k; j++)
			if (bx0[k] < bx1[j] && bx0[j] < bx1[k] &&
			    by0[k] < by1[j] && by0[j] < by1[k]) {
				print "labels " j " and " k " overlap"; bad = 1
			}
		for (i = 1; i <= nseg; i++) {
			dx = sx1[i] - sx0[i]; dy = sy1[i] - sy0[i]
			m = int(sqrt(dx * dx + dy * dy) / (0.1 * e[k])) + 1
			for (q = 0; q <= m; q++)
				if (inside(sx0[i] + q / m * dx, sy0[i] + q / m * dy, k)) {
					if (on[k] && scol[i] == tcol[k]) {
						onown[k] = 1
						break
					}
					print "label " k " meets segment " i; bad = 1
					break
				}
		}
		if (on[k] && !onown[k]) { print "label " k " is on no line of its own"; bad = 1 }
	}
	# a leader ends on its own label and crosses no other
	for (i = 1; i <= nld; i++) {
		dx = lx1[i] - lx0[i]; dy = ly1[i] - ly0[i]
		own = 0
		for (k = 1; k <= nl; k++) {
			ex = 1e-3 * e[k]    # the coordinates are rounded
			if (lx1[i] >= bx0[k] - ex && lx1[i] <= bx1[k] + ex &&
			    ly1[i] >= by0[k] - ex && ly1[i] <= by1[k] + ex) {
				own = k
				continue
			}
			m = int(sqrt(dx * dx + dy * dy) / (0.1 * e[k])) + 1
			for (q = 0; q <= m; q++)
				if (inside(lx0[i] + q / m * dx, ly0[i] + q / m * dy, k)) {
					print "leader " i " crosses label " k; bad = 1
					break
				}
		}
		if (!own) { print "leader " i " ends on no label"; bad = 1 }
	}
	if (nl == 0) { print "no labels"; bad = 1 }
	exit bad
}'

# Labels clear of every curve: eight concentric circles (polylines of 90
# sides) 0.9 apart, each labelled by its size, with a line across all
# of them through their rightmost points, where the labels would go,
# and a fan of five lines meeting at one point.
awk 'BEGIN { for (k = 0; k < 8; k++) { print "points size=" k - 3
	for (i = 0; i <= 90; i++) print (10 + 0.9 * k) * cos(i * 3.14159265358979 / 45),
	    (10 + 0.9 * k) * sin(i * 3.14159265358979 / 45); print "" }
	print "points size=across"; print 8, 0; print 20, 0; print ""
	for (k = 0; k < 5; k++) printf "points size=f%d\n0 -20\n%d %d\n\n", k, 18 - k, k - 16 }' \
    >"$T/rings.pts"
run "$B/loftplot -l size $T/rings.pts"
status 0
cp "$T/out" "$T/rings.svg"
svg_ok "$T/rings.svg"
[ "$(grep -c '<text' "$T/rings.svg")" = 14 ] &&
    [ "$(grep -c 'class="label on-curve"' "$T/rings.svg")" -ge 1 ] &&
    awk "$LABELS_CLEAR" \
    "$T/rings.svg" >"$T/clear" && ok || no "rings: $(head -3 "$T/clear")"
# The demo's graded set of eight: labels by their curves or, where the
# outlines crowd, on them.  The curves are cubic paths, not polylines:
# in their place the checker gets the outlines as sample -n 64 writes
# them (within a thousandth of a label of the cubics), in the colours
# of the curves in the picture, in order.
run "$B/grade -r -3:4 man/figures/insole.knots | $B/splinefit | $B/loftplot -l size"
status 0
cp "$T/out" "$T/nest.svg"
$B/grade -r -3:4 man/figures/insole.knots | $B/splinefit | $B/sample -n 64 |
    awk -v cols="$(sed -n 's/.*class="curve" stroke="\([^"]*\)".*/\1/p' "$T/nest.svg" | tr '\n' ' ')" '
function flush() { if (d != "") printf "<path class=\"curve\" stroke=\"%s\" d=\"%s\"/>\n", c[++r], d; d = "" }
BEGIN { split(cols, c, " ") }
NF == 0 { flush(); next }
{ d = d (d == "" ? "M" : " L") $1 " " (-$2) }
END { flush() }' >"$T/nest.lines"
[ "$(grep -c '<text' "$T/nest.svg")" = 8 ] &&
    [ "$(grep -c 'class="label on-curve"' "$T/nest.svg")" -ge 1 ] &&
    [ "$(wc -l <"$T/nest.lines")" = 8 ] &&
    grep -v 'class="curve"' "$T/nest.svg" | cat - "$T/nest.lines" |
    awk "$LABELS_CLEAR" >"$T/clear" && ok || no "graded labels: $(head -3 "$T/clear")"
# The same awk sees labels struck through, by lines 0.4 apart across the
# picture (narrower than any label): the check can fail.
awk 'BEGIN { printf "<path class=\"curve\" d=\""
	for (x = -25; x <= 25; x += 0.4) printf "M%g -25 L%g 25 ", x, x
	print "\"/>" }' >"$T/hatch"
cat "$T/rings.svg" "$T/hatch" | awk "$LABELS_CLEAR" >/dev/null &&
    no "LABELS_CLEAR passes struck labels" || ok

# -t: the segment's tangents / 3, from the ends: (0,0)-(0,2/3) and
# (1,0)-(1,2/3).
run "$B/loftplot -t $T/seg.cubic"
[ "$(path_d tangents "$T/out")" = "M0 0 L0 -0.666667 M1 0 L1 -0.666667" ] &&
    ok || no "-t: $(path_d tangents "$T/out")"
# Labels: the attribute's value, escaped, or the record's number.
run "{ printf 'points name=a<b&\"c\"\n0 0\n1 1\n\npoints\n0 1\n1 0\n'; } |
    $B/loftplot -l name"
status 0
cp "$T/out" "$T/labels.svg"
svg_ok "$T/labels.svg"
[ "$(sed -n 's/.*<text [^>]*>\(.*\)<\/text>/\1/p' "$T/labels.svg" |
    tr '\n' ' ')" = "a&lt;b&amp;&quot;c&quot; 2 " ] && ok ||
    no "labels: $(grep '<text' "$T/labels.svg")"
# Two records share their rightmost point (1,1): their labels do not
# overlap, and neither meets a line (LABELS_CLEAR below).
run "printf '0 0\n1 1\n\n0 1\n1 1\n' | $B/loftplot -l n"
[ "$(grep -c '<text' "$T/out")" = 2 ] && awk "$LABELS_CLEAR" "$T/out" &&
    ok || no "labels at one point overlap: $(grep '<text' "$T/out")"
# A crowd (issue 28): 300 records whose rightmost points stand a
# 250th of a line apart in one column.  Walking each label of the last
# resort down past all those before it made the placement quadratic;
# after LAST_MOVES moves a label goes on the rows below the picture
# instead.  Invariants: 300 labels, no two overlap (their boxes as
# LABELS_CLEAR takes them), and the picture is far less than the 300
# lines high that one column of them would make.
awk 'BEGIN { for (i = 0; i < 300; i++) printf "points\n0 %.4f\n1 %.4f\n\n", i * 0.001, i * 0.001 }' >"$T/crowd.pts"
run "$B/loftplot -l id $T/crowd.pts"
status 0
awk '/viewBox=/ { b = $0; sub(/.*viewBox="/, "", b); split(b, vb, /[ "]/) }
/<text / {
	t = $0; sub(/.*translate\(/, "", t); split(t, v, /[ )(]/)
	s = $0; sub(/<\/text>.*/, "", s); sub(/.*>/, "", s)
	em = 12 * v[5]; n++
	x0[n] = v[1]; x1[n] = v[1] + 0.62 * em * length(s)
	y0[n] = v[2] - 0.85 * em; y1[n] = v[2] + 0.15 * em
}
END {
	if (n != 300) { print n " labels"; exit 1 }
	for (k = 1; k <= n; k++)
		for (j = 1; j < k; j++)
			if (x0[k] < x1[j] && x0[j] < x1[k] && y0[k] < y1[j] && y0[j] < y1[k]) {
				print "labels " j " and " k " overlap"; exit 1 }
	if (!(vb[4] < 100 * em)) { print "the page is " vb[4] / em " lines high"; exit 1 }
}' "$T/out" >"$T/why" && ok || no "a crowd of labels: $(cat "$T/why")"
# Patch ids at the patch's middle, f(1/2, 1/2), not at a corner: the
# bilinear patch through (0,0,0) (4,0,0) (0,3,0) (4,3,1) is
# f(s,t) = (4s, 3t, st); split at s = 1/2, the halves' middles are
# f(1/4, 1/2) = (1, 1.5, 0.125) and f(3/4, 1/2) = (3, 1.5, 0.375).  In
# the iso view a point goes to ((y - x)/sqrt 2, (2z - x - y)/sqrt 6),
# y up; the label is centred there (text-anchor middle).
run "$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 | $B/patchsplit -u 0.5 |
    $B/loftplot -v iso -l id"
status 0
sed -n 's/.*text-anchor="middle".*translate(\([^ ]*\) \([^)]*\)).*>\([0-9]*\)<.*/\3 \1 \2/p' \
    "$T/out" | awk 'function want(id, x, y, z) {
		wx[id] = (y - x) / sqrt(2); wy[id] = -(2 * z - x - y) / sqrt(6) }
	function abs(a) { return a < 0 ? -a : a }
	BEGIN { want(2, 1, 1.5, 0.125); want(3, 3, 1.5, 0.375) }
	{ n++; if (!($1 in wx) || abs($2 - wx[$1]) > 1e-5 || abs($3 - wy[$1]) > 1e-5) bad = 1 }
	END { exit bad || n != 2 }' && ok ||
    no "patch ids not at f(1/2,1/2): $(grep '<text' "$T/out")"
# -B: a rectangle of that colour under everything, the size of the
# frame; a colour that is neither a name nor #rgb/#rrggbb is refused.
run "$B/loftplot -B '#102030' $T/seg.cubic"
status 0
[ "$(sed -n 's/.*viewBox="\([^"]*\)".*/\1/p' "$T/out")" = \
    "$(sed -n 's/<rect class="background" fill="#102030" stroke="none" x="\([^"]*\)" y="\([^"]*\)" width="\([^"]*\)" height="\([^"]*\)"\/>/\1 \2 \3 \4/p' "$T/out")" ] &&
    [ "$(grep -n '<rect' "$T/out" | cut -d: -f1)" -lt "$(grep -n '<path' "$T/out" | head -1 | cut -d: -f1)" ] &&
    ok || no "-B: $(grep '<rect\|viewBox' "$T/out")"
run "$B/loftplot $T/seg.cubic"
grep -q '<rect' "$T/out" && no "a background without -B" || ok
fails 2 "-B '#12': a colour is a name (white) or #rgb or #rrggbb" "$B/loftplot -B '#12' $T/seg.cubic"
fails 2 "-B 'red\"/>': a colour" "$B/loftplot -B 'red\"/>' $T/seg.cubic"
# Rows of the wrong width: sample -k of a plane curve writes x y k, which
# drawn with the curve would be a 3-D point record: refused, named, and
# the curve still drawn.
run "{ $B/splinefit $T/rect.knots; $B/splinefit $T/rect.knots | $B/sample -k -n 2; } | $B/loftplot"
status 1
says "loftplot: <stdin>:"
says "3 coordinates, where the first record has 2: rows of sample -k, -d, -s or -t? loftplot draws coordinates alone"
[ "$(grep -c 'class="curve"' "$T/out")" = 1 ] && ok || no "the good curve not drawn"
# A bezier record is drawn as a polyline within a quarter pixel of it:
# the parabola of control points (0,0) (1,2) (2,0), y = x (2 - x).  A
# chord of it from x = a to b is farthest from it at x = (a + b)/2,
# where the tangent is parallel to the chord: (b - a)^2 / 4 below it
# vertically, (b - a)^2 / 4 / sqrt(1 + s^2) away, s the chord's slope;
# the tolerance
# is 0.25 px of the record's own extent, 2: 0.25 * 2 / 640.  Each vertex
# is on the parabola, and the polyline is not needlessly fine: some
# chord is more than a quarter of the tolerance away.
run "printf 'bezier\n0 0\n1 2\n2 0\n' | $B/loftplot"
status 0
path_d curve "$T/out" | tr 'ML' '\n\n' | awk 'NF == 2 {
	x = $1; y = -$2; n++
	if ((y - x * (2 - x)) ^ 2 > 1e-10) bad = 1
	if (n > 1) { s = (y - py) / (x - px)
		g = (x - px) ^ 2 / 4 / sqrt(1 + s * s); if (g > most) most = g }
	px = x; py = y }
	END { tol = 0.25 * 2 / 640
	exit !(n > 3 && !bad && most <= tol && most > tol / 4 && px == 2) }' &&
    ok || no "bezier not flattened within 1/4 px: $(path_d curve "$T/out" | head -c 300)"
# Without -n, a surface's lines are as fine as their bending needs: the
# bezier-surface of degrees 1 and 2 whose line u = 0 is that parabola
# and u = 1 the parabola 1 higher (x = 2v, y = u + 4v(1 - v)).  Its
# extent is 2 (x 0..2, y 0..2), so each vertex of the edge u = 0 lies on
# y = x (2 - x), each chord within 0.25 * 2 / 640 of it, some chord more
# than a quarter of that; the straight edges v = 0, v = 1 are one chord.
run "printf 'bezier-surface m=1 n=2\n0 0 0\n1 2 0\n2 0 0\n0 1 0\n1 3 0\n2 1 0\n' |
    $B/loftplot -g 1"
status 0
path_d curve "$T/out" | sed -n 1p | tr 'ML' '\n\n' | awk 'NF == 2 {
	x = $1; y = -$2; n++
	if ((y - x * (2 - x)) ^ 2 > 1e-10) bad = 1
	if (n > 1) { s = (y - py) / (x - px)
		g = (x - px) ^ 2 / 4 / sqrt(1 + s * s); if (g > most) most = g }
	px = x; py = y }
	END { tol = 0.25 * 2 / 640
	exit !(n > 3 && !bad && most <= tol && most > tol / 4 && px == 2) }' &&
    [ "$(path_d curve "$T/out" | sed -n '3,4p' | tr '\n' '|')" = "M0 0 L0 -1|M2 0 L2 -1|" ] &&
    ok || no "surface lines not within 1/4 px: $(path_d curve "$T/out" | head -c 300)"

# -m marks the rows of a point record; a graded set, labelled by size.
run "$B/loftplot -m $T/rect.knots"
grep -q 'class="points"' "$T/out" && ok || no "-m draws no markers"
run "$B/grade -r -1:1 man/figures/insole.knots | $B/splinefit | $B/loftplot -l size"
status 0
cp "$T/out" "$T/graded.svg"
svg_ok "$T/graded.svg"
[ "$(grep -c 'class="curve"' "$T/graded.svg")" = 3 ] &&
    [ "$(sed -n 's/.*<text [^>]*>\(.*\)<\/text>/\1/p' "$T/graded.svg" |
    tr '\n' ' ')" = "-1 0 +1 " ] && ok || no "graded set: 3 curves, -1 0 +1"

# ---- loftplot: bad input ----------------------------------------------------
# Good records around bad ones: the bad are reported, the picture of the
# good is written whole, exit 1.
{ cat "$T/seg.cubic"; printf '\ncubic\n1 2 3\n\n'; cat "$T/rect.knots"
  printf '\nspline\n1 2\n'; } >"$T/mixed"
run "$B/loftplot $T/mixed"
status 1
says "loftplot: $T/mixed:5: cubic rows need 8 or 12 numbers, not 3"
says "loftplot: $T/mixed:14: unknown record type 'spline'"
cp "$T/out" "$T/mixed.svg"
svg_ok "$T/mixed.svg"
[ "$(grep -c 'class="curve"' "$T/mixed.svg")" = 2 ] && ok ||
    no "good records around bad ones: 2 curves"
fails 1 "loftplot: nothing to draw" "$B/loftplot /dev/null"
fails 1 "loftplot: <stdin>:2: cubic rows need" "printf 'cubic\n1 2 3\n' | $B/loftplot"
fails 1 "points have 4 numbers; loftplot reads 2 or 3" \
    "printf '1 2 3 4\n' | $B/loftplot"
fails 1 "points have 1 number;" "printf '1\n2\n' | $B/loftplot"
fails 1 "cubic record: -K reads knots" "$B/loftplot -K $T/seg.cubic /dev/null"
fails 1 "tangent vanishes in segment 1 at u = 0: no curvature for the comb" \
    "printf 'cubic\n0 0 1 0 0 0 1 0\n' | $B/loftplot -c"
run "printf 'cubic\n0 0 1 0 0 0 1 0\n' | $B/loftplot"
status 0
# Coordinates near the largest double are drawn; a drawing wider than
# it is not.
run "printf 'cubic\n0 0 1e308 0 1e308 1e308 1e308 1e308\n' | $B/loftplot"
status 0
cp "$T/out" "$T/huge.svg"
svg_ok "$T/huge.svg"
fails 1 "too large to frame" "printf -- '-1e308 0\n1e308 0\n' | $B/loftplot"
fails 1 "<stdin>:2: coordinates too large to draw" \
    "printf 'cubic\n-1e308 0 1e308 0 1 1 1 1\n' | $B/loftplot"
fails 1 "attribute closed=2: want 0 or 1" \
    "printf 'cubic closed=2\n0 0 1 0 0 2 0 -2\n' | $B/loftplot"
# A -K file that is missing: reported; the curve is still drawn.
run "$B/loftplot -K $T/nonexistent $T/seg.cubic"
status 1
says "loftplot: $T/nonexistent: No such file or directory"
grep -q 'class="curve"' "$T/out" && ok || no "curve drawn without its -K"
run "$B/loftplot $T/seg.cubic > /dev/full"
status 1
says "loftplot: write error"
# Fig. 1: knots alone
run "$B/loftplot -K man/figures/insole.knots < /dev/null"
status 0

# ---- loftplot: surfaces and control points ----------------------------------
# The bilinear patch through (0,0,0) (4,0,0) (0,3,0) (4,3,1) is
# f(u,v) = (4u, 3v, uv) exactly (patchnew.1).  -g 2 -n 2: the lines
# u = 0, 1/2, 1 and v = 0, 1/2, 1, three points each.  The inner ones
# (mesh) come first: u = 1/2 is (2,0,0) (2,1.5,0.25) (2,3,0.5), v = 1/2
# is (0,1.5,0) (2,1.5,0.25) (4,1.5,0.5); then the edges (curve):
# u = 0, u = 1, v = 0, v = 1.  y is written negated.
$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 >"$T/bilin.patch"
run "$B/loftplot -g 2 -n 2 $T/bilin.patch"
status 0
cp "$T/out" "$T/bilin.svg"
svg_ok "$T/bilin.svg"
[ "$(path_d mesh "$T/bilin.svg" | tr '\n' '|')" = \
    "M2 0 L2 -1.5 L2 -3|M0 -1.5 L2 -1.5 L4 -1.5|" ] && ok ||
    no "mesh of the bilinear patch: $(path_d mesh "$T/bilin.svg")"
[ "$(path_d curve "$T/bilin.svg" | tr '\n' '|')" = \
    "M0 0 L0 -1.5 L0 -3|M4 0 L4 -1.5 L4 -3|M0 0 L2 0 L4 0|M0 -3 L2 -3 L4 -3|" ] &&
    ok || no "edges of the bilinear patch: $(path_d curve "$T/bilin.svg")"
# -v xz: (4u, uv); u = 1/2 rises from 0 to 0.5, v = 1/2 from 0 to 0.5.
run "$B/loftplot -g 2 -n 2 -v xz $T/bilin.patch"
[ "$(path_d mesh "$T/out" | tr '\n' '|')" = \
    "M2 0 L2 -0.25 L2 -0.5|M0 0 L2 -0.25 L4 -0.5|" ] && ok ||
    no "mesh of the bilinear patch, -v xz: $(path_d mesh "$T/out")"
# -g 1: the edges only.
run "$B/loftplot -g 1 $T/bilin.patch"
[ "$(grep -c 'class="mesh"' "$T/out") $(grep -c 'class="curve"' "$T/out")" = \
    "0 4" ] && ok || no "-g 1 draws other than the 4 edges"

# Every point of a wireframe is a point of sample's wireframe at the same
# parameters, and every point of sample's is drawn (each path point
# takes one sample point, so points that coincide in the view count
# once each): a design of six
# dragged patches, and the Bezier surface of the cylinder of Carriazo's
# Example 4.1, each seen in x-y and x-z.  Coordinates are written to 1e-6
# of a frame of a few units: 1e-5 apart at most.
$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 |
    $B/patchdrag -u 0.5 -v 0.5 -b 0,0,1 | $B/patchsplit -v 0.4 |
    $B/patchsplit -i 3 -v 0.5 | $B/patchsplit -u 0.3 >"$T/six.patch"
$B/bezapprox -n 3,3 -x u -y 'cos(pi*v)' -z 'sin(pi*v)' >"$T/cyl.bez"
for f in six.patch cyl.bez; do
	$B/sample -n 4 "$T/$f" >"$T/$f.pts"
	for v in xy xz; do
		$B/loftplot -g 4 -n 4 -v $v "$T/$f" >"$T/$f-$v.svg"
		svg_ok "$T/$f-$v.svg"
		{ path_d mesh "$T/$f-$v.svg"; path_d curve "$T/$f-$v.svg"; } |
		    awk -v v=$v '
NR == FNR {
	gsub(/[ML]/, " ")
	m = split($0, w, " ")
	for (i = 1; i < m; i += 2) { k++; px[k] = w[i]; py[k] = -w[i + 1] }
	next
}
NF == 3 { r++; sx[r] = $1; sy[r] = v == "xy" ? $2 : $3 }
END {
	for (i = 1; i <= k; i++) {
		for (j = 1; j <= r; j++)
			if (!hit[j] &&
			    (px[i] - sx[j]) ^ 2 + (py[i] - sy[j]) ^ 2 < 1e-10) {
				hit[j] = 1; break }
		if (j > r) { print "path point " px[i] " " py[i] " is not sampled"; exit 1 }
	}
	for (j = 1; j <= r; j++)
		if (!hit[j]) { print "sample point " j " is not drawn"; exit 1 }
	if (k != r || k == 0) { print k " points drawn, " r " sampled"; exit 1 }
}' - "$T/$f.pts" >"$T/msg" && ok || no "wireframe of $f, -v $v: $(cat "$T/msg")"
	done
done
[ "$(wc -l <"$T/six.patch.pts")" -ge 300 ] && ok || no "six patches sampled"

# -b: the control points of a bezier record, at its rows: the paper's
# parabola of Example 3.1, P1 = (5/8, 1/8) (P0 = (0,0), P2 = (1,1)).
# A marker at (x, y) is "M x-r -y a r r ...": its centre is M's point
# plus (r, 0).
ctl_centres() {
	path_d control-points "$1" | tr 'M' '\n' | awk 'NF {
		x = $1 + substr($3, 2); y = $2 == 0 ? 0 : -$2
		printf "%.6f %.6f\n", x, y }'
}
run "$B/bezapprox -n 2 -x t -y 't^2' | $B/loftplot -b"
status 0
cp "$T/out" "$T/parab.svg"
svg_ok "$T/parab.svg"
[ "$(ctl_centres "$T/parab.svg" | tr '\n' '|')" = \
    "0.000000 0.000000|0.625000 0.125000|1.000000 1.000000|" ] && ok ||
    no "control points of the parabola: $(ctl_centres "$T/parab.svg")"
[ "$(path_d control-polygon "$T/parab.svg")" = "M0 0 L0.625 -0.125 L1 -1" ] &&
    ok || no "control polygon: $(path_d control-polygon "$T/parab.svg")"
# without -b, none; -b leaves other records alone
run "$B/bezapprox -n 2 -x t -y 't^2' | $B/loftplot"
grep -q 'class="control' "$T/out" && no "control points without -b" || ok
run "$B/loftplot -b $T/seg.cubic $T/bilin.patch"
grep -q 'class="control' "$T/out" && no "-b draws a cubic's or patch's" || ok
# A bezier-surface: a marker at each of its 16 rows, in order, and the
# net: 4 lines along v (rows i fixed), then 4 along u, 4 points each.
$B/loftplot -b -v xz "$T/cyl.bez" >"$T/cyl.svg"
svg_ok "$T/cyl.svg"
ctl_centres "$T/cyl.svg" | awk '
NR == FNR { x[FNR] = $1; y[FNR] = $2; n = FNR; next }
NF == 3 { r++; if ((x[r] - $1) ^ 2 + (y[r] - $3) ^ 2 > 1e-10) bad = 1 }
END { exit bad || n != 16 || r != 16 }' - "$T/cyl.bez" && ok ||
    no "control points of the cylinder: $(ctl_centres "$T/cyl.svg" | head -3)"
path_d control-polygon "$T/cyl.svg" | awk '{ n++; if (NF != 8) bad = 1 }
END { exit bad || n != 8 }' && ok || no "control net of the cylinder: 8 lines"

# Bad surfaces: reported, left out, the good ones drawn.
{ cat "$T/bilin.patch"; printf '\npatch id=2\n1 2 3 4 5 6 7 8 9 10\n\n'
  printf 'bezier-surface m=1\n0 0 0\n1 0 0\n'; } >"$T/badsurf"
run "$B/loftplot $T/badsurf"
status 1
says "loftplot: $T/badsurf:9: patch record has 1 row; a patch has 5"
says "loftplot: $T/badsurf:12: bezier-surface record without its degree n="
[ "$(grep -c 'class="curve"' "$T/out")" = 4 ] && ok ||
    no "good patch around bad surfaces: 4 edges"
fails 2 "-g '0'" "$B/loftplot -g 0 $T/bilin.patch"
fails 1 "coordinates too large to draw" \
    "printf 'bezier-surface m=1 n=1\n-1.7e308 1.7e308 0\n0 0 0\n0 0 0\n0 0 0\n' |
    $B/loftplot -v iso"

# ---- grade: the formula by hand ----------------------------------------
# The rectangle: L = 100 long (x), W = 40 wide (y), heel point (0,0), the
# first knot of smallest x.  -l 10 -w 2: x' = x + x k 10/100,
# y' = y + y k 2/40; size -1: 100 -> 90, 20 -> 19; size +1: 110, 21.
# Lengths grow by 10 and widths by 2 a step: not a proportional
# enlargement (factors 1.1 and 1.05).
run "$B/grade -r -1:1 -l 10 -w 2 $T/rect.knots"
status 0
out_is "points size=-1 name=rect
0 0
0 -19
90 -19
90 19
0 19

points size=0 name=rect
0 0
0 -20
100 -20
100 20
0 20

points size=+1 name=rect
0 0
0 -21
110 -21
110 21
0 21
"
# -o 100,0: x' = x + (x - 100) 10/100: 0 -> -10, 100 stays.
run "$B/grade -r 1:1 -l 10 -w 2 -o 100,0 $T/rect.knots"
out_is "points size=+1 name=rect
-10 0
-10 -21
100 -21
100 21
-10 21
"
# start= and end= directions stretch with the outline: (1.1, 1.05).
run "printf 'points size=-1 start=1,1 end=0,-1\n0 0\n100 20\n50 -20\n' |
    $B/grade -r 1:1 -l 10 -w 2"
out_is "points size=0 start=1.1,1.05 end=0,-1.05
0 0
110 21
55 -21
"
# The insole with the default steps, English: 25.4/3 mm (a third of an
# inch) and 2.54 mm: size k is exactly 265 + 25.4 k / 3 long and
# 95 + 2.54 k wide, for k = -3..4.
$B/grade -r -3:4 man/figures/insole.knots | awk '
/^points/ { if (n) check(); split($2, s, "="); k = s[2] + 0; n = 0; next }
NF == 2 { if (!n++) { x0 = x1 = $1; y0 = y1 = $2 }
	if ($1 < x0) x0 = $1; if ($1 > x1) x1 = $1
	if ($2 < y0) y0 = $2; if ($2 > y1) y1 = $2 }
function check() { recs++
	if ((x1 - x0 - 265 - 25.4 / 3 * k) ^ 2 > 1e-22 ||
	    (y1 - y0 - 95 - 2.54 * k) ^ 2 > 1e-22) {
		print "size " k ": " x1 - x0 " by " y1 - y0; bad = 1 } }
END { check(); exit bad || recs != 8 }' >"$T/msg" && ok ||
    no "insole sizes: $(cat "$T/msg")"
# -s 0:0 is the identity: the rows come back as they went in.
run "$B/grade -r 0:0 man/figures/insole.knots"
{ echo "points size=0"; sed '/^#/d' man/figures/insole.knots; echo; } |
    cmp -s - "$T/out" && ok || no "-s 0:0 changes the knots"
# Two steps of one are one step of two: L grows by l each time, so the
# factors (L+l)/L and (L+2l)/(L+l) multiply to (L+2l)/L; the heel point
# stays where it is.
$B/grade -r 1:1 man/figures/insole.knots | $B/grade -r 1:1 >"$T/twice"
$B/grade -r 2:2 man/figures/insole.knots >"$T/once"
paste -d ' ' "$T/twice" "$T/once" | awk '
NR == 1 { if ($0 != "points size=+2 points size=+2") bad = 1; next }
NF == 4 { if (($1 - $3) ^ 2 + ($2 - $4) ^ 2 > 1e-20) bad = 1; n++ }
END { exit bad || n != 22 }' && ok || no "grade twice by 1 differs from by 2"
# many records in, many out, in order
run "sed 's/rect/second/' $T/rect.knots | $B/grade -r -1:0 - $T/rect.knots"
[ "$(grep '^points' "$T/out" | tr '\n' ' ')" = \
    "points size=-1 name=second points size=0 name=second points size=-1 name=rect points size=0 name=rect " ] &&
    ok || no "many records: $(grep '^points' "$T/out" | tr '\n' ' ')"

# ---- grade: bad input -----------------------------------------------------
fails 1 "cubic record: grade reads knots" "$B/grade -r 0:1 $T/seg.cubic"
fails 1 "knots have 3 coordinates; grade reads plane outlines" \
    "printf '0 0 0\n1 1 1\n' | $B/grade -r 0:1"
fails 1 "<stdin>:1: the knots have no extent along x" \
    "printf '0 0\n0 1\n' | $B/grade -r 0:1"
fails 1 "no extent along y" "printf '0 0\n1 0\n' | $B/grade -r 0:1"
fails 1 "size -10 leaves the outline no length (100 -100)" \
    "$B/grade -r -10:0 -l 10 $T/rect.knots"
fails 1 "attribute size=big: want a whole or half number" \
    "printf 'points size=big\n0 0\n1 1\n' | $B/grade -r 0:1"
fails 1 "attribute start=1: want 2 numbers" \
    "printf 'points start=1\n0 0\n100 50\n' | $B/grade -r 0:1"
fails 1 "record has no knots" "printf 'points\n' | $B/grade -r 0:0"
{ printf '0 0\n0 1\n\n'; cat "$T/rect.knots"; } >"$T/gmixed"
run "$B/grade -r 0:0 $T/gmixed"
status 1
says "grade: $T/gmixed:1: the knots have no extent along x"
[ "$(grep -c '^points size=0 name=rect$' "$T/out")" = 1 ] && ok ||
    no "grade: the good record after a bad one"
run "$B/grade -r 0:0 $T/rect.knots > /dev/full"
status 1
says "grade: write error"

# ---- the figures: regenerated from nothing but the programs -------------
# In a copy of man/figures, so the tree is left alone: every figure is
# made without a message, is a good SVG, and is the committed one by its
# geometry (tests/svgcmp.awk: every element and word the same, every
# number within 2e-6 of the frame, so that a last digit may turn over).
mkdir -p "$T/figures"
cp man/figures/* "$T/figures/"
rm -f "$T/figures/"*.svg
# potrace's trace beside the noisy glyph needs potrace: without it the
# Makefile keeps the committed figure, so the copy gets that one
if ! command -v potrace >/dev/null 2>&1; then
	cp man/figures/noisy-glyph-potrace.svg "$T/figures/"
	echo "skip: man/figures/noisy-glyph-potrace.svg made again (no potrace)"
fi
# (without the caller's MAKEFLAGS: under make -j the nested make warns
# that it has no jobserver, which is no fault of the figures)
if MAKEFLAGS= MFLAGS= make -s -C "$T/figures" BIN="$(pwd)/$B" >"$T/out" 2>"$T/err" &&
    [ ! -s "$T/err" ]; then
	ok
else
	no "make -C man/figures: $(head -3 "$T/err")"
fi
n=0
for f in man/figures/*.svg; do
	n=$((n + 1))
	g="$T/figures/${f##*/}"
	svg_ok "$g"
	d=$(awk -f tests/svgcmp.awk "$f" "$g") && ok ||
	    no "$f differs from what the programs make now (make figures): $d"
done
# the comparator itself: a figure with one control point moved by 1e-5
# of its frame (0.006 pixels) is not the figure; one whose last digits
# turned over is
f=man/figures/manning-fig03.svg
sed 's/C0.066667 -0.066667/C0.066678 -0.066667/' "$f" >"$T/moved.svg"
sed 's/C0.066667 -0.066667/C0.066668 -0.066666/' "$f" >"$T/digit.svg"
cmp -s "$f" "$T/moved.svg" || cmp -s "$f" "$T/digit.svg" &&
    no "svgcmp: $f no longer holds the point the cases change"
awk -f tests/svgcmp.awk "$f" "$T/moved.svg" >/dev/null &&
    no "svgcmp: a point moved by 1e-5 of the frame passed" || ok
awk -f tests/svgcmp.awk "$f" "$T/digit.svg" >/dev/null && ok ||
    no "svgcmp: a last digit turned over failed"
[ "$n" -ge 42 ] && [ "$(ls "$T/figures/"*.svg | wc -l)" -eq "$n" ] && ok ||
    no "$n figures committed, $(ls "$T/figures/"*.svg | wc -l) made"

# ---- issue 28: the comb of a curve in any units ---------------------------
# The insole drawn with -c at 1e160 and 1e-160 is the picture at unit
# scale with every number times the scale: the comb's points divided by
# it agree with the unit picture's within 0.05 mm, a tenth of a pixel of
# its 640 (the digits written of a number of 1e160 are fewer; a comb scaled
# through squares of 1e-320 or 1e320 was refused, or lost).  Its numbers
# are in units of its data-unit, where it has one (svgplot.c).
combs() {
	awk -v s="$1" '/^[0-9-]/ { print $1 * s, $2 * s; next } { print }' \
	    man/figures/insole.knots | "$B/splinefit" | "$B/loftplot" -c |
	    awk -v s="$1" 'BEGIN { u = 1 }
		/data-unit="/ { u = $0; sub(/.*data-unit="/, "", u); sub(/".*/, "", u) }
		/class="comb"/ { sub(/.* d="/, ""); sub(/".*/, "")
		gsub(/[ML]/, " "); n = split($0, v, " ")
		for (i = 1; i <= n; i++) printf "%.4f\n", v[i] * u / s }'
}
combs 1 >"$T/comb1"
for sc in 1e160 1e-160; do
	combs "$sc" >"$T/comb$sc"
	[ "$(wc -l <"$T/comb1")" -gt 100 ] &&
	    awk 'NR == FNR { a[FNR] = $1; next }
		{ d = $1 - a[FNR]; if (d < 0) d = -d; if (d > 0.05) bad = 1 }
		END { exit bad || NR != 2 * FNR }' "$T/comb1" "$T/comb$sc" &&
	    ok || no "loftplot -c at scale $sc is not the unit comb scaled"
done

# ---- issue 24: a point record's closed=1 closes its polyline --------------
d=$(printf 'points closed=1\n0 0\n1 0\n1 1\n' | "$B/loftplot" |
    sed -n 's/.*class="curve".* d="\([^"]*\)".*/\1/p')
[ "$d" = "M0 0 L1 0 L1 -1 L0 0 Z" ] && ok ||
    no "points closed=1: path '$d', want back to the first point and Z"
d=$(printf 'points closed=0\n0 0\n1 0\n1 1\n' | "$B/loftplot" |
    sed -n 's/.*class="curve".* d="\([^"]*\)".*/\1/p')
[ "$d" = "M0 0 L1 0 L1 -1" ] && ok || no "points closed=0: path '$d'"

# ---- issue 28: labels in linear time ----------------------------------------
# 5,000 labelled records drawn over each other: the labels of the pile
# each stand apart (no two texts at one point).  How long it takes is
# make bench's to say, not this test's.
awk 'BEGIN { for (r = 1; r <= 5000; r++)
	printf "points id=%d\n0 0\n5 0\n5 5\n\n", r }' >"$T/pile"
if "$B/loftplot" -l id "$T/pile" >"$T/pile.svg" 2>"$T/err"; then
	n=$(grep -c 'class="label' "$T/pile.svg")
	d=$(sed -n 's/.*class="label.*translate(\([^)]*\)).*/\1/p' \
	    "$T/pile.svg" | sort -u | wc -l)
	[ "$n" -eq 5000 ] && [ "$d" -eq 5000 ] && ok ||
	    no "a pile of 5000 labelled records: $n labels at $d places"
else
	no "a pile of 5000 labelled records: exit $?: $(head -2 "$T/err")"
fi

# ---- issue 27: loftplot -i writes the page (the browser drives it in
# tests/browser); here, what the file holds, without a browser
if [ -s bin/wasm/loft.wasm ]; then
	printf 'points name=</script><b>x\n0 0\n1 0\n1 1\n0 1\n' >"$T/k"
	printf 'points\n0 0\nfoo\n\ncubic\n1 2 3\n' >"$T/bad"
	"$B/splinefit" "$T/k" | "$B/loftplot" -i -K "$T/k" - "$T/bad" \
	    >"$T/page.html" 2>"$T/err"
	rc=$?
	[ "$rc" -eq 1 ] && grep -q 'bad:' "$T/err" && ok ||
	    no "loftplot -i with bad records: exit $rc, want 1; $(cat "$T/err")"
	n=$(grep -c '</script>' "$T/page.html")
	[ "$n" -eq 2 ] && grep -q '^<!DOCTYPE html>' "$T/page.html" &&
	    [ "$(tail -n 1 "$T/page.html")" = '</html>' ] && ok ||
	    no "loftplot -i: $n </script> in the page, want 2 (data, code)"
	grep -q 'name=\\u003c/script>\\u003cb>x' "$T/page.html" && ok ||
	    no "loftplot -i: the record's < not escaped in the page's data"
	# the module is all there: its base64 decodes to the file's bytes
	sed -n 's/^"module": "\([^"]*\)"}$/\1/p' "$T/page.html" >"$T/b64"
	if command -v base64 >/dev/null 2>&1; then
		base64 -d "$T/b64" | cmp -s - bin/wasm/loft.wasm && ok ||
		    no "loftplot -i: the page's module is not bin/wasm/loft.wasm"
	fi
else
	echo "skip: loftplot -i's page (no WebAssembly module)"
fi

echo "loftplot: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
