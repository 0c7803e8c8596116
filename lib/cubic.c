/*
 * cubic.c: one parametric cubic segment and its intrinsic properties
 * (Manning 1973, sections 2 and 4).
 */
#include "internal.h"

/*
 * Eq. 7:
 *   P(u) = P_A + u P'_A + u^2 (3(P_B - P_A) - 2P'_A - P'_B)
 *              + u^3 (P'_A + P'_B - 2(P_B - P_A)),
 * gathered by the chord c = P_B - P_A and the end tangents:
 *   P   = P_A + (3u^2 - 2u^3) c + (u - 2u^2 + u^3) P'_A + (u^3 - u^2) P'_B
 *   P'  = (6u - 6u^2) c + (1 - 4u + 3u^2) P'_A + (3u^2 - 2u) P'_B
 *   P'' = (6 - 12u) c + (6u - 4) P'_A + (6u - 2) P'_B.
 * Working from the chord keeps the second derivative accurate on short
 * segments far from the origin; the weights are exactly 0 or 1 at the
 * ends, and at u = 1 the point is P_B itself, so segments join exactly.
 */
void
loft_cubic_eval(const double *seg, int dim, double u,
    double *p, double *d1, double *d2)
{
	const double *pa = seg, *pb = seg + dim, *ta = seg + 2 * dim,
	    *tb = seg + 3 * dim;
	double uu = u * u, uuu = uu * u;

	for (int k = 0; k < dim; k++) {
		double c = pb[k] - pa[k];

		if (p != NULL)
			p[k] = u == 1 ? pb[k] : pa[k] + (3 * uu - 2 * uuu) * c +
			    (u - 2 * uu + uuu) * ta[k] + (uuu - uu) * tb[k];
		if (d1 != NULL)
			d1[k] = (6 * u - 6 * uu) * c + (1 - 4 * u + 3 * uu) *
			    ta[k] + (3 * uu - 2 * u) * tb[k];
		if (d2 != NULL)
			d2[k] = (6 - 12 * u) * c + (6 * u - 4) * ta[k] +
			    (6 * u - 2) * tb[k];
	}
}

/*
 * Eq. 2: d2P/ds2 = P''/(P'.P') - (P'.P'') P' / (P'.P')^2.
 */
static void
curvature_plain(const double *d1, const double *d2, double dd, int dim,
    double *kn)
{
	double dq = vdot(d1, d2, dim);

	for (int k = 0; k < dim; k++)
		kn[k] = (d2[k] - dq / dd * d1[k]) / dd;
}

/*
 * Where P'.P' overflows or loses its digits to underflow (a curve far
 * outside the unit box), P' and P'' are scaled by the same power of two,
 * 2^-e, exactly: the curvature vector of the scaled derivatives is 2^e
 * times the true one, and scaling back by 2^-e is exact too.  Inside
 * VNORM_LO .. VNORM_HI (of P'.P') the plain formula stands, bit for bit.
 */
int
loft_curvature_vector(const double *d1, const double *d2, int dim, double *kn)
{
	double dd = vdot(d1, d1, dim), a[LOFT_MAXDIM], b[LOFT_MAXDIM];
	double m = vmaxabs(d1, dim);
	int e;

	if (!(m > 0) || !(m < INFINITY))
		return LOFT_EGEOM;
	if (dd >= VNORM_LO && dd <= VNORM_HI) {
		curvature_plain(d1, d2, dd, dim, kn);
		return 0;
	}
	e = ilogb(m);
	for (int k = 0; k < dim; k++) {
		a[k] = ldexp(d1[k], -e);
		b[k] = ldexp(d2[k], -e);
	}
	curvature_plain(a, b, vdot(a, a, dim), dim, kn);
	for (int k = 0; k < dim; k++)
		kn[k] = ldexp(kn[k], -e);
	return 0;
}

/*
 * Eq. 9, with cos(theta_A) = T_A . c/|c| and cos(theta_B) = T_B . c/|c|:
 *   |P'_A| = 2W / (1 + alpha cos(theta_B) + (1 - alpha) cos(theta_A))
 *   |P'_B| = 2W / (1 + alpha cos(theta_A) + (1 - alpha) cos(theta_B))
 * Eq. 11 is this with alpha = 2/3, P'_A = r_i T_i and P'_B = l_{i+1} T_{i+1}.
 * A denominator below NORMALISE_MIN means both tangents turn back along
 * the chord (theta near 180 degrees at both ends): the magnitude would be
 * beyond any sensible multiple of the chord.
 */
#define NORMALISE_MIN 1e-9

int
loft__normalise_cos(double w, double ca, double cb, double alpha, double *ma,
    double *mb)
{
	double da = 1 + alpha * cb + (1 - alpha) * ca;
	double db = 1 + alpha * ca + (1 - alpha) * cb;

	if (!(da > NORMALISE_MIN) || !(db > NORMALISE_MIN))
		return LOFT_EGEOM;
	*ma = 2 * w / da;
	*mb = 2 * w / db;
	return 0;
}

int
loft_normalise(const double *chord, const double *ta, const double *tb,
    int dim, double alpha, double *ma, double *mb)
{
	double w = vnorm(chord, dim);

	if (!(w > 0))
		return LOFT_EGEOM;
	return loft__normalise_cos(w, vdot(ta, chord, dim) / w,
	    vdot(tb, chord, dim) / w, alpha, ma, mb);
}
