#!/bin/sh
# loftcut.sh: command tests of patchloft and patchcut, run from the top
# of the tree.  The references are computed here, in awk, from the
# paper's matrix M typed in and from the geometry of the cases (a
# cylinder, the bilinear patch z = xy, a station); the last line is
# "loftcut: N passed, M failed".

T=bin/test/loftcut
. tests/lib.sh

# ---- independent evaluation --------------------------------------------
# EVAL: awk functions over patch records read into B[id, row, col, k]:
# H1..H5 are the columns of MacCallum's M (section 4 of the paper),
#   M = [ -8 -8 -2  2  16 ; 18 14 5 -3 -32 ; -11 -5 -4 1 16 ;
#          0  0  1  0   0 ;  1  0 0  0   0 ]  over [u^4 u^3 u^2 u 1],
# and ev(id, u, v) sets P, Fu, Fv: f = sum H_i(u) B_ij H_j(v).
EVAL='
function H(u, h) {
	h[1] = -8*u^4 + 18*u^3 - 11*u^2 + 1; h[2] = -8*u^4 + 14*u^3 - 5*u^2
	h[3] = -2*u^4 + 5*u^3 - 4*u^2 + u;  h[4] = 2*u^4 - 3*u^3 + u^2
	h[5] = 16*u^4 - 32*u^3 + 16*u^2
}
function dH(u, h) {
	h[1] = -32*u^3 + 54*u^2 - 22*u; h[2] = -32*u^3 + 42*u^2 - 10*u
	h[3] = -8*u^3 + 15*u^2 - 8*u + 1; h[4] = 8*u^3 - 9*u^2 + 2*u
	h[5] = 64*u^3 - 96*u^2 + 32*u
}
function ev(id, u, v,   i, j, k, hu, hv, du, dv, b) {
	H(u, hu); H(v, hv); dH(u, du); dH(v, dv)
	for (k = 1; k <= 3; k++) { P[k] = 0; Fu[k] = 0; Fv[k] = 0
		for (i = 1; i <= 5; i++) for (j = 1; j <= 5; j++) {
			b = B[id, i, j, k]; P[k] += hu[i] * b * hv[j]
			Fu[k] += du[i] * b * hv[j]; Fv[k] += hu[i] * b * dv[j] } }
}
function unitnormal(n,   l) {
	n[1] = Fu[2]*Fv[3] - Fu[3]*Fv[2]; n[2] = Fu[3]*Fv[1] - Fu[1]*Fv[3]
	n[3] = Fu[1]*Fv[2] - Fu[2]*Fv[1]
	l = sqrt(n[1]^2 + n[2]^2 + n[3]^2); n[1] /= l; n[2] /= l; n[3] /= l
}
# patch records: ids in order, links L[id, edge], su S[id]
/^patch/ { id = substr($2, 4); r = 0; ids[++np] = id; S[id] = 1
	for (f = 3; f <= NF; f++) { split($f, kv, "=")
		if (kv[1] ~ /^[uv][01]$/) L[id, kv[1]] = kv[2]
		if (kv[1] == "su") S[id] = kv[2] }
	next }
type == "" && NF == 15 { r++
	for (j = 1; j <= 5; j++) for (k = 1; k <= 3; k++) B[id, r, j, k] = $((j-1)*3 + k)
	next }
'

# g1 FILE: the largest |n1 x n2| (2 where they point opposite ways)
# between the unit normals of the two sides of every shared edge, at 11
# points along it, and the largest gap between the sides' points.
g1() {
	awk "$EVAL"'
	function side(a, b, t1, u1, v1, u2, v2,   n1, n2, p, d, k) {
		ev(a, u1, v1); unitnormal(n1); for (k = 1; k <= 3; k++) p[k] = P[k]
		ev(b, u2, v2); unitnormal(n2)
		d = sqrt((n1[2]*n2[3]-n1[3]*n2[2])^2 + (n1[3]*n2[1]-n1[1]*n2[3])^2 + \
		    (n1[1]*n2[2]-n1[2]*n2[1])^2)
		if (n1[1]*n2[1] + n1[2]*n2[2] + n1[3]*n2[3] < 0) d = 2
		if (d > worst) worst = d
		d = sqrt((p[1]-P[1])^2 + (p[2]-P[2])^2 + (p[3]-P[3])^2)
		if (d > gap) gap = d
	}
	END { for (q = 1; q <= np; q++) { id = ids[q]
		for (s = 0; s <= 10; s++) { t = s / 10
			if ((id, "u1") in L) side(id, L[id, "u1"], t, 1, t, 0, t)
			if ((id, "v1") in L) side(id, L[id, "v1"], t, t, 1, t, 0) } }
	    printf "%.3g %.3g %d\n", worst, gap, np }' "$1"
}

# ---- usage -------------------------------------------------------------
usage_ok patchloft
usage_ok patchcut
fails 2 "-S and -E are for an open loft" "$B/patchloft -c -S 1,0 /dev/null"
fails 2 "want a direction of 2 or 3 numbers, not zero" "$B/patchloft -S 0,0 /dev/null"
fails 2 "give a plane" "$B/patchcut /dev/null"
fails 2 "want from:to:step" "$B/patchcut -x 1:0:0.5 /dev/null"
fails 2 "want from:to:step" "$B/patchcut -x 0:1:0 /dev/null"
fails 2 "want a value or from:to:step" "$B/patchcut -x a /dev/null"
fails 2 "want a,b,c,d" "$B/patchcut -p 0,0,0,1 /dev/null"
fails 2 "want a,b,c,d" "$B/patchcut -p 1,0,0 /dev/null"
fails 2 "want a tolerance above 0" "$B/patchcut -x 1 -t 0 /dev/null"
fails 1 "more than 100000 planes" "$B/patchcut -x 0:1:1e-9 /dev/null"

# ---- patchloft: the hull -----------------------------------------------
H=man/figures/hull.knots
$B/splinefit -o $H >"$T/hull.cubic"
run "$B/patchloft $T/hull.cubic"
status 0
cp "$T/out" "$T/hull.design"
[ "$(grep -c '^patch' "$T/hull.design")" -eq 24 ] && ok ||
    no "hull: not 4 strips of 6 patches"

# sections on the patch edges: the edge u = 0 of patch (k, j) (id
# 6k + j + 1) and u = 1 of the last strip are the segments of the
# sections, evaluated here by Hermite's cubic (Manning's eq. 7)
edges() {
	awk -v nseg="$2" "$EVAL"'
	function cub(i, u, k) { return (2*u^3 - 3*u^2 + 1) * C[i, k] + (3*u^2 - 2*u^3) * C[i, k+3] + \
	    (u^3 - 2*u^2 + u) * C[i, k+6] + (u^3 - u^2) * C[i, k+9] }
	FILENAME == ARGV[1] && NF == 12 && !/^cubic/ { nc++; for (k = 1; k <= 12; k++) C[nc, k] = $k; next }
	FILENAME == ARGV[1] { next }
	END { nstrip = np / nseg
		for (k = 0; k <= nstrip; k++) for (j = 0; j < nseg; j++) for (s = 0; s <= 8; s++) {
			t = s / 8; kk = k < nstrip ? k : k - 1; uu = k < nstrip ? 0 : 1
			ev(kk * nseg + j + 1, uu, t)
			for (c = 1; c <= 3; c++) { d = P[c] - cub(k * nseg + j + 1, t, c)
				d = d < 0 ? -d : d; if (d > w) w = d } }
	    printf "%.3g\n", w }' "$1" "$3"
}
e=$(edges "$T/hull.cubic" 6 "$T/hull.design")
awk -v e="$e" 'BEGIN { exit !(e <= 1e-14) }' && ok ||
    no "hull: the sections are off the patch edges by $e"
set -- $(g1 "$T/hull.design")
awk -v w="$1" -v g="$2" 'BEGIN { exit !(w <= 1e-12 && g <= 1e-14) }' && ok ||
    no "hull: normals across shared edges differ by $1, points by $2"

# sections of 3 and 2 segments: the union of breakpoints 0 1/3 1/2 2/3
# 1 gives 4; the first section's point at 1/2 is in the middle of its
# segment 2, now the end of the patch column 2
printf 'points\n0 0 0\n0 1 0.2\n0 2 0\n0 3 0.5\n\npoints\n2 0 0\n2 1.5 0.5\n2 3 0\n' |
    $B/splinefit -o >"$T/mixed.cubic"
run "$B/patchloft $T/mixed.cubic"
status 0
cp "$T/out" "$T/mixed.design"
[ "$(grep -c '^patch' "$T/mixed.design")" -eq 4 ] && ok ||
    no "mixed counts: not 4 patches"
set -- $(g1 "$T/mixed.design")
awk -v w="$1" 'BEGIN { exit !(w <= 1e-12) }' && ok ||
    no "mixed counts: normals differ by $1"
# the edge u = 0 at v of patch j is section 1 at T = 3 t, t = 0, 1/3,
# 1/2, 2/3, 1 between breakpoints; the same for section 2 at 2 t
awk "$EVAL"'
function cub(i, u, k) { return (2*u^3 - 3*u^2 + 1) * C[i, k] + (3*u^2 - 2*u^3) * C[i, k+3] + \
    (u^3 - 2*u^2 + u) * C[i, k+6] + (u^3 - u^2) * C[i, k+9] }
FILENAME == ARGV[1] && NF == 12 { nc++; for (k = 1; k <= 12; k++) C[nc, k] = $k; next }
FILENAME == ARGV[1] { next }
{ type = "" }
END { split("0 0.333333333333333333 0.5 0.666666666666666667 1", tb, " ")
	for (j = 1; j <= 4; j++) for (s = 0; s <= 8; s++) {
		t = tb[j] + s / 8 * (tb[j+1] - tb[j])
		for (sec = 1; sec <= 2; sec++) {
			m = sec == 1 ? 3 : 2; T = t * m; i = int(T); if (i >= m) i = m - 1
			ev(j, sec - 1, s / 8)
			for (c = 1; c <= 3; c++) { d = P[c] - cub((sec == 1 ? 0 : 3) + i + 1, T - i, c)
				d = d < 0 ? -d : d; if (d > w) w = d } } }
    exit !(w <= 1e-12) }' "$T/mixed.cubic" "$T/mixed.design" && ok ||
    no "mixed counts: the sections are not on the edges"

# ---- patchloft: a cylinder ---------------------------------------------
# circles of radius 1 (8 knots each) at x = 0, 1, 2.5, 4: every point of
# the surface is as far from the axis as the sections' points are (the
# fit's accuracy, measured here on the sections by eq. 7)
awk 'BEGIN { for (x = 0; x < 4; x++) { print "points"
	for (i = 0; i < 8; i++) { a = 2 * 3.14159265358979324 * i / 8
	    printf "%s %.17g %.17g\n", (x == 2 ? 2.5 : x == 3 ? 4 : x), cos(a), sin(a) }
	print "" } }' | $B/splinefit >"$T/cyl.cubic"
run "$B/patchloft $T/cyl.cubic"
status 0
cp "$T/out" "$T/cyl.design"
lim=$(awk '/^cubic/ { next } NF == 12 { for (s = 0; s <= 64; s++) { u = s / 64
	for (c = 2; c <= 3; c++) y[c] = (2*u^3 - 3*u^2 + 1) * $c + (3*u^2 - 2*u^3) * $(c+3) + \
	    (u^3 - 2*u^2 + u) * $(c+6) + (u^3 - u^2) * $(c+9)
	r = sqrt(y[2]^2 + y[3]^2); if (!n++ || r < lo) lo = r; if (r > hi) hi = r } }
	END { printf "%.17g %.17g\n", lo, hi }' "$T/cyl.cubic")
awk "$EVAL"'END { split(lim, b, " "); lo = b[1] - 1e-12; hi = b[2] + 1e-12
	for (q = 1; q <= np; q++) for (a = 0; a <= 8; a++) for (c = 0; c <= 8; c++) {
		ev(ids[q], a / 8, c / 8); r = sqrt(P[2]^2 + P[3]^2)
		if (r < lo || r > hi) bad++
		if (P[1] < -1e-12 || P[1] > 4 + 1e-12) bad++ }
	exit (bad > 0) || !(hi - lo < 0.01) }' lim="$lim" "$T/cyl.design" && ok ||
    no "cylinder: points off the cylinder (the sections' radii: $lim)"
set -- $(g1 "$T/cyl.design")
awk -v w="$1" 'BEGIN { exit !(w <= 1e-12) }' && ok || no "cylinder: normals differ by $1"

# a closed loft of closed sections, 5 and 7 segments: a ring
awk 'BEGIN { pi = 3.14159265358979324; for (k = 0; k < 6; k++) { a = 2*pi*k/6
	m = k % 2 ? 7 : 5; print "points"; for (i = 0; i < m; i++) { b = 2*pi*i/m
	r = 3 + (1 + 0.2*k) * cos(b); printf "%.17g %.17g %.17g\n", r*cos(a), r*sin(a), (1+0.1*k)*sin(b) }
	print "" } }' | $B/splinefit >"$T/ring.cubic"
run "$B/patchloft -c $T/ring.cubic"
status 0
cp "$T/out" "$T/ring.design"
set -- $(g1 "$T/ring.design")
awk -v w="$1" -v g="$2" -v n="$3" 'BEGIN { exit !(w <= 1e-12 && g <= 1e-14 && n == 66) }' &&
    ok || no "ring: normals differ by $1, points by $2, $3 patches (want 6 x 11)"

# ---- the design is one the other programs take -------------------------
for c in "patchsplit -u 0.3" "patchsplit -v 0.5 -i 5" \
    "patchdrag -i 5 -u 0.5 -v 0.5 -b 0,0.1,0" "sample -n 4" "loftplot" \
    "patchcut -x 3"; do
	run "$B/$c $T/hull.design"
	status 0
	[ -s "$T/out" ] && ok || no "$c: no output"
done
run "$B/patchsplit -u 0.5 $T/hull.design | $B/patchsplit -v 0.5"
set -- $(g1 "$T/out")
awk -v w="$1" -v n="$3" 'BEGIN { exit !(w <= 1e-12 && n == 96) }' && ok ||
    no "split twice: normals differ by $1, $3 patches"
# patchjoin: a patch made beside the boundary station 0 joins patch 1
awk 'NR == 2 { printf "-c -1,%s,%s -c %s,%s,%s -c -1,%s,%s -c %s,%s,%s\n",
    $2, $3, $1, $2, $3, $5, $6, $4, $5, $6 }' \
    "$T/hull.design" >"$T/corners"
$B/patchnew -i 100 $(cat "$T/corners") >"$T/new"
cat "$T/hull.design" "$T/new" >"$T/hull2"
run "$B/patchjoin -P 1 -S 100 $T/hull2"
status 0
grep -q '^patch id=100 .*u1=1' "$T/out" && ok || no "patchjoin: 100 not joined to 1"

# ---- patchcut: the bilinear patch z = xy -------------------------------
$B/patchnew -c 0,0,0 -c 1,0,0 -c 0,1,0 -c 1,1,1 >"$T/bil"
run "$B/patchcut -z 0.25 -t 1e-4 $T/bil"
status 0
# every point on xy = 1/4 and z = 1/4 to rounding, ends at (1/4, 1) and
# (1, 1/4), every chord's middle within the tolerance of the hyperbola
# (its distance |xy - c| / |grad| to first order)
awk 'NR == 1 { ok = $0 == "points plane=z value=0.25"; next } NF == 3 {
	n++; e = $1 * $2 - 0.25; e = e < 0 ? -e : e; if (e > w) w = e
	z = $3 - 0.25; z = z < 0 ? -z : z; if (z > wz) wz = z
	if (n > 1) { xm = (x + $1) / 2; ym = (y + $2) / 2
		g = (xm * ym - 0.25) / sqrt(xm^2 + ym^2); g = g < 0 ? -g : g; if (g > gm) gm = g }
	if (n == 1) { x1 = $1; y1 = $2 } x = $1; y = $2 }
	function at(x, y, a, b) { return (x - a)^2 + (y - b)^2 <= 1e-30 }
	END { a = at(x1, y1, 0.25, 1) || at(x1, y1, 1, 0.25)
	    b = at(x, y, 0.25, 1) || at(x, y, 1, 0.25)
	    exit !(ok && w <= 1e-15 && wz <= 1e-15 && a && b && gm <= 1.05e-4 && gm > 1e-6) }' \
    "$T/out" && ok || no "z = 0.25 of z = xy: not the hyperbola xy = 1/4"
# the plane x + y = 1: the parabola z = x (1 - x)
run "$B/patchcut -p 1,1,0,1 $T/bil"
status 0
awk 'NR == 1 { ok = $0 == "points plane=1,1,0 value=1"; next } NF == 3 {
	e = $3 - $1 * (1 - $1); e = e < 0 ? -e : e; if (e > w) w = e
	s = $1 + $2 - 1; s = s < 0 ? -s : s; if (s > ws) ws = s; n++ }
	END { exit !(ok && w <= 2e-15 && ws <= 2e-15 && n > 10) }' "$T/out" && ok ||
    no "x + y = 1 of z = xy: not the parabola z = x (1 - x)"
# four patches of it (split twice), cut by z = 0.25 through their shared
# edges: one curve; cut by x = 0.5 along the shared edge u = 1/2: one
# curve, the line z = y / 2
$B/patchsplit -u 0.5 "$T/bil" | $B/patchsplit -v 0.5 >"$T/bil4"
run "$B/patchcut -z 0.25 $T/bil4"
status 0
[ "$(grep -c '^points' "$T/out")" -eq 1 ] && ok ||
    no "z = 0.25 of 4 patches: $(grep -c '^points' "$T/out") curves, want 1"
awk '/^[a-z]/ { next } NF == 3 { e = $1 * $2 - 0.25; e = e < 0 ? -e : e; if (e > w) w = e }
    END { exit !(w <= 1e-15) }' "$T/out" && ok || no "z = 0.25 of 4 patches: off the hyperbola"
run "$B/patchcut -x 0.5 $T/bil4"
status 0
[ "$(grep -c '^points' "$T/out")" -eq 1 ] && ok ||
    no "x = 0.5 along a shared edge: $(grep -c '^points' "$T/out") curves, want 1"
awk '/^[a-z]/ { next } NF == 3 { e = $3 - $2 / 2; e = e < 0 ? -e : e; if (e > w) w = e; n++
	if ($1 != 0.5) bad = 1; if ($2 < lo || n == 1) lo = $2; if ($2 > hi) hi = $2 }
    END { exit !(!bad && w <= 1e-15 && lo == 0 && hi == 1) }' "$T/out" && ok ||
    no "x = 0.5 along a shared edge: not the line z = y/2 from y = 0 to 1"
# -c: a cubic through the points; a bezier-surface record is cut too
run "$B/patchcut -c -z 0.25 $T/bil"
status 0
head -n 1 "$T/out" | grep -q '^cubic closed=0 plane=z value=0.25$' && ok ||
    no "-c: $(head -n 1 "$T/out")"
printf 'bezier-surface m=1 n=1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n' >"$T/bs"
run "$B/patchcut -z 0.25 $T/bs"
status 0
awk '/^[a-z]/ { next } NF == 3 { e = $1 * $2 - 0.25; e = e < 0 ? -e : e; if (e > w) w = e; n++ }
    END { exit !(n > 3 && w <= 1e-15) }' "$T/out" && ok ||
    no "a bezier-surface z = xy: not the hyperbola"

# ---- patchcut: stations and waterlines of the hull ---------------------
# the cut at station 2 (x = 3) is station 2: every point on its cubic
# (nearest point found here by sampling and Newton's steps on eq. 7)
run "$B/patchcut -x 3 $T/hull.design"
status 0
[ "$(grep -c '^points' "$T/out")" -eq 1 ] && ok || no "x = 3: not one curve"
awk 'FILENAME == ARGV[1] && /name=station2/ { on = 1; next }
	FILENAME == ARGV[1] && /^cubic/ { on = 0; next }
	FILENAME == ARGV[1] { if (on && NF == 12) { ns++; for (k = 1; k <= 12; k++) C[ns, k] = $k } next }
	function pt(i, u, q, d,   k) { for (k = 1; k <= 3; k++) {
		q[k] = (2*u^3 - 3*u^2 + 1) * C[i, k] + (3*u^2 - 2*u^3) * C[i, k+3] + \
		    (u^3 - 2*u^2 + u) * C[i, k+6] + (u^3 - u^2) * C[i, k+9]
		d[k] = (6*u - 6*u^2) * (C[i, k+3] - C[i, k]) + (1 - 4*u + 3*u^2) * C[i, k+6] + \
		    (3*u^2 - 2*u) * C[i, k+9] } }
	/^points/ { next }
	NF == 3 { best = 1e300
	for (i = 1; i <= ns; i++) for (s = 0; s <= 200; s++) { u = s / 200; pt(i, u, q, d)
		e = ($1-q[1])^2 + ($2-q[2])^2 + ($3-q[3])^2; if (e < best) { best = e; bi = i; bu = u } }
	u = bu; for (it = 0; it < 30; it++) { pt(bi, u, q, d)
		num = ($1-q[1])*d[1] + ($2-q[2])*d[2] + ($3-q[3])*d[3]
		u += num / (d[1]^2 + d[2]^2 + d[3]^2); u = u < 0 ? 0 : u > 1 ? 1 : u }
	pt(bi, u, q, d); e = sqrt(($1-q[1])^2 + ($2-q[2])^2 + ($3-q[3])^2); if (e > w) w = e
	if (!n++) { f1 = $2; f2 = $3 } l1 = $2; l2 = $3 }
	END { exit !(w <= 1e-12 && f1 == C[1, 2] && f2 == C[1, 3] && l1 == C[ns, 5] && l2 == C[ns, 6]) }' \
    "$T/hull.cubic" "$T/out" && ok || no "x = 3: not station 2"
# a waterline around the hull, through three strips and across the
# keel: one closed curve, every point at z = 0.5 to rounding (1e-15 of
# the hull's size, 7)
run "$B/patchcut -z 0.5 $T/hull.design"
status 0
awk '/^points/ { n++; c = $4 == "closed=1"; next } NF == 3 { e = $3 - 0.5; e = e < 0 ? -e : e
    if (e > w) w = e } END { exit !(n == 1 && c && w <= 7e-15) }' "$T/out" && ok ||
    no "z = 0.5: not one closed curve on the plane"
# stations between: each on its plane (x to rounding, a few units in
# the last place of 5)
run "$B/patchcut -x 0.75:5.25:1.5 -t 0.001 $T/hull.design"
status 0
awk '/^points/ { split($3, v, "="); x = v[2]; n++; next } NF == 3 { e = $1 - x
	e = e < 0 ? -e : e; if (e > w) w = e } END { exit !(n == 4 && w <= 1e-14) }' \
    "$T/out" && ok || no "x = 0.75:5.25:1.5: not 4 stations on their planes"
# a plane that misses: said, naming the record; the other planes cut
run "$B/patchcut -x 9 -x 3 $T/hull.design"
status 1
says "patchcut: $T/hull.design:1: plane x = 9 misses the design"
[ "$(grep -c '^points' "$T/out")" -eq 1 ] && ok || no "x = 9, 3: x = 3 not cut"

# ---- bad input -----------------------------------------------------------
printf 'cubic\n0 0 1 0 1 0 1 0\n\ncubic\n0 0 1 1 0 1 1 0 1 1 0 1\n' >"$T/dims"
fails 1 "patchloft: $T/dims:4: section 2 has 3 coordinates, section 1 2" \
    "$B/patchloft $T/dims"
head -n 2 "$T/dims" >"$T/one"
fails 1 "patchloft: $T/one:1: 1 section: an open loft needs at least 2" \
    "$B/patchloft $T/one"
printf 'cubic\n0 0 1 0 1 0 1 0\n\npoints\n0 1\n1 1\n' >"$T/pts"
fails 1 "patchloft: $T/pts:4: a point record is no curve" "$B/patchloft $T/pts"
printf 'cubic\n0 0 1 0 1 0 1 0\n\nbezier\n0 1\n1 1\n' >"$T/bez"
fails 1 "patchloft: $T/bez:4: a bezier record: a section is a cubic or quartic curve" \
    "$B/patchloft $T/bez"
# sections that cross: the second runs from above the first to below it
printf 'cubic\n0 0 1 0 1 0 1 0\n\ncubic\n0 1 1 -1 1 -2 1 -2\n\ncubic\n0 2 1 2 1 0 1 0\n' >"$T/cross"
fails 1 "patchloft: $T/cross:4: section 2 crosses section 1" "$B/patchloft $T/cross"
printf 'cubic closed=1\n0 0 1 0 1 0 1 0\n\ncubic\n0 1 1 1 1 0 1 0\n' >"$T/mix"
fails 1 "section 2 is open, section 1 closed" "$B/patchloft $T/mix"
fails 1 "patchloft: $T/mixed.cubic:1: 2 sections: a closed loft needs at least 3" \
    "$B/patchloft -c $T/mixed.cubic"
printf 'cubic\n0 0 1 0 1 0 1 0\n\ncubic\n0 0 1 0 1 0 1 0\n' >"$T/same"
fails 1 "patchloft: $T/same:4: section 2 crosses section 1" "$B/patchloft $T/same"
fails 1 "patchloft: $T/hull.cubic:1: -S has 2 numbers, the sections 3 coordinates" \
    "$B/patchloft -S 1,0 $T/hull.cubic"
fails 1 "patchcut: $T/hull.cubic:1: cubic record: patchcut cuts surface records" \
    "$B/patchcut -x 1 $T/hull.cubic"
$B/patchnew -c 0,0 -c 1,0 -c 0,1 -c 1,1 >"$T/flat"
fails 1 "the plane's normal has no part in the surfaces' 2 coordinates" \
    "$B/patchcut -z 1 $T/flat"
finish loftcut
