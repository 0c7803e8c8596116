#!/bin/sh
# glyphs_held.sh: make compare-approx's second glyph table, run from the
# top of the tree: splinefit -e on noisy contours of typefaces from
# other packages than the corpus's (DejaVu Sans, Liberation Serif
# Italic, URW Bookman Light, URW Z003; 25 contours each, read by
# tests/glyphs.py), by tests/bench/glyphs_noisy.py as the first table.
# The rules of lib/corners.c were made on the first table's faces; this
# one says how they hold on faces drawn otherwise: sans serif stroke
# ends, italic serifs, a script.  A face that is missing is left out,
# and the table skipped with one line where none is found.
W=bin/bench
P=/usr/bin/python3
F=/usr/share/fonts
if ! $P -c 'import fontTools, scipy' 2>/dev/null; then
	echo "compare-approx: held-out faces skipped (no /usr/bin/python3" \
	    "with fontTools and scipy)"
	exit 0
fi
: >$W/gh.knots
: >$W/gh.truth
for f in truetype/dejavu/DejaVuSans.ttf \
    truetype/liberation/LiberationSerif-Italic.ttf \
    opentype/urw-base35/URWBookman-Light.otf \
    opentype/urw-base35/Z003-MediumItalic.otf; do
	[ -f "$F/$f" ] &&
	    $P tests/glyphs.py $W/gh1.knots $W/gh1.truth 25 "$F/$f" 2>/dev/null &&
	    cat $W/gh1.knots >>$W/gh.knots && cat $W/gh1.truth >>$W/gh.truth
done
if [ ! -s $W/gh.truth ]; then
	echo "compare-approx: held-out faces skipped (none of DejaVu Sans," \
	    "Liberation Serif Italic, URW Bookman, URW Z003 found)"
	exit 0
fi
echo
echo "held-out faces (DejaVu Sans, Liberation Serif Italic, URW Bookman" \
    "Light, URW Z003; 25 contours each):"
$P tests/bench/glyphs_noisy.py $W/gh.truth $W $W/gh.knots
