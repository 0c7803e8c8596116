#!/bin/sh
# patch.sh: command tests of patchnew, patchsplit, patchdrag, patchjoin
# and sample's surfaces, run from the top of the tree.  Expected outputs
# are derived by hand in the comments; the last line is
# "patchcmd: N passed, M failed".

T=bin/test/patchcmd
. tests/lib.sh
# near FILE1 FILE2 TOL: same shape, numbers within TOL
near() {
	awk -v tol="$3" 'NR == FNR { a[FNR] = $0; n = FNR; next }
	    { split(a[FNR], x); if (NF != split(a[FNR], x)) bad = 1
	      for (i = 1; i <= NF; i++) { d = $i - x[i]; if (d < 0) d = -d
	      if (d > tol) bad = 1 } m = FNR }
	    END { exit bad || m != n }' "$1" "$2"
}

# ---- usage ---------------------------------------------------------
for p in patchnew patchsplit patchdrag patchjoin; do
	usage_ok "$p"
done
fails 2 "give four corners with -c" "$B/patchnew -c 0,0 -c 1,0 -c 0,1"
fails 2 "want 2 numbers" "$B/patchnew -c 0,0 -c 1,0 -c 0,1 -c 1,1,1"
# malformed option syntax is a usage error (2); a number the method
# cannot use is bad input (1), as in issue 4
fails 2 "-u '0.5x' is not a number" "$B/patchsplit -u 0.5x /dev/null"
fails 2 "usage: patchsplit" "$B/patchsplit -u"
fails 2 "-i '2.5': want a whole number" "$B/patchsplit -i 2.5 -u 0.5 /dev/null"
fails 1 "patchsplit: -u 1.5: want a number between 0 and 1, both excluded" \
    "$B/patchsplit -u 1.5 /dev/null"
fails 1 "-v 0: want a number between 0 and 1" "$B/patchsplit -v 0 /dev/null"
fails 1 "-v -0.5: want a number between 0 and 1" "$B/patchsplit -v -0.5 /dev/null"
fails 2 "give -u t or -v t" "$B/patchsplit /dev/null"
fails 2 "give one of -u and -v" "$B/patchsplit -u 0.5 -v 0.5 /dev/null"
fails 2 "give -u, and one of -b and -t" "$B/patchdrag -u 0.5 /dev/null"
fails 1 "patchdrag: -w 0,0,0: a direction cannot be zero" \
    "$B/patchdrag -u 0.5 -b 0,0,1 -w 0,0,0 /dev/null"
fails 1 "patchdrag: -e 0.7: want a reach from 0 to 0.5" \
    "$B/patchdrag -e 0.7 -u 0.5 -b 0,0,1 /dev/null"
fails 2 "-u 'half' is not a number" "$B/patchdrag -u half -b 0,0,1 /dev/null"
fails 2 "-b 'x' is not a number" "$B/patchdrag -u 0.5 -b 0,0,x /dev/null"
fails 2 "give the two patches with -P and -S" "$B/patchjoin -P 1 /dev/null"
fails 2 "-S 'x': want a whole number" "$B/patchjoin -P 1 -S x /dev/null"
fails 1 "patchnew: -i 0: want an id from 1 to 1000000000" \
    "$B/patchnew -i 0 -c 0,0 -c 1,0 -c 0,1 -c 1,1"
fails 2 "-i '1.5': want a whole number" \
    "$B/patchnew -i 1.5 -c 0,0 -c 1,0 -c 0,1 -c 1,1"
fails 2 "-f obj has none" "$B/sample -f obj -u /dev/null"
fails 2 "want points or obj" "$B/sample -f stl /dev/null"

# ---- patchnew -------------------------------------------------------
# Corners (00) = 0,0,0, (10) = 4,0,0, (01) = 0,3,0, (11) = 4,3,1 of the
# bilinear patch: f_u = (1-v)(4,0,0) + v(4,0,1), f_v = (1-u)(0,3,0) +
# u(0,3,1), twist (11)-(10)-(01)+(00) = (0,0,1); the (h) entries are
# midpoints: (0h) = (0,1.5,0), (hh) = the corners' mean (2,1.5,0.25).
run "$B/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1"
status 0
out_is "patch id=1
0 0 0 0 3 0 0 3 0 0 3 0 0 1.5 0
4 0 0 4 3 1 0 3 1 0 3 1 4 1.5 0.5
4 0 0 4 0 1 0 0 1 0 0 1 4 0 0.5
4 0 0 4 0 1 0 0 1 0 0 1 4 0 0.5
2 0 0 2 3 0.5 0 3 0.5 0 3 0.5 2 1.5 0.25
"
cp "$T/out" "$T/hull.patch"
sed -n 2,7p "$T/hull.patch" >"$T/hull.patch.rows"
# Four straight edges of the same patch as cubics (slope = chord): Coons'
# patch of straight lines is the bilinear patch.
cat >"$T/edges.cubic" <<'E'
cubic
0 0 0 4 0 0 4 0 0 4 0 0

cubic
0 3 0 4 3 1 4 0 1 4 0 1

cubic
0 0 0 0 3 0 0 3 0 0 3 0

cubic
4 0 0 4 3 1 0 3 1 0 3 1
E
run "$B/patchnew -b $T/edges.cubic"
status 0
near "$T/out" "$T/hull.patch" 1e-15 && ok || no "Coons of lines: $(cat "$T/out")"
sed 's/^0 3 0 4 3 1 /0 3 0 4 3 1.5 /' "$T/edges.cubic" >"$T/bad.cubic"
fails 1 "bad.cubic:10: corner (11): the end of curve 2 (v=1) is 0.5 from the end of curve 4 (u=1)" \
    "$B/patchnew -b $T/bad.cubic"
fails 1 "-b wants 4 curve records" "head -5 $T/edges.cubic | $B/patchnew -b"
fails 1 "<stdin>:1: a boundary is one segment, not 2" \
    "{ sed -n 1,2p $T/edges.cubic; sed -n 2,3p $T/edges.cubic; sed -n '4,\$p' $T/edges.cubic; } | $B/patchnew -b"

# ---- patchsplit ------------------------------------------------------
# Fig. 5: 1 -> 2 (u < 0.4), 3; then 2 -> 4 (v < 0.5), 5.  4 and 5 each
# lie across half of 3's u0 edge; scale factors 0.4 x 0.5, 0.6 x 1.
run "$B/patchsplit -u 0.4 $T/hull.patch | $B/patchsplit -i 2 -v 0.5 | grep patch"
status 0
out_is "patch id=4 su=0.4 sv=0.5 u1=3 v1=5
patch id=5 su=0.4 sv=0.5 u1=3 v0=4
patch id=3 su=0.6 u0=4:0:0.5,5:0.5:1"
# A split patch's halves meet exactly: the u = 1 line of patch 2 is the
# u = 0 line of patch 3.  At -n 4 each patch gives 10 records, the lines
# u = j/4 first: records 5 and 11.
$B/patchsplit -u 0.4 "$T/hull.patch" >"$T/two.patch"
$B/sample -n 4 "$T/two.patch" | awk -v RS= 'NR == 5 || NR == 11' >"$T/edges"
[ "$(sed -n 1,5p "$T/edges")" = "$(sed -n 6,10p "$T/edges")" ] && ok ||
    no "split halves meet: $(cat "$T/edges")"
# every patch split: the four halves of patches 2 and 3, new ids from
# the largest, 3: 4, 5 (of 2) and 6, 7 (of 3)
run "$B/patchsplit -v 0.5 $T/two.patch | grep patch"
out_is "patch id=4 su=0.4 sv=0.5 u1=6 v1=5
patch id=5 su=0.4 sv=0.5 u1=7 v0=4
patch id=6 su=0.6 sv=0.5 u0=4 v1=7
patch id=7 su=0.6 sv=0.5 u0=5 v0=6"
# other attributes go to both halves
run "sed 's/^patch id=1/patch id=1 name=hull/' $T/hull.patch | $B/patchsplit -u 0.5 | grep -c 'name=hull'"
out_is "2"
# bad input: nothing is written
fails 1 "hull4.patch:1: patch record has 4 rows; a patch has 5" \
    "head -5 $T/hull.patch > $T/hull4.patch; $B/patchsplit -u 0.5 $T/hull4.patch"
fails 1 "no patch with id 9 in the input" "$B/patchsplit -i 9 -u 0.5 $T/hull.patch"
fails 1 "<stdin>:1: patch 1: neighbour 7 across u1 is not in the design" \
    "sed 's/^patch id=1/patch id=1 u1=7/' $T/hull.patch | $B/patchsplit -u 0.5"
fails 1 "patch 1 names 2 across u1, but 2 does not name 1" \
    "{ sed 's/^patch id=1/patch id=1 u1=2/' $T/hull.patch; sed 's/id=1/id=2/' $T/hull.patch; } | $B/patchsplit -u 0.5"
fails 1 "id 1 is used twice" "cat $T/hull.patch $T/hull.patch | $B/patchsplit -u 0.5"
fails 1 "patch has no id=" "sed 's/^patch id=1/patch/' $T/hull.patch | $B/patchsplit -u 0.5"
fails 1 "attribute u0=2:0.5:0.5: from and to must differ" \
    "sed 's/^patch id=1/patch id=1 u0=2:0.5:0.5/' $T/hull.patch | $B/patchsplit -u 0.5"
fails 1 "cubic record: patchsplit reads patch records" \
    "$B/patchsplit -u 0.5 $T/edges.cubic"
{ cat "$T/hull.patch"; printf 'patch id=2\n1 nan 3\n\n'; } >"$T/mixed.patch"
fails 1 "nothing written: the input is one design" "$B/patchsplit -u 0.5 $T/mixed.patch"
says "mixed.patch:9: 'nan' is not a number"
fails 1 "<stdin>:2: patch rows need 10 or 15 numbers, not 3" \
    "printf 'patch id=2\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n' | $B/patchsplit -u 0.5"

# ---- patchdrag ------------------------------------------------------
# Central drag at (1/2, 1/2): H5(1/2) = 1, so (hh) gains the drag itself:
# (2, 1.5, 0.25) + (0, 0, 0.3) = (2, 1.5, 0.55); nothing else changes.
run "$B/patchdrag -u 0.5 -v 0.5 -b 0,0,0.3 $T/hull.patch"
status 0
sed '6s/ 2 1.5 0.25$/ 2 1.5 0.55/' "$T/hull.patch" | cmp -s - "$T/out" && ok ||
    no "central drag: $(cat "$T/out")"
# -t: to (2, 1.5, 1): the same coefficient, now (2, 1.5, 1)
run "$B/patchdrag -u 0.5 -v 0.5 -t 2,1.5,1 $T/hull.patch"
sed '6s/ 2 1.5 0.25$/ 2 1.5 1/' "$T/hull.patch" | cmp -s - "$T/out" && ok ||
    no "drag to a target: $(cat "$T/out")"
# -w 0,0,1: the z part of the drag is dropped: (hh) + (0.2, 0, 0)
run "$B/patchdrag -u 0.5 -v 0.5 -b 0.2,0,5 -w 0,0,1 $T/hull.patch"
sed '6s/ 2 1.5 0.25$/ 2.2 1.5 0.25/' "$T/hull.patch" | cmp -s - "$T/out" && ok ||
    no "drag in the display plane: $(cat "$T/out")"
fails 1 "zero displacement after projection onto the display plane" \
    "$B/patchdrag -u 0.5 -v 0.5 -b 0,0,1 -w 0,0,2 $T/hull.patch"
fails 1 "zero displacement: nothing to drag" \
    "$B/patchdrag -u 0.5 -v 0.5 -b 0,0,0 $T/hull.patch"
fails 1 "-b has 2 coordinates but the record has 3" \
    "$B/patchdrag -u 0.5 -v 0.5 -b 0,1 $T/hull.patch"
fails 1 "patch 1: -v V is needed to drag a patch" \
    "$B/patchdrag -u 0.5 -b 0,0,1 $T/hull.patch"
fails 1 "is on the patch's edge u0, which dragging keeps fixed (no neighbour across u0)" \
    "$B/patchdrag -u 0 -v 0.5 -b 0,0,1 $T/hull.patch"
fails 1 "the input holds 2 records: name the one to drag with -i" \
    "$B/patchdrag -u 0.5 -v 0.5 -b 0,0,1 $T/two.patch"
fails 1 "no record with id 7 in the input" \
    "$B/patchdrag -i 7 -u 0.5 -v 0.5 -b 0,0,1 $T/two.patch"
fails 1 "-u 2 -v 0.5 is outside the patch's parameter square" \
    "$B/patchdrag -u 2 -v 0.5 -b 0,0,1 $T/hull.patch"
fails 1 "-u -0.5 -v 0.5 is outside the patch's parameter square" \
    "$B/patchdrag -u -0.5 -v 0.5 -b 0,0,1 $T/hull.patch"
fails 1 "no record with id 0 in the input" \
    "$B/patchdrag -i 0 -u 0.5 -v 0.5 -b 0,0,1 $T/two.patch"
fails 1 "no patch with id 0 in the input" "$B/patchsplit -i 0 -u 0.5 $T/two.patch"
# a design whose result is not finite (issue 12: with the check in
# loft_run_design taken out, patchsplit wrote rows cut short and exited
# 0): the unit square as patchnew -c writes it, every number scaled by
# 1.7e308, near the largest double; splitting at v = 0.3 and dragging
# by 1e308 overflow.
# loft(5): nothing is written, one message, exit 1.
printf 'patch id=1\n0 0 0 1.7e308 0 1.7e308 0 1.7e308 0 8.5e307
1.7e308 0 1.7e308 1.7e308 0 1.7e308 0 1.7e308 1.7e308 8.5e307
1.7e308 0 1.7e308 0 0 0 0 0 1.7e308 0
1.7e308 0 1.7e308 0 0 0 0 0 1.7e308 0
8.5e307 0 8.5e307 1.7e308 0 1.7e308 0 1.7e308 8.5e307 8.5e307\n' \
    >"$T/huge.patch"
fails 1 "huge.patch:1: result is not finite" "$B/patchsplit -v 0.3 $T/huge.patch"
fails 1 "huge.patch:1: result is not finite" \
    "$B/patchdrag -u 0.5 -v 0.5 -b 1e308,1e308 $T/huge.patch"
fails 1 "hull.patch:1: a patch cannot be joined to itself" \
    "$B/patchjoin -P 1 -S 1 $T/hull.patch"
# T-junctions (Fig. 5: 3's edge u0 holds 4 for v 0..0.5 and 5 for
# 0.5..1): the central rule, only (hh) of the dragged patch changes
# (row 5 of its record: line 6 of patch 4, line 20 of patch 3), and -V
# says which side of the junction stops the edge rule
$B/patchsplit -u 0.4 "$T/hull.patch" | $B/patchsplit -i 2 -v 0.5 >"$T/fig5.patch"
run "$B/patchdrag -V -i 3 -u 0.1 -v 0.25 -b 0,0,0.1 $T/fig5.patch"
status 0
says "fig5.patch:15: patch 3: central rule (a T-junction on u0: neighbour 4 lies along v=0 to 0.5 of it, and the edge rule needs one along all of it)"
diff "$T/fig5.patch" "$T/out" | grep -c '^[<>]' | grep -q '^2$' &&
    [ "$(diff "$T/fig5.patch" "$T/out" | head -1)" = 20c20 ] && ok ||
    no "T-junction drag of 3 changed more than (hh): $(diff "$T/fig5.patch" "$T/out")"
run "$B/patchdrag -V -i 4 -u 0.9 -v 0.5 -b 0,0,0.1 $T/fig5.patch"
status 0
says "patch 4: central rule (a T-junction on u0 of neighbour 3: this patch lies along v=0 to 0.5 of it, and the edge rule would move 3's other neighbours there)"
[ "$(diff "$T/fig5.patch" "$T/out" | head -1)" = 6c6 ] && ok ||
    no "T-junction drag of 4 changed more than (hh): $(diff "$T/fig5.patch" "$T/out")"
# across 4's whole edge v1 lies 5 and nothing else: the edge rule
run "$B/patchdrag -V -i 4 -u 0.5 -v 0.9 -b 0,0,0.1 $T/fig5.patch"
says "patch 4: edge rule across v1: patches 4 and 5 moved"
# near an edge with a neighbour: both patches change, -V says so
run "$B/patchdrag -V -i 2 -u 0.9 -v 0.5 -b 0,0,0.1 $T/two.patch"
status 0
says "patch 2: edge rule across u1: patches 2 and 3 moved"
[ "$(grep -c '^patch' "$T/out")" = 2 ] && ok || no "edge drag writes the design"
cmp -s "$T/out" "$T/two.patch" && no "edge drag changed nothing" || ok
run "$B/patchdrag -V -u 0.1 -v 0.5 -b 0,0,0.1 $T/hull.patch"
says "patch 1: central rule (no neighbour across u0): (hh) moved by"
# a fitted straight curve: the middle of its first segment (h) = (0.5, 0)
# moves by (0, 1) / H5(1/2) = (0, 1): sampled at u = 1/2, (0.5, 1)
printf '0 0\n1 0\n2 0\n' >"$T/line.knots"
run "$B/splinefit -o -S 1,0 -E 1,0 $T/line.knots | $B/patchdrag -u 0.5 -b 0,1 | $B/sample -n 2"
status 0
out_is "0 0
0.5 1
1 0
1.5 0
2 0

"
run "$B/splinefit -o -S 1,0 -E 1,0 $T/line.knots | $B/patchdrag -u 0.5 -b 0,1 | head -1"
out_is "quartic closed=0"
run "$B/splinefit -o -S 1,0 -E 1,0 $T/line.knots | $B/patchdrag -V -u 0.9 -b 0,1"
says "edge rule: segments 1 and 2 moved"
fails 1 "the point at u = 0 is an end of the curve" \
    "$B/splinefit -o -S 1,0 -E 1,0 $T/line.knots | $B/patchdrag -u 0 -b 0,1"
fails 1 "-u 3 is outside the curve's parameter range 0 to 2" \
    "$B/splinefit -o -S 1,0 -E 1,0 $T/line.knots | $B/patchdrag -u 3 -b 0,1"

# ---- patchjoin ------------------------------------------------------
# Patch 2 nearly against patch 1's u = 1 edge: after the join its u = 0
# edge is 1's u = 1 edge, row 0 of 2 = row 1 of 1, and its slope row
# across (row 2) that of 1 (row 3), both scale factors being 1.
$B/patchnew -i 2 -c 4.05,0,0.1 -c 8,0,0 -c 4,3.1,1 -c 8,3,2 >"$T/sub.patch"
run "$B/patchjoin -v -P 1 -S 2 $T/hull.patch $T/sub.patch"
status 0
says "sub.patch:1: edge u0 of 2 joined to edge u1 of 1"
says "now 0 apart, largest slope mismatch 0"
[ "$(grep '^patch' "$T/out" | tr '\n' ' ')" = "patch id=1 u1=2 patch id=2 u0=1 " ] &&
    ok || no "join links: $(grep '^patch' "$T/out")"
[ "$(sed -n 9p "$T/out")" = "$(sed -n 3p "$T/hull.patch")" ] && ok ||
    no "joined edge: $(sed -n 9p "$T/out")"
[ "$(sed -n 11p "$T/out")" = "$(sed -n 5p "$T/hull.patch")" ] && ok ||
    no "joined slopes: $(sed -n 11p "$T/out")"
sed -n 2,7p "$T/out" | cmp -s - "$T/hull.patch.rows" && ok || no "principal changed"
sed 's/^patch id=2/patch id=2 su=2/' "$T/sub.patch" >"$T/sub2.patch"
run "$B/patchjoin -P 1 -S 2 $T/hull.patch $T/sub2.patch | sed -n 11p"
# scale factor 2 against 1: slopes doubled: (8 0 0 8 0 2 0 0 2 0 0 2 8 0 1)
out_is "8 0 0 8 0 2 0 0 2 0 0 2 8 0 1"
$B/patchnew -i 2 -c 5,0,0 -c 8,0,0 -c 5,3,1 -c 8,3,2 >"$T/far.patch"
fails 1 "patches 1 and 2 share no edge" "$B/patchjoin -P 1 -S 2 $T/hull.patch $T/far.patch"
fails 1 "no patch with id 3 in the input" "$B/patchjoin -P 1 -S 3 $T/hull.patch $T/sub.patch"
# a subsidiary with a neighbour beside the edge to join is refused
{ sed 's/^patch id=2/patch id=2 v1=5/' "$T/sub.patch"
  $B/patchnew -i 5 -c 4,3.1,1 -c 8,3,2 -c 4,6,1 -c 8,6,2 |
  sed 's/^patch id=5/patch id=5 v0=2/'; } >"$T/subpair.patch"
fails 1 "the subsidiary 2 has a neighbour across v1, which meets the edge to join" \
    "$B/patchjoin -P 1 -S 2 $T/hull.patch $T/subpair.patch"

# ---- sample: wireframes and OBJ --------------------------------------
# -n 4: lines u = 0, 1/4, ..., 1 and v = 0, ..., 1: 10 records of 5 points,
# a blank line after each and one more after the last (gnuplot's grid)
run "$B/sample -n 4 $T/hull.patch"
status 0
[ "$(grep -c . "$T/out")" = 50 ] && [ "$(grep -c '^$' "$T/out")" = 11 ] &&
    [ "$(tail -2 "$T/out" | tr -d '\n')" = "" ] && ok ||
    no "wireframe: $(grep -c . "$T/out") points"
# the corner (11) is the last point of the line u = 1, exactly
[ "$(awk -v RS= 'NR == 5' "$T/out" | tail -1)" = "4 3 1" ] && ok ||
    no "wireframe corner"
run "$B/sample -n 4 -u $T/hull.patch | awk -v RS= 'NR == 7' | head -2"
# the line v = 1/4: u = 0 then 1/4; f(1/4, 1/4) of the bilinear patch
# = (1, 0.75, 1/16)
out_is "0 0.75 0 0 0.25
1 0.75 0.0625 0.25 0.25"
run "$B/sample -n 4 -f obj $T/two.patch"
status 0
[ "$(grep -c '^v ' "$T/out")" = 50 ] && [ "$(grep -c '^f ' "$T/out")" = 64 ] &&
    [ "$(grep -c '^o patch-' "$T/out")" = 2 ] && ok ||
    no "obj: $(grep -c '^v ' "$T/out") vertices, $(grep -c '^f ' "$T/out") faces"
# faces name vertices 1 to 50, the second patch's from 26
awk '$1 == "f" { for (i = 2; i <= 4; i++) { if ($i < 1 || $i > 50) bad = 1
	if (NR > 60 && $i <= 25) bad = 1 } } END { exit bad }' "$T/out" && ok ||
    no "obj face numbers"
grep -q '^f 1 6 7$' "$T/out" && ok || no "obj: first face 1 6 7"
fails 1 "-d and -k need a curve" "$B/sample -k $T/hull.patch"
fails 1 "patch record has 4 rows" "$B/sample $T/hull4.patch"
run "$B/splinefit -o $T/line.knots | $B/sample -n 2 -f obj"
out_is "o cubic
v 0 0 0
v 0.5 0 0
v 1 0 0
v 1.5 0 0
v 2 0 0
l 1 2 3 4 5"

# ---- write errors ---------------------------------------------------
run "$B/patchsplit -u 0.5 $T/hull.patch > /dev/full"
status 1
says "patchsplit: write error"
run "$B/patchnew -c 0,0 -c 1,0 -c 0,1 -c 1,1 > /dev/full"
status 1
says "patchnew: write error"

echo "patchcmd: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
