#!/bin/sh
# compare.sh: `make compare`, run from the top of the tree: the bending
# energy of splinefit's curves beside Manning's, the chord spline's,
# Hobby's and Spiro's on a corpus of uneven closed knot sets (issue 13).
# Spiro needs libspiro (Debian: libspiro-dev); without it its row is
# skipped with one line.  N sets (default 200).
W=bin/bench
N=${N:-300}
CC=${CC:-cc}
mkdir -p $W || exit 1
if [ -f /usr/include/spiroentrypoints.h ] &&
    $CC -std=c99 -O2 -Wall -Wextra -DHAVE_SPIRO -o $W/compare tests/bench/compare.c \
    bin/libloft.a -lspiro -lm 2>/dev/null; then
	:
else
	echo "compare: libspiro not found: Spiro's row skipped"
	$CC -std=c99 -O2 -o $W/compare tests/bench/compare.c bin/libloft.a -lm ||
	    exit 1
fi
$W/compare corpus "$N" man/figures/insole.knots >$W/uneven.knots || exit 1
$W/compare run $W/uneven.knots
