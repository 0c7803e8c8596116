#!/bin/sh
# install.sh: make install into a temporary PREFIX puts every program,
# the library, its header, every page and the example files where they
# belong, each a copy of the file in the tree, and every installed
# page's examples run with the installed programs in a copy of the
# installed examples (tests/examples.sh -i); make uninstall then removes
# exactly those files: none of them is left, nor share/loft, and a file
# of someone else's beside them stays.  The list of what should be there is made here from the tree
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
# the example files: each a copy of the tree's, every one that
# man/examples/README lists, and nothing else
E=$P/share/loft/examples
listed=$(sed -n 's/^\([A-Za-z0-9][-A-Za-z0-9._]*\)  .*/\1/p' man/examples/README)
k=0
for f in README $listed; do
	k=$((k + 1))
	cmp -s "man/examples/$f" "$E/$f" && ok ||
	    no "share/loft/examples/$f is not a copy of man/examples/$f"
done
[ "$k" -ge 10 ] && ok || no "only $k example files listed"
got=$(find "$P/share/loft" -type f | wc -l)
[ "$got" -eq "$k" ] && ok || no "installed $got example files, want $k"
# every installed page's examples, run with the installed programs in a
# copy of the installed example files
if sh tests/examples.sh -i "$P" >"$T/ex" 2>&1; then
	ok
else
	no "the installed pages' examples: $(grep -v '^skip' "$T/ex" | head -5)"
fi
if MAKEFLAGS= MFLAGS= make -s uninstall PREFIX="$P" >"$T/out" 2>"$T/err"; then
	ok
else
	no "make uninstall: $(head -3 "$T/err")"
fi
left=$(find "$P" -type f ! -path "$P/bin/other")
[ -z "$left" ] && ok || no "left after uninstall: $(echo $left | head -c 200)"
[ ! -d "$P/share/loft" ] && ok || no "uninstall left share/loft"
[ "$(cat "$P/bin/other" 2>/dev/null)" = "not loft's" ] && ok ||
    no "uninstall removed a file it did not install"
rm -rf "$P"

# without a WebAssembly toolchain (a compiler that is not there), the
# page is built without its module, with one line that says so, and
# make goes on: the Makefile is .POSIX, so make runs recipes with sh -e
# (in a copy of the tree, so this tree's module stays)
W=$T/nowasm
rm -rf "$W" && mkdir -p "$W" && cp -R Makefile lib cmd "$W/"
if (cd "$W" && MAKEFLAGS= MFLAGS= make -s WASM_CC=./no-such-cc \
    bin/wasm/page.o) >"$T/out" 2>"$T/err"; then
	ok
else
	no "make without a wasm toolchain: $(tail -2 "$T/err")"
fi
[ -f "$W/bin/wasm/page.o" ] && [ ! -s "$W/bin/wasm/loft.wasm" ] && ok ||
    no "without a wasm toolchain: no page.o, or a module"
[ "$(grep -c 'no WebAssembly toolchain' "$T/out" "$T/err" |
    awk -F: '{ n += $2 } END { print n }')" -eq 1 ] && ok ||
    no "without a wasm toolchain: not one line that says so"
rm -rf "$W"

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
