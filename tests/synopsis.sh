#!/bin/sh
# synopsis.sh: each program's man page SYNOPSIS says what its usage text
# says (issue 12): every option, its argument and its brackets.  Run from
# the top of the tree; the last line is "synopsis: N passed, M failed".
#
# The SYNOPSIS is rendered from its mdoc by the rules of mdoc(7) for the
# macros the pages use (Nm Op Oo Oc Po Pc Fl Ar Cm Ns), independently of
# the program, and compared word for word, spaces aside, with what
# `PROG -h` prints, its "usage: " taken off.  A page of two synopses
# (two .Nm lines) matches a usage of two lines.

T=bin/test/synopsis
. tests/lib.sh

# render PAGE: the page's SYNOPSIS as one line of plain text
render() {
	awk '
	/^\.Sh / { on = ($2 == "SYNOPSIS"); next }
	!on || !/^\./ { next }
	# put word w; punctuation attaches as mdoc sets it
	function put(w) {
		if (w ~ /^[,:;.)\]]$/ || out == "" || glue) out = out w
		else out = out " " w
		glue = (w ~ /^[(\[]$/)
	}
	function closeops() {
		while (nop > 0) { put("]"); nop-- }
	}
	{
		sub(/^\./, "")
		n = split($0, w, /[ \t]+/)
		nop = 0
		for (i = 1; i <= n; i++) {
			m = w[i]
			next_is_word = (i < n && w[i + 1] !~ /^(Nm|Op|Oo|Oc|Po|Pc|Fl|Ar|Cm|Ns)$/)
			if (m == "Nm") {
				if (next_is_word) { i++; put(w[i]) }
			} else if (m == "Op") { put("["); nop++ }
			else if (m == "Oo") put("[")
			else if (m == "Oc") put("]")
			else if (m == "Po") put("(")
			else if (m == "Pc") put(")")
			else if (m == "Ns") glue = 1
			else if (m == "Fl") {
				if (next_is_word && w[i + 1] !~ /^[,:;|]$/) { i++; put("-" w[i]) }
				else put("-")
			} else if (m == "Ar") {
				if (next_is_word) { i++; put(w[i]) }
				else { put("file"); put("...") }
			} else if (m == "Cm") {
				if (next_is_word) { i++; put(w[i]) }
			} else put(m)
		}
		closeops()
	}
	END { print out }' "$1"
}

# usage PROG: what PROG -h prints, on one line, "usage: " taken off
usage() {
	"$B/$1" -h | sed '1s/^usage: //' | tr -s ' \n' '  ' | sed 's/ *$//'
}

# the renderer itself, on mdoc whose rendering mdoc(7) gives
cat >"$T/probe.1" <<'EOF'
.Sh SYNOPSIS
.Nm probe
.Op Fl ab
.Op Fl S Ar tx , Ns Ar ty Ns Op , Ns Ar tz
.Fl f Cm a Ns | Ns Cm b
.Po
.Fl u Ar t | Fl v Ar t
.Pc
.Op Ar
.Sh DESCRIPTION
.Op Fl x
EOF
r=$(render "$T/probe.1")
want='probe [-ab] [-S tx,ty[,tz]] -f a|b (-u t | -v t) [file ...]'
[ "$r" = "$want" ] && ok || no "render: '$r', want '$want'"

for c in cmd/*.c; do
	p=$(basename "$c" .c)
	if [ ! -f "man/$p.1" ]; then
		no "$p: no man/$p.1"
		continue
	fi
	page=$(render "man/$p.1")
	text=$(usage "$p")
	[ -n "$text" ] && [ "$page" = "$text" ] && ok ||
	    no "$p: SYNOPSIS of man/$p.1 is
	'$page'
    where $p -h says
	'$text'"
done

finish synopsis
