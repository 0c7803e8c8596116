# raster.awk: the closed polygon of the points of a loft record filled
# (even-odd) on square pixels PX wide, as a plain PBM (P1), with a
# margin of 4 pixels; the picture's lower left corner is at x0, y0 (its
# pixel units times PX from there are the points' units).
/^[-0-9.]/ { n++; x[n] = $1; y[n] = $2
	if (n == 1 || $1 < lx) lx = $1; if (n == 1 || $1 > hx) hx = $1
	if (n == 1 || $2 < ly) ly = $2; if (n == 1 || $2 > hy) hy = $2 }
END {
	x0 = lx - 4 * PX; y0 = ly - 4 * PX
	w = int((hx + 4 * PX - x0) / PX) + 1; h = int((hy + 4 * PX - y0) / PX) + 1
	print "P1"; print w, h
	for (r = 0; r < h; r++) {
		yc = y0 + (h - r - 0.5) * PX; m = 0
		for (i = 1; i <= n; i++) {
			j = i % n + 1
			if ((y[i] <= yc) != (y[j] <= yc)) {
				c = x[i] + (yc - y[i]) * (x[j] - x[i]) / (y[j] - y[i])
				for (k = m; k > 0 && xs[k] > c; k--) xs[k + 1] = xs[k]
				xs[k + 1] = c; m++
			}
		}
		line = ""; k = 1; inside = 0
		for (col = 0; col < w; col++) {
			xc = x0 + (col + 0.5) * PX
			while (k <= m && xs[k] < xc) { inside = !inside; k++ }
			line = line (inside ? "1" : "0")
			if (length(line) >= 70) { print line; line = "" }
		}
		if (line != "") print line
	}
}
