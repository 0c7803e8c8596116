#!/bin/sh
# bad.sh: every program against hostile input, failing output and changes
# of units (issue 6).  Run from the top of the tree; the last line is
# "bad: N passed, M failed".
#
# The suite is a table.  For each program P in PROGS it needs
#   P_run [options] FILE...  run P as a user would
#   P_good 1|2               print a good record of P's input, with a
#                            header and at least two rows; the last row of
#                            record 1 must still be good with its first
#                            number set to 0
#   P_cases                  P's own cases: what its records mean
# The stream cases (numbers, headers, lines, bytes, files, output
# failures) are made from P's good records, so covering a new program is
# writing those three functions and adding its name to PROGS.
#
# Each case is put between P's good records 1 and 2 (the "sandwich") and
# the whole checked: the exit status, one message "P: FILE:LINE: ..."
# naming the case's line, and standard output exactly the output of the
# good records alone (plus the case's own output where the case is good),
# in whole records of finite numbers.

B=${LOFT_BIN:-bin}              # check-valgrind runs the programs through wrappers
BIG=${LOFT_BIG_KNOTS:-1000000}  # the big record's rows (check-valgrind: fewer)
PROMPT=5                        # seconds a program may take to notice a closed pipe
T=bin/test/bad
PROGS="splinefit sample"

rm -rf "$T" && mkdir -p "$T" || exit 2
pass=0
fail=0
ok() { pass=$((pass + 1)); }
no() { fail=$((fail + 1)); printf 'FAIL %s: %s\n' "$P" "$*" >&2; }

# ---- checks ------------------------------------------------------------

# valid FILE: whole records only: each a header or none, then rows of
# strict finite decimals with one count per record, then one blank line.
valid() {
	[ ! -s "$1" ] && return 0
	[ -z "$(tail -c 1 "$1")" ] || { echo "no final newline"; return 1; }
	awk '
	function bad(what) { print "line " NR ": " what; failed = 1; exit 1 }
	/^$/ { if (!inrec || !rows) bad("blank line where no record"); inrec = 0; next }
	{
		if (!inrec) { inrec = 1; rows = 0; cols = -1; if ($1 ~ /^[A-Za-z]/) next }
		else if ($1 ~ /^[A-Za-z]/) bad("header inside a record")
		for (i = 1; i <= NF; i++) {
			if ($i !~ /^-?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/)
				bad("not a finite number: " substr($i, 1, 30))
			x = $i + 0
			if (x != 0 && x == 2 * x)
				bad("not finite: " $i)
		}
		if (cols < 0) cols = NF
		else if (NF != cols) bad(NF " numbers in a row after rows of " cols)
		rows++
	}
	END { if (!failed && inrec) bad("record not ended by a blank line") }' "$1"
}

# run ARGS...: P_run with $OPTS on ARGS, keeping stdout, stderr, status
run() {
	what="$tc"
	"${P}_run" $OPTS "$@" >"$T/out" 2>"$T/err"
	echo $? >"$T/rc"
}
status() {
	[ "$(cat "$T/rc")" = "$1" ] && ok ||
	    no "$what: exit $(cat "$T/rc"), want $1; stderr: $(head -3 "$T/err")"
}
says() {
	grep -F -q -- "$1" "$T/err" && ok ||
	    no "$what: stderr lacks '$1': $(head -3 "$T/err" | cut -c1-200)"
}
quiet() {
	[ ! -s "$T/err" ] && ok || no "$what: stderr: $(head -3 "$T/err" | cut -c1-200)"
}
# one message, in the form "P: FILE:LINE: ..."
message_at() {
	[ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "^$P: $1:$2: ." "$T/err" &&
	    ok || no "$what: want one message at $1:$2, got: $(head -3 "$T/err" |
	    cut -c1-200)"
}
out_is() {
	cmp -s "$1" "$T/out" && ok ||
	    no "$what: stdout differs from $1: $(head -3 "$T/out" | cut -c1-200)"
}
out_valid() {
	v=$(valid "$T/out") && ok || no "$what: stdout not whole records: $v"
}

# ---- the sandwich --------------------------------------------------------

# opts [OPTIONS]: the options of the cases that follow; makes the good
# records' expected outputs under them.
opts() {
	OPTS=$*
	for k in 1 2; do
		tc="good record $k (options '$OPTS')"
		"${P}_good" $k >"$T/g$k"
		run "$T/g$k"
		status 0
		quiet
		out_valid
		[ -s "$T/out" ] && ok || no "$what: no output"
		cp "$T/out" "$T/o$k"
	done
	n1=$(wc -l <"$T/g1")
}

# sandwich CASEFILE: good record 1, the case, good record 2, into $T/in.
# The case's line L is line n1 + 1 + L of $T/in.
sandwich() {
	{ cat "$T/g1"; echo; cat "$1"; echo; cat "$T/g2"; } >"$T/in"
}

# bad NAME LINE [MESSAGE]: the case in $T/case is a bad record with its
# error on its line LINE: exit 1, one message there, the good records'
# output unchanged around it.
bad() {
	tc=$1
	sandwich "$T/case"
	run "$T/in"
	status 1
	message_at "$T/in" $((n1 + 1 + $2))
	[ -n "$3" ] && says "$3"
	cat "$T/o1" "$T/o2" >"$T/want"
	out_is "$T/want"
}

# same NAME: the case in $T/case reads as the record in $T/ref does.
same() {
	tc=$1
	run "$T/ref"
	status 0
	cat "$T/o1" "$T/out" "$T/o2" >"$T/want"
	sandwich "$T/case"
	run "$T/in"
	status 0
	quiet
	out_is "$T/want"
}

# good NAME: the case in $T/case is good: exit 0, no message, its output
# whole between the good records' (records are independent).
good() {
	tc=$1
	run "$T/case"
	status 0
	quiet
	out_valid
	[ -s "$T/out" ] && ok || no "$what: no output"
	cp "$T/out" "$T/caseout"
	cat "$T/o1" "$T/out" "$T/o2" >"$T/want"
	sandwich "$T/case"
	run "$T/in"
	status 0
	out_is "$T/want"
}

# sane NAME: the case in $T/case either works (as in good) or fails with
# one message naming its file and line: never a crash, never a NaN.
sane() {
	tc=$1
	run "$T/case"
	if [ "$(cat "$T/rc")" = 0 ]; then
		good "$1"
	else
		status 1
		grep -q "^$P: $T/case:[0-9]*: [a-z0-9]" "$T/err" && ok ||
		    no "$what: fails without a message: $(head -2 "$T/err")"
		out_valid
	fi
}

# mutate TOKEN: good record 1 with the first number of its last row
# replaced by TOKEN, into $T/case.
mutate() {
	awk -v t="$1" -v n="$n1" 'NR == n { $1 = t } { print }' "$T/g1" \
	    >"$T/case"
}

# ---- the stream cases every program gets --------------------------------

stream_cases() {
	opts

	# empty input, only comments, only blank lines: nothing to say
	for c in '' '# a comment\n#\n' '\n\n\n' ' \t \n\f\n\v\r\n' '#' ; do
		tc="input '$c'"
		printf "$c" >"$T/case"
		run "$T/case"
		status 0
		quiet
		[ ! -s "$T/out" ] && ok || no "$what: output"
	done
	: >"$T/ref"
	printf '\n\n \n\t\r\n# comment\n\n' >"$T/case"
	same "blank and comment lines between records"

	# numbers
	for tok in nan NaN -nan inf -Inf infinity 0x10 1,5 1.5.2 --1 +-1 1e 1e+ \
	    . + - 1d0 '1 e5' 0b1 1_000 "$(printf '\302\275')"; do
		mutate "$tok"
		bad "number '$tok'" "$n1" "is not a number"
	done
	for tok in 1e400 -1e400 1e99999999999999999999 \
	    179769313486231580793728971405303415079934132710037826936173778980444968292764750946649017977587207096330286416692887910946555547851940402630657488671505820681908902000708383676273854845817711531764475730270069855571366959622842914819860834936475292719074168444365510704342711559699508093042880177904174497792; do
		mutate "$tok"
		bad "number '$(echo "$tok" | cut -c1-20)'" "$n1" "out of range"
	done
	mutate "1$(awk 'BEGIN { while (n++ < 400) printf "0" }')"
	bad "number of 401 digits" "$n1" "too long"
	mutate 0
	cp "$T/case" "$T/ref"
	for tok in -0 +0 0.0 -0.0 .0 0. 00 0e10 -0e-10 1e-99999 -1e-400; do
		mutate "$tok"
		same "number '$tok' (zero)"
	done
	for tok in 1e-320 -4.9e-324 2.2250738585072014e-308; do
		mutate "$tok"
		good "number '$tok' (subnormal)"
	done

	# rows: a number too many or too few; the mixed record
	awk -v n="$n1" 'NR == n { $0 = $0 " 5" } { print }' "$T/g1" >"$T/case"
	bad "a number too many" "$n1" "row has more than"
	awk -v n="$n1" 'NR == n { $NF = "" } { print }' "$T/g1" >"$T/case"
	bad "a number too few" "$n1" "row has"
	awk -v n="$n1" 'NR == n { $0 = $1 } { print }' "$T/g1" >"$T/case"
	bad "a row of one number" "$n1" "row has 1"
	awk -v n="$n1" 'NR == n { $0 = "" } NR == n - 1 { $0 = $0 " 0 0" } { print }' \
	    "$T/g1" | sed '$d' >"$T/case"
	bad "mixed counts in one record" "$((n1 - 1))"

	# headers
	for a in oops =3 a= 9a=1 -a=1 'a=b c' "a=$(printf '\377')" \
	    "a=$(printf '\303\251')" "$(printf 'a=\001')"; do
		awk -v a="$a" 'NR == 1 { $0 = $0 " " a } { print }' "$T/g1" \
		    >"$T/case"
		bad "attribute '$a'" 1 "bad attribute"
	done
	awk 'NR == 1 { $0 = $0 " a=1 b=2 a=3" } { print }' "$T/g1" >"$T/case"
	bad "attribute given twice" 1 "attribute 'a' given twice"
	awk 'NR == 1 { for (i = 0; i < 70; i++) $0 = $0 " a" i "=1" } { print }' \
	    "$T/g1" >"$T/case"
	bad "70 attributes" 1 "too many attributes"
	for ty in x.y 9x -x "$(printf 'x\377')"; do
		awk -v t="$ty" 'NR == 1 { $1 = t } { print }' "$T/g1" >"$T/case"
		case $ty in 9x|-x) m="not a number" ;; *) m="bad record type" ;; esac
		bad "record type '$ty'" 1 "$m"
	done
	awk 'NR == 1 { $1 = "nosuchtype" } { print }' "$T/g1" >"$T/case"
	bad "unknown record type" 1
	awk 'NR == 1 { h = $0 } { print } NR == 2 { print h }' "$T/g1" >"$T/case"
	bad "a header after a row" 3 "header line inside a record"
	awk 'NR == 1 { print }' "$T/g1" >"$T/case"
	bad "a header and no rows" 1
	printf '\357\273\277' | cat - "$T/g1" >"$T/case"
	bad "a UTF-8 byte order mark" 1
	cp "$T/g1" "$T/ref"
	awk 'NR == 1 { gsub(/ /, " \t  "); $0 = "  " $0 " # note" } { print }' \
	    "$T/g1" >"$T/case"
	same "white space and a comment in the header"
	awk 'NR == 1 { $0 = $0 " note=x=y,z" } { print }' "$T/g1" >"$T/case"
	good "an attribute value with = and ,"
	awk 'NR == 1 { printf "%s big=", $0; while (n++ < 1048576) printf "x";
	    print ""; next } { print }' "$T/g1" >"$T/case"
	good "a 1 MB attribute value"

	# lines
	cp "$T/g1" "$T/ref"
	awk '{ printf "%s\r\n", $0 }' "$T/g1" >"$T/case"
	same "CRLF line ends"
	awk 'NR > 1 { gsub(/ /, "\t "); $0 = " \t" $0 " \t" } { print }' "$T/g1" \
	    >"$T/case"
	same "tabs and spaces around numbers"
	awk 'NR > 1 { $0 = $0 "# a note" } NR == 2 { print "   # between rows" }
	    { print }' "$T/g1" >"$T/case"
	same "comments after and between rows"
	awk 'NR == 2 { printf "#"; while (n++ < 1048576) printf "c"; print "" }
	    { print }' "$T/g1" >"$T/case"
	same "a 1 MB comment line"
	awk 'NR == 2 { printf "# \377\376 \300\200 \355\240\200\n" } { print }' \
	    "$T/g1" >"$T/case"
	same "invalid UTF-8 in a comment"
	awk '{ printf "%s\r", $0 } END { print "" }' "$T/g1" >"$T/case"
	bad "CR line ends (old Mac)" 1
	awk -v n="$n1" 'NR == n { printf "0"; while (k++ < 524288) printf " 0";
	    print ""; next } { print }' "$T/g1" >"$T/case"
	bad "a 1 MB row of numbers" "$n1" "row has more than"
	awk -v n="$n1" 'NR == n { s = "1"; while (length(s) < 1048576) s = s s
	    $1 = s } { print }' "$T/g1" >"$T/case"
	bad "a 1 MB number" "$n1" "too long"
	awk -v n="$n1" 'NR == n { $1 = $1 "\377" } { print }' "$T/g1" >"$T/case"
	bad "invalid UTF-8 in a number" "$n1" "is not a number"

	# NUL bytes: in a row, in a comment inside a record, between records
	{ sed '$d' "$T/g1"; tail -n 1 "$T/g1" | sed 's/ /@/' | tr @ '\000'; } \
	    >"$T/case"
	bad "a NUL byte in a row" "$n1" "NUL byte"
	{ cat "$T/g1"; printf '# a \000 b\n'; } >"$T/case"
	bad "a NUL byte in a comment in a record" "$((n1 + 1))" "NUL byte"
	printf '# a \000 b\n' >"$T/case"
	bad "a NUL byte in a comment between records" 1 "NUL byte"

	# the end of the stream: no final newline; cut inside a row
	tc="no final newline"
	{ cat "$T/g1"; echo; cat "$T/g2"; } | awk '{ printf "%s%s", s, $0; s = "\n" }' \
	    >"$T/in"
	run "$T/in"
	status 0
	cat "$T/o1" "$T/o2" >"$T/want"
	out_is "$T/want"
	tc="cut inside the last row"
	{ cat "$T/g1"; echo; sed '$d' "$T/g2"; tail -n 1 "$T/g2" |
	    awk '{ printf "%s", $1 }'; } >"$T/in"
	run "$T/in"
	status 1
	message_at "$T/in" $((n1 + $(wc -l <"$T/g2") + 1))
	out_is "$T/o1"

	# files: missing, a directory, garbage
	tc="a missing file among good ones"
	cat "$T/o1" "$T/o2" >"$T/want"
	run "$T/g1" "$T/nonexistent" "$T/g2"
	status 1
	[ "$(cat "$T/err")" = "$P: $T/nonexistent: No such file or directory" ] &&
	    ok || no "$what: $(cat "$T/err")"
	out_is "$T/want"
	tc="a directory"
	run "$T"
	status 1
	says "$P: $T: read error: Is a directory"
	tc="a binary file (the program itself)"
	dd if="bin/$P" of="$T/case" bs=65536 count=1 2>/dev/null
	run "$T/case"
	status 1
	[ -s "$T/err" ] && ! grep -v -q "^$P: $T/case:[0-9]*: [a-zA-Z'0-9]" \
	    "$T/err" && ok || no "$what: a message that is not 'P: FILE:LINE: ...'"
	out_valid
}

# ---- output failures ------------------------------------------------------

# many: good record 1, N times, as a stream (on standard output).
many() {
	awk -v n="$1" '{ r = r $0 "\n" } END { while (n-- > 0) printf "%s\n", r }' \
	    "$T/g1"
}

output_cases() {
	opts
	tc="standard output /dev/full"
	"${P}_run" "$T/g1" >/dev/full 2>"$T/err"
	echo $? >"$T/rc"
	status 1
	says "$P: write error: "
	tc="standard output /dev/full, much output"
	many 3000 >"$T/in"
	"${P}_run" "$T/in" >/dev/full 2>"$T/err"
	echo $? >"$T/rc"
	status 1
	says "$P: write error: "
	[ "$(wc -l <"$T/err")" -eq 1 ] && ok || no "$what: more than one message"
	# A closed pipe: the reader of a million records' output stops after
	# one line.  SIGPIPE kills the program, or (ignored, as some parents
	# leave it) the write fails with EPIPE and it exits 1; quietly, and
	# before it reads much more.
	for sig in default ignored; do
		tc="a closed pipe, SIGPIPE $sig"
		t0=$(date +%s)
		(
			[ $sig = ignored ] && trap '' PIPE
			many 1000000 2>/dev/null |
			    { "${P}_run" -; echo $? >"$T/rc"; } 2>"$T/err" | head -n 1
		) >"$T/out"
		t1=$(date +%s)
		[ $((t1 - t0)) -le $PROMPT ] && ok ||
		    no "$what: took $((t1 - t0)) s to stop"
		quiet
		[ "$(wc -l <"$T/out")" -eq 1 ] && ok || no "$what: no first line"
		if [ $sig = ignored ]; then
			status 1
		else
			rc=$(cat "$T/rc")
			[ "$rc" = 1 ] || [ "$rc" -gt 128 ] && ok ||
			    no "$what: exit $rc"
		fi
	done
}

# ---- units: the same curve scaled, translated -----------------------------

# curve_points: the points of every curve record on standard input at
# u = 0, 1/8, .. 1 of each piece, one "x y [z]" per line; computed here,
# not by sample, from the record's own definition.  Record types:
#   cubic  P_A P_B P'_A P'_B, Hermite form of Manning's eq. 7:
#          P = (2u^3 - 3u^2 + 1) P_A + (3u^2 - 2u^3) P_B
#              + (u^3 - 2u^2 + u) P'_A + (u^3 - u^2) P'_B
# (add the types of new programs' output here).
curve_points() {
	awk '
	/^[A-Za-z]/ { type = $1; next }
	/^$/ { next }
	type == "cubic" {
		d = NF / 4
		for (j = 0; j <= 8; j++) {
			u = j / 8
			h00 = 2*u^3 - 3*u^2 + 1; h01 = 3*u^2 - 2*u^3
			h10 = u^3 - 2*u^2 + u; h11 = u^3 - u^2
			s = ""
			for (k = 1; k <= d; k++) {
				x = h00*$k + h01*$(k+d) + h10*$(k+2*d) + h11*$(k+3*d)
				s = s sprintf("%.17g ", x)
			}
			print s
		}
		next
	}
	{ print "unknown record type " type > "/dev/stderr"; exit 1 }'
}

# units OPTIONS FILE: P on FILE and on FILE scaled by 1e-6 and 1e6 and
# translated by 1e6 gives the same curve scaled and translated, each
# point within 1e-9 of the curve's size.  Every number of FILE's rows is
# a coordinate (programs whose input rows hold derivatives need their
# own transformation here).
UNITS_TOL=1e-9
units() {
	OPTS=$1
	file=$2
	tc="units of $file ($OPTS)"
	run "$file"
	status 0
	curve_points <"$T/out" >"$T/p0"
	for tr in "1e-6 0" "1e6 0" "1 1e6"; do
		set -- $tr
		tc="$OPTS $file: knots times $1 plus $2"
		awk -v s="$1" -v d="$2" '/^[ \t]*[-+.0-9]/ { sub(/#.*/, "")
			for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * s + d) }
			{ print }' "$file" >"$T/scaled"
		run "$T/scaled"
		status 0
		curve_points <"$T/out" >"$T/p1"
		e=$(awk -v s="$1" -v d="$2" -v tol=$UNITS_TOL '
		NR == FNR { n = split($0, a)
			for (k = 1; k <= n; k++) {
				x[FNR, k] = a[k] * s + d
				if (FNR == 1) x0[k] = a[k]
				e = a[k] - x0[k]; e = e < 0 ? -e : e
				if (e > size) size = e
			}
			rows = FNR; next }
		{ for (k = 1; k <= NF; k++) { e = $k - x[FNR, k]; e = e < 0 ? -e : e
			if (e > worst) worst = e } m = FNR }
		END { size *= s < 0 ? -s : s
			if (m != rows || !(size > 0)) { print "the points differ in number"; exit }
			if (!(worst <= tol * size))
				printf "off by %.3g of the size %.3g", worst / size, size }' \
		    "$T/p0" "$T/p1")
		[ -z "$e" ] && ok || no "$what: $e"
	done
}

# ---- splinefit -------------------------------------------------------------

splinefit_run() { "$B/splinefit" "$@"; }
splinefit_good() {
	case $1 in
	1) printf 'points id=1\n0 0\n1 0\n1 1\n0 1\n' ;;
	2) printf 'points id=2\n2 0 1\n0 1 0\n-2 0 1\n0 -1 0\n' ;;
	esac
}

# knots ROWS: the rows (printf text) under a header 'points', into $T/case
knots() { printf "points\n$1" >"$T/case"; }

splinefit_cases() {
	opts
	knots '0 0\n'
	bad "one knot" 1 "1 knot: a closed curve needs at least 3"
	knots '0 0\n1 0\n'
	bad "two knots" 1 "2 knots: a closed curve needs at least 3"
	knots '0 0\n1 0\n1 0\n0 1\n'
	bad "coincident consecutive knots" 4 "knot 3 coincides with knot 2"
	knots '0 0\n1 0\n1 1e-13\n0 1\n'
	bad "nearly coincident knots (1e-13)" 4 "knot 3 coincides with knot 2"
	knots '0 0\n1 0\n1 1e-10\n0 1\n'
	sane "nearly coincident knots (1e-10)"
	knots '0 0\n1 0\n1 1\n0 0\n'
	bad "last knot on the first" 2 "closing the curve"
	knots '0 0\n1 1\n3 3\n2 2\n'
	bad "all knots collinear" 1 "all knots lie on one line"
	knots '0 0\n1 1\n3 3\n2 2.000000001\n'
	sane "nearly collinear knots (1e-9)"
	knots '0 0\n1 1\n3 3\n2 2.0000000000001\n'
	sane "nearly collinear knots (1e-13)"
	knots '0\n1\n2\n'
	bad "points of 1 coordinate" 2 "knots have 1 coordinate"
	knots '0 0 0 0\n1 0 0 0\n1 1 0 0\n'
	bad "points of 4 coordinates" 2 "knots have 4 coordinates"
	knots '0 0\n1 0 0\n1 1 0\n'
	bad "2 then 3 coordinates" 3 "row has more than 2 numbers"
	knots '0 0 0\n1 0\n1 1 0\n'
	bad "3 then 2 coordinates" 3 "row has 2 numbers"
	printf 'cubic closed=1\n0 0 1 0 0 2 0 -2\n' >"$T/case"
	bad "a curve record" 1 "cubic record: splinefit reads knots"
	printf 'points start=1,0\n0 0\n1 0\n1 1\n' >"$T/case"
	same_as_without_attr "start= on a closed curve"
	knots '1e300 0\n0 1e300\n-1e300 0\n'
	sane "knots near 1e300"
	knots '1.7e308 0\n0 1.7e308\n-1.7e308 0\n'
	sane "knots near the largest double"
	knots '1e-320 0\n0 1e-320\n-1e-320 0\n'
	sane "subnormal knots"
	knots '1e-300 0\n0 1e-300\n1e300 1e300\n'
	sane "knots 1e-300 and 1e300"
	# neighbouring chords in the ratio 1e6, each way
	knots '0 0\n1 0\n1 1e-6\n0 1\n'
	sane "chords 1 : 1e-6"
	knots '0 0\n1e-6 0\n1 1\n1 2\n0 1\n'
	sane "chords 1e-6 : 1"
	knots '0 0\n1 0\n1.000001 0.000001\n2 1\n3 1\n3.000001 1.000001\n3 5\n'
	sane "chords alternating 1 and 1e-6"

	# the sign rules of section 8 disagree on fig. 15's knots
	knots '10 0\n3.5 9.4\n0 2\n-3.5 9.4\n-10 0\n-7 -7\n0 -10\n7 -7\n'
	cp "$T/case" "$T/fig15"
	sane "fig. 15 (sign rules disagree), -k positive"
	opts -k turn
	sane "fig. 15 (sign rules disagree), -k turn"
	opts -i 2
	cp "$T/fig15" "$T/case"
	bad "no convergence in -i 2" 1 "no convergence in 2 iterations: tangents still move by 0."

	opts -o
	knots '0 0\n'
	bad "one knot, open" 1 "1 knot: an open curve needs at least 2"
	knots '0 0\n1 0\n'
	good "two knots, open"
	knots '0 0\n1 1\n3 3\n2 2\n'
	good "collinear knots, open"
	# a curve through collinear knots (in order, no end tangents given)
	# is their line: every point of it is on y = x
	curve_points <"$T/caseout" | awk '{ d = $1 - $2; if (d < 0) d = -d
	    if (d > m) m = d } END { exit !(m < 1e-12) }' && ok ||
	    no "open collinear knots: the curve leaves their line"
	knots '0 0\n1 0\n0 0\n'
	bad "open, doubling back" 3 "knots 1 and 3 on either side of knot 2 coincide"
	printf 'points start=1\n0 0\n1 0\n' >"$T/case"
	bad "start= of 1 number" 1 "attribute start=1: want 2 numbers"
	printf 'points end=nan,1\n0 0\n1 0\n' >"$T/case"
	bad "end=nan,1" 1 "want 2 numbers"
	printf 'points start=0,0\n0 0\n1 0\n' >"$T/case"
	bad "start=0,0" 1 "start tangent is zero"
	printf 'points start=-1,0 end=-1,0\n0 0\n1 0\n' >"$T/case"
	bad "both tangents back along the chord" 3 "turn back along the chord"

	# a record of BIG knots on the unit circle: fits, in linear memory
	# (peak measured with /usr/bin/time -v: see the notes), lossless
	# knots, tangents across the radius
	opts -p 9
	tc="$BIG knots"
	awk -v n="$BIG" 'BEGIN { print "points id=big"; for (i = 0; i < n; i++) {
	    a = 2 * 3.14159265358979324 * i / n; printf "%.17g %.17g\n", cos(a), sin(a) } }' \
	    >"$T/case"
	run "$T/case"
	status 0
	awk -v n="$BIG" 'NR == 1 { if ($0 != "cubic closed=1 id=big") exit; next }
	    NF == 8 { r = sqrt($1 * $1 + $2 * $2); d = $1 * $5 + $2 * $6
	        if (r < 1 - 1e-8 || r > 1 + 1e-8 || d * d > 1e-16 * ($5 * $5 + $6 * $6))
	            exit; m++; next }
	    NF != 0 { exit } END { exit m != n }' "$T/out" && ok ||
	    no "$what: not $BIG segments with knots on the circle"

	# units: the same curve whatever the units and the origin
	for o in "" -o "-m chord" "-m ferguson -o"; do
		units "$o" man/figures/insole.knots
	done
	units "-k turn" "$T/fig15"
	printf '0 0 0\n4 1 1\n5 3 -2\n2 5 0\n-1 2 1\n' >"$T/space"
	units "" "$T/space"
	units "-o -S 1,0,0 -E 0,1,1" "$T/space"
	printf '0 0\n1 0\n1.001 0.001\n2 1\n3 1\n3.001 1.001\n3 5\n' >"$T/uneven"
	units "" "$T/uneven"
}

# same_as_without_attr NAME: the record in $T/case is read as if its
# header had no attributes beyond the type.
same_as_without_attr() {
	awk 'NR == 1 { $0 = $1 } { print }' "$T/case" >"$T/ref"
	same "$1"
}

# ---- sample ----------------------------------------------------------------

sample_run() { "$B/sample" "$@"; }
sample_good() {
	case $1 in
	1) printf 'cubic closed=0 id=1\n0 0 1 0 0 2 0 -2\n1 0 2 0 0 -2 0 2\n' ;;
	2) printf 'cubic closed=1\n0 0 0 1 0 0 1 1 0 -1 1 0\n1 0 0 0 0 0 1 -1 0 -1 -1 0\n' ;;
	esac
}

sample_cases() {
	opts
	printf 'cubic\n0 0 1 0 0 2 0\n' >"$T/case"
	bad "a truncated cubic row" 2 "cubic rows need 8 or 12 numbers, not 7"
	printf 'cubic\n0 1 0 1\n' >"$T/case"
	bad "a cubic of 1 coordinate" 2 "not 4"
	printf 'cubic\n0 0 0 0 1 0 0 0 1 1 0 0 0 1 0 0\n' >"$T/case"
	bad "a cubic of 4 coordinates" 2 "not 16"
	printf 'cubic\n0 0 1 0 0 2 0 -2\n0 0 1 0 0 2 0 -2 0 0 0 0\n' >"$T/case"
	bad "a cubic of 2 then 3 coordinates" 3 "row has more than 8 numbers"
	printf 'cubic closed=2\n0 0 1 0 0 2 0 -2\n' >"$T/case"
	bad "closed=2" 1 "attribute closed=2: want 0 or 1"
	printf 'cubic closed=yes\n0 0 1 0 0 2 0 -2\n' >"$T/case"
	bad "closed=yes" 1 "want 0 or 1"
	printf 'points\n0 0\n1 1\n' >"$T/case"
	bad "a point record" 1 "a point record is no curve"
	printf '0 0\n1 1\n' >"$T/case"
	bad "rows without a header" 1 "a point record is no curve"
	printf 'cubic\n0 0 1e308 0 0 1e308 0 -1e308\n' >"$T/case"
	bad "coefficients near the largest double" 2 "overflows"
	printf 'cubic\n1e-320 0 2e-320 0 0 1e-320 0 -1e-320\n' >"$T/case"
	sane "subnormal coefficients"
	# found by fuzzing: -p rounded the largest double up to 1.8e+308,
	# which no program reads back
	opts -p 2
	printf 'cubic\n1.7976931348623157e308 0 1.7976931348623157e308 0 0 0 0 0\n' \
	    >"$T/case"
	good "-p 2 and the largest double"
	opts
	printf 'cubic\n0 0 1 0 0 0 1 0\n' >"$T/case"
	good "a zero end tangent"
	opts -d -k -u
	printf 'cubic\n0 0 1 0 0 0 1 0\n' >"$T/case"
	bad "a zero end tangent, -d" 2 "tangent vanishes in segment 1"
	printf 'cubic\n0 0 0 0 0 0 0 0\n' >"$T/case"
	bad "a segment that is a point, -d" 2 "tangent vanishes"
	printf 'cubic\n0 0 1e-300 0 1e-300 0 1e-300 0\n' >"$T/case"
	sane "a tiny segment, -d -k"
	printf 'cubic\n0 0 1e300 0 1e300 0 1e300 0\n' >"$T/case"
	sane "a huge segment, -d -k"

	# a record of BIG segments along the x axis, one point each
	opts -n 1 -p 9
	tc="$BIG segments"
	awk -v n="$BIG" 'BEGIN { print "cubic closed=0"; for (i = 0; i < n; i++)
	    printf "%d 0 %d 0 1 0 1 0\n", i, i + 1 }' >"$T/case"
	run "$T/case"
	status 0
	awk -v n="$BIG" 'NF == 2 { if ($1 != m || $2 != 0) exit; m++; next }
	    NF != 0 { exit } END { exit m != n + 1 }' "$T/out" && ok ||
	    no "$what: not $BIG + 1 points 0..$BIG on the axis"
}

# ---- run them -----------------------------------------------------------------

for P in $PROGS; do
	stream_cases
	output_cases
	"${P}_cases"
done
P=bad
echo "bad: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
