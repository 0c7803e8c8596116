/*
 * step.c: STEP (ISO 10303-21, the AP214 automotive_design schema, which
 * OpenCASCADE, FreeCAD and Rhino read): every curve one
 * B_SPLINE_CURVE_WITH_KNOTS, every patch one B_SPLINE_SURFACE_WITH_KNOTS,
 * exactly (the Bezier pieces as a clamped B-spline whose parameter is
 * loft's), all in one GEOMETRIC_SET of a shape representation whose
 * length unit is tocad -u's.  A curve's name is its record's size= and
 * id=, as DXF's layers.  Curves in the plane get z = 0.
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
	return 0;
}

static int
step_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
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
step_surface(struct loft_cad_doc *d, const struct loft_bsurf *b)
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
	return add_item(s, n);
}

static int
step_end(struct loft_cad_doc *d)
{
	static const char *const unit[][2] = {
		{ "mm", ".MILLI.," }, { "cm", ".CENTI.," }, { "m", "$," },
	};
	struct step *s = d->state;
	const char *prefix = NULL;

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
	    "#20=SHAPE_REPRESENTATION('',(#21),#13);\n#21=GEOMETRIC_SET('',(");
	for (size_t i = 0; i < s->nitem; i++)
		put_long(d, i ? ",#%ld" : "#%ld", s->item[i]);
	loft_cad_puts(d, "));\n");
	loft_cad_to_head(d, 0);
	return 0;
}

static void
step_free(struct loft_cad_doc *d)
{
	struct step *s = d->state;

	if (s != NULL)
		free(s->item);
	free(s);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_step = {
	.name = "step", .title = "STEP",
	.begin = step_begin, .end = step_end, .begin_record = step_begin_record,
	.curve = step_curve, .surface = step_surface, .free = step_free,
};
