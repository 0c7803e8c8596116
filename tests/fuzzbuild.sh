#!/bin/sh
# fuzzbuild.sh: every libFuzzer harness of tests/fuzz compiles, without
# a warning, with the compiler make check builds with (${CC:-cc})
# (tests/registry.sh checks that FUZZERS names each).  make fuzz needs
# clang's -fsanitize=fuzzer, so make check never built the harnesses,
# and two fell behind the programs they include: the harnesses of
# measure and hydro still called parse_fields after -f's list moved
# into lib/run.c (loft_opt_fields), and make fuzz stopped at the first.
# Compiled only (-c): the fuzzer's own main is clang's.  The last line
# is "fuzzbuild: N passed, M failed".

T=bin/test/fuzzbuild
. tests/lib.sh

CFLAGS_FUZZ="-std=c99 -D_POSIX_C_SOURCE=200809L -Ilib -DLOFT_FUZZ -Wall
    -Wextra -Wno-unused-function -Werror"
n=0
for f in tests/fuzz/*.c; do
	h=${f##*/}
	h=${h%.c}
	n=$((n + 1))
	# shellcheck disable=SC2086
	if ${CC:-cc} $CFLAGS_FUZZ -c -o "$T/$h.o" "$f" 2>"$T/err"; then
		ok
	else
		no "tests/fuzz/$h.c does not compile: $(head -3 "$T/err")"
	fi
done
[ "$n" -ge 18 ] && ok || no "only $n harnesses in tests/fuzz"
echo "fuzzbuild: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
