#!/bin/sh
# grade.sh: command tests of grade in size systems, run from the top of
# the tree.  The reference values are the size systems' own formulas
# (an English size a third of an inch, a Paris point two thirds of a
# centimetre, Mondopoint a millimetre a size number), computed here in
# awk, and invariants (a rotated outline grades to the rotated grading,
# a mirror is a reflection turning the same way).  The last line is
# "grade: N passed, M failed".

T=bin/test/grade
. tests/lib.sh
K=man/figures/insole.knots
# the bundled insole, 265 mm long (x) and 95 mm wide (y), heel (0,0)
L0=265
W0=95
{ echo "points size=7 name=insole"; sed '/^#/d' $K; } >"$T/s7.knots"

# box: for each record "size L W" (size as written, then the extents of
# its bounding box)
box() {
	awk '
	function flush() { if (n) printf "%s %.17g %.17g\n", size, x1 - x0, y1 - y0; n = 0 }
	/^points/ { flush(); size = "?"
		for (i = 2; i <= NF; i++) if ($i ~ /^size=/) size = substr($i, 6)
		next }
	NF == 2 { if (!n++) { x0 = x1 = $1; y0 = y1 = $2 }
		if ($1 < x0) x0 = $1; if ($1 > x1) x1 = $1
		if ($2 < y0) y0 = $2; if ($2 > y1) y1 = $2 }
	END { flush() }' "$@"
}
# check_box BASE LSTEP WSTEP SIZES...: the boxes of $T/out are
# L0 + (S - BASE) LSTEP by W0 + (S - BASE) WSTEP, to 1e-9 relative, for
# exactly the sizes named, in order (LSTEP, WSTEP awk expressions)
check_box() {
	b=$1 ls=$2 ws=$3
	shift 3
	e=$(box "$T/out" | awk -v b="$b" -v L="$L0" -v W="$W0" -v want="$*" "
	BEGIN { ls = $ls; ws = $ws; n = split(want, s, \" \") }
	{ k++; d = \$1 - b; l = L + d * ls; w = W + d * ws
	  if (\$1 != s[k]) printf \"size %s where %s; \", \$1, s[k]
	  if ((\$2 - l) ^ 2 > (1e-9 * l) ^ 2 || (\$3 - w) ^ 2 > (1e-9 * w) ^ 2)
		printf \"size %s: %.17g by %.17g, want %.17g by %.17g; \", \$1, \$2, \$3, l, w }
	END { if (k != n) printf \"%d sizes, want %d\", k, n }")
	[ -z "$e" ] && ok || no "$what: $e"
}

# ---- the size systems: lengths and widths by their formulas ------------
# English: a third of an inch, and a quarter inch of joint girth over
# 2.5 of width, a size.
run "$B/grade -s 3:12 $T/s7.knots"
status 0
check_box 7 "25.4 / 3" "25.4 / 4 / 2.5" "3 4 5 6 7 8 9 10 11 12"
run "$B/grade -S english -s 5:9 $T/s7.knots"
check_box 7 "25.4 / 3" "25.4 / 4 / 2.5" "5 6 7 8 9"
# the English step is 8.4666..., not 8.46: size 8 is 273.4666... long
box "$T/out" | awk '$1 == 8 { exit !($2 > 273.466 && $2 < 273.467) }' &&
    ok || no "the English step: $(box "$T/out")"
# Paris points: two thirds of a centimetre, 5 mm of girth over 2.5
run "$B/grade -S paris -b 41 -s 38:44 $K"
status 0
check_box 41 "20 / 3" "5 / 2.5" "38 39 40 41 42 43 44"
# Mondopoint: the size is millimetres of foot, so 1 mm a size number,
# in 5 mm intervals; width 3/10 of the length step
run "$B/grade -S mondopoint -b 265 -s 250:280 $K"
status 0
check_box 265 "1" "0.3" "250 255 260 265 270 275 280"
run "$B/grade -S mondopoint -b 265 -s 262:264:1 $K"
check_box 265 "1" "0.3" "262 263 264"
# half sizes, written without trailing zeros
run "$B/grade -s 6:8:0.5 $T/s7.knots"
status 0
check_box 7 "25.4 / 3" "2.54" "6 6.5 7 7.5 8"
run "$B/grade -S paris -b 40.5 -s 40:41:0.5 $K"
check_box 40.5 "20 / 3" "2" "40 40.5 41"
# one size; -b is for records without size=, which wins
run "$B/grade -b 9 -s 8 $T/s7.knots"
check_box 7 "25.4 / 3" "2.54" "8"
# -l and -w replace the system's steps, per size number
run "$B/grade -S mondopoint -b 265 -s 255:265 -l 2 -w 0.5 $K"
check_box 265 "2" "0.5" "255 260 265"

# ---- relative steps, -r ---------------------------------------------------
# with a known size the sizes are absolute: 7 - 1 .. 7 + 1
run "$B/grade -r -1:1 $T/s7.knots"
status 0
check_box 7 "25.4 / 3" "2.54" "6 7 8"
# without one, signed steps from 0, as before
run "$B/grade -r -1:1:0.5 $K"
check_box 0 "25.4 / 3" "2.54" "-1 -0.5 0 +0.5 +1"
# Mondopoint steps go by 5 unless told
run "$B/grade -S mondopoint -r -5:5 $K"
check_box 0 "1" "0.3" "-5 0 +5"
# a relative size= adds to the step; -s refuses it
run "printf 'points size=+1\n0 0\n100 20\n50 -20\n' | $B/grade -r 1 -l 10 -w 2"
out_is "points size=+2
0 0
110 21
55 -21
"

# ---- the long axis: an outline with its toe along y ----------------------
# Turned a quarter counter-clockwise, (x, y) -> (-y, x): the heel stays
# the knot of least length coordinate, so grading the turned outline is
# turning the graded one, exactly.
awk '/^points/ { print; next } NF == 2 { printf "%.17g %.17g\n", -$2, $1; next }
    { print }' \
    "$T/s7.knots" >"$T/turned.knots"
$B/grade -s 5:9 $T/turned.knots >"$T/a"
$B/grade -s 5:9 $T/s7.knots | awk '/^points/ || NF != 2 { print; next }
    { printf "%.17g %.17g\n", -$2, $1 }' >"$T/b"
paste -d ' ' "$T/a" "$T/b" | awk '
/^points/ { if ($1 $2 $3 != $4 $5 $6) bad = 1; next }
NF == 4 { if (($1 - $3) ^ 2 + ($2 - $4) ^ 2 > (1e-9 * 265) ^ 2) bad = 1; n++ }
END { exit bad || n != 5 * 22 }' && ok ||
    no "the turned outline does not grade as the grading turned"
# its box: length along y, width along x
run "$B/grade -s 5:9 $T/turned.knots"
box "$T/out" | awk '{ print "points size=" $1; print 0, 0; print $3, $2; print "" }' >"$T/out2" &&
    mv "$T/out2" "$T/out"
what="toe along y"
check_box 7 "25.4 / 3" "2.54" "5 6 7 8 9"
# -a x grades the turned outline along x, its width, the other way
run "$B/grade -a x -s 8 -l 10 -w 2 $T/turned.knots"
box "$T/out" | awk '{ e = ($2 - 105) ^ 2 + ($3 - 267) ^ 2
    exit !(e < 1e-18) }' && ok || no "-a x: $(box "$T/out")"

# ---- -m: the mirror image --------------------------------------------------
# Each size then its mirror: knot j of the mirror is knot n-1-j of the
# size reflected across y = 0 (the heel's y, the length axis through
# the reference point); the signed area by the shoelace formula keeps
# its sign, so the mirror turns the same way.
run "$B/grade -m -s 6:8 $T/s7.knots"
status 0
awk '
function area(p, n,   a, i, j) { a = 0
	for (i = 1; i <= n; i++) { j = i % n + 1
		a += p[i, 1] * p[j, 2] - p[j, 1] * p[i, 2] }
	return a / 2 }
function flush() {
	if (!n) return
	r++
	if (r % 2) { m = n; for (i = 1; i <= n; i++) { a[i, 1] = p[i, 1]; a[i, 2] = p[i, 2] }
		if (head !~ /side=left/) { print "not left: " head; bad = 1 } }
	else {
		if (head !~ /side=right/) { print "not right: " head; bad = 1 }
		if (n != m) { print "mirror of " n " knots, not " m; bad = 1 }
		for (i = 1; i <= n; i++) {
			x = a[n + 1 - i, 1]; y = -a[n + 1 - i, 2]
			if ((p[i, 1] - x) ^ 2 + (p[i, 2] - y) ^ 2 > (1e-9 * 265) ^ 2) {
				print "knot " i ": " p[i, 1], p[i, 2] " not " x, y; bad = 1 } }
		if (area(a, m) * area(p, n) <= 0) { print "the mirror turns the other way"; bad = 1 }
	}
	n = 0 }
/^points/ { flush(); head = $0; next }
NF == 2 { n++; p[n, 1] = $1; p[n, 2] = $2 }
END { flush(); if (r != 6) { print r " records, want 6"; bad = 1 }; exit bad }' \
    "$T/out" >"$T/msg" && ok || no "-m: $(head -3 "$T/msg")"
# the sizes of both sides by the formula
box "$T/out" | awk 'NR % 2 == 1' >"$T/l" && box "$T/out" | awk 'NR % 2 == 0' >"$T/r"
cmp -s "$T/l" "$T/r" && ok || no "-m: the mirror's box differs from its size's"
# side=right on the input: the mirror is the left; about -o's line
run "printf 'points side=right\n0 10\n100 30\n50 -10\n' | $B/grade -m -r 0 -o 0,10 -l 10 -w 2"
out_is "points size=0 side=right
0 10
100 30
50 -10

points size=0 side=left
50 30
100 -10
0 10
"
# start= and end= trade places on the mirror, reflected and reversed
run "printf 'points start=1,1 end=0,-1\n0 0\n100 20\n50 -20\n' | $B/grade -m -r 0 -l 10 -w 2"
grep -q '^points size=0 side=right start=0,-1 end=-1,1$' "$T/out" && ok ||
    no "-m start= and end=: $(grep '^points' "$T/out" | tr '\n' ' ')"

# ---- -O: one file per size -------------------------------------------------
mkdir -p "$T/files"
run "$B/grade -m -s 6:7:0.5 -O $T/files/insole-%s.knots $T/s7.knots $T/s7.knots"
status 0
out_empty
[ "$(cd "$T/files" && ls | tr '\n' ' ')" = \
    "insole-6.5.knots insole-6.knots insole-7.knots " ] && ok ||
    no "-O files: $(ls "$T/files" | tr '\n' ' ')"
$B/grade -m -s 6:7:0.5 $T/s7.knots $T/s7.knots >"$T/all"
for s in 6 6.5 7; do
	awk -v s="$s" '/^points/ { keep = index($0, "size=" s " ") > 0 } keep' \
	    "$T/all" >"$T/want"
	[ "$(grep -c '^points' "$T/want")" = 4 ] &&
	    cmp -s "$T/want" "$T/files/insole-$s.knots" && ok ||
	    no "-O: insole-$s.knots is not the size $s records of the stdout form"
done
# an old file is replaced whole; a bad record adds nothing
run "{ cat $T/s7.knots; echo; printf 'points\n0 0\n0 1\n'; } |
    $B/grade -b 7 -s 6 -O $T/files/insole-%s.knots"
status 1
says "grade: <stdin>:25: the knots have no extent along x"
$B/grade -s 6 $T/s7.knots | cmp -s - "$T/files/insole-6.knots" && ok ||
    no "-O: insole-6.knots not replaced by the one good record"
# a file that cannot be made is named; the others are still written
run "$B/grade -b 7 -s 6:7 -O $T/nodir/x-%s.knots $K"
status 1
says "grade: $T/nodir/x-6.knots: cannot create"
fails 2 "-O 'insole.knots': want a file name with one %s" \
    "$B/grade -s 7 -O insole.knots $K"
fails 2 "want a file name with one %s" "$B/grade -s 7 -O '%s-%s' $K"
fails 2 "want a file name with one %s" "$B/grade -s 7 -O 'x-%d-%s' $K"
[ -z "$(ls "$T/files" | grep -v '^insole-[0-9.]*\.knots$')" ] && ok ||
    no "-O left temporary files: $(ls "$T/files")"

# ---- units: the outline in metres, the steps in metres -----------------------
awk '/^points/ { print; next } NF == 2 { printf "%.17g %.17g\n", $1 / 1000, $2 / 1000; next } { print }' \
    "$T/s7.knots" >"$T/metres.knots"
lm=$(awk 'BEGIN { printf "%.17g", 25.4 / 3 / 1000 }')
wm=$(awk 'BEGIN { printf "%.17g", 2.54 / 1000 }')
$B/grade -s 4:10:0.5 -m $T/s7.knots >"$T/mm"
for o in "-l $lm -w $wm" "-u m"; do
	$B/grade $o -s 4:10:0.5 -m $T/metres.knots >"$T/m"
	paste -d ' ' "$T/mm" "$T/m" | awk '
	/^points/ { for (i = 1; i <= NF / 2; i++) if ($i != $(i + NF / 2)) bad = 1
		next }
	NF == 4 { if (($1 / 1000 - $3) ^ 2 + ($2 / 1000 - $4) ^ 2 > (1e-9 * 0.265) ^ 2) bad = 1; n++ }
	END { exit bad || n != 13 * 2 * 22 }' && ok ||
	    no "units: grade in metres ($o) is not the grade in millimetres scaled"
done
run "$B/grade -u in -b 7 -s 8 $K"
check_box 7 "1 / 3" "0.1" "8"
# millimetre steps on an outline in metres: the record is refused
fails 1 "grade: $T/metres.knots:1: a length step of 8.46667 a size is more than 0.25 of the outline's length 0.265" \
    "$B/grade -s 8 $T/metres.knots"

# ---- bad input ----------------------------------------------------------------
fails 1 "grade: $K:4: no base size: absolute sizes (-s) need the outline's own" \
    "$B/grade -s 3:12 $K"
fails 1 "size 0 is outside the english range, 1 to 18" "$B/grade -s 0:2 $T/s7.knots"
fails 1 "size 19 is outside the english range, 1 to 18" "$B/grade -r 12 $T/s7.knots"
fails 1 "size 14 is outside the paris range, 15 to 56" "$B/grade -S paris -b 40 -s 14:16 $K"
fails 1 "size 360 is outside the mondopoint range, 100 to 350" \
    "$B/grade -S mondopoint -b 360 -s 300 $K"
fails 1 "size=+1 is a step from an unknown size, not a size" \
    "printf 'points size=+1\n0 0\n100 20\n50 -20\n' | $B/grade -s 7"
fails 1 "<stdin>:1: the outline is 100 by 98, square within 5%" \
    "printf 'points\n0 0\n100 49\n0 -49\n' | $B/grade -r 1 -l 1 -w 1"
run "printf 'points\n0 0\n100 49\n0 -49\n' | $B/grade -a y -r 1 -l 1 -w 1"
status 0
fails 1 "the knots have no extent along y" "printf '0 0\n100 0\n' | $B/grade -r 1"
# the message names the bad record's line; the good ones are written
{ cat "$T/s7.knots"; echo; echo "points size=30"; sed '/^#/d' $K; echo; cat "$T/s7.knots"; } >"$T/mixed"
run "$B/grade -s 8 $T/mixed"
status 1
says "grade: $T/mixed:25: size 30 is outside the english range"
[ "$(grep -c '^points size=8 name=insole$' "$T/out")" = 2 ] && ok ||
    no "the good records around a bad one"
# usage
fails 2 "-S 'french'" "$B/grade -S french -s 7 $K"
fails 2 "want SIZE or FROM:TO[:STEP]" "$B/grade -s 7.25 $K"
fails 2 "want SIZE or FROM:TO[:STEP]" "$B/grade -s 6:8:0 $K"
fails 2 "want SIZE or FROM:TO[:STEP]" "$B/grade -s 6:8:-1 $K"
fails 2 "give -s or -r once" "$B/grade -s 7 -r 1 $K"
fails 2 "-a 'z'" "$B/grade -a z -s 7 $K"
fails 2 "-u 'ft'" "$B/grade -u ft -s 7 $K"
fails 2 "more than 1000 sizes" "$B/grade -r -1000:1000:0.5 $K"

finish grade
