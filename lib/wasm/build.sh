#!/bin/sh
# build.sh CC OUT SRC...: the WebAssembly module of loftplot -i (issue
# 27) at OUT, from the library's sources SRC (lib/*.c), the programs
# the page runs (cmd/splinefit.c, cmd/patchdrag.c, cmd/loftplot.c, each
# with its main renamed) and lib/wasm/loftwasm.c, by CC for wasm32-wasi
# (Debian: clang, lld, wasi-libc, libclang-rt-14-dev-wasm32).  Without
# that toolchain it says so in one line; the Makefile then
# builds loftplot without the module.  Exit status 0, 3 when there is
# no toolchain, 1 when the build failed.
cc=$1 out=$2
shift 2
dir=${out%/*}/obj
flags="--target=wasm32-wasi -Oz -mnontrapping-fptoint -msign-ext -std=c99
    -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Ilib"
mkdir -p "$dir" || exit 1
printf '#include <math.h>\nint main(void) { return (int)sqrt(4.0); }\n' \
    >"$dir/probe.c"
# shellcheck disable=SC2086
if ! "$cc" $flags -o "$dir/probe.wasm" "$dir/probe.c" 2>/dev/null; then
	echo "loftplot -i: no WebAssembly toolchain ($cc for wasm32-wasi:" \
	    "apt-get install clang lld wasi-libc libclang-rt-14-dev-wasm32)"
	exit 3
fi
objs=
for f in "$@" lib/wasm/loftwasm.c cmd/splinefit.c cmd/patchdrag.c \
    cmd/loftplot.c; do
	case $f in
	lib/approx.c | lib/outfiles.c) continue ;;  # splinefit -e, -O: not in the page
	esac
	b=${f##*/}
	b=${b%.c}
	case $f in
	cmd/*) o=$dir/cmd_$b.o; def=-Dmain=loft_main_$b ;;
	*) o=$dir/$b.o; def= ;;
	esac
	# shellcheck disable=SC2086
	"$cc" $flags $def -c -o "$o" "$f" || exit 1
	objs="$objs $o"
done
# shellcheck disable=SC2086
"$cc" --target=wasm32-wasi -mexec-model=reactor -Wl,--gc-sections \
    -Wl,--strip-all -o "$out" $objs -lm
