#!/bin/sh
# realcad.sh: fromcad against independent readers, on documents written
# here by ezdxf (blocks, arrays, nested and extruded inserts, ellipses,
# hidden layers, an ASTM D6673 pattern file) and on real files Debian
# ships (LibreCAD's parts library for DXF, the breeze and Adwaita icon
# themes for SVG), each compared with ezdxf's or svgelements' own
# geometry by tests/realcad.py.  The real corpora are sampled (at most
# REALCAD_FILES files each, 200 by default) so that make check stays
# short.  Run from the top of the tree; the last line is "realcad: N
# passed, M failed".  (svgelements reads the SVGs, ezdxf the DXFs; the
# SVG part is skipped alone where ezdxf is missing and svgelements not.)

T=bin/test/realcad
. tests/lib.sh

F="$B/fromcad"
N=${REALCAD_FILES:-200}
PY=
for p in ${PYTHON:-} /usr/bin/python3 python3; do
	if "$p" -c 'import ezdxf' >/dev/null 2>&1; then PY=$p; break; fi
done

# many KIND NAME: fromcad reads each file of $T/list with exit 0 (an
# annotation is no error), and its records are those of the independent
# reader (one python run for them all); a line of totals.  A document in
# error as SVG 1.1 defines it (F.2: path data in error, drawn up to the
# error; a use of an id no element has, drawn as nothing: breeze's
# network-mobile-80-*-locked and kmahjongg) exits 1 with fromcad's
# message and is compared too.
INERROR="drawn up to there, as SVG renders it|: no element of that id: not read"
many() {
	mkdir -p "$T/lofts"
	: >"$T/pairs"
	i=0
	while IFS= read -r f; do
		i=$((i + 1))
		if $F $FOPT "$f" >"$T/lofts/$i" 2>"$T/oneerr" ||
		    ! grep -v -E "passed over|$INERROR" "$T/oneerr" | grep -q .; then
			printf '%s\t%s\n' "$f" "$T/lofts/$i" >>"$T/pairs"
		else
			no "fromcad $f: exit 1: $(grep -v 'passed over' "$T/oneerr" | head -2)"
		fi
	done <"$T/list"
	"$PY" tests/realcad.py "$1" "$T/pairs" >"$T/cmp" 2>&1
	grep '^FAIL' "$T/cmp" | while IFS= read -r l; do echo "$l" >&2; done
	nbad=$(grep -c '^FAIL' "$T/cmp")
	fail=$((fail + nbad))
	pass=$((pass + $(wc -l <"$T/pairs") - nbad))
	echo "realcad: $2: $(tail -1 "$T/cmp")"
}

if [ -z "$PY" ]; then
	echo "realcad: DXF cases skipped: no python3 with ezdxf (Debian python3-ezdxf)"
else
	"$PY" tests/realcad.py gen "$T" && ok || no "realcad.py gen failed"
	echo "$T/blocks.dxf" >"$T/list"
	many dxf generated
	FOPT=-F many dxf-F "generated, HATCH boundaries read (-F)"
	# HATCH paths of ellipse and spline edges (rational too, fit data
	# or none, R2013 and R2000) against ezdxf's evaluation, at -t 0.001
	ls "$T"/hatch20*.dxf >"$T/list"
	FOPT="-F -t 0.001" many dxf-Ft "generated, HATCH ellipse and spline edges (-F -t 0.001)"
	echo "$T/blocks.dxf" >"$T/list"
	# the TEXT noted, the two lines on layers off and frozen passed over
	run "$F $T/blocks.dxf"
	status 0
	says "blocks.dxf: 1 TEXT, 1 HATCH passed over (annotations, fills and empty arcs; -S makes them errors)"
	says "blocks.dxf: 2 LINE passed over on layers off or frozen (-H reads them)"
	n0=$(grep -c '^[a-z]' "$T/out")
	run "$F -H $T/blocks.dxf"
	status 0
	[ "$(grep -c '^[a-z]' "$T/out")" = $((n0 + 2)) ] && ok || no "-H: $(grep -c '^[a-z]' "$T/out") records, want $((n0 + 2))"
	run "$F -S $T/blocks.dxf"
	status 1
	says "TEXT (handle"
	# D6673: one record per size, each with its own turn points (the
	# sizes stacked at one place), the size's TEXT passed over
	run "$F $T/d6673.dxf"
	status 0
	says "d6673.dxf: 2 TEXT passed over"
	grep '^points' "$T/out" >"$T/heads"
	printf '%s\n' "points closed=1 layer=1 block=S7 corners=2,4" \
	    "points closed=1 layer=1 block=S8 corners=2,4" | cmp -s - "$T/heads" &&
	    ok || no "d6673.dxf: records $(cat "$T/heads")"
	# tocad's attributes as XDATA, as ezdxf reads them
	printf 'cubic size=4.5 offset=2 name=heel\n0 0 10 0 3 0 0 3\n' |
	    $B/tocad -f dxf >"$T/attr.dxf"
	"$PY" -c 'import sys, ezdxf
d = ezdxf.readfile(sys.argv[1])
e = [e for e in d.modelspace() if e.dxftype() == "LWPOLYLINE"][0]
x = [t.value for t in e.get_xdata("LOFT")]
sys.exit(x != ["size=4.5", "offset=2", "name=heel"] or not d.appids.has_entry("LOFT"))' \
	    "$T/attr.dxf" && ok || no "ezdxf does not find tocad's XDATA in $T/attr.dxf"
	LIB=
	for d in /usr/share/librecad/library /usr/share/librecad; do
		[ -d "$d" ] && { LIB=$d; break; }
	done
	if [ -z "$LIB" ]; then
		echo "realcad: LibreCAD cases skipped: no /usr/share/librecad (Debian librecad-data)"
	else
		find "$LIB" -name '*.dxf' | LC_ALL=C sort >"$T/all"
		awk -v n="$N" 'NR == FNR { t++; next } (FNR - 1) % int((t + n - 1) / n) == 0' \
		    "$T/all" "$T/all" >"$T/list"
		many dxf librecad
		# the library's HATCHes, boundaries read (-F): one edge path
		# may hold several loops (elektro/dev/dev22.dxf), cut as
		# ezdxf chains them
		while IFS= read -r f; do
			grep -q '^HATCH' "$f" && printf '%s\n' "$f"
		done <"$T/all" >"$T/hatched"
		awk -v n="$N" 'NR == FNR { t++; next } (FNR - 1) % int((t + n - 1) / n) == 0' \
		    "$T/hatched" "$T/hatched" >"$T/list"
		FOPT=-F many dxf-F "librecad, HATCH boundaries read (-F)"
	fi
fi

SPY=
for p in ${PYTHON:-} /usr/bin/python3 python3; do
	if "$p" -c 'import svgelements' >/dev/null 2>&1; then SPY=$p; break; fi
done
if [ -z "$SPY" ]; then
	echo "realcad: SVG cases skipped: no python3 with svgelements (Debian python3-svgelements)"
else
	PY=$SPY
	[ -s "$T/features.svg" ] || "$PY" tests/realcad.py gen "$T"
	if [ -s "$T/features.svg" ]; then
		echo "$T/features.svg" >"$T/list"
		many svg generated
		# breeze's ways (realcad.py gen_svg): in error, "12.", ...
		echo "$T/inerror.svg" >"$T/list"
		many svg "generated, where svgelements parts from SVG"
		# the hidden two noted, the text noted, -H reads the hidden
		run "$F $T/features.svg"
		says "features.svg: 2 path passed over hidden (display:none, visibility:hidden; -H reads them)"
		says "features.svg: 1 text passed over"
		n0=$(grep -c '^[a-z]' "$T/out")
		run "$F -H $T/features.svg"
		[ "$(grep -c '^[a-z]' "$T/out")" = $((n0 + 2)) ] && ok || no "svg -H: $(grep -c '^[a-z]' "$T/out") records, want $((n0 + 2))"
	fi
	: >"$T/all"
	for d in /usr/share/icons/breeze /usr/share/icons/Adwaita; do
		[ -d "$d" ] && find "$d" -name '*.svg' -type f >>"$T/all"
	done
	if [ ! -s "$T/all" ]; then
		echo "realcad: icon cases skipped: no breeze or Adwaita icons (Debian breeze-icon-theme, adwaita-icon-theme)"
	else
		LC_ALL=C sort -o "$T/all" "$T/all"
		awk -v n="$N" 'NR == FNR { t++; next } (FNR - 1) % int((t + n - 1) / n) == 0' \
		    "$T/all" "$T/all" >"$T/list"
		many svg icons
	fi
fi

finish realcad
