#!/bin/sh
# run.sh: run every test suite, show its failures, and add up the suites'
# closing "N passed, M failed" lines into one.  A suite that dies before
# its closing line counts as one failure.

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

suite bin/test/unit
suite bin/test/paper man/figures/insole.knots
suite sh tests/cmd.sh
suite sh tests/fit.sh
suite bin/test/patch
suite sh tests/patch.sh
suite bin/test/bezier
suite sh tests/bezapprox.sh
suite bin/test/numtest
suite bin/test/pow10gen -c lib/pow10.h
suite sh tests/loftplot.sh
suite sh tests/grade.sh
suite sh tests/offset.sh
suite bin/test/cad
suite sh tests/tocad.sh
suite sh tests/loftcut.sh
suite sh tests/fromcad.sh
suite sh tests/roundtrip.sh
suite sh tests/bad.sh
suite bin/test/hostile
suite sh tests/oom.sh
suite bin/test/arclen
suite sh tests/measure.sh
suite sh tests/approx.sh
suite sh tests/install.sh
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
