#!/bin/sh
# stepiges.sh: fromcad's STEP and IGES readers, and tocad's STEP and
# IGES as sewn shells.  References: the records tocad was given (a round trip
# comes back to rounding, by sampling both at the same parameters);
# closed forms for conics written by hand; OpenCASCADE (python3-gmsh)
# for files it writes, its own evaluation of its surfaces, and its
# reading and evaluation of tocad's shells (vertices, edges, faces,
# volumes; each face at loft's parameters).  What needs gmsh
# skips with one line when it is missing.
# The last line is "stepiges: N passed, M failed".

T=bin/test/stepiges
. tests/lib.sh

# a python that has module $1, or nothing
python_with() {
	for p in /usr/bin/python3 python3; do
		if command -v "$p" >/dev/null 2>&1 && "$p" -c "import $1" \
		    2>/dev/null; then
			echo "$p"
			return
		fi
	done
}
OCCPY=$(python_with gmsh)

# within WHAT LIMIT: $T/val holds the worst error; at most LIMIT
within() {
	read -r e <"$T/val"
	awk -v e="$e" -v l="$2" 'BEGIN { exit !(e ~ /^[0-9.]+([eE][-+]?[0-9]+)?$/ &&
	    e + 0 <= l + 0) }' &&
	    ok || no "$1: error '$e', want at most $2"
}

# same A B: the largest difference between the rows of numbers of A and
# B (sample's output), a row equal to the one before dropped (where a
# curve of one record comes back as pieces, their joints are twice),
# over the largest coordinate; "count" when the rows do not pair up
same() {
	awk '
	function keep(f, i,    s, k, n) { s = $0; n = NF
		if (n == 0) return
		if (s == last[f]) return
		last[f] = s; R[f, ++N[f]] = s; W[f, N[f]] = n }
	FNR == 1 { f++ }
	{ keep(f) }
	END { if (N[1] != N[2] || N[1] == 0) { print "count " N[1] " " N[2]; exit }
		for (i = 1; i <= N[1]; i++) {
			n = split(R[1, i], a, " "); split(R[2, i], b, " ")
			for (k = 1; k <= n; k++) { d = a[k] - b[k]; if (d < 0) d = -d
				if (d > w) w = d; m = a[k] < 0 ? -a[k] : a[k]; if (m > big) big = m } }
		print (big > 0 ? w / big : w) }' "$1" "$2"
}

# ---- the inputs -----------------------------------------------------------

$B/splinefit man/figures/insole.knots >"$T/ins.cubic"
printf '0 0 0\n10 5 2\n20 0 4\n30 -5 3\n' | $B/splinefit -o >"$T/space.cubic"
printf 'quartic id=7\n0 0 10 0 0 12 0 -12 5 4\n10 0 20 4 0 -12 3 2 1 1\n' \
    >"$T/q.quartic"
printf 'bezier\n0 0 1\n2 6 0\n5 -4 2\n7 8 1\n9 -3 0\n12 1 3\n' >"$T/b5.bezier"
$B/patchnew -c 0,0,0 -c 10,0,0 -c 0,10,0 -c 10,10,5 | $B/patchsplit -u 0.5 |
    $B/patchdrag -i 2 -u 0.5 -v 0.5 -b 0,0,3 >"$T/hull.patch"
printf 'bezier-surface m=2 n=1\n0 0 0\n0 4 1\n2 0 3\n2 4 -1\n5 1 0\n5 5 2\n' \
    >"$T/bs.surf"

# ---- round trips: tocad's STEP and IGES come back to rounding -------------

for fmt in step iges; do
	for r in ins.cubic space.cubic q.quartic b5.bezier hull.patch bs.surf; do
		run "$B/tocad -f $fmt $T/$r | $B/fromcad"
		status 0
		$B/sample -n 7 "$T/$r" >"$T/a"
		$B/sample -n 7 "$T/out" >"$T/b" 2>"$T/err" && ok ||
		    no "$fmt $r: fromcad's records not sampled: $(head -2 "$T/err")"
		same "$T/a" "$T/b" >"$T/val"
		within "$fmt round trip of $r (relative)" 1e-12
	done
	# a file named on the line, told from its content
	$B/tocad -f $fmt "$T/bs.surf" >"$T/x.$fmt"
	run "$B/fromcad $T/x.$fmt"
	status 0
	grep -q '^bezier-surface .*m=2 n=1' "$T/out" && ok ||
	    no "$fmt: not told from its content: $(head -1 "$T/out")"
done

# ---- units: STEP's and IGES's length unit, read into millimetres ----------
# tocad writes millimetres; with the file's unit rewritten, fromcad's
# numbers are the millimetre ones times the unit's millimetres (a closed
# form: 1 in = 25.4 mm, 1 m = 1000 mm, 1 cm = 10 mm)

# scaled A B K: the largest difference between B's numbers and K times
# A's, field by field (words must be equal), over B's largest number;
# "count" when the lines or fields do not pair up
scaled() {
	awk -v k="$3" '
	FNR == 1 { f++ }
	{ L[f, FNR] = $0; N[f] = FNR }
	END { if (N[1] != N[2] || N[1] == 0) { print "count"; exit }
		for (i = 1; i <= N[1]; i++) {
			n = split(L[1, i], a, " ")
			if (split(L[2, i], b, " ") != n) { print "count"; exit }
			for (j = 1; j <= n; j++) {
				if (a[j] !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/) {
					if (a[j] != b[j]) { print "count"; exit }
					continue }
				d = b[j] - k * a[j]; if (d < 0) d = -d
				m = b[j] < 0 ? -b[j] : b[j]
				if (d > w) w = d; if (m > big) big = m } }
		print (big > 0 ? w / big : w) }' "$1" "$2"
}
cat "$T/space.cubic" "$T/bs.surf" >"$T/u.in"
$B/tocad -f step "$T/u.in" >"$T/u.step"
$B/tocad -f iges "$T/u.in" >"$T/u.igs"
$B/fromcad "$T/u.step" >"$T/u.mm" 2>"$T/err" && [ ! -s "$T/err" ] && ok ||
    no "units: tocad's millimetre STEP: $(head -2 "$T/err")"
$B/fromcad "$T/u.igs" >"$T/u.gmm" 2>"$T/err" && [ ! -s "$T/err" ] && ok ||
    no "units: tocad's millimetre IGES: $(head -2 "$T/err")"
# unitcheck WHAT FILE FACTOR: fromcad reads FILE, exit 0, its numbers are
# the millimetre file's (of its format) times FACTOR to 1e-15
unitcheck() {
	run "$B/fromcad $2"
	status 0
	case $2 in *.igs) ref=$T/u.gmm ;; *) ref=$T/u.mm ;; esac
	scaled "$ref" "$T/out" "$3" >"$T/val"
	within "units: $1 (x $3)" 1e-15
}
mmunit='SI_UNIT(\.MILLI\.,\.METRE\.)'
sed "s/$mmunit/SI_UNIT(\$,.METRE.)/" "$T/u.step" >"$T/u-m.step"
unitcheck "STEP in metres" "$T/u-m.step" 1000
sed "s/$mmunit/SI_UNIT(.CENTI.,.METRE.)/" "$T/u.step" >"$T/u-cm.step"
unitcheck "STEP in centimetres" "$T/u-cm.step" 10
# an inch: a conversion of 25.4 millimetres
sed "s/^#10=.*/#10=(CONVERSION_BASED_UNIT('INCH',#900002)LENGTH_UNIT()NAMED_UNIT(#900003));\\
#900001=(LENGTH_UNIT()NAMED_UNIT(*)$mmunit);\\
#900002=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#900001);\\
#900003=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);/" "$T/u.step" \
    >"$T/u-in.step"
unitcheck "STEP in inches (a conversion of the millimetre)" "$T/u-in.step" 25.4
for u in in m cm; do
	$B/tocad -f step -u $u "$T/u.in" >"$T/tu.step"
	$B/tocad -f iges -u $u "$T/u.in" >"$T/tu.igs"
	k=$(case $u in in) echo 25.4 ;; m) echo 1000 ;; *) echo 10 ;; esac)
	unitcheck "tocad -u $u, STEP" "$T/tu.step" $k
	unitcheck "tocad -u $u, IGES" "$T/tu.igs" $k
done
# a unit loft does not read: a note naming it, the numbers kept, exit 0
sed "s/^#10=.*/#10=(CONVERSION_BASED_UNIT('FURLONG',#900002)LENGTH_UNIT()NAMED_UNIT(*));/" \
    "$T/u.step" >"$T/u-fur.step"
unitcheck "STEP in an unknown unit" "$T/u-fur.step" 1
says "length unit #10 'FURLONG'"
says "coordinates kept as the file has them"

# igesunit FLAG,NAME: u.igs with global parameters 14 and 15 so (its
# resolution, 19, shortened to keep the line in 72 columns)
igesunit() {
	awk -v new="$1" '/G      2$/ { b = substr($0, 1, 72)
		sub(/^2,2HMM,/, new ",", b); sub(/,[0-9.]+E-[0-9]+,/, ",1E-09,", b)
		printf "%-72sG%7d\n", b, 2; next } { print }' "$T/u.igs"
}
for c in "1,2HIN 25.4" "6,1HM 1000" "10,2HCM 10" "3,4HINCH 25.4" \
    "9,2HUM 0.001" "4,2HFT 304.8"; do
	set -- $c
	igesunit "$1" >"$T/u-g.igs"
	unitcheck "IGES unit flag and name $1" "$T/u-g.igs" "$2"
done
igesunit "3,4HFURL" >"$T/u-g.igs"
unitcheck "IGES in an unknown unit" "$T/u-g.igs" 1
says "unit flag 3 names unit 'FURL'"
igesunit "12,2HMM" >"$T/u-g.igs"
unitcheck "IGES with flag 12" "$T/u-g.igs" 1
says "unit flag '12' is no IGES unit"
# no global section at all (a fuzzer's file): the numbers kept, a note
# (the reader took an offset of the absent section's null pointer,
# which check-san's UndefinedBehaviorSanitizer reports)
grep -v 'G *[0-9]*$' "$T/u.igs" >"$T/u-nog.igs"
unitcheck "IGES without a global section" "$T/u-nog.igs" 1
says "no unit flag: coordinates kept as the file has them"

# ---- STEP written by hand: conics, rational forms, trims ------------------

step_doc() {
	printf 'ISO-10303-21;\nHEADER;\nFILE_SCHEMA((%s));\nENDSEC;\nDATA;\n' \
	    "'AUTOMOTIVE_DESIGN'"
	cat
	printf 'ENDSEC;\nEND-ISO-10303-21;\n'
}
# a circle of radius 5 about (1,2,3) in a tilted plane; a quarter arc of
# it trimmed by parameter; a rational B-spline quarter circle of radius
# 2 in the complex-entity form; a line trimmed by points; an ellipse
step_doc >"$T/conic.step" <<'EOF'
#1=CARTESIAN_POINT('',(1.,2.,3.));
#2=DIRECTION('',(0.,0.6,0.8));
#3=DIRECTION('',(1.,0.,0.));
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);
#5=CIRCLE('c',#4,5.);
#6=TRIMMED_CURVE('t',#5,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.5707963267948966)),.T.,.PARAMETER.);
#10=CARTESIAN_POINT('',(2.,0.,0.));
#11=CARTESIAN_POINT('',(2.,2.,0.));
#12=CARTESIAN_POINT('',(0.,2.,0.));
#13=(BOUNDED_CURVE()B_SPLINE_CURVE(2,(#10,#11,#12),.CIRCULAR_ARC.,.F.,.F.)B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.,1.),.UNSPECIFIED.)CURVE()GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE((1.,0.7071067811865476,1.))REPRESENTATION_ITEM(''));
#20=CARTESIAN_POINT('',(0.,0.,0.));
#21=DIRECTION('',(1.,1.,0.));
#22=VECTOR('',#21,1.);
#23=LINE('',#20,#22);
#24=CARTESIAN_POINT('',(1.,1.,0.));
#25=CARTESIAN_POINT('',(3.,3.,0.));
#26=TRIMMED_CURVE('',#23,(#24),(#25),.T.,.CARTESIAN.);
#30=ELLIPSE('e',#4,4.,2.);
#40=GEOMETRIC_SET('',(#5,#6,#13,#26,#30));
EOF
run "$B/fromcad -t 1e-9 $T/conic.step"
status 0
[ "$(grep -c '^cubic' "$T/out")" -eq 5 ] && ok || no "conics: $(grep -c '^cubic' "$T/out") curves, want 5"
$B/sample -n 50 "$T/out" >"$T/pts"
# each curve's points against its closed form, in the record's order
awk -v c="1 2 3" '
	BEGIN { cx = 1; cy = 2; cz = 3; nx = 0; ny = 0.6; nz = 0.8 }
	NF == 0 { if (!gap) rec++; gap = 1; next }
	{ gap = 0; r = rec + 1; x = $1 - cx; y = $2 - cy; z = $3 - cz
	  if (r <= 2) { d = sqrt(x*x + y*y + z*z) - 5; e = x*nx + y*ny + z*nz }
	  else if (r == 3) { d = sqrt($1*$1 + $2*$2) - 2; e = $3 }
	  else if (r == 4) { d = $1 - $2; e = ($1 < 1 - 1e-12 || $1 > 3 + 1e-12) ? 1 : $3 }
	  else { u = x; v = y * 0.8 - z * 0.6; d = sqrt((u/4)^2 + (v/2)^2) - 1; e = x*nx + y*ny + z*nz }
	  if (d < 0) d = -d; if (e < 0) e = -e; if (d > w) w = d; if (e > w) w = e
	  if (r == 2 && (x < -1e-9 || $2 - cy < -1e-9)) w = 9 }
	END { print w + 0 }' "$T/pts" >"$T/val"
within "conics against their closed forms (-t 1e-9)" 1e-9
# the quarter arc (the second record) runs from parameter 0, (6,2,3), to
# a quarter turn on, (1,6,0): o + 5 y with y = z x x = (0,0.8,-0.6)
awk 'NF == 0 { if (!gap) rec++; gap = 1; next } { gap = 0 }
    rec == 1 { if (!n++) a = $0; b = $0 }
    END { split(a, p, " "); split(b, q, " ")
	print sqrt((p[1]-6)^2 + (p[2]-2)^2 + (p[3]-3)^2) + sqrt((q[1]-1)^2 + (q[2]-6)^2 + q[3]^2) }' \
    "$T/pts" >"$T/val"
within "the trimmed arc's ends" 1e-12

# a rational B-spline surface (a quarter cylinder of radius 3, height 2)
step_doc >"$T/cyl.step" <<'EOF'
#1=CARTESIAN_POINT('',(3.,0.,0.));
#2=CARTESIAN_POINT('',(3.,0.,2.));
#3=CARTESIAN_POINT('',(3.,3.,0.));
#4=CARTESIAN_POINT('',(3.,3.,2.));
#5=CARTESIAN_POINT('',(0.,3.,0.));
#6=CARTESIAN_POINT('',(0.,3.,2.));
#7=(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,1,((#1,#2),(#3,#4),(#5,#6)),.UNSPECIFIED.,.F.,.F.,.F.)B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.)GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(((1.,1.),(0.7071067811865476,0.7071067811865476),(1.,1.)))REPRESENTATION_ITEM('')SURFACE());
#8=GEOMETRIC_SET('',(#7));
EOF
run "$B/fromcad -t 1e-6 $T/cyl.step"
status 0
$B/sample -n 6 "$T/out" | awk 'NF { d = sqrt($1*$1 + $2*$2) - 3; if (d < 0) d = -d
    if ($3 < -1e-12 || $3 > 2 + 1e-12) d = 1; if (d > w) w = d } END { print w + 0 }' >"$T/val"
within "rational surface within -t 1e-6 of the cylinder" 1e-6

# bad STEP: each says what and where, and exits 1
step_doc >"$T/bad.step" <<'EOF'
#1=CARTESIAN_POINT('',(0.,0.,0.));
#2=CARTESIAN_POINT('',(1.,0.,0.));
#3=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(1.,0.),.UNSPECIFIED.);
#4=B_SPLINE_CURVE_WITH_KNOTS('',70,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);
#5=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#9),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);
#6=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,3),(0.,1.),.UNSPECIFIED.);
#7=B_SPLINE_CURVE_WITH_KNOTS('good',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);
#8=GEOMETRIC_SET('',(#3,#4,#5,#6,#7));
EOF
run "$B/fromcad $T/bad.step"
status 1
says "bad.step:8: knot 3 decreases"
says "#4: its degree (1 to 63) or control points cannot be read"
says "#5: its degree"
says "#6: its knots and multiplicities do not make 4 knots"
grep -q '^cubic name=good' "$T/out" && ok || no "bad step: the good curve not read: $(head -2 "$T/out")"
# a trimmed curve trimming itself (a fuzzer's file): said and passed
# over, the circle beside it read.  Its sense (.T.) was read from the
# parsed values before its basis was parsed, which can move them:
# check-san's AddressSanitizer reported the read after the move
step_doc >"$T/self.step" <<'EOF'
#1=CARTESIAN_POINT('',(1.,2.,3.));
#2=DIRECTION('',(0.,0.6,0.8));
#3=DIRECTION('',(1.,0.,0.));
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);
#5=CIRCLE('c',#4,5.);
#6=TRIMMED_CURVE('t',#6,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.5707963267948966)),.T.,.PARAMETER.);
#7=GEOMETRIC_SET('',(#5,#6));
EOF
run "$B/fromcad $T/self.step"
status 1
says "self.step:11: #6: a trimmed curve whose basis is no line, circle or ellipse, passed over"
[ "$(grep -c '^cubic' "$T/out")" -eq 1 ] && ok ||
    no "self.step: $(grep -c '^cubic' "$T/out") curves, want the circle"
run "printf 'ISO-10303-21;\nDATA;\nENDSEC;\n' | $B/fromcad"
fails 1 "no entity instances" "printf 'ISO-10303-21;\nDATA;\nENDSEC;\n' | $B/fromcad"
fails 1 "not a document fromcad reads (dxf|svg|csv|step|iges; -f names the format)" "echo hello | $B/fromcad"

# ---- files OpenCASCADE writes (through gmsh), checked by its own evaluation

if [ -n "$OCCPY" ]; then
	cat >"$T/occgen.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
occ = gmsh.model.occ
def save(name):
    occ.synchronize()
    gmsh.write(sys.argv[1] + "/" + name + ".step")
    gmsh.model.remove()
gmsh.model.add("box"); occ.addBox(1, 2, 3, 4, 5, 6); save("box")
gmsh.model.add("cyl"); occ.addCylinder(0, 0, 0, 0, 0, 3, 1.5); save("cyl")
gmsh.model.add("sph"); occ.addSphere(0, 0, 0, 2); save("sph")
gmsh.model.add("fil"); occ.addBox(0, 0, 0, 2, 2, 2); occ.synchronize()
occ.fillet([1], [1, 2], [0.3]); save("fil")
# 6 x 5 points of degree 3: 3 x 2 spans, knots 0..3 and 0..2
gmsh.model.add("bs")
p = [occ.addPoint(i, j, 0.2 * ((i - 2.5) ** 2 - (j - 2) ** 2 + i * j / 3.0))
     for j in range(5) for i in range(6)]
occ.addBSplineSurface(p, 6, degreeU=3, degreeV=3); save("bs")
gmsh.model.add("rat")
p = [occ.addPoint(i, j, 0.5 * ((i + j) % 2)) for j in range(3) for i in range(4)]
w = [1 + 0.5 * ((3 * k) % 4) for k in range(12)]
occ.addBSplineSurface(p, 4, degreeU=2, degreeV=2, weights=w); save("rat")
gmsh.finalize()
PY
	# occcheck.py FILE PTS: "faces points worst": the largest distance
	# from PTS's points to the surfaces of FILE as OpenCASCADE evaluates
	# them (getValue at the parameters of the nearest point), over the
	# model's size
	cat >"$T/occcheck.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
faces = [t for d, t in gmsh.model.getEntities(2)]
pts = [[float(x) for x in l.split()[:3]] for l in open(sys.argv[2]) if l.strip()]
worst = 0.0
for p in pts:
    best = 1e300
    for t in faces:
        q = gmsh.model.getClosestPoint(2, t, p)[0]
        try:
            q = gmsh.model.getValue(2, t, gmsh.model.getParametrization(2, t, q))
        except Exception:
            pass
        best = min(best, sum((q[k] - p[k]) ** 2 for k in range(3)) ** 0.5)
    worst = max(worst, best)
b = gmsh.model.getBoundingBox(-1, -1)
size = sum((b[k + 3] - b[k]) ** 2 for k in range(3)) ** 0.5
print(len(faces), len(pts), worst / size)
gmsh.finalize()
PY
	# occspan.py FILE RECORDS SU SV: the Bezier patches of RECORDS, span
	# (a, b) u-major, evaluated here (Bernstein sums) at a 7 x 7 grid
	# against OpenCASCADE's getValue at (a + s, b + r); the worst distance
	cat >"$T/occspan.py" <<'PY'
import sys, gmsh
from math import comb
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
recs, cur = [], None
for l in open(sys.argv[2]):
    w = l.split()
    if not w:
        cur = None
    elif w[0] == "bezier-surface":
        a = dict(x.split("=") for x in w[1:])
        cur = [int(a["m"]), int(a["n"]), []]
        recs.append(cur)
    else:
        cur[2].append([float(x) for x in w])
su, sv = int(sys.argv[3]), int(sys.argv[4])
t = gmsh.model.getEntities(2)[0][1]
worst = 0.0 if len(recs) == su * sv else 1e300
for k, (m, n, P) in enumerate(recs[:su * sv]):
    a, b = k // sv, k % sv
    for i in range(7):
        for j in range(7):
            s, r = i / 6.0, j / 6.0
            x = [sum(comb(m, p) * s ** p * (1 - s) ** (m - p) *
                     comb(n, q) * r ** q * (1 - r) ** (n - q) *
                     P[p * (n + 1) + q][c] for p in range(m + 1)
                     for q in range(n + 1)) for c in range(3)]
            y = gmsh.model.getValue(2, t, [a + s, b + r])
            worst = max(worst, sum((x[c] - y[c]) ** 2 for c in range(3)) ** 0.5)
print(len(recs), worst)
gmsh.finalize()
PY
	mkdir -p "$T/occ"
	"$OCCPY" "$T/occgen.py" "$T/occ" >/dev/null 2>&1
	# file, -t, the records wanted, the largest deviation over the size,
	# sample's steps (rat's -t 1e-3 is 2.7e-4 of its size, 3.6)
	for c in box:0:6:1e-14:5 bs:0:6:1e-14:5 cyl:0:2:1e-14:5 \
	    fil:0:6:1e-14:5 rat:1e-3:0:2.7e-4:2; do
		set -- $(echo "$c" | tr : ' ')
		topt=; [ "$2" = 0 ] || topt="-t $2"
		$B/fromcad $topt "$T/occ/$1.step" >"$T/occ/$1.loft" 2>"$T/err"
		n=$(grep -c '^bezier-surface' "$T/occ/$1.loft")
		[ "$3" = 0 ] || [ "$n" = "$3" ] && ok ||
		    no "OpenCASCADE's $1.step: $n surfaces, want $3"
		$B/sample -n "$5" "$T/occ/$1.loft" >"$T/occ/$1.pts"
		set -- $("$OCCPY" "$T/occcheck.py" "$T/occ/$1.step" \
		    "$T/occ/$1.pts" 2>/dev/null | tail -n 1) "$4" "$1"
		echo "$3" >"$T/val"
		within "OpenCASCADE's $5.step: $2 points off its faces" "$4"
	done
	# what is passed over is said, with exit 1
	run "$B/fromcad $T/occ/cyl.step"
	status 1
	says "1 CYLINDRICAL_SURFACE item passed over"
	run "$B/fromcad $T/occ/sph.step"
	status 1
	says "1 SPHERICAL_SURFACE item passed over"
	# the B-spline's spans, patch by patch, at OpenCASCADE's parameters
	set -- $("$OCCPY" "$T/occspan.py" "$T/occ/bs.step" "$T/occ/bs.loft" 3 2 \
	    2>/dev/null | tail -n 1)
	[ "$1" = 6 ] && ok || no "OpenCASCADE's bs.step: $1 patches, want 6"
	echo "$2" >"$T/val"
	within "OpenCASCADE's bs.step: patches against getValue by span" 1e-14
else
	echo "stepiges: skipped: no python3-gmsh (OpenCASCADE): its files, shells and degree 63"
fi

# ---- tocad's STEP and IGES as sewn shells -----------------------------------

# a closed box of six bilinear patches, each normal inward (cubeflip.surf
# below is the same box with its normals out)
cat >"$T/cube.surf" <<'EOF'
bezier-surface m=1 n=1
0 0 0
0 1 0
2 0 0
2 1 0

bezier-surface m=1 n=1
0 0 3
2 0 3
0 1 3
2 1 3

bezier-surface m=1 n=1
0 0 0
2 0 0
0 0 3
2 0 3

bezier-surface m=1 n=1
0 1 0
0 1 3
2 1 0
2 1 3

bezier-surface m=1 n=1
0 0 0
0 0 3
0 1 0
0 1 3

bezier-surface m=1 n=1
2 0 0
2 1 0
2 0 3
2 1 3
EOF
# hull.patch with patch 3's numbers moved by rounding (a part in 1e15):
# its shared side is no longer the same points, but its link still says
# it is shared; and without the links, two sides
awk '/^patch id=3/ { p = 1 } /^$/ { p = 0 } !p || /^patch/ { print; next }
    { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * (1 + 1e-15)); print }' \
    "$T/hull.patch" >"$T/nudged.patch"
sed -E 's/ (u0|u1|v0|v1)=[0-9]+//g' "$T/nudged.patch" >"$T/unlinked.patch"
# shellcount FILE: "faces edges vertices shell loose", counted in a STEP
# or IGES file itself: its faces, edges and vertices; its shell, CLOSED
# (STEP: a CLOSED_SHELL; IGES: a shell (514) of form 1 in a manifold
# solid (186)) or OPEN (an OPEN_SHELL; a 514 of form 2 and no 186) or
# NONE; and its surfaces in no face (STEP: B-spline surfaces beyond the
# faces; IGES: 128s not subordinate)
shellcount() {
	case $1 in
	*.step) awk '/ADVANCED_FACE/ { f++ } /EDGE_CURVE/ { e++ }
	    /VERTEX_POINT/ { v++ } /B_SPLINE_SURFACE_WITH_KNOTS/ { b++ }
	    /CLOSED_SHELL/ { s = "CLOSED" } /OPEN_SHELL/ { s = "OPEN" }
	    END { print f + 0, e + 0, v + 0, s ? s : "NONE", b - f }' "$1" ;;
	# IGES: the Face entities (510), the counts of the Edge List (504)
	# and the Vertex List (502), whose parameters begin a line
	*) awk 'substr($0, 73, 1) == "D" { d++; t = substr($0, 1, 8) + 0
		if (d % 2) { st = substr($0, 67, 2) } else {
			f = substr($0, 33, 8) + 0
			if (t == 510) nf++; if (t == 186) solid++
			if (t == 514) { shells++; form = f }
			if (t == 128 && st == "00") loose++ } }
	    substr($0, 73, 1) == "P" { split($0, w, ",")
		if (w[1] == "504") ne = w[2]; if (w[1] == "502") nv = w[2] }
	    END { s = "NONE"
		if (shells == 1 && form == 1 && solid == 1) s = "CLOSED"
		if (shells == 1 && form == 2 && !solid) s = "OPEN"
		print nf + 0, ne + 0, nv + 0, s, loose + 0 }' "$1" ;;
	esac
}
# the same box with each patch's u and v swapped: its normals the other
# way round
awk '/^bezier/ { r = 0; print; next } NF == 3 { R[++r] = $0
    if (r == 4) print R[1] "\n" R[3] "\n" R[2] "\n" R[4]; next } { print }' \
    "$T/cube.surf" >"$T/cubeflip.surf"
# a box 3 x 3 x 3 of bicubic patches (cube.surf's, stretched, made
# cubic; their points on whole numbers, so that sides meet exactly), the
# top's four inner points raised by 1: its volume is 27 + 9/4 = 29.25
# (each inner Bernstein function of degree 3 averages 1/4)
awk '/^bezier/ { r = 0; rec++; next }
    NF == 3 { P[++r] = ($1 * 3 / 2) " " ($2 * 3) " " $3; if (r < 4) next
	split(P[1], a); split(P[2], b); split(P[3], c); split(P[4], d)
	print "bezier-surface m=3 n=3"
	for (i = 0; i <= 3; i++) for (j = 0; j <= 3; j++) { l = ""
	    for (q = 1; q <= 3; q++) {
		x = (3 - i) * (3 - j) * a[q] + (3 - i) * j * b[q]
		x = (x + i * (3 - j) * c[q] + i * j * d[q]) / 9
		if (q == 3 && rec == 2 && i % 3 && j % 3) x += 1
		l = l (q > 1 ? " " : "") x }
	    print l }
	print "" }' "$T/cube.surf" >"$T/bulge.surf"
# igesshell.awk: what IGES's B-rep must hold, checked in the file: for
# each face (510), its loop's edges (508, with their senses) follow each
# other head to tail; no edge of the edge list (504) is run twice the
# same way; each edge's curve (126) begins and ends at its vertices
# (502), to 1e-10 (the designs here are about 10 across); and the loop
# turns counterclockwise about its surface's normal (its vector area,
# from the loop's control points, against the cross of the surface's
# diagonals).  Prints the faces, the counts of those
# broken, and the volume the shell (514) encloses with its faces' and
# its solid's senses, exact for plane quadrilaterals (the divergence
# theorem: a third of the sum of each plane's point times its area)
cat >"$T/igesshell.awk" <<'AWK'
# the parameters of each entity, by its directory line
substr($0, 73, 1) == "P" { k = substr($0, 66, 7) + 0; P[k] = P[k] substr($0, 1, 64) }
substr($0, 73, 1) == "D" { if (++d % 2) type[d] = substr($0, 1, 8) + 0 }
function pt(k, i, q) { return W[k, i + q] + 0 }
# the loop's vertex numbers: its edge j's start (end 0) or end (end 1)
function vtx(k, j, e,   el, x, of) { el = W[k, 4 + 5 * (j - 1)]; x = W[k, 5 + 5 * (j - 1)]
	of = W[k, 6 + 5 * (j - 1)]; return W[el, 3 + 5 * (x - 1) + ((e == of) ? 4 : 2)] }
END {
	for (k in P) { s = P[k]; gsub(/[ ;]/, "", s); sub(/,$/, "", s)
		n = split(s, w, ","); for (i = 1; i <= n; i++) W[k, i] = w[i] }
	for (k = 1; k < d; k += 2) if (type[k] == 510) {
		nl++; L = W[k, 5]; S = W[k, 2]; N = W[L, 2]
		# the loop closes head to tail
		for (j = 1; j <= N; j++)
			if (vtx(L, j, 1) != vtx(L, j % N + 1, 0)) chain++
		# each edge once each way; its curve's ends at its vertices
		area[0] = area[1] = area[2] = 0
		for (j = 1; j <= N; j++) {
			el = W[L, 4 + 5 * (j - 1)]; x = W[L, 5 + 5 * (j - 1)]
			of = W[L, 6 + 5 * (j - 1)]
			if (use[el, x, of]++) share++
			c = W[el, 3 + 5 * (x - 1)]; K = W[c, 2]; M = W[c, 3]
			o = 7 + (K + M + 2) + (K + 1)
			for (e = 0; e < 2; e++) { v = W[el, 3 + 5 * (x - 1) + 2 + 2 * e]
				vl = W[el, 3 + 5 * (x - 1) + 1 + 2 * e]
				for (q = 1; q <= 3; q++) { dd = pt(c, o + 3 * K * e, q) - pt(vl, 2 + 3 * (v - 1), q)
					if (dd * dd > 1e-20) ends++ } }
			# the loop's polygon of control points, in its sense
			for (i = 0; i <= K; i++) { ii = of ? i : K - i
				for (q = 1; q <= 3; q++) p[q] = pt(c, o + 3 * ii, q)
				if (j > 1 || i > 0) { area[0] += pr[2] * p[3] - pr[3] * p[2]
					area[1] += pr[3] * p[1] - pr[1] * p[3]; area[2] += pr[1] * p[2] - pr[2] * p[1] }
				else { for (q = 1; q <= 3; q++) p0[q] = p[q] }
				for (q = 1; q <= 3; q++) pr[q] = p[q] } }
		area[0] += pr[2] * p0[3] - pr[3] * p0[2]; area[1] += pr[3] * p0[1] - pr[1] * p0[3]
		area[2] += pr[1] * p0[2] - pr[2] * p0[1]
		# the surface's normal, the cross of its diagonals
		K1 = W[S, 2]; K2 = W[S, 3]; o = 10 + (K1 + W[S, 4] + 2) + (K2 + W[S, 5] + 2) + (K1 + 1) * (K2 + 1)
		for (q = 1; q <= 3; q++) { a[q] = pt(S, o + 3 * ((K1 + 1) * (K2 + 1) - 1), q) - pt(S, o, q)
			b[q] = pt(S, o + 3 * K2 * (K1 + 1), q) - pt(S, o + 3 * K1, q) }
		nx = a[2] * b[3] - a[3] * b[2]; ny = a[3] * b[1] - a[1] * b[3]
		nz = a[1] * b[2] - a[2] * b[1]
		if (nx * area[0] + ny * area[1] + nz * area[2] <= 0) turn++
		fl[k] = nx * pt(S, o, 1) + ny * pt(S, o, 2) + nz * pt(S, o, 3)
	}
	# the volume of a shell of plane quadrilaterals, by the divergence
	# theorem, with its faces' and its solid's senses
	for (k = 1; k < d; k += 2) if (type[k] == 514) { sh = k
		for (j = 1; j <= W[k, 2]; j++) vol += (W[k, 2 + 2 * j] ? 1 : -1) * fl[W[k, 1 + 2 * j]] / 6 }
	for (k = 1; k < d; k += 2) if (type[k] == 186 && W[k, 2] == sh && !W[k, 3]) vol = -vol
	print nl + 0, chain + 0, share + 0, ends + 0, turn + 0, vol + 0
}
AWK
# stepshell.awk: for the boxes of bilinear faces, the CLOSED_SHELL of
# tocad's STEP (an entity a line): its faces, those whose outer bound
# does not turn counterclockwise about the face's normal (the surface's,
# Su x Sv, times the face's sense), and the volume enclosed, by the
# divergence theorem from each bound's vector area and a point of it:
# a solid inside out gives it negative
cat >"$T/stepshell.awk" <<'AWK'
# tocad's STEP, one entity a line: "#n=TYPE(args);"
/^#[0-9]+=/ { n = substr($0, 2, index($0, "=") - 2); s = substr($0, index($0, "=") + 1)
	T[n] = substr(s, 1, index(s, "(") - 1); A[n] = substr(s, index(s, "(")) }
function refs(s, r,   k, m) { m = 0; while (match(s, /#[0-9]+/)) {
	r[++m] = substr(s, RSTART + 1, RLENGTH - 1); s = substr(s, RSTART + RLENGTH) } return m }
function flag(s) { return s ~ /\.T\.\);$/ }
function xyz(p,   s) { s = A[p]; sub(/^\('',\(/, "", s); sub(/\)\);$/, "", s); return split(s, X, ",") }
END {
	for (k in T) if (T[k] == "CLOSED_SHELL") { nf = refs(A[k], F)
		for (f = 1; f <= nf; f++) {
			refs(A[F[f]], fr); bound = fr[1]; surf = fr[2]
			sense = flag(A[F[f]]) ? 1 : -1
			refs(A[bound], br); sense2 = flag(A[bound]) ? 1 : -1
			refs(A[surf], sr)
			for (i = 1; i <= 4; i++) { xyz(sr[i]); for (q = 1; q <= 3; q++) P[i, q] = X[q] }
			for (q = 1; q <= 3; q++) {
				u[q] = P[3, q] - P[1, q] + P[4, q] - P[2, q]
				v[q] = P[2, q] - P[1, q] + P[4, q] - P[3, q] }
			N[1] = sense * (u[2] * v[3] - u[3] * v[2]); N[2] = sense * (u[3] * v[1] - u[1] * v[3])
			N[3] = sense * (u[1] * v[2] - u[2] * v[1])
			ne = refs(A[br[1]], E); a[1] = a[2] = a[3] = 0
			for (j = 1; j <= ne; j++) { refs(A[E[j]], er); refs(A[er[1]], cr)
				vt = flag(A[E[j]]) ? cr[1] : cr[2]; refs(A[vt], vr); xyz(vr[1]); for (q = 1; q <= 3; q++) Q[j, q] = X[q] }
			for (j = 1; j <= ne; j++) { jj = j % ne + 1
				a[1] += Q[j, 2] * Q[jj, 3] - Q[j, 3] * Q[jj, 2]
				a[2] += Q[j, 3] * Q[jj, 1] - Q[j, 1] * Q[jj, 3]
				a[3] += Q[j, 1] * Q[jj, 2] - Q[j, 2] * Q[jj, 1] }
			d = sense2 * (a[1] * N[1] + a[2] * N[2] + a[3] * N[3])
			if (d <= 0) turned++
			# the plane's flux of x / 3: its area vector, the face's way
			vol += sense2 * (a[1] * Q[1, 1] + a[2] * Q[1, 2] + a[3] * Q[1, 3]) / 6
		} }
	print nf + 0, turned + 0, vol + 0
}
AWK
for fmt in step iges; do
	for c in hull.patch:2:7:6:OPEN nudged.patch:2:7:6:OPEN \
	    unlinked.patch:2:8:8:OPEN cube.surf:6:12:8:CLOSED \
	    cubeflip.surf:6:12:8:CLOSED bulge.surf:6:12:8:CLOSED \
	    man/examples/hull.design:24:58:35:OPEN; do
		set -- $(echo "$c" | tr : ' ')
		f=$1; [ -f "$f" ] || f=$T/$1
		$B/tocad -f $fmt "$f" >"$T/sewn.$fmt"
		got=$(shellcount "$T/sewn.$fmt")
		[ "$got" = "$2 $3 $4 $5 0" ] && ok ||
		    no "$fmt shell of $1: faces edges vertices shell loose '$got', want '$2 $3 $4 $5 0'"
		if [ $fmt = iges ]; then
			set -- $(awk -f "$T/igesshell.awk" "$T/sewn.iges") "$@"
			[ "$1 $2 $3 $4 $5" = "$8 0 0 0 0" ] && ok ||
			    no "iges shell of $7: faces, loops broken, edges twice, ends off, turned '$1 $2 $3 $4 $5', want '$8 0 0 0 0'"
			# the closed boxes: 2 x 3 x 1, out (the sign of either)
			case $7 in cube*)
				echo "$6" | awk '{ d = $1 - 6; print (d < 0 ? -d : d) }' >"$T/val"
				within "iges shell of $7: the volume it encloses, 6" 1e-12 ;;
			esac
			shift 6
		else
			case $1 in cube*)
				set -- $(awk -f "$T/stepshell.awk" "$T/sewn.step") "$@"
				[ "$1 $2" = "6 0" ] && ok ||
				    no "step shell of $4: faces, bounds turned '$1 $2', want '6 0'"
				echo "$3" | awk '{ d = $1 - 6; print (d < 0 ? -d : d) }' >"$T/val"
				within "step shell of $4: the volume it encloses, 6" 1e-12
				shift 3 ;;
			esac
		fi
		# each surface once: the shell's structure and its edges'
		# curves are not read again
		run "$B/fromcad $T/sewn.$fmt"
		status 0
		[ "$(grep -c '^bezier-surface' "$T/out")" = "$2" ] &&
		    [ "$(grep -c -v -e '^bezier-surface' -e '^[-0-9]' -e '^$' \
		    "$T/out")" = 0 ] &&
		    ok || no "$fmt shell of $1: not $2 surfaces and nothing else back"
	done
done
if [ -n "$OCCPY" ]; then
	# OpenCASCADE reads one connected shell: vertices, edges, faces,
	# volumes, and the volume's size
	cat >"$T/topo.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
n = [len(gmsh.model.getEntities(d)) for d in range(4)]
v = sum(gmsh.model.occ.getMass(3, t) for d, t in gmsh.model.getEntities(3))
print(*n, "%.12g" % v)
gmsh.finalize()
PY
	# occpatch.py FILE PTS: PTS is sample -u's wireframe of the records
	# (x y z u v), a record's lines ending with two blank lines; each
	# record against the face of FILE that OpenCASCADE evaluates
	# (getValue at the same u, v) closest to it.  Prints the faces, the
	# records, the faces matched (each once), and the worst distance
	# over the model's size
	cat >"$T/occpatch.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
faces = [t for d, t in gmsh.model.getEntities(2)]
recs = [[[float(x) for x in l.split()] for l in r.splitlines() if l.strip()]
        for r in open(sys.argv[2]).read().split("\n\n\n") if r.strip()]
worst, used = 0.0, set()
for r in recs:
    best, bt = 1e300, None
    for t in faces:
        e = max(sum((a - b) ** 2 for a, b in zip(gmsh.model.getValue(
            2, t, p[3:5]), p[:3])) ** 0.5 for p in r)
        if e < best:
            best, bt = e, t
    worst = max(worst, best)
    used.add(bt)
b = gmsh.model.getBoundingBox(-1, -1)
size = sum((b[k + 3] - b[k]) ** 2 for k in range(3)) ** 0.5
print(len(faces), len(recs), len(used), worst / size)
gmsh.finalize()
PY
	for fmt in step iges; do
		for c in hull.patch:6:7:2:0:0 nudged.patch:6:7:2:0:0 \
		    unlinked.patch:8:8:2:0:0 cube.surf:8:12:6:1:6 \
		    cubeflip.surf:8:12:6:1:6 bulge.surf:8:12:6:1:29.25 \
		    man/examples/hull.design:35:58:24:0:0; do
			set -- $(echo "$c" | tr : ' ')
			f=$1; [ -f "$f" ] || f=$T/$1
			$B/tocad -f $fmt "$f" >"$T/sewn.$fmt"
			got=$("$OCCPY" "$T/topo.py" "$T/sewn.$fmt" 2>/dev/null |
			    tail -n 1)
			[ "$got" = "$2 $3 $4 $5 $6" ] && ok ||
			    no "OpenCASCADE on the $fmt shell of $1: '$got', want '$2 $3 $4 $5 $6'"
			# each face's surface at loft's parameters
			$B/sample -n 6 -u "$f" >"$T/sewn.pts"
			set -- $("$OCCPY" "$T/occpatch.py" "$T/sewn.$fmt" \
			    "$T/sewn.pts" 2>/dev/null | tail -n 1) "$4" "$1"
			[ "$1" = "$5" ] && [ "$2" = "$5" ] && [ "$3" = "$5" ] &&
			    ok || no "OpenCASCADE on the $fmt shell of $6: faces, records, matched '$1 $2 $3', want $5 each"
			echo "$4" >"$T/val"
			within "OpenCASCADE on the $fmt shell of $6: its faces at loft's (u, v)" 1e-14
		done
	done
else
	:       # said once above
fi

# ---- degrees above 25: cubic pieces within -t, which OpenCASCADE reads -----

awk 'BEGIN { print "bezier"; for (i = 0; i < 64; i++) print i, i % 2 }' \
    >"$T/b63.bezier"
awk 'BEGIN { print "bezier-surface m=30 n=2"
    for (i = 0; i <= 30; i++) for (j = 0; j <= 2; j++)
	print i, j, (i % 3) * (j == 1) }' >"$T/s30.surf"
for fmt in step iges; do
	run "$B/tocad -f $fmt -t 1e-4 $T/b63.bezier"
	status 0
	cp "$T/out" "$T/b63.$fmt"
	run "$B/fromcad $T/b63.$fmt"
	status 0
	grep -q '^cubic' "$T/out" && ok || no "$fmt: degree 63 not written as cubics"
	# every point of the cubics is within -t of the curve at the same
	# parameter: sampled at the same steps (the pieces cut the curve's
	# parameter evenly, 256 of them here)
	n=$(grep -c . "$T/out"); n=$((n - 1))
	$B/sample -n "$n" "$T/b63.bezier" >"$T/a"
	$B/sample -n 1 "$T/out" >"$T/b"
	paste -d ' ' "$T/a" "$T/b" | awk 'NF == 4 { d = sqrt(($1-$3)^2 + ($2-$4)^2)
	    if (d > w) w = d } END { print w + 0 }' >"$T/val"
	within "$fmt: degree 63 as cubics, at the pieces' ends" 1e-12
	$B/sample -n 8 "$T/out" >"$T/b"
	$B/sample -n $((8 * n)) "$T/b63.bezier" >"$T/a"
	paste -d ' ' "$T/a" "$T/b" | awk 'NF == 4 { d = sqrt(($1-$3)^2 + ($2-$4)^2)
	    if (d > w) w = d } END { print w + 0 }' >"$T/val"
	within "$fmt: degree 63 as cubics within -t 1e-4" 1e-4
	run "$B/tocad -f $fmt -t 1e-4 $T/s30.surf"
	status 0
	cp "$T/out" "$T/s30.$fmt"
done
if [ -n "$OCCPY" ]; then
	# OpenCASCADE finds the curve and the surface, and sample's points
	# of the records given lie on them within -t
	cat >"$T/occnear.py" <<'PY'
import sys, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1])
gmsh.model.occ.synchronize()
dim = int(sys.argv[3])
ents = [t for d, t in gmsh.model.getEntities(dim)]
worst = 0.0 if ents else 1e300
for l in open(sys.argv[2]):
    p = [float(x) for x in l.split()]
    if not p:
        continue
    p = (p + [0.0, 0.0])[:3]
    best = min(sum((c - q) ** 2 for c, q in zip(
        gmsh.model.getClosestPoint(dim, t, p)[0], p)) ** 0.5 for t in ents)
    worst = max(worst, best)
print(len(ents), worst)
gmsh.finalize()
PY
	$B/sample -n 100 "$T/b63.bezier" >"$T/b63.pts"
	$B/sample -n 6 "$T/s30.surf" >"$T/s30.pts"
	for f in b63:1 s30:2; do
		for fmt in step iges; do
			set -- $("$OCCPY" "$T/occnear.py" "$T/${f%:*}.$fmt" \
			    "$T/${f%:*}.pts" "${f#*:}" 2>/dev/null | tail -n 1)
			[ "${1:-0}" -ge 1 ] && ok ||
			    no "OpenCASCADE: ${f%:*}.$fmt read as nothing"
			echo "$2" >"$T/val"
			within "OpenCASCADE: ${f%:*}.$fmt within -t 1e-4" 1e-4
		done
	done
else
	:       # said once above
fi

# ---- IGES written by hand: lines, arcs, planes, matrices, dependents -------

# iges_doc: an IGES file from lines "type form matrix-DE status params;"
# (the parameters without the type), by the fixed form: 80 columns,
# directory entries of two lines, parameters in columns 1-64 with their
# entry's line in 66-72
iges_doc() {
	awk '
	{ type[++n] = $1; form[n] = $2; mat[n] = $3; st[n] = $4
	  p = $0; sub(/^[^ ]+ [^ ]+ [^ ]+ [^ ]+ /, "", p); par[n] = $1 "," p }
	END {
	  printf "%-72sS%7d\n", "hand made", 1
	  printf "%-72sG%7d\n", "1H,,1H;,4Htest,8Htest.igs,4Htest,4Htest,32,38,6,308,15,", 1
	  printf "%-72sG%7d\n", "4Htest,1.,2,2HMM,1,1.,15H20260101.000000,1E-08,10.,4Htest,4Htest,", 2
	  printf "%-72sG%7d\n", "11,0,15H20260101.000000;", 3
	  pl = 0
	  for (i = 1; i <= n; i++) {   # parameter lines first, to count them
		s = par[i]; first[i] = pl + 1; cnt = 0
		while (length(s) > 0) { P[++pl] = sprintf("%-64s %7dP%7d", substr(s, 1, 64), 2 * i - 1, pl)
			s = substr(s, 65); cnt++ }
		lines[i] = cnt }
	  for (i = 1; i <= n; i++) {
		printf "%8d%8d%8d%8d%8d%8d%8d%8d%8sD%7d\n", type[i], first[i], 0, 0, 0, 0, mat[i], 0, st[i], 2 * i - 1
		printf "%8d%8d%8d%8d%8d%8s%8s%8s%8dD%7d\n", type[i], 0, 0, lines[i], form[i], "", "", "LABEL" i, 0, 2 * i }
	  for (k = 1; k <= pl; k++) print P[k]
	  printf "S%7dG%7dD%7dP%7d%40sT%7d\n", 1, 3, 2 * n, pl, "", 1 }'
}
# 1 (D1): a segment; 2 (D3): a matrix, a quarter turn about z and a move
# by (10,0,0); 3 (D5): an arc of radius 2 about (1,1) at z 3, from
# angle 0 to a half turn, moved by D3; 4 (D7): a full circle; 5 (D9): a
# segment that belongs to a composite curve (status 01: passed over);
# 6 (D11): that composite curve, made of 5; 7 (D13): a plane z = 1
# bounded by the composite curve and by 4; 8 (D15): a curve of a kind
# loft does not read (112)
iges_doc >"$T/hand.igs" <<'EOF'
110 0 0 00000000 0.,0.,0.,3.,4.,0.;
124 0 0 00000000 0.,-1.,0.,10.,1.,0.,0.,0.,0.,0.,1.,0.;
100 0 3 00000000 3.,1.,1.,3.,1.,-1.,1.;
100 0 0 00000000 0.,0.,0.,5.,0.,5.,0.;
110 0 0 00010000 -2.,-3.,1.,4.,6.,1.;
102 0 0 00000000 1,9;
108 1 0 00000000 0.,0.,1.,1.,11,0.,0.,0.,0.;
112 0 0 00000000 3,1,3,1,0.,1.,0.,1.,0.,0.,0.,1.,0.,0.,0.,0.,0.,0.,0.,0.,1.,1.,0.,0.,0.,0.,0.,0.,0.,0.;
EOF
run "$B/fromcad -t 1e-9 $T/hand.igs"
status 1
says "1 entities of type 112 passed over"
[ "$(grep -c '^cubic' "$T/out")" -eq 3 ] && ok || no "iges: $(grep -c '^cubic' "$T/out") curves, want 3 (the segment, the arc, the circle)"
grep -q '^bezier-surface name=LABEL7 entity=13 m=1 n=1' "$T/out" && ok ||
    no "iges: the bounded plane not read: $(grep bezier-surface "$T/out")"
$B/sample -n 40 "$T/out" >"$T/pts"
# the segment along (0,0)-(3,4); the arc: (x,y) about (1,1) radius 2 with
# y >= 1, turned a quarter (x,y) -> (-y,x) and moved by (10,0): so about
# (9,1), radius 2, x <= 9, z 3; the circle: radius 5 about the origin;
# the plane: z = 1, the box of the bounding segment, x -2..4, y -3..6
awk 'NF == 0 { if (!gap) rec++; gap = 1; next }
    { gap = 0; r = rec + 1
      if (r == 1) { d = $1 * 4 - $2 * 3; e = ($1 < -1e-12 || $1 > 3 + 1e-12) }
      else if (r == 2) { d = sqrt(($1 - 9)^2 + ($2 - 1)^2) - 2; e = ($3 - 3) + ($1 > 9 + 1e-9) }
      else if (r == 3) { d = sqrt($1^2 + $2^2) - 5; e = $3 }
      else { d = $3 - 1; e = ($1 < -2 - 1e-12 || $1 > 4 + 1e-12 || $2 < -3 - 1e-12 || $2 > 6 + 1e-12) }
      if (d < 0) d = -d; if (e < 0) e = -e; if (d > w) w = d; if (e > w) w = e }
    END { print w + 0 }' "$T/pts" >"$T/val"
within "iges by hand: segment, moved arc, circle, plane (-t 1e-9)" 1e-9
# the plane's corners reach its bounds
awk 'NF == 3 { if ($1 == -2 && $2 == -3) a = 1; if ($1 == 4 && $2 == 6) b = 1 }
    END { exit !(a && b) }' "$T/pts" && ok || no "iges: the plane does not span its bounding curve"
# bad IGES: a 126 whose counts do not fit, and a missing matrix
iges_doc >"$T/bad.igs" <<'EOF'
126 0 0 00000000 5,3,0,0,1,0,0.,1.;
110 0 9 00000000 0.,0.,0.,1.,1.,1.;
110 0 0 00000000 0.,0.,0.,1.,1.,1.;
EOF
run "$B/fromcad $T/bad.igs"
status 1
says "bad.igs:5: 126 (D1): its degree (1 to 63) or counts do not fit its 9 parameters"
says "bad.igs:7: 110 (D3): its transformation cannot be read"
[ "$(grep -c '^cubic' "$T/out")" -eq 1 ] && ok || no "bad iges: the good line not read"
if [ -n "$OCCPY" ]; then
	# OpenCASCADE reads the same entities: the points of fromcad's
	# curves lie on its curves (a file of the curves alone: with a face
	# in it, it keeps only the face), and its plane's on its face
	iges_doc >"$T/handc.igs" <<'EOF'
110 0 0 00000000 0.,0.,0.,3.,4.,0.;
124 0 0 00000000 0.,-1.,0.,10.,1.,0.,0.,0.,0.,0.,1.,0.;
100 0 3 00000000 3.,1.,1.,3.,1.,-1.,1.;
100 0 0 00000000 0.,0.,0.,5.,0.,5.,0.;
EOF
	$B/fromcad -t 1e-9 "$T/handc.igs" | $B/sample -n 10 >"$T/hand.pts"
	set -- $("$OCCPY" "$T/occnear.py" "$T/handc.igs" "$T/hand.pts" 1 \
	    2>/dev/null | tail -n 1)
	[ "${1:-0}" -eq 3 ] && ok || no "OpenCASCADE: handc.igs: ${1:-no} curves, want 3"
	echo "$2" >"$T/val"
	# (OpenCASCADE's projection onto a curve stops near 1e-8 of its size,
	# 6e-8 here; the closed forms above hold the curves to 1e-9)
	within "OpenCASCADE: handc.igs: fromcad's curves on its curves" 1e-7
	$B/fromcad "$T/hand.igs" 2>/dev/null | awk '/^bezier-surface/ { s = 1 }
	    s' | $B/sample -n 4 >"$T/hand.pts"
	set -- $("$OCCPY" "$T/occnear.py" "$T/hand.igs" "$T/hand.pts" 2 \
	    2>/dev/null | tail -n 1)
	echo "$2" >"$T/val"
	within "OpenCASCADE: hand.igs: fromcad's plane on its face" 1e-12
fi

finish stepiges
