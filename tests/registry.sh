#!/bin/sh
# registry.sh: every list kept by hand beside one of loft's tables says
# what the table says, so that a list edited alone fails here.  The
# tables: the library's (record types, output formats, readers:
# bin/test/tables prints them) and the Makefile's PROGS and FUZZERS.
# The lists: tocad's and fromcad's usage, their pages and their tests;
# cmd/, man/, loft.7's programs, records and SEE ALSO; the fuzz
# harnesses and their corpora; tests/bad.sh's programs; loft.5's
# sections, one a record type.
# The last line is "registry: N passed, M failed".

T=bin/test/registry
. tests/lib.sh
TOP=${REGISTRY_TOP:-.}  # the tree checked (a copy, to see this fail)

# makevar NAME: the words of the Makefile variable NAME (continued lines)
makevar() {
	awk -v v="$1" '$0 ~ "^" v "[ \t]*[+]?=" { f = 1; sub(/^[^=]*=/, "") }
	f { c = sub(/\\$/, ""); print; if (!c) f = 0 }' "$TOP/Makefile" |
	    tr -s ' \t' '\n\n' | sed '/^$/d'
}
# same WHAT A B: the files of words A and B hold the same words, in any
# order, each once
same() {
	sort "$2" >"$T/a"
	sort "$3" >"$T/b"
	if cmp -s "$T/a" "$T/b" && [ -s "$T/a" ] &&
	    [ -z "$(uniq -d "$T/a")" ]; then
		ok
	else
		no "$1: $(comm -3 "$T/a" "$T/b" | tr '\n\t' ' -') (differ)"
	fi
}
words() { tr -s ' |,\t' '\n\n\n\n' | sed '/^$/d'; }

bin/test/tables >"$T/tables" || { no "bin/test/tables failed"; finish registry; exit; }
sed -n 's/^type //p' "$T/tables" >"$T/types"
sed -n 's/^format //p' "$T/tables" >"$T/formats"
sed -n 's/^reader //p' "$T/tables" >"$T/readers"

# ---- output formats: tocad -----------------------------------------------
bin/tocad -h | sed -n 's/.*-f \([a-z|]*\).*/\1/p' | words >"$T/l"
same "tocad's usage -f against the format table" "$T/formats" "$T/l"
sed -n '/^\.Sh SYNOPSIS/,/^\.Sh/s/^\.Fl f Cm \(.*\)/\1/p' "$TOP/man/tocad.1" |
    sed 's/ Ns | Ns Cm /|/g' |
    words >"$T/l"
same "tocad.1's SYNOPSIS -f against the format table" "$T/formats" "$T/l"
for f in $(cat "$T/formats"); do
	grep -q "^\.It Cm $f\$" "$TOP/man/tocad.1" && ok ||
	    no "tocad.1 has no paragraph .It Cm $f"
	grep -q -- "-f $f\\b" "$TOP/tests/tocad.sh" && ok ||
	    no "tests/tocad.sh never runs tocad -f $f"
done
sed -n "s/.*-f 'ps': want \\([a-z, ]*\\)\".*/\\1/p" "$TOP/tests/tocad.sh" |
    sed 's/ or /,/' | words >"$T/l"
same "tests/tocad.sh's expected -f message against the format table" \
    "$T/formats" "$T/l"

# ---- readers: fromcad ---------------------------------------------------------
bin/fromcad -h | sed -n 's/.*-f \([a-z|]*\).*/\1/p' | words >"$T/l"
same "fromcad's usage -f against the reader table" "$T/readers" "$T/l"
sed -n 's/^\.Op Fl f Cm \(.*\)/\1/p' "$TOP/man/fromcad.1" |
    sed 's/ Ns | Ns Cm /|/g' | words >"$T/l"
same "fromcad.1's SYNOPSIS -f against the reader table" "$T/readers" "$T/l"
sed -n 's/^\.It Fl f Cm \(.*\)/\1/p' "$TOP/man/fromcad.1" |
    sed 's/ Ns | Ns Cm /|/g' | words >"$T/l"
same "fromcad.1's OPTIONS -f against the reader table" "$T/readers" "$T/l"
for r in $(cat "$T/readers"); do
	grep -q -i "\\b$r\\b" "$TOP/tests/fromcad.sh" && ok ||
	    no "tests/fromcad.sh never names the reader $r"
done

# ---- programs -------------------------------------------------------------------
makevar PROGS >"$T/progs"
ls "$TOP"/cmd/*.c | sed 's|.*/||; s|\.c$||' >"$T/l"
same "PROGS against cmd/*.c" "$T/progs" "$T/l"
ls "$TOP"/man/*.1 | sed 's|.*/||; s|\.1$||' >"$T/l"
same "PROGS against man/*.1" "$T/progs" "$T/l"
awk '/^\.Ss Programs/ { f = 1; next } /^\.S[sh]/ { f = 0 }
    f && /^\.It Xr [a-z]+ 1/ { print $3 }' "$TOP/man/loft.7" >"$T/l"
same "PROGS against loft.7's Programs" "$T/progs" "$T/l"
awk '/^\.Sh SEE ALSO/ { f = 1; next } /^\.Sh/ { f = 0 }
    f && /^\.Xr [a-z]+ 1/ { print $2 }' "$TOP/man/loft.7" >"$T/l"
same "PROGS against loft.7's SEE ALSO" "$T/progs" "$T/l"
# tests/bad.sh tries every program that reads records: all but fromcad
sed -n '/^PROGS=\${BAD_PROGS:-"/,/"}$/p' "$TOP/tests/bad.sh" |
    sed 's/^PROGS=\${BAD_PROGS:-"//; s/"}$//; s/\\$//' | words >"$T/l"
grep -v '^fromcad$' "$T/progs" >"$T/p"
same "PROGS but fromcad against tests/bad.sh's PROGS" "$T/p" "$T/l"

# ---- fuzzing: harness, corpus and FUZZERS, for stream and every program
# but tocad (its documents are made whole in memory from records the
# stream harness already covers)
makevar FUZZERS >"$T/fuzzers"
ls "$TOP"/tests/fuzz/*.c | sed 's|.*/||; s|\.c$||' >"$T/l"
same "FUZZERS against the harnesses tests/fuzz/*.c" "$T/fuzzers" "$T/l"
ls "$TOP"/tests/fuzz/corpus >"$T/l"
same "FUZZERS against the corpora tests/fuzz/corpus/*" "$T/fuzzers" "$T/l"
{ grep -v '^tocad$' "$T/progs"; echo stream; } >"$T/p"
same "PROGS but tocad, and stream, against FUZZERS" "$T/p" "$T/fuzzers"
for f in $(cat "$T/fuzzers"); do
	[ -n "$(ls "$TOP/tests/fuzz/corpus/$f")" ] && ok ||
	    no "tests/fuzz/corpus/$f is empty"
done

# ---- record types: loft.5 and loft.7 ------------------------------------------
# loft.5 has a section for each type, named by it (points: "Point records")
awk '/^\.Ss Point records$/ { print "points" }
    /^\.Ss [a-z][a-z-]*$/ { print $2 }' "$TOP/man/loft.5" >"$T/l"
same "the type table against loft.5's sections" "$T/types" "$T/l"
awk '/^\.Ss Records/ { f = 1; next } /^\.S[sh]/ { f = 0 }
    f && /^\.It Cm [a-z-]+$/ { print $3 }' "$TOP/man/loft.7" >"$T/l"
same "the type table against loft.7's Records" "$T/types" "$T/l"
finish registry
