# loft: make builds bin/ and libloft.a; make check runs every test;
# make demo grades and fits the bundled insole; make figures draws the
# papers' figures; make bench times the programs against GNU spline
# (tests/bench/run.sh); make install PREFIX=... installs.

CC      = cc
CFLAGS  = -O2 -g
LOFT_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Ilib
LDLIBS  = -lm
PREFIX  = /usr/local
DESTDIR =

PROGS   = splinefit sample bezapprox patchnew patchsplit patchdrag patchjoin \
          plot grade
LIBOBJ  = bin/obj/num.o bin/obj/stream.o bin/obj/run.o bin/obj/cubic.o \
          bin/obj/fit.o bin/obj/cspline.o bin/obj/curve.o \
          bin/obj/expr.o bin/obj/bezier.o bin/obj/normal.o \
          bin/obj/quartic.o bin/obj/patch.o bin/obj/surface.o bin/obj/dtoa.o
BINS    = bin/splinefit bin/sample bin/bezapprox bin/patchnew \
          bin/patchsplit bin/patchdrag bin/patchjoin bin/plot bin/grade
TESTS   = bin/test/unit bin/test/paper bin/test/patch bin/test/bezier \
          bin/test/numtest bin/test/pow10gen
BENCH   = bin/bench/gen bin/bench/floor bin/bench/timeit bin/bench/tandiff
LIB     = bin/libloft.a
MAN1    = man/splinefit.1 man/sample.1 man/bezapprox.1 man/patchnew.1 \
          man/patchsplit.1 man/patchdrag.1 man/patchjoin.1 man/plot.1 \
          man/grade.1
MAN5    = man/loft.5
MAN7    = man/loft.7

all: $(BINS) $(LIB)

bin/obj/.dir bin/test/.dir bin/bench/.dir:
	mkdir -p $(@D) && touch $@

bin/obj/%.o: lib/%.c lib/loft.h lib/internal.h bin/obj/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -c -o $@ $<

bin/obj/dtoa.o: lib/pow10.h

$(LIB): $(LIBOBJ)
	rm -f $@
	ar rcs $@ $(LIBOBJ)

bin/%: cmd/%.c $(LIB) lib/loft.h
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

bin/test/%: tests/%.c tests/check.h $(LIB) lib/loft.h bin/test/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

bin/bench/%: tests/bench/%.c $(LIB) lib/loft.h bin/bench/.dir
	$(CC) $(LOFT_CFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

check: all $(TESTS)
	@sh tests/run.sh

bench: all $(BENCH)
	@sh tests/bench/run.sh

demo: all
	bin/grade -s -3:4 man/figures/insole.knots | bin/splinefit | \
	    bin/plot -l size > bin/insoles.svg
	@echo "demo: wrote $$(pwd)/bin/insoles.svg: the insole of" \
	    "man/figures/insole.knots graded into 8 sizes, -3 to +4, each fitted"

figures: all
	$(MAKE) -C man/figures

install: all
	mkdir -p $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib \
	    $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(PREFIX)/share/man/man5 \
	    $(DESTDIR)$(PREFIX)/share/man/man7
	cp $(BINS) $(DESTDIR)$(PREFIX)/bin/
	cp $(LIB) $(DESTDIR)$(PREFIX)/lib/
	cp lib/loft.h $(DESTDIR)$(PREFIX)/include/
	cp $(MAN1) $(DESTDIR)$(PREFIX)/share/man/man1/
	cp $(MAN5) $(DESTDIR)$(PREFIX)/share/man/man5/
	cp $(MAN7) $(DESTDIR)$(PREFIX)/share/man/man7/

clean:
	rm -rf bin

.PHONY: all check bench demo figures install clean
.SECONDARY:
