#!/bin/sh
# fromcad.sh: fromcad on small DXF, SVG and CSV documents written here,
# against numbers derived by hand in the comments (or, where ezdxf is
# installed, the numbers given to ezdxf and its own Bezier
# decomposition); and the hostile documents of tests/bad.sh's kind,
# which fromcad's whole-document reading does not fit.  Run from the top
# of the tree; the last line is "fromcad: N passed, M failed".

T=bin/test/fromcad
. tests/lib.sh

F="$B/fromcad"

# near FILE TOL: stdout has the records of FILE, headers the same and
# every number within TOL (relative to 1 + |want|)
near() {
	awk -v tol="$2" -v what="$what" '
	FNR == 1 { f++ }
	f == 1 { want[++nw] = $0; next }
	{ got[++ng] = $0 }
	END {
		if (nw != ng) { printf "%s: %d lines, want %d\n", what, ng, nw; exit 1 }
		for (i = 1; i <= nw; i++) {
			n = split(want[i], a); m = split(got[i], b)
			if (n != m) { printf "%s: line %d is \"%s\", want \"%s\"\n", what, i, got[i], want[i]; exit 1 }
			for (k = 1; k <= n; k++) {
				if (a[k] ~ /^[a-z]/) {
					if (a[k] != b[k]) { printf "%s: line %d: %s, want %s\n", what, i, b[k], a[k]; exit 1 }
					continue
				}
				d = a[k] - b[k]; if (d < 0) d = -d
				s = a[k] < 0 ? -a[k] : a[k]
				if (d > tol * (1 + s)) { printf "%s: line %d: %s, want %s\n", what, i, b[k], a[k]; exit 1 }
			}
		}
	}' "$1" "$T/out" >"$T/near" && ok || no "$(cat "$T/near")"
}

# dxf FILE: a DXF of the groups on standard input (one "code value" a
# line) in an ENTITIES section, with $INSUNITS=$UNITS when set
dxf() {
	awk -v units="$UNITS" 'BEGIN {
		printf "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1027\n"
		if (units != "") printf "9\n$INSUNITS\n70\n%s\n", units
		printf "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
	}
	NF { c = $1; sub(/^[ \t]*[-0-9]+[ \t]?/, ""); printf "%s\n%s\n", c, $0 }
	END { printf "0\nENDSEC\n0\nEOF\n" }' >"$1"
}

svg() {         # svg FILE BODY: an SVG 100 mm square, 1 mm a user unit
	printf '<?xml version="1.0"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">\n%s\n</svg>\n' "$2" >"$1"
}

usage_ok fromcad
fails 2 "-f 'dwg': want dxf, svg, csv, step or iges" "$F -f dwg /dev/null"
fails 2 "-t" "$F -t 0 /dev/null"
fails 2 "-p '18'" "$F -p 18 /dev/null"

# ---- SVG ------------------------------------------------------------
# A cubic with control points b0 (0,0) b1 (1,0) b2 (2,1) b3 (2,2): the
# Hermite row is P_A = b0, P_B = b3, P'_A = 3(b1 - b0) = (3,0),
# P'_B = 3(b3 - b2) = (0,3); y turned up negates every y.
svg "$T/c.svg" '<path d="M0 0 C1 0 2 1 2 2"/>'
run "$F $T/c.svg"
status 0
out_is "cubic closed=0
0 0 2 -2 3 0 0 -3
"
# The same in relative commands with implicit repeats and SVG's number
# syntax: c1,0 2,1 2,2 repeated once more from (2,2): b1 (3,2), b2
# (4,3), b3 (4,4); "1.5.5" is 1.5 .5.
svg "$T/rel.svg" '<path d="m0,0c1,0,2,1,2,2 1 0 2 1 2 2L1.5.5"/>'
run "$F $T/rel.svg"
out_is "cubic closed=0
0 0 2 -2 3 0 0 -3
2 -2 4 -4 3 0 0 -3
4 -4 1.5 -0.5 -2.5 3.5 -2.5 3.5
"
# S reflects the last control point: after C1 0 2 1 2 2, S's first
# control is 2 (2,2) - (2,1) = (2,3); S 3 4 4 4: b = (2,2) (2,3) (3,4)
# (4,4): P'_A = (0,3), P'_B = (3,0).  Q 5 4 6 6 from (4,4): P'_A =
# 2((5,4) - (4,4)) = (2,0), P'_B = 2((6,6) - (5,4)) = (2,4); T 8 8
# reflects (5,4) about (6,6) to (7,8): P'_A = (2,4), P'_B = (2,0).
svg "$T/sq.svg" '<path d="M0 0C1 0 2 1 2 2S3 4 4 4Q5 4 6 6T8 8"/>'
run "$F $T/sq.svg"
out_is "cubic closed=0
0 0 2 -2 3 0 0 -3
2 -2 4 -4 0 -3 3 0
4 -4 6 -6 2 0 2 -4
6 -6 8 -8 2 -4 2 0
"
# Straight segments only: a knot record; H and V, and Z closes it
# without repeating the start; each subpath is a record; e-notation.
svg "$T/lines.svg" '<path id="sq" d="M1 1H3V2h-2z m5e0 0 l1e-3 0"/>'
run "$F $T/lines.svg"
out_is "points closed=1 name=sq
1 -1
3 -1
3 -2
1 -2

points closed=0 name=sq
6 -1
6.001 -1
"
# polyline, polygon (its last point repeating the first is dropped),
# line, and rect (corners marked)
svg "$T/poly.svg" '<polyline points="0,0 1,0 1,1"/><polygon points="0 0 2 0 2 2 0 0"/><line x1="1" y1="2" x2="3" y2="4"/><rect x="1" y="2" width="3" height="4"/>'
run "$F $T/poly.svg"
out_is "points closed=0
0 0
1 0
1 -1

points closed=1
0 0
2 0
2 -2

points closed=0
1 -2
3 -4

points closed=1 corners=1,2,3,4
1 -2
4 -2
4 -6
1 -6
"
# A transform stack applied by hand: the point (1,0) and (1,1) under
# rotate(90) (x,y) -> (-y,x): (0,1) (-1,1); scale(2): (0,2) (-2,2);
# translate(1,2): (1,4) (-1,4); matrix(1 0 0 1 10 0) on the outer g:
# (11,4) (9,4); turned up: (11,-4) (9,-4).
svg "$T/tr.svg" '<g transform="matrix(1 0 0 1 10 0)"><g transform="translate(1,2)"><g transform="scale(2)"><path transform="rotate(90)" d="M1 0L1 1"/></g></g></g>'
run "$F $T/tr.svg"
out_is "points closed=0
11 -4
9 -4
"
# rotate about a point, skewX, skewY: rotate(90 1 1) takes (2,1) to
# (1,2); skewX(45) (x,y) -> (x + y, y): (1,2) -> (3,2); skewY(45)
# (x,y) -> (x, y + x): (3,2) -> (3,5).  tan(45 degrees) is 1 within
# rounding.
svg "$T/sk.svg" '<g transform="skewY(45)"><g transform="skewX(45)"><path transform="rotate(90 1 1)" d="M2 1 L2 1"/></g></g>'
run "$F $T/sk.svg"
printf 'points closed=0\n3 -5\n3 -5\n\n' >"$T/sk.want"
near "$T/sk.want" 1e-15
# A tangent goes through the linear part only: C under translate(5,0)
# keeps P'_A = (3,0).
svg "$T/tt.svg" '<path transform="translate(5 0) scale(1,2)" d="M0 0 C1 0 2 1 2 2"/>'
run "$F $T/tt.svg"
out_is "cubic closed=0
5 0 7 -4 3 0 0 -6
"
# Units: 1 in = 25.4 mm, 72 pt to the inch, 96 px; no width: px.  The
# point (1,1) of a viewBox one unit wide of width 1in is at 25.4 mm.
for u in "1in 1 25.4" "72pt 72 25.4" "96px 96 25.4" "96 96 25.4" "2.54cm 1 25.4" "25.4mm 1 25.4"; do
	set -- $u
	printf '<svg width="%s" height="%s" viewBox="0 0 %s %s"><path d="M%s %s L0 0"/></svg>' \
	    "$1" "$1" "$2" "$2" "$2" "$2" >"$T/u.svg"
	run "$F $T/u.svg"
	printf 'points closed=0\n%s -%s\n0 0\n\n' "$3" "$3" >"$T/u.want"
	near "$T/u.want" 1e-15
done
printf '<svg><path d="M96 0 L0 96"/></svg>' >"$T/px.svg"
run "$F $T/px.svg"
printf 'points closed=0\n25.4 0\n0 -25.4\n\n' >"$T/u.want"
near "$T/u.want" 1e-15
# preserveAspectRatio: a 200 by 100 mm box over a square viewBox meets
# at the smaller scale, 1 mm a unit; slice at 2; none keeps both.
for u in "meet 100 -100" "slice 200 -200" "none 200 -100"; do
	set -- $u
	printf '<svg width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="xMidYMid %s"><path d="M100 100 L0 0"/></svg>' \
	    "$1" | sed 's/xMidYMid none/none/' >"$T/par.svg"
	run "$F $T/par.svg"
	printf 'points closed=0\n%s %s\n0 0\n\n' "$2" "$3" >"$T/u.want"
	near "$T/u.want" 1e-15
done

# Arcs: every point of the cubics that replace an arc lies within the
# tolerance of the circle (here radius 10 about (10,0), turned up: the
# centre stays (10,0)); by default 1e-4 of the radius.  sample -n 64
# gives the points; the distance from the centre is the check.
onarc() {       # onarc R CX CY TOL: every point of $T/pts within TOL of the circle
	awk -v r="$1" -v cx="$2" -v cy="$3" -v tol="$4" -v what="$what" '
	NF { d = sqrt(($1 - cx)^2 + ($2 - cy)^2) - r; if (d < 0) d = -d
	     if (d > m) m = d; n++ }
	END { if (n < 10 || m > tol) { printf "%s: %d points, %g off the arc, want <= %g\n", what, n, m, tol; exit 1 } }' "$T/pts" >"$T/near" &&
	    ok || no "$(cat "$T/near")"
}
svg "$T/arc.svg" '<path d="M0 0 A10 10 0 0 1 20 0 A10 10 0 1 1 0 0"/>'
run "$F $T/arc.svg"
status 0
$B/sample -n 64 "$T/out" >"$T/pts"
onarc 10 10 0 1e-3
what="arc within 1e-4 r, not merely 1e-3"
onarc 10 10 0 1e-3
run "$F -t 1e-7 $T/arc.svg"
$B/sample -n 64 "$T/out" >"$T/pts"
what="arc -t 1e-7"
onarc 10 10 0 1e-7
# the same arc 1000 times larger has as many pieces (the default is
# relative to the radius), each 1000 times as large
svg "$T/arc2.svg" '<path d="M0 0 A10000 10000 0 0 1 20000 0 A10000 10000 0 1 1 0 0"/>'
$F "$T/arc.svg" | awk 'NF > 2 { l = ""; for (i = 1; i <= NF; i++) l = l sprintf("%s%.17g", i > 1 ? " " : "", $i * 1000); $0 = l } { print }' >"$T/arc1000"
run "$F $T/arc2.svg"
near "$T/arc1000" 1e-12
# an ellipse's arc rotated 30 degrees: points on the ellipse, checked in
# its own frame: ((x-cx)c + (y-cy)s)^2/rx^2 + (-(x-cx)s + (y-cy)c)^2/ry^2 = 1
svg "$T/ell.svg" '<ellipse cx="5" cy="5" rx="4" ry="2" transform="rotate(30 5 5)"/>'
run "$F $T/ell.svg"
out_is_cubic() { head -1 "$T/out" | grep -q "^cubic closed=1" && ok || no "$what: $(head -1 "$T/out")"; }
out_is_cubic
$B/sample -n 32 "$T/out" >"$T/pts"
awk -v what="ellipse" 'NF { x = $1 - 5; y = -$2 - 5; c = cos(atan2(1, 1) * 4 / 6); s = sin(atan2(1, 1) * 4 / 6)
	u = x * c + y * s; v = -x * s + y * c; e = sqrt(u * u / 16 + v * v / 4) - 1; if (e < 0) e = -e; if (e > m) m = e }
	END { if (m > 1e-4) { printf "%s: %g off\n", what, m; exit 1 } }' "$T/pts" >"$T/near" && ok || no "$(cat "$T/near")"

# Layers: an Inkscape layer's label, encoded; an element's id as name=
printf '<svg xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"><g inkscape:groupmode="layer" inkscape:label="Cut line #1"><g id="inner"><path id="p1" d="M0 0L96 0"/></g></g></svg>' >"$T/layer.svg"
run "$F $T/layer.svg"
out_is "points closed=0 layer=Cut%20line%20%231 name=p1
0 0
25.4 0
"

# An Inkscape document: DOCTYPE with an internal subset, namedview,
# defs, metadata passed over; the layer's translate(-10,-20) takes
# m 20,30 to (10,10), the end 20,20 further to (30,30); turned up.
# P'_A = 3(10,0), P'_B = 3((40,50) - (40,40)) = (0,30), y negated.
cat >"$T/ink.svg" <<'EOF'
<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<!-- Created with Inkscape (http://www.inkscape.org/) -->
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
  <!ENTITY ns "http://www.w3.org/2000/svg">
]>
<svg
   width="210mm"
   height="297mm"
   viewBox="0 0 210 297"
   version="1.1"
   id="svg1"
   inkscape:version="1.2 (dc2aedaf03, 2022-05-15)"
   sodipodi:docname="pattern.svg"
   xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
   xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
   xmlns="http://www.w3.org/2000/svg"
   xmlns:svg="http://www.w3.org/2000/svg">
  <sodipodi:namedview id="namedview7" pagecolor="#ffffff" inkscape:document-units="mm" />
  <defs id="defs2"><linearGradient id="g1"><stop offset="0" style="stop-color:#000"/></linearGradient></defs>
  <metadata><rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"><cc:Work/></rdf:RDF></metadata>
  <g
     inkscape:label="Layer 1"
     inkscape:groupmode="layer"
     id="layer1"
     transform="translate(-10,-20)">
    <path
       style="fill:none;stroke:#000000;stroke-width:0.264583"
       d="m 20,30 c 10,0 20,10 20,20"
       id="path1"
       sodipodi:nodetypes="cc" />
  </g>
</svg>
EOF
run "$F $T/ink.svg"
status 0
out_is "cubic closed=0 layer=Layer%201 name=path1
10 -10 30 -30 30 0 0 -30
"

# ---- SVG that cannot be read whole, or is passed over ----------------
svg "$T/text.svg" '<path d="M0 0L1 0"/>
<text x="0" y="0">label</text>
<image href="x.png"/>
<path d="M0 0L2 0"/>'
# text and image are passed over with one note, exit 0; -S refuses them
run "$F $T/text.svg"
status 0
says "text.svg: 1 text, 1 image passed over (annotations and elements loft does not know; -S makes them errors)"
out_is "points closed=0
0 0
1 0

points closed=0
0 0
2 0
"
run "$F -S $T/text.svg"
status 1
says "text.svg:4: text: an annotation or an element loft does not know: not read (-S)"
says "text.svg:5: image: an annotation or an element loft does not know: not read (-S)"
svg "$T/badpath.svg" '<path d="M0 0L1 0"/>
<path id="b" d="M0 0 L1 x"/>
<path d="M0 0 L3 0"/>'
run "$F $T/badpath.svg"
status 1
says "badpath.svg:4: path id=b: bad path data at 'x'"
out_is "points closed=0
0 0
1 0

points closed=0
0 0
3 0
"
svg "$T/nan.svg" '<path d="M0 0Lnan 0"/><path d="M1e999 0L0 0"/><polyline points="1 2 3"/>'
run "$F $T/nan.svg"
status 1
[ "$(grep -c 'not read' "$T/err")" = 3 ] && ok || no "nan.svg: want 3 messages: $(cat "$T/err")"
out_empty
# A huge coordinate whose scaled value overflows
printf '<svg width="100in" viewBox="0 0 1 1"><path d="M1e307 0L0 0"/><path d="M1 0L0 0"/></svg>' >"$T/huge.svg"
run "$F $T/huge.svg"
status 1
says "result is not finite"
out_is "points closed=0
2540 0
0 0
"
# Truncated: what was read before is written, and the cut is named.
head -c 150 "$T/text.svg" >"$T/cut.svg"
run "$F $T/cut.svg"
status 1
says "truncated?"
# Deep nesting: 300 groups; what lies deeper than 256 is not read, with
# one message; the path beside them is read.
awk 'BEGIN { printf "<svg>"; for (i = 0; i < 300; i++) printf "<g>"; printf "<path d=\"M0 0L1 1\"/>";
	for (i = 0; i < 300; i++) printf "</g>"; printf "<path d=\"M0 0L96 0\"/></svg>\n" }' >"$T/deep.svg"
run "$F $T/deep.svg"
status 1
[ "$(wc -l <"$T/err")" = 1 ] && ok || no "deep.svg: want one message: $(head -3 "$T/err")"
says "nested deeper than 256"
out_is "points closed=0
0 0
25.4 0
"
# A path of 10^6 segments (and 10^5) read whole: every segment a row.
# (Its time, linear in the segments, is make bench's case fromcad-path;
# make check-valgrind asks for fewer through LOFT_BIG_KNOTS.)
BIG=${LOFT_BIG_KNOTS:-1000000}
SMALL=$((BIG / 10))
for n in $SMALL $BIG; do
	awk -v n=$n 'BEGIN { printf "<svg><path d=\"M0 0"; for (i = 0; i < n; i++) printf "c1 0 1 1 1 1"; printf "\"/></svg>\n" }' >"$T/long$n.svg"
done
$F "$T/long$SMALL.svg" | wc -l >"$T/nsmall"
$F "$T/long$BIG.svg" | wc -l >"$T/nbig"
[ "$(cat "$T/nsmall")" = $((SMALL + 2)) ] && [ "$(cat "$T/nbig")" = $((BIG + 2)) ] && ok ||
    no "long paths: $(cat "$T/nsmall") and $(cat "$T/nbig") lines"
rm -f "$T"/long*.svg
# Text quoted in a message keeps the message one line (found by fuzzing)
printf '<svg><path d="M0 0 L1 0 L\n\001x"/></svg>' >"$T/ctl.svg"
run "$F $T/ctl.svg"
status 1
says "ctl.svg:2: path: bad path data at '?x': drawn up to there, as SVG renders it"
[ "$(wc -l <"$T/err")" = 1 ] && ok || no "ctl.svg: message of more lines: $(cat "$T/err")"
# Garbage and binary bytes: a message, nothing written, exit 1
printf '<\001\002\377garbage' >"$T/garbage.svg"
fails 1 "malformed XML" "$F $T/garbage.svg"
printf '<html><body/></html>' >"$T/html.svg"
fails 1 "the root element is not svg" "$F $T/html.svg"

# ---- DXF --------------------------------------------------------------
# $INSUNITS 1 (inches): every coordinate times 25.4, as awk multiplies.
UNITS=1 dxf "$T/in.dxf" <<'EOF'
0 LINE
5 1F
8 0
10 1
20 2
30 0
11 3.5
21 -0.1
31 0
EOF
run "$F $T/in.dxf"
status 0
awk 'BEGIN { printf "points closed=0 layer=0\n%.17g %.17g\n%.17g %.17g\n\n", 1 * 25.4, 2 * 25.4, 3.5 * 25.4, -0.1 * 25.4 }' >"$T/in.want"
near "$T/in.want" 0
# centimetres, and no $INSUNITS: numbers kept
UNITS=5 dxf "$T/cm.dxf" <<'EOF'
0 LINE
10 1
20 2
11 3
21 4
EOF
run "$F $T/cm.dxf"
out_is "points closed=0
10 20
30 40
"
dxf "$T/none.dxf" <<'EOF'
0 LINE
10 1
20 2
11 3
21 4
EOF
run "$F $T/none.dxf"
out_is "points closed=0
1 2
3 4
"
# A cubic SPLINE of knots 0 0 0 0 1 2 2 2 2 and control points P0..P4
# (0,0) (1,2) (3,3) (5,1) (6,0).  Inserting knot 1 twice (Boehm, by
# hand): a = 1/2 each time, so Q2 = (P1+P2)/2 = (2,2.5), Q3 = (P2+P3)/2
# = (4,2), then R = (Q2+Q3)/2 = (3,2.25): pieces (0,0) (1,2) (2,2.5)
# (3,2.25) and (3,2.25) (4,2) (5,1) (6,0).  Hermite rows: P'_A = 3(b1 -
# b0), P'_B = 3(b3 - b2).
dxf "$T/spl.dxf" <<'EOF'
0 SPLINE
5 2A
8 curves
70 8
71 3
72 9
73 5
74 0
40 0
40 0
40 0
40 0
40 1
40 2
40 2
40 2
40 2
10 0
20 0
30 0
10 1
20 2
30 0
10 3
20 3
30 0
10 5
20 1
30 0
10 6
20 0
30 0
EOF
run "$F $T/spl.dxf"
status 0
out_is "cubic closed=0 layer=curves
0 0 3 2.25 3 6 3 -0.75
3 2.25 6 0 3 -0.75 3 -3
"
# The knots scaled and shifted (10 12 14 for 0 1 2) make the same curve.
sed 's/^40 0$/40 10/; s/^40 1$/40 12/; s/^40 2$/40 14/' "$T/spl.dxf" >/dev/null
awk 'prev == "40" { $0 = ($0 == "0" ? "10" : $0 == "1" ? "12" : $0 == "2" ? "14" : $0) } { print; prev = $0 }' "$T/spl.dxf" >"$T/spl2.dxf"
run "$F $T/spl2.dxf"
out_is "cubic closed=0 layer=curves
0 0 3 2.25 3 6 3 -0.75
3 2.25 6 0 3 -0.75 3 -3
"
# Unequal knot spans: knots 0 0 0 0 1 3 3 3 3, the same control points:
# inserting 1: a2 = (1-0)/(3-0) = 1/3, a3 = 1/3: Q2 = (2P1+P2)/3 =
# (5/3, 7/3), Q3 = (2P2+P3)/3 = (11/3, 7/3); again: a = (1-0)/(3-0) =
# 1/3, R = (2Q2+Q3)/3 = (7/3, 7/3).  Rows checked to 1e-15.
awk 'prev == "40" && $0 == "2" { $0 = "3" } { print; prev = $0 }' "$T/spl.dxf" >"$T/spl3.dxf"
run "$F $T/spl3.dxf"
awk 'BEGIN { printf "cubic closed=0 layer=curves\n"
	printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", 0, 0, 7/3, 7/3, 3, 6, 3 * (7/3 - 5/3), 3 * (7/3 - 7/3)
	printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n\n", 7/3, 7/3, 6, 0, 3 * (11/3 - 7/3), 3 * (7/3 - 7/3), 3, -3 }' >"$T/spl3.want"
near "$T/spl3.want" 1e-15
# Unclamped: the uniform cubic B-spline of knots 0..7 and control
# points (0,0) (6,0) (6,6) (0,6) is one piece over [3,4], whose Bezier
# points are the textbook (P0 + 4P1 + P2)/6 = (5,1), (2P1 + P2)/3 =
# (6,2), (P1 + 2P2)/3 = (6,4), (P1 + 4P2 + P3)/6 = (5,5): the row
# (5,1) (5,5) 3(1,1) 3(-1,1).
{ printf '0 SPLINE\n71 3\n'; for k in 0 1 2 3 4 5 6 7; do echo "40 $k"; done
  printf '10 0\n20 0\n10 6\n20 0\n10 6\n20 6\n10 0\n20 6\n'; } | dxf "$T/uni.dxf"
run "$F $T/uni.dxf"
printf 'cubic closed=0\n5 1 5 5 3 3 -3 3\n\n' >"$T/uni.want"
near "$T/uni.want" 1e-14
# Degree 2, one piece (knots 0 0 0 1 1 1): raised to a cubic exactly,
# P'_A = 2(b1 - b0) = (2,4), P'_B = 2(b2 - b1) = (2,-4).
dxf "$T/q.dxf" <<'EOF'
0 SPLINE
71 2
40 0
40 0
40 0
40 1
40 1
40 1
10 0
20 0
10 1
20 2
10 2
20 0
EOF
run "$F $T/q.dxf"
out_is "cubic closed=0
0 0 2 0 2 4 2 -4
"
# Degree 4, one piece: a bezier record of its control points
printf '0 SPLINE\n71 4\n' >"$T/d4"
for k in 0 0 0 0 0 1 1 1 1 1; do echo "40 $k"; done >>"$T/d4"
for p in "0 0" "1 1" "2 0" "3 1" "4 0"; do set -- $p; printf '10 %s\n20 %s\n30 1\n' "$1" "$2"; done >>"$T/d4"
dxf "$T/d4.dxf" <"$T/d4"
run "$F $T/d4.dxf"
out_is "bezier piece=1
0 0 1
1 1 1
2 0 1
3 1 1
4 0 1
"
# A SPLINE by fit points: a knot record with its end tangents
dxf "$T/fit.dxf" <<'EOF'
0 SPLINE
8 3
71 3
74 3
12 1
22 0
32 0
13 0
23 -1
33 0
11 0
21 0
11 5
21 5
11 10
21 0
EOF
run "$F $T/fit.dxf"
out_is "points closed=0 layer=3 start=1,0 end=0,-1
0 0
5 5
10 0
"
# A rational SPLINE: the quarter of the unit circle, degree 2, weights
# 1, sqrt(2)/2, 1 -- cubic pieces from (1,0) to (0,1) whose points are
# within the tolerance of radius 1: by default 10^-4 of half the extent
# of the control points (sqrt 2 / 2 * 10^-4), or -t
printf '%s\n' '0 SPLINE' '5 BEEF' '8 0' '71 2' '40 0' '40 0' '40 0' '40 1' \
    '40 1' '40 1' '41 1' '41 0.7071067811865476' '41 1' '10 1' '20 0' \
    '10 1' '20 1' '10 0' '20 1' | dxf "$T/rat.dxf"
for t in "" 1e-10; do
	run "$F ${t:+-t $t} $T/rat.dxf"
	status 0
	awk -v tol="${t:-7.0711e-5}" -v what="rational $t" 'NR == 1 { next } NF == 8 {
		if (NR == 2 && ($1 != 1 || $2 != 0)) bad = "start " $1 " " $2
		ex = $3; ey = $4; n++
		for (s = 0.125; s < 1; s += 0.125) {
			u = 1 - s
			x = u*u*(1+2*s)*$1 + s*s*(3-2*s)*$3 + s*u*u*$5 - s*s*u*$7
			y = u*u*(1+2*s)*$2 + s*s*(3-2*s)*$4 + s*u*u*$6 - s*s*u*$8
			d = sqrt(x*x + y*y) - 1; if (d < 0) d = -d; if (d > m) m = d
		} }
	END { if (ex != 0 || ey != 1) bad = "end " ex " " ey
		if (m > tol) bad = sprintf("%g off the circle", m)
		if (bad != "") { printf "%s: %s\n", what, bad; exit 1 } }' "$T/out" >"$T/near" &&
	    ok || no "$(cat "$T/near")"
done
# weights of 0 are refused, with the handle and line
printf '%s\n' '0 SPLINE' '5 BEEF' '71 1' '40 0' '40 0' '40 1' '40 1' \
    '41 1' '41 0' '10 0' '20 0' '10 1' '20 0' | dxf "$T/rat0.dxf"
fails 1 "rat0.dxf:15: SPLINE (handle BEEF): its weights are not all above 0" "$F $T/rat0.dxf"

# An ASTM D6673 pattern: boundary on layer 1, turn points on layer 2 at
# its vertices 2 and 4, one POINT on layer 2 at no vertex (kept), and a
# curve point on layer 3 (kept).
dxf "$T/d6673.dxf" <<'EOF'
0 POINT
8 2
10 10
20 0
0 LWPOLYLINE
5 10
8 1
90 5
70 1
10 0
20 0
10 10
20 0
10 10
20 10
10 5
20 15
10 0
20 10
0 POINT
8 2
10 0
20 10
0 POINT
8 2
10 50
20 50
0 POINT
8 3
10 5
20 15
EOF
run "$F $T/d6673.dxf"
status 0
out_is "points closed=1 layer=1 corners=2,5
0 0
10 0
10 10
5 15
0 10

points layer=2
50 50

points layer=3
5 15
"
# POLYLINE, VERTEX, SEQEND (R12), closed, and a 3-D polyline
dxf "$T/poly.dxf" <<'EOF'
0 POLYLINE
8 1
66 1
70 1
10 0
20 0
30 0
0 VERTEX
8 1
10 1
20 2
0 VERTEX
8 1
10 3
20 4
0 VERTEX
8 1
10 5
20 0
0 SEQEND
0 POLYLINE
70 8
0 VERTEX
70 32
10 1
20 2
30 3
0 VERTEX
70 32
10 4
20 5
30 6
0 SEQEND
EOF
run "$F $T/poly.dxf"
out_is "points closed=1 layer=1
1 2
3 4
5 0

points closed=0
1 2 3
4 5 6
"
# A bulge of 1 is a half circle, counter-clockwise: from (0,0) to
# (10,0) about (5,0) through (5,-5).  Every knot lies on the circle, and
# the middle of every chord within 1e-4 r of it; the knots turn
# counter-clockwise (y falls first).
dxf "$T/bulge.dxf" <<'EOF'
0 LWPOLYLINE
90 2
10 0
20 0
42 1
10 10
20 0
EOF
run "$F $T/bulge.dxf"
status 0
awk -v what=bulge 'NR == 1 { next } NF == 2 {
	d = sqrt(($1 - 5)^2 + $2^2) - 5; if (d < 0) d = -d; if (d > m) m = d
	if (n) { mx = (px + $1) / 2; my = (py + $2) / 2; s = 5 - sqrt((mx - 5)^2 + my^2); if (s > sm) sm = s }
	if (n == 1 && $2 >= 0) bad = 1; px = $1; py = $2; n++ }
	END { if (m > 1e-12 || sm > 5e-4 || sm < 1e-4 || bad || n < 10 || px != 10 || py != 0) { printf "%s: %d knots, %g off, chords %g off\n", what, n, m, sm; exit 1 } }' "$T/out" >"$T/near" &&
    ok || no "$(cat "$T/near")"
# The same half circle 1000 times smaller: as many knots, each 1000
# times nearer the origin (the tolerance is relative to the radius)
awk 'prev == "10" || prev == "20" { $0 = $0 / 1000 } { print; prev = $0 }' "$T/bulge.dxf" >"$T/bulge3.dxf"
awk 'NF == 2 { $0 = sprintf("%.17g %.17g", $1 / 1000, $2 / 1000) } { print }' "$T/out" >"$T/bulge3.want"
run "$F $T/bulge3.dxf"
near "$T/bulge3.want" 1e-12
# An extrusion direction (0,0,-1): the OCS x axis is -x in the world
dxf "$T/ocs.dxf" <<'EOF'
0 LWPOLYLINE
90 2
210 0
220 0
230 -1
10 1
20 2
10 3
20 4
EOF
run "$F $T/ocs.dxf"
out_is "points closed=0
-1 2
-3 4
"
# ARC and CIRCLE: chords of the circle, knots on it
dxf "$T/arc.dxf" <<'EOF'
0 ARC
10 1
20 1
40 2
50 0
51 90
0 CIRCLE
10 0
20 0
40 3
EOF
run "$F $T/arc.dxf"
status 0
awk -v what=arcs '/^points/ { r = ++rec == 1 ? 2 : 3; cx = cy = rec == 1 ? 1 : 0; next } NF == 2 {
	d = sqrt(($1 - cx)^2 + ($2 - cy)^2) - r; if (d < 0) d = -d; if (d > m) m = d; n[rec]++ }
	END { if (m > 1e-12 || n[1] < 10 || n[2] < 40) { printf "%s: %g off, %d and %d knots\n", what, m, n[1], n[2]; exit 1 } }' "$T/out" >"$T/near" &&
    ok || no "$(cat "$T/near")"

# ---- DXF that cannot be read whole ------------------------------------
# TEXT, ATTRIB and HATCH are passed over with one note; an INSERT of
# no block is a message with the handle and the line; the rest is read
dxf "$T/text.dxf" <<'EOF'
0 TEXT
5 3A
1 hello
0 INSERT
5 3B
66 1
0 ATTRIB
0 SEQEND
0 HATCH
5 3C
0 LINE
10 0
20 0
11 1
21 1
EOF
run "$F $T/text.dxf"
status 1
says "text.dxf:21: INSERT (handle 3B): no block of its name"
says "text.dxf: 1 TEXT, 1 ATTRIB, 1 HATCH passed over (annotations, fills and empty arcs; -S makes them errors)"
[ "$(wc -l <"$T/err")" = 2 ] && ok || no "text.dxf: want 2 messages: $(cat "$T/err")"
run "$F -S $T/text.dxf"
status 1
says "text.dxf:15: TEXT (handle 3A): an annotation or a fill: not read (-S)"
says "text.dxf:31: HATCH (handle 3C): an annotation or a fill: not read (-S)"
[ "$(wc -l <"$T/err")" = 4 ] && ok || no "text.dxf -S: want 4 messages: $(cat "$T/err")"
out_is "points closed=0
0 0
1 1
"
# A coordinate that is no number (NaN, garbage, out of range): that
# entity alone is not read
dxf "$T/nan.dxf" <<'EOF'
0 LINE
10 nan
20 0
11 1
21 1
0 LINE
10 1e999
20 0
11 1
21 1
0 LINE
10 0x10
20 0
11 1
21 1
0 LINE
10 0
20 0
11 2
21 2
EOF
run "$F $T/nan.dxf"
status 1
[ "$(grep -c 'is not a finite number' "$T/err")" = 3 ] && ok || no "nan.dxf: $(cat "$T/err")"
says "nan.dxf:15: LINE: group 10 'nan' is not a finite number (line 17)"
out_is "points closed=0
0 0
2 2
"
# Huge coordinates: in inches they overflow
UNITS=1 dxf "$T/huge.dxf" <<'EOF'
0 LINE
10 1e308
20 0
11 1
21 1
0 LINE
10 0
20 0
11 1
21 0
EOF
run "$F $T/huge.dxf"
status 1
says "huge.dxf:19: result is not finite"
out_is "points closed=0
0 0
25.4 0
"
# Truncated inside an LWPOLYLINE: the LINE before it is written, the
# polyline named, not read
head -n 38 "$T/d6673.dxf" >"$T/trunc.dxf"
run "$F $T/trunc.dxf"
status 1
says "LWPOLYLINE (handle 10): the file ends inside it"
says "the file ends without an EOF group"
out_is "points layer=2
10 0
"
# group 90 says more vertices than there are
sed 's/^5$/6/' "$T/d6673.dxf" >/dev/null
awk 'prev == "90" { $0 = 7 } { print; prev = $0 }' "$T/d6673.dxf" >"$T/n90.dxf"
run "$F $T/n90.dxf"
status 1
says "group 90 says 7 vertices; it has 5"
# A bad group code, and a POLYLINE with no SEQEND
printf '0\nSECTION\n2\nENTITIES\n0\nLINE\nten\n1\n0\nPOLYLINE\n0\nVERTEX\n10\n1\n20\n1\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n0\nENDSEC\n0\nEOF\n' >"$T/code.dxf"
run "$F $T/code.dxf"
status 1
says "code.dxf:7: 'ten' is not a group code"
says "code.dxf:9: POLYLINE: no SEQEND ends its vertices"
out_is "points closed=0
0 0
1 1
"
# Binary DXF: its sentinel is recognised
printf 'AutoCAD Binary DXF\r\n\032\000\000\000' >"$T/bin.dxf"
fails 1 "bin.dxf:1: a binary DXF" "$F $T/bin.dxf"
fails 1 "bin.dxf:1: a binary DXF" "$F -f dxf $T/bin.dxf"

# ---- CSV --------------------------------------------------------------
# columns in any order, an extra column passed over, quotes, CRLF, two
# records, the header repeated over the second
printf 'name,y,"X"\r\na,2,1\r\nb,4,3\r\n\r\nname,y,"X"\r\nc,6,5\r\n' >"$T/a.csv"
run "$F $T/a.csv"
status 0
out_is "1 2
3 4

5 6
"
printf 'x;y;z\n1;2;3\n4;5;6\n' >"$T/z.csv"
run "$F $T/z.csv"
out_is "1 2 3
4 5 6
"
printf 'x,y\n1,2\n3,nan\n\n5,6\n7\n\n8,9\n' >"$T/bad.csv"
run "$F $T/bad.csv"
status 1
says "bad.csv:3: y 'nan' is not a finite number"
says "bad.csv:6: the row has no column y"
out_is "8 9
"
# a bad last row with no line end after it (found by fuzzing)
printf 'x,y\n1,2\n3' >"$T/badend.csv"
fails 1 "badend.csv:3: the row has no column y" "$F $T/badend.csv"
printf 'a,b\n1,2\n' >"$T/nohdr.csv"
fails 1 "nohdr.csv:1: the header line names no x and y" "$F -f csv $T/nohdr.csv"
# CSV as spreadsheets write it (issues 24, 28): RFC 4180 quotes holding
# separators, doubled quotes and a line end; extra fields an error, not
# passed over; units honoured (reference: 1 in = 25.4 mm, 1 cm = 10 mm);
# decimal commas with ';'; Excel's sep= line; trailing empty columns
# and rows; a byte order mark
csv() { printf "$1" >"$T/c.csv"; run "$F $T/c.csv"; }
csv 'label,x,y\n"Smith, J",5,5\n'
status 0
out_is "5 5
"
csv 'x,y\n1,5,2,5\n'
status 1
says "c.csv:2: the row has 4 fields and the header 2"
out_empty
csv 'name,x,y\n"a ""quoted""\nname",1,2\n"b",3,4\n'
status 0
out_is "1 2
3 4
"
csv 'X (mm),Y (cm),z [in]\n1,2,1\n'
status 0
out_is "1 20 25.4
"
csv 'x (furlong),y\n1,2\n'
status 1
says "c.csv:1: column x: unit 'furlong' is none loft knows"
csv 'x;y\n1,5;2,5\n-0,25;1e3\n'
status 0
out_is "1.5 2.5
-0.25 1000
"
csv 'sep=;\nx;y\n1,5;2\n'
status 0
out_is "1.5 2
"
csv 'x,y,,\r\n1,2,,\r\n3,4,,\r\n,,,\r\n,,,\r\n'
status 0
out_is "1 2
3 4
"
csv '\357\273\277x,y\n1,2\n'
status 0
out_is "1 2
"
csv 'x,y\n"1,2\n'
status 1
says "c.csv:2: a quote is never closed"
out_empty
# issue 28: a DXF circle at -t 1e-18 of its radius came out as 4 chords,
# a square, exit 0: a tolerance below the rounding is refused
printf '0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n1\n0\nENDSEC\n0\nEOF\n' >"$T/circ.dxf"
fails 1 "circ.dxf:5: CIRCLE: it needs more chords than the tolerance allows" "$F -t 1e-18 $T/circ.dxf"
# a byte order mark before a DXF
{ printf '\357\273\277'; cat "$T/circ.dxf"; } >"$T/bom.dxf"
run "$F $T/bom.dxf"
status 0
# 10^5 columns in a pass: a quadratic reading took 20 s (issue 28); a
# failing sanitizer or valgrind run would time out the suite, not this
awk 'BEGIN { for (i = 0; i < 100000; i++) printf "c%d,", i; print "x,y"
	for (i = 0; i < 100000; i++) printf "%d,", i; print "7,8" }' >"$T/wide.csv"
run "$F $T/wide.csv"
status 0
out_is "7 8
"

# ---- formats, files, output -------------------------------------------
fails 1 "empty.dxf: empty file" "$F $(: >"$T/empty.dxf"; echo "$T/empty.dxf")"
printf '\001\002\003 binary\n' >"$T/junk"
fails 1 "junk: not a document fromcad reads (dxf|svg|csv|step|iges;" "$F $T/junk"
fails 1 "nosuch: No such file" "$F $T/nosuch"
# -f reads what the content would not say: a DXF named .svg
cp "$T/none.dxf" "$T/dxf.svg"
run "$F $T/dxf.svg"
status 0
run "$F -f svg $T/none.dxf"
status 1
# several files, in order, a bad one between good ones
run "$F $T/none.dxf $T/junk $T/c.svg -"
status 1
[ "$(grep -c '^points\|^cubic' "$T/out")" = 2 ] && ok || no "three files: $(cat "$T/out")"
# stdin
run "$F <$T/c.svg"
out_is "cubic closed=0
0 0 2 -2 3 0 0 -3
"
# a full disk is a write error
if [ -w /dev/full ]; then
	run "$F $T/c.svg >/dev/full"
	status 1
	says "write error"
fi
# the shipped example: 22 knots in millimetres, closed, on layer 1
run "$F man/figures/insole.dxf"
status 0
grep -v '^#' man/figures/insole.knots | awk 'NF' >"$T/k"
awk 'NR > 1 && NF' "$T/out" | cmp -s - "$T/k" && ok || no "insole.dxf: knots differ from insole.knots"
head -1 "$T/out" | grep -qx 'points closed=1 layer=1' && ok || no "insole.dxf: $(head -1 "$T/out")"

# ---- hostile shapes (issue 28) ----------------------------------------
# Empty points: nothing drawn, no crash, and what follows is read.
for pts in '' '   ' ','; do
	printf '<svg><polyline points="%s"/><polygon points="%s"/><path d="M0 0L96 0"/></svg>' "$pts" "$pts" >"$T/empty.svg"
	run "$F $T/empty.svg"
	status 0
	out_is "points closed=0
0 0
25.4 0
"
done
# A stray closing tag is said with its line; what follows it is read.
printf '<svg><path d="M0 0 L96 0"/></g>\n<path d="M96 0 L0 0"/></svg>' >"$T/stray.svg"
run "$F $T/stray.svg"
status 1
says "stray.svg:1: </g> closes no open element"
out_is "points closed=0
0 0
25.4 0

points closed=0
25.4 0
0 0
"
# A closing tag for an outer element closes the inner one too.
printf '<svg><g><path d="M0 0 L96 0"></g>\n<path d="M96 0 L0 0"/></svg>' >"$T/mis.svg"
run "$F $T/mis.svg"
status 1
says "mis.svg:1: </g> comes while <path> of line 1 is open"
[ "$(grep -c '^points' "$T/out")" = 2 ] && ok || no "mis.svg: $(cat "$T/out")"
# Path data must start with a moveto: no invented 0,0.
printf '<svg><path d="L6 6 L7 5"/></svg>' >"$T/l.svg"
fails 1 "path data must start with a moveto (M or m) at 'L6 6 L7 5'" "$F $T/l.svg"
# An LWPOLYLINE vertex whose 20 comes before its 10 is one vertex.
printf '%s\n' '0 LWPOLYLINE' '8 0' '90 3' '10 0' '20 0' '20 5' '10 1' \
    '10 2' '20 7' | dxf "$T/yx.dxf"
run "$F $T/yx.dxf"
status 0
out_is "points closed=0 layer=0
0 0
1 5
2 7
"
# A tolerance finer than the rounding of the radius is refused, never
# a square.
printf '%s\n' '0 CIRCLE' '10 0' '20 0' '40 1' | dxf "$T/circ.dxf"
for t in 1e-17 1e-300; do
	fails 1 "it needs more chords than the tolerance allows" "$F -t $t $T/circ.dxf"
done
# A bulge of 5e-324 (and 1e-20) is a straight segment.
printf '%s\n' '0 LWPOLYLINE' '8 0' '10 0' '20 0' '42 5e-324' '10 4' '20 0' \
    '42 1e-20' '10 8' '20 0' | dxf "$T/bulge.dxf"
run "$F $T/bulge.dxf"
status 0
out_is "points closed=0 layer=0
0 0
4 0
8 0
"
# Extrusions of length 1e-300 to 1e300 are the direction (0, 0, -1):
# its OCS x axis is -x, so the x coordinates are negated.
for z in 1e-300 1e-170 1e170 1e300; do
	printf '%s\n' '0 LWPOLYLINE' '8 0' '10 1' '20 2' '10 3' '20 4' '210 0' \
	    '220 0' "230 -$z" | dxf "$T/ext.dxf"
	run "$F $T/ext.dxf"
	status 0
	out_is "points closed=0 layer=0
-1 2
-3 4
"
done
# A degree-63 SPLINE of 4,000 control points is read (in linear time:
# make bench's concern; here its pieces are counted).
awk 'BEGIN { n = 4000; p = 63; printf "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n8\n0\n71\n%d\n", p
	for (i = 0; i <= p; i++) printf "40\n0\n"
	for (i = 1; i < n - p; i++) printf "40\n%d\n", i
	for (i = 0; i <= p; i++) printf "40\n%d\n", n - p
	for (i = 0; i < n; i++) printf "10\n%d\n20\n%d\n", i, i % 5
	printf "0\nENDSEC\n0\nEOF\n" }' >"$T/deg63.dxf"
run "$F $T/deg63.dxf"
status 0
[ "$(grep -c '^bezier' "$T/out")" = $((4000 - 63)) ] && ok || no "deg63: $(grep -c '^bezier' "$T/out") pieces"

# A block that inserts itself, and an element that uses itself: drawn
# 16 deep, with one message each
printf '%s\n' 0 SECTION 2 BLOCKS 0 BLOCK 2 A 0 LINE 10 0 20 0 11 1 21 0 \
    0 INSERT 2 A 10 1 20 0 0 ENDBLK 0 ENDSEC 0 SECTION 2 ENTITIES \
    0 INSERT 2 A 0 ENDSEC 0 EOF >"$T/self.dxf"
run "$F $T/self.dxf"
status 1
says "self.dxf:19: INSERT: blocks nested deeper than 16 INSERTs (does a block insert itself?): not read"
[ "$(wc -l <"$T/err")" = 1 ] && [ "$(grep -c '^points' "$T/out")" = 16 ] && ok ||
    no "self.dxf: $(grep -c '^points' "$T/out") records; $(head -3 "$T/err")"
printf '<svg><g id="a"><use href="#a" x="1"/><path d="M0 0L1 1"/></g></svg>' >"$T/self.svg"
run "$F $T/self.svg"
status 1
says "use: uses nested deeper than 16 (does it use itself?): not read"
[ "$(wc -l <"$T/err")" = 1 ] && [ "$(grep -c '^points' "$T/out")" = 17 ] && ok ||
    no "self.svg: $(grep -c '^points' "$T/out") records; $(head -3 "$T/err")"
# A block inserted, scaled unevenly and turned, in a block inserted so
# too: the two transforms make a shear, which no INSERT can say (ezdxf
# 0.18's nested virtual entities stray 1 unit from it).  Block A: a
# circle of radius 2 at (3, 2), base point (1, 1); B: A at (2, 0),
# scales 1.5 and -0.5, turned 20 degrees; the model: B at (0, -20),
# scales 0.8 and 1.9, turned 75.  Each point written for the circle,
# taken back through the two transforms (inverted in awk), lies on the
# circle, to 1e-9.
printf '%s\n' 0 SECTION 2 HEADER 9 '$INSUNITS' 70 4 0 ENDSEC \
    0 SECTION 2 BLOCKS 0 BLOCK 2 A 10 1 20 1 0 CIRCLE 10 3 20 2 40 2 \
    0 ENDBLK 0 BLOCK 2 B 10 0 20 0 0 INSERT 2 A 10 2 20 0 41 1.5 42 -0.5 \
    50 20 0 ENDBLK 0 ENDSEC 0 SECTION 2 ENTITIES 0 INSERT 2 B 10 0 20 -20 \
    41 0.8 42 1.9 50 75 0 ENDSEC 0 EOF >"$T/shear.dxf"
run "$F $T/shear.dxf"
status 0
awk 'function back(x, y, sx, sy, a, tx, ty,   c, s, u, v) {
	# the inverse of p -> R(a) S(sx, sy) p + t
	a *= atan2(0, -1) / 180; c = cos(a); s = sin(a)
	x -= tx; y -= ty; u = c * x + s * y; v = -s * x + c * y
	X = u / sx; Y = v / sy
}
/^points/ { n++; next }
NF == 2 {
	back($1, $2, 0.8, 1.9, 75, 0, -20)
	back(X, Y, 1.5, -0.5, 20, 2, 0)
	X += 1; Y += 1               # A base point
	d = sqrt((X - 3)^2 + (Y - 2)^2) - 2
	if (d * d > 1e-18) bad++; m++
}
END { exit !(n == 1 && m >= 8 && !bad) }' "$T/out" && ok ||
    no "shear.dxf: the circle through two uneven inserts: $(head -3 "$T/out")"
# An INSERT of a block that is not there
printf '%s\n' '0 INSERT' '2 NONE' '10 0' '20 0' | dxf "$T/none.dxf"
fails 1 "INSERT: no block of its name (group 2) in the BLOCKS section" "$F $T/none.dxf"

# A symbol's viewBox (0 0 2 2) fitted to the use's box, x 10 y 10, 20
# by 10: scale 5 (the smaller), centred across: (0,0) at (15,10) and
# (2,2) at (25,20) user units, 25.4/96 mm each, y turned up; a use of
# width 100% keeps the symbol's own units, at its x and y (3, 0).
printf '<svg><defs><symbol id="s" viewBox="0 0 2 2"><path d="M0 0L2 2"/></symbol></defs><use href="#s" x="10" y="10" width="20" height="10"/><use href="#s" x="96" width="100%%" height="100%%"/></svg>' >"$T/sym.svg"
printf '%s\n' "points closed=0" "3.96875 -2.6458333333333335" \
    "6.614583333333334 -5.291666666666667" "" "points closed=0" "25.4 0" \
    "25.929166666666667 -0.5291666666666667" "" >"$T/sym.want"
run "$F $T/sym.svg"
status 0
near "$T/sym.want" 1e-15

# An ellipse with only rx (SVG 2's auto ry), or with r (as Inkscape
# writes some): the circle of that radius, as a circle element gives
printf '<svg><circle r="96"/><ellipse rx="96"/><ellipse r="96"/></svg>' >"$T/auto.svg"
run "$F $T/auto.svg"
status 0
awk 'BEGIN { RS = "" } { sub(/^[^\n]*\n/, ""); r[NR] = $0 } END { exit !(NR == 3 && r[1] == r[2] && r[2] == r[3] && r[1] ~ /^25.4 0 /) }' "$T/out" &&
    ok || no "auto.svg: $(head -3 "$T/out")"

# ---- tocad's attributes come back (XDATA of application LOFT) ---------
# size=, offset=, name= and id= of a plane curve (LWPOLYLINE), a space
# curve (POLYLINE) and an exact one (SPLINE, tocad -s) come back on
# fromcad's records; closed= and corners= are the entity's own.
for s in "" -s; do
	printf 'cubic size=4.5 offset=2 name=heel closed=0\n0 0 10 0 3 0 0 3\n\nbezier size=7 id=3\n0 0 0\n1 2 3\n3 3 3\n4 0 1\n' |
	    $B/tocad $s -f dxf >"$T/attr.dxf"
	run "$F $T/attr.dxf"
	status 0
	grep '^[a-z]' "$T/out" | grep -v '^points layer=[23]' >"$T/heads"
	printf '%s\n' "size=4.5 offset=2 name=heel" "size=7 id=3" >"$T/want"
	sed 's/.* layer=[^ ]* //' "$T/heads" | cmp -s - "$T/want" && ok ||
	    no "tocad $s attributes: $(cat "$T/heads")"
done
# XDATA that is no loft attribute, or of another application, is not read
printf '%s\n' '0 LINE' '8 0' '10 0' '20 0' '11 1' '21 0' '1001 ACAD' \
    '1000 size=1' '1001 LOFT' '1000 not an attr' '1000 a=b#c' '1000 1Z=1' \
    '1000 closed=1' '1000 ok=1' | dxf "$T/xd.dxf"
run "$F $T/xd.dxf"
status 0
out_is "points closed=0 layer=0 ok=1
0 0
1 0
"

# Path data in error is drawn up to the command in error, as SVG 1.1
# (F.2) and SVG 2 (9.5.4) render it, and the error is said (exit 1):
# a command with no numbers at the end, with or without a space after
# it (breeze's network-mobile-*-locked icons); numbers after Z.  A number
# ending in its point ("12.") is SVG 1.1's digit-sequence "." and reads
# as 12 (SVG 2 and Chromium stop the path there; breeze's folder-open).
svg "$T/perr.svg" '<path d="M 10,10 20,10 v 10 h "/>
<path d="M 10,30 20,30 l"/>
<path d="M 10,40 L 20,40 Z 3 4"/>
<path d="M 10,50 L 12. 50"/>'
run "$F $T/perr.svg"
status 1
says "perr.svg:3: path: bad path data at 'h ': drawn up to there, as SVG renders it"
says "perr.svg:4: path: bad path data at 'l': drawn up to there, as SVG renders it"
says "perr.svg:5: path: bad path data at '3 4': drawn up to there, as SVG renders it"
[ "$(wc -l <"$T/err")" = 3 ] && ok || no "perr.svg: $(cat "$T/err")"
out_is "points closed=0
10 -10
20 -10
20 -20

points closed=0
10 -30
20 -30

points closed=1
10 -40
20 -40

points closed=0
10 -50
12 -50
"
# An ellipse with neither rx, ry nor r has radii of 0 (SVG 2's auto):
# nothing drawn, no message; a flowRoot (SVG 1.2's draft text, drawn by
# no browser) is passed over whole, its flowRegion's rect not drawn
svg "$T/noradii.svg" '<ellipse cx="16" cy="16"/>
<flowRoot><flowRegion><rect x="1" y="1" width="5" height="5"/></flowRegion><flowPara>a</flowPara></flowRoot>'
run "$F $T/noradii.svg"
status 0
out_empty
says "noradii.svg: 1 flowRoot passed over"

# ---- straight= (issue 23): lines that curves meet with their tangent ----
# straight_ok FILE SIZE: every segment splinefit names in straight= of
# the cubic records of FILE is within 1e-9 SIZE of its chord: a Hermite
# row strays from its chord by at most 4/27 (|T_A x c| + |T_B x c|)/|c|
# (the basis functions h10, h11 of eq. 7 stay under 4/27); and the
# segments named are those from (X0 Y0) and (X1 Y1), given after SIZE
straight_ok() {
	awk -v size="$2" -v want="$3" '
	/^cubic/ { n = 0; s = ""; for (i = 2; i <= NF; i++) if ($i ~ /^straight=/) s = substr($i, 10); next }
	NF == 0 { next }
	{ n++; if (("," s ",") !~ ("," n ",")) next
	  cx = $3 - $1; cy = $4 - $2; c = sqrt(cx * cx + cy * cy)
	  a = $5 * cy - $6 * cx; b = $7 * cy - $8 * cx
	  d = 4 / 27 * ((a < 0 ? -a : a) + (b < 0 ? -b : b)) / c
	  if (d > 1e-9 * size) { printf "segment %d strays %g from its chord\n", n, d; bad = 1 }
	  got = got sprintf("%s(%g %g)", got == "" ? "" : " ", $1, $2) }
	END { if (got != want) { printf "straight segments from %s, want %s\n", got, want; bad = 1 }; exit bad }' \
	    "$1" >"$T/st" && ok || no "$what: $(cat "$T/st")"
}
# A stadium LWPOLYLINE: (0,0) to (10,0), a half turn of bulge 1 round
# (10,5) to (10,10), back to (0,10), a half turn round (0,5).  At -t 0.5
# a chord of radius 5 spans 4 asin(sqrt(0.5/10)) = 0.902 rad, so a half
# turn takes ceil(pi/0.902) = 4 chords, 3 knots inside: knots 1 (0,0),
# 2 (10,0), 3-5, 6 (10,10), 7 (0,10): straight=1,6.
printf '%s\n' '0 LWPOLYLINE' '8 0' '70 1' '10 0' '20 0' '10 10' '20 0' \
    '42 1' '10 10' '20 10' '10 0' '20 10' '42 1' | dxf "$T/stadium.dxf"
run "$F -t 0.5 $T/stadium.dxf"
status 0
sed -n 1p "$T/out" >"$T/head"
echo "points closed=1 layer=0 straight=1,6" | cmp -s - "$T/head" && ok ||
    no "stadium.dxf: header $(cat "$T/head"), want straight=1,6"
run "$F -t 0.5 $T/stadium.dxf | $B/splinefit"
status 0
straight_ok "$T/out" 20 "(0 0) (10 10)"
# the same turned the other way (bulges -1, clockwise) and a polygon's
# corners, a D whose arc leaves the line at a right angle: no straight=
printf '%s\n' '0 LWPOLYLINE' '8 0' '70 1' '10 0' '20 0' '42 -1' '10 0' \
    '20 10' '10 10' '20 10' '42 -1' '10 10' '20 0' | dxf "$T/stadcw.dxf"
run "$F -t 0.5 $T/stadcw.dxf"
grep -q '^points closed=1 layer=0 straight=5,10$' "$T/out" && ok ||
    no "stadcw.dxf: header $(sed -n 1p "$T/out"), want straight=5,10"
printf '%s\n' '0 LWPOLYLINE' '8 0' '70 1' '10 0' '20 0' '10 10' '20 0' \
    '10 10' '20 10' '10 0' '20 10' '0 LWPOLYLINE' '8 0' '70 1' '10 0' \
    '20 0' '10 0' '20 10' '42 1' | dxf "$T/corner.dxf"
run "$F $T/corner.dxf"
status 0
grep -c straight "$T/out" | grep -qx 0 && ok ||
    no "corner.dxf: straight= on a polygon or a D: $(grep '^p' "$T/out")"
# SVG: a stadium path of radius 10 and a rect rounded by 5 are cubic
# records; at -t 0.01 a quarter-turn piece strays r (2/27) sin^6(pi/8) /
# cos^2(pi/8) = 0.0027 (r 10) from the arc, so each half turn is two
# pieces and each corner one: straight=1,4 and straight=1,3,5,7.  A path
# whose arc leaves its line at a right angle, and a polygon: none.
svg "$T/stadium.svg" '<path d="M10 10 H40 A10 10 0 0 1 40 30 H10 A10 10 0 0 1 10 10 Z"/>
<rect x="0" y="50" width="40" height="20" rx="5"/>
<path d="M0 90 H10 A5 5 0 0 1 0 90 Z"/><polygon points="50,50 60,50 60,60"/>'
run "$F -t 0.01 $T/stadium.svg"
status 0
grep '^[a-z]' "$T/out" >"$T/heads"
printf '%s\n' "cubic closed=1 straight=1,4" "cubic closed=1 straight=1,3,5,7" \
    "cubic closed=1" "points closed=1" | cmp -s - "$T/heads" && ok ||
    no "stadium.svg: headers $(cat "$T/heads")"
# its joints as knots, straight= kept (span i is segment i), fitted
awk '/^cubic/ { printf "points"; for (i = 2; i <= NF; i++) if ($i ~ /^(closed|straight)=/) printf " %s", $i; print ""; next }
    { print NF ? $1 " " $2 : "" }' "$T/out" >"$T/st.knots"
run "sed -n 1,8p $T/st.knots | $B/splinefit"
status 0
straight_ok "$T/out" 30 "(10 -10) (40 -30)"

# ---- ezdxf, when installed ---------------------------------------------
PY=
for p in ${PYTHON:-} python3 /usr/bin/python3; do
	if "$p" -c 'import ezdxf' >/dev/null 2>&1; then PY=$p; break; fi
done
if [ -z "$PY" ]; then
	echo "fromcad: ezdxf cases skipped: no python3 with ezdxf (Debian python3-ezdxf)"
else
	for ver in R12 R2018; do
		"$PY" tests/fromcad_ezdxf.py "$ver" "$T/ez$ver.dxf" "$T/ez$ver.want" &&
		    ok || no "ezdxf $ver: could not write the DXF"
		what="fromcad of ezdxf's $ver"
		run "$F $T/ez$ver.dxf"
		status 0
		near "$T/ez$ver.want" 1e-12
	done
fi

finish fromcad
