# loft: make builds bin/ and libloft.a; make check runs every test;
# make demo grades and fits the bundled insole; make figures draws the
# papers' figures; make bench times the programs against GNU spline
# (tests/bench/run.sh); make install PREFIX=... installs, and make
# uninstall PREFIX=... removes what it installed; make examples makes
# the example files of man/examples again.

CC      = cc
CFLAGS  = -O2 -g
LOFT_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Ilib
LDLIBS  = -lm
PREFIX  = /usr/local
DESTDIR =

PROGS   = splinefit sample bezapprox patchnew patchsplit patchdrag patchjoin \
          loftplot grade offset measure tocad patchloft patchcut fromcad
LIBOBJ  = bin/obj/num.o bin/obj/stream.o bin/obj/run.o bin/obj/cubic.o \
          bin/obj/fit.o bin/obj/cspline.o bin/obj/curve.o \
          bin/obj/expr.o bin/obj/bezier.o bin/obj/normal.o \
          bin/obj/quartic.o bin/obj/patch.o bin/obj/surface.o bin/obj/dtoa.o \
          bin/obj/grade.o bin/obj/outfiles.o \
          bin/obj/offset.o \
          bin/obj/bernstein.o bin/obj/arclen.o bin/obj/measure.o \
          bin/obj/flatten.o bin/obj/merge.o bin/obj/fair.o \
          bin/obj/skin.o bin/obj/cut.o bin/obj/cadread.o \
          bin/obj/dxfread.o bin/obj/svgread.o bin/obj/csvread.o
LIBOBJ += bin/obj/error.o bin/obj/grow.o bin/obj/record.o \
          bin/obj/knots.o bin/obj/design.o bin/obj/types.o
LIBOBJ += $(CADOBJ)
# the program layer (loftprog.h; the CAD writers in CADOBJ are on it
# too); every other module is the core and includes only loft.h
PROGOBJ = bin/obj/stream.o bin/obj/run.o bin/obj/outfiles.o \
          bin/obj/design.o $(CADINOBJ) $(CADOBJ)
CADINOBJ = bin/obj/cadread.o bin/obj/dxfread.o bin/obj/svgread.o \
          bin/obj/csvread.o
LIBOBJ += bin/obj/approx.o bin/obj/cholesky.o
LIBOBJ += bin/obj/straight.o
CADOBJ  = bin/obj/bezform.o bin/obj/cad.o bin/obj/dxf.o bin/obj/svgcad.o \
          bin/obj/step.o bin/obj/iges.o bin/obj/stl.o bin/obj/obj.o \
          bin/obj/svgplot.o
# PROGS is the one list of programs: their binaries and pages follow
# from it (a program is cmd/NAME.c and man/NAME.1).
BINS    = $(PROGS:%=bin/%)
TESTS   = bin/test/unit bin/test/paper bin/test/patch bin/test/bezier \
          bin/test/numtest bin/test/pow10gen bin/test/offsetref \
          bin/test/hostile bin/test/oom.so bin/test/arclen \
          bin/test/cad
BENCH   = bin/bench/gen bin/bench/floor bin/bench/timeit bin/bench/tandiff \
          bin/bench/numbers
BENCH  += bin/test/noisy
TESTS  += bin/test/noisy bin/test/nearest
TESTS  += bin/test/straight
LIB     = bin/libloft.a
MAN1    = $(PROGS:%=man/%.1)
MAN5    = man/loft.5
MAN7    = man/loft.7
# the example files the pages' EXAMPLES name, installed to
# share/loft/examples (man/examples/README says what each is)
EXAMPLES = $(addprefix man/examples/,README knots toe.knots insole.knots \
          arc.knots hull.knots seam.knots insole.dxf many-insoles.knots \
          v0.knots v1.knots u0.knots u1.knots hull.patch split.patch \
          pieces.patch hull.design noisy-insole.pts)
EXDIR   = $(DESTDIR)$(PREFIX)/share/loft/examples

all: $(BINS) $(LIB)

bin/obj/.dir bin/test/.dir bin/bench/.dir:
	mkdir -p $(@D) && touch $@

bin/obj/%.o: lib/%.c lib/loft.h lib/internal.h bin/obj/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -c -o $@ $<

bin/obj/dtoa.o: lib/pow10.h
bin/obj/run.o: lib/version.h
$(CADOBJ) bin/tocad bin/sample bin/test/cad: lib/loftcad.h
$(PROGOBJ): lib/loftprog.h
$(CADINOBJ) bin/test/numtest: lib/cadread.h

$(LIB): $(LIBOBJ)
	rm -f $@
	ar rcs $@ $(LIBOBJ)

bin/%: cmd/%.c $(LIB) lib/loft.h lib/loftprog.h
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

bin/test/%: tests/%.c tests/check.h $(LIB) lib/loft.h lib/loftprog.h \
    bin/test/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

bin/test/oom.so: tests/oom.c bin/test/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -shared -fPIC -o $@ tests/oom.c

bin/bench/%: tests/bench/%.c $(LIB) lib/loft.h lib/loftprog.h \
    bin/bench/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

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
# noisy outlines, the table of issue 14 (skipped without scipy)
compare-approx: all bin/test/noisy
	@if /usr/bin/python3 -c 'import scipy, numpy' 2>/dev/null; then \
	    /usr/bin/python3 tests/bench/approx_scipy.py; else \
	    echo "compare-approx: skipped (no /usr/bin/python3 with scipy)"; fi
	@if /usr/bin/python3 tests/glyphs.py bin/bench/g.knots bin/bench/g.truth \
	    100 2>/dev/null && [ -s bin/bench/g.truth ]; then /usr/bin/python3 \
	    tests/bench/glyphs_noisy.py bin/bench/g.truth bin/bench; else \
	    echo "compare-approx: glyphs skipped (no fontTools or fonts)"; fi
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
	rm -f $(addprefix $(DESTDIR)$(PREFIX)/bin/,$(notdir $(BINS))) \
	    $(DESTDIR)$(PREFIX)/lib/$(notdir $(LIB)) \
	    $(DESTDIR)$(PREFIX)/include/loft.h \
	    $(DESTDIR)$(PREFIX)/include/loftprog.h \
	    $(DESTDIR)$(PREFIX)/include/loftcad.h \
	    $(addprefix $(DESTDIR)$(PREFIX)/share/man/man1/,$(notdir $(MAN1))) \
	    $(addprefix $(DESTDIR)$(PREFIX)/share/man/man5/,$(notdir $(MAN5))) \
	    $(addprefix $(DESTDIR)$(PREFIX)/share/man/man7/,$(notdir $(MAN7))) \
	    $(addprefix $(EXDIR)/,$(notdir $(EXAMPLES)))
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

# make -j clean all: clean must finish before anything is built (it ran
# beside the build and removed bin/ under ar); GNU make runs goals in
# order only when not parallel, so with clean among them it is not.
ifneq ($(filter clean,$(MAKECMDGOALS)),)
.NOTPARALLEL:
endif

.PHONY: all check check-quick bench compare demo figures install uninstall clean examples
.SECONDARY:

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
	@(cd $(SAN_DIR) && \
	    ASAN_OPTIONS=log_path=$(CURDIR)/$(SAN_DIR)/log/asan:detect_leaks=1 \
	    UBSAN_OPTIONS=log_path=$(CURDIR)/$(SAN_DIR)/log/ubsan:print_stacktrace=1 \
	    $(MAKE) CC="$(CC)" CFLAGS="$(SAN_CFLAGS)" check); rc=$$?; \
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
	        "$(VALGRIND)" "$(VG_OPTS)" "$(CURDIR)/$(VG_DIR)/log" "$$p" \
	        "$(CURDIR)/bin/$$p" >$(VG_DIR)/$$p && chmod +x $(VG_DIR)/$$p \
	        || exit 1; \
	done; \
	LOFT_BIN=$(VG_DIR) LOFT_BIG_KNOTS=20000 sh tests/run.sh; rc=$$?; \
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
          patchjoin loftplot grade offset measure patchloft patchcut fromcad
LIBSRC  = $(LIBOBJ:bin/obj/%.o=lib/%.c)

bin/fuzz/%: tests/fuzz/%.c tests/fuzz/fuzz.h $(LIBSRC) lib/loft.h \
    lib/loftprog.h lib/loftcad.h lib/cadread.h lib/internal.h \
    $(PROGS:%=cmd/%.c)
	@mkdir -p bin/fuzz
	$(FUZZ_CC) $(LOFT_CFLAGS) $(FUZZ_CFLAGS) -o $@ $< $(LIBSRC) $(LDLIBS)

fuzz:
	@if ! command -v $(FUZZ_CC) >/dev/null 2>&1; then \
	    echo "fuzz: skipped: no $(FUZZ_CC) for -fsanitize=fuzzer"; exit 0; fi; \
	$(MAKE) $(FUZZERS:%=bin/fuzz/%) || exit 1; \
	for f in $(FUZZERS); do \
	    mkdir -p bin/fuzz/corpus/$$f && \
	    echo "fuzz: $$f for $(FUZZ_SECONDS) s" && \
	    bin/fuzz/$$f -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	        -dict=tests/fuzz/loft.dict -artifact_prefix=bin/fuzz/$$f- \
	        -print_final_stats=1 \
	        bin/fuzz/corpus/$$f tests/fuzz/corpus/$$f 2>bin/fuzz/$$f.log; \
	    rc=$$?; grep -E '^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss)' \
	        bin/fuzz/$$f.log; \
	    if [ $$rc -ne 0 ]; then tail -40 bin/fuzz/$$f.log; \
	        echo "fuzz: $$f failed: see bin/fuzz/$$f.log"; exit 1; fi; \
	done

.PHONY: check-san check-valgrind fuzz
