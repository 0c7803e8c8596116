#!/bin/sh
# tocad.sh: tocad's documents read back independently: DXF, SVG, STEP and
# IGES parsed in awk from the formats' definitions (tests/cad.awk) and
# their curves and surfaces evaluated there, against the points sample
# writes (which evaluates the records by their own equations); STL's mesh
# checked for cracks and orientation by counting its edges.  With the
# real readers installed (python3-ezdxf, python3-gmsh for OpenCASCADE,
# admesh), their checks too; each is skipped with one line when missing.
# The last line is "tocad: N passed, M failed".

T=bin/test/tocad
. tests/lib.sh
FUNCS=$(cat tests/cad.awk)     # awk functions, before a program's text

# a python that has module $1, or nothing
python_with() {
	for p in python3 /usr/bin/python3; do
		if command -v "$p" >/dev/null 2>&1 && "$p" -c "import $1" \
		    2>/dev/null; then
			echo "$p"
			return
		fi
	done
}
EZPY=$(python_with ezdxf)
OCCPY=$(python_with gmsh)
ADMESH=$(command -v admesh)

# within WHAT LIMIT: $T/val holds one number, the worst error (written
# by a pipeline, whose last part runs in a subshell that cannot count);
# at most LIMIT
within() {
	read -r e <"$T/val"
	awk -v e="$e" -v l="$2" 'BEGIN { exit !(e ~ /^[0-9.]+([eE][-+]?[0-9]+)?$/ &&
	    e + 0 <= l + 0) }' &&
	    ok || no "$1: error '$e', want at most $2"
}

# ---- the inputs ----------------------------------------------------------

$B/splinefit man/figures/insole.knots >"$T/ins.cubic"
$B/sample -n 20 -u "$T/ins.cubic" >"$T/ins.pts"         # x y u
# an open curve in space
printf '0 0 0\n10 5 2\n20 0 4\n30 -5 3\n' | $B/splinefit -o >"$T/space.cubic"
$B/sample -n 20 -u "$T/space.cubic" >"$T/space.pts"
# a quartic and a Bezier of degree 5 in the plane
printf 'quartic id=7\n0 0 10 0 0 12 0 -12 5 4\n' >"$T/q.quartic"
printf 'bezier\n0 0\n2 6\n5 -4\n7 8\n9 -3\n12 1\n' >"$T/b5.bezier"
# a hull: two patches sharing an edge, bulged; and one with a T-junction
$B/patchnew -c 0,0,0 -c 10,0,0 -c 0,10,0 -c 10,10,5 | $B/patchsplit -u 0.5 |
    $B/patchdrag -i 2 -u 0.5 -v 0.5 -b 0,0,3 >"$T/hull.patch"
$B/patchsplit -i 3 -v 0.4 "$T/hull.patch" >"$T/tee.patch"
$B/sample -n 8 -u "$T/hull.patch" >"$T/hull.pts"        # x y z u v
size_hull=15        # the design's box: 10 x 10 x 5, diagonal 15

# ---- usage -----------------------------------------------------------------

usage_ok tocad
fails 2 "-f names the format" "$B/tocad $T/ins.cubic"
fails 2 "-f 'ps': want dxf, svg, step, iges, stl or obj" "$B/tocad -f ps $T/ins.cubic"
fails 2 "want a tolerance above 0" "$B/tocad -f dxf -t 0 $T/ins.cubic"
fails 2 "-u 'ft'" "$B/tocad -f svg -u ft $T/ins.cubic"

# ---- DXF ---------------------------------------------------------------------

# dxf_pairs FILE: the groups as "code<TAB>value" lines
dxf_pairs() {
	awk 'NR % 2 { c = $1 + 0; next } { sub(/\r$/, ""); print c "\t" $0 }' "$1"
}

# The structure of a DXF: a comment, then HEADER, TABLES, ENTITIES in
# order, EOF last; unique handles; every entity's layer in the table;
# each LWPOLYLINE's 90 matching its vertices.
dxf_valid() {
	dxf_pairs "$1" | awk -F '\t' '
	function bad(w) { print w; err = 1; exit 1 }
	$1 == 0 && $2 == "SECTION" { insec = 1; next }
	insec && $1 == 2 { sec[++ns] = $2; cur = $2; insec = 0; next }
	$1 == 0 && $2 == "EOF" { eof = NR; next }
	eof { bad("groups after EOF") }
	$1 == 5 { if (h[$2]++) bad("handle " $2 " twice") }
	cur == "TABLES" && $1 == 0 && $2 == "LAYER" { inlayer = 1; next }
	inlayer && $1 == 2 { layer[$2] = 1; inlayer = 0 }
	cur == "ENTITIES" && $1 == 0 {
		if (etype == "LWPOLYLINE" && nv != want) bad("90 says " want ", " nv " vertices")
		etype = $2; nv = 0; want = -1; if ($2 != "ENDSEC") nent++
	}
	cur == "ENTITIES" && $1 == 8 && !($2 in layer) { bad("layer " $2 " not in the table") }
	cur == "ENTITIES" && etype == "LWPOLYLINE" && $1 == 90 { want = $2 }
	cur == "ENTITIES" && etype == "LWPOLYLINE" && $1 == 10 { nv++ }
	$1 != 999 && $1 != 0 && $1 != 1 && $1 != 2 && $1 != 5 && $1 != 6 &&
	    $1 != 8 && $1 != 9 && $1 != 100 && $2 !~ /^-?[0-9.]+(e[-+][0-9]+)?$/ {
		bad("code " $1 ": not a number: " $2) }
	END {
		if (err) exit 1
		if (ns != 3 || sec[1] != "HEADER" || sec[2] != "TABLES" || sec[3] != "ENTITIES")
			{ print "sections: " sec[1] " " sec[2] " " sec[3]; exit 1 }
		if (!eof) { print "no EOF"; exit 1 }
	}'
}

# dxf_vertices FILE: the x y of the vertices of the first LWPOLYLINE
dxf_vertices() {
	dxf_pairs "$1" | awk -F '\t' '$1 == 0 { on = $2 == "LWPOLYLINE" && !seen++ }
	    on && $1 == 10 { x = $2 } on && $1 == 20 { print x, $2 }'
}

# poly_dev POLY PTS: the largest distance from a point of PTS (x y ...)
# to the closed polyline POLY (x y a line)
poly_dev() {
	awk "$FUNCS"'
	FNR == 1 { f++ }
	f == 1 { X[n + 0] = $1; Y[n + 0] = $2; n++; next }
	NF >= 2 { m = 1e300
		for (i = 0; i < n; i++) {
			j = (i + 1) % n
			d = segdist($1, $2, X[i], Y[i], X[j], Y[j])
			if (d < m) m = d
		}
		cnt++; if (m > worst) worst = m }
	END { if (cnt) printf "%.6g\n", worst; else print "nothing" }' "$1" "$2"
}

for t in 0.01 0.001; do
	run "$B/tocad -f dxf -t $t $T/ins.cubic"
	status 0
	cp "$T/out" "$T/ins.dxf"
	v=$(dxf_valid "$T/ins.dxf") && ok || no "dxf -t $t: not a valid DXF: $v"
	dxf_vertices "$T/ins.dxf" >"$T/poly"
	# every point of the curve within the tolerance of the polyline
	poly_dev "$T/poly" "$T/ins.pts" >"$T/val"; within "dxf -t $t: curve to polyline" "$t"
	nt=$(wc -l <"$T/poly")
	[ -n "$n1" ] && [ "$nt" -le "$n1" ] && no "dxf -t $t: $nt vertices, no more than at a coarser tolerance"
	n1=$nt
done
# the default: 1e-5 of the control points' box (man page); the box of
# the sampled points is inside it, so its diagonal gives a stricter test
# that still passes by a margin when the bound is met
run "$B/tocad -f dxf $T/ins.cubic"
cp "$T/out" "$T/insd.dxf"
dxf_vertices "$T/insd.dxf" >"$T/poly"
d=$(awk 'NF { if (!n++ || $1 < a) a = $1; if (n == 1 || $1 > b) b = $1
    if (n == 1 || $2 < c) c = $2; if (n == 1 || $2 > e) e = $2 }
    END { print 1e-5 * sqrt((b - a)^2 + (e - c)^2) }' "$T/ins.pts")
poly_dev "$T/poly" "$T/ins.pts" >"$T/val"; within "dxf default tolerance" "$d"
# -n 20: the vertices are the curve's points at the same steps as sample -n 20
run "$B/tocad -f dxf -n 20 $T/ins.cubic"
dxf_vertices "$T/out" | awk '{ print $1, $2 }' >"$T/poly"
awk 'NF { print $1, $2 }' "$T/ins.pts" | sed '$d' >"$T/want"
paste -d ' ' "$T/poly" "$T/want" | awk '{ e = sqrt(($1-$3)^2 + ($2-$4)^2); cnt++; if (e > w) w = e }
    END { print cnt ? w + 0 : "nothing" }' >"$T/val"; within "dxf -n 20 against sample -n 20" 1e-12
[ "$(wc -l <"$T/poly")" -eq "$(wc -l <"$T/want")" ] && ok ||
    no "dxf -n 20: $(wc -l <"$T/poly") vertices, want $(wc -l <"$T/want") (the closing one once)"
# a closed curve is a closed polyline (70 = 1)
dxf_pairs "$T/out" | grep -q -x "$(printf '70\t1')" && ok || no "dxf: closed curve not flagged closed"

# -s: one SPLINE of degree 3, the knots of 22 cubic pieces, evaluated by
# de Boor at the parameters sample wrote
dxf_spline_dev() {
	dxf_pairs "$1" | awk "$FUNCS"'
	FNR == 1 { f++ }
	f == 1 && $1 == 71 { p = $2 } f == 1 && $1 == 40 { K[nk++] = $2 }
	f == 1 && $1 == 10 { X[nc + 0] = $2 } f == 1 && $1 == 20 { Y[nc + 0] = $2 }
	f == 1 && $1 == 30 { Z[nc++] = $2 }
	f == 1 { next }
	NF >= 3 { deboor(p, K, nk, X, Y, Z, $(NF), R)
		e = 0; for (k = 1; k < NF; k++) e += (R[k] - $k)^2
		cnt++; if (sqrt(e) > w) w = sqrt(e) }
	END { print "deg=" p, "knots=" nk, "ctl=" nc, cnt ? w + 0 : "nothing" }' - "$2"
}
run "$B/tocad -f dxf -s $T/ins.cubic"
status 0
cp "$T/out" "$T/inss.dxf"
v=$(dxf_valid "$T/inss.dxf") && ok || no "dxf -s: not a valid DXF: $v"
set -- $(dxf_spline_dev "$T/inss.dxf" "$T/ins.pts")
[ "$1 $2 $3" = "deg=3 knots=71 ctl=67" ] && ok || no "dxf -s: spline '$1 $2 $3', want deg=3 knots=71 (67 + 4) ctl=67 (22 * 3 + 1)"
echo "$4" >"$T/val"; within "dxf -s: spline against sample" 3e-12
# a curve in space: SPLINE with z
run "$B/tocad -f dxf -s $T/space.cubic"
dxf_spline_dev "$T/out" "$T/space.pts" | awk '{ print $4 }' >"$T/val"
    within "dxf -s: space curve against sample" 1e-12

# $INSUNITS: 4 for millimetres (the default), 1 for inches
for u in mm:4 in:1; do
	$B/tocad -f dxf -u ${u%:*} "$T/ins.cubic" | dxf_pairs - |
	    awk -F '\t' '$2 == "$INSUNITS" { getline; print $2 }' >"$T/val"
	[ "$(cat "$T/val")" = "${u#*:}" ] && ok || no "dxf -u ${u%:*}: \$INSUNITS $(cat "$T/val")"
done

# layers: a graded set, one layer a size, in order; knots on layer 3
$B/grade -r -2:2 man/figures/insole.knots >"$T/graded.knots"
$B/splinefit "$T/graded.knots" >"$T/graded.cubic"
run "$B/tocad -f dxf $T/graded.cubic"
dxf_pairs "$T/out" | awk -F '\t' '$1 == 0 { t = $2 } t == "LAYER" && $1 == 2' |
    cut -f 2 | tr '\n' ' ' >"$T/layers"
[ "$(cat "$T/layers")" = "size_-2 size_-1 size_0 size_+1 size_+2 " ] && ok ||
    no "dxf layers: '$(cat "$T/layers")'"
run "$B/tocad -f dxf man/figures/insole.knots"
status 0
[ "$(dxf_pairs "$T/out" | grep -c "$(printf '^0\tPOINT$')")" -eq \
    "$(grep -c '^[-0-9]' man/figures/insole.knots)" ] && ok || no "dxf: not one POINT a knot"
dxf_pairs "$T/out" | awk -F '\t' '$1 == 0 { t = $2 } t == "POINT" && $1 == 8 && $2 != "3" { exit 1 }' &&
    ok || no "dxf: knots not on layer 3"

if [ -n "$EZPY" ]; then
	# ezdxf's audit of every kind of DXF tocad writes, and its SPLINE
	# evaluated at sample's parameters
	cat >"$T/ez.py" <<'PY'
import sys, ezdxf
doc = ezdxf.readfile(sys.argv[1])
a = doc.audit()
print(len(a.errors), len(a.fixes), end=" ")
worst = 0.0
if len(sys.argv) > 2:
    sp = [e for e in doc.modelspace() if e.dxftype() == "SPLINE"][0]
    tool = sp.construction_tool()
    for line in open(sys.argv[2]):
        f = [float(x) for x in line.split()]
        if not f:
            continue
        p = tool.point(f[-1])
        worst = max(worst, sum((p[k] - f[k]) ** 2 for k in range(len(f) - 1)) ** 0.5)
print(worst)
PY
	for f in ins insd inss; do
		set -- $("$EZPY" "$T/ez.py" "$T/$f.dxf" $([ $f = inss ] && echo "$T/ins.pts") 2>&1)
		[ "$1 $2" = "0 0" ] && ok || no "ezdxf audit of $f.dxf: $*"
	done
	echo "$3" >"$T/val"; within "ezdxf: the SPLINE against sample" 3e-12
	$B/tocad -f dxf "$T/space.cubic" >"$T/space.dxf"
	set -- $("$EZPY" "$T/ez.py" "$T/space.dxf" 2>&1)
	[ "$1 $2" = "0 0" ] && ok || no "ezdxf audit of a 3-D polyline: $*"
	$B/tocad -f dxf "$T/graded.cubic" man/figures/insole.knots >"$T/graded.dxf"
	set -- $("$EZPY" "$T/ez.py" "$T/graded.dxf" 2>&1)
	[ "$1 $2" = "0 0" ] && ok || no "ezdxf audit of layers and points: $*"
else
	echo "tocad: skipped: no python3-ezdxf"
fi

# ASTM D6673 turn points: a curve's corners= (its joints, loft.5) become
# POINTs on layer 2 at its polyline's vertices, or at its SPLINE's
# control points at the joints.  The reference: the corner knots' own
# numbers in the knot file (splinefit's joints are its knots), and, read
# by awk here, the LWPOLYLINE's vertices.
{ echo "points corners=3,9,15"; grep '^[-0-9]' man/figures/insole.knots; } >"$T/turn.knots"
awk '/^[-0-9]/ && (++n == 3 || n == 9 || n == 15)' "$T/turn.knots" >"$T/turn.want"
$B/splinefit "$T/turn.knots" >"$T/turn.cubic"
head -1 "$T/turn.cubic" | grep -q '^cubic closed=1 corners=3,9,15$' && ok ||
    no "splinefit: the cubic's header '$(head -1 "$T/turn.cubic")' names no corners 3,9,15"
# dxf_turns FILE: "x y" of each POINT on layer 2; with -v, those that are
# not also a vertex of an LWPOLYLINE
dxf_turns() {
	dxf_pairs "$2" | awk -F '\t' -v novertex="$1" '
	$1 == 0 { t = $2; lay = "" } $1 == 8 { lay = $2 }
	t == "LWPOLYLINE" && $1 == 10 { x = $2 } t == "LWPOLYLINE" && $1 == 20 { V[x + 0, $2 + 0] = 1 }
	t == "POINT" && lay == "2" && $1 == 10 { x = $2 }
	t == "POINT" && lay == "2" && $1 == 20 { P[++n] = x " " $2; PX[n] = x + 0; PY[n] = $2 + 0 }
	END { for (i = 1; i <= n; i++) if (novertex != "-v" || !((PX[i], PY[i]) in V)) print P[i] }'
}
for s in "" "-s"; do
	run "$B/tocad -f dxf $s $T/turn.cubic"
	status 0
	cp "$T/out" "$T/turn$s.dxf"
	v=$(dxf_valid "$T/turn$s.dxf") && ok || no "dxf $s with turn points: not a valid DXF: $v"
	dxf_turns - "$T/turn$s.dxf" | paste -d ' ' "$T/turn.want" - |
	    awk 'NF != 4 || $1 != $3 || $2 != $4 { exit 1 } END { exit NR != 3 }' &&
	    ok || no "dxf $s: turn points '$(dxf_turns - "$T/turn$s.dxf" | tr '\n' ,)', want the corner knots"
done
[ -z "$(dxf_turns -v "$T/turn.dxf")" ] && ok || no "dxf: turn points off the polyline's vertices"
# knots that name corners (fromcad's D6673 boundaries): layer-3 POINTs
# at every knot, and layer-2 turn points at knots 2 and 4, the knots'
# own coordinates; a knot number past the record is refused
printf 'points corners=2,4\n0 0\n40 0\n40 20\n0 20\n' >"$T/kturn.knots"
run "$B/tocad -f dxf $T/kturn.knots"
status 0
[ "$(dxf_turns - "$T/out" | tr '\n' ,)" = "40 0,0 20," ] && ok ||
    no "dxf of knots with corners=2,4: turn points '$(dxf_turns - "$T/out" | tr '\n' ,)', want 40 0 and 0 20"
printf 'points corners=2,5\n0 0\n40 0\n40 20\n0 20\n' >"$T/kturn5.knots"
run "$B/tocad -f dxf $T/kturn5.knots"
status 1
says "kturn5.knots:1: attribute corners=2,5: want knot numbers from 1 to 4 in increasing order, separated by commas"
# a corners= that names no joint (of 2 pieces, open: 1 to 3), out of
# order or not a number: a message each, the other records written
printf 'cubic closed=0 corners=%s\n0 0 1 0 1 0 1 0\n1 0 1 1 0 1 0 1\n\n' 2 3 4 0 2,2 x >"$T/badturn"
run "$B/tocad -f dxf $T/badturn"
status 1
says "corners=4: want joint numbers from 1 to 3 in increasing order"
[ "$(grep -c 'want joint numbers' "$T/err")" = 4 ] && ok || no "dxf: not one message a bad corners="
[ "$(dxf_pairs "$T/out" | grep -c "$(printf '^0\tLWPOLYLINE$')")" = 2 ] && ok ||
    no "dxf: the good corners= records not all written"
if [ -n "$EZPY" ]; then
	# ezdxf: the POINTs on layer 2 where the corner knots are, and each
	# on a vertex of the LWPOLYLINE, or a control point of the SPLINE
	cat >"$T/ezturn.py" <<'PY'
import sys, ezdxf
doc = ezdxf.readfile(sys.argv[1])
a = doc.audit()
want = [tuple(float(v) for v in l.split()) for l in open(sys.argv[2]) if l.strip()]
msp = doc.modelspace()
got = [(p.dxf.location.x, p.dxf.location.y) for p in msp.query('POINT[layer=="2"]')]
on = set()
for e in msp.query("LWPOLYLINE"):
    on |= {(v[0], v[1]) for v in e.get_points("xy")}
for e in msp.query("SPLINE"):
    on |= {(v[0], v[1]) for v in e.control_points}
print(len(a.errors), int(got == want), int(all(g in on for g in got)))
PY
	for s in "" "-s"; do
		set -- $("$EZPY" "$T/ezturn.py" "$T/turn$s.dxf" "$T/turn.want" 2>&1)
		[ "$*" = "0 1 1" ] && ok || no "ezdxf of turn points (dxf $s): '$*' (audit errors, at the corners, on the curve)"
	done
fi

# LibreCAD (2.2's dxf2pdf, headless): it reads tocad's DXFs and prints
# them at 1:1 to a PDF whose drawing has the curves' extent in
# millimetres: a polyline, SPLINEs, a graded set on its layers with knots
# as POINTs, the insole in inches ($INSUNITS 1: the same paper size),
# and one with turn points.
# The reference is the box of sample's points of the curves; within
# 0.1 mm (dxf2pdf's 1200 dpi is 0.02 mm, and its SPLINEs are its own
# chords).  A DXF LibreCAD cannot read gets a dialog, no PDF: the
# timeout ends it and the check fails.
PDFPY=$(python_with zlib)
if command -v librecad >/dev/null 2>&1 && [ -n "$PDFPY" ] &&
    command -v timeout >/dev/null 2>&1; then
	mkdir -p "$T/lc/home" "$T/lc/run" "$T/lc/pdf" && chmod 700 "$T/lc/run"
	$B/tocad -f dxf "$T/graded.cubic" man/figures/insole.knots >"$T/lc/graded.dxf"
	$B/tocad -f dxf -s "$T/graded.cubic" >"$T/lc/gradeds.dxf"
	cp "$T/insd.dxf" "$T/lc/ins.dxf"
	cp "$T/inss.dxf" "$T/lc/inss.dxf"
	cp "$T/turn.dxf" "$T/lc/turn.dxf"
	awk '/^[-0-9]/ { print $1 / 25.4, $2 / 25.4; next } { print }' \
	    man/figures/insole.knots | $B/splinefit | $B/tocad -f dxf -u in \
	    >"$T/lc/insin.dxf"
	# box FILE...: the width and height of sample's points of the curves
	box() {
		cat "$@" | $B/sample -n 50 | awk 'NF { if (!n++) { a = b = $1; c = e = $2 }
		    if ($1 < a) a = $1; if ($1 > b) b = $1
		    if ($2 < c) c = $2; if ($2 > e) e = $2 }
		    END { printf "%.6f %.6f\n", b - a, e - c }'
	}
	for f in ins:ins.cubic inss:ins.cubic graded:graded.cubic \
	    gradeds:graded.cubic insin:ins.cubic turn:turn.cubic; do
		n=${f%%:*}
		(cd "$T/lc" && HOME=$PWD/home XDG_RUNTIME_DIR=$PWD/run \
		    QT_QPA_PLATFORM=offscreen timeout 60 librecad dxf2pdf -s 1 \
		    -t pdf "$n.dxf") >"$T/lc/$n.log" 2>&1
		if [ ! -s "$T/lc/pdf/$n.pdf" ]; then
			no "librecad dxf2pdf $n.dxf: no PDF: $(grep -v DEBUG "$T/lc/$n.log" | head -3)"
			continue
		fi
		set -- $("$PDFPY" tests/pdf_extent.py "$T/lc/pdf/$n.pdf" 2>&1) \
		    $(box "$T/${f#*:}")
		awk -v p="$1" -v w="$2" -v h="$3" -v W="$4" -v H="$5" 'BEGIN {
		    d = w - W; e = h - H; exit !(p > 0 && d * d <= 0.01 && e * e <= 0.01) }' &&
		    ok || no "librecad: $n.dxf printed $1 paths over $2 x $3 mm, want $4 x $5"
	done
else
	echo "tocad: skipped: LibreCAD's print of the DXFs (no librecad, python3 or timeout)"
fi

# ---- SVG -------------------------------------------------------------------

# svg_paths FILE: each C segment of the first path as "x0 y0 x1 y1 x2 y2 x3 y3"
svg_cubics() {
	awk '/<path/ && !seen++ { s = $0; sub(/.* d="/, "", s); sub(/".*/, "", s)
	    gsub(/,/, " ", s); n = split(s, w, " "); k = 0
	    for (i = 1; i <= n; i++) {
		if (w[i] == "M") { x = w[i + 1]; y = w[i + 2]; i += 2 }
		else if (w[i] == "C") { print x, y, w[i+1], w[i+2], w[i+3], w[i+4], w[i+5], w[i+6]
			x = w[i + 5]; y = w[i + 6]; i += 6 }
		else if (w[i] == "Z") ;
		else { print "unknown " w[i]; exit 1 }
	    } }' "$1"
}
run "$B/tocad -f svg $T/ins.cubic"
status 0
cp "$T/out" "$T/ins.svg"
[ "$(svg_cubics "$T/ins.svg" | wc -l)" -eq 22 ] && ok || no "svg: not 22 cubics"
# exact: each cubic at the 20 steps of sample -n 20 is sample's point
svg_cubics "$T/ins.svg" | awk "$FUNCS"'
    FNR == 1 { f++ }
    f == 1 { for (k = 0; k < 8; k++) C[n + 0, k] = $(k + 1); n++; next }
    NF { i = int($3); t = $3 - i; if (i == n) { i--; t = 1 }
	for (k = 0; k < 8; k++) P[k] = C[i, k]
	cubic(P, t, R); e = sqrt((R[1] - $1)^2 + (R[2] - $2)^2); cnt++; if (e > w) w = e }
    END { print cnt ? w + 0 : "nothing" }' - "$T/ins.pts" >"$T/val"; within "svg: cubics against sample" 3e-12
# true scale: width and height in mm are the viewBox's size in the
# stream's unit (25.4 mm an inch), y flipped
for u in mm in; do
	$B/tocad -f svg -u $u "$T/ins.cubic" |
	    awk -v mm=$([ $u = in ] && echo 25.4 || echo 1) '/<svg/ {
		match($0, /width="[^"]*"/); w = substr($0, RSTART + 7, RLENGTH - 10)
		match($0, /height="[^"]*"/); h = substr($0, RSTART + 8, RLENGTH - 11)
		match($0, /viewBox="[^"]*"/); split(substr($0, RSTART + 9, RLENGTH - 10), v, " ")
		e = (w - mm * v[3]) / w; if (e < 0) e = -e
		f = (h - mm * v[4]) / h; if (f < 0) f = -f
		print (e > f ? e : f) + 0 }' >"$T/val"; within "svg -u $u: width and height in mm" 1e-15
done
grep -q 'transform="scale(1,-1)"' "$T/ins.svg" && ok || no "svg: y not flipped"
# well-formed XML to Python's own parser (any python3 has it)
XMLPY=$(python_with xml.dom.minidom)
if [ -n "$XMLPY" ]; then
	$B/tocad -f svg "$T/graded.cubic" "$T/q.quartic" >"$T/graded.svg"
	n=$("$XMLPY" -c 'import sys, xml.dom.minidom as m
print(len(m.parse(sys.argv[1]).getElementsByTagName("path")))' "$T/graded.svg" 2>&1)
	[ "$n" = 6 ] && ok || no "svg: python's XML parser: $n"
else
	echo "tocad: skipped: no python3 for the SVG's XML"
fi
# the viewBox holds the curve: its x from the box of the sampled points,
# y flipped (top = -ymax)
awk '/<svg/ { match($0, /viewBox="[^"]*"/); print substr($0, RSTART + 9, RLENGTH - 10) }' \
    "$T/ins.svg" >"$T/vb"
awk 'FNR == 1 { f++ } f == 1 { x0 = $1; y0 = $2; w = $3; h = $4; next }
    NF && ($1 < x0 - 1e-9 || $1 > x0 + w + 1e-9 || -$2 < y0 - 1e-9 || -$2 > y0 + h + 1e-9) { bad++ }
    END { exit bad > 0 }' "$T/vb" "$T/ins.pts" && ok || no "svg: a point outside the viewBox"
# a quartic and a Bezier of degree 5: cubics within the tolerance
for r in q.quartic b5.bezier; do
	$B/sample -n 200 "$T/$r" >"$T/r.pts"
	$B/tocad -f svg -t 1e-4 "$T/$r" | svg_cubics - >"$T/r.cub"
	awk "$FUNCS"'FNR == 1 { f++ }
	    f == 1 { for (k = 0; k < 8; k++) P[k] = $(k + 1)
		for (j = 0; j <= 50; j++) { cubic(P, j / 50, R); X[n + 0] = R[1]; Y[n++] = R[2] }
		next }
	    NF { m = 1e300; for (i = 0; i + 1 < n; i++) {
		d = segdist($1, $2, X[i], Y[i], X[i + 1], Y[i + 1]); if (d < m) m = d }
		cnt++; if (m > w) w = m }
	    END { print cnt ? w + 0 : "nothing" }' "$T/r.cub" "$T/r.pts" >"$T/val"
	    within "svg: $r's cubics within -t 1e-4 (sampled at 1/50)" 1.2e-4
	[ "$(wc -l <"$T/r.cub")" -gt 1 ] && ok || no "svg: $r in one cubic: not approximated"
done

# ---- STEP ----------------------------------------------------------------------

# step_eval FILE PTS: the largest distance from sample's points to the
# STEP's curves (x y [z] u) or surfaces (x y z u v), by de Boor on the
# entity with the same position in the file as the record in PTS (as
# sample -n 8 writes them: 18 records a surface)
step_eval() {
	awk -v per="$(grep -q '^patch' "${2%.pts}.patch" 2>/dev/null &&
	    echo 18 || echo 1)" "$FUNCS"'
	FNR == 1 { f++ }
	f == 1 && /CARTESIAN_POINT/ { s = $0; sub(/=.*/, "", s); id = substr(s, 2)
		sub(/^[^(]*\([^(]*\(/, ""); sub(/\).*/, ""); split($0, c, ",")
		PX[id] = c[1]; PY[id] = c[2]; PZ[id] = c[3]; next }
	f == 1 && /B_SPLINE_(CURVE|SURFACE)_WITH_KNOTS/ { ne++; E[ne] = $0; next }
	f == 1 { next }
	(FNR == 1 || prevblank) && NF { rec++; k = int((rec - 1) / per) + 1
		if (k != cur) parse(E[cur = k]) }
	{ prevblank = (NF == 0) }
	NF { check_row() }
	END { print cnt ? w + 0 : "nothing" }
	# lists: "(a,b,c)" items of the entity text, in order
	function lists(s, L,    n, d, i, ch, cur) {
		n = 0; d = 0; cur = ""
		for (i = 1; i <= length(s); i++) {
			ch = substr(s, i, 1)
			if (ch == "(") { d++; if (d == 2) cur = ""; else if (d > 2) cur = cur ch; continue }
			if (ch == ")") { if (d == 2) L[++n] = cur; else if (d > 2) cur = cur ch; d--; continue }
			if (d >= 2) cur = cur ch
		}
		return n
	}
	function parse(s,    L, n, a, m, i, j, k, nr, rows, row) {
		surf = s ~ /SURFACE/
		n = lists(s, L)
		split(s, a, ","); p = a[2] + 0
		if (!surf) {
			nc = split(L[1], a, ","); for (i = 1; i <= nc; i++) {
				id = substr(a[i], 2); X[i-1] = PX[id]; Y[i-1] = PY[id]; Z[i-1] = PZ[id] }
			knots(L[2], L[3], K); return
		}
		q = a[3] + 0
		nr = split(L[1], rows, /\),\(/)
		for (i = 1; i <= nr; i++) { gsub(/[()]/, "", rows[i]); nn = split(rows[i], row, ",")
			for (j = 1; j <= nn; j++) { id = substr(row[j], 2)
				SX[i-1, j-1] = PX[id]; SY[i-1, j-1] = PY[id]; SZ[i-1, j-1] = PZ[id] } }
		mu = nr; mv = nn
		knots(L[2], L[4], KU); knots(L[3], L[5], KV)
	}
	function knots(ms, ks, KK,    a, b, n, i, r) {
		nk = 0; n = split(ms, a, ","); split(ks, b, ",")
		for (i = 1; i <= n; i++) for (r = 0; r < a[i]; r++) KK[nk++] = b[i] + 0
	}
' "$1" "$2"
}

# the structure: header, schema, data, one entity an instance, ends
step_valid() {
	awk 'NR == 1 && $0 != "ISO-10303-21;" { print "first line " $0; exit 1 }
	    /^#/ { if (!/^#[0-9]+=[A-Z_(].*;$/) { print "entity " NR ": " $0; exit 1 }
		id = $0; sub(/=.*/, "", id); if (seen[id]++) { print id " twice"; exit 1 } }
	    /^#/ { s = $0; while (match(s, /#[0-9]+/)) { ref[substr(s, RSTART, RLENGTH)] = NR
		s = substr(s, RSTART + RLENGTH) } }
	    { last = $0 }
	    END { if (last != "END-ISO-10303-21;") { print "last line " last; exit 1 }
		for (r in ref) if (!(r in seen)) { print r " referenced, not defined"; exit 1 } }' "$1"
}


# ---- IGES ----------------------------------------------------------------------

# The fixed form: 80 columns, sections S G D P T in order, each numbered
# from 1; the directory's pointers and counts match the parameter lines;
# the T line counts each section.
iges_valid() {
	awk '
	function bad(w) { print "line " NR ": " w; err = 1; exit 1 }
	length($0) != 80 { bad("not 80 columns") }
	{ s = substr($0, 73, 1); n = substr($0, 74) + 0 }
	s != last { if (last != "" && index("SGDPT", s) <= index("SGDPT", last)) bad("section " s " after " last)
		last = s; k = 0 }
	++k != n { bad("sequence " n ", want " k) }
	{ cnt[s] = n }
	s == "D" && n % 2 == 1 { type[n] = substr($0, 1, 8) + 0; ptr[n] = substr($0, 9, 8) + 0 }
	s == "D" && n % 2 == 0 { lines[n - 1] = substr($0, 25, 8) + 0
		if (substr($0, 1, 8) + 0 != type[n - 1]) bad("entity types differ") }
	s == "P" { de = substr($0, 66, 7) + 0; if (!(de in first)) first[de] = n; plines[de]++
		if (n == first[de]) { split(substr($0, 1, 64), a, ","); if (a[1] + 0 != type[de]) bad("P type " a[1] " vs " type[de]) } }
	s == "T" { t = $0 }
	END { if (err) exit 1
		for (d in ptr) { if (first[d] != ptr[d]) { print "DE " d " points to " ptr[d] ", data at " first[d]; exit 1 }
			if (plines[d] != lines[d]) { print "DE " d ": " lines[d] " lines, data " plines[d]; exit 1 } }
		want = sprintf("S%7dG%7dD%7dP%7d", cnt["S"], cnt["G"], cnt["D"], cnt["P"])
		if (substr(t, 1, 32) != want) { print "T " substr(t, 1, 32) " want " want; exit 1 } }' "$1"
}

# The entities' parameters ("126,..." of each, in order) from the P lines
iges_params() {
	awk 'substr($0, 73, 1) == "P" { de = substr($0, 66, 7) + 0
	    if (de != cur) { if (s != "") print s; s = ""; cur = de }
	    x = substr($0, 1, 64); sub(/ +$/, "", x); s = s x }
	    END { if (s != "") print s }' "$1"
}

# iges_eval FILE PTS: as step_eval, for 126 curves and 128 surfaces
iges_eval() {
	iges_params "$1" | awk -v per="$(grep -q '^patch' "${2%.pts}.patch" 2>/dev/null &&
	    echo 18 || echo 1)" "$FUNCS"'
	FNR == 1 { f++ }
	f == 1 { sub(/;$/, ""); E[++ne] = $0; next }
	(FNR == 1 || prevblank) && NF { rec++; k = int((rec - 1) / per) + 1
		if (k != cur) parse(E[cur = k]) }
	{ prevblank = (NF == 0) }
	NF { check_row() }
	END { print cnt ? w + 0 : "nothing" }
	function parse(s,    a, i, j, o, kk, nc) {
		split(s, a, ",")
		surf = a[1] == 128
		if (!surf) {    # 126: K M props(4) knots(K+M+2) weights(K+1) points
			kk = a[2]; p = a[3]; nk = kk + p + 2; o = 8
			for (i = 0; i < nk; i++) K[i] = a[o + i]
			o += nk + kk + 1
			for (i = 0; i <= kk; i++) { X[i] = a[o + 3*i]; Y[i] = a[o + 3*i + 1]; Z[i] = a[o + 3*i + 2] }
			return
		}
		# 128: K1 K2 M1 M2 props(5) S T weights points, u fastest
		mu = a[2] + 1; mv = a[3] + 1; p = a[4]; q = a[5]; o = 11
		for (i = 0; i < mu + p + 1; i++) KU[i] = a[o + i]; o += mu + p + 1
		for (i = 0; i < mv + q + 1; i++) KV[i] = a[o + i]; o += mv + q + 1
		o += mu * mv
		for (j = 0; j < mv; j++) for (i = 0; i < mu; i++) {
			SX[i, j] = a[o]; SY[i, j] = a[o + 1]; SZ[i, j] = a[o + 2]; o += 3 }
	}' - "$2"
}

# both formats, every kind of record: the structure, and the entities
# evaluated at sample's parameters
$B/sample -n 8 -u "$T/tee.patch" >"$T/tee.pts"
for f in step:step iges:igs; do
	fmt=${f%:*}
	ext=${f#*:}
	for c in ins.cubic:3e-12 hull.patch:1e-13 tee.patch:1e-13 space.cubic:1e-12; do
		r=${c%:*}
		name=${r%.*}
		run "$B/tocad -f $fmt $T/$r"
		status 0
		cp "$T/out" "$T/$name.$ext"
		v=$("${fmt}_valid" "$T/$name.$ext") && ok || no "$fmt $name: $v"
		"${fmt}_eval" "$T/$name.$ext" "$T/$name.pts" >"$T/val"
		within "$fmt: $name against sample" "${c#*:}"
	done
done

if [ -n "$OCCPY" ]; then
	# OpenCASCADE (through gmsh) reads the files; every point sample
	# wrote lies on the imported curves or surfaces to 1e-7 of the size
	cat >"$T/occ.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
dim = int(sys.argv[3])
ents = [t for d, t in gmsh.model.getEntities(dim)]
pts = [[float(x) for x in l.split()] for l in open(sys.argv[2]) if l.strip()]
worst = 0.0
for f in pts:
    # a curve's rows end with the parameter, a surface's with u and v
    p = (f[:-1] + [0.0])[:3] if dim == 1 else f[:3]
    best = 1e300
    for t in ents:
        c = gmsh.model.getClosestPoint(dim, t, p)[0]
        best = min(best, sum((c[k] - p[k]) ** 2 for k in range(3)) ** 0.5)
    worst = max(worst, best)
print(len(ents), worst)
gmsh.finalize()
PY
	# the insole's size: its length, 265 mm
	for f in ins.step ins.igs; do
		set -- $("$OCCPY" "$T/occ.py" "$T/$f" "$T/ins.pts" 1 2>/dev/null | tail -n 1)
		[ "${1:-0}" -ge 1 ] && ok || no "OpenCASCADE: $f: no curves ($*)"
		echo "$2" >"$T/val"; within "OpenCASCADE: $f: sample's points off the curve" 2.6e-5
	done
	for f in hull.step tee.step tee.igs; do
		set -- $("$OCCPY" "$T/occ.py" "$T/$f" "$T/${f%.*}.pts" 2 2>/dev/null | tail -n 1)
		want=$(grep -c '^patch' "$T/${f%.*}.patch")
		[ "$1" = "$want" ] && ok || no "OpenCASCADE: $f: $1 surfaces, want $want"
		echo "$2" >"$T/val"; within "OpenCASCADE: $f: sample's points off the surfaces" 1.5e-6
	done
	# the two patches of hull.step share a side: one edge (7, not 8)
	set -- $("$OCCPY" "$T/occ.py" "$T/hull.step" "$T/hull.pts" 1 2>/dev/null | tail -n 1)
	[ "$1" = 7 ] && ok || no "OpenCASCADE: hull.step: $1 edges, want 7 (one shared)"
else
	echo "tocad: skipped: no python3-gmsh (OpenCASCADE)"
fi

# ---- STL -----------------------------------------------------------------------

# stl_edges FILE: "facets boundary-edges twice-directed bad-normals"
# from an ASCII STL whose welded vertices are the same text
stl_edges() {
	awk '/facet normal/ { nx = $3; ny = $4; nz = $5; nf++; k = 0 }
	    /vertex/ { V[k] = $2 " " $3 " " $4; X[k] = $2; Y[k] = $3; Z[k] = $4; k++ }
	    /endloop/ { for (i = 0; i < 3; i++) { a = V[i]; b = V[(i + 1) % 3]
			if (dir[a, b]++) twice++
			if (a < b) und[a, b]++; else und[b, a]++ }
		ux = X[1] - X[0]; uy = Y[1] - Y[0]; uz = Z[1] - Z[0]
		vx = X[2] - X[0]; vy = Y[2] - Y[0]; vz = Z[2] - Z[0]
		cx = uy * vz - uz * vy; cy = uz * vx - ux * vz; cz = ux * vy - uy * vx
		l = sqrt(cx * cx + cy * cy + cz * cz)
		if (l == 0 || (cx * nx + cy * ny + cz * nz) / l < 1 - 1e-9) badn++ }
	    END { for (e in und) if (und[e] == 1) bd++
		print nf, bd + 0, twice + 0, badn + 0 }' "$1"
}
run "$B/tocad -f stl -n 8 $T/hull.patch"
status 0
cp "$T/out" "$T/hull.stl"
head -n 1 "$T/hull.stl" | grep -q '^solid ' && tail -n 1 "$T/hull.stl" | grep -q '^endsolid' &&
    ok || no "stl: no solid ... endsolid"
# two patches of 8 x 8 cells, two triangles a cell: 256 facets; welded,
# the design is one sheet of 16 x 8 cells whose boundary is 48 edges;
# no directed edge twice (orientation consistent); normals as the
# vertices' order says
set -- $(stl_edges "$T/hull.stl")
[ "$*" = "256 48 0 0" ] && ok || no "stl: facets, boundary, twice-directed, bad normals: $*, want 256 48 0 0"
# a T-junction: patch 2's edge u = 1 against patches 4 (v 0 to 0.4) and 5
# (0.4 to 1), 5 steps each: the points of each side are put into the
# other's edge, so the only free edges are the outline's 7 sides of 5
run "$B/tocad -f stl -n 5 $T/tee.patch"
status 0
cp "$T/out" "$T/tee.stl"
set -- $(stl_edges "$T/tee.stl")
[ "$2 $3 $4" = "35 0 0" ] && ok || no "stl T-junction: boundary, twice-directed, bad normals: $2 $3 $4, want 35 0 0"
# the hull's second patch with u reversed (rows (0) (1) (0)_u (1)_u (h)
# become (1) (0) -(1)_u -(0)_u (h)): the same surface run the other
# way, so its own triangles face the other side; the mesh is oriented
# across the shared edge all the same
awk 'BEGIN { RS = ""; FS = "\n"; ORS = "" }
    NR == 2 { split($4, r2, " "); split($5, r3, " ")
	print $1 "\n" $3 "\n" $2 "\n"
	for (i = 1; i <= 15; i++) printf "%s%.17g", (i > 1 ? " " : ""), -r3[i]
	print "\n"
	for (i = 1; i <= 15; i++) printf "%s%.17g", (i > 1 ? " " : ""), -r2[i]
	print "\n" $6 "\n\n"; next }
    { print $0 "\n\n" }' "$T/hull.patch" >"$T/rev.patch"
run "$B/tocad -f stl -n 8 $T/rev.patch"
status 0
cp "$T/out" "$T/rev.stl"
set -- $(stl_edges "$T/rev.stl")
[ "$*" = "256 48 0 0" ] && ok || no "stl of a reversed patch: $*, want 256 48 0 0"
# vertices on the surface: each is one of sample's wireframe points
awk 'FNR == 1 { f++ } f == 1 && NF { P[$1 " " $2 " " $3] = 1; X[n + 0] = $1; Y[n + 0] = $2; Z[n++] = $3; next }
    f == 2 && /vertex/ { m = 1e300; for (i = 0; i < n; i++) {
	d = ($2 - X[i])^2 + ($3 - Y[i])^2 + ($4 - Z[i])^2; if (d < m) m = d }
	cnt++; if (sqrt(m) > w) w = sqrt(m) }
    END { print cnt ? w + 0 : "nothing" }' "$T/hull.pts" "$T/hull.stl" >"$T/val"; within "stl: vertices on the surface (sample -n 8)" 1e-13
# binary: 80 bytes, the count, 50 bytes a facet
run "$B/tocad -f stl -b -n 8 $T/hull.patch"
status 0
cp "$T/out" "$T/hullb.stl"
[ "$(wc -c <"$T/hullb.stl")" -eq $((84 + 50 * 256)) ] && ok || no "stl -b: $(wc -c <"$T/hullb.stl") bytes"
[ "$(od -A n -t u4 -j 80 -N 4 "$T/hullb.stl" | tr -d ' ')" = 256 ] && ok || no "stl -b: count"
# a tolerance: more facets for a finer one
n1=$($B/tocad -f stl -t 0.1 "$T/hull.patch" | grep -c 'facet normal')
n2=$($B/tocad -f stl -t 0.01 "$T/hull.patch" | grep -c 'facet normal')
[ "$n2" -gt "$n1" ] && [ "$n1" -ge 2 ] && ok || no "stl -t: $n1 facets at 0.1, $n2 at 0.01"
if [ -n "$ADMESH" ]; then
	# admesh's exact check: disconnected edges only on the boundary,
	# and no facet it must reverse to orient the mesh
	for f in hull.stl hullb.stl tee.stl rev.stl; do
		admesh -e "$T/$f" >"$T/adm" 2>&1
		b=$(awk -F: '/disconnected edge/ { n = $2 + 0; k = /1 disc/ ? 1 : /2 disc/ ? 2 : 3; s += k * n }
		    END { print s + 0 }' "$T/adm")
		want=$([ $f = tee.stl ] && echo 35 || echo 48)
		[ "$b" = "$want" ] && ok || no "admesh -e $f: $b disconnected edges, want $want: $(grep disconnected "$T/adm")"
		admesh -d "$T/$f" >"$T/adm" 2>&1
		grep -q 'Facets reversed *: *0$' "$T/adm" && ok ||
		    no "admesh -d $f: $(grep -i reversed "$T/adm")"
	done
else
	echo "tocad: skipped: no admesh"
fi

# ---- bad records: a message, the rest written, exit 1 -------------------------

{ cat "$T/ins.cubic"; cat "$T/hull.patch"; } >"$T/mixed"
run "$B/tocad -f dxf $T/mixed"
status 1
says "tocad: $T/mixed:"
says "a patch record is a surface: DXF takes curves and points"
[ "$(grep -c 'a patch record' "$T/err")" -eq 2 ] && ok || no "dxf: not one message a patch"
v=$(dxf_valid "$T/out") && ok || no "dxf with patches left out: $v"
$B/tocad -f dxf "$T/ins.cubic" | cmp -s - "$T/out" && ok || no "dxf: the curve's document changed by the patches left out"
run "$B/tocad -f svg $T/mixed"
status 1
says "a patch record is a surface: SVG takes curves"
tail -n 1 "$T/out" | grep -q '^</svg>$' && ok || no "svg: not whole"
{ cat man/figures/insole.knots; echo; cat "$T/hull.patch"; } >"$T/mixed2"
run "$B/tocad -f step $T/mixed2"
status 1
says "a point record is a set of knots, no curve (fit one with splinefit first): STEP takes curves and surfaces"
v=$(step_valid "$T/out") && ok || no "step with knots left out: $v"
[ "$(grep -c B_SPLINE_SURFACE "$T/out")" -eq 2 ] && ok || no "step: the patches not written"
run "$B/tocad -f stl $T/mixed"
status 1
says "a cubic record is a curve: STL takes surfaces"
fails 1 "tocad: nothing to draw" "$B/tocad -f dxf $T/hull.patch"
fails 1 "tocad: nothing to draw" "$B/tocad -f svg /dev/null"
# P_B - P'_B/3 is beyond the largest double
printf 'cubic\n0 0 1.7e308 0 0 0 -1.7e308 0\n' >"$T/huge"
run "$B/tocad -f step $T/huge $T/ins.cubic"
status 1
says "coefficients too large"
step_eval "$T/out" "$T/ins.pts" >"$T/val"; within "step: the good curve after a bad one" 3e-12
run "$B/tocad -f dxf -t 1e-9 $T/ins.cubic"
status 1
says "needs more than 65536 steps a piece"
# issue 28: a tolerance below the rounding of the coordinates (1e-12 of
# the size, 283 here) is refused by the one check every -t has
run "$B/tocad -f dxf -t 1e-300 $T/ins.cubic"
status 1
says "tolerance 1e-300 is below 1e-12 of the size 282.9"

# ---- OBJ ---------------------------------------------------------------------

# obj_check FILE: OBJ parsed by its definition (v x y z; l, p and f
# elements of 1-based vertex indices) with every vertex checked against
# the hyperbolic paraboloid z = x y that the bilinear patch through
# (0,0,0) (1,0,0) (0,1,0) (1,1,1) is: "vertices faces lines points
# bad-indices unused-vertices worst-|z-xy|"
obj_check() {
	awk '$1 == "v" { nv++; x[nv] = $2; y[nv] = $3; z[nv] = $4; next }
	$1 == "f" || $1 == "l" || $1 == "p" {
		n[$1]++
		for (i = 2; i <= NF; i++) {
			if ($i !~ /^[0-9]+$/ || $i < 1 || $i > nv) bad++
			used[$i] = 1
		}
		next }
	$1 != "o" && NF { bad++ }
	END { for (i = 1; i <= nv; i++) { if (!(i in used)) unused++
		e = z[i] - x[i] * y[i]; if (e < 0) e = -e; if (e > w) w = e }
	    printf "%d %d %d %d %d %d %.3g\n", nv, n["f"], n["l"], n["p"],
	        bad, unused, w }' "$1"
}
$B/patchnew -c 0,0,0 -c 1,0,0 -c 0,1,0 -c 1,1,1 >"$T/saddle.patch"
run "$B/tocad -f obj -n 6 $T/saddle.patch"
cp "$T/out" "$T/saddle.obj"
set -- $(obj_check "$T/saddle.obj")
# one patch of 6 x 6 steps: 49 vertices, 72 triangles
[ "$1 $2 $3 $4 $5 $6" = "49 72 0 0 0 0" ] && ok ||
    no "obj: vertices faces lines points bad unused: $*, want 49 72 0 0 0 0"
echo "$7" >"$T/val"; within "obj: vertices on z = x y" 1e-14
# a curve and knots beside the surface: their own elements, indices on
printf '0 0\n1 1\n2 0\n' >"$T/three.knots"
run "$B/tocad -f obj -n 4 $T/saddle.patch $T/three.knots $T/space.cubic"
set -- $(awk '$1 != "v" || NF == 4' "$T/out" | obj_check /dev/stdin)
[ "$3 $4 $5" = "1 1 0" ] && ok || no "obj: lines points bad: $3 $4 $5, want 1 1 0"
grep -q '^o points$' "$T/out" && grep -q '^o surfaces$' "$T/out" && ok ||
    no "obj: no objects named points and surfaces"
# sample -f obj goes through the same format: each surface its own mesh
$B/sample -f obj -n 6 "$T/saddle.patch" "$T/saddle.patch" >"$T/s.obj"
set -- $(obj_check "$T/s.obj")
[ "$1 $2 $5 $6" = "98 144 0 0" ] && ok ||
    no "sample -f obj: vertices faces bad unused: $1 $2 $5 $6, want 98 144 0 0"
echo "$7" >"$T/val"; within "sample -f obj: vertices on z = x y" 1e-14

# ---- units and determinism ---------------------------------------------------

# the stream scaled by 1e-3: the same polyline (the default tolerance is
# relative), every number scaled
awk '/^[a-z]/ || !NF { print; next } { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * 1e-3); print }' \
    "$T/ins.cubic" >"$T/small.cubic"
$B/tocad -f dxf "$T/small.cubic" | dxf_vertices - >"$T/small.poly"
dxf_vertices "$T/insd.dxf" >"$T/poly"
[ "$(wc -l <"$T/small.poly")" -eq "$(wc -l <"$T/poly")" ] && ok ||
    no "dxf: $(wc -l <"$T/small.poly") vertices at 1e-3 scale, $(wc -l <"$T/poly") at 1"
paste -d ' ' "$T/small.poly" "$T/poly" | awk '{ e = sqrt(($1 - 1e-3 * $3)^2 + ($2 - 1e-3 * $4)^2)
    cnt++; if (e > w) w = e } END { print w / 0.265 }' >"$T/val"; within "dxf: vertices scale with the input" 1e-14
$B/tocad -f iges "$T/tee.patch" | cmp -s - "$T/tee.igs" && ok || no "iges: not the same bytes twice"

finish tocad
