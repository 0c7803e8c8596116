/*
 * step.c: STEP (ISO 10303-21, the AP214 automotive_design schema, which
 * OpenCASCADE, FreeCAD and Rhino read): every curve one
 * B_SPLINE_CURVE_WITH_KNOTS, every patch one B_SPLINE_SURFACE_WITH_KNOTS,
 * exactly (the Bezier pieces as a clamped B-spline whose parameter is
 * loft's).  Curves go in one GEOMETRIC_SET; patches are sewn into one
 * shell (stepshell below): an edge that two patches share is one
 * EDGE_CURVE between the same VERTEX_POINTs, so that a reader gets a
 * connected shell, and a closed one (every edge shared by two faces) is
 * a solid.  The shape representation's length unit is tocad -u's.  A
 * curve's name is its record's size= and id=, as DXF's layers.  Curves
 * in the plane get z = 0.
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

/* A patch kept for the shell: its surface entity and boundary. */
struct sface {
	long surf;              /* its B_SPLINE_SURFACE */
	int deg[4];             /* of its edges */
	double *edge[4];        /* their control points, see stepshell */
	long patch;             /* its index in the design, or -1 */
	char *name;
	long corner[4];         /* vertices, after welding */
	long use[4];            /* the edge each side is, or -1: none */
	int fwd[4];             /* the side runs along that edge's curve */
};

struct step {
	long next;              /* the next entity number */
	long *item;             /* the geometric set's members */
	size_t nitem, itemcap;
	const char *name;
	const struct loft_record *rec;  /* the record being written */
	double tol;                     /* its tolerance */
	struct sface *face;
	size_t nface, facecap;
	struct loft_design design;      /* the patches' links */
};

static void
put_real(struct loft_cad_doc *d, double x)
{
	char buf[LOFT_NUMBUF + 2];

	if (!isfinite(x)) {
		d->out.bad = LOFT_EGEOM;
		return;
	}
	loft_cad_put(d, buf, (size_t)loft_cad_real(buf, x));
}

static void
put_long(struct loft_cad_doc *d, const char *fmt, long v)
{
	char buf[48];

	snprintf(buf, sizeof buf, fmt, v);
	loft_cad_puts(d, buf);
}

/* "#n=CARTESIAN_POINT('',(x,y,z));"; returns n. */
static long
cartesian(struct loft_cad_doc *d, const double *p, int dim)
{
	struct step *s = d->state;
	long n = s->next++;

	put_long(d, "#%ld=CARTESIAN_POINT('',(", n);
	for (int k = 0; k < 3; k++) {
		if (k > 0)
			loft_cad_puts(d, ",");
		put_real(d, k < dim ? p[k] : 0);
	}
	loft_cad_puts(d, "));\n");
	return n;
}

/* "(#a,#a+1,...)" of count consecutive entities from first. */
static void
refs(struct loft_cad_doc *d, long first, size_t count)
{
	loft_cad_puts(d, "(");
	for (size_t i = 0; i < count; i++)
		put_long(d, i ? ",#%ld" : "#%ld", first + (long)i);
	loft_cad_puts(d, ")");
}

/* The knots of a Bezier of one piece per unit: "(d+1,d,...,d+1),(0.,1.,...)". */
static void
knots(struct loft_cad_doc *d, size_t npieces, int deg)
{
	for (int pass = 0; pass < 2; pass++) {
		loft_cad_puts(d, pass ? ",(" : "(");
		for (size_t i = 0; i <= npieces; i++) {
			if (i > 0)
				loft_cad_puts(d, ",");
			if (pass)
				put_real(d, (double)i);
			else
				put_long(d, "%ld", i == 0 || i == npieces ?
				    deg + 1 : deg);
		}
		loft_cad_puts(d, ")");
	}
}

static int
add_item(struct step *s, long n)
{
	if (loft__grow((void **)&s->item, &s->itemcap, s->nitem + 1,
	    sizeof *s->item) != 0)
		return LOFT_ENOMEM;
	s->item[s->nitem++] = n;
	return 0;
}

static int
step_begin(struct loft_cad_doc *d)
{
	struct step *s = calloc(1, sizeof *s);

	if (s == NULL)
		return LOFT_ENOMEM;
	s->next = 100;          /* #1..#99: the context, written last */
	d->state = s;
	return 0;
}

static int
step_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	((struct step *)d->state)->name = it->name;
	((struct step *)d->state)->rec = it->rec;
	((struct step *)d->state)->tol = it->tol;
	return 0;
}

static int
write_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	struct step *s = d->state;
	size_t np = c->npieces * (size_t)c->deg + 1;
	long first = s->next, n;

	for (size_t k = 0; k < np; k++)
		cartesian(d, loft_cad_ctl(c, k), c->dim);
	n = s->next++;
	put_long(d, "#%ld=B_SPLINE_CURVE_WITH_KNOTS('", n);
	loft_cad_puts(d, s->name);
	put_long(d, "',%ld,", c->deg);
	refs(d, first, np);
	loft_cad_puts(d, ",.UNSPECIFIED.,.F.,.F.,");
	knots(d, c->npieces, c->deg);
	loft_cad_puts(d, ",.UNSPECIFIED.);\n");
	return add_item(s, n);
}

static int keep_face(struct step *s, const struct loft_bsurf *b, long surf);

static int
write_surface(struct loft_cad_doc *d, const struct loft_bsurf *b)
{
	struct step *s = d->state;
	long first = s->next, n;
	size_t w = (size_t)b->n + 1;

	for (size_t k = 0; k < (size_t)(b->m + 1) * w; k++)
		cartesian(d, b->ctl + 3 * k, 3);
	n = s->next++;
	put_long(d, "#%ld=B_SPLINE_SURFACE_WITH_KNOTS('", n);
	loft_cad_puts(d, s->name);
	put_long(d, "',%ld,", b->m);
	put_long(d, "%ld,(", b->n);
	for (int i = 0; i <= b->m; i++) {       /* rows: u index */
		if (i > 0)
			loft_cad_puts(d, ",");
		refs(d, first + (long)(i * w), w);
	}
	loft_cad_puts(d, "),.UNSPECIFIED.,.F.,.F.,.F.,");
	/* u multiplicities, v multiplicities, u knots, v knots */
	put_long(d, "(%ld,", b->m + 1);
	put_long(d, "%ld),", b->m + 1);
	put_long(d, "(%ld,", b->n + 1);
	put_long(d, "%ld),(0.,1.),(0.,1.),.UNSPECIFIED.);\n", b->n + 1);
	return keep_face(s, b, n);
}

/* A curve or a patch, as cubics where its degree is above what readers
 * take (the patch's links are then not kept). */
static int
step_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	return loft_cad_curve_limited(d, c, ((struct step *)d->state)->tol,
	    write_curve);
}

static int
step_surface(struct loft_cad_doc *d, const struct loft_bsurf *b)
{
	struct step *s = d->state;

	if (b->m > LOFT_CAD_MAXDEG || b->n > LOFT_CAD_MAXDEG)
		s->rec = NULL;
	return loft_cad_surface_limited(d, b, s->tol, write_surface);
}

/* ---- the shell ------------------------------------------------------- */

/*
 * A patch's sides, in the order its loop runs them, counterclockwise
 * in (u, v), so that the face's normal is f_u x f_v: side 0 is v = 0,
 * 1 is u = 1, 2 is v = 1 and 3 is u = 0.  Each side's curve is kept in
 * the direction of its surface parameter (u on sides 0 and 2, v on 1
 * and 3), from corner sfrom to corner sto (corners 0 (0,0), 1 (1,0),
 * 2 (1,1), 3 (0,1)); the loop runs sides 2 and 3 backwards.
 */
static const int sfrom[4] = { 0, 1, 3, 0 }, sto[4] = { 1, 2, 2, 3 };
/* The side of each loft_edge (u0, u1, v0, v1). */
static const int side_of[4] = { 3, 1, 0, 2 };

/* Keep the patch b, written as entity surf, for the shell. */
static int
keep_face(struct step *s, const struct loft_bsurf *b, long surf)
{
	struct sface *f;
	struct loft_error err;
	int m = b->m, n = b->n;

	if (loft__grow((void **)&s->face, &s->facecap, s->nface + 1,
	    sizeof *s->face) != 0)
		return LOFT_ENOMEM;
	f = memset(s->face + s->nface, 0, sizeof *s->face);
	f->surf = surf;
	f->patch = -1;
	if ((f->name = malloc(strlen(s->name) + 1)) == NULL)
		return LOFT_ENOMEM;
	strcpy(f->name, s->name);
	s->nface++;
	for (int e = 0; e < 4; e++) {
		int deg = e % 2 ? n : m;

		f->deg[e] = deg;
		if ((f->edge[e] = malloc(3 * (size_t)(deg + 1) *
		    sizeof *f->edge[e])) == NULL)
			return LOFT_ENOMEM;
		for (int k = 0; k <= deg; k++) {
			int i = e == 0 || e == 2 ? k : e == 1 ? m : 0;
			int j = e == 1 || e == 3 ? k : e == 2 ? n : 0;

			memcpy(f->edge[e] + 3 * k, b->ctl + 3 * (i * (n + 1) +
			    j), 3 * sizeof *b->ctl);
		}
	}
	/* a patch with an id: its links say which sides are shared */
	if (s->rec != NULL && loft_record_is(s->rec, LOFT_KIND_MEMBER) &&
	    loft_attr(s->rec, "id") != NULL &&
	    loft_design_add(&s->design, s->rec, &err) == 0) {
		s->design.p[s->design.n - 1].rec = NULL;
		f->patch = (long)s->design.n - 1;
	}
	return 0;
}

/* The point of corner c of face f: the first or last of a side. */
static const double *
corner_pt(const struct sface *f, int c)
{
	return c == 0 ? f->edge[0] : c == 1 ? f->edge[1] : c == 2 ?
	    f->edge[1] + 3 * f->deg[1] : f->edge[3] + 3 * f->deg[3];
}

static long
root(long *up, long v)
{
	while (up[v] != v)
		v = up[v] = up[up[v]];
	return v;
}

static void
join(long *up, long a, long b)
{
	a = root(up, a);
	b = root(up, b);
	if (a != b)
		up[a > b ? a : b] = a < b ? a : b;
}

/* Order of corners by their points, for welding equal ones. */
static const struct step *sort_s;
static int
cmp_corner(const void *a, const void *b)
{
	long x = *(const long *)a, y = *(const long *)b;
	const double *p = corner_pt(sort_s->face + x / 4, (int)(x % 4));
	const double *q = corner_pt(sort_s->face + y / 4, (int)(y % 4));

	for (int k = 0; k < 3; k++)
		if (p[k] != q[k])
			return p[k] < q[k] ? -1 : 1;
	return 0;
}

/* The face of design patch index ip, or -1. */
static long
face_of_patch(const struct step *s, long ip)
{
	for (size_t i = 0; i < s->nface; i++)
		if (s->face[i].patch == ip)
			return (long)i;
	return -1;
}

/*
 * Weld corners: those at the same point, and those that the patches'
 * links put together (a link over a whole side: its ends meet the
 * neighbour's side's ends, the same way round when it runs from 0 to
 * 1).  force[4 f + e] is then 4 g + e' + 1 for the side it is shared
 * with, so that the sides are one edge even where rounding made their
 * points differ; 0 otherwise.
 */
static void
weld(struct step *s, long *up, long *force)
{
	size_t nc = 4 * s->nface;
	long *ord = malloc(nc * sizeof *ord);

	for (size_t i = 0; i < nc; i++)
		up[i] = (long)i, force[i] = 0;
	if (ord != NULL) {
		for (size_t i = 0; i < nc; i++)
			ord[i] = (long)i;
		sort_s = s;
		qsort(ord, nc, sizeof *ord, cmp_corner);
		for (size_t i = 1; i < nc; i++)
			if (cmp_corner(ord + i - 1, ord + i) == 0)
				join(up, ord[i - 1], ord[i]);
		free(ord);
	}
	for (size_t f = 0; f < s->nface; f++) {
		const struct loft_patch *p;

		if (s->face[f].patch < 0)
			continue;
		p = s->design.p + s->face[f].patch;
		for (int le = 0; le < 4; le++) {
			const struct loft_link *L = p->link[le];
			long g, ip;
			int e = side_of[le], ge = -1;

			if (p->nlink[le] != 1 || fmin(L->a, L->b) != 0 ||
			    fmax(L->a, L->b) != 1 || (ip = loft_design_find(
			    &s->design, L->id)) < 0 || (g = face_of_patch(s,
			    ip)) < 0)
				continue;
			for (int k = 0; k < 4; k++)
				if (s->design.p[ip].nlink[k] == 1 &&
				    s->design.p[ip].link[k]->id == p->id)
					ge = side_of[k];
			if (ge < 0)
				continue;
			join(up, 4 * (long)f + sfrom[e], 4 * g + (L->a == 0 ?
			    sfrom[ge] : sto[ge]));
			join(up, 4 * (long)f + sto[e], 4 * g + (L->a == 0 ?
			    sto[ge] : sfrom[ge]));
			force[4 * f + (size_t)e] = 4 * g + ge + 1;
		}
	}
}

/* Whether side e of f has all its points at one place (a pole). */
static int
degenerate(const struct sface *f, int e)
{
	for (int k = 1; k <= f->deg[e]; k++)
		if (memcmp(f->edge[e], f->edge[e] + 3 * k, 3 * sizeof(double)))
			return 0;
	return 1;
}

/* Whether sides (f, e) and (g, h) have the same points, the same way
 * round (same 1) or the other (same 0). */
static int
same_points(const struct sface *f, int e, const struct sface *g, int h,
    int same)
{
	int d = f->deg[e];

	if (g->deg[h] != d)
		return 0;
	for (int k = 0; k <= d; k++)
		if (memcmp(f->edge[e] + 3 * k, g->edge[h] + 3 * (same ? k :
		    d - k), 3 * sizeof(double)))
			return 0;
	return 1;
}

struct sedge {
	long from, to;          /* welded corners */
	long face;              /* whose side gives its curve */
	int side, uses;
	long ent;               /* its EDGE_CURVE */
};

/* The edge side (f, e) is: an earlier one it is forced or found to be,
 * or a new one; -1 when out of memory. */
static long
edge_for(struct step *s, long *up, const long *force, struct sedge **E,
    size_t *ne, size_t *cap, size_t f, int e)
{
	struct sface *F = s->face + f;
	long a = root(up, 4 * (long)f + sfrom[e]), b = root(up, 4 * (long)f +
	    sto[e]), fz = force[4 * f + (size_t)e] - 1;

	for (size_t k = 0; k < *ne; k++) {
		struct sedge *x = *E + k;
		const struct sface *G = s->face + x->face;
		int same;

		if (!((x->from == a && x->to == b) || (x->from == b &&
		    x->to == a)) || x->uses >= 2)
			continue;
		same = x->from == a && (a != b || same_points(F, e, G, x->side,
		    1));
		if ((fz >= 0 && fz / 4 == x->face && fz % 4 == x->side) ||
		    same_points(F, e, G, x->side, same)) {
			x->uses++;
			F->fwd[e] = same;
			return (long)k;
		}
	}
	if (loft__grow((void **)E, cap, *ne + 1, sizeof **E) != 0)
		return -1;
	(*E)[*ne] = (struct sedge){ a, b, (long)f, e, 1, 0 };
	F->fwd[e] = 1;
	return (long)(*ne)++;
}

/* "#n=ORIENTED_EDGE(...)" of side e of f; returns n. */
static long
oriented(struct loft_cad_doc *d, const struct sface *f, int e,
    const struct sedge *E)
{
	struct step *s = d->state;
	long n = s->next++;

	put_long(d, "#%ld=ORIENTED_EDGE('',*,*,", n);
	put_long(d, "#%ld,", E[f->use[e]].ent);
	loft_cad_puts(d, f->fwd[e] == (e < 2) ? ".T.);\n" : ".F.);\n");
	return n;
}

/* The vertices and edges of the shell, written. */
static void
put_edges(struct loft_cad_doc *d, struct sedge *E, size_t ne)
{
	struct step *s = d->state;
	long *vent = calloc(4 * s->nface, sizeof *vent);

	if (vent == NULL) {
		d->out.bad = LOFT_ENOMEM;
		return;
	}
	for (size_t k = 0; k < ne; k++) {
		struct sedge *x = E + k;
		const struct sface *F = s->face + x->face;
		long c[2] = { x->from, x->to }, first;

		for (int j = 0; j < 2; j++)
			if (vent[c[j]] == 0) {
				long p = cartesian(d, corner_pt(s->face + c[j] / 4,
				    (int)(c[j] % 4)), 3);

				vent[c[j]] = s->next++;
				put_long(d, "#%ld=VERTEX_POINT('',", vent[c[j]]);
				put_long(d, "#%ld);\n", p);
			}
		first = s->next;
		for (int j = 0; j <= F->deg[x->side]; j++)
			cartesian(d, F->edge[x->side] + 3 * j, 3);
		put_long(d, "#%ld=B_SPLINE_CURVE_WITH_KNOTS('',", s->next);
		put_long(d, "%ld,", F->deg[x->side]);
		refs(d, first, (size_t)F->deg[x->side] + 1);
		loft_cad_puts(d, ",.UNSPECIFIED.,.F.,.F.,");
		knots(d, 1, F->deg[x->side]);
		loft_cad_puts(d, ",.UNSPECIFIED.);\n");
		x->ent = s->next + 1;
		put_long(d, "#%ld=EDGE_CURVE('',", x->ent);
		put_long(d, "#%ld,", vent[x->from]);
		put_long(d, "#%ld,", vent[x->to]);
		put_long(d, "#%ld,.T.);\n", s->next);
		s->next += 2;
	}
	free(vent);
}

/* The face f's loop and face; returns the ADVANCED_FACE's number. */
static long
put_face(struct loft_cad_doc *d, const struct sface *f, const struct sedge *E)
{
	struct step *s = d->state;
	long oe[4], n = 0, loop, bound, face;

	for (int e = 0; e < 4; e++)
		if (f->use[e] >= 0)
			oe[n++] = oriented(d, f, e, E);
	loop = s->next++;
	put_long(d, "#%ld=EDGE_LOOP('',(", loop);
	for (long k = 0; k < n; k++)
		put_long(d, k ? ",#%ld" : "#%ld", oe[k]);
	loft_cad_puts(d, "));\n");
	bound = s->next++;
	put_long(d, "#%ld=FACE_OUTER_BOUND('',", bound);
	put_long(d, "#%ld,.T.);\n", loop);
	face = s->next++;
	put_long(d, "#%ld=ADVANCED_FACE('", face);
	loft_cad_puts(d, f->name);
	put_long(d, "',(#%ld),", bound);
	put_long(d, "#%ld,.T.);\n", f->surf);
	return face;
}

/*
 * Sew the patches into one shell and write it: corners welded, each
 * side an edge shared with the side it meets, loops, faces; a closed
 * shell (every edge in two faces) as a solid.  A patch whose sides are
 * all points goes in the geometric set instead.  Returns the model's
 * entity (MANIFOLD_SOLID_BREP or SHELL_BASED_SURFACE_MODEL), or 0.
 */
static long
sew(struct loft_cad_doc *d)
{
	struct step *s = d->state;
	size_t nc = 4 * s->nface, ne = 0, cap = 0, nf = 0;
	long *up = malloc(nc * sizeof *up), *force = malloc(nc * sizeof *force);
	long *fent = malloc(s->nface * sizeof *fent), shell = 0, model = 0;
	struct sedge *E = NULL;
	int closed = 1;

	if (up == NULL || force == NULL || fent == NULL)
		goto oom;
	weld(s, up, force);
	for (size_t f = 0; f < s->nface; f++)
		for (int e = 0; e < 4; e++)
			if ((s->face[f].use[e] = degenerate(s->face + f, e) ? -1 :
			    edge_for(s, up, force, &E, &ne, &cap, f, e)) < -1 ||
			    (!degenerate(s->face + f, e) && s->face[f].use[e] < 0))
				goto oom;
	put_edges(d, E, ne);
	for (size_t k = 0; k < ne; k++)
		closed &= E[k].uses == 2;
	for (size_t f = 0; f < s->nface; f++) {
		const struct sface *F = s->face + f;

		if (F->use[0] < 0 && F->use[1] < 0 && F->use[2] < 0 &&
		    F->use[3] < 0) {
			if (add_item(s, F->surf) != 0)
				goto oom;
			continue;
		}
		fent[nf++] = put_face(d, F, E);
	}
	if (nf > 0) {
		shell = s->next++;
		put_long(d, closed && ne > 0 ? "#%ld=CLOSED_SHELL('',(" :
		    "#%ld=OPEN_SHELL('',(", shell);
		for (size_t k = 0; k < nf; k++)
			put_long(d, k ? ",#%ld" : "#%ld", fent[k]);
		loft_cad_puts(d, "));\n");
		model = s->next++;
		put_long(d, closed && ne > 0 ? "#%ld=MANIFOLD_SOLID_BREP('',"
		    : "#%ld=SHELL_BASED_SURFACE_MODEL('',(", model);
		put_long(d, closed && ne > 0 ? "#%ld);\n" : "#%ld));\n", shell);
	}
	free(up);
	free(force);
	free(fent);
	free(E);
	return model;
oom:
	free(up);
	free(force);
	free(fent);
	free(E);
	d->out.bad = LOFT_ENOMEM;
	return 0;
}

static int
step_end(struct loft_cad_doc *d)
{
	static const char *const unit[][2] = {
		{ "mm", ".MILLI.," }, { "cm", ".CENTI.," }, { "m", "$," },
	};
	struct step *s = d->state;
	const char *prefix = NULL;
	long model = s->nface > 0 ? sew(d) : 0;
	int nitems = 0;

	for (size_t i = 0; i < sizeof unit / sizeof unit[0]; i++)
		if (strcmp(d->o.unit_name, unit[i][0]) == 0)
			prefix = unit[i][1];
	loft_cad_puts(d, "ENDSEC;\nEND-ISO-10303-21;\n");
	loft_cad_to_head(d, 1);
	loft_cad_puts(d, "ISO-10303-21;\nHEADER;\n"
	    "FILE_DESCRIPTION(('loft tocad: exact B-spline curves and "
	    "surfaces'),'2;1');\n"
	    "FILE_NAME('','',(''),(''),'loft tocad','loft','');\n"
	    "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
	    "ENDSEC;\nDATA;\n"
	    "#1=APPLICATION_CONTEXT('automotive design');\n"
	    "#2=APPLICATION_PROTOCOL_DEFINITION('international standard',"
	    "'automotive_design',2000,#1);\n"
	    "#3=PRODUCT_CONTEXT('',#1,'mechanical');\n"
	    "#4=PRODUCT('loft','loft','',(#3));\n"
	    "#5=PRODUCT_DEFINITION_FORMATION('','',#4);\n"
	    "#6=PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');\n"
	    "#7=PRODUCT_DEFINITION('design','',#5,#6);\n"
	    "#8=PRODUCT_DEFINITION_SHAPE('','',#7);\n"
	    "#9=SHAPE_DEFINITION_REPRESENTATION(#8,#20);\n");
	if (prefix != NULL) {
		loft_cad_puts(d, "#10=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(");
		loft_cad_puts(d, prefix);
		loft_cad_puts(d, ".METRE.));\n");
	} else {        /* inches: a conversion of the metre */
		loft_cad_puts(d, "#15=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,"
		    ".METRE.));\n#16=LENGTH_MEASURE_WITH_UNIT("
		    "LENGTH_MEASURE(0.0254),#15);\n#17=DIMENSIONAL_EXPONENTS("
		    "1.,0.,0.,0.,0.,0.,0.);\n#10=(CONVERSION_BASED_UNIT('INCH',"
		    "#16)LENGTH_UNIT()NAMED_UNIT(#17));\n");
	}
	loft_cad_puts(d, "#11=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,"
	    ".RADIAN.));\n"
	    "#12=(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());\n"
	    "#13=(GEOMETRIC_REPRESENTATION_CONTEXT(3)"
	    "GLOBAL_UNIT_ASSIGNED_CONTEXT((#10,#11,#12))"
	    "REPRESENTATION_CONTEXT('',''));\n"
	    "#20=SHAPE_REPRESENTATION('',(");
	if (s->nitem > 0)
		put_long(d, nitems++ ? ",#%ld" : "#%ld", 21);
	if (model > 0)
		put_long(d, nitems++ ? ",#%ld" : "#%ld", model);
	loft_cad_puts(d, "),#13);\n");
	if (s->nitem > 0) {
		loft_cad_puts(d, "#21=GEOMETRIC_SET('',(");
		for (size_t i = 0; i < s->nitem; i++)
			put_long(d, i ? ",#%ld" : "#%ld", s->item[i]);
		loft_cad_puts(d, "));\n");
	}
	loft_cad_to_head(d, 0);
	return 0;
}

static void
step_free(struct loft_cad_doc *d)
{
	struct step *s = d->state;

	if (s != NULL) {
		free(s->item);
		for (size_t i = 0; i < s->nface; i++) {
			free(s->face[i].name);
			for (int e = 0; e < 4; e++)
				free(s->face[i].edge[e]);
		}
		free(s->face);
		loft_design_free(&s->design);
	}
	free(s);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_step = {
	.name = "step", .title = "STEP",
	.begin = step_begin, .end = step_end, .begin_record = step_begin_record,
	.curve = step_curve, .surface = step_surface, .free = step_free,
};
