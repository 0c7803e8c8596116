#!/bin/sh
# cmd.sh: command tests of the programs in bin/, run from the top of the
# tree.  Expected outputs are derived by hand in the comments; the last
# line is "cmd: N passed, M failed".

T=bin/test/cmd
. tests/lib.sh

printf '0 0\n1 0\n1 1\n0 1\n' >"$T/square.knots"
printf '10 0\n3.5 9.4\n0 2\n-3.5 9.4\n-10 0\n-7 -7\n0 -10\n7 -7\n' \
    >"$T/fig15.knots"

# ---- usage ---------------------------------------------------------
for p in splinefit sample; do
	usage_ok "$p"
done
# --help and --version (issue 18), every program (each is cmd/NAME.c):
# --help is -h to the byte; --version is one line "NAME (loft) V" with V
# the version lib/version.h keeps; either into a full disk is a write
# error, exit 1; another long option is a usage error, and one after the
# first argument is not looked at (-h --version is -h).
version=$(sed -n 's/^#define LOFT_VERSION "\(.*\)"$/\1/p' lib/version.h)
[ -n "$version" ] && ok || no "lib/version.h: no LOFT_VERSION"
for c in cmd/*.c; do
	p=$(basename "$c" .c)
	"$B/$p" -h >"$T/h" 2>/dev/null
	run "$B/$p --help"
	status 0
	cmp -s "$T/h" "$T/out" && [ -s "$T/out" ] && ok ||
	    no "$p --help: stdout is not that of -h"
	run "$B/$p --version"
	status 0
	out_is "$p (loft) $version"
	if [ -w /dev/full ]; then
		for o in --help --version; do
			run "$B/$p $o >/dev/full"
			status 1
			says "$p: write error: "
		done
	fi
	run "$B/$p --versions"
	status 2
	run "$B/$p -h --version"
	status 0
	cmp -s "$T/h" "$T/out" && ok || no "$p -h --version: not the usage"
done
fails 2 "-p '0': want a whole number from 1 to 17" "$B/splinefit -p 0 $T/square.knots"
fails 2 "-p '18'" "$B/sample -p 18 /dev/null"
fails 2 "-n '0'" "$B/sample -n 0 /dev/null"
fails 2 "-S and -E give the ends of an open curve" "$B/splinefit -S 1,0 $T/square.knots"
fails 2 "want 2 or 3 numbers" "$B/splinefit -o -S 1 $T/square.knots"
fails 2 "-S 'x' is not a number" "$B/splinefit -o -S x,1 $T/square.knots"
fails 2 "want manning, ferguson, chord or fair" "$B/splinefit -m cubic $T/square.knots"
fails 2 "want positive or turn" "$B/splinefit -k neg $T/square.knots"
fails 2 "want a number from 0.5 to 1" "$B/splinefit -a 0.3 $T/square.knots"
fails 2 "-i '0'" "$B/splinefit -i 0 $T/square.knots"

# ---- output derived by hand ----------------------------------------
# Two knots, tangents at 90 degrees to the chord: eq. 9 gives both
# magnitudes 2W/(1 + 0) = 2.
run "printf '0 0\n1 0\n' | $B/splinefit -m manning -o -S 0,1 -E 0,-1"
status 0
out_is "cubic closed=0
0 0 1 0 0 2 0 -2
"
# The same segment sampled: P(1/2) = (P_A + P_B)/2 + (P'_A - P'_B)/8.
printf 'cubic closed=0\n0 0 1 0 0 2 0 -2\n' >"$T/seg.cubic"
run "$B/sample -n 2 $T/seg.cubic"
out_is "0 0
0.5 0.5
1 0

"
# -a: the header, as written above, as a comment before the same rows;
# a surface's before its lines.  loft's reader skips it: loftplot draws the
# same picture with and without it.
run "$B/sample -a -n 2 $T/seg.cubic"
out_is "# cubic closed=0
0 0
0.5 0.5
1 0

"
printf 'cubic closed=0 size=+1 id=a=b\n0 0 1 0 0 2 0 -2\n' >"$T/attr.cubic"
run "$B/sample -a -n 1 $T/attr.cubic"
[ "$(head -1 "$T/out")" = "# cubic closed=0 size=+1 id=a=b" ] && ok ||
    no "sample -a: $(head -1 "$T/out")"
$B/sample -n 4 $T/seg.cubic | $B/loftplot >"$T/plain.svg"
$B/sample -a -n 4 $T/seg.cubic | $B/loftplot >"$T/attr.svg"
cmp -s "$T/plain.svg" "$T/attr.svg" && ok || no "sample -a: loftplot reads it otherwise"
run "$B/patchnew -i 7 -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 | $B/sample -a -n 1"
[ "$(grep -n '^#' "$T/out")" = "1:# patch id=7" ] && ok ||
    no "sample -a of a patch: $(grep -n '#' "$T/out")"
# Two blank lines after each input record's points: to gnuplot each
# record is a data set, so index 1 is the second record's rows, the
# segment moved up by 1 (by hand: (0,1) (0.5,1.5) (1,1)); GNU graph
# reads the same three polylines as from one blank line (with -B, which
# keeps its line mode: an empty data set would bump it); loft's reader
# takes both, loftplot draws the same picture.
{ cat $T/seg.cubic; printf '\ncubic\n0 1 1 1 0 2 0 -2\n\ncubic\n0 2 1 2 0 2 0 -2\n'; } \
    >"$T/three.cubic"
$B/sample -n 2 "$T/three.cubic" >"$T/three.pts"
awk 'BEGIN { RS = ""; ORS = "\n\n" } { print }' "$T/three.pts" >"$T/one.pts"
[ "$(grep -c '^$' "$T/three.pts")" = 6 ] && [ "$(grep -c '^$' "$T/one.pts")" = 3 ] &&
    ok || no "sample: not two blank lines a record"
$B/loftplot "$T/three.pts" >"$T/three.svg"
$B/loftplot "$T/one.pts" >"$T/one.svg"
cmp -s "$T/three.svg" "$T/one.svg" && ok || no "loftplot reads two blank lines otherwise"
if command -v gnuplot >/dev/null 2>&1; then
	(cd "$T" && gnuplot -e "set table 'index1.txt'; plot 'three.pts' index 1 using 1:2 with lines") 2>"$T/err"
	[ "$(awk '$3 == "i" { printf "%s %s|", $1, $2 }' "$T/index1.txt")" = \
	    "0 1|0.5 1.5|1 1|" ] && ok || no "gnuplot index 1: $(cat "$T/index1.txt" "$T/err")"
	# and with sample -a's header comments, the same data sets
	$B/sample -a -n 2 "$T/three.cubic" >"$T/three-a.pts"
	(cd "$T" && gnuplot -e "set table 'index1a.txt'; plot 'three-a.pts' index 1 using 1:2 with lines") 2>"$T/err"
	[ "$(awk '$3 == "i" { printf "%s %s|", $1, $2 }' "$T/index1a.txt")" = \
	    "0 1|0.5 1.5|1 1|" ] && ok || no "gnuplot index 1 after sample -a: $(cat "$T/index1a.txt" "$T/err")"
else
	echo "skip: gnuplot's index of sample's records (no gnuplot)"
fi
if command -v graph >/dev/null 2>&1 && graph --version 2>&1 | grep -q plotutils; then
	graph -T svg -B "$T/three.pts" >"$T/g2.svg" 2>"$T/err"
	graph -T svg -B "$T/one.pts" >"$T/g1.svg" 2>>"$T/err"
	[ "$(grep -c '<polyline' "$T/g2.svg")" = 3 ] && cmp -s "$T/g1.svg" "$T/g2.svg" &&
	    [ ! -s "$T/err" ] && ok || no "GNU graph reads two blank lines otherwise: $(head -2 "$T/err")"
else
	echo "skip: GNU graph on sample's records (no plotutils graph)"
fi
# With R2 = 3(P_B-P_A) - 2P'_A - P'_B = (3,-2), R3 = (-2,0):
# P' = (0,2), (1.5,0), (0,-2) and P'' = (6,-4), (0,-4), (-6,-4) at
# u = 0, 1/2, 1, so the curvature (x'y''-y'x'')/|P'|^3 is -12/8, -6/3.375,
# -12/8.
run "$B/sample -n 2 -k -u -d -p 6 $T/seg.cubic"
out_is "0 0 0 0 1 -1.5
0.5 0.5 0.5 1 0 -1.77778
1 0 1 0 -1 -1.5

"
# The square: tangents parallel to P_{i+1} - P_{i-1} already solve eq. 10
# by symmetry; at 45 degrees to each chord, eq. 8 gives magnitude
# 2/(1 + cos 45) = 4 - 2 sqrt 2, components 2 sqrt 2 - 2 = 0.828427.
run "$B/splinefit -m manning -p 6 $T/square.knots"
status 0
out_is "cubic closed=1
0 0 1 0 0.828427 -0.828427 0.828427 0.828427
1 0 1 1 0.828427 0.828427 -0.828427 0.828427
1 1 0 1 -0.828427 0.828427 -0.828427 -0.828427
0 1 0 0 -0.828427 -0.828427 0.828427 -0.828427
"
# The default with -1 (a cubic a span) fits the square with the same
# symmetry (fit.sh checks its magnitude); the tests of the stream below
# compare against it.  Without -1 each quarter turn is split in two
# (fit.sh: the knots of a circle give the circle).
run "$B/splinefit -1 -p 6 $T/square.knots"
status 0
awk 'NR > 1 && NF == 8 { for (i = 5; i <= 8; i++) { a = $i < 0 ? -$i : $i
    if (v == "") v = a; else if (a != v) bad = 1 } } END { exit bad }' \
    "$T/out" && ok || no "$what: the square's magnitudes differ"
cp "$T/out" "$T/square.cubic6"
# Lossless: knots come back in the rows exactly as they were written.
run "printf '0.1 0.2\n0.30000000000000004 1e-300\n' | $B/splinefit -o"
head -2 "$T/out" | tail -1 | grep -q '^0.1 0.2 0.30000000000000004 1e-300 ' &&
    ok || no "lossless knots: $(cat "$T/out")"

# ---- attributes ----------------------------------------------------
run "printf 'points id=7 start=0,1 end=0,-1\n0 0\n1 0\n' | $B/splinefit -m manning -o"
out_is "cubic closed=0 id=7
0 0 1 0 0 2 0 -2
"
# -E wins over the attribute: end tangent (0,1) also at 90 degrees.
run "printf 'points start=0,1 end=0,-1\n0 0\n1 0\n' | $B/splinefit -m manning -o -E 0,1"
out_is "cubic closed=0
0 0 1 0 0 2 0 2
"
fails 1 "attribute start=1,0,0: want 2 numbers" \
    "printf 'points start=1,0,0\n0 0\n1 1\n' | $B/splinefit -o"
fails 1 "the start tangent has 3 coordinates but the knots have 2" \
    "$B/splinefit -o -S 1,0,0 $T/square.knots"

# ---- batches and bad records between good ones ----------------------
i=0
: >"$T/many.knots"
while [ $i -lt 50 ]; do
	cat "$T/square.knots" >>"$T/many.knots"
	echo >>"$T/many.knots"
	i=$((i + 1))
done
run "$B/splinefit -1 -p 6 $T/many.knots"
status 0
[ "$(grep -c '^cubic' "$T/out")" = 50 ] && ok || no "50 records in, 50 out"
[ "$(sort -u "$T/out" | wc -l)" -eq 6 ] && ok || no "batch records differ"
run "$B/splinefit -1 $T/many.knots | $B/sample -n 4"
[ "$(grep -c . "$T/out")" = $((50 * 17)) ] && ok || no "50 x 17 points"
run "$B/splinefit $T/many.knots | $B/sample -n 4"
[ "$(grep -c . "$T/out")" = $((50 * 33)) ] && ok ||
    no "50 x 33 points: the square's quarter turns split in two"

{ cat "$T/square.knots"; printf '\n# bad\n0 0\nnan 1\n1 1\n\n'
  cat "$T/square.knots"; } >"$T/mixed.knots"
run "$B/splinefit -1 -p 6 $T/mixed.knots"
status 1
says "splinefit: $T/mixed.knots:8: 'nan' is not a number"
cat "$T/square.cubic6" "$T/square.cubic6" | cmp -s - "$T/out" && ok ||
    no "good records around a bad one"
{ cat "$T/seg.cubic"; printf '\ncubic\n1 2 3\n\n'; cat "$T/seg.cubic"; } \
    >"$T/mixed.cubic"
run "$B/sample -n 2 $T/mixed.cubic"
status 1
says "sample: $T/mixed.cubic:5: cubic rows need 8 or 12 numbers, not 3"
[ "$(grep -c . "$T/out")" = 6 ] && ok || no "sample: good records kept"

# ---- degeneracies, each named ---------------------------------------
fails 1 "<stdin>:3: knot 3 coincides with knot 2" \
    "printf '0 0\n1 0\n1 0\n0 1\n' | $B/splinefit -d 0"
fails 1 "<stdin>:1: knot 1 coincides with knot 4 (closing the curve" \
    "printf '0 0\n1 0\n1 1\n0 0\n' | $B/splinefit -d 0"
fails 1 "2 knots: a closed curve needs at least 3" \
    "printf '0 0\n1 0\n' | $B/splinefit"
fails 1 "1 knot: an open curve needs at least 2" \
    "printf '0 0\n' | $B/splinefit -o"
fails 1 "start tangent is zero" \
    "printf 'points start=0,0\n0 0\n1 0\n' | $B/splinefit -o"
fails 2 "-S '0,0': a direction cannot be zero" \
    "printf '0 0\n1 0\n' | $B/splinefit -o -S 0,0"
fails 1 "<stdin>:2: knots 1 and 3 on either side of knot 2 coincide" \
    "printf '0 0\n1 0\n0 0\n0 1\n' | $B/splinefit -m manning"
fails 1 "all knots lie on one line" \
    "printf '0 0\n1 1\n3 3\n2 2\n' | $B/splinefit"
fails 1 "no convergence in 2 iterations: tangents still move by" \
    "$B/splinefit -m manning -i 2 $T/fig15.knots"
fails 1 "knots have 1 coordinate; 2 or 3 are needed" \
    "printf '0\n1\n2\n' | $B/splinefit"
fails 1 "knots have 4 coordinates" \
    "printf '0 0 0 0\n1 0 0 0\n1 1 0 0\n' | $B/splinefit"
fails 1 "cubic record: splinefit reads knots" "$B/splinefit $T/seg.cubic"
fails 1 "a point record is no curve" "$B/sample $T/square.knots"
fails 1 "<stdin>:1: a point record is no curve" \
    "printf 'points\n0 0\n1 1\n' | $B/sample"
fails 1 "sample: $T: read error: Is a directory" "$B/sample $T"
fails 1 "unknown record type 'spline'" "printf 'spline\n1 2\n' | $B/sample"
fails 1 "tangent vanishes in segment 1" \
    "printf 'cubic\n0 0 1 0 0 0 1 0\n' | $B/sample -d"
run "printf 'cubic\n0 0 1 0 0 0 1 0\n' | $B/sample -n 1"
status 0
fails 1 "attribute closed=2: want 0 or 1" \
    "printf 'cubic closed=2\n0 0 1 0 0 2 0 -2\n' | $B/sample"
fails 1 "record has no knots" "printf 'points id=1\n' | $B/splinefit"

# ---- -v --------------------------------------------------------------
run "$B/splinefit -m manning -v $T/fig15.knots"
status 0
says "fig15.knots:1: 8 knots,"
says "iterations, converged"
says "the other sign rule (-k turn) reaches a DIFFERENT curve"
grep -q '^cubic closed=1$' "$T/out" && ok || no "-v still writes the curve"
run "$B/splinefit -m manning -v -k turn $T/square.knots"
says "the other sign rule (-k positive) reaches the same curve"
run "$B/splinefit -v -m chord $T/square.knots"
says "0 iterations"

# ---- files, standard input, output errors ---------------------------
run "$B/splinefit -1 -p 6 $T/nonexistent.knots - $T/square.knots < $T/square.knots"
status 1
says "splinefit: $T/nonexistent.knots: No such file or directory"
cat "$T/square.cubic6" "$T/square.cubic6" | cmp -s - "$T/out" && ok ||
    no "files after a missing one, and -, are read"
run "$B/splinefit $T/square.knots > /dev/full"
status 1
says "splinefit: write error"
run "$B/splinefit $T/square.knots | $B/sample > /dev/full"
status 1
says "sample: write error"
i=0
while [ $i -lt 200 ]; do cat "$T/many.knots"; i=$((i + 1)); done >"$T/big.knots"
run "$B/splinefit $T/big.knots | $B/sample | head -1"
status 0
out_is "0 0"
# CRLF line ends, no final newline
run "printf '0 0\r\n1 0\r\n1 1\r\n0 1' | $B/splinefit -1 -p 6"
cmp -s "$T/out" "$T/square.cubic6" && ok || no "CRLF and no final newline"

# ---- the README's tour --------------------------------------------------
run "$B/splinefit man/figures/insole.knots | $B/sample -n 20"
status 0
[ "$(grep -c . "$T/out")" = 441 ] && ok || no "insole: 22 x 20 + 1 points"
# arc.knots lie on the unit circle; so must Manning's curve, closely
run "$B/splinefit -m manning -o -S 1,0 -E 0,-1 man/figures/arc.knots | $B/sample"
status 0
awk 'NF == 2 { d = sqrt($1 * $1 + $2 * $2) - 1; if (d < 0) d = -d
	if (d > m) m = d; n++ } END { exit !(n == 49 && m < 1e-6) }' "$T/out" &&
    ok || no "arc: 49 points within 1e-6 of the unit circle"
run "{ cat man/figures/insole.knots; echo; cat man/figures/insole.knots; } |
    $B/splinefit | $B/sample -p 6"
status 0
[ "$(grep -c . "$T/out")" = 706 ] && ok || no "batch: 2 x (22 x 16 + 1)"

# splinefit(1)'s -v example, unfolded, is what the command says: the
# page's text is the reference, so the page cannot drift from the program.
sed -n '/^\$ splinefit -v -m manning man\/figures\/insole.knots/,/^\.Ed/p' man/splinefit.1 |
    sed '1d;$d' | tr '\n' ' ' | sed 's/ $//' >"$T/want"
$B/splinefit -v -m manning man/figures/insole.knots 2>"$T/got" >/dev/null
[ -s "$T/want" ] && [ "$(cat "$T/want")" = "$(cat "$T/got")" ] && ok ||
    no "splinefit(1)'s -v example: '$(cat "$T/want")', the program says '$(cat "$T/got")'"

echo "cmd: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
