#!/bin/sh
# offsets.sh: command tests of offsets, run from the top of the tree.
# References: a table written here by hand, and the Wigley hull's
# half-breadths in closed form.  The last line is "offsets: N passed,
# M failed".

T=bin/test/offsets
. tests/lib.sh

# same WHAT GOT WANT TOL FLOOR: the rows of numbers agree, each
# |g - w| <= TOL max(|w|, FLOOR); header lines compared as text
same() {
	if [ ! -s "$2" ]; then no "$1: no output: $(head -3 "$T/err")"; return; fi
	msg=$(awk -v tol="$4" -v fl="$5" 'NR == FNR { for (i = 1; i <= NF; i++)
		g[FNR, i] = $i; ng[FNR] = NF; rows = FNR; next }
	{ if (ng[FNR] != NF) { print "row " FNR ": " ng[FNR] " fields, want " NF; exit }
	  for (i = 1; i <= NF; i++) { w = $i
	    if (w !~ /^[-+0-9.]/) { if (g[FNR, i] != w) { print "row " FNR ": got " g[FNR, i] ", want " w; exit } continue }
	    d = g[FNR, i] - w; d = d < 0 ? -d : d; s = w < 0 ? -w : w; if (s < fl) s = fl
	    if (!(d <= tol * s)) { print "row " FNR " column " i ": got " g[FNR, i] ", want " w; exit } } }
	END { if (FNR != rows) print "got " rows " rows, want " FNR }' "$2" "$3")
	[ -z "$msg" ] && ok || no "$1: $msg"
}

# ---- usage -------------------------------------------------------------
usage_ok offsets
fails 2 "give stations -x and waterlines -z, or -k" "$B/offsets /dev/null"
fails 2 "give stations -x and waterlines -z, or -k" "$B/offsets -x 1 /dev/null"
fails 2 "-k reads a table: no -x or -z" "$B/offsets -k -x 1 /dev/null"
fails 2 "-x want" "$B/offsets -x 2:1:1 -z 0 /dev/null"

# ---- a table, its stations, the hull lofted through them, the table ----
# Half-breadths of a small hull at five stations and six waterlines; the
# end stations are on the centreplane (stem and stern), the keel is at
# z = 0 on every station.
cat >"$T/hull.offsets" <<'TABLE'
offsets z=0,0.25,0.5,1,1.5,2
0    0    0    0    0    0    0
1.5  0    0.4  0.7  0.95 1.05 1.1
3    0    0.55 0.85 1.1  1.2  1.25
4.5  0    0.45 0.75 1.0  1.15 1.2
6    0    0    0    0    0    0
TABLE
run "$B/offsets -k $T/hull.offsets"
status 0
# each row a station record: (x, half-breadth, z) from the lowest up
awk 'NR == 1 { split(substr($2, 3), z, ","); next }
	{ printf "points station=%s\n", $1
	  for (i = 2; i <= NF; i++) print $1, $i, z[i - 1]; print "" }' \
    "$T/hull.offsets" >"$T/want"
same "offsets -k: one station per row" "$T/out" "$T/want" 0 0
# the round trip: every number back to rounding (1e-13 of the hull's 6)
run "$B/offsets -k $T/hull.offsets | $B/splinefit -o | $B/patchloft | $B/offsets -x 0:6:1.5 -z 0,0.25,0.5,1,1.5,2"
status 0
awk NF "$T/out" >"$T/got"
same "table -> stations -> patchloft -> offsets" "$T/got" "$T/hull.offsets" 1e-13 6

# a station without a point, written -1: left out of the station
printf 'offsets z=0,1,2\n0 0 -1 1\n1 0 1 -1\n' >"$T/gap"
run "$B/offsets -k $T/gap"
printf 'points station=0\n0 0 0\n0 1 2\n\npoints station=1\n1 0 0\n1 1 1\n\n' >"$T/want"
same "offsets -k: -1 is no point" "$T/out" "$T/want" 0 0

# ---- the Wigley hull: y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2) --------------
awk 'BEGIN { L = 4; B = 0.5; T = 0.25; split("0 2 0", a); split("0 1 1", b)
	print "bezier-surface m=2 n=2"
	for (i = 0; i < 3; i++) for (j = 0; j < 3; j++)
		printf "%.17g %.17g %.17g\n", -L / 2 + L * i / 2,
		    B / 2 * a[i + 1] * b[j + 1], -T + T * j / 2 }' >"$T/wig"
run "$B/offsets -x -2:2:0.5 -z -0.25:0:0.05 $T/wig"
status 0
awk NF "$T/out" >"$T/got"
awk 'BEGIN { L = 4; B = 0.5; T = 0.25
	print "offsets z=-0.25,-0.2,-0.15,-0.1,-0.05,0"
	for (x = -2; x <= 2; x += 0.5) { printf "%.17g", x
		for (k = 0; k <= 5; k++) { z = -0.25 + 0.05 * k
			printf " %.17g", B / 2 * (1 - (2 * x / L)^2) * (1 - (z / T)^2) }
		print "" } }' >"$T/want"
same "Wigley half-breadths against the closed form" "$T/got" "$T/want" 1e-13 0.5
# outside the hull: -1
run "$B/offsets -x 3 -z 0 $T/wig"
awk NF "$T/out" >"$T/got"
printf 'offsets z=0\n3 -1\n' >"$T/want"
same "a station beyond the hull: -1" "$T/got" "$T/want" 0 0

# ---- bad input -----------------------------------------------------------
fails 1 "offsets record without its waterlines z=" "printf 'offsets\n0 1 2\n' | $B/offsets -k"
fails 1 "z=0: want 2 waterline heights" "printf 'offsets z=0\n0 1 2\n' | $B/offsets -k"
fails 1 "the waterlines must rise" "printf 'offsets z=1,0\n0 1 2\n' | $B/offsets -k"
fails 1 "a station needs 2" "printf 'offsets z=0,1\n0 1 -1\n' | $B/offsets -k"
fails 1 "cubic record: offsets -k reads offsets records" "printf 'cubic\n0 0 1 0 1 0 1 0\n' | $B/offsets -k"
fails 1 "a point record: offsets reads surface records" "printf '0 0 0\n1 1 1\n' | $B/offsets -x 0 -z 0"

finish offsets
