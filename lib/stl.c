/*
 * stl.c: STL, ASCII or binary (tocad -b): the surfaces of the input as
 * one triangle mesh that cad.c made (one step count for every patch and
 * vertices welded, so patches that share an edge leave no crack there,
 * and oriented consistently), each facet with its unit normal,
 * counter-clockwise seen from where the normal points.  Binary STL holds single-precision floats, little-endian.
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdint.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

/* The unit normal of triangle a, b, c (0 when it has no area). */
static void
normal(const double *a, const double *b, const double *c, double *n)
{
	double u[3], v[3], m;

	vsub(u, b, a, 3);
	vsub(v, c, a, 3);
	m = fmax(vmaxabs(u, 3), vmaxabs(v, 3));
	if (m > 0 && m < INFINITY) {
		/* by a power of two, exactly: the cross product of sides of
		 * 1e-200 or 1e200 would underflow or overflow (issue 28) */
		int e = ilogb(m);

		for (int k = 0; k < 3; k++) {
			u[k] = ldexp(u[k], -e);
			v[k] = ldexp(v[k], -e);
		}
	}
	n[0] = u[1] * v[2] - u[2] * v[1];
	n[1] = u[2] * v[0] - u[0] * v[2];
	n[2] = u[0] * v[1] - u[1] * v[0];
	if (vunit(n, 3) == 0 || !isfinite(n[0] + n[1] + n[2]))
		n[0] = n[1] = n[2] = 0;
}

static void
put_u32(struct loft_cad_doc *d, uint32_t x)
{
	unsigned char b[4];

	for (int i = 0; i < 4; i++)
		b[i] = (unsigned char)(x >> (8 * i));
	loft_cad_put(d, b, 4);
}

static void
put_float(struct loft_cad_doc *d, double x)
{
	float f = (float)x;
	uint32_t u;

	if (!isfinite(f)) {     /* beyond a float's range */
		d->out.bad = LOFT_EGEOM;
		return;
	}
	memcpy(&u, &f, 4);
	put_u32(d, u);
}

static void
put_triple(struct loft_cad_doc *d, const char *word, const double *p)
{
	loft_cad_puts(d, word);
	for (int k = 0; k < 3; k++) {
		loft_cad_puts(d, " ");
		loft_cad_putnum(d, p[k]);
	}
	loft_cad_puts(d, "\n");
}

static int
stl_mesh(struct loft_cad_doc *d, const double *v, size_t nv,
    const size_t *tri, size_t nt)
{
	static const char head[80] = "loft tocad: binary STL";
	double n[3];

	(void)nv;
	if (d->o.binary) {
		if (nt > UINT32_MAX)
			return LOFT_ENOMEM;
		loft_cad_put(d, head, sizeof head);
		put_u32(d, (uint32_t)nt);
	} else {
		loft_cad_puts(d, "solid loft\n");
	}
	for (size_t k = 0; k < nt; k++) {
		const double *a = v + 3 * tri[3 * k], *b = v + 3 * tri[3 * k + 1];
		const double *c = v + 3 * tri[3 * k + 2];

		normal(a, b, c, n);
		if (d->o.binary) {
			for (int q = 0; q < 3; q++)
				put_float(d, n[q]);
			for (int q = 0; q < 9; q++)
				put_float(d, (q < 3 ? a : q < 6 ? b : c)[q % 3]);
			loft_cad_put(d, "\0\0", 2);
			continue;
		}
		put_triple(d, "facet normal", n);
		loft_cad_puts(d, "outer loop\n");
		put_triple(d, "vertex", a);
		put_triple(d, "vertex", b);
		put_triple(d, "vertex", c);
		loft_cad_puts(d, "endloop\nendfacet\n");
	}
	if (!d->o.binary)
		loft_cad_puts(d, "endsolid loft\n");
	return 0;
}

const struct loft_cad_format loft_cad_stl = {
	.name = "stl", .title = "STL", .mesh = stl_mesh,
};
