# lib.sh: the helpers of the command suites, sourced by them after they
# set T (their scratch directory).  Each assertion counts a pass or a
# failure; finish prints the suite's "NAME: N passed, M failed" line.

B=${LOFT_BIN:-bin}      # check-valgrind runs the programs through wrappers
rm -rf "$T" && mkdir -p "$T" || exit 2
pass=0
fail=0

ok() { pass=$((pass + 1)); }
no() { fail=$((fail + 1)); printf 'FAIL %s\n' "$*" >&2; }

# run CMD: run it in sh, keeping its stdout, stderr and exit status
run() {
	sh -c "$1" >"$T/out" 2>"$T/err"
	echo $? >"$T/rc"
	what=$1
}
status() {
	[ "$(cat "$T/rc")" = "$1" ] && ok ||
	    no "$what: exit $(cat "$T/rc"), want $1; stderr: $(head -3 "$T/err")"
}
says() {
	grep -F -q -- "$1" "$T/err" && ok ||
	    no "$what: stderr lacks '$1': $(head -3 "$T/err")"
}
out_is() {
	printf '%s\n' "$1" | cmp -s - "$T/out" && ok ||
	    no "$what: stdout is '$(head -8 "$T/out")', want '$1'"
}
out_empty() {
	[ ! -s "$T/out" ] && ok || no "$what: stdout not empty: $(head -3 "$T/out")"
}
# fails STATUS MESSAGE CMD: exits STATUS, says MESSAGE, writes nothing
fails() {
	run "$3"
	status "$1"
	says "$2"
	out_empty
}
# usage_ok PROG: -h prints the usage and exits 0; a bad option exits 2
# with the same usage on standard error
usage_ok() {
	run "$B/$1 -h"
	status 0
	grep -q "^usage: $1 " "$T/out" && ok || no "$1 -h prints no usage"
	cp "$T/out" "$T/usage"
	run "$B/$1 -Z"
	status 2
	tail -n "$(wc -l <"$T/usage")" "$T/err" | cmp -s - "$T/usage" && ok ||
	    no "$1 -Z: stderr does not end with the usage of -h"
}
# finish NAME: the closing line that tests/run.sh adds up
finish() {
	echo "$1: $pass passed, $fail failed"
	[ "$fail" -eq 0 ]
}
