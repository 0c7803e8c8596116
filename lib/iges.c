/*
 * iges.c: IGES 5.3 (fixed 80-column records): every curve one rational
 * B-spline curve, entity 126, every patch one rational B-spline surface,
 * entity 128, both flagged polynomial (all weights 1) and exact: the
 * Bezier pieces as a clamped B-spline whose parameter is loft's.  Units
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

struct iges {
	struct loft_writer dir;         /* the directory entry lines */
	long nde;                       /* directory lines so far */
	long np;                        /* parameter lines so far */
	char line[DATA_COLS + 1];       /* the parameter line being filled */
	int len;
	long first;                     /* the entity's first parameter line */
	double tol;                     /* the record's tolerance */
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

/* The last parameter ends the entity with ';'; then its directory entry. */
static int
end_entity(struct loft_cad_doc *d, int type, double last)
{
	struct iges *g = d->state;
	char buf[LOFT_NUMBUF + 2], de[400];
	long de1 = g->nde + 1;

	loft_cad_real(buf, last);
	param(d, buf, ';');
	flush_param(d);
	snprintf(de, sizeof de, "%8d%8ld%8d%8d%8d%8d%8d%8d%8sD%7ld\n"
	    "%8d%8d%8d%8ld%8d%8s%8s%8s%8dD%7ld\n", type, g->first, 0, 0, 0, 0,
	    0, 0, "00000000", de1, type, 0, 0, g->np - g->first + 1, 0, "", "",
	    "", 0, de1 + 1);
	loft_put_type(&g->dir, de);
	g->nde += 2;
	g->first = g->np + 1;
	return g->dir.bad ? LOFT_ENOMEM : 0;
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
 * control points, the parameter range, the plane's normal. */
static int
write_curve(struct loft_cad_doc *d, const struct loft_bcurve *c)
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
	return end_entity(d, 126, c->dim == 2 ? 1 : 0);
}

/* 128: K1, K2, M1, M2, closed and periodic flags, knots in u and v,
 * weights, control points with the u index running fastest, the range. */
static int
write_surface(struct loft_cad_doc *d, const struct loft_bsurf *s)
{
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
	return end_entity(d, 128, 1);
}

static int
iges_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	((struct iges *)d->state)->tol = it->tol;
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
	return loft_cad_surface_limited(d, s, ((struct iges *)d->state)->tol,
	    write_surface);
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
	    "loft tocad: exact B-spline curves (126) and surfaces (128)", 1);
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
	return g->dir.bad ? LOFT_ENOMEM : 0;
}

static void
iges_free(struct loft_cad_doc *d)
{
	struct iges *g = d->state;

	if (g != NULL)
		loft_writer_free(&g->dir);
	free(g);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_iges = {
	.name = "iges", .title = "IGES",
	.begin = iges_begin, .end = iges_end, .begin_record = iges_begin_record,
	.curve = iges_curve,
	.surface = iges_surface, .free = iges_free,
};
