#!/bin/sh
# install.sh: make install into a temporary PREFIX puts every program,
# the library, its header and every page where they belong, each a copy
# of the file in the tree; make uninstall then removes exactly those
# files: none of them is left, and a file of someone else's beside them
# stays.  The list of what should be there is made here from the tree
# (cmd/*.c, man/*.[157]), not from the Makefile's own variables.  The
# last line is "install: N passed, M failed".

T=bin/test/install
. tests/lib.sh

P="$(pwd)/$T/prefix"
rm -rf "$P"
mkdir -p "$P/bin"
echo "not loft's" >"$P/bin/other"
# (without the caller's MAKEFLAGS, as tests/loftplot.sh runs make)
if MAKEFLAGS= MFLAGS= make -s install PREFIX="$P" >"$T/out" 2>"$T/err"; then
	ok
else
	no "make install: $(head -3 "$T/err")"
fi
: >"$T/want"
for c in cmd/*.c; do
	p=${c##*/}
	p=${p%.c}
	echo "bin/$p bin/$p" >>"$T/want"
done
echo "bin/libloft.a lib/libloft.a" >>"$T/want"
echo "lib/loft.h include/loft.h" >>"$T/want"
echo "lib/loftprog.h include/loftprog.h" >>"$T/want"
echo "lib/loftcad.h include/loftcad.h" >>"$T/want"
for m in man/*.[157]; do
	echo "$m share/man/man${m##*.}/${m##*/}" >>"$T/want"
done
n=0
while read -r src dst; do
	n=$((n + 1))
	cmp -s "$src" "$P/$dst" && ok || no "$dst is not a copy of $src"
done <"$T/want"
[ "$n" -ge 20 ] && ok || no "only $n files expected"
# nothing in bin, lib, include or the manual beyond them (and the other
# file)
got=$(find "$P/bin" "$P/lib" "$P/include" "$P/share/man" -type f | wc -l)
[ "$got" -eq $((n + 1)) ] && ok || no "installed $got files, want $((n + 1))"
if MAKEFLAGS= MFLAGS= make -s uninstall PREFIX="$P" >"$T/out" 2>"$T/err"; then
	ok
else
	no "make uninstall: $(head -3 "$T/err")"
fi
left=$(find "$P" -type f ! -path "$P/bin/other")
[ -z "$left" ] && ok || no "left after uninstall: $(echo $left | head -c 200)"
[ "$(cat "$P/bin/other" 2>/dev/null)" = "not loft's" ] && ok ||
    no "uninstall removed a file it did not install"
rm -rf "$P"

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
