#!/bin/sh
# units.sh: the units sweep (issue 28).  Every program, on its inputs
# scaled by s from 1e-300 to 1e300 (and its length options with them),
# must write its output at scale 1 with every number times s^p, p the
# number's dimension (1 a length, 2 an area, -1 a curvature, 0 a count
# or a parameter), or refuse clearly: exit 1, nothing written, and a
# message "PROG: ..." saying why.  Never a silently different number.
# Run from the top of the tree; the last line is "units: N passed, M
# failed".
#
# Tolerance: each number within REL of the largest number of its
# dimension in that output (REL 1e-9; 1e-5 for SVG, whose numbers have 4
# decimals): a wrong power of s, a lost digit of exponent, a count that
# changes, all fail it; rounding of a few hundred operations does not.
# Reference: the program's own output at scale 1, an independent run
# (invariance), never a stored value.

T=bin/test/units
. tests/lib.sh

SCALES=${UNITS_SCALES:-"1e-300 1e-200 1e-160 1e-80 1e80 1e160 1e200 1e300"}
refused=0

# scale S < FILE: the numbers of every row times S (headers, comments
# and blank lines kept)
scale() {
	awk -v s="$1" '/^[ \t]*(#|[A-Za-z])/ || NF == 0 { print; next }
	    { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * s); print }'
}
# scale_csv S < FILE: the same for CSV rows of numbers after a header
scale_csv() {
	awk -v s="$1" -F, -v OFS=, 'NR == 1 { print; next }
	    { for (i = 1; i <= NF; i++) $i = sprintf("%.17g", $i * s); print }'
}
# scale_dxf S < FILE: DXF values of coordinate groups (10-39) and of
# radii (40) times S
scale_dxf() {
	awk -v s="$1" 'NR % 2 == 1 { code = $1 + 0; print; next }
	    { if (code >= 10 && code <= 40) $0 = sprintf("%.17g", $1 * s)
	    print }'
}
# sc V: V times the current scale, for options that are lengths
sc() {
	awk -v v="$1" -v s="$S" 'BEGIN { printf "%.17g", v * s }'
}
# sc2 V: V times the scale squared (loftplot -C: a length times a length)
sc2() {
	awk -v v="$1" -v s="$S" 'BEGIN { printf "%.17g", v * s * s }'
}

# compare MODE S FILE1 FILES: FILES is FILE1 scaled by S, by MODE:
#   rows       numbers of rows power 1; header words equal, but for the
#              attributes error= (power 2), offset= and value= (1) and
#              su= (0), compared as numbers
#   cols:P...  column i of rows power P_i (measure's fields)
#   obj        OBJ: v lines power 1, the rest equal
#   stl        ASCII STL: vertex lines power 1, facet normals 0
#   svg        loftplot's picture, by compare_svg
compare() {
	[ "$1" = svg ] && { compare_svg "$2" "$3" "$4"; return; }
	awk -v mode="$1" -v s="$2" '
	function isnum(x) { return x ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ }
	function pw(x, p) {
		if (p == 1) return x * s
		if (p == 2) return x * s * s
		if (p == -1) return x / s
		return x
	}
	# token k of line l of file f, and its power (-9: compare as text)
	function power(f, l, k, tok,   w, kv) {
		w = f == 1 ? W1[l, 1] : W2[l, 1]
		if (mode == "svg") return tok ~ /^(width|height|version)=/ ? 0 : 1
		if (mode == "obj") return w == "v" ? 1 : w == "vn" ? 0 : -9
		if (mode == "stl") return w == "vertex" ? 1 : w == "facet" ? 0 : -9
		if (w ~ /^[A-Za-z]/) {          # a header
			if (split(tok, kv, "=") != 2 || !(kv[1] in AP)) return -9
			return AP[kv[1]]
		}
		if (mode ~ /^cols:/) return P[k]
		return 1
	}
	function value(tok,   kv) {
		if (split(tok, kv, "=") == 2) tok = kv[2]
		gsub(/^"|"$/, "", tok)
		return tok
	}
	BEGIN { if (mode ~ /^cols:/) { split(substr(mode, 6), P, ":") }
		# the numeric attributes of headers, by their power
		AP["error"] = 2; AP["offset"] = 1; AP["value"] = 1; AP["su"] = 0 }
	FNR == 1 { f++ }
	{
		n = split($0, t, " ")
		if (mode == "svg" && $0 !~ /^<[?]xml/) {
			n = 0; rest = $0
			gsub(/#[0-9A-Fa-f]+/, "#", rest)        # colours
			gsub(/"http[^"]*"/, "", rest)           # the namespace
			while (match(rest, /[a-z-]*(width|height|version)="[^"]*"|[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?/)) {
				t[++n] = substr(rest, RSTART, RLENGTH)
				rest = substr(rest, RSTART + RLENGTH)
			}
		}
		N[f, FNR] = n; L[f] = FNR
		for (k = 1; k <= n; k++)
			if (f == 1) W1[FNR, k] = t[k]; else W2[FNR, k] = t[k]
	}
	END {
		if (L[1] != L[2]) { print "lines: " L[1] " and " L[2]; exit 1 }
		for (l = 1; l <= L[1]; l++) {
			if (N[1, l] != N[2, l]) { print "line " l ": " N[1, l] " and " N[2, l] " words"; exit 1 }
			for (k = 1; k <= N[1, l]; k++) {
				p = power(1, l, k, W1[l, k]); a = value(W1[l, k])
				PW[l, k] = p
				if (p == -9 || !isnum(a)) continue
				x = pw(a + 0, p); if (x < 0) x = -x
				if (x > M[p]) M[p] = x
			}
		}
		for (l = 1; l <= L[1]; l++)
			for (k = 1; k <= N[1, l]; k++) {
				p = PW[l, k]; a = value(W1[l, k]); b = value(W2[l, k])
				if (p == -9 || !isnum(a)) {
					if (W1[l, k] != W2[l, k]) { print "line " l ": " W1[l, k] " but " W2[l, k]; exit 1 }
					continue
				}
				if (!isnum(b)) { print "line " l ": " b " is not a number"; exit 1 }
				want = pw(a + 0, p); d = b - want; if (d < 0) d = -d
				if (!(d <= tol * M[p])) {
					printf "line %d word %d: %s, want %.17g (%s times s^%d)\n", l, k, b, want, a, p
					exit 1
				}
			}
	}' tol="${REL:-1e-9}" "$3" "$4"
}

# compare_svg S FILE1 FILES: loftplot's picture (svgplot.c) of a drawing
# scaled by S is the picture at scale 1 with every length times S, and
# nothing else changed.  A picture's lengths are in units of its svg
# element's data-unit (1 without; svgplot.c names a power of ten
# beyond frames of 1e-6 to 1e9 units, where browsers would show
# nothing), so a length is its number times that unit; the unit is not
# compared.  The invariant, exactly: the same elements,
# attributes and texts in the same order (labels print the records'
# own attribute values, text); the same numbers where they are not
# lengths (the page's width and height in pixels, font size and halo in
# font pixels, opacities, arc flags); and each length (viewBox,
# coordinates of paths, rects and label positions, stroke widths,
# dashes, marker radii, a label's scale) within REL of the largest
# length of the picture of S times its value at scale 1.  svgplot.c
# writes every length to a place of 1e-7 to 1e-6 of the frame's larger
# side, so REL 1.5e-6 of the largest length is 1.5 to 15 units of that
# place: a value at scale S and at 1 may round either side of a tie,
# while a page that grows by a tenth of a pixel, a length off by 1e-5 of
# the frame, a lost exponent, a comb or label placed otherwise, all fail.
compare_svg() {
	awk -v s="$1" -v tol="${REL:-1.5e-6}" '
	function isnum(x) { return x ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ }
	# token: its power (0, 1; -9 text) and its text
	function put(p, v) { n = ++N[f]; P[f, n] = p; V[f, n] = v; LN[f, n] = FNR }
	# path data: numbers power 1 but the 3rd to 5th of each 7 of an arc
	function pathdata(d,   c, k, i, m, t) {
		gsub(/[A-DF-Za-df-z]/, " & ", d)
		m = split(d, t, /[ ,]+/); c = ""; k = 0
		for (i = 1; i <= m; i++) {
			if (t[i] == "") continue
			if (!isnum(t[i])) { c = t[i]; k = 0; put(-9, t[i]); continue }
			put((c == "a" || c == "A") && (k % 7 >= 2 && k % 7 <= 4) ? 0 : 1, t[i])
			k++
		}
	}
	# numbers of a list (viewBox, dasharray, transform), power p
	function numbers(v, p,   i, m, t) {
		gsub(/[(),]/, " & ", v)
		m = split(v, t, / +/)
		for (i = 1; i <= m; i++)
			if (t[i] != "") put(isnum(t[i]) ? p : -9, t[i])
	}
	function attribute(tag, labels, name, v) {
		put(-9, name)
		if (tag == "svg" && (name == "width" || name == "height")) put(0, v)
		else if (tag == "svg" && name == "viewBox") numbers(v, 1)
		else if (tag == "g" && (name == "font-size" || name == "stroke-width")) put(labels ? 0 : 1, v)
		else if (tag == "path" && name == "d") pathdata(v)
		else if (name == "stroke-width" || name == "stroke-dasharray" || name == "transform") numbers(v, 1)
		else if (tag == "rect" && name ~ /^(x|y|width|height)$/) put(1, v)
		else if (name == "stroke-opacity") put(0, v)
		else put(-9, v)
	}
	FNR == 1 { f++; U[f] = 1 }
	{
		line = $0
		while (line != "") {
			if (substr(line, 1, 1) != "<") {        # text
				i = index(line, "<"); if (i == 0) i = length(line) + 1
				put(-9, substr(line, 1, i - 1)); line = substr(line, i); continue
			}
			i = index(line, ">"); tag = substr(line, 2, i - 2); line = substr(line, i + 1)
			match(tag, /^[^ ]*/); name = substr(tag, 1, RLENGTH); put(-9, "<" name)
			rest = substr(tag, RLENGTH + 1)
			labels = rest ~ /font-family=/
			while (match(rest, /[a-zA-Z:-]+="[^"]*"/)) {
				a = substr(rest, RSTART, RLENGTH); rest = substr(rest, RSTART + RLENGTH)
				j = index(a, "=")
				if (substr(a, 1, j - 1) == "data-unit") {       # lengths in it
					U[f] = substr(a, j + 2, length(a) - j - 2); continue
				}
				attribute(name, labels, substr(a, 1, j - 1), substr(a, j + 2, length(a) - j - 2))
			}
			put(-9, rest)           # "/", "?" and what is not an attribute
		}
	}
	END {
		if (N[1] != N[2]) { print N[1] " and " N[2] " words"; exit 1 }
		for (k = 1; k <= N[1]; k++) {
			if (P[1, k] != 1) continue
			x = V[1, k] * U[1] * s; if (x < 0) x = -x
			if (x > M) M = x
		}
		for (k = 1; k <= N[1]; k++) {
			a = V[1, k]; b = V[2, k]; p = P[1, k]
			if (p == -9) {
				if (a != b) { print "line " LN[2, k] ": " b " but " a; exit 1 }
				continue
			}
			if (!isnum(b)) { print "line " LN[2, k] ": " b " is not a number"; exit 1 }
			want = p == 1 ? a * U[1] * s : a + 0
			d = (p == 1 ? b * U[2] : b) - want; if (d < 0) d = -d
			if (!(d <= (p == 1 ? tol * M : 1e-12 * (want < 0 ? -want : want)))) {
				printf "line %d: %s, want %.17g (%s times s^%d)\n", LN[2, k], b, want, a, p
				exit 1
			}
		}
	}' "$2" "$3"
}

# sweep NAME MODE PREP CMD: CMD (a shell command using $S and $IN) run
# on PREP's output (PREP: "scale", "scale_csv" or "scale_dxf" of the file
# $SRC) at every scale, against scale 1
sweep() {
	name=$1 mode=$2 prep=$3 cmd=$4
	S=1
	$prep 1 <"$SRC" >"$T/in1"
	IN=$T/in1
	eval "$cmd" >"$T/ref" 2>"$T/referr"
	if [ $? -ne 0 ] || [ ! -s "$T/ref" ]; then
		no "$name: fails at scale 1: $(head -2 "$T/referr")"
		return
	fi
	for S in $SCALES; do
		$prep "$S" <"$SRC" >"$T/ins"
		IN=$T/ins
		eval "$cmd" >"$T/out" 2>"$T/err"
		rc=$?
		what="$name at scale $S"
		# (exit 2: an option scaled past its range, a usage error)
		if [ $rc -eq 1 -o $rc -eq 2 ] && [ ! -s "$T/out" ] &&
		    grep -q "^[a-z]*: " "$T/err"; then
			refused=$((refused + 1))        # a clear refusal
			printf '%s: refused: %s\n' "$what" "$(head -1 "$T/err")" >>"$T/refusals"
			ok
			continue
		fi
		[ $rc -eq 0 ] || { no "$what: exit $rc: $(head -2 "$T/err")"; continue; }
		[ ! -s "$T/err" ] || { no "$what: says $(head -2 "$T/err")"; continue; }
		v=$(compare "$mode" "$S" "$T/ref" "$T/out") && ok || no "$what: $v"
	done
}

B=${LOFT_BIN:-bin}
: >"$T/refusals"
K=man/figures/insole.knots
H=man/figures/hull.knots
"$B/splinefit" $K >"$T/insole.cubic"
"$B/splinefit" -o $H >"$T/hull.cubic"
"$B/patchloft" "$T/hull.cubic" >"$T/hull.design"
awk 'BEGIN { print "points closed=1"; for (i = 0; i < 16; i++)
	printf "%.17g %.17g\n", 3 + 2 * cos(i * 3.141592653589793 / 8),
	    -1 + 2 * sin(i * 3.141592653589793 / 8) }' | "$B/splinefit" >"$T/circle.cubic"
# two patches that share a side, unjoined
"$B/patchnew" -i 1 -c 0,0,0 -c 1,0,0.2 -c 1,1,0 -c 0,1,0.3 |
    "$B/patchsplit" -u 0.5 | sed 's/ [uv][01]=[0-9]*//g' >"$T/two.design"
"$B/grade" -r -2:2 -l 1 -w 0.5 $K | "$B/splinefit" >"$T/graded.cubic"
# issue 28's curve: extrema 2 at scale 1, 0 at 1e80; and in space
printf 'bezier\n0 0\n1 2\n3 0\n4 1\n' >"$T/b.bezier"
printf 'bezier\n0 0 0\n1 2 1\n3 0 -1\n4 1 2\n' >"$T/b3.bezier"
awk 'BEGIN { print "x,y"; for (i = 0; i < 12; i++) printf "%d,%g\n", i, (i % 4) * 1.5 }' >"$T/pts.csv"
printf '0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n1\n20\n2\n30\n0\n40\n3\n0\nLINE\n8\n0\n10\n0\n20\n0\n30\n0\n11\n5\n21\n1\n31\n0\n0\nENDSEC\n0\nEOF\n' >"$T/c.dxf"

# the area (power 2) apart: it overflows or underflows from 1e+-160 on,
# and its refusal would hide the other fields
PF=length,cx,cy,xmin,ymin,xmax,ymax,minradius,minradius_u,inflexions,extrema,energy,jump
PP=1:1:1:1:1:1:1:1:0:0:0:-1:-1
SF=length,cx,cy,cz,xmin,zmax,minradius,minradius_u,extrema,energy,jump
SP=1:1:1:1:1:1:1:0:0:-1:-1

SRC=$K
sweep "splinefit" rows scale '"$B/splinefit" $IN'
sweep "splinefit -m chord" rows scale '"$B/splinefit" -m chord $IN'
SRC=$H
sweep "splinefit -o" rows scale '"$B/splinefit" -o $IN'
sweep "splinefit -o -S 0,0,1" rows scale '"$B/splinefit" -o -S 0,1e-320,0 $IN'
sweep "patchloft" rows scale '"$B/splinefit" -o $IN | "$B/patchloft"'
sweep "patchloft -S" rows scale '"$B/splinefit" -o $IN | "$B/patchloft" -S 0,0,1e-300'
SRC=$T/insole.cubic
sweep "sample -n" rows scale '"$B/sample" -n 3 $IN'
sweep "sample -s" rows scale '"$B/sample" -s $(sc 7) $IN'
sweep "sample -t" rows scale '"$B/sample" -t $(sc 0.05) $IN'
sweep "bezapprox" rows scale '"$B/bezapprox" -n 7 $IN'
sweep "offset" rows scale '"$B/offset" -d $(sc 3) -d $(sc -2) $IN'
sweep "measure, plane" "cols:$PP" scale '"$B/measure" -f $PF $IN'
sweep "measure, area" "cols:2" scale '"$B/measure" -f area $IN'
sweep "patchdrag, a curve" rows scale '"$B/patchdrag" -u 3.5 -b $(sc 1),$(sc 2) $IN'
sweep "tocad -f obj, a curve" obj scale '"$B/tocad" -f obj $IN'
# loftplot: the picture is the same at every scale (compare_svg)
sweep "loftplot" svg scale '"$B/loftplot" $IN'
sweep "loftplot -c -t" svg scale '"$B/loftplot" -c -t $IN'
sweep "loftplot -C" svg scale '"$B/loftplot" -C $(sc2 300) -n 8 $IN'
sweep "loftplot -v iso -l" svg scale '"$B/loftplot" -v iso -l id -B white $IN'
SRC=$T/circle.cubic
# (not minradius_u: on a circle where the radius is least is rounding)
sweep "measure, a circle" "cols:1:1:1:1:0:0:-1" scale \
    '"$B/measure" -f length,cx,cy,minradius,inflexions,extrema,energy $IN'
SRC=$T/hull.cubic
sweep "measure, space" "cols:$SP" scale '"$B/measure" -f $SF $IN'
SRC=$T/b.bezier
sweep "measure, issue 28's curve" "cols:$PP" scale '"$B/measure" -f $PF $IN'
SRC=$T/b3.bezier
sweep "measure, issue 28's curve in space" "cols:$SP" scale '"$B/measure" -f $SF $IN'
SRC=$K
sweep "grade" rows scale '"$B/grade" -r -1:1 -l $(sc 1) -w $(sc 0.5) $IN'
SRC=$T/hull.design
sweep "patchsplit" rows scale '"$B/patchsplit" -u 0.5 $IN'
sweep "patchdrag, a patch" rows scale '"$B/patchdrag" -i 8 -u 0.5 -v 0.5 -b $(sc 0.1),$(sc 0.2),$(sc 0.3) $IN'
sweep "patchdrag -w" rows scale '"$B/patchdrag" -i 8 -u 0.5 -v 0.5 -b $(sc 0.1),$(sc 0.2),$(sc 0.3) -w 0,0,1e-320 $IN'
sweep "patchcut" rows scale '"$B/patchcut" -x $(sc 3) -z $(sc 0.5) $IN'
sweep "bezapprox, a surface" rows scale '"$B/patchsplit" -u 0.5 $IN | "$B/bezapprox" -n 3,3'
sweep "tocad -f obj" obj scale '"$B/tocad" -f obj $IN'
sweep "loftplot, a surface" svg scale '"$B/loftplot" -v iso -b -g 6 -l id $IN'
sweep "tocad -f stl" stl scale '"$B/tocad" -f stl $IN'
SRC=$T/two.design
sweep "patchjoin" rows scale '"$B/patchjoin" -P 2 -S 3 $IN'
SRC=/dev/null
sweep "patchnew" rows scale '"$B/patchnew" -c $(sc 0),$(sc 0),0 -c $(sc 1),0,$(sc 0.2) -c $(sc 1),$(sc 1),0 -c 0,$(sc 1),$(sc 0.3)'
SRC=$T/graded.cubic
sweep "loftplot -l, a graded set" svg scale '"$B/loftplot" -l size -c $IN'
SRC=$K
sweep "loftplot -m, points" svg scale '"$B/loftplot" -m $IN'
SRC=$T/pts.csv
sweep "fromcad, CSV" rows scale_csv '"$B/fromcad" $IN'
SRC=$T/c.dxf
sweep "fromcad, DXF" rows scale_dxf '"$B/fromcad" -f dxf $IN'

# directions of any length are the same direction, to the last digit
# (issue 28: -S 1e-320,0 and -w 0,0,1e-320 differed in the last digit)
same_as() {
	what=$1
	eval "$2" >"$T/a" 2>&1
	eval "$3" >"$T/b" 2>&1
	cmp -s "$T/a" "$T/b" && [ -s "$T/a" ] && ok ||
	    no "$what: $(diff "$T/a" "$T/b" | head -3)"
}
same_as "splinefit -o -S 1e-320,0,0" '"$B/splinefit" -o -S 1e-320,0,0 $H' \
    '"$B/splinefit" -o -S 1,0,0 $H'
same_as "splinefit -S 0,1e300" '"$B/splinefit" -S 0,1e300 $K' \
    '"$B/splinefit" -S 0,1 $K'
same_as "patchdrag -w 0,0,1e-320" \
    '"$B/patchdrag" -i 8 -u 0.5 -v 0.5 -b 1,2,3 -w 0,0,1e-320 $T/hull.design' \
    '"$B/patchdrag" -i 8 -u 0.5 -v 0.5 -b 1,2,3 -w 0,0,1 $T/hull.design'
same_as "patchloft -S 0,0,1e-300" '"$B/patchloft" -S 0,0,1e-300 $T/hull.cubic' \
    '"$B/patchloft" -S 0,0,1 $T/hull.cubic'

# loftplot's picture of a drawing whose frame is 100 to 1000 units (the
# insole, 286 of them) is at every scale the same text as at scale 1,
# but for the svg element's data-unit="1eK" at scale 1eK: svgplot.c
# moves the point of the same digits of %e
"$B/loftplot" -c -t -l id "$T/insole.cubic" >"$T/plot1"
for S in $SCALES; do
	scale "$S" <"$T/insole.cubic" | "$B/loftplot" -c -t -l id |
	    sed "s/ data-unit=\"$S\"//" >"$T/plots"
	cmp -s "$T/plot1" "$T/plots" && ok ||
	    no "loftplot at scale $S: not the picture at 1: $(diff "$T/plot1" "$T/plots" | head -3 | cut -c1-200)"
done

# the refusals, for the record (each was "a clear refusal")
sed 's/^/note: /' "$T/refusals"
finish units
