/*
 * iges.c: IGES 5.3 (fixed 80-column records): every curve one rational
 * B-spline curve, entity 126, every patch one rational B-spline surface,
 * entity 128, both flagged polynomial (all weights 1) and exact: the
 * Bezier pieces as a clamped B-spline whose parameter is loft's.  The
 * patches are sewn into one shell (sewing.c) of IGES's B-rep entities:
 * faces (510) of the 128s, each with one loop (508) of edges from one
 * edge list (504) between the vertices of one vertex list (502), an edge
 * that two patches share named by both loops; a closed shell (514 form
 * 1) in a manifold solid (186), an open one (514 form 2) alone.  Units
 * from tocad -u.  The dates of the global section are fixed, so the same
 * input gives the same file.  Curves in the plane get z = 0.
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdlib.h>
#include <string.h>

#include "loftcad.h"
#include "internal.h"

#define DATA_COLS 64            /* of a parameter line, then its DE pointer */
#define GLOBAL_COLS 72

/* A directory entry's status number: independent, or physically
 * dependent (subordinate: used by another entity, not a whole of its
 * own), both as geometry. */
#define INDEPENDENT "00000000"
#define SUBORDINATE "00010000"
#define DE_LINE 81              /* bytes of a directory line, '\n' too */

struct iges {
	struct loft_writer dir;         /* the directory entry lines */
	long nde;                       /* directory lines so far */
	long np;                        /* parameter lines so far */
	char line[DATA_COLS + 1];       /* the parameter line being filled */
	int len;
	long first;                     /* the entity's first parameter line */
	double tol;                     /* the record's tolerance */
	const struct loft_record *rec;  /* the record being written */
	const char *name;
	struct loft_sew sew;            /* the patches, for the shell */
};

/* Close the parameter line being filled. */
static void
flush_param(struct loft_cad_doc *d)
{
	struct iges *g = d->state;
	char buf[160];

	snprintf(buf, sizeof buf, "%-*s %7ldP%7ld\n", DATA_COLS, g->line,
	    g->nde + 1, ++g->np);
	loft_cad_puts(d, buf);
	g->len = 0;
	g->line[0] = '\0';
}

/* One parameter and its delimiter, on the current line if it fits. */
static void
param(struct loft_cad_doc *d, const char *tok, char delim)
{
	struct iges *g = d->state;
	int n = (int)strlen(tok);

	if (g->len + n + 1 > DATA_COLS)
		flush_param(d);
	memcpy(g->line + g->len, tok, (size_t)n);
	g->len += n;
	g->line[g->len++] = delim;
	g->line[g->len] = '\0';
}

static void
param_int(struct loft_cad_doc *d, long v)
{
	char buf[32];

	snprintf(buf, sizeof buf, "%ld", v);
	param(d, buf, ',');
}

static void
param_real(struct loft_cad_doc *d, double x)
{
	char buf[LOFT_NUMBUF + 2];

	if (!isfinite(x)) {
		d->out.bad = LOFT_EGEOM;
		return;
	}
	loft_cad_real(buf, x);
	param(d, buf, ',');
}

/* The entity's last parameter, the one just put, ends it with ';';
 * then its directory entry, of form and status.  Returns the entry's
 * number (its first directory line), or -1 when out of memory. */
static long
end_entity(struct loft_cad_doc *d, int type, int form, const char *status)
{
	struct iges *g = d->state;
	char de[400];
	long de1 = g->nde + 1;

	g->line[g->len - 1] = ';';
	flush_param(d);
	snprintf(de, sizeof de, "%8d%8ld%8d%8d%8d%8d%8d%8d%8sD%7ld\n"
	    "%8d%8d%8d%8ld%8d%8s%8s%8s%8dD%7ld\n", type, g->first, 0, 0, 0, 0,
	    0, 0, status, de1, type, 0, 0, g->np - g->first + 1, form, "", "",
	    "", 0, de1 + 1);
	loft_put_type(&g->dir, de);
	g->nde += 2;
	g->first = g->np + 1;
	return g->dir.bad ? -1 : de1;
}

/* Make the entry de subordinate, after it was written. */
static void
set_subordinate(struct iges *g, long de)
{
	size_t at = (size_t)(de - 1) * DE_LINE + 64;

	if (at + 8 <= g->dir.len)
		memcpy(g->dir.buf + at, SUBORDINATE, 8);
}

static int
iges_begin(struct loft_cad_doc *d)
{
	struct iges *g = calloc(1, sizeof *g);

	if (g == NULL)
		return LOFT_ENOMEM;
	g->first = 1;
	d->state = g;
	return 0;
}

/* 126: K, M, planar, closed, polynomial, periodic, knots, weights,
 * control points, the parameter range, the plane's normal; of status
 * st.  Returns the entry's number, or -1 when out of memory. */
static long
put_curve(struct loft_cad_doc *d, const struct loft_bcurve *c, const char *st)
{
	size_t np = c->npieces * (size_t)c->deg + 1;

	param_int(d, 126);
	param_int(d, (long)np - 1);
	param_int(d, c->deg);
	param_int(d, c->dim == 2);
	param_int(d, 0);
	param_int(d, 1);
	param_int(d, 0);
	for (size_t i = 0; i <= c->npieces; i++)
		for (int r = 0; r < (i == 0 || i == c->npieces ? c->deg + 1 :
		    c->deg); r++)
			param_real(d, (double)i);
	for (size_t k = 0; k < np; k++)
		param_real(d, 1);
	for (size_t k = 0; k < np; k++) {
		const double *p = loft_cad_ctl(c, k);

		for (int q = 0; q < 3; q++)
			param_real(d, q < c->dim ? p[q] : 0);
	}
	param_real(d, 0);
	param_real(d, (double)c->npieces);
	param_real(d, 0);
	param_real(d, 0);
	param_real(d, c->dim == 2 ? 1 : 0);
	return end_entity(d, 126, 0, st);
}

static int
write_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	return put_curve(d, c, INDEPENDENT) < 0 ? LOFT_ENOMEM : 0;
}

/* 128: K1, K2, M1, M2, closed and periodic flags, knots in u and v,
 * weights, control points with the u index running fastest, the range. */
static int
write_surface(struct loft_cad_doc *d, const struct loft_bsurf *s)
{
	struct iges *g = d->state;
	long de;

	param_int(d, 128);
	param_int(d, s->m);
	param_int(d, s->n);
	param_int(d, s->m);
	param_int(d, s->n);
	param_int(d, 0);
	param_int(d, 0);
	param_int(d, 1);
	param_int(d, 0);
	param_int(d, 0);
	for (int dir = 0; dir < 2; dir++)
		for (int k = 0; k < 2 * ((dir ? s->n : s->m) + 1); k++)
			param_real(d, k > (dir ? s->n : s->m));
	for (int k = 0; k < (s->m + 1) * (s->n + 1); k++)
		param_real(d, 1);
	for (int j = 0; j <= s->n; j++)
		for (int i = 0; i <= s->m; i++)
			for (int q = 0; q < 3; q++)
				param_real(d, s->ctl[3 * (i * (s->n + 1) + j) + q]);
	param_real(d, 0);
	param_real(d, 1);
	param_real(d, 0);
	param_real(d, 1);
	if ((de = end_entity(d, 128, 0, INDEPENDENT)) < 0)
		return LOFT_ENOMEM;
	return loft_sew_add(&g->sew, s, g->rec, g->name, de);
}

static int
iges_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	struct iges *g = d->state;

	g->tol = it->tol;
	g->rec = it->rec;
	g->name = it->name;
	return 0;
}

/* A curve or a patch, as cubics where its degree is above what readers
 * take (LOFT_CAD_MAXDEG). */
static int
iges_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
{
	return loft_cad_curve_limited(d, c, ((struct iges *)d->state)->tol,
	    write_curve);
}

static int
iges_surface(struct loft_cad_doc *d, const struct loft_bsurf *s)
{
	struct iges *g = d->state;

	if (s->m > LOFT_CAD_MAXDEG || s->n > LOFT_CAD_MAXDEG)
		g->rec = NULL;
	return loft_cad_surface_limited(d, s, g->tol, write_surface);
}

/* ---- the shell (sewn by sewing.c) ------------------------------------ */

/* Each edge's curve, a 126 of one Bezier piece over [0, 1]; the vertex
 * list (502) and the edge list (504), whose edge k runs from vertex
 * from + 1 to vertex to + 1 of the list.  Returns the 504's entry, or
 * -1 when out of memory. */
static long
put_edges(struct loft_cad_doc *d)
{
	struct iges *g = d->state;
	struct loft_sew *w = &g->sew;
	long vl;

	for (size_t k = 0; k < w->nedge; k++) {
		struct loft_sew_edge *x = w->edge + k;
		const struct loft_sew_face *F = w->face + x->face;
		struct loft_bcurve c = { F->side[x->side], 1, F->deg[x->side],
		    3, 0 };

		if ((x->ent = put_curve(d, &c, SUBORDINATE)) < 0)
			return -1;
	}
	param_int(d, 502);
	param_int(d, (long)w->nvert);
	for (size_t i = 0; i < 3 * w->nvert; i++)
		param_real(d, w->vert[i]);
	if ((vl = end_entity(d, 502, 1, SUBORDINATE)) < 0)
		return -1;
	param_int(d, 504);
	param_int(d, (long)w->nedge);
	for (size_t k = 0; k < w->nedge; k++) {
		param_int(d, w->edge[k].ent);
		param_int(d, vl);
		param_int(d, w->edge[k].from + 1);
		param_int(d, vl);
		param_int(d, w->edge[k].to + 1);
	}
	return end_entity(d, 504, 1, SUBORDINATE);
}

/* Face f: its loop (508) of its edges from the list el, each with its
 * sense and no parameter-space curve, and the face (510) of its surface,
 * now subordinate, bounded by that loop as its outer one.  Returns the
 * 510's entry, or -1 when out of memory. */
static long
put_face(struct loft_cad_doc *d, const struct loft_sew_face *f, long el)
{
	struct iges *g = d->state;
	long n = 0, loop;

	for (int e = 0; e < 4; e++)
		n += f->edge[e] >= 0;
	param_int(d, 508);
	param_int(d, n);
	for (int e = 0; e < 4; e++)
		if (f->edge[e] >= 0) {
			param_int(d, 0);        /* an edge, not a vertex */
			param_int(d, el);
			param_int(d, f->edge[e] + 1);
			param_int(d, f->fwd[e]);
			param_int(d, 0);        /* parameter-space curves */
		}
	if ((loop = end_entity(d, 508, 1, SUBORDINATE)) < 0)
		return -1;
	set_subordinate(g, f->surf);
	param_int(d, 510);
	param_int(d, f->surf);
	param_int(d, 1);
	param_int(d, 1);                /* the first loop is the outer */
	param_int(d, loop);
	return end_entity(d, 510, 1, SUBORDINATE);
}

/*
 * Sew the patches into one shell (sewing.c) and write it: edges,
 * vertices, loops, faces and the shell (514), form 1 (closed: every
 * edge in two faces) in a manifold solid (186), else form 2 (open) as
 * the whole.  A patch whose sides are all points stays a 128 alone.
 * Returns 0 or LOFT_ENOMEM.
 */
static int
sew(struct loft_cad_doc *d)
{
	struct iges *g = d->state;
	struct loft_sew *w = &g->sew;
	long *fent = malloc(w->nface * sizeof *fent), el, shell;
	size_t nf = 0;
	int rc = LOFT_ENOMEM;

	if (w->nface == 0) {
		free(fent);
		return 0;
	}
	if (fent == NULL || loft_sew_run(w) != 0)
		goto done;
	rc = 0;
	if (w->nedge == 0)
		goto done;
	rc = LOFT_ENOMEM;
	if ((el = put_edges(d)) < 0)
		goto done;
	for (size_t f = 0; f < w->nface; f++) {
		const struct loft_sew_face *F = w->face + f;

		if (F->edge[0] >= 0 || F->edge[1] >= 0 || F->edge[2] >= 0 ||
		    F->edge[3] >= 0)
			if ((fent[nf++] = put_face(d, F, el)) < 0)
				goto done;
	}
	param_int(d, 514);
	param_int(d, (long)nf);
	for (size_t k = 0; k < nf; k++) {
		param_int(d, fent[k]);
		/* its normal is its surface's, or in a closed shell whose
		 * surfaces' normals point in, the other way round */
		param_int(d, !w->closed || w->volume >= 0);
	}
	if ((shell = end_entity(d, 514, w->closed ? 1 : 2, w->closed ?
	    SUBORDINATE : INDEPENDENT)) < 0)
		goto done;
	if (w->closed) {
		param_int(d, 186);
		param_int(d, shell);
		param_int(d, 1);        /* the shell's normals point out */
		param_int(d, 0);        /* no voids */
		if (end_entity(d, 186, 0, INDEPENDENT) < 0)
			goto done;
	}
	rc = 0;
done:
	free(fent);
	return rc;
}

/* "nH..." */
static void
hollerith(char *buf, size_t cap, const char *s)
{
	snprintf(buf, cap, "%zuH%s", strlen(s), s);
}

static int
iges_end(struct loft_cad_doc *d)
{
	static const struct { const char *word, *name; int flag; } units[] = {
		{ "in", "IN", 1 }, { "mm", "MM", 2 }, { "cm", "CM", 10 },
		{ "m", "M", 6 },
	};
	struct iges *g = d->state;
	int rc = sew(d);
	char tok[64], line[96];
	const char *gl[25];
	char hu[32], big[LOFT_NUMBUF + 2], res[LOFT_NUMBUF + 2], fl[8];
	double size = 0, far = 0;
	long ng = 0, len = 0;
	int u = 1;

	for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
		if (strcmp(d->o.unit_name, units[i].word) == 0)
			u = (int)i;
	for (int k = 0; k < 3; k++) {
		size = hypot(size, d->box[3 + k] - d->box[k]);
		far = fmax(far, fmax(fabs(d->box[k]), fabs(d->box[3 + k])));
	}
	loft_cad_real(big, far);
	loft_cad_real(res, size > 0 ? size * 1e-10 : 1e-10);
	hollerith(hu, sizeof hu, units[u].name);
	snprintf(fl, sizeof fl, "%d", units[u].flag);
	gl[0] = "1H,"; gl[1] = "1H;"; gl[2] = "4Hloft"; gl[3] = "8Hloft.igs";
	gl[4] = "10Hloft tocad"; gl[5] = "4Hloft"; gl[6] = "32"; gl[7] = "38";
	gl[8] = "6"; gl[9] = "308"; gl[10] = "15"; gl[11] = "4Hloft";
	gl[12] = "1."; gl[13] = fl; gl[14] = hu; gl[15] = "1"; gl[16] = "1.";
	gl[17] = "15H19700101.000000"; gl[18] = res; gl[19] = big;
	gl[20] = "4Hloft"; gl[21] = "4Hloft"; gl[22] = "11"; gl[23] = "0";
	gl[24] = "15H19700101.000000";

	loft_cad_to_head(d, 1);
	snprintf(line, sizeof line, "%-*sS%7d\n", GLOBAL_COLS,
	    "loft tocad: exact B-spline curves (126), surfaces (128) in a B-rep", 1);
	loft_cad_puts(d, line);
	line[0] = '\0';
	for (int i = 0; i < 25; i++) {
		snprintf(tok, sizeof tok, "%s%c", gl[i], i == 24 ? ';' : ',');
		if (len + (long)strlen(tok) > GLOBAL_COLS) {
			snprintf(tok + 32, 32, "G%7ld\n", ++ng);
			loft_cad_puts(d, line);
			for (long k = len; k < GLOBAL_COLS; k++)
				loft_cad_puts(d, " ");
			loft_cad_puts(d, tok + 32);
			line[0] = '\0';
			len = 0;
			snprintf(tok, sizeof tok, "%s%c", gl[i], i == 24 ? ';' :
			    ',');
		}
		strcat(line, tok);
		len += (long)strlen(tok);
	}
	snprintf(tok, sizeof tok, "G%7ld\n", ++ng);
	loft_cad_puts(d, line);
	for (long k = len; k < GLOBAL_COLS; k++)
		loft_cad_puts(d, " ");
	loft_cad_puts(d, tok);
	loft_cad_put(d, g->dir.buf, g->dir.len);
	loft_cad_to_head(d, 0);
	snprintf(line, sizeof line, "S%7dG%7ldD%7ldP%7ld%*sT%7d\n", 1, ng,
	    g->nde, g->np, GLOBAL_COLS - 32, "", 1);
	loft_cad_puts(d, line);
	return rc != 0 || g->dir.bad ? LOFT_ENOMEM : 0;
}

static void
iges_free(struct loft_cad_doc *d)
{
	struct iges *g = d->state;

	if (g != NULL) {
		loft_writer_free(&g->dir);
		loft_sew_free(&g->sew);
	}
	free(g);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_iges = {
	.name = "iges", .title = "IGES",
	.begin = iges_begin, .end = iges_end, .begin_record = iges_begin_record,
	.curve = iges_curve,
	.surface = iges_surface, .free = iges_free,
};
