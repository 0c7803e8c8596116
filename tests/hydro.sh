#!/bin/sh
# hydro.sh: command tests of hydro, run from the top of the tree.  The
# hulls are made here by awk as Bezier surfaces, and every reference is a
# closed form derived in the comments (or scipy's quadrature), never
# hydro's own output.  The last line is "hydro: N passed, M failed".

T=bin/test/hydro
. tests/lib.sh

TOL=1e-9        # the issue's bar: every closed form to 1e-9 relative

# same WHAT GOT WANT FLOOR: rows of numbers in the files GOT and WANT
# agree, each |g - w| <= TOL max(|w|, FLOOR) (FLOOR: where w is 0 by
# symmetry, a length of the hull to the field's power).  HYDRO_ERRS=1
# prints the largest |g - w| / max(|w|, FLOOR) of each comparison.
same() {
	if [ ! -s "$2" ]; then no "$1: no output: $(head -3 "$T/err")"; return; fi
	[ -n "$HYDRO_ERRS" ] && awk -v fl="$4" -v what="$1" 'NR == FNR {
		for (i = 1; i <= NF; i++) g[FNR, i] = $i; next }
	{ for (i = 1; i <= NF; i++) { w = $i; d = g[FNR, i] - w; d = d < 0 ? -d : d
	    s = w < 0 ? -w : w; if (s < fl) s = fl; if (s > 0 && d / s > m) m = d / s } }
	END { printf "error: %s: %.2g\n", what, m }' "$2" "$3"
	msg=$(awk -v tol="$TOL" -v fl="$4" 'NR == FNR { for (i = 1; i <= NF; i++)
		g[FNR, i] = $i; ng[FNR] = NF; rows = FNR; next }
	{ if (ng[FNR] != NF) { print "row " FNR ": " ng[FNR] " numbers, want " NF; exit }
	  for (i = 1; i <= NF; i++) { w = $i; d = g[FNR, i] - w; d = d < 0 ? -d : d
	    s = w < 0 ? -w : w; if (s < fl) s = fl
	    if (!(d <= tol * s)) { print "row " FNR " column " i ": got " g[FNR, i] ", want " w; exit } } }
	END { if (FNR != rows) print "got " rows " rows, want " FNR }' "$2" "$3")
	[ -z "$msg" ] && ok || no "$1: $msg"
}

# ---- usage -------------------------------------------------------------
usage_ok hydro
fails 2 "-f 'size'" "$B/hydro -f volume,size /dev/null"
fails 2 "-z want from:to:step" "$B/hydro -z 1:0:1 /dev/null"
fails 2 "-r" "$B/hydro -r 0 /dev/null"
fails 2 "-s" "$B/hydro -s 0 /dev/null"
fails 2 "displacement needs a density" "$B/hydro -f displacement /dev/null"

# ---- the Wigley hull ---------------------------------------------------
# y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2), -L/2 <= x <= L/2, -T <= z <= 0, is
# one bi-quadratic Bezier surface: x = L(u - 1/2) (controls -L/2, 0, L/2),
# z = T(v - 1) (controls -T, -T/2, 0), 4u(1 - u) = 2 B_1^2(u) (Bernstein
# coefficients 0 2 0), 1 - (v - 1)^2 = v(2 - v) (coefficients 0 1 1).
# Its edges u = 0, u = 1 and v = 0 lie in y = 0: the starboard half,
# closed up to the centreplane.  wigley L B T [S] (all times S, default 1)
wigley() {
	awk -v L="$1" -v B="$2" -v T="$3" -v S="${4:-1}" 'BEGIN {
	split("0 2 0", a); split("0 1 1", b)
	print "bezier-surface m=2 n=2"
	for (i = 0; i < 3; i++) for (j = 0; j < 3; j++)
		printf "%.17g %.17g %.17g\n", S * (-L / 2 + L * i / 2),
		    S * B / 2 * a[i + 1] * b[j + 1], S * (-T + T * j / 2) }'
}
# the port side too: y negated, u reversed so the normals stay outward
wigley_whole() {
	wigley "$@"
	echo
	wigley "$@" | awk 'NR == 1 { print; next } { r[NR] = $1 " " (-$2) " " $3 }
	    END { for (i = 2; i >= 0; i--) for (j = 0; j < 3; j++) print r[2 + 3 * i + j] }'
}
# At a waterline Z, -T < Z <= 0, with c = 1 - (Z/T)^2 and
# g(Z) = (Z + T) - (Z^3 + T^3) / (3 T^2) = int_-T^Z (1 - z^2/T^2) dz:
#   V   = 2 int int y = B (2L/3) g            (int (1 - (2x/L)^2) = 2L/3)
#   vcb = int z (1 - z^2/T^2) / g = ((Z^2 - T^2)/2 - (Z^4 - T^4)/(4T^2)) / g
#   awp = B c (2L/3), lcb = lcf = 0, lwl = L, bwl = B c, t = Z + T
#   I_T = (2/3) int (B c/2)^3 (1 - (2x/L)^2)^3 = (2/3)(B c/2)^3 (16L/35)
#   I_L = 2 (B c/2) int x^2 (1 - (2x/L)^2) = (B c/2) L^3/15
#   am  = B g (the section x = 0), cm = am/(bwl t), cp = V/(am L) = 2/3,
#   cb  = V/(L bwl t), cwp = awp/(L bwl) = 2/3
# At Z = 0: cb = 4/9, cm = cwp = 2/3, KB = 5T/8, BMt = 3B^2/(35T),
# BMl = 3L^2/(40T): the issue's figures, which these reduce to.
wigley_want() {
	awk -v L="$1" -v B="$2" -v T="$3" -v S="${5:-1}" -v zs="$4" 'BEGIN {
	n = split(zs, z, ",")
	for (k = 1; k <= n; k++) {
		Z = z[k]; c = 1 - (Z / T)^2; g = (Z + T) - (Z^3 + T^3) / (3 * T^2)
		V = B * 2 * L / 3 * g
		vcb = ((Z^2 - T^2) / 2 - (Z^4 - T^4) / (4 * T^2)) / g
		awp = B * c * 2 * L / 3; bwl = B * c; t = Z + T
		it = 2 / 3 * (B * c / 2)^3 * 16 * L / 35; il = B * c / 2 * L^3 / 15
		am = B * g
		printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
		    S * Z, S^3 * V, S * vcb, S^2 * awp, S * it / V, S * il / V,
		    S * (vcb + T + it / V), S * (vcb + T + il / V), S * L,
		    S * bwl, S * t, V / (L * bwl * t), V / (am * L),
		    am / (bwl * t), awp / (L * bwl), S^2 * am, S * 0 }
	}'
}
WF=z,volume,vcb,awp,bmt,bml,kmt,kml,lwl,bwl,t,cb,cp,cm,cwp,am,lcb
ZS=-0.2,-0.15,-0.1,-0.05,0
wigley 4 0.5 0.25 >"$T/wig"
run "$B/hydro -z -0.2:0:0.05 -f $WF $T/wig"
status 0
awk NF "$T/out" >"$T/got"
wigley_want 4 0.5 0.25 "$ZS" >"$T/want"
same "Wigley hull at five waterlines" "$T/got" "$T/want" 0.1
# the issue's figures by themselves, at the design waterline
run "$B/hydro -f cb,cwp,cm,vcb,bmt,bml $T/wig"
awk NF "$T/out" >"$T/got"
awk 'BEGIN { L = 4; B = 0.5; T = 0.25
	printf "%.17g %.17g %.17g %.17g %.17g %.17g\n", 4 / 9, 2 / 3, 2 / 3,
	    -T + 5 * T / 8, 3 * B^2 / (35 * T), 3 * L^2 / (40 * T) }' >"$T/want"
same "Wigley: Cb 4/9, Cwp = Cm = 2/3, KB 5T/8, BMt, BMl" "$T/got" "$T/want" 0

# the same hull as one of MacCallum's patches (loft.5): the rows and
# columns (0), (1), (0)_u, (1)_u, (h) of a quadratic with Bezier points
# P0 P1 P2 are P0, P2, 2(P1 - P0), 2(P2 - P1), (P0 + 2 P1 + P2)/4
wigley 4 0.5 0.25 | awk 'NR > 1 { n = NR - 2; for (k = 1; k <= 3; k++) P[int(n / 3), n % 3, k] = $k }
	END { split("1 0 0|0 0 1|-2 2 0|0 -2 2|0.25 0.5 0.25", r, "|")
	print "patch id=1"
	for (i = 0; i < 5; i++) { split(r[i + 1], wi, " "); line = ""
	    for (j = 0; j < 5; j++) { split(r[j + 1], wj, " ")
		for (k = 1; k <= 3; k++) { v = 0
		    for (a = 0; a < 3; a++) for (b = 0; b < 3; b++) v += wi[a + 1] * wj[b + 1] * P[a, b, k]
		    line = line sprintf(" %.17g", v) } }
	    print substr(line, 2) } }' >"$T/wigp"
run "$B/hydro -z -0.2:0:0.05 -f $WF $T/wigp"
status 0
awk NF "$T/out" >"$T/got"
wigley_want 4 0.5 0.25 "$ZS" >"$T/want"
same "Wigley hull as a patch record at five waterlines" "$T/got" "$T/want" 0.1

# another shape of it, and half against whole
wigley 100 12 6 >"$T/wig2"
run "$B/hydro -z -5:0:1 -f $WF $T/wig2"
awk NF "$T/out" >"$T/got"
wigley_want 100 12 6 -5,-4,-3,-2,-1,0 >"$T/want"
same "Wigley 100 x 12 x 6 at six waterlines" "$T/got" "$T/want" 1
wigley_whole 100 12 6 >"$T/wig2w"
run "$B/hydro -w -z -5:0:1 -f $WF,tcb $T/wig2w"
status 0
awk NF "$T/out" >"$T/gotw"
awk '{ print $0, 0 }' "$T/want" >"$T/wantw"
same "Wigley whole (-w) against the closed form" "$T/gotw" "$T/wantw" 1
run "$B/hydro -z -5:0:1 -f wetted $T/wig2"
cp "$T/out" "$T/wh"
run "$B/hydro -w -z -5:0:1 -f wetted $T/wig2w"
same "Wigley: wetted area of the half mirrored = of the whole" "$T/out" "$T/wh" 0
fails 1 "reaches y = -6 < 0" "$B/hydro $T/wig2w"

# units: the hull scaled by 1e-100 and 1e100, every field scales with it
for S in 1e-100 1e100; do
	wigley 4 0.5 0.25 "$S" >"$T/wigs"
	run "$B/hydro -z $(awk -v s=$S 'BEGIN { printf "%.17g", -0.1 * s }') -f $WF $T/wigs"
	awk NF "$T/out" >"$T/got"
	wigley_want 4 0.5 0.25 -0.1 "$S" >"$T/want"
	same "Wigley scaled by $S" "$T/got" "$T/want" "$(awk -v s=$S 'BEGIN { print 1e-3 * s }')"
done

# wetted surface: 2 int int sqrt(1 + y_x^2 + y_z^2) dx dz, by scipy's
# dblquad (an independent adaptive quadrature)
if /usr/bin/python3 -c 'import scipy' 2>/dev/null; then
	run "$B/hydro -z -0.2:0:0.1 -f wetted $T/wig"
	awk NF "$T/out" >"$T/got"
	/usr/bin/python3 -c '
from scipy.integrate import dblquad
L, B, T = 4.0, 0.5, 0.25
def f(z, x):
    yx = B / 2 * (-8 * x / L**2) * (1 - (z / T)**2)
    yz = B / 2 * (1 - (2 * x / L)**2) * (-2 * z / T**2)
    return (1 + yx * yx + yz * yz) ** 0.5
for Z in (-0.2, -0.1, 0.0):
    v, e = dblquad(f, -L / 2, L / 2, -T, Z, epsabs=1e-14, epsrel=1e-13)
    print(repr(2 * v))' >"$T/want"
	same "Wigley wetted surface against scipy dblquad" "$T/got" "$T/want" 0
else
	echo "skip: wetted surface against scipy (no /usr/bin/python3 with scipy)"
fi

# ---- a box barge -------------------------------------------------------
# L x B x D, x in [0, L], the half y in [0, B/2], z in [0, D]: bottom, side
# and two ends, bilinear, normals outward.  At draft Z: V = L B Z, lcb =
# lcf = L/2, vcb = Z/2, awp = L B, BMt = B^2/(12 Z), BMl = L^2/(12 Z),
# KM = Z/2 + BM, lwl = L, bwl = B, t = Z, every coefficient 1, wetted
# L B + 2 (L + B) Z, the section am = B Z.
barge() {
	awk -v L="$1" -v b="$(awk -v B="$2" 'BEGIN { print B / 2 }')" -v D="$3" -v skip="$4" 'BEGIN {
	f[1] = "0 0 0|" L " 0 0|0 " b " 0|" L " " b " 0"
	f[2] = "0 " b " 0|" L " " b " 0|0 " b " " D "|" L " " b " " D
	f[3] = L " 0 0|" L " 0 " D "|" L " " b " 0|" L " " b " " D
	f[4] = "0 0 0|0 " b " 0|0 0 " D "|0 " b " " D
	for (k = 1; k <= 4; k++) { if (k == skip) continue
		print "bezier-surface m=1 n=1"; n = split(f[k], p, "|")
		for (i = 1; i <= n; i++) print p[i]; print "" } }'
}
barge 20 6 4 >"$T/barge"
run "$B/hydro -z 1:3:0.5 -f z,volume,lcb,vcb,awp,lcf,bmt,bml,kmt,kml,lwl,bwl,t,cb,cp,cm,cwp,wetted,am $T/barge"
status 0
awk NF "$T/out" >"$T/got"
awk 'BEGIN { L = 20; B = 6; for (Z = 1; Z <= 3; Z += 0.5)
	printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g 1 1 1 1 %.17g %.17g\n",
	    Z, L * B * Z, L / 2, Z / 2, L * B, L / 2, B^2 / (12 * Z),
	    L^2 / (12 * Z), Z / 2 + B^2 / (12 * Z), Z / 2 + L^2 / (12 * Z),
	    L, B, Z, L * B + 2 * (L + B) * Z, B * Z }' >"$T/want"
same "box barge at five drafts" "$T/got" "$T/want" 0
cp "$T/want" "$T/bwant"
run "$B/hydro -r 1.025 -z 2 -f displacement $T/barge"
awk NF "$T/out" >"$T/got"
echo 246 >"$T/want"
same "box barge: displacement 1.025 x 240" "$T/got" "$T/want" 0
fails 1 "above the hull's top z = 4" "$B/hydro -z 5 $T/barge"
fails 1 "at or below the hull's lowest point z = 0" "$B/hydro -z 0 $T/barge"
barge 20 6 4 3 >"$T/open"
fails 1 "open below the waterline z = 2: its ends do not close" "$B/hydro -z 2 $T/open"
barge 20 6 4 2 >"$T/open"
fails 1 "open below the waterline z = 2: its sides do not close" "$B/hydro -z 2 $T/open"
barge 20 6 4 1 >"$T/open"
fails 1 "open below the waterline z = 2: its bottom does not close" "$B/hydro -z 2 $T/open"
fails 1 "a point record: hydro reads surface records" "printf '1 2 3\n4 5 6\n' | $B/hydro"

# the same barge as MacCallum patches (patchnew -c: four corners, the
# bilinear patch, as patch records): the same closed forms
i=0
barge 20 6 4 | awk '/^bezier/ { n = 0; next } NF == 3 { c[n++] = $1 "," $2 "," $3 }
	NF == 0 && n == 4 { print c[0], c[2], c[1], c[3] }' |
while read -r a b c d; do
	i=$((i + 1))
	"$B/patchnew" -i "$i" -c "$a" -c "$b" -c "$c" -c "$d" && echo
done >"$T/bargep"
run "$B/hydro -z 1:3:0.5 -f z,volume,lcb,vcb,awp,lcf,bmt,bml,kmt,kml,lwl,bwl,t,cb,cp,cm,cwp,wetted,am $T/bargep"
status 0
awk NF "$T/out" >"$T/got"
same "box barge of patch records at five drafts" "$T/got" "$T/bwant" 0

# ---- a half-cylinder ---------------------------------------------------
# Radius R, length L, axis on x at z = 0: the quarter circle from the keel
# (y 0, z -R) to (R, 0) in K cubic arcs (inner control points at 4/3
# tan(d/4) of the radius along the tangents, d = the arc's angle; over
# d = pi/128 the radial error is below 1e-15 of R), its shell and two
# end caps (each arc's fan from the axis), normals outward.  Below
# Z (-R < Z <= 0), with c = sqrt(R^2 - Z^2) and A = R^2 acos(-Z/R) + Z c
# the circle's area below Z: V = L A, int z dA = -(2/3) c^3,
# awp = 2 c L, BMt = (2c)^3 L / 12 / V, BMl = 2c L^3 / 12 / V, bwl = 2c,
# cb = cm = A / (2 c (Z + R)), cp = cwp = 1, wetted = 2 R L acos(-Z/R) + 2A.
cylinder() {
	awk -v R="$1" -v L="$2" -v K=64 'function pt(t, k) {
		return sprintf("%.17g %.17g", k * cos(t), k * sin(t)) }
	BEGIN { pi = atan2(0, -1); d = pi / 2 / K; h = 4 / 3 * sin(d / 4) / cos(d / 4)
	for (i = 0; i < K; i++) {
		a = -pi / 2 + i * d; b = a + d
		y[0] = R * cos(a); z[0] = R * sin(a)
		y[1] = y[0] - h * R * sin(a); z[1] = z[0] + h * R * cos(a)
		y[3] = R * cos(b); z[3] = R * sin(b)
		y[2] = y[3] + h * R * sin(b); z[2] = z[3] - h * R * cos(b)
		print "bezier-surface m=3 n=1"
		for (j = 0; j < 4; j++) printf "0 %.17g %.17g\n%.17g %.17g %.17g\n", y[j], z[j], L, y[j], z[j]
		print ""
		print "bezier-surface m=1 n=3"
		for (j = 0; j < 4; j++) printf "%.17g 0 0\n", L
		for (j = 0; j < 4; j++) printf "%.17g %.17g %.17g\n", L, y[j], z[j]
		print ""
		print "bezier-surface m=3 n=1"
		for (j = 0; j < 4; j++) printf "0 0 0\n0 %.17g %.17g\n", y[j], z[j]
		print "" } }'
}
cylinder 2 10 >"$T/cyl"
run "$B/hydro -z -1.5:0:0.5 -f z,volume,vcb,awp,bmt,bml,lwl,bwl,t,cb,cp,cm,cwp,wetted,am,lcb $T/cyl"
status 0
awk NF "$T/out" >"$T/got"
awk 'BEGIN { R = 2; L = 10; for (Z = -1.5; Z <= 0; Z += 0.5) {
	c = sqrt(R^2 - Z^2); ac = atan2(c, -Z); A = R^2 * ac + Z * c; V = L * A
	printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g 1 %.17g 1 %.17g %.17g %.17g\n",
	    Z, V, -2 / 3 * c^3 / A, 2 * c * L, (2 * c)^3 * L / 12 / V,
	    2 * c * L^3 / 12 / V, L, 2 * c, Z + R, A / (2 * c * (Z + R)),
	    A / (2 * c * (Z + R)), 2 * R * L * ac + 2 * A, A, L / 2 } }' >"$T/want"
same "half-cylinder at four waterlines" "$T/got" "$T/want" 1e-3

# ---- the curve of sectional areas --------------------------------------
# Wigley: the section at x has area B (1 - (2x/L)^2) g(Z)
run "$B/hydro -s 9 -z -0.1 $T/wig"
status 0
awk NF "$T/out" | sed 1d >"$T/got"
awk 'BEGIN { L = 4; B = 0.5; T = 0.25; Z = -0.1; g = (Z + T) - (Z^3 + T^3) / (3 * T^2)
	for (i = 0; i < 9; i++) { x = -L / 2 + L * i / 8
		printf "%.17g %.17g\n", x, B * (1 - (2 * x / L)^2) * g } }' >"$T/want"
same "Wigley: the curve of sectional areas" "$T/got" "$T/want" 1e-3
head -1 "$T/out" | grep -q '^points name=sectional-area z=-0.1$' && ok ||
    no "hydro -s: header is '$(head -1 "$T/out")'"
fails 1 "waterline z = 0.1 is above the hull's top z = 0" "$B/hydro -s 5 -z 0.1 $T/wig"
# the area under the curve of sectional areas is the volume: the curve
# through 41 stations, fitted by splinefit, within 1e-5 (the fit's
# error) of the volume the divergence theorem gives, on a lofted hull
"$B/offsets" -k man/examples/hull.offsets | "$B/splinefit" -o | "$B/patchloft" >"$T/hull6"
a=$("$B/hydro" -z 1 -s 41 "$T/hull6" | "$B/splinefit" -o | "$B/measure" -f area | awk NF)
v=$("$B/hydro" -z 1 -f volume "$T/hull6" | awk NF)
awk -v a="$a" -v v="$v" 'BEGIN { d = a + v; d = d < 0 ? -d : d; exit !(v > 0 && d <= 1e-5 * v) }' &&
    ok || no "area under the curve of sectional areas $a, volume $v"

finish hydro
