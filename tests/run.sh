#!/bin/sh
# run.sh: run every test suite, show its failures, and add up the suites'
# closing "N passed, M failed" lines into one.  A suite that dies before
# its closing line counts as one failure.
#
# QUICK=1 (make check-quick) runs the quick tier only: the suites run by
# "suite" (about 10 s), not those run by "slow".

passed=0
failed=0

suite() {
	out=$("$@" 2>&1)
	last=$(printf '%s\n' "$out" |
	    grep -E '^[a-z]+: [0-9]+ passed, [0-9]+ failed$' | tail -n 1)
	printf '%s\n' "$out" | grep -v -E '^[a-z]+: [0-9]+ passed, [0-9]+ failed$'
	if [ -z "$last" ]; then
		echo "$*: died before its summary"
		failed=$((failed + 1))
		return
	fi
	echo "$last"
	set -- $last
	passed=$((passed + $2))
	failed=$((failed + $4))
}
slow() {
	[ -n "$QUICK" ] || suite "$@"
}

suite bin/test/unit
suite bin/test/paper man/figures/insole.knots
suite sh tests/cmd.sh
suite sh tests/fit.sh
slow bin/test/patch
suite sh tests/patch.sh
suite sh tests/linetype.sh
suite sh tests/registry.sh
suite bin/test/bezier
suite sh tests/bezapprox.sh
slow bin/test/numtest
suite bin/test/pow10gen -c lib/pow10.h
slow sh tests/loftplot.sh
slow sh tests/browser/run.sh
suite sh tests/grade.sh
slow sh tests/offset.sh
suite bin/test/cad
slow sh tests/tocad.sh
suite sh tests/loftcut.sh
slow sh tests/fromcad.sh
slow sh tests/stepiges.sh
slow sh tests/realcad.sh
slow sh tests/roundtrip.sh
slow sh tests/bad.sh
suite bin/test/hostile
slow sh tests/oom.sh
suite bin/test/arclen
suite bin/test/grid
suite bin/test/bspline
suite bin/test/straight
slow sh tests/measure.sh
slow sh tests/install.sh
slow sh tests/examples.sh
slow sh tests/approx.sh
suite sh tests/hydro.sh
suite sh tests/offsets.sh
suite sh tests/synopsis.sh
slow sh tests/units.sh
suite bin/test/sparse
suite sh tests/unroll.sh
slow sh tests/fuzzbuild.sh
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
