# energy.awk: for each cubic record (2-D rows P_A P_B P'_A P'_B) of the
# input, one line: its bending energy, the integral of curvature squared
# along it, by Simpson's rule on N intervals per segment (awk -v N=...,
# else 400); its largest curvature on those points; its length; and the
# largest jump of the curvature, and of the unit tangent, across a knot.
# The reference of tests/fit.sh: its own formulas, not the library's.
function seg(x0, y0, x1, y1, dx0, dy0, dx1, dy1,   ax, ay, bx, by, i, u, px, py, qx, qy, v2, c, w, e, k) {
	ax = 3 * (x1 - x0) - 2 * dx0 - dx1; ay = 3 * (y1 - y0) - 2 * dy0 - dy1
	bx = dx0 + dx1 - 2 * (x1 - x0); by = dy0 + dy1 - 2 * (y1 - y0)
	e = 0
	for (i = 0; i <= N; i++) {
		u = i / N
		px = dx0 + u * (2 * ax + 3 * u * bx); py = dy0 + u * (2 * ay + 3 * u * by)
		qx = 2 * ax + 6 * u * bx; qy = 2 * ay + 6 * u * by
		v2 = px * px + py * py; c = px * qy - py * qx
		w = (i == 0 || i == N) ? 1 : (i % 2 ? 4 : 2)
		k = c / (v2 * sqrt(v2)); if (k < 0) k = -k; if (k > kmax) kmax = k
		e += w * c * c / (v2 * v2 * sqrt(v2))
		len += w * sqrt(v2) / (3 * N)
	}
	# the curvatures at the ends: P''(0) = 2a, P''(1) = 2a + 6b
	k0[ns] = (dx0 * 2 * ay - dy0 * 2 * ax) / (dx0 * dx0 + dy0 * dy0) ^ 1.5
	k1[ns] = (dx1 * (2 * ay + 6 * by) - dy1 * (2 * ax + 6 * bx)) / (dx1 * dx1 + dy1 * dy1) ^ 1.5
	t0x[ns] = dx0 / sqrt(dx0 * dx0 + dy0 * dy0); t0y[ns] = dy0 / sqrt(dx0 * dx0 + dy0 * dy0)
	t1x[ns] = dx1 / sqrt(dx1 * dx1 + dy1 * dy1); t1y[ns] = dy1 / sqrt(dx1 * dx1 + dy1 * dy1)
	ns++
	return e / (3 * N)
}
function put(   i, j, kj, tj, d) {
	kj = 0; tj = 0
	for (i = 0; i < ns; i++) {
		j = i + 1
		if (j == ns) { if (!closed) break; j = 0 }
		d = k1[i] - k0[j]; if (d < 0) d = -d; if (d > kj) kj = d
		d = (t1x[i] - t0x[j]) ^ 2 + (t1y[i] - t0y[j]) ^ 2; if (d > tj) tj = d
	}
	printf "%.12g %.12g %.12g %.3g %.3g\n", E, kmax, len, kj, sqrt(tj)
}
BEGIN { if (N + 0 <= 0) N = 400 }
/^cubic/ { if (n) put(); E = 0; kmax = 0; len = 0; ns = 0; n++; closed = $0 ~ /closed=1/; next }
NF == 8 { E += seg($1, $2, $3, $4, $5, $6, $7, $8) }
END { if (n) put() }
