# loft: make builds bin/ and libloft.a; make check runs every test;
# make demo grades and fits the bundled insole; make figures draws the
# papers' figures; make bench times the programs against GNU spline
# (tests/bench/run.sh); make install PREFIX=... installs, and make
# uninstall PREFIX=... removes what it installed; make examples makes
# the example files of man/examples again.
#
# POSIX make (GNU make and bmake both run it, -j too): suffix rules make
# each object beside its source (lib/NAME.o from lib/NAME.c), one rule
# links the programs into bin/, another the tests into bin/test.  To
# add a program: one word in PROGS; a library module: one word in the
# object list of its layer.  make -j clean all removes under a build:
# make clean first, then make -j.

.POSIX:
.SUFFIXES:
.SUFFIXES: .c .o

CC      = cc
CFLAGS  = -O2 -g
LOFT_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Ilib
LDLIBS  = -lm
PREFIX  = /usr/local
DESTDIR =

# PROGS is the one list of programs: their binaries and pages follow
# from it (a program is cmd/NAME.c and man/NAME.1).
PROGS   = splinefit sample bezapprox patchnew patchsplit patchdrag patchjoin \
          loftplot grade offset measure tocad patchloft patchcut fromcad \
          unroll hydro offsets

# The library's objects, by layer.  The core (lib/loft.h; each includes
# only loft.h and internal.h, never a FILE):
COREOBJ = lib/num.o lib/cubic.o lib/fit.o lib/cspline.o lib/curve.o \
          lib/expr.o lib/bezier.o lib/normal.o lib/quartic.o lib/patch.o \
          lib/surface.o lib/dtoa.o lib/grade.o lib/offset.o \
          lib/bernstein.o lib/arclen.o lib/measure.o lib/flatten.o \
          lib/merge.o lib/fair.o lib/skin.o lib/cut.o lib/error.o \
          lib/grow.o lib/record.o lib/knots.o lib/types.o lib/approx.o \
          lib/cholesky.o lib/bezform.o lib/grid.o lib/labels.o lib/bspline.o \
          lib/mesh.o lib/sparse.o lib/unroll.o lib/surfmeasure.o \
          lib/waterline.o lib/hydro.o lib/straight.o \
          lib/corners.o
# the program layer (lib/loftprog.h): streams, the run loop, designs
PROGOBJ = lib/stream.o lib/run.o lib/outfiles.o lib/design.o \
          lib/surfrecs.o lib/optrange.o
# the CAD output formats (lib/loftcad.h): the document protocol, the
# format table, one module a format, and loftplot's picture
CADOBJ  = lib/cad.o lib/cadformats.o lib/dxf.o lib/svgcad.o lib/step.o \
          lib/iges.o lib/stl.o lib/obj.o lib/svgplot.o lib/cadlimit.o \
          lib/sewing.o
# the CAD readers (lib/cadread.h): what they share, their table, one
# module a reader
CADINOBJ = lib/cadread.o lib/cadreaders.o lib/dxfread.o lib/svgread.o \
          lib/csvread.o lib/bsplineread.o lib/stepread.o lib/igesread.o
LIBOBJ  = $(COREOBJ) $(PROGOBJ) $(CADOBJ) $(CADINOBJ)
LIB     = bin/libloft.a
# loftplot's page (loftplot -i), below
WASM_CC  = clang
WASMSRC  = $(LIBOBJ:.o=.c)
PAGEOBJ  = bin/wasm/page.o lib/wasm/pageout.o
PAGELIB  = bin/libloftpage.a

BINS    = $(PROGS:%=bin/%)
CMDOBJ  = $(PROGS:%=cmd/%.o)
# the test programs, tests/NAME.c each, linked into bin/test
TESTPROGS = unit paper patch bezier numtest pow10gen offsetref hostile \
          arclen cad noisy nearest tables grid bspline sparse straight
TESTOBJ = $(TESTPROGS:%=tests/%.o)
TESTS   = $(TESTPROGS:%=bin/test/%) bin/test/oom.so bin/test/line/progs
BENCHPROGS = gen floor timeit tandiff numbers
BENCHOBJ = $(BENCHPROGS:%=tests/bench/%.o)
BENCH   = $(BENCHPROGS:%=bin/bench/%) bin/test/noisy
MAN1    = $(PROGS:%=man/%.1)
MAN5    = man/loft.5
MAN7    = man/loft.7
# the example files the pages' EXAMPLES name, installed to
# share/loft/examples (man/examples/README says what each is)
EXNAMES = README knots toe.knots insole.knots arc.knots hull.knots \
          seam.knots insole.dxf many-insoles.knots v0.knots v1.knots \
          u0.knots u1.knots hull.patch split.patch pieces.patch \
          hull.design noisy-insole.pts hull.offsets
EXAMPLES = $(EXNAMES:%=man/examples/%)
EXDIR   = $(DESTDIR)$(PREFIX)/share/loft/examples

all: $(BINS) $(LIB)

.c.o:
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -c -o $@ $<

# what each object reads besides its source
$(LIBOBJ) $(CMDOBJ) $(TESTOBJ) $(BENCHOBJ) tests/linetype.o: lib/loft.h
$(LIBOBJ) tests/linetype.o tests/unit.o: lib/internal.h
$(PROGOBJ) $(CADOBJ) $(CADINOBJ) $(CMDOBJ) $(TESTOBJ) $(BENCHOBJ): \
    lib/loftprog.h
$(CADOBJ) cmd/tocad.o cmd/sample.o cmd/loftplot.o tests/cad.o \
    tests/tables.o: lib/loftcad.h
$(CADINOBJ) tests/numtest.o: lib/cadread.h
$(TESTOBJ): tests/check.h
lib/dtoa.o: lib/pow10.h
lib/run.o: lib/version.h

$(LIB): $(LIBOBJ)
	@mkdir -p bin
	rm -f $@
	ar rcs $@ $(LIBOBJ)

# each program from its object, bin/NAME from cmd/NAME.o (relinking
# them all when one changes costs a link each, no compiling); only
# loftplot takes anything from $(PAGELIB), its page
$(BINS): $(CMDOBJ) $(LIB) $(PAGELIB)
	@mkdir -p bin
	$(CC) $(CFLAGS) -o $@ cmd/`basename $@`.o $(PAGELIB) $(LIB) $(LDLIBS)

# loftplot -i (issue 27): loftplot carries its page, made into C by
# lib/wasm/embed.c from lib/wasm/page.html and the WebAssembly module of
# lib/wasm/build.sh (loft's programs built by clang for wasm32-wasi;
# build.sh leaves out the modules the page does not run).  Without that
# toolchain build.sh says so in a line and the page is made with no
# module: loftplot -i then says how to get one.

$(PAGELIB): $(PAGEOBJ)
	rm -f $@
	ar rcs $@ $(PAGEOBJ)

bin/wasm/embed: lib/wasm/embed.c
	@mkdir -p bin/wasm
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ lib/wasm/embed.c

bin/wasm/loft.wasm: $(WASMSRC) lib/wasm/loftwasm.c lib/wasm/build.sh \
    cmd/splinefit.c cmd/patchdrag.c cmd/loftplot.c lib/loft.h \
    lib/loftprog.h lib/loftcad.h lib/internal.h lib/wasm/page.h
	@mkdir -p bin/wasm
	rm -f $@
	@rc=0; sh lib/wasm/build.sh $(WASM_CC) $@ $(WASMSRC) || rc=$$?; \
	    if [ $$rc -eq 3 ]; then : >$@; else exit $$rc; fi

bin/wasm/page.c: bin/wasm/embed lib/wasm/page.html bin/wasm/loft.wasm
	if [ -s bin/wasm/loft.wasm ]; then \
	    bin/wasm/embed lib/wasm/page.html bin/wasm/loft.wasm >$@; else \
	    bin/wasm/embed lib/wasm/page.html >$@; fi

bin/wasm/page.o: bin/wasm/page.c lib/wasm/page.h
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -c -o $@ bin/wasm/page.c

lib/wasm/pageout.o: lib/wasm/pageout.c lib/wasm/page.h lib/loftprog.h \
    lib/loft.h

# make bench-page: the page's time per drag of a knot of 100 with the
# comb (refit and redraw, by performance.now() in headless Chromium);
# skipped without the module, chromium or puppeteer-core
bench-page: all
	@sh tests/browser/run.sh bench

$(TESTPROGS:%=bin/test/%): $(TESTOBJ) $(LIB)
	@mkdir -p bin/test
	$(CC) $(CFLAGS) -o $@ tests/`basename $@`.o $(LIB) $(LDLIBS)

bin/test/oom.so: tests/oom.c
	@mkdir -p bin/test
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -shared -fPIC -o $@ tests/oom.c

# every program again with one more record type, tests/linetype.c's
# degree-1 `line` (tests/linetype.sh): types.c built with its row
bin/test/line/types.o: lib/types.c lib/loft.h lib/internal.h
	@mkdir -p bin/test/line
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -DLOFT_TEST_LINE -c -o $@ lib/types.c
bin/test/line/progs: bin/test/line/types.o tests/linetype.o $(CMDOBJ) $(LIB) \
    $(PAGELIB)
	for p in $(PROGS); do $(CC) $(CFLAGS) -o bin/test/line/$$p \
	    cmd/$$p.o tests/linetype.o bin/test/line/types.o $(PAGELIB) $(LIB) \
	    $(LDLIBS) || exit 1; done
	touch $@

$(BENCHPROGS:%=bin/bench/%): $(BENCHOBJ) $(LIB)
	@mkdir -p bin/bench
	$(CC) $(CFLAGS) -o $@ tests/bench/`basename $@`.o $(LIB) $(LDLIBS)

check: all $(TESTS)
	@sh tests/run.sh

# make check-quick: the quick tier of make check for the edit-compile-test
# loop (tests/run.sh, QUICK: the suites it runs with "suite"), well under
# 15 s; make check before a commit.
check-quick: all $(TESTS)
	@QUICK=1 sh tests/run.sh

bench: all $(BENCH)
	@sh tests/bench/run.sh

# make compare: splinefit's curves beside Manning's, the chord spline's,
# Hobby's and (with libspiro) Spiro's on uneven closed knots (issue 13)
compare: all
	@sh tests/bench/compare.sh

# make compare-approx: splinefit -e beside scipy's smoothing spline on 60
# noisy outlines, the table of issue 14 (skipped without scipy); then
# beside potrace on noisy glyph contours of the corpus's faces, and of
# four faces held out (tests/bench/glyphs_held.sh), issue 23's tables
compare-approx: all bin/test/noisy
	@if /usr/bin/python3 -c 'import scipy, numpy' 2>/dev/null; then \
	    /usr/bin/python3 tests/bench/approx_scipy.py; else \
	    echo "compare-approx: skipped (no /usr/bin/python3 with scipy)"; fi
	@mkdir -p bin/bench
	@if /usr/bin/python3 tests/glyphs.py bin/bench/g.knots bin/bench/g.truth \
	    100 2>/dev/null && [ -s bin/bench/g.truth ]; then /usr/bin/python3 \
	    tests/bench/glyphs_noisy.py bin/bench/g.truth bin/bench \
	    bin/bench/g.knots; else \
	    echo "compare-approx: glyphs skipped (no fontTools or fonts)"; fi
	@sh tests/bench/glyphs_held.sh
.PHONY: compare-approx

demo: all
	bin/grade -r -3:4 man/figures/insole.knots | bin/splinefit | \
	    bin/loftplot -l size > bin/insoles.svg
	@echo "demo: wrote $$(pwd)/bin/insoles.svg: the insole of" \
	    "man/figures/insole.knots graded into 8 sizes, -3 to +4, each fitted"

figures: all
	$(MAKE) -C man/figures

install: all
	mkdir -p $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib \
	    $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(PREFIX)/share/man/man5 \
	    $(DESTDIR)$(PREFIX)/share/man/man7 $(EXDIR)
	cp $(BINS) $(DESTDIR)$(PREFIX)/bin/
	cp $(LIB) $(DESTDIR)$(PREFIX)/lib/
	cp lib/loft.h lib/loftprog.h lib/loftcad.h $(DESTDIR)$(PREFIX)/include/
	cp $(MAN1) $(DESTDIR)$(PREFIX)/share/man/man1/
	cp $(MAN5) $(DESTDIR)$(PREFIX)/share/man/man5/
	cp $(MAN7) $(DESTDIR)$(PREFIX)/share/man/man7/
	cp $(EXAMPLES) $(EXDIR)/

# the files install copies, by name, and nothing else (the directories
# stay: they may hold other things, and may have been there before;
# but share/loft/examples and share/loft are loft's, gone when empty)
uninstall:
	rm -f $(PROGS:%=$(DESTDIR)$(PREFIX)/bin/%) \
	    $(DESTDIR)$(PREFIX)/lib/libloft.a \
	    $(DESTDIR)$(PREFIX)/include/loft.h \
	    $(DESTDIR)$(PREFIX)/include/loftprog.h \
	    $(DESTDIR)$(PREFIX)/include/loftcad.h \
	    $(PROGS:%=$(DESTDIR)$(PREFIX)/share/man/man1/%.1) \
	    $(DESTDIR)$(PREFIX)/share/man/man5/loft.5 \
	    $(DESTDIR)$(PREFIX)/share/man/man7/loft.7 \
	    $(EXNAMES:%=$(EXDIR)/%)
	rmdir $(EXDIR) $(DESTDIR)$(PREFIX)/share/loft 2>/dev/null || :

# make examples: the example files made again, copies of man/figures'
# and what loft's programs make of them (the hand-written ones, which
# man/examples/README names, are sources).  They are committed, and
# tests/examples.sh checks them against what this makes in a scratch
# directory (MKEX=dir).
MKEX    = man/examples
EXBIN   = bin
examples: all
	mkdir -p $(MKEX)
	cp man/figures/insole.knots man/figures/arc.knots \
	    man/figures/hull.knots man/figures/insole.dxf \
	    man/figures/noisy-insole.pts $(MKEX)/
	cp man/figures/manning-fig14.knots $(MKEX)/seam.knots
	$(EXBIN)/grade -r -3:4 -m man/figures/insole.knots \
	    >$(MKEX)/many-insoles.knots
	$(EXBIN)/patchnew -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 >$(MKEX)/hull.patch
	$(EXBIN)/patchsplit -u 0.4 $(MKEX)/hull.patch >$(MKEX)/split.patch
	$(EXBIN)/patchnew -i 1 -c 0,0,0 -c 4,0,0 -c 0,3,0 -c 4,3,1 \
	    >$(MKEX)/pieces.patch
	$(EXBIN)/patchnew -i 2 -c 4.05,0,0.1 -c 8,0,0 -c 4,3.1,1 -c 8,3,2 \
	    >>$(MKEX)/pieces.patch
	$(EXBIN)/splinefit -o man/figures/hull.knots | $(EXBIN)/patchloft \
	    >$(MKEX)/hull.design

clean:
	rm -rf bin
	rm -f lib/*.o lib/wasm/*.o cmd/*.o tests/*.o tests/bench/*.o

.PHONY: all check check-quick bench compare demo figures install uninstall clean examples
.PHONY: bench-page

# ---- reliability (issue 6): sanitizers, valgrind, fuzzing ---------------
# Each covers the programs in PROGS and the harnesses in FUZZERS.

# make check-san: the whole of make check, built with AddressSanitizer and
# UndefinedBehaviorSanitizer in a copy of the tree under bin/san (its
# objects never mix with the normal build).  Reports go to bin/san/log;
# any report fails the target, even one from a run whose test passed.
SAN_CFLAGS = -O1 -g -fno-omit-frame-pointer \
             -fsanitize=address,undefined,float-cast-overflow \
             -fno-sanitize-recover=all
SAN_DIR = bin/san

check-san:
	rm -rf $(SAN_DIR) && mkdir -p $(SAN_DIR)/log
	cp -R Makefile lib cmd tests man $(SAN_DIR)/
	@top=$$(pwd); rc=0; (cd $(SAN_DIR) && $(MAKE) clean >/dev/null && \
	    ASAN_OPTIONS=log_path=$$top/$(SAN_DIR)/log/asan:detect_leaks=1 \
	    UBSAN_OPTIONS=log_path=$$top/$(SAN_DIR)/log/ubsan:print_stacktrace=1 \
	    $(MAKE) CC="$(CC)" CFLAGS="$(SAN_CFLAGS)" check) || rc=$$?; \
	if ls $(SAN_DIR)/log | grep -q .; then head -60 $(SAN_DIR)/log/*; \
	    echo "check-san: sanitizer reports in $(SAN_DIR)/log"; exit 1; fi; \
	[ $$rc -eq 0 ] && echo "check-san: no sanitizer reports"; exit $$rc

# make check-valgrind: the test suites with every program in PROGS run by
# memcheck (tests/*.sh call the programs through $LOFT_BIN); any error or
# leak in a program's log fails the target.  Skipped without valgrind.
VALGRIND = valgrind
VG_DIR  = bin/vg
VG_OPTS = -q --error-exitcode=99 --leak-check=full \
          --errors-for-leak-kinds=definite,indirect,possible \
          --show-leak-kinds=definite,indirect,possible

check-valgrind: all $(TESTS)
	@if ! command -v $(VALGRIND) >/dev/null 2>&1; then \
	    echo "check-valgrind: skipped: no $(VALGRIND) on PATH"; exit 0; fi; \
	rm -rf $(VG_DIR) && mkdir -p $(VG_DIR)/log && \
	for p in $(PROGS); do \
	    printf '#!/bin/sh\nexec %s %s --log-file=%s/%%p.%s "%s" "$$@"\n' \
	        "$(VALGRIND)" "$(VG_OPTS)" "$$(pwd)/$(VG_DIR)/log" "$$p" \
	        "$$(pwd)/bin/$$p" >$(VG_DIR)/$$p && chmod +x $(VG_DIR)/$$p \
	        || exit 1; \
	done; \
	rc=0; LOFT_BIN=$(VG_DIR) LOFT_BIG_KNOTS=20000 sh tests/run.sh || rc=$$?; \
	bad=$$(find $(VG_DIR)/log -type f -size +0 | wc -l); \
	if [ "$$bad" -gt 0 ]; then cat $$(find $(VG_DIR)/log -type f -size +0); \
	    echo "check-valgrind: $$bad runs with memcheck errors"; exit 1; fi; \
	echo "check-valgrind: $$(ls $(VG_DIR)/log | wc -l) program runs," \
	    "no memcheck errors"; exit $$rc

# make fuzz FUZZ_SECONDS=N: each libFuzzer harness of tests/fuzz for N
# seconds in one process (one core), starting from its corpus tests/fuzz/corpus/NAME;
# what it learns goes to bin/fuzz/corpus/NAME, crashes to bin/fuzz/.
# Needs clang (-fsanitize=fuzzer); skipped without it.
FUZZ_CC      = clang
FUZZ_SECONDS = 60
FUZZ_CFLAGS  = -O1 -g -fno-omit-frame-pointer -DLOFT_FUZZ \
               -fsanitize=fuzzer,address,undefined,float-cast-overflow \
               -fno-sanitize-recover=all -Wno-unused-function
FUZZERS = stream splinefit sample bezapprox patchnew patchsplit patchdrag \
          patchjoin loftplot grade offset measure patchloft patchcut fromcad \
          unroll hydro offsets
LIBSRC  = $(LIBOBJ:.o=.c)

fuzz:
	@if ! command -v $(FUZZ_CC) >/dev/null 2>&1; then \
	    echo "fuzz: skipped: no $(FUZZ_CC) for -fsanitize=fuzzer"; exit 0; fi; \
	mkdir -p bin/fuzz && for f in $(FUZZERS); do \
	    echo "fuzz: building bin/fuzz/$$f" && \
	    $(FUZZ_CC) $(LOFT_CFLAGS) $(FUZZ_CFLAGS) -o bin/fuzz/$$f \
	        tests/fuzz/$$f.c $(LIBSRC) $(LDLIBS) || exit 1; \
	done; \
	for f in $(FUZZERS); do \
	    mkdir -p bin/fuzz/corpus/$$f && \
	    echo "fuzz: $$f for $(FUZZ_SECONDS) s" && rc=0 && \
	    bin/fuzz/$$f -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	        -dict=tests/fuzz/loft.dict -artifact_prefix=bin/fuzz/$$f- \
	        -print_final_stats=1 \
	        bin/fuzz/corpus/$$f tests/fuzz/corpus/$$f 2>bin/fuzz/$$f.log \
	        || rc=$$?; grep -E '^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss)' \
	        bin/fuzz/$$f.log || :; \
	    if [ $$rc -ne 0 ]; then tail -40 bin/fuzz/$$f.log; \
	        echo "fuzz: $$f failed: see bin/fuzz/$$f.log"; exit 1; fi; \
	done

.PHONY: check-san check-valgrind fuzz
