#!/bin/sh
# oom.sh: every program on a typical input with its k-th allocation made
# to fail, for k = 1, 2, ... until a run makes fewer than k (issue 12,
# after SQLite's out-of-memory loops).  Each run that met its failure
# must end in exit 1 with a message "PROG: ..." naming memory on standard
# error and standard output holding only whole records of the run
# without the failure (a filter: any of them; a design: all or none; loftplot: a whole
# SVG document, of the records it could read),
# or, where the program or the C library could do without that memory
# (a stdio buffer, say), exactly the output of that run and exit 0.
# Never a crash, a hang or another status.
#
# The failures come from tests/oom.c, preloaded (LD_PRELOAD) into the
# program alone.  The suite skips itself, with one line, where that
# cannot work: a sanitized build (make check-san: AddressSanitizer must
# own malloc), the memcheck wrappers of make check-valgrind, or a C
# library the shim does not know (it needs glibc).

T=bin/test/oom
. tests/lib.sh
SHIM=$(pwd)/bin/test/oom.so
MAXK=${LOFT_OOM_MAX:-20000}     # a bound on k, far above any run here
TIMEOUT=20                      # seconds one run may take
F=man/figures

skip() {
	echo "oom: skipped: $1"
	finish oom
	exit 0
}
[ -n "$LOFT_BIN" ] && skip "the programs are wrappers (LOFT_BIN)"
grep -q __asan_init "$B/loftplot" 2>/dev/null && skip "a sanitized build"
LD_PRELOAD=$SHIM "$B/loftplot" -h >/dev/null 2>&1 ||
    skip "the shim does not load here (it needs glibc)"
command -v timeout >/dev/null 2>&1 && TO="timeout $TIMEOUT" || TO=

# whole FILE GOOD KIND: FILE's records (blank-line separated) are each a
# record of GOOD (KIND records), or FILE is empty or GOOD (else)
whole() {
	[ ! -s "$1" ] && return 0
	cmp -s "$1" "$2" && return 0
	if [ "$3" = document ]; then    # the picture of what could be read
		head -n 1 "$1" | grep -q '^<?xml ' && [ "$(tail -n 1 "$1")" = \
		    "</svg>" ] && return 0
		echo "not a whole SVG document"
		return 1
	fi
	if [ "$3" = stl ]; then          # an STL of what could be read
		[ "$(head -n 1 "$1")" = "solid loft" ] &&
		    [ "$(tail -n 1 "$1")" = "endsolid loft" ] && return 0
		echo "not a whole STL document"
		return 1
	fi
	[ "$3" = records ] || { echo "part of the output"; return 1; }
	[ -z "$(tail -c 1 "$1")" ] || { echo "no final newline"; return 1; }
	awk 'BEGIN { RS = "" } NR == FNR { good[$0] = 1; next }
	    !($0 in good) { print "a record not in the good output: " \
	    substr($0, 1, 60); exit 1 }' "$2" "$1"
}

# oom KIND PROG ARGS...: the loop for one command
oom() {
	kind=$1
	shift
	prog=$1
	shift
	what="oom: $prog $*"
	"$B/$prog" "$@" >"$T/good" 2>"$T/gerr"
	[ $? -eq 0 ] && [ -s "$T/good" ] && [ ! -s "$T/gerr" ] ||
	    { no "$what: the run without failures fails"; return; }
	k=1
	bad=0
	while [ "$k" -le "$MAXK" ]; do
		rm -f "$T/mark"
		LD_PRELOAD=$SHIM LOFT_OOM_FAIL=$k LOFT_OOM_MARK=$T/mark \
		    LOFT_OOM_PROG=$prog $TO "$B/$prog" "$@" >"$T/out" 2>"$T/err"
		rc=$?
		if [ ! -f "$T/mark" ]; then
			[ $rc -eq 0 ] && cmp -s "$T/out" "$T/good" ||
			    { no "$what: a run of fewer than $k allocations" \
			    "fails"; bad=1; }
			break
		fi
		why=
		if [ $rc -eq 0 ]; then
			cmp -s "$T/out" "$T/good" || why="exit 0, other output"
			[ -s "$T/err" ] && why="exit 0 with a message"
		elif [ $rc -ne 1 ]; then
			why="exit $rc"
		elif ! grep -q "^$prog: ." "$T/err"; then
			why="exit 1 without a message"
		elif ! grep -q -i "memory" "$T/err"; then
			why="a message that does not name memory"
		elif v=$(whole "$T/out" "$T/good" "$kind"); then
			:
		else
			why="stdout: $v"
		fi
		grep -q -E 'AddressSanitizer|runtime error|double free|corrupt' \
		    "$T/err" && why="$why; stderr: $(head -1 "$T/err")"
		if [ -n "$why" ]; then
			no "$what: allocation $k failing: $why ($(head -1 "$T/err" |
			    cut -c1-120))"
			bad=$((bad + 1))
			[ $bad -ge 5 ] && { no "$what: more failures not shown"; break; }
		fi
		k=$((k + 1))
	done
	[ "$k" -gt "$MAXK" ] && no "$what: more than $MAXK allocations"
	[ $bad -eq 0 ] && ok
	echo "oom: $prog $*: $((k - 1)) allocations failed in turn" >"$T/note"
}

# the inputs, made without failures
"$B/splinefit" $F/insole.knots >"$T/insole.cubic" || exit 2
"$B/patchnew" -i 1 -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 >"$T/p1" || exit 2
"$B/patchnew" -i 2 -c 4,0,0 -c 8,0,0 -c 4,3,1 -c 8,3,2 >"$T/p2" || exit 2
sed -e '1s/$/ u1=2/' -e '$d' "$T/p1" >"$T/design"
{ echo; sed -e '1s/$/ u0=1/' "$T/p2"; } >>"$T/design"
"$B/patchnew" -i 2 -c 4.05,0,0.1 -c 8,0,0 -c 4,3.1,1 -c 8,3,2 >"$T/p3" || exit 2
cat "$T/p1" "$T/p3" >"$T/pieces"
printf 'cubic\n0 0 1 0 1 0 1 0\n\ncubic\n0 1 1 1 1 0 1 0\n\n' >"$T/bounds"
printf 'cubic\n0 0 0 1 0 1 0 1\n\nquartic\n1 0 1 1 0 1 0 1 1 0.5\n' >>"$T/bounds"

oom records splinefit $F/insole.knots
# -e on 17 clean points round an ellipse: the corners found are not met
# within 0.0434, the fit without them is (memory running out there was
# "tolerance not met")
cat >"$T/ellipse" <<'EOF'
86.716794 0.000000
80.861003 19.646099
64.084484 36.638883
38.653001 48.683383
8.001216 54.152922
-23.731177 52.308810
-52.258544 43.400102
-73.728105 28.629970
-85.240276 9.993203
-85.240276 -9.993203
-73.728105 -28.629970
-52.258544 -43.400102
-23.731177 -52.308810
8.001216 -54.152922
38.653001 -48.683383
64.084484 -36.638883
80.861003 -19.646099
EOF
oom records splinefit -o -e 0.0434 "$T/ellipse"
oom records sample -n 4 "$T/insole.cubic"
oom records bezapprox -n 5 "$T/insole.cubic"
oom records bezapprox -n 3,3 -x u -y v -z 'u*v'
oom records grade -r -1:1 $F/insole.knots
oom design patchnew -i 1 -c 0,0 -c 1,0 -c 0,1 -c 1,1
oom design patchnew -b "$T/bounds"
oom design patchsplit -u 0.4 "$T/design"
oom design patchdrag -i 1 -u 0.9 -v 0.5 -b 0,0,1 "$T/design"
oom design patchjoin -P 1 -S 2 "$T/pieces"
oom document loftplot -l id "$T/insole.cubic" "$T/design"
# the other paths: surfaces, OBJ, every layer of a picture
"$B/bezapprox" -n 3,3 -x u -y v -z 'u*v' >"$T/net" || exit 2
oom records sample -f obj "$T/net"
oom records sample -d -k -u "$T/insole.cubic"
oom records bezapprox -n 3,3 "$T/p1"
oom document loftplot -c -b -m -t -K $F/insole.knots "$T/insole.cubic" "$T/net" \
    "$T/p1"
# issue 28: the programs and readers that round touched
oom records measure "$T/insole.cubic"
printf 'sep=;\nname;X (mm);y\n"a;\nb";1,5;2\n;3;4\n' >"$T/pts.csv"
oom records fromcad "$T/pts.csv"
oom design patchcut -x 2 -z 0.5 "$T/design"
oom stl tocad -f stl "$T/design"
"$B/splinefit" -o $F/hull.knots >"$T/hull.cubic" || exit 2
oom design patchloft "$T/hull.cubic"

# issue 25: the Wigley hull (tests/hydro.sh) floated at three
# waterlines and its curve of sectional areas; a table of offsets
awk 'BEGIN { split("0 2 0", a); split("0 1 1", b); print "bezier-surface m=2 n=2"
	for (i = 0; i < 3; i++) for (j = 0; j < 3; j++)
		printf "%.17g %.17g %.17g\n", -2 + 2 * i, 0.25 * a[i + 1] * b[j + 1],
		    -0.25 + 0.125 * j }' >"$T/wigley"
oom design hydro -z -0.2:0:0.1 "$T/wigley"
oom design hydro -s 5 "$T/wigley"
oom records offsets -k man/examples/hull.offsets
oom design offsets -x -2:2:1 -z -0.2:0:0.1 "$T/wigley"

# issue 12: a record too large for memory (made so by failing every
# allocation above 1 MB) is one bad record, reported at a line of it
# (where memory ran out) and skipped to its end; it ended the whole file,
# losing the good record after it.  big NAME: $T/big between two good
# records; its lines are 7 to 6 + its length.
big() {
	what="oom: $1"
	g1='points id=1\n0 0\n1 0\n1 1\n0 1\n'
	g3='points id=3\n2 0 1\n0 1 0\n-2 0 1\n0 -1 0\n'
	{ printf "$g1\n"; cat "$T/big"; printf "\n$g3"; } >"$T/in"
	{ printf "$g1\n$g3"; } >"$T/ref"
	"$B/splinefit" "$T/ref" >"$T/good"
	LD_PRELOAD=$SHIM LOFT_OOM_ABOVE=1000000 LOFT_OOM_PROG=splinefit \
	    $TO "$B/splinefit" "$T/in" >"$T/out" 2>"$T/err"
	rc=$?
	[ $rc -eq 1 ] && ok || no "$what: exit $rc, want 1"
	m="record too large for memory (out of memory at this line): skipped to its end"
	awk -v p="splinefit: $T/in:" -v m=" $m" -v hi="$((6 + $(wc -l <"$T/big")))" '
	    NR == 1 && index($0, p) == 1 { rest = substr($0, length(p) + 1)
		l = rest + 0; good = l >= 7 && l <= hi && rest == l ":" m }
	    END { exit !(good && NR == 1) }' "$T/err" && ok ||
	    no "$what: want one message at a line of it: $(head -2 "$T/err")"
	cmp -s "$T/out" "$T/good" && ok ||
	    no "$what: stdout is not the good records' curves"
}
awk 'BEGIN { print "points id=2"; for (i = 0; i < 200000; i++) print i, i % 7 }' \
    >"$T/big"
big "a record of 200,000 rows"
awk 'BEGIN { print "points id=2"; print "0 0"; for (i = 0; i < 600000; i++)
    printf "0 "; print ""; print "1 1" }' >"$T/big"
big "a row of 1.2 MB"
finish oom
