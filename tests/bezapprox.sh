#!/bin/sh
# bezapprox.sh: command tests of bezapprox and of sample on its records,
# run from the top of the tree.  Expected values are derived by hand in
# the comments or come from the paper (Carriazo et al. 2015); the last
# line is "bezcmd: N passed, M failed".

T=bin/test/bezcmd
. tests/lib.sh

# num_near LINE FIELD WANT TOL: field FIELD of stdout's line LINE
num_near() {
	awk -v l="$1" -v f="$2" -v w="$3" -v tol="$4" 'NR == l {
	    d = $f - w; if (d < 0) d = -d; found = 1; exit !(d <= tol) }
	    END { if (!found) exit 1 }' "$T/out" && ok ||
	    no "$what: line $1 field $2 is not $3 within $4: $(sed -n "$1p" "$T/out")"
}
# error_near WANT TOL: the header's error= attribute
error_near() {
	e=$(sed -n '1s/.*error=\([^ ]*\).*/\1/p' "$T/out")
	awk -v e="$e" -v w="$1" -v tol="$2" 'BEGIN { d = e - w
	    if (d < 0) d = -d; exit !(e != "" && d <= tol) }' && ok ||
	    no "$what: error=$e, want $1 within $2"
}

# ---- usage ---------------------------------------------------------
usage_ok bezapprox
fails 2 "-y is missing" "$B/bezapprox -x t"
fails 2 "-x is missing" "$B/bezapprox -y t"
fails 2 "-z is missing: a surface needs" "$B/bezapprox -n 3,3 -x u -y v"
fails 2 "not both" "$B/bezapprox -x t -y t /dev/null"
fails 2 "-n 2.5" "$B/bezapprox -n 2.5 -x t -y t"
# a degree the method cannot use is bad input, exit 1
fails 1 "degree 0: want 1 to 24" "$B/bezapprox -n 0 -x t -y t"
fails 1 "degree 25" "$B/bezapprox -n 25 -x t -y t"
fails 1 "degree 2: want 3 to 24" "$B/bezapprox -c -n 2 -x t -y t"
fails 1 "degree 2: want 3 to 24" "$B/bezapprox -c -n 2,4 -x u -y v -z 0"

# ---- expressions: errors name the column and point at it -------------
fails 1 "bezapprox: -y: column 3: expected a number, a name or '(', found '^'" \
    "$B/bezapprox -n 2 -x t -y 't^^2'"
# the caret stands under column 3: two spaces of indent, two before it
[ "$(sed -n 3p "$T/err")" = "    ^" ] && ok || no "caret: '$(sed -n 3p "$T/err")'"
[ "$(sed -n 2p "$T/err")" = "  t^^2" ] && ok || no "expression echo"
fails 1 "-x: column 1: unknown function 'foo'" "$B/bezapprox -x 'foo(t)' -y t"
fails 1 "-x: column 1: unknown name 'u' (the variable here is t)" \
    "$B/bezapprox -x u -y t"
fails 1 "-z: column 1: unknown name 't' (the variables here are u and v)" \
    "$B/bezapprox -n 2,2 -x u -y v -z t"
fails 1 "the curve is not finite at t = 0" "$B/bezapprox -x 'log(t)' -y t"
fails 1 "the curve is not finite" "$B/bezapprox -x '1/(t-0.5)' -y t"
fails 1 "derivative vanishes at t = 0.5" \
    "$B/bezapprox -n 2 -x '(t-0.5)^2' -y '(t-0.5)^3'"
fails 1 "the curve is a single point" "$B/bezapprox -x 1 -y 2"
fails 1 "boundary v = 0: the curve's derivative vanishes at t = 0.5" \
    "$B/bezapprox -n 2,2 -x '(u-0.5)^2' -y '(v-0.5)^2' -z 0"
# x_u = x_v = (1, 1, 0) at the centre only
fails 1 "not regular at (u, v) = (0.5, 0.5): x_u x x_v = 0" \
    "$B/bezapprox -n 2,2 -x u+v -y 'u+v+(u-0.5)^2-(v-0.5)^2' -z '(u-0.5)*(v-0.5)'"

# ---- Example 3.1: P_1 = (5/8, 1/8), F = 1/240 ---------------------------
run "$B/bezapprox -n 2 -x t -y 't^2'"
status 0
[ "$(sed -n 1p "$T/out" | cut -d' ' -f1)" = bezier ] && ok || no "header"
error_near 0.004166666666666667 1e-17
num_near 3 1 0.625 1e-15
num_near 3 2 0.125 1e-15
out_is "$(sed -n 1,3p "$T/out")
1 1
"
# Example 3.2, clamped: P_1 = alpha(1/4) + lambda_1 n(1/4) with
# lambda_1 = -sqrt(5)/32, n(1/4) = (-1, 2)/sqrt(5): (1/4 + 1/32, 0)
run "$B/bezapprox -c -n 4 -x t -y 't^2'"
status 0
error_near 0.000873819987 1e-12
num_near 3 1 0.28125 1e-15
num_near 3 2 0 1e-16
# -v reports the lambdas: lambda_2 = -59 sqrt(2)/1536 = -0.05432200532...
run "$B/bezapprox -v -c -n 4 -x t -y 't^2'"
says "lambda_2 = -0.054322005"
# -p trims the numbers, error= too
run "$B/bezapprox -p 4 -n 2 -x t -y 't^2'"
out_is "bezier error=0.004167
0 0
0.625 0.125
1 1
"

# ---- space curves: a line has no principal normal --------------------
run "$B/bezapprox -v -n 3 -x t -y 2*t -z 0"
status 0
says "no principal normal at t = 0.33333333333333331 (zero curvature): P_1 stays on the curve"
num_near 3 1 0.3333333333333333 1e-16
num_near 3 2 0.6666666666666666 1e-16

# ---- curve records -------------------------------------------------
# the parabola (t, t^2) as one cubic segment, P'_A = (1, 0), P'_B = (1, 2),
# and as two over [0, 1/2] and [1/2, 1] (tangents halved): Example 3.1
printf 'cubic\n0 0 1 1 1 0 1 2\n' >"$T/parabola1"
printf 'cubic size=+2 closed=0\n0 0 0.5 0.25 0.5 0 0.5 0.5\n0.5 0.25 1 1 0.5 0.5 0.5 1\n' \
    >"$T/parabola2"
for f in parabola1 parabola2; do
	run "$B/bezapprox -n 2 $T/$f"
	status 0
	error_near 0.004166666666666667 1e-17
	num_near 3 1 0.625 1e-15
	num_near 3 2 0.125 1e-15
done
# other attributes pass through; closed= and type go
sed -n 1p "$T/out" | grep -q '^bezier error=[^ ]* size=+2$' && ok ||
    no "attributes: $(sed -n 1p "$T/out")"
# a cubic's corners= name its joints, which the one piece does not have
# and its straight= name its segments, which the one piece does not have
run "printf 'cubic closed=0 corners=2 straight=1 size=3\n0 0 1 0 1 0 1 0\n1 0 1 1 0 1 0 1\n' | $B/bezapprox"
sed -n 1p "$T/out" | grep -q '^bezier error=[^ ]* size=3$' && ok ||
    no "corners=, straight=: $(sed -n 1p "$T/out")"
# a closed curve gives P_0 = P_n exactly
printf '0 0\n1 0\n1 1\n0 1\n' >"$T/square.knots"
run "$B/splinefit $T/square.knots | $B/bezapprox -n 5"
status 0
[ "$(sed -n 2p "$T/out")" = "$(sed -n 7p "$T/out")" ] && ok ||
    no "closed: P_0 $(sed -n 2p "$T/out"), P_5 $(sed -n 7p "$T/out")"
# a bad record between good ones: both good ones come out, exit 1
cat "$T/parabola1" >"$T/mixed"
printf '\n0 0\n1 1\n\nbezier\n0 0\n' >>"$T/mixed"
printf '\n' >>"$T/mixed"
cat "$T/parabola1" >>"$T/mixed"
run "$B/bezapprox -n 2 $T/mixed"
status 1
says "bezapprox: $T/mixed:4: a point record is no curve"
says "bezapprox: $T/mixed:7: bezier record of 1 control points: want 2 to 64"
[ "$(grep -c '^bezier' "$T/out")" = 2 ] && ok || no "mixed: two records"
# the insole through splinefit
run "$B/splinefit man/figures/insole.knots | $B/bezapprox -n 9 | $B/sample -n 4"
status 0
[ "$(grep -c . "$T/out")" = 5 ] && ok || no "insole: 5 sampled points"

# ---- sample on bezier records ------------------------------------------
# B(1/2) of Example 3.1: (5/4 t(1-t) + t^2, 1/4 t(1-t) + t^2) = (9/16, 5/16)
run "$B/bezapprox -n 2 -x t -y 't^2' | $B/sample -n 2"
status 0
num_near 2 1 0.5625 1e-15
num_near 2 2 0.3125 1e-15
# a bezier written by hand: B(1/2) of (0,0) (1,2) (2,0) is (1, 1); B' = (2, 0)
printf 'bezier\n0 0\n1 2\n2 0\n' >"$T/hand.bez"
run "$B/sample -n 2 -d $T/hand.bez"
num_near 2 1 1 0
num_near 2 2 1 0
num_near 2 3 1 0
num_near 2 4 0 0

# ---- surfaces ----------------------------------------------------------
run "$B/bezapprox -n 3,3 -x u -y 'cos(pi*v)' -z 'sin(pi*v)'"
status 0
sed -n 1p "$T/out" | grep -q '^bezier-surface m=3 n=3 error=' && ok ||
    no "surface header: $(sed -n 1p "$T/out")"
[ "$(grep -c . "$T/out")" = 17 ] && ok || no "16 control points"
# P_00 = x(0, 0) = (0, 1, 0), P_33 = x(1, 1) = (1, -1, sin pi)
num_near 2 2 1 0
num_near 17 1 1 0
num_near 17 2 -1 0
cp "$T/out" "$T/cyl.bez"
# the wireframe: 2 (n + 1) iso-lines of n + 1 points, corners on the surface
run "$B/sample -n 4 $T/cyl.bez"
status 0
# (a blank line after each, and one more after the surface's last)
[ "$(grep -c '^$' "$T/out")" = 11 ] && [ "$(tail -2 "$T/out" | tr -d '\n')" = "" ] &&
    [ "$(grep -c . "$T/out")" = 50 ] && ok || no "10 iso-lines"
num_near 1 2 1 1e-15
num_near 5 2 -1 1e-15
# a bezier-surface by hand: the bilinear x = u, y = v, z = uv
printf 'bezier-surface m=1 n=1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n' >"$T/bilinear"
run "$B/sample -n 2 $T/bilinear"
num_near 2 3 0 0
num_near 6 3 0.25 0
fails 1 "bezier-surface record has 3 rows; m=1 n=1 needs 4" \
    "printf 'bezier-surface m=1 n=1\n0 0 0\n0 1 0\n1 0 0\n' | $B/sample"
fails 1 "without its degree n=" \
    "printf 'bezier-surface m=1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n' | $B/sample"

# surface records: the bilinear patch x = 4u, y = 3v, z = uv of four
# corners; a bilinear function's Bezier net of any degree holds its values
# at (i/m, j/n) (linear precision), so at 2,2: P_ij = (2i, 1.5j, ij/4)
run "$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 | $B/bezapprox -n 2,2"
status 0
error_near 0 1e-25
for i in 0 1 2; do for j in 0 1 2; do
	l=$((3 * i + j + 2))
	num_near $l 1 $((2 * i)) 1e-15
	num_near $l 2 "$(awk -v j=$j 'BEGIN { print 1.5 * j }')" 1e-15
	num_near $l 3 "$(awk -v i=$i -v j=$j 'BEGIN { print i * j / 4 }')" 1e-15
done; done
sed -n 1p "$T/out" | grep -q '^bezier-surface m=2 n=2 error=[^ ]*$' && ok ||
    no "a patch's id and links stay behind: $(sed -n 1p "$T/out")"
# and the bezier-surface record written above, read back
run "$B/bezapprox -n 4,4 $T/cyl.bez"
status 0
sed -n 1p "$T/out" | grep -q '^bezier-surface m=4 n=4 error=' && ok ||
    no "bezier-surface in: $(sed -n 1p "$T/out")"
fails 1 "a patch record is a surface: give its degrees with -n m,n" \
    "$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 | $B/bezapprox -n 3"
fails 1 "a cubic record is a curve: -n m,n approximates surfaces" \
    "$B/bezapprox -n 3,3 $T/parabola1"
fails 1 "in the plane has no normals" \
    "$B/patchnew -c 0,0 -c 4,0 -c 0,3 -c 4,3 | $B/bezapprox -n 3,3"

# ---- output failures -----------------------------------------------
if [ -w /dev/full ]; then
	run "$B/bezapprox -x t -y t >/dev/full"
	status 1
	says "bezapprox: write error"
fi

# issue 28: 24,24, the documented top degrees, on a saddle was "the
# system is singular": rounding made the positive definite system look
# so.  Ridged, it solves, and its error= is the F of the control points
# written: an independent 25-point Gauss-Legendre integral of |x - B|^2
# here (exact for that polynomial of degree 48 in each variable)
cat >"$T/f.awk" <<'AWK'
# F = the double integral of |x - B|^2 over [0,1]^2 for x = (u, v, u^2 - v^2)
# and the bezier-surface B read, by 25-point Gauss-Legendre in each
# direction: exact for the polynomial |x - B|^2 of degree 48 in each.
function gl(q,   i, k, x, p0, p1, p2, dp) {
	for (i = 1; i <= q; i++) {
		x = cos(3.141592653589793 * (i - 0.25) / (q + 0.5))
		for (it = 0; it < 100; it++) {
			p0 = 1; p1 = x
			for (k = 2; k <= q; k++) { p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k; p0 = p1; p1 = p2 }
			dp = q * (x * p1 - p0) / (x * x - 1)
			x -= p1 / dp
		}
		p0 = 1; p1 = x
		for (k = 2; k <= q; k++) { p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k; p0 = p1; p1 = p2 }
		dp = q * (x * p1 - p0) / (x * x - 1)
		T[i] = (1 - x) / 2; W[i] = 1 / ((1 - x * x) * dp * dp)
	}
}
function bern(n, i, t,   c, k) {
	c = 1
	for (k = 1; k <= i; k++) c = c * (n - k + 1) / k
	return c * t ^ i * (1 - t) ^ (n - i)
}
NR == 1 { for (f = 2; f <= NF; f++) if ($f ~ /^[mn]=/) { split($f, kv, "="); D[kv[1]] = kv[2] + 0 }
	if ($f ~ /^error=/) ; next }
NF == 3 { P[np, 1] = $1; P[np, 2] = $2; P[np, 3] = $3; np++ }
END {
	m = D["m"]; n = D["n"]; q = 25; gl(q)
	for (a = 1; a <= q; a++) for (i = 0; i <= m; i++) BU[a, i] = bern(m, i, T[a])
	for (a = 1; a <= q; a++) for (j = 0; j <= n; j++) BV[a, j] = bern(n, j, T[a])
	F = 0
	for (a = 1; a <= q; a++) for (b = 1; b <= q; b++) {
		x[1] = T[a]; x[2] = T[b]; x[3] = T[a] ^ 2 - T[b] ^ 2
		for (c = 1; c <= 3; c++) y[c] = 0
		for (i = 0; i <= m; i++) for (j = 0; j <= n; j++) {
			w = BU[a, i] * BV[b, j]
			for (c = 1; c <= 3; c++) y[c] += w * P[i * (n + 1) + j, c]
		}
		d = 0; for (c = 1; c <= 3; c++) d += (x[c] - y[c]) ^ 2
		F += W[a] * W[b] * d
	}
	printf "%.17g\n", F
}
AWK
for mn in 24,24 16,16; do
	run "$B/bezapprox -n $mn -x u -y v -z 'u*u-v*v'"
	status 0
	f=$(awk -f "$T/f.awk" "$T/out")
	error_near "$f" "$(awk -v f="$f" 'BEGIN { print f * 1e-9 }')"
done

finish bezcmd
