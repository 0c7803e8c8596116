#!/bin/sh
# linetype.sh: every program meets a record type it was not written
# for: tests/linetype.c's `line`, straight segments of degree 1, added
# as one row of the type table in the copies of the programs in
# bin/test/line (make check builds them).  Each program must either take
# it, its output then the same numbers as the program's for the same
# straight curve written as a cubic (P' = P_B - P_A at both ends: the
# reference is that identity, not a program's output of the line), or
# refuse it: exit 1, a message "PROG: FILE:LINE: ..." for each refusal
# and nothing else on standard error.  Never exit 0 with other numbers,
# and never read past a row (patchnew -b and patchdrag once did).
# The last line is "linetype: N passed, M failed".

T=bin/test/linetype
. tests/lib.sh
L=bin/test/line
PROGS=${LINE_PROGS:-$(awk '/^PROGS[ \t]*=/ { f = 1; sub(/^PROGS[ \t]*=/, "") }
    f { c = sub(/\\$/, ""); print; if (!c) f = 0 }' Makefile)}

# the curves, as lines and as the same lines written as cubics
printf 'line\n0 0 3 4\n3 4 6 0\n' >"$T/l2"
printf 'cubic\n0 0 3 4 3 4 3 4\n3 4 6 0 3 -4 3 -4\n' >"$T/c2"
printf 'line id=1\n0 0 0 3 0 0.5\n\nline id=2\n0 2 1 3 2 1.5\n' >"$T/l3"
printf 'cubic id=1\n0 0 0 3 0 0.5 3 0 0.5 3 0 0.5\n\n' >"$T/c3"
printf 'cubic id=2\n0 2 1 3 2 1.5 3 0 0.5 3 0 0.5\n' >>"$T/c3"
# the four sides of a square, for patchnew -b
for s in '0 0 0 1 0 0' '0 1 0 1 1 0' '0 0 0 0 1 0' '1 0 0 1 1 0'; do
	printf 'line\n%s\n\n' "$s"
done >"$T/l4"
awk '/^line/ { print "cubic"; next } NF == 0 { print; next }
{ print $1, $2, $3, $4, $5, $6, $4 - $1, $5 - $2, $6 - $3, $4 - $1, $5 - $2, $6 - $3 }' \
    "$T/l4" >"$T/c4"

# numbers FILE: the numbers of FILE, one a line, in order
numbers() {
	tr -s ' \t,;"=<>/()' '\n\n\n\n\n\n\n\n\n\n' <"$1" |
	    grep -E '^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$'
}

# check PROG INPUT OPTIONS...: PROG of bin/test/line on INPUT's line
# records takes them as the cubics of INPUT's c file, or refuses them
check() {
	p=$1 in=$2
	shift 2
	what="$p $* on lines"
	"$L/$p" "$@" "$T/l$in" >"$T/out" 2>"$T/err"
	rc=$?
	if [ $rc -eq 0 ]; then
		[ ! -s "$T/err" ] && ok || no "$what: exit 0 but said $(head -2 "$T/err")"
		[ -n "$ANY" ] && return
		"$B/$p" "$@" "$T/c$in" >"$T/ref" 2>/dev/null
		numbers "$T/out" >"$T/n1"
		numbers "$T/ref" >"$T/n2"
		paste "$T/n1" "$T/n2" | awk -v a="$(wc -l <"$T/n1")" \
		    -v b="$(wc -l <"$T/n2")" '
		    { d = $1 - $2; d = d < 0 ? -d : d
		      s = ($1 < 0 ? -$1 : $1) + ($2 < 0 ? -$2 : $2)
		      if (d > 1e-9 * (1 + s)) bad++ }
		    END { exit !(a == b && a > 0 && bad == 0) }' && ok ||
		    no "$what: taken, but not as the same cubic"
	elif [ $rc -eq 1 ]; then
		grep -q "^$p: $T/l$in:[0-9][0-9]*: " "$T/err" &&
		    ! grep -v -q "^$p: " "$T/err" && ok || no "$what: refused without a message: $(head -2 "$T/err")"
	else
		no "$what: exit $rc: $(head -2 "$T/err")"
	fi
}

[ -x "$L/sample" ] || { echo "linetype: $L has no programs (make check builds them)"; exit 1; }

# every program of PROGS once, those that read curves in each way
check sample 2 -n 4
check sample 2 -t 0.01
check sample 2 -s 0.5 -u
check sample 2 -n 3 -d -k
check measure 2
check offset 2 -d 0.5
check tocad 2 -f dxf
# drawn exactly: the line's own segments, not the cubic's curves
ANY=1; check tocad 2 -f svg; ANY=
sed -n 's/.*<path d="\([^"]*\)".*/\1/p' "$T/out" >"$T/path"
[ "$(numbers "$T/path" | tr '\n' ' ')" = "0 0 3 4 6 0 " ] && ok ||
    no "tocad -f svg: the line drawn as $(cat "$T/path")"
check tocad 3 -f obj
check tocad 3 -f stl
ANY=1; check loftplot 2; ANY=
check bezapprox 2
check grade 2 -s 7
check splinefit 2
check patchnew 4 -b
check patchdrag 2 -u 0.5 -b 0,1
check patchdrag 3 -i 1 -u 0.5 -b 0,1,0
check patchloft 3
check patchsplit 3 -u 0.5
check patchjoin 3 -P 1 -S 2
check patchcut 3 -x 1
check unroll 3
check hydro 3
check offsets 3 -x 0.5 -z 0.5
# every program of PROGS is tried here, but fromcad, which reads CAD
# files, not records
for p in $PROGS; do
	[ "$p" = fromcad ] || grep -E -q "^(ANY=1; )?check $p " tests/linetype.sh && ok ||
	    no "$p: not tried on a line record"
done
finish linetype
