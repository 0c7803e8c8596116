#!/bin/sh
# run.sh: loftplot -i's page in headless Chromium (tests/browser/page.js,
# puppeteer-core from npm into bin/node_modules), run from the top of
# the tree; the last line is "browser: N passed, M failed".
#   sh tests/browser/run.sh          the tests (make check)
#   sh tests/browser/run.sh bench    the time per drag (make bench-page)
# Each missing peer skips the whole with one line: the module (no
# WebAssembly toolchain), chromium, node, or npm's puppeteer-core.
mode=${1:-check}
B=${LOFT_BIN:-bin}
T=bin/test/browser
CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
NODE_DIR=$(pwd)/bin
export B CHROMIUM NODE_DIR

skip() { echo "browser: skip: $*"; echo "browser: 0 passed, 0 failed"
	exit 0; }

[ -s bin/wasm/loft.wasm ] ||
    skip "no WebAssembly module (make with clang, lld, wasi-libc)"
[ -x "$CHROMIUM" ] || skip "no $CHROMIUM"
command -v node >/dev/null 2>&1 || skip "no node"
if [ ! -d bin/node_modules/puppeteer-core ]; then
	command -v npm >/dev/null 2>&1 || skip "no npm for puppeteer-core"
	(cd bin && npm install --no-save --no-audit --no-fund --prefix . \
	    puppeteer-core >/dev/null 2>&1) ||
	    skip "npm could not install puppeteer-core"
fi
rm -rf "$T" && mkdir -p "$T" || exit 2
if [ "$mode" = bench ]; then
	node tests/browser/page.js bench "$T"
	exit
fi
node tests/browser/page.js check "$T" >"$T/log" 2>&1
grep '^FAIL' "$T/log" >&2
grep -v '^ok\|^FAIL' "$T/log" | head -20 >&2
pass=$(grep -c '^ok' "$T/log")
fail=$(grep -c '^FAIL' "$T/log")
[ "$pass" -gt 0 ] || fail=$((fail + 1))
echo "browser: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
