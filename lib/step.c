/*
 * step.c: STEP (ISO 10303-21, the AP214 automotive_design schema, which
 * OpenCASCADE, FreeCAD and Rhino read): every curve one
 * B_SPLINE_CURVE_WITH_KNOTS, every patch one B_SPLINE_SURFACE_WITH_KNOTS,
 * exactly (the Bezier pieces as a clamped B-spline whose parameter is
 * loft's).  Curves go in one GEOMETRIC_SET; patches are sewn into one
 * shell (sewing.c): an edge that two patches share is one
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

struct step {
	long next;              /* the next entity number */
	long *item;             /* the geometric set's members */
	size_t nitem, itemcap;
	const char *name;
	const struct loft_record *rec;  /* the record being written */
	double tol;                     /* its tolerance */
	struct loft_sew sew;            /* the patches, for the shell */
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
	return loft_sew_add(&s->sew, b, s->rec, s->name, n);
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

/* ---- the shell (sewn by sewing.c) ------------------------------------ */

/* "#n=ORIENTED_EDGE(...)" of side e of f; returns n. */
static long
oriented(struct loft_cad_doc *d, const struct loft_sew_face *f, int e)
{
	struct step *s = d->state;
	long n = s->next++;

	put_long(d, "#%ld=ORIENTED_EDGE('',*,*,", n);
	put_long(d, "#%ld,", s->sew.edge[f->edge[e]].ent);
	loft_cad_puts(d, f->fwd[e] ? ".T.);\n" : ".F.);\n");
	return n;
}

/* The vertices and edges of the shell, written. */
static void
put_edges(struct loft_cad_doc *d)
{
	struct step *s = d->state;
	struct loft_sew *w = &s->sew;
	long *vent = calloc(w->nvert + 1, sizeof *vent);

	if (vent == NULL) {
		d->out.bad = LOFT_ENOMEM;
		return;
	}
	for (size_t k = 0; k < w->nedge; k++) {
		struct loft_sew_edge *x = w->edge + k;
		const struct loft_sew_face *F = w->face + x->face;
		long c[2] = { x->from, x->to }, first;

		for (int j = 0; j < 2; j++)
			if (vent[c[j]] == 0) {
				long p = cartesian(d, w->vert + 3 * c[j], 3);

				vent[c[j]] = s->next++;
				put_long(d, "#%ld=VERTEX_POINT('',", vent[c[j]]);
				put_long(d, "#%ld);\n", p);
			}
		first = s->next;
		for (int j = 0; j <= F->deg[x->side]; j++)
			cartesian(d, F->side[x->side] + 3 * j, 3);
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

/*
 * The face f's loop and face; returns the ADVANCED_FACE's number.  In a
 * closed shell whose surfaces' normals point in (its volume negative),
 * each face is the other way round from its surface, and so its bound:
 * the solid is not inside out.
 */
static long
put_face(struct loft_cad_doc *d, const struct loft_sew_face *f)
{
	struct step *s = d->state;
	long oe[4], n = 0, loop, bound, face;
	const char *sense = !s->sew.closed || s->sew.volume >= 0 ?
	    ".T.);\n" : ".F.);\n";

	for (int e = 0; e < 4; e++)
		if (f->edge[e] >= 0)
			oe[n++] = oriented(d, f, e);
	loop = s->next++;
	put_long(d, "#%ld=EDGE_LOOP('',(", loop);
	for (long k = 0; k < n; k++)
		put_long(d, k ? ",#%ld" : "#%ld", oe[k]);
	loft_cad_puts(d, "));\n");
	bound = s->next++;
	put_long(d, "#%ld=FACE_OUTER_BOUND('',", bound);
	put_long(d, "#%ld,", loop);
	loft_cad_puts(d, sense);
	face = s->next++;
	put_long(d, "#%ld=ADVANCED_FACE('", face);
	loft_cad_puts(d, f->name);
	put_long(d, "',(#%ld),", bound);
	put_long(d, "#%ld,", f->surf);
	loft_cad_puts(d, sense);
	return face;
}

/*
 * Sew the patches into one shell (sewing.c) and write it: vertices,
 * edges, loops, faces; a closed shell (every edge in two faces) as a
 * solid.  A patch whose sides are all points goes in the geometric set
 * instead.  Returns the model's entity (MANIFOLD_SOLID_BREP or
 * SHELL_BASED_SURFACE_MODEL), or 0.
 */
static long
sew(struct loft_cad_doc *d)
{
	struct step *s = d->state;
	struct loft_sew *w = &s->sew;
	long *fent = malloc(w->nface * sizeof *fent), shell = 0, model = 0;
	size_t nf = 0;
	int closed;

	if (fent == NULL || loft_sew_run(w) != 0)
		goto oom;
	closed = w->closed;
	put_edges(d);
	for (size_t f = 0; f < w->nface; f++) {
		const struct loft_sew_face *F = w->face + f;

		if (F->edge[0] < 0 && F->edge[1] < 0 && F->edge[2] < 0 &&
		    F->edge[3] < 0) {
			if (add_item(s, F->surf) != 0)
				goto oom;
			continue;
		}
		fent[nf++] = put_face(d, F);
	}
	if (nf > 0) {
		shell = s->next++;
		put_long(d, closed ? "#%ld=CLOSED_SHELL('',(" :
		    "#%ld=OPEN_SHELL('',(", shell);
		for (size_t k = 0; k < nf; k++)
			put_long(d, k ? ",#%ld" : "#%ld", fent[k]);
		loft_cad_puts(d, "));\n");
		model = s->next++;
		put_long(d, closed ? "#%ld=MANIFOLD_SOLID_BREP(''," :
		    "#%ld=SHELL_BASED_SURFACE_MODEL('',(", model);
		put_long(d, closed ? "#%ld);\n" : "#%ld));\n", shell);
	}
	free(fent);
	return model;
oom:
	free(fent);
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
	long model = s->sew.nface > 0 ? sew(d) : 0;
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
		loft_sew_free(&s->sew);
	}
	free(s);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_step = {
	.name = "step", .title = "STEP",
	.begin = step_begin, .end = step_end, .begin_record = step_begin_record,
	.curve = step_curve, .surface = step_surface, .free = step_free,
};
