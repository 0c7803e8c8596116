/*
 * loftcad.h: loft's curves and surfaces written into CAD documents (DXF,
 * SVG at true scale, STEP, IGES, STL, OBJ) for tocad(1), and loftplot(1)'s
 * SVG picture.
 *
 * Every record is first put in exact Bezier form (bezform.c): a curve as
 * polynomial pieces of one degree, a surface as tensor-product Bezier
 * patches.  A format is one module behind struct loft_cad_format, a table
 * of callbacks in the manner of libspiro's bezctx: the geometry knows no
 * format, and a new format is one file and one line of loft_cad_formats
 * (cadformats.c).
 * A format sets only the callbacks of what it can take; cad.c turns
 * curves into polylines (within the tolerance) for a format that takes
 * only polylines, and surfaces into one welded triangle mesh for a format
 * that takes only meshes.  A record whose kind the format has no callback
 * for is an error, and the document goes on without it.
 *
 * The loft stream writer (loftprog.h) is not one of these formats: a
 * format is handed a record's geometry in Bezier form, while a stream
 * keeps each record as it is, its own type, rows and attributes (a
 * cubic's Hermite rows, a patch's MacCallum coefficients and neighbour
 * links); written back from Bezier form, a cubic would come out a
 * bezier record and a patch a bezier-surface that no longer names its
 * neighbours.  OBJ (obj.c) is also written record by record into a
 * program's stream writer (loft_cad_attach), as sample -f obj does.
 *
 * loftplot's picture (svgplot.c, loft_cad_svgplot) is a format outside
 * loft_cad_formats: loftplot calls its callbacks itself, with points
 * already projected to its view's plane; an item's style class, colour
 * and width say how each record is drawn, and two callbacks only the
 * picture sets, box and label, write the labels' grounds and texts.
 *
 * Conventions as in loft.h: caller-owned arrays, 0 or a LOFT_E* code,
 * and the library never prints.  The document is made in memory and
 * handed back whole (loft_cad_finish), so nothing reaches the output
 * before the last record is in.
 */
#ifndef LOFTCAD_H
#define LOFTCAD_H

#include "loftprog.h"

/* The exact Bezier forms of the record types are the core's
 * (loft.h, bezform.c). */

/* ------------------------------------------------------------------ */
/* Documents (cad.c)                                                   */

/* A curve of npieces Bezier pieces of degree deg, each deg + 1 points of
 * dim numbers, piece i from ctl[i * (deg + 1) * dim]; piece i + 1 starts
 * where piece i ends.  The parameter of piece i runs over [i, i + 1]. */
struct loft_bcurve {
	const double *ctl;
	size_t npieces;
	int deg, dim;
	int closed;             /* the record's closed=1 */
};

/* A tensor-product Bezier patch of degrees m in u and n in v, control
 * points of 3 numbers u-major: P_ij at ctl[3 * (i * (n + 1) + j)]. */
struct loft_bsurf {
	const double *ctl;
	int m, n;
};

/* What a format learns of a record before its geometry. */
struct loft_cad_item {
	const struct loft_record *rec;  /* its attributes */
	const char *name;       /* from size= and id= ("size_4.5-id_2"), or "" */
	double size;            /* diagonal of its control points' box */
	double tol;             /* chordal tolerance for it, in its units */
	/* the picture's (svgplot.c; NULL and 0 for the other formats): */
	const char *cls;        /* its style class: "curve", "comb", ... */
	const char *colour;     /* its colour, "#1f4e9c" */
	double width_px;        /* its stroke width in pixels; 0: the */
	                        /* picture's LOFT_PLOT_CURVE_PX */
};

struct loft_cad_opts {
	double tol;             /* chordal tolerance in the stream's units, */
	                        /* or 0: LOFT_CAD_RELTOL of each record's size */
	int exact;              /* -s: exact curves where the format has a */
	                        /* choice (DXF SPLINE, not polylines) */
	int binary;             /* -b: binary STL */
	long per;               /* -n: polyline steps a piece, mesh steps */
	                        /* along a patch side; or 0: by tol */
	double unit_mm;         /* millimetres in the stream's unit */
	const char *unit_name;  /* "mm", "cm", "m", "in" */
	/* the picture's (svgplot.c), 0 for the other formats: */
	double frame[4];        /* its viewBox: left, top (y down), width, */
	                        /* height, in the drawing's units */
	long picture_px;        /* pixels of the frame's larger side */
	const char *background; /* its colour, or NULL: none (white) */
};

/*
 * The default chordal tolerance of a polyline: 1e-5 of the record's size,
 * 3 micrometres on a 300 mm insole, well under the step of a cutting
 * plotter, knife or laser (about 25 micrometres), and an SVG's cubic
 * approximation of a quartic is held to the same.
 */
#define LOFT_CAD_RELTOL 1e-5

/*
 * The default chordal tolerance of a mesh: 1e-3 of the design's size,
 * 0.1 mm on a 100 mm part, a 3-D printer's layer.
 */
#define LOFT_CAD_MESHTOL 1e-3

struct loft_cad_doc;

/*
 * A format: every callback gets the document and writes into it
 * through loft_cad_put, loft_cad_puts and loft_cad_putnum.  They return
 * 0 or LOFT_ENOMEM.  begin is called once before the first record's
 * geometry, end once after the last, begin_record and end_record around
 * each record's geometry.  NULL callbacks are kinds the format cannot
 * take.  box and label are the picture's (loftplot, svgplot.c), whose
 * program calls the callbacks itself with its points already in the
 * plane: lines first, then boxes, then labels.
 */
struct loft_cad_format {
	const char *name;       /* the -f word */
	const char *title;      /* for messages: "DXF" */
	int (*begin)(struct loft_cad_doc *d);
	int (*end)(struct loft_cad_doc *d);
	int (*begin_record)(struct loft_cad_doc *d,
	    const struct loft_cad_item *it);
	int (*end_record)(struct loft_cad_doc *d);
	/* exact curves: one call per record */
	int (*curve)(struct loft_cad_doc *d, const struct loft_bcurve *c);
	/* curves within it->tol, when curve is NULL or the user asked */
	int (*polyline)(struct loft_cad_doc *d, const double *p, size_t n,
	    int dim, int closed);
	/* point records (knots) */
	int (*points)(struct loft_cad_doc *d, const double *p, size_t n,
	    int dim);
	/* after a curve or polyline: the n points of its corners (the
	 * record's corners=, loft.5), at its joints; a format without it
	 * leaves corners= unread */
	int (*turns)(struct loft_cad_doc *d, const double *p, size_t n,
	    int dim);
	/* exact surfaces: one call per patch */
	int (*surface)(struct loft_cad_doc *d, const struct loft_bsurf *s);
	/* or all surfaces as one mesh at the end, before end: nv vertices
	 * of 3 numbers, nt triangles of 3 vertex indices, counter-clockwise
	 * seen from the side f_u x f_v points to */
	int (*mesh)(struct loft_cad_doc *d, const double *v, size_t nv,
	    const size_t *tri, size_t nt);
	/* a filled box lo..hi (2 numbers each), a label's ground */
	int (*box)(struct loft_cad_doc *d, const double *lo,
	    const double *hi);
	/* the text s, size high, beginning at the plane point at (or
	 * centred on it, middle 1) */
	int (*label)(struct loft_cad_doc *d, const double *at, double size,
	    int middle, const char *s);
	void (*free)(struct loft_cad_doc *d);   /* of state, may be NULL */
};

/*
 * loftplot's SVG picture (svgplot.c), not one of loft_cad_formats: a
 * frame of o.frame, o.picture_px pixels on its larger side; an item's
 * cls styles its lines ("comb" faint, "tangents" dashed, "points" and
 * "knots" filled markers, "control-points" hollow ones; any other a
 * line).  Its callbacks: curve (cubic pieces, dim >= 2; a piece that
 * does not begin where the one before ended begins a new subpath; else
 * LOFT_EINPUT), polyline and points (markers), several to one record's
 * path, box and label.  begin returns LOFT_EGEOM when the frame is not
 * finite and positive.  Coordinates are plane points, y up, written to
 * 1e-6 of the frame.
 */
extern const struct loft_cad_format loft_cad_svgplot;
/* The picture's sizes in its pixels: the lines' width, the labels' font. */
#define LOFT_PLOT_CURVE_PX 1.5
#define LOFT_PLOT_FONT_PX 12

/* The formats, by name, ending with a NULL name. */
struct loft_cad_entry {
	const char *name;
	const struct loft_cad_format *format;
};
extern const struct loft_cad_entry loft_cad_formats[];

/* The format of loft_cad_formats called name, or NULL. */
const struct loft_cad_format *loft_cad_format_named(const char *name);

/* loft_parse_word of name among loft_cad_formats' names (tocad -f): 0
 * and the entry's index in *i, or an error naming the choices. */
#define LOFT_CAD_MAXFORMATS 32
int loft_cad_format_find(const char *name, int *i, struct loft_error *err);

/* The document being made. */
struct loft_cad_doc {
	const struct loft_cad_format *f;
	struct loft_cad_opts o;
	struct loft_writer out;         /* the document's body */
	struct loft_writer head;        /* and its head, written first */
	int in_head;
	void *state;                    /* the format's own */
	size_t nrec;                    /* records written */
	double box[6];                  /* lo x y z, hi x y z of all written */
	int bad;                        /* a callback failed: no document */
	/* internal: scratch and the surfaces kept for a mesh */
	double *tmp;
	size_t tmpcap;
	double *surf;
	size_t nsurf, surfcap;
	struct loft_design design;      /* their patches' links */
};

/*
 * Start a document in format f (an entry of loft_cad_formats) with
 * options o.  d is the caller's and need not be zeroed.
 */
void loft_cad_init(struct loft_cad_doc *d, const struct loft_cad_format *f,
    const struct loft_cad_opts *o);

/*
 * Add record rec to the document, whole or not at all.  Returns 0;
 * LOFT_EINPUT when it is no curve, surface or point record, or one of a
 * kind the format cannot take (err says which and what can); LOFT_EGEOM
 * when its coefficients overflow; LOFT_ENOMEM.
 */
int loft_cad_record(struct loft_cad_doc *d, const struct loft_record *rec,
    struct loft_error *err);

/*
 * End the document: the mesh of a mesh format, the format's end.  Returns
 * 0 with the document in d->head.buf[0..d->head.len) followed by
 * d->out.buf[0..d->out.len), or LOFT_EINPUT when
 * no record was written ("nothing to draw"), LOFT_ENOMEM, LOFT_EGEOM when
 * a number was not finite.
 */
int loft_cad_finish(struct loft_cad_doc *d, struct loft_error *err);

void loft_cad_free(struct loft_cad_doc *d);

/*
 * For a program that writes a format record by record into its own
 * writer w (sample -f obj), not a document made whole at the end:
 * loft_cad_attach moves w's text and digits into d's body, so that the
 * format's callbacks (begin_record, polyline, mesh, ...), called by the
 * program, append to it; loft_cad_detach moves it all back to w,
 * whose record then goes out whole or not at all as loft_run makes it.
 * d comes from loft_cad_init; between the two calls w is not used.
 */
void loft_cad_attach(struct loft_cad_doc *d, struct loft_writer *w);
void loft_cad_detach(struct loft_cad_doc *d, struct loft_writer *w);

/* Append n raw bytes to the document. */
void loft_cad_put(struct loft_cad_doc *d, const void *s, size_t n);

/*
 * on = 1: what is appended from now on goes to the document's head,
 * which is written before everything else (a DXF layer table, an SVG
 * viewBox, IGES's directory: heads that can be made only after the
 * body); on = 0: to the body again.
 */
void loft_cad_to_head(struct loft_cad_doc *d, int on);

/* Append the string s. */
void loft_cad_puts(struct loft_cad_doc *d, const char *s);

/*
 * Format x losslessly (shortest text that reads back the same) into buf
 * (LOFT_NUMBUF bytes) as a real of STEP and IGES: always a '.', an
 * exponent as E.  Returns the length.  x must be finite.
 */
int loft_cad_real(char *buf, double x);

/* Append x as loft_format_num writes it (no space before), with the
 * body's digits: 0 (lossless) unless a program set d->out.digits. */
void loft_cad_putnum(struct loft_cad_doc *d, double x);

/*
 * The knots of a curve of npieces Bezier pieces of degree deg as a
 * clamped B-spline: the distinct knots 0, 1, ..., npieces into knot and
 * their multiplicities deg + 1, deg, ..., deg, deg + 1 into mult
 * (npieces + 1 each).  Its control points are the pieces' points with
 * each joint once: npieces * deg + 1.
 */
void loft_cad_knots(size_t npieces, int deg, double *knot, int *mult);

/* Point k of the B-spline control points of c (k <= npieces * deg). */
const double *loft_cad_ctl(const struct loft_bcurve *c, size_t k);


/* ------------------------------------------------------------------ */
/* Degrees a format cannot take (cadlimit.c)                           */

/*
 * The highest B-spline degree STEP and IGES readers take: OpenCASCADE
 * reads a curve or surface of a higher one as nothing.
 */
#define LOFT_CAD_MAXDEG 25

/*
 * Hand the curve c to write as it is, or, when its degree is above
 * LOFT_CAD_MAXDEG, as cubic pieces each within tol of it at the same
 * parameter (bspline.c).  Returns write's code, or LOFT_ENOMEM; when no
 * 4096 cubics a piece would do, d->out.bad is LOFT_EGEOM.
 */
int loft_cad_curve_limited(struct loft_cad_doc *d, const struct loft_bcurve *c,
    double tol, int (*write)(struct loft_cad_doc *, const struct loft_bcurve *));

/* The same for a patch, as bicubic patches (no more than 4096). */
int loft_cad_surface_limited(struct loft_cad_doc *d, const struct loft_bsurf *s,
    double tol, int (*write)(struct loft_cad_doc *, const struct loft_bsurf *));


/* ------------------------------------------------------------------ */
/* Patches sewn into one shell (sewing.c), for STEP and IGES           */

/*
 * A patch kept for the shell.  Its sides, in the order its loop runs
 * them (counterclockwise in (u, v), so that the face's normal is
 * f_u x f_v): 0 is v = 0, 1 is u = 1, 2 is v = 1, 3 is u = 0, each
 * side's points in the direction of its surface parameter.
 */
struct loft_sew_face {
	long surf;              /* the writer's entity of its surface */
	char *name;             /* the writer's name of it */
	double *ctl;            /* its control points, as loft_bsurf's */
	int m, n;               /* its degrees */
	int deg[4];             /* of its sides */
	double *side[4];        /* their deg + 1 control points, 3 each */
	long patch;             /* its index in the sewing's design, or -1 */
	/* after loft_sew_run: */
	long edge[4];           /* the edge each side is, or -1: a pole */
	int fwd[4];             /* the loop runs along that edge's curve */
};

/* An edge: a Bezier curve of one piece over [0, 1], the points of the
 * side (face, side), from vertex from to vertex to. */
struct loft_sew_edge {
	long from, to;          /* vertex numbers */
	long face;
	int side;
	int uses;               /* faces it bounds: 1, or 2 when shared */
	long ent;               /* the writer's, 0 until it sets it */
};

/* A shell being sewn; zero it before the first loft_sew_add. */
struct loft_sew {
	struct loft_sew_face *face;
	size_t nface, facecap;
	/* after loft_sew_run: */
	struct loft_sew_edge *edge;
	size_t nedge, edgecap;
	double *vert;           /* the vertices' points, 3 each */
	size_t nvert;
	int closed;             /* every edge bounds two faces (and one is) */
	double volume;          /* closed: the volume the faces enclose, */
	                        /* negative when their normals point in */
	struct loft_design design;      /* the patches' links */
};

/*
 * Keep the patch b (its points are copied), written by the caller as
 * its entity surf and called name, for the shell.  rec, when not NULL,
 * is its record: a patch with an id brings its links, which make the
 * sides they join one edge even where rounding made their points differ
 * (a link over a whole side, loft.5).  Returns 0 or LOFT_ENOMEM.
 */
int loft_sew_add(struct loft_sew *w, const struct loft_bsurf *b,
    const struct loft_record *rec, const char *name, long surf);

/*
 * Sew the patches kept: corners at the same point, or put together by a
 * link, are one vertex; a side with the same points as another's (either
 * way round), or linked to it, is one edge with it; a side all at one
 * point is no edge.  Fills each face's edge and fwd, the edges, the
 * vertices, closed and, for a closed shell, volume (the divergence
 * theorem, exact to rounding).  Called once, after the last
 * loft_sew_add.  Returns 0 or LOFT_ENOMEM.
 */
int loft_sew_run(struct loft_sew *w);

void loft_sew_free(struct loft_sew *w);

#endif
