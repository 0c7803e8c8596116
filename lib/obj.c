/*
 * obj.c: Wavefront OBJ (tocad -f obj, sample -f obj): each record an
 * object "o TYPE-ID" (its id= when it has one); a curve as a polyline,
 * "v x y z" lines (z = 0 in the plane) and one "l" element of them;
 * points as vertices and a "p" element; surfaces as one triangle mesh,
 * "v" lines and "f a b c" faces counter-clockwise seen from where f_u x
 * f_v points.  Indices count from 1 over the whole document, so the
 * format keeps the number of vertices written.  Numbers are written as
 * the document's writer writes them (sample's -p).
 * Program layer (loftcad.h, on loftprog.h): a CAD format.
 */
#include <stdio.h>
#include <stdlib.h>

#include "loftcad.h"
#include "internal.h"

struct obj {
	size_t nvert;           /* vertices written so far */
	char name[128];         /* the record's object, not yet written */
	int pending;
};

/* The format's state, made on first use (sample calls no begin). */
static struct obj *
state(struct loft_cad_doc *d)
{
	if (d->state == NULL)
		d->state = calloc(1, sizeof(struct obj));
	return d->state;
}

static int
obj_begin_record(struct loft_cad_doc *d, const struct loft_cad_item *it)
{
	struct obj *s = state(d);
	const char *id = loft_attr(it->rec, "id");

	if (s == NULL)
		return LOFT_ENOMEM;
	snprintf(s->name, sizeof s->name, "%s%s%.100s",
	    it->rec->type ? it->rec->type : "points", id ? "-" : "",
	    id ? id : "");
	s->pending = 1;
	return 0;
}

static int
obj_end_record(struct loft_cad_doc *d)
{
	if (d->state != NULL)
		((struct obj *)d->state)->pending = 0;
	return 0;
}

/* "o NAME" of the record whose geometry comes now ("o surfaces" for the
 * mesh of all of a document's), and n vertices; the first one's index. */
static size_t
put_vertices(struct loft_cad_doc *d, struct obj *s, const double *p, size_t n,
    int dim)
{
	size_t first = s->nvert + 1;

	loft_cad_puts(d, "o ");
	loft_cad_puts(d, s->pending ? s->name : "surfaces");
	loft_cad_puts(d, "\n");
	s->pending = 0;
	for (size_t i = 0; i < n; i++) {
		loft_cad_puts(d, "v");
		for (int k = 0; k < 3; k++) {
			loft_cad_puts(d, " ");
			loft_cad_putnum(d, k < dim ? p[i * dim + k] : 0);
		}
		loft_cad_puts(d, "\n");
	}
	s->nvert += n;
	return first;
}

/* An element: word, then the indices first .. first + n - 1 (and first
 * again when closed). */
static void
put_element(struct loft_cad_doc *d, const char *word, size_t first, size_t n,
    int closed)
{
	char buf[32];

	loft_cad_puts(d, word);
	for (size_t k = 0; k < n + (closed != 0); k++) {
		snprintf(buf, sizeof buf, " %zu", first + k % n);
		loft_cad_puts(d, buf);
	}
	loft_cad_puts(d, "\n");
}

static int
obj_polyline(struct loft_cad_doc *d, const double *p, size_t n, int dim,
    int closed)
{
	struct obj *s = state(d);

	if (s == NULL)
		return LOFT_ENOMEM;
	put_element(d, "l", put_vertices(d, s, p, n, dim), n, closed);
	return 0;
}

static int
obj_points(struct loft_cad_doc *d, const double *p, size_t n, int dim)
{
	struct obj *s = state(d);

	if (s == NULL)
		return LOFT_ENOMEM;
	put_element(d, "p", put_vertices(d, s, p, n, dim), n, 0);
	return 0;
}

static int
obj_mesh(struct loft_cad_doc *d, const double *v, size_t nv,
    const size_t *tri, size_t nt)
{
	struct obj *s = state(d);
	size_t first;
	char buf[96];

	if (s == NULL)
		return LOFT_ENOMEM;
	first = put_vertices(d, s, v, nv, 3);
	for (size_t k = 0; k < nt; k++) {
		snprintf(buf, sizeof buf, "f %zu %zu %zu\n", first + tri[3 * k],
		    first + tri[3 * k + 1], first + tri[3 * k + 2]);
		loft_cad_puts(d, buf);
	}
	return 0;
}

static void
obj_free(struct loft_cad_doc *d)
{
	free(d->state);
	d->state = NULL;
}

const struct loft_cad_format loft_cad_obj = {
	.name = "obj", .title = "OBJ",
	.begin_record = obj_begin_record, .end_record = obj_end_record,
	.polyline = obj_polyline, .points = obj_points, .mesh = obj_mesh,
	.free = obj_free,
};
