# svgcmp.awk: compare two of loftplot's SVG documents by their geometry
# (issue 12: the figures were compared byte for byte, so a change in a
# last printed digit failed them).
#
#   awk -f tests/svgcmp.awk WANT.svg GOT.svg
#
# exits 0 when GOT is WANT: the same lines, each the same once its
# numbers are taken out (elements, attributes, colours, classes, path
# commands, label texts: exactly), and the same count of numbers, each
# within
#   FRAME_TOL of the frame (the larger side of WANT's viewBox) for a
#             coordinate or length in the drawing's units: loftplot
#             prints them to 1e-6 of the frame (RESOLUTION), so a last
#             digit may turn over once or twice, but nothing moves by
#             more than 1/700 of a pixel of the 640-pixel picture;
#   PIXEL_TOL for the width and height of the picture, in pixels to one
#             decimal: one unit of it, with room for rounding;
#   exactly   for an arc's two flags (the 4th and 5th numbers of each
#             "a" or "A"), which are 0 or 1.
# Otherwise it prints the first differences, line by line, and exits 1.

BEGIN {
	FRAME_TOL = 2e-6
	PIXEL_TOL = 0.15
	NUM = "-?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?"
	# the attributes whose values hold numbers
	split("d viewBox transform stroke-width width height x y cx cy r " \
	    "x1 y1 x2 y2 points font-size", a, " ")
	for (k in a)
		numeric[a[k]] = 1
}

FNR == NR { want[++nw] = $0; next }
{ got[++ng] = $0 }

# decompose(line, which): the line with its numbers replaced by "#" into
# skel[which]; the numbers into val[which, 1..], their kinds ("f" frame,
# "p" pixel, "x" exact) into kind[which, 1..]; returns their count.
function decompose(line, which,    out, n, attr, name, v, s, cmd, idx, seg, i) {
	out = ""
	n = 0
	while (match(line, / [a-zA-Z:-]+="[^"]*"/)) {
		attr = substr(line, RSTART, RLENGTH)
		out = out substr(line, 1, RSTART - 1)
		line = substr(line, RSTART + RLENGTH)
		name = substr(attr, 2, index(attr, "=") - 2)
		if (!(name in numeric)) {
			out = out attr
			continue
		}
		v = substr(attr, length(name) + 4)
		v = substr(v, 1, length(v) - 1)
		s = " " name "=\""
		cmd = ""
		idx = 0
		while (match(v, NUM)) {
			seg = substr(v, 1, RSTART - 1)
			for (i = length(seg); i > 0; i--)
				if (substr(seg, i, 1) ~ /[A-Za-z]/) {
					cmd = substr(seg, i, 1)
					idx = 0
					break
				}
			s = s seg "#"
			val[which, ++n] = substr(v, RSTART, RLENGTH) + 0
			if (name == "d" && (cmd == "a" || cmd == "A") &&
			    (idx % 7 == 3 || idx % 7 == 4))
				kind[which, n] = "x"
			else if (name == "width" || name == "height")
				kind[which, n] = (out ~ /<svg/) ? "p" : "f"
			else
				kind[which, n] = "f"
			idx++
			v = substr(v, RSTART + RLENGTH)
		}
		out = out s v "\""
	}
	skel[which] = out line
	return n
}

function differ(what) {
	if (++bad <= 10)
		printf("line %d: %s\n", i, what)
}

END {
	if (nw != ng) {
		printf("%d lines, want %d\n", ng, nw)
		exit 1
	}
	frame = 0
	for (i = 1; i <= nw; i++)
		if (match(want[i], /viewBox="[^"]*"/)) {
			split(substr(want[i], RSTART + 9, RLENGTH - 10), vb, " ")
			frame = vb[3] > vb[4] ? vb[3] : vb[4]
			break
		}
	if (!(frame > 0)) {
		print "no viewBox with a size in " ARGV[1]
		exit 1
	}
	for (i = 1; i <= nw; i++) {
		nwn = decompose(want[i], 1)
		ngn = decompose(got[i], 2)
		if (skel[1] != skel[2] || nwn != ngn) {
			differ("not the same element: " substr(got[i], 1, 120))
			continue
		}
		for (k = 1; k <= nwn; k++) {
			d = val[2, k] - val[1, k]
			if (d < 0)
				d = -d
			t = FRAME_TOL * frame
			if (kind[1, k] == "x")
				t = 0
			else if (kind[1, k] == "p")
				t = PIXEL_TOL
			if (d > t) {
				differ(sprintf("number %d is %.17g, want %.17g " \
				    "within %g", k, val[2, k], val[1, k], t))
				break
			}
		}
	}
	exit bad > 0
}
