#!/bin/sh
# examples.sh: every command in the EXAMPLES section of every manual page,
# and every command in the README's code blocks, runs as written.
#
# sh tests/examples.sh            the tree: man/*.[157] with man/examples,
#                                 the programs of bin/ ($LOFT_BIN), README
# sh tests/examples.sh -i PREFIX  an installed tree: PREFIX/share/man's
#                                 pages with PREFIX/share/loft/examples and
#                                 PREFIX/bin (tests/install.sh runs it)
#
# Pages.  In the EXAMPLES section a command is a line ".Dl $ CMD", or a
# line "$ CMD" of a ".Bd -literal" block with the indented lines after it
# (a command continued after "|", "\" or inside quotes); the mdoc escapes
# \e \- \~ \& \(aq are read as the page shows them.  The lines of a block
# after a command that are neither a command nor indented are its output
# as the page shows it.  One example (a .Dl line, or a .Bd block) runs in
# a fresh copy of the example files, its commands in order, each by sh in
# that directory with loft's programs first on PATH; so no example can
# rely on another's files.  Each command must exit 0.  Where the page
# shows output, what the command writes (standard output and standard
# error together, as a terminal shows them, though standard error may
# come first here) must be that output: the same
# words in the same order, any run of blanks and newlines counting as one
# (a page folds long lines and shows blank lines as it likes), numbers
# equal to 1e-9 of their size or both below 1e-12 (rounding noise, as
# measure's curvature jump; another libm may print other noise).  The
# whole output is compared, however long.  After each example every
# shipped file must be as it was: an example writes only files of its own.
#
# README (the tree only).  In an indented code block each line indented
# four spaces is a command, and lines indented more continue it; a block
# whose first word ends in "/" is a listing of the tree, not commands.
# The commands run in order, as the README says, from the top of the
# tree: in a scratch directory holding bin (a link to the tree's) and a
# copy of man, so their files do not litter the tree; "make TARGET" runs
# in the tree itself, but not "make check" (this is part of it).  Each
# must exit 0; the README shows no output to compare.  (make check-san's
# copy of the tree has no README.)
#
# A command that calls gnuplot, graph, parallel, chromium or python where
# that tool is not installed, or loftplot -i where the page was built
# without its WebAssembly module, is skipped with the rest of its example, and
# one line per missing tool names the examples skipped.  GNUTERM=dumb
# keeps gnuplot from opening a window.
#
# Besides: every file man/examples/README lists is there and named by
# some example, and nothing else is there; what "make examples" makes, in
# a scratch directory, is what is shipped; a made-up page with a broken
# example and a wrong output fails (so this test can fail); and a batch
# split by GNU parallel into jobs of a few records, on this machine and
# through -S :, gives the same bytes as one run (README's "Scaling out";
# skipped without parallel).
# The last line is "examples: N passed, M failed".

T=bin/test/examples
[ "$1" = -i ] && T=bin/test/examples-installed
. tests/lib.sh
ROOT=$(pwd)
TOOLS="gnuplot graph parallel chromium python3 python"

if [ "$1" = -i ]; then
	P=$(cd "$2" && pwd) || exit 2
	BINDIR=$P/bin
	EX=$P/share/loft/examples
	PAGES=$(ls "$P"/share/man/man[157]/*.[157])
	README=
else
	BINDIR=$(cd "$B" && pwd)
	EX=$ROOT/man/examples
	PAGES=$(ls man/*.[157])
	README=README
	[ -f README ] || { README=; echo "skip: the README's commands (no README)"; }
fi
export GNUTERM=dumb

# ---- extracting the commands ----------------------------------------------
# awk -v out=DIR -f: writes DIR/E.C.cmd (command C of example E), E.C.want
# (the output the page shows, if any) and E.C.at (FILE:LINE), numbered so
# that ls lists them in order; DIR/errors names what it cannot read.
EXTRACT='
function unesc(s,   o, i, c) {
	if (mode != "man")
		return s
	o = ""
	while ((i = index(s, "\\")) > 0) {
		o = o substr(s, 1, i - 1)
		c = substr(s, i + 1, 1)
		if (c == "e") o = o "\\"
		else if (c == "-") o = o "-"
		else if (c == "~") o = o " "
		else if (c == "&") o = o
		else if (substr(s, i + 1, 3) == "(aq") { o = o "\047"; i += 2 }
		else { print FILENAME ":" FNR ": escape \\" c " not read here" >> (out "/errors"); o = o "\\" c }
		s = substr(s, i + 2)
	}
	return o s
}
function name(ext) { return out "/" sprintf("%03d.%02d.", ex, c) ext }
function command(line) {
	c++
	f = name("cmd")
	printf "%s\n", unesc(line) > f
	close(f)
	printf "%s:%d\n", FILENAME, FNR > name("at")
	close(name("at"))
	st = "cmd"
}
function more(line,   f) {
	f = name(st == "cmd" ? "cmd" : "want")
	printf "%s\n", unesc(line) >> f
	close(f)
}
mode == "man" && /^\.Sh / { sec = ($2 == "EXAMPLES"); lit = 0; next }
mode == "man" && !sec { next }
mode == "man" && !lit && /^\.Bd -literal/ { lit = 1; ex++; c = 0; st = ""; next }
mode == "man" && lit && /^\.Ed/ { lit = 0; next }
mode == "man" && !lit && /^\.Dl \$ / {
	ex++; c = 0
	if (index($0, "\""))
		print FILENAME ":" FNR ": a .Dl line with a double quote (mdoc eats it): use .Bd -literal" >> (out "/errors")
	command(substr($0, 7))
	next
}
mode == "man" && lit && /^\$ / { command(substr($0, 3)); next }
mode == "man" && lit && /^\./ { next }
mode == "man" && lit && st == "cmd" && /^[ \t]/ { more($0); next }
mode == "man" && lit && st != "" { st = "want"; more($0); next }
mode == "readme" && /^    [^ ]/ && !blk && prev == "" {
	blk = 1; ex++; c = 0
	split($0, w, " ")
	list = (w[1] ~ /\/$/)
}
mode == "readme" && blk && !/^    / { blk = 0 }
mode == "readme" && blk && !list && /^    [^ ]/ { command(substr($0, 5)); st = "cmd" }
mode == "readme" && blk && !list && /^     / { more($0) }
{ prev = $0 }
'

# extract MODE FILE DIR: the commands of FILE into DIR
extract() {
	rm -rf "$3" && mkdir -p "$3" || exit 2
	awk -v mode="$1" -v out="$3" "$EXTRACT" "$2"
	if [ -s "$3/errors" ]; then
		while read -r line; do
			no "$line"
		done <"$3/errors"
	fi
}

# ---- comparing output -----------------------------------------------------
# awk -f SAME got want: exit 0 when the words agree as the header says
SAME='
function isnum(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function abs(x) { return x < 0 ? -x : x }
function close_to(a, b,   m) {
	a += 0; b += 0
	if (abs(a) < 1e-12 && abs(b) < 1e-12) return 1
	m = abs(a) > abs(b) ? abs(a) : abs(b)
	return abs(a - b) <= 1e-9 * m
}
FNR == 1 { file++ }
{ for (i = 1; i <= NF; i++) word[file, ++n[file]] = $i }
END {
	if (n[1] != n[2]) { print "has " n[1] + 0 " words, the page shows " n[2] + 0; exit 1 }
	for (i = 1; i <= n[1]; i++) {
		a = word[1, i]; b = word[2, i]
		if (a == b || (isnum(a) && isnum(b) && close_to(a, b))) continue
		print "word " i " is " a ", the page shows " b
		exit 1
	}
}
'

# ---- running ----------------------------------------------------------------
# The shipped files, and their sums, to check that no example changes one.
ls "$EX" >"$T/shipped" || exit 2
(cd "$EX" && cksum $(cat "$ROOT/$T/shipped")) >"$T/sums"

SKIPPED=            # "tool place" lines of the commands skipped
quiet=0             # 1 while the made-up page runs: count, say nothing
qpass=0
qfail=0
good() { if [ $quiet = 1 ]; then qpass=$((qpass + 1)); else ok; fi; }
bad() { if [ $quiet = 1 ]; then qfail=$((qfail + 1)); else no "$@"; fi; }

# missing CMDFILE: the first tool of TOOLS the command calls and this
# machine lacks, if any; or wasm-module, where it runs loftplot -i and
# the page was built without its module (no wasm32 toolchain)
missing() {
	if grep -q 'loftplot -i' "$1" && [ ! -s "$ROOT/bin/wasm/loft.wasm" ]; then
		echo wasm-module
		return
	fi
	for tool in $TOOLS; do
		if grep -E -q "(^|[|;&({]|then|do)[[:space:]]*$tool([[:space:]]|$)" "$1" &&
		    ! command -v "$tool" >/dev/null 2>&1; then
			echo "$tool"
			return
		fi
	done
}

# brief TEXT N: TEXT on one line, cut to N characters
brief() {
	printf '%s' "$1" | tr '\n' ' ' | cut -c "1-$2"
}

# runall DIR HERE: run the commands in DIR; each example in a fresh copy
# of the example files (HERE empty), or all in the directory HERE
runall() {
	for e in $(ls "$1" | sed -n 's/^\([0-9]*\)\.[0-9]*\.cmd$/\1/p' | sort -u); do
		if [ -z "$2" ]; then
			w=$ROOT/$T/run
			rm -rf "$w" && cp -R "$EX" "$w" || exit 2
		else
			w=$2
		fi
		for cmd in "$1/$e".*.cmd; do
			at=$(cat "${cmd%.cmd}.at")
			tool=$(missing "$cmd")
			if [ -n "$tool" ]; then
				SKIPPED="$SKIPPED$tool ${at##*/}
"
				break
			fi
			text=$(cat "$cmd")
			case $text in
			"make check"*)
				continue ;;
			make\ *)
				(cd "$ROOT" && MAKEFLAGS= MFLAGS= sh -c "$text") \
				    >"$T/got" 2>&1 ;;
			*)
				(cd "$w" && PATH="$BINDIR:$PATH" sh -c "$text") \
				    >"$T/got" 2>&1 ;;
			esac
			rc=$?
			if [ $rc -ne 0 ]; then
				bad "$at: exit $rc: $(brief "$text" 70): $(head -c 200 "$T/got")"
				continue
			fi
			good
			want=${cmd%.cmd}.want
			[ -f "$want" ] || continue
			if why=$(awk "$SAME" "$T/got" "$want"); then
				good
			else
				bad "$at: output $why: $(brief "$text" 60)"
			fi
		done
		[ -n "$2" ] && continue
		(cd "$w" && cksum $(cat "$ROOT/$T/shipped") 2>&1) |
		    cmp -s - "$T/sums" && good ||
		    bad "${at%:*}: an example changed a shipped file (near line ${at##*:})"
	done
}

# ---- the made-up page: a broken example must fail ---------------------------
cat >"$T/broken.1" <<'EOF'
.Sh EXAMPLES
.Dl $ splinefit no-such.knots
.Bd -literal -offset indent
$ printf '0 0\en1 0\en1 1\en' | splinefit -o | measure -f length
2.5

.Ed
.Bd -literal -offset indent
$ printf '0 0\en3 4\en' | splinefit -o |
    measure -f length
5

.Ed
EOF
extract man "$T/broken.1" "$T/x"
quiet=1
runall "$T/x" ""
quiet=0
[ $qpass -eq 6 ] && [ $qfail -eq 2 ] && ok ||
    no "the made-up page: $qpass passed, $qfail failed; want 6 and 2"

# ---- the pages, and the README ------------------------------------------------
n=0
for page in $PAGES; do
	extract man "$page" "$T/x"
	n=$((n + $(ls "$T/x" | grep -c '\.cmd$')))
	cat "$T"/x/*.cmd >>"$T/all" 2>/dev/null
	runall "$T/x" ""
done
[ "$n" -ge 80 ] && ok || no "only $n commands in the pages' EXAMPLES"
if [ -n "$README" ]; then
	extract readme "$README" "$T/x"
	m=$(ls "$T/x" | grep -c '\.cmd$')
	[ "$m" -ge 25 ] && ok || no "only $m commands in the README"
	cat "$T"/x/*.cmd >>"$T/all" 2>/dev/null
	w=$ROOT/$T/readme
	rm -rf "$w" && mkdir -p "$w" && cp -R man "$w/man" &&
	    ln -s "$BINDIR" "$w/bin" || exit 2
	runall "$T/x" "$w"
fi

# ---- the example files ----------------------------------------------------------
if [ -z "$1" ]; then
	# the list in man/examples/README, the files, and what names them
	sed -n 's/^\([A-Za-z0-9][-A-Za-z0-9._]*\)  .*/\1/p' man/examples/README | sort >"$T/listed"
	grep -v '^README$' "$T/shipped" | sort | cmp -s - "$T/listed" && ok ||
	    no "man/examples holds $(grep -v '^README$' "$T/shipped" | sort | comm -3 - "$T/listed" | tr '\n' ' ')beyond or short of its README's list"
	for f in $(cat "$T/listed"); do
		grep -F -q -- "$f" "$T/all" && ok ||
		    no "man/examples/$f is named by no example"
	done
	# what make examples makes now, in a scratch directory
	if MAKEFLAGS= MFLAGS= make -s examples MKEX="$ROOT/$T/made" \
	    EXBIN="$BINDIR" >"$T/out" 2>"$T/err"; then
		made=$(ls "$T/made")
		[ $(echo $made | wc -w) -ge 10 ] && ok ||
		    no "make examples made only $made"
		for f in $made; do
			cmp -s "$T/made/$f" "man/examples/$f" && ok ||
			    no "man/examples/$f is not what make examples makes now"
		done
	else
		no "make examples: $(head -3 "$T/err")"
	fi
fi

# ---- scaling out: a batch split by GNU parallel ---------------------------------
if [ -n "$1" ]; then
	:
elif ! command -v parallel >/dev/null 2>&1; then
	SKIPPED="${SKIPPED}parallel the_split_batches
"
else
	K=man/examples/many-insoles.knots
	PATH="$BINDIR:$PATH"
	export PATH
	# the batch twice over, so that it splits into many jobs
	cat "$K" "$K" >"$T/batch"
	recs=$(grep -c '^$' "$T/batch")
	[ "$recs" -ge 30 ] && ok || no "the batch has $recs records"
	for pipe in 'splinefit | sample -p 6' 'splinefit' \
	    'splinefit -m manning | measure' 'grade -r -1:1 | splinefit'; do
		sh -c "$pipe" <"$T/batch" >"$T/one" 2>"$T/err" && [ -s "$T/one" ] &&
		    ok || no "$pipe: $(head -3 "$T/err")"
		for how in '-N 1' '-N 7' '--block 3k' '-S : -N 5'; do
			parallel $how --pipe -k --recend '\n\n' "$pipe" \
			    <"$T/batch" >"$T/split" 2>"$T/err"
			cmp -s "$T/one" "$T/split" && ok ||
			    no "parallel $how '$pipe': not the bytes of one run: $(head -3 "$T/err")"
		done
	done
	# and the jobs were many: each of -N 7's gets 7 records
	jobs=$(parallel -N 7 --pipe --recend '\n\n' 'echo' <"$T/batch" | wc -l)
	[ "$jobs" -eq $(((recs + 6) / 7)) ] && ok ||
	    no "parallel -N 7 ran $jobs jobs for $recs records"
fi

# one line for each tool missing, naming what it skipped
printf '%s' "$SKIPPED" | awk '
	{ gsub(/_/, " ", $2); at[$1] = at[$1] (at[$1] == "" ? "" : ", ") $2 }
	END { for (t in at) print "skip: " at[t] " (no " t ")" }'

finish examples
