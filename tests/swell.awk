# swell.awk: of two files of cubic records (splinefit's output), the
# default's and the chord spline's, over records with corners=, the
# spans of the first that swell (farthest distance from their chord,
# at 63 points) past 1.1 times the more of the chord spline's swell and
# the sagitta of the circles through the span's knots and either
# neighbour, + 1e-6 of the chord (issue 23: no ballooning beside a
# corner).  Prints "SPANS-PAST SPANS".
function swell(x0, y0, x1, y1, a0, b0, a1, b1,    j, u, h00, h10, h01, h11, x, y, cx, cy, c, d, m) {
	cx = x1 - x0; cy = y1 - y0; c = sqrt(cx * cx + cy * cy); m = 0
	if (c == 0) return 0
	for (j = 1; j < 64; j++) { u = j / 64
		h00 = 2 * u^3 - 3 * u^2 + 1; h10 = u^3 - 2 * u^2 + u
		h01 = -2 * u^3 + 3 * u^2; h11 = u^3 - u^2
		x = h00 * x0 + h10 * a0 + h01 * x1 + h11 * a1
		y = h00 * y0 + h10 * b0 + h01 * y1 + h11 * b1
		d = ((x - x0) * cy - (y - y0) * cx) / c; if (d < 0) d = -d
		if (d > m) m = d }
	return m
}
function sag(ax, ay, bx, by, qx, qy,    ab, aq, bq, s, ar, r) {
	ab = sqrt((ax - bx)^2 + (ay - by)^2); aq = sqrt((ax - qx)^2 + (ay - qy)^2)
	bq = sqrt((bx - qx)^2 + (by - qy)^2); s = (ab + aq + bq) / 2
	ar = s * (s - ab) * (s - aq) * (s - bq); if (ar <= 0) return 0
	r = ab * aq * bq / (4 * sqrt(ar)); return r - sqrt(r * r > ab * ab / 4 ? r * r - ab * ab / 4 : 0)
}
FNR == 1 { f++; rec = 0 }
/^cubic/ { rec++; n[f, rec] = 0; cor[rec] = /corners=/; next }
NF == 8 { k = ++n[f, rec]; for (i = 1; i <= 8; i++) v[f, rec, k, i] = $i }
END {
	for (r = 1; r <= rec; r++) { m = n[1, r]; if (!cor[r]) continue
		for (k = 1; k <= m; k++) {
			sd = swell(v[1, r, k, 1], v[1, r, k, 2], v[1, r, k, 3], v[1, r, k, 4], v[1, r, k, 5], v[1, r, k, 6], v[1, r, k, 7], v[1, r, k, 8])
			sc = swell(v[2, r, k, 1], v[2, r, k, 2], v[2, r, k, 3], v[2, r, k, 4], v[2, r, k, 5], v[2, r, k, 6], v[2, r, k, 7], v[2, r, k, 8])
			p = k > 1 ? k - 1 : m; q = k < m ? k + 1 : 1
			s1 = sag(v[1, r, k, 1], v[1, r, k, 2], v[1, r, k, 3], v[1, r, k, 4], v[1, r, p, 1], v[1, r, p, 2])
			s2 = sag(v[1, r, k, 1], v[1, r, k, 2], v[1, r, k, 3], v[1, r, k, 4], v[1, r, q, 3], v[1, r, q, 4])
			b = sc; if (s1 > b) b = s1; if (s2 > b) b = s2
			c = sqrt((v[1, r, k, 3] - v[1, r, k, 1])^2 + (v[1, r, k, 4] - v[1, r, k, 2])^2)
			if (sd > 1.1 * b + 1e-6 * c) bad++
			spans++ } }
	print bad + 0, spans + 0
}
