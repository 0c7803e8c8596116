# cad.awk: functions the tocad suite's readers share, written from the
# formats' definitions (not from tocad): de Boor's algorithm for a point
# of a B-spline curve, the Bezier cubic, distances.

# deboor(p, K, nk, X, Y, Z, t, R): the point at t of the B-spline of
# degree p with knots K[0..nk-1] and control points X, Y, Z[0..] into
# R[1..3].
function deboor(p, K, nk, X, Y, Z, t, R,    nc, s, j, r, a, dx, dy, dz) {
	nc = nk - p - 1
	for (s = p; s < nc - 1 && !(t < K[s + 1]); s++)
		;
	for (j = 0; j <= p; j++) {
		dx[j] = X[j + s - p]; dy[j] = Y[j + s - p]; dz[j] = Z[j + s - p]
	}
	for (r = 1; r <= p; r++)
		for (j = p; j >= r; j--) {
			a = (t - K[j + s - p]) / (K[j + 1 + s - r] - K[j + s - p])
			dx[j] = (1 - a) * dx[j - 1] + a * dx[j]
			dy[j] = (1 - a) * dy[j - 1] + a * dy[j]
			dz[j] = (1 - a) * dz[j - 1] + a * dz[j]
		}
	R[1] = dx[p]; R[2] = dy[p]; R[3] = dz[p]
}

# cubic(P, t, R): the cubic Bezier of control points P[0..7] (x y pairs)
# at t into R[1..2].
function cubic(P, t, R,    s) {
	s = 1 - t
	R[1] = s*s*s*P[0] + 3*s*s*t*P[2] + 3*s*t*t*P[4] + t*t*t*P[6]
	R[2] = s*s*s*P[1] + 3*s*s*t*P[3] + 3*s*t*t*P[5] + t*t*t*P[7]
}

function abs(x) { return x < 0 ? -x : x }

# segdist(px, py, ax, ay, bx, by): distance from p to the segment a b.
function segdist(px, py, ax, ay, bx, by,    dx, dy, l, t) {
	dx = bx - ax; dy = by - ay; l = dx * dx + dy * dy
	t = l > 0 ? ((px - ax) * dx + (py - ay) * dy) / l : 0
	if (t < 0) t = 0
	if (t > 1) t = 1
	return sqrt((px - ax - t * dx)^2 + (py - ay - t * dy)^2)
}

# The B-spline entity step_eval and iges_eval parsed, in globals: surf,
# and a curve's degree p, knots K[0..nk-1], control points X, Y, Z; or a
# surface's degrees p, q, knots KU, KV, mu x mv control points SX, SY,
# SZ[i, j].

# ev2(u, v): the surface at (u, v) into R, by de Boor in v along each
# row of control points, then in u through the results.
function ev2(u, v,    i, j, TX, TY, TZ, CX, CY, CZ) {
	for (i = 0; i < mu; i++) {
		for (j = 0; j < mv; j++) { CX[j] = SX[i, j]; CY[j] = SY[i, j]; CZ[j] = SZ[i, j] }
		deboor(q, KV, q + mv + 1, CX, CY, CZ, v, R)
		TX[i] = R[1]; TY[i] = R[2]; TZ[i] = R[3]
	}
	deboor(p, KU, p + mu + 1, TX, TY, TZ, u, R)
}

# check_row(): the distance of the row of sample's output in $0 (x y [z]
# u, or x y z u v) from the entity there, into the worst w and count cnt.
function check_row(    e, k) {
	if (surf) {
		ev2($4, $5)
		e = sqrt((R[1] - $1)^2 + (R[2] - $2)^2 + (R[3] - $3)^2)
	} else {
		deboor(p, K, nk, X, Y, Z, $NF, R)
		e = 0
		for (k = 1; k < NF; k++)
			e += (R[k] - $k)^2
		e = sqrt(e)
	}
	cnt++
	if (e > w)
		w = e
}
