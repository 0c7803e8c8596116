/*
 * stepread.c: STEP (ISO 10303-21 exchange files, AP203 and AP214) read
 * into loft's records.  Read: the surfaces of faces (ADVANCED_FACE,
 * FACE_SURFACE) that are B-splines (B_SPLINE_SURFACE_WITH_KNOTS, its
 * rational complex form, BEZIER_SURFACE) or planes (PLANE, as the
 * rectangle of the face's bounds), and the curves and surfaces a
 * GEOMETRIC_SET or GEOMETRIC_CURVE_SET holds (B-spline and Bezier curves,
 * rational or not, CIRCLE, TRIMMED_CURVE of a LINE or CIRCLE, and the
 * surfaces above).  Coordinates are read into millimetres from the
 * length unit of the representation context (an SI_UNIT of the metre
 * with its prefix, or a CONVERSION_BASED_UNIT of one, such as the inch).
 * Everything else (the topology, trimming, other surfaces) is passed
 * over; surfaces of faces of other kinds are counted in one message.
 * Program layer (loftprog.h, cadread.h): it writes records.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cadread.h"

/* Entity numbers are read up to here: more digits than a file could
 * hold, and 10 STEP_MAXID + 9 still fits a 32-bit long (wasm32). */
#define STEP_MAXID 100000000L

/* A value of a parameter list: its kind, and what it holds. */
enum { V_NUM, V_REF, V_STR, V_ENUM, V_LIST, V_UNSET, V_TYPED };
struct val {
	int kind;
	double x;               /* V_NUM */
	long ref;               /* V_REF */
	const char *s;          /* V_STR, V_ENUM, V_TYPED: its text */
	size_t len;
	size_t first, n;        /* V_LIST, V_TYPED: children; a list for */
	size_t next;            /* V_TYPED; the next sibling, or 0: none */
};

struct ent {                    /* "#id=body;" */
	long id, line;
	size_t at, len;         /* the body in the document */
};

/* Surface kinds of faces loft does not read, counted for one message. */
#define NSKIP 8

struct step {
	const char *buf;
	size_t len;
	struct loft_cadin *c;
	struct ent *e;
	size_t ne, ecap;
	struct val *v;          /* v[0] is unused: index 0 means none */
	size_t nv, vcap;
	int oom;
	double mm;              /* millimetres in the file's length unit */
	struct {
		const char *s;
		size_t len;
		long n;
	} skip[NSKIP];
};

/* ---- the exchange structure ------------------------------------------ */

static size_t
new_val(struct step *st, int kind)
{
	if (loft__grow((void **)&st->v, &st->vcap, st->nv + 1,
	    sizeof *st->v) != 0) {
		st->oom = 1;
		return 0;
	}
	memset(st->v + st->nv, 0, sizeof *st->v);
	st->v[st->nv].kind = kind;
	return st->nv++;
}

static int
is_word(int ch)
{
	return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') ||
	    (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
}

static size_t
skip_space(const char *s, size_t i, size_t n)
{
	for (;;) {
		while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' ||
		    s[i] == '\n'))
			i++;
		if (i + 1 < n && s[i] == '/' && s[i + 1] == '*') {
			const char *e = NULL;

			for (size_t k = i + 2; k + 1 < n; k++)
				if (s[k] == '*' && s[k + 1] == '/') {
					e = s + k;
					break;
				}
			i = e ? (size_t)(e - s) + 2 : n;
			continue;
		}
		return i;
	}
}

static size_t parse_val(struct step *st, const char *s, size_t *i, size_t n,
    int depth);

/* Values up to ')' (commas or spaces between), children of node p. */
static int
parse_list(struct step *st, const char *s, size_t *i, size_t n, size_t p,
    int depth)
{
	size_t last = 0;

	(*i)++;                 /* the '(' */
	for (;;) {
		size_t k;

		*i = skip_space(s, *i, n);
		if (*i >= n)
			return -1;
		if (s[*i] == ')') {
			(*i)++;
			return 0;
		}
		if (s[*i] == ',') {
			(*i)++;
			continue;
		}
		if ((k = parse_val(st, s, i, n, depth + 1)) == 0)
			return -1;
		if (last == 0)
			st->v[p].first = k;
		else
			st->v[last].next = k;
		last = k;
		st->v[p].n++;
	}
}

/* Lists nested deeper than this are no STEP entity's. */
#define MAX_DEPTH 32

/* One value at s[*i]; its node, or 0 when it is malformed. */
static size_t
parse_val(struct step *st, const char *s, size_t *i, size_t n, int depth)
{
	size_t k, a;

	*i = skip_space(s, *i, n);
	if (*i >= n || depth > MAX_DEPTH)
		return 0;
	a = *i;
	if (s[a] == '(') {
		if ((k = new_val(st, V_LIST)) == 0 || parse_list(st, s, i, n, k,
		    depth) != 0)
			return 0;
		return k;
	}
	if (s[a] == '\'') {
		for (*i = a + 1; *i < n; (*i)++)
			if (s[*i] == '\'') {
				if (*i + 1 < n && s[*i + 1] == '\'')
					(*i)++;
				else
					break;
			}
		if (*i >= n || (k = new_val(st, V_STR)) == 0)
			return 0;
		st->v[k].s = s + a + 1;
		st->v[k].len = *i - a - 1;
		(*i)++;
		return k;
	}
	if (s[a] == '$' || s[a] == '*') {
		(*i)++;
		return new_val(st, V_UNSET);
	}
	if (s[a] == '.') {
		for (*i = a + 1; *i < n && s[*i] != '.'; (*i)++)
			;
		if (*i >= n || (k = new_val(st, V_ENUM)) == 0)
			return 0;
		st->v[k].s = s + a + 1;
		st->v[k].len = *i - a - 1;
		(*i)++;
		return k;
	}
	if (s[a] == '#') {
		long id = 0;

		for (*i = a + 1; *i < n && s[*i] >= '0' && s[*i] <= '9' &&
		    id < STEP_MAXID; (*i)++)
			id = 10 * id + (s[*i] - '0');
		if (*i == a + 1 || (k = new_val(st, V_REF)) == 0)
			return 0;
		st->v[k].ref = id;
		return k;
	}
	if ((s[a] >= 'A' && s[a] <= 'Z') || (s[a] >= 'a' && s[a] <= 'z')) {
		for (*i = a; *i < n && is_word(s[*i]); (*i)++)
			;
		if ((k = new_val(st, V_TYPED)) == 0)
			return 0;
		st->v[k].s = s + a;
		st->v[k].len = *i - a;
		*i = skip_space(s, *i, n);
		if (*i < n && s[*i] == '(') {
			size_t l = new_val(st, V_LIST);

			if (l == 0 || parse_list(st, s, i, n, l, depth) != 0)
				return 0;
			st->v[k].first = l;
		}
		return k;
	}
	for (*i = a; *i < n && strchr(",)( \t\r\n", s[*i]) == NULL; (*i)++)
		;
	if ((k = new_val(st, V_NUM)) == 0 ||
	    loft_parse_num(s + a, *i - a, &st->v[k].x, NULL) != 0)
		return 0;
	return k;
}

static int
cmp_ent(const void *a, const void *b)
{
	const struct ent *x = a, *y = b;

	return (x->id > y->id) - (x->id < y->id);
}

/* The entity instances of the DATA sections; -1 when out of memory. */
static int
scan(struct step *st)
{
	const char *s = st->buf;
	size_t n = st->len, i = 0;
	long line = 1;

	for (;;) {
		size_t a, b;
		long id = 0;
		int q = 0, depth = 0;

		/* to the next '#' that begins a line's instance */
		while (i < n && s[i] != '#') {
			if (s[i] == '\n')
				line++;
			else if (s[i] == '\'')  /* header strings */
				for (i++; i < n && s[i] != '\''; i++)
					line += s[i] == '\n';
			i++;
		}
		if (i >= n)
			return 0;
		for (i++; i < n && s[i] >= '0' && s[i] <= '9' && id <
		    STEP_MAXID; i++)
			id = 10 * id + (s[i] - '0');
		a = skip_space(s, i, n);
		if (a >= n || s[a] != '=')
			continue;
		for (b = a + 1; b < n; b++) {
			if (s[b] == '\'')
				q = !q;
			else if (!q && s[b] == '(')
				depth++;
			else if (!q && s[b] == ')')
				depth--;
			else if (!q && depth == 0 && s[b] == ';')
				break;
		}
		if (loft__grow((void **)&st->e, &st->ecap, st->ne + 1,
		    sizeof *st->e) != 0)
			return -1;
		st->e[st->ne++] = (struct ent){ id, line, a + 1, b - a - 1 };
		for (; i < b && i < n; i++)
			line += s[i] == '\n';
		i = b + 1;
	}
}

static const struct ent *
find(const struct step *st, long id)
{
	size_t lo = 0, hi = st->ne;

	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;

		if (st->e[mid].id < id)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo < st->ne && st->e[lo].id == id ? st->e + lo : NULL;
}

/* The parsed body of entity id (a V_TYPED, or a V_LIST of them: a
 * complex instance), or 0. */
static size_t
body(struct step *st, long id, const struct ent **ep)
{
	const struct ent *e = find(st, id);
	size_t i = 0;

	if (ep != NULL)
		*ep = e;
	if (e == NULL)
		return 0;
	return parse_val(st, st->buf + e->at, &i, e->len, 0);
}

static int
typed_is(const struct val *v, const char *name)
{
	return v->kind == V_TYPED && loft__word_is(v->s, v->len, name);
}

/* The parameter list of the part name of entity id (a simple instance
 * of that type, or that part of a complex one), or 0. */
static size_t
part(struct step *st, long id, const char *name)
{
	size_t b = body(st, id, NULL);

	if (b == 0)
		return 0;
	if (st->v[b].kind == V_LIST)
		for (size_t k = st->v[b].first; k != 0; k = st->v[k].next) {
			if (typed_is(&st->v[k], name))
				return st->v[k].first;
		}
	return typed_is(&st->v[b], name) ? st->v[b].first : 0;
}

/* The type name of entity id (the first part's of a complex one). */
static const struct val *
type_of(struct step *st, long id)
{
	size_t b = body(st, id, NULL);

	if (b == 0)
		return NULL;
	if (st->v[b].kind == V_LIST)
		b = st->v[b].first;
	return b != 0 && st->v[b].kind == V_TYPED ? &st->v[b] : NULL;
}

/* Child k of list l, or NULL. */
static const struct val *
arg(const struct step *st, size_t l, size_t k)
{
	size_t c;

	if (l == 0 || st->v[l].kind != V_LIST)
		return NULL;
	for (c = st->v[l].first; c != 0 && k > 0; k--)
		c = st->v[c].next;
	return c != 0 ? &st->v[c] : NULL;
}

static long
ref_arg(const struct step *st, size_t l, size_t k)
{
	const struct val *v = arg(st, l, k);

	return v != NULL && v->kind == V_REF ? v->ref : 0;
}

static size_t
list_arg(const struct step *st, size_t l, size_t k)
{
	const struct val *v = arg(st, l, k);

	return v != NULL && v->kind == V_LIST ? (size_t)(v - st->v) : 0;
}

/* The numbers of list l into x (at most max); their count, or -1. */
static long
numbers(const struct step *st, size_t l, double *x, size_t max)
{
	size_t n = 0;

	if (l == 0)
		return -1;
	for (size_t c = st->v[l].first; c != 0; c = st->v[c].next) {
		const struct val *v = &st->v[c];

		if (n >= max)
			return -1;
		if (v->kind == V_NUM)
			x[n++] = v->x;
		else if (v->kind == V_TYPED && v->first != 0 &&
		    st->v[v->first].n == 1 &&
		    st->v[st->v[v->first].first].kind == V_NUM)
			x[n++] = st->v[st->v[v->first].first].x;
		else
			return -1;
	}
	return (long)n;
}

/* A CARTESIAN_POINT (or a DIRECTION) into x[0..3); 0 or -1. */
static int
point(struct step *st, long id, const char *type, double *x)
{
	size_t mark = st->nv, l = part(st, id, type);
	long n = numbers(st, list_arg(st, l, 1), x, 3);

	st->nv = mark;
	if (n < 1)
		return -1;
	for (long k = n; k < 3; k++)
		x[k] = 0;
	if (strcmp(type, "CARTESIAN_POINT") == 0)
		for (int k = 0; k < 3; k++)
			x[k] *= st->mm;
	return 0;
}

/* ---- geometry ---------------------------------------------------------- */

/* A coordinate frame: origin o, axes x, y, z (unit, right-handed). */
struct frame {
	double o[3], x[3], y[3], z[3];
};

static void
cross(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

static int
unit(double *a)
{
	double s = fmax(fabs(a[0]), fmax(fabs(a[1]), fabs(a[2]))), l;

	if (!(s > 0) || !isfinite(s))
		return -1;
	l = s * sqrt((a[0] / s) * (a[0] / s) + (a[1] / s) * (a[1] / s) +
	    (a[2] / s) * (a[2] / s));
	for (int k = 0; k < 3; k++)
		a[k] /= l;
	return 0;
}

/* AXIS2_PLACEMENT_3D (or _2D) id; 0 or -1. */
static int
placement(struct step *st, long id, struct frame *f)
{
	size_t mark = st->nv, l = part(st, id, "AXIS2_PLACEMENT_3D");
	long r;
	int rc = 0;
	double d;

	if (l == 0)
		l = part(st, id, "AXIS2_PLACEMENT_2D");
	memset(f, 0, sizeof *f);
	f->z[2] = 1;
	f->x[0] = 1;
	if (l == 0 || point(st, ref_arg(st, l, 1), "CARTESIAN_POINT", f->o))
		rc = -1;
	if (rc == 0 && (r = ref_arg(st, l, 2)) != 0 && st->v[l].n > 3 &&
	    point(st, r, "DIRECTION", f->z) != 0)
		rc = -1;
	if (rc == 0 && (r = ref_arg(st, l, st->v[l].n > 3 ? 3 : 2)) != 0 &&
	    point(st, r, "DIRECTION", f->x) != 0)
		rc = -1;
	if (rc == 0 && unit(f->z) == 0) {
		/* the x axis made square to z */
		d = f->x[0] * f->z[0] + f->x[1] * f->z[1] + f->x[2] * f->z[2];
		for (int k = 0; k < 3; k++)
			f->x[k] -= d * f->z[k];
		if (unit(f->x) != 0) {          /* x along z: any square one */
			double a[3] = { fabs(f->z[0]) < 0.9, fabs(f->z[0]) >=
			    0.9, 0 };

			cross(f->z, a, f->x);
			(void)unit(f->x);
		}
		cross(f->z, f->x, f->y);
	} else {
		rc = -1;
	}
	st->nv = mark;
	return rc;
}

/* A name for records: the entity's own (its first parameter). */
static struct loft__bsname
name_of(struct step *st, size_t l, long id)
{
	const struct val *v = arg(st, l, 0);
	struct loft__bsname nm = { "", 0, id };

	if (v != NULL && v->kind == V_STR) {
		nm.name = v->s;
		nm.nname = v->len;
	}
	return nm;
}

/* The points of list of references l into a new array (3 each). */
static double *
point_list(struct step *st, size_t l, size_t *n)
{
	double *p;
	size_t k = 0;

	*n = l != 0 ? st->v[l].n : 0;
	if (*n == 0 || (p = malloc(*n * 3 * sizeof *p)) == NULL)
		return NULL;
	for (size_t c = st->v[l].first; c != 0; c = st->v[c].next, k++)
		if (st->v[c].kind != V_REF || point(st, st->v[c].ref,
		    "CARTESIAN_POINT", p + 3 * k) != 0) {
			free(p);
			return NULL;
		}
	return p;
}

/* Knots of a _WITH_KNOTS part: multiplicities at list a, values at b,
 * want of them, into a new array. */
static double *
knot_list(struct step *st, size_t a, size_t b, size_t want)
{
	long nm;
	double *t = NULL, *m = NULL, *v = NULL;
	long *mi = NULL;
	size_t cap = a != 0 ? st->v[a].n : 0;

	if (cap == 0 || b == 0 || st->v[b].n != cap)
		return NULL;
	m = malloc(cap * sizeof *m);
	v = malloc(cap * sizeof *v);
	mi = malloc(cap * sizeof *mi);
	t = malloc(want * sizeof *t);
	if (m == NULL || v == NULL || mi == NULL || t == NULL ||
	    (nm = numbers(st, a, m, cap)) < 0 || numbers(st, b, v, cap) !=
	    nm)
		goto bad;
	for (long i = 0; i < nm; i++) {
		if (!(m[i] >= 1 && m[i] <= 1e9) || m[i] != floor(m[i]))
			goto bad;
		mi[i] = (long)m[i];
	}
	if (loft__bs_knots(v, mi, (size_t)nm, want, t) != 0)
		goto bad;
	free(m);
	free(v);
	free(mi);
	return t;
bad:
	free(m);
	free(v);
	free(mi);
	free(t);
	return NULL;
}

/* Bezier knots: deg + 1 zeros then deg + 1 ones. */
static double *
bezier_knots(int deg)
{
	double *t = malloc(2 * (size_t)(deg + 1) * sizeof *t);

	for (int i = 0; t != NULL && i < 2 * (deg + 1); i++)
		t[i] = i > deg;
	return t;
}

/* The degree argument k of list l: 1 to 63, or -1. */
static int
degree(const struct step *st, size_t l, size_t k)
{
	const struct val *v = arg(st, l, k);

	if (v == NULL || v->kind != V_NUM || v->x != floor(v->x) || v->x < 1 ||
	    v->x > LOFT_BSPLINE_MAXDEG)
		return -1;
	return (int)v->x;
}

/* A B-spline or Bezier curve id (simple or complex, rational or not)
 * as records; 0, or -1 (complained about). */
static int
bspline_curve(struct step *st, long id, long line)
{
	size_t mark = st->nv, l = part(st, id, "B_SPLINE_CURVE_WITH_KNOTS");
	size_t g = part(st, id, "B_SPLINE_CURVE"), rw, kl = l;
	struct loft__bs b = { 0, 0, NULL, NULL, NULL };
	struct loft__bsname nm;
	int rc = -1, bez = 0;
	double *w = NULL;

	if (g == 0 && l != 0)           /* simple: name, deg, pts, ... */
		g = l, kl = 0;
	if (g == 0 && (g = part(st, id, "BEZIER_CURVE")) != 0)
		bez = 1;
	nm = name_of(st, g, id);
	/* the simple forms begin with a name; the complex part does not */
	{
		size_t o = arg(st, g, 0) != NULL && arg(st, g, 0)->kind ==
		    V_STR ? 1 : 0;

		if (o == 0)
			nm = (struct loft__bsname){ "", 0, id };
		b.deg = degree(st, g, o);
		b.ctl = point_list(st, list_arg(st, g, o + 1), &b.n);
		if (b.deg < 0 || b.ctl == NULL) {
			loft__cadin_say(st->c, line, "#%ld: its degree (1 to %d) "
			    "or control points cannot be read", id,
			    LOFT_BSPLINE_MAXDEG);
			goto done;
		}
		if (bez)
			b.t = bezier_knots(b.deg);
		else if (kl == 0)       /* simple: mults at o + 5, knots o + 6 */
			b.t = knot_list(st, list_arg(st, g, o + 5),
			    list_arg(st, g, o + 6), b.n + b.deg + 1);
		else
			b.t = knot_list(st, list_arg(st, kl, 0),
			    list_arg(st, kl, 1), b.n + b.deg + 1);
	}
	if (b.t == NULL) {
		loft__cadin_say(st->c, line, "#%ld: its knots and "
		    "multiplicities do not make %zu knots", id, b.n + b.deg + 1);
		goto done;
	}
	if ((rw = part(st, id, "RATIONAL_B_SPLINE_CURVE")) != 0) {
		w = malloc(b.n * sizeof *w);
		if (w == NULL || numbers(st, list_arg(st, rw, 0), w, b.n) !=
		    (long)b.n) {
			loft__cadin_say(st->c, line, "#%ld: its weights cannot "
			    "be read", id);
			goto done;
		}
		b.w = w;
	}
	rc = loft__bs_curve(st->c, &b, &nm, line);
done:
	free((void *)b.t);
	free((void *)b.ctl);
	free(w);
	st->nv = mark;
	return rc;
}

/* Knots of one direction of a surface: the _WITH_KNOTS part's lists
 * at ka and kb, or a Bezier's. */
static double *
surf_knots(struct step *st, int bez, size_t wk, size_t ka, size_t kb,
    size_t n, int deg)
{
	if (bez)
		return bezier_knots(deg);
	return knot_list(st, list_arg(st, wk, ka), list_arg(st, wk, kb),
	    n + (size_t)deg + 1);
}

/* The rows of points of surface part g (list at k): nu by nv, into
 * s->ctl; 0 or -1. */
static int
surf_points(struct step *st, size_t rows, struct loft__bsurf *s)
{
	size_t k = 0, n;
	double *ctl = NULL;

	s->nu = rows != 0 ? st->v[rows].n : 0;
	s->nv = 0;
	for (size_t r = rows ? st->v[rows].first : 0; r != 0;
	    r = st->v[r].next, k++) {
		double *p = point_list(st, st->v[r].kind == V_LIST ? r : 0, &n);

		if (p == NULL || (k > 0 && n != s->nv) || (k == 0 && n > (size_t)
		    LOFT_BSPLINE_MAXCTL / s->nu) || (k == 0 && (ctl =
		    malloc(s->nu * n * 3 * sizeof *ctl)) == NULL)) {
			free(p);
			free(ctl);
			return -1;
		}
		s->nv = n;
		memcpy(ctl + k * n * 3, p, n * 3 * sizeof *p);
		free(p);
	}
	s->ctl = ctl;
	return ctl != NULL ? 0 : -1;
}

/* A B-spline or Bezier surface id as records; 0 or -1. */
static int
bspline_surface(struct step *st, long id, long line, long face)
{
	size_t mark = st->nv, l = part(st, id, "B_SPLINE_SURFACE_WITH_KNOTS");
	size_t g = part(st, id, "B_SPLINE_SURFACE"), wk = l, o, rw;
	struct loft__bsurf s = { 0, 0, 0, 0, NULL, NULL, NULL, NULL };
	struct loft__bsname nm;
	double *w = NULL;
	int rc = -1, bez = 0;

	if (g == 0 && l != 0)
		g = l, wk = 0;
	if (g == 0 && (g = part(st, id, "BEZIER_SURFACE")) != 0)
		bez = 1;
	o = arg(st, g, 0) != NULL && arg(st, g, 0)->kind == V_STR ? 1 : 0;
	nm = o ? name_of(st, g, face ? face : id) :
	    (struct loft__bsname){ "", 0, face ? face : id };
	s.p = degree(st, g, o);
	s.q = degree(st, g, o + 1);
	if (s.p < 0 || s.q < 0 || surf_points(st, list_arg(st, g, o + 2),
	    &s) != 0) {
		loft__cadin_say(st->c, line, "#%ld: its degrees (1 to %d) or "
		    "rows of control points cannot be read", id,
		    LOFT_BSPLINE_MAXDEG);
		goto done;
	}
	/* simple: u mults at o + 7, v mults o + 8, u knots o + 9, v o + 10 */
	s.tu = surf_knots(st, bez, wk ? wk : g, wk ? 0 : o + 7, wk ? 2 : o + 9,
	    s.nu, s.p);
	s.tv = surf_knots(st, bez, wk ? wk : g, wk ? 1 : o + 8, wk ? 3 : o + 10,
	    s.nv, s.q);
	if (s.tu == NULL || s.tv == NULL) {
		loft__cadin_say(st->c, line, "#%ld: its knots and "
		    "multiplicities do not fit its control points", id);
		goto done;
	}
	if ((rw = part(st, id, "RATIONAL_B_SPLINE_SURFACE")) != 0) {
		size_t k = 0, rows = list_arg(st, rw, 0);

		w = malloc(s.nu * s.nv * sizeof *w);
		for (size_t r = rows ? st->v[rows].first : 0; w != NULL &&
		    r != 0 && k < s.nu; r = st->v[r].next, k++)
			if (numbers(st, r, w + k * s.nv, s.nv) != (long)s.nv)
				break;
		if (w == NULL || k != s.nu) {
			loft__cadin_say(st->c, line, "#%ld: its weights cannot "
			    "be read", id);
			goto done;
		}
		s.w = w;
	}
	rc = loft__bs_surface(st->c, &s, &nm, line);
done:
	free((void *)s.tu);
	free((void *)s.tv);
	free((void *)s.ctl);
	free(w);
	st->nv = mark;
	return rc;
}

/* ---- conics, lines, trims --------------------------------------------- */

/* Quarter turns at most a rational quadratic piece of an arc spans. */
#define ARC_PIECE (M_PI / 2)

/*
 * The arc of the ellipse o + a cos t x + b sin t y from t0 sweeping by
 * sw (signed) as rational quadratic pieces: each piece's middle point
 * lies where the end tangents meet, at the middle angle over cos h (h
 * half the piece's angle), with weight cos h.
 */
static int
arc(struct step *st, const struct frame *f, double a, double b, double t0,
    double sw, const struct loft__bsname *nm, long line)
{
	long k = (long)ceil(fabs(sw) / ARC_PIECE - 1e-12);
	double *ctl, *w, *t, h;
	struct loft__bs bs;
	int rc;

	if (k < 1)
		k = 1;
	h = sw / (double)k / 2;
	ctl = malloc((size_t)(2 * k + 1) * 3 * sizeof *ctl);
	w = malloc((size_t)(2 * k + 1) * sizeof *w);
	t = malloc((size_t)(2 * k + 4) * sizeof *t);
	if (ctl == NULL || w == NULL || t == NULL) {
		free(ctl);
		free(w);
		free(t);
		loft__cadin_say(st->c, line, "out of memory");
		return -1;
	}
	for (long i = 0; i <= 2 * k; i++) {
		double u = t0 + (double)i * h, s = i % 2 ? 1 / cos(h) : 1;

		for (int q = 0; q < 3; q++)
			ctl[3 * i + q] = f->o[q] + s * (a * cos(u) * f->x[q] +
			    b * sin(u) * f->y[q]);
		w[i] = i % 2 ? cos(h) : 1;
	}
	/* knots 0 0 0 1 1 2 2 ... k-1 k-1 k k k */
	t[0] = 0;
	for (long i = 1; i < 2 * k + 3; i++)
		t[i] = (double)((i - 1) / 2);
	t[2 * k + 3] = (double)k;
	bs = (struct loft__bs){ 2, (size_t)(2 * k + 1), t, ctl, w };
	rc = loft__bs_curve(st->c, &bs, nm, line);
	free(ctl);
	free(w);
	free(t);
	return rc;
}

/* The number of value v (a number, or a typed measure of one). */
static int
num_of(const struct step *st, const struct val *v, double *x)
{
	if (v != NULL && v->kind == V_TYPED && v->first != 0 &&
	    st->v[v->first].n == 1)
		v = &st->v[st->v[v->first].first];
	if (v == NULL || v->kind != V_NUM)
		return -1;
	*x = v->x;
	return 0;
}

/* A conic id (CIRCLE, ELLIPSE): its frame and semi-axes; 0 or -1. */
static int
conic(struct step *st, long id, struct frame *f, double *a, double *b)
{
	size_t mark = st->nv, l = part(st, id, "CIRCLE");
	int rc = -1, ell = 0;

	if (l == 0 && (l = part(st, id, "ELLIPSE")) != 0)
		ell = 1;
	if (l != 0 && placement(st, ref_arg(st, l, 1), f) == 0 &&
	    num_of(st, arg(st, l, 2), a) == 0 && (!ell || num_of(st,
	    arg(st, l, 3), b) == 0) && *a > 0 && isfinite(*a)) {
		if (!ell)
			*b = *a;
		*a *= st->mm;
		*b *= st->mm;
		rc = *a > 0 && isfinite(*a) && *b > 0 && isfinite(*b) ? 0 : -1;
	}
	st->nv = mark;
	return rc;
}

/* A LINE id: its point and its vector (direction times magnitude). */
static int
line_of(struct step *st, long id, double *p, double *d)
{
	size_t mark = st->nv, l = part(st, id, "LINE"), v;
	double mag = 1;
	int rc = -1;

	if (l != 0 && point(st, ref_arg(st, l, 1), "CARTESIAN_POINT", p) ==
	    0 && (v = part(st, ref_arg(st, l, 2), "VECTOR")) != 0 &&
	    point(st, ref_arg(st, v, 1), "DIRECTION", d) == 0 &&
	    num_of(st, arg(st, v, 2), &mag) == 0 && unit(d) == 0) {
		for (int k = 0; k < 3; k++)
			d[k] *= mag * st->mm;
		rc = 0;
	}
	st->nv = mark;
	return rc;
}

/* The parameter of trim list l on a line (p, d) or a conic f, a, b:
 * its PARAMETER_VALUE, else its point's projection; 0 or -1. */
static int
trim_at(struct step *st, size_t l, int line, const double *p,
    const double *d, const struct frame *f, double a, double b, double *t)
{
	double x[3];

	for (size_t k = 0; k < (l ? st->v[l].n : 0); k++) {
		const struct val *v = arg(st, l, k);

		if (v != NULL && typed_is(v, "PARAMETER_VALUE"))
			return num_of(st, v, t);
	}
	for (size_t k = 0; k < (l ? st->v[l].n : 0); k++) {
		long r = ref_arg(st, l, k);

		if (r == 0 || point(st, r, "CARTESIAN_POINT", x) != 0)
			continue;
		if (line) {
			double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];

			*t = ((x[0] - p[0]) * d[0] + (x[1] - p[1]) * d[1] +
			    (x[2] - p[2]) * d[2]) / dd;
		} else {
			double u = 0, w = 0;

			for (int q = 0; q < 3; q++) {
				u += (x[q] - f->o[q]) * f->x[q];
				w += (x[q] - f->o[q]) * f->y[q];
			}
			*t = atan2(w / b, u / a);
		}
		return 0;
	}
	return -1;
}

/* A TRIMMED_CURVE of a LINE or a conic as records; 0 or -1. */
static int
trimmed(struct step *st, long id, long line)
{
	size_t mark = st->nv, l = part(st, id, "TRIMMED_CURVE");
	long basis = ref_arg(st, l, 1);
	double p[3], d[3], a = 0, b = 0, t0, t1;
	const struct val *sense = arg(st, l, 4);
	/* read before the basis is parsed, which may move st->v */
	int fwd = sense == NULL || sense->kind != V_ENUM ||
	    loft__word_is(sense->s, sense->len, "T");
	struct loft__bsname nm = name_of(st, l, id);
	int is_line = line_of(st, basis, p, d) == 0, rc = -1;
	struct frame f;

	if (!is_line && conic(st, basis, &f, &a, &b) != 0)
		loft__cadin_say(st->c, line, "#%ld: a trimmed curve whose "
		    "basis is no line, circle or ellipse, passed over", id);
	else if (trim_at(st, list_arg(st, l, 2), is_line, p, d, &f, a, b,
	    &t0) != 0 || trim_at(st, list_arg(st, l, 3), is_line, p, d, &f, a,
	    b, &t1) != 0)
		loft__cadin_say(st->c, line, "#%ld: its trims cannot be read",
		    id);
	else if (is_line) {
		struct loft__bs bs;
		double ctl[6], t[4] = { 0, 0, 1, 1 };

		for (int q = 0; q < 3; q++) {
			ctl[q] = p[q] + t0 * d[q];
			ctl[3 + q] = p[q] + t1 * d[q];
		}
		bs = (struct loft__bs){ 1, 2, t, ctl, NULL };
		rc = loft__bs_curve(st->c, &bs, &nm, line);
	} else {
		/* the sweep from t0 to t1, counterclockwise when sense is .T. */
		double sw = fwd ? t1 - t0 : t0 - t1;

		sw = fmod(sw, 2 * M_PI);
		if (sw <= 0)
			sw += 2 * M_PI;
		rc = arc(st, &f, a, b, t0, fwd ? sw : -sw, &nm, line);
	}
	st->nv = mark;
	return rc;
}

/* A curve id of a geometric set as records; 0, or -1 (complained). */
static int
curve(struct step *st, long id, long line)
{
	struct frame f;
	double a, b;
	size_t mark = st->nv;
	struct loft__bsname nm;
	int rc;

	if (part(st, id, "B_SPLINE_CURVE") || part(st, id,
	    "B_SPLINE_CURVE_WITH_KNOTS") || part(st, id, "BEZIER_CURVE"))
		return bspline_curve(st, id, line);
	if (part(st, id, "TRIMMED_CURVE"))
		return trimmed(st, id, line);
	if (conic(st, id, &f, &a, &b) == 0) {
		nm = name_of(st, part(st, id, "CIRCLE") ? part(st, id, "CIRCLE") :
		    part(st, id, "ELLIPSE"), id);
		rc = arc(st, &f, a, b, 0, 2 * M_PI, &nm, line);
		st->nv = mark;
		return rc;
	}
	return 1;               /* not a curve loft reads */
}

/* ---- faces ------------------------------------------------------------- */

/* Append point x to the bounds (3 numbers each, at most cap). */
static void
bound_add(double **p, size_t *n, size_t *cap, const double *x, int *oom)
{
	if (loft__grow((void **)p, cap, 3 * (*n + 1), sizeof **p) != 0) {
		*oom = 1;
		return;
	}
	memcpy(*p + 3 * *n, x, 3 * sizeof **p);
	(*n)++;
}

/* The points that bound edge curve geometry g (a SURFACE_CURVE's 3-D
 * curve, a conic's box, a B-spline's control points); its vertices are
 * added by the caller. */
static void
edge_bounds(struct step *st, long g, double **p, size_t *n, size_t *cap,
    int *oom)
{
	size_t l;
	struct frame f;
	double a, b, x[3];

	if ((l = part(st, g, "SURFACE_CURVE")) != 0 ||
	    (l = part(st, g, "SEAM_CURVE")) != 0)
		g = ref_arg(st, l, 1);
	if (conic(st, g, &f, &a, &b) == 0) {
		for (int s = 0; s < 4; s++) {
			for (int q = 0; q < 3; q++)
				x[q] = f.o[q] + (s < 2 ? (s ? a : -a) * f.x[q] :
				    (s == 3 ? b : -b) * f.y[q]);
			bound_add(p, n, cap, x, oom);
		}
		return;
	}
	if ((l = part(st, g, "B_SPLINE_CURVE_WITH_KNOTS")) != 0 ||
	    (l = part(st, g, "B_SPLINE_CURVE")) != 0) {
		size_t o = arg(st, l, 0) && arg(st, l, 0)->kind == V_STR, m;
		double *c = point_list(st, list_arg(st, l, o + 1), &m);

		for (size_t i = 0; c != NULL && i < m; i++)
			bound_add(p, n, cap, c + 3 * i, oom);
		free(c);
	}
}

/* The points bounding face l's loops into *p (3 each), *n of them. */
static void
face_bounds(struct step *st, size_t l, double **p, size_t *n, int *oom)
{
	size_t cap = 0, bl = list_arg(st, l, 1);

	*n = 0;
	for (size_t k = 0; k < (bl ? st->v[bl].n : 0); k++) {
		size_t fb = part(st, ref_arg(st, bl, k), "FACE_OUTER_BOUND"), el;
		double x[3];

		if (fb == 0)
			fb = part(st, ref_arg(st, bl, k), "FACE_BOUND");
		el = part(st, ref_arg(st, fb, 1), "EDGE_LOOP");
		for (size_t j = 0; j < (el ? st->v[list_arg(st, el, 1)].n : 0);
		    j++) {
			size_t oe = part(st, ref_arg(st, list_arg(st, el, 1), j),
			    "ORIENTED_EDGE");
			size_t ec = part(st, ref_arg(st, oe, 3), "EDGE_CURVE");

			for (int v = 1; v <= 2; v++) {
				size_t vp = part(st, ref_arg(st, ec, (size_t)v),
				    "VERTEX_POINT");

				if (point(st, ref_arg(st, vp, 1),
				    "CARTESIAN_POINT", x) == 0)
					bound_add(p, n, &cap, x, oom);
			}
			if (ec != 0)
				edge_bounds(st, ref_arg(st, ec, 3), p, n, &cap,
				    oom);
		}
		if ((el = part(st, ref_arg(st, fb, 1), "POLY_LOOP")) != 0) {
			size_t m;
			double *c = point_list(st, list_arg(st, el, 1), &m);

			for (size_t i = 0; c != NULL && i < m; i++)
				bound_add(p, n, &cap, c + 3 * i, oom);
			free(c);
		}
	}
}

/* A PLANE face: the rectangle of its bounds in the plane's axes, as a
 * bezier-surface of degrees 1 and 1 whose normal is the plane's. */
static int
plane_face(struct step *st, long face, size_t l, long plane, long line)
{
	size_t mark = st->nv, n = 0, pl = part(st, plane, "PLANE");
	double *p = NULL, lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY,
	    -INFINITY }, net[12];
	struct frame f;
	struct loft__bsname nm = name_of(st, l, face);
	int oom = 0;

	if (placement(st, ref_arg(st, pl, 1), &f) != 0) {
		loft__cadin_say(st->c, line, "#%ld: its plane's placement "
		    "cannot be read", face);
		return -1;
	}
	face_bounds(st, l, &p, &n, &oom);
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < 2; k++) {
			const double *ax = k ? f.y : f.x;
			double c = 0;

			for (int q = 0; q < 3; q++)
				c += (p[3 * i + q] - f.o[q]) * ax[q];
			lo[k] = fmin(lo[k], c);
			hi[k] = fmax(hi[k], c);
		}
	free(p);
	st->nv = mark;
	if (oom || n == 0 || !(hi[0] > lo[0] && hi[1] > lo[1])) {
		loft__cadin_say(st->c, line, oom ? "out of memory" : "#%ld: a "
		    "plane face without bounds of any area, passed over", face);
		return -1;
	}
	for (int i = 0; i < 2; i++)     /* P_ij, u-major */
		for (int j = 0; j < 2; j++)
			for (int q = 0; q < 3; q++)
				net[3 * (2 * i + j) + q] = f.o[q] + (i ? hi[0] :
				    lo[0]) * f.x[q] + (j ? hi[1] : lo[1]) * f.y[q];
	return loft__bs_patch(st->c, net, 1, 1, &nm, line);
}

/* Count a face of a surface type loft does not read. */
static void
skipped(struct step *st, const struct val *t)
{
	const char *s = t ? t->s : "an unknown surface";
	size_t n = t ? t->len : strlen(s);
	int k;

	for (k = 0; k < NSKIP && st->skip[k].n > 0; k++)
		if (st->skip[k].len == n && memcmp(st->skip[k].s, s, n) == 0)
			break;
	if (k == NSKIP) {       /* the last counts the rest */
		k--;
		s = "other";
		n = 5;
	}
	st->skip[k].s = s;
	st->skip[k].len = n;
	st->skip[k].n++;
}

/* A face: its surface, if loft reads its kind. */
static void
face(struct step *st, const struct ent *e)
{
	size_t mark = st->nv, l = part(st, e->id, "ADVANCED_FACE");
	long sid;

	if (l == 0)
		l = part(st, e->id, "FACE_SURFACE");
	sid = ref_arg(st, l, 2);
	if (part(st, sid, "B_SPLINE_SURFACE") || part(st, sid,
	    "B_SPLINE_SURFACE_WITH_KNOTS") || part(st, sid, "BEZIER_SURFACE"))
		(void)bspline_surface(st, sid, e->line, e->id);
	else if (part(st, sid, "PLANE"))
		(void)plane_face(st, e->id, l, sid, e->line);
	else
		skipped(st, type_of(st, sid));
	st->nv = mark;
}

/* A geometric set: its curves and surfaces. */
static void
set(struct step *st, const struct ent *e)
{
	size_t mark = st->nv, l = part(st, e->id, "GEOMETRIC_SET"), items, inner;

	if (l == 0)
		l = part(st, e->id, "GEOMETRIC_CURVE_SET");
	items = list_arg(st, l, 1);
	inner = st->nv;
	for (size_t k = 0; k < (items ? st->v[items].n : 0); k++) {
		long id = ref_arg(st, items, k);
		const struct ent *ie = find(st, id);
		long line = ie != NULL ? ie->line : e->line;

		if (part(st, id, "B_SPLINE_SURFACE") || part(st, id,
		    "B_SPLINE_SURFACE_WITH_KNOTS") || part(st, id,
		    "BEZIER_SURFACE"))
			(void)bspline_surface(st, id, line, 0);
		else if (curve(st, id, line) > 0) {
			const struct val *t = type_of(st, id);

			if (t == NULL || !typed_is(t, "CARTESIAN_POINT"))
				skipped(st, t);
		}
		st->nv = inner;
	}
	st->nv = mark;
}

/* ---- the length unit ----------------------------------------------------- */

/* Length units followed through conversions up to this deep: an inch
 * of a millimetre of a metre is 2; more is a loop. */
#define UNIT_DEPTH 8

/* ISO 10303-41's si_prefix: millimetres in the metre with that prefix. */
static const struct { const char *name; double mm; } si_prefix[] = {
	{ "EXA", 1e21 }, { "PETA", 1e18 }, { "TERA", 1e15 }, { "GIGA", 1e12 },
	{ "MEGA", 1e9 }, { "KILO", 1e6 }, { "HECTO", 1e5 }, { "DECA", 1e4 },
	{ "DECI", 100 }, { "CENTI", 10 }, { "MILLI", 1 }, { "MICRO", 1e-3 },
	{ "NANO", 1e-6 }, { "PICO", 1e-9 }, { "FEMTO", 1e-12 },
	{ "ATTO", 1e-15 },
};

/* Millimetres in the SI_UNIT parameters l (prefix, name; a simple
 * instance has named_unit's dimensions first), or 0: not a metre. */
static double
si_mm(const struct step *st, size_t l)
{
	size_t k = l != 0 && st->v[l].n == 3 ? 1 : 0;
	const struct val *p = arg(st, l, k), *n = arg(st, l, k + 1);

	if (p == NULL || n == NULL || n->kind != V_ENUM ||
	    !loft__word_is(n->s, n->len, "METRE"))
		return 0;
	if (p->kind == V_UNSET)
		return 1000;
	for (size_t i = 0; p->kind == V_ENUM &&
	    i < sizeof si_prefix / sizeof si_prefix[0]; i++)
		if (loft__word_is(p->s, p->len, si_prefix[i].name))
			return si_prefix[i].mm;
	return 0;
}

/* Millimetres in unit entity id: an SI_UNIT of the metre, or a
 * CONVERSION_BASED_UNIT whose (LENGTH_)MEASURE_WITH_UNIT is a number of
 * such a unit (ISO 10303-41); 0 when it is neither. */
static double
unit_mm(struct step *st, long id, int depth)
{
	size_t mark = st->nv, l, m;
	double mm = 0, x;

	if (depth > UNIT_DEPTH)
		return 0;
	if ((l = part(st, id, "SI_UNIT")) != 0) {
		mm = si_mm(st, l);
	} else if ((l = part(st, id, "CONVERSION_BASED_UNIT")) != 0) {
		long r = ref_arg(st, l, 1);

		if ((m = part(st, r, "LENGTH_MEASURE_WITH_UNIT")) == 0)
			m = part(st, r, "MEASURE_WITH_UNIT");
		if (m != 0 && num_of(st, arg(st, m, 0), &x) == 0 && x > 0)
			mm = x * unit_mm(st, ref_arg(st, m, 1), depth + 1);
	}
	st->nv = mark;
	return mm > 0 && isfinite(mm) ? mm : 0;
}

/* Whether entity e's text holds word (a cheap test before parsing). */
static int
mentions(const struct step *st, const struct ent *e, const char *word)
{
	size_t n = strlen(word);

	for (size_t i = 0; i + n <= e->len; i++)
		if (memcmp(st->buf + e->at + i, word, n) == 0)
			return 1;
	return 0;
}

/* What the length units found tell: how many, the first's entity and
 * millimetres, and whether they all agree. */
struct units {
	long n, first;
	double mm;
	int differ;
};

static void
units_add(struct step *st, struct units *u, long id)
{
	size_t mark = st->nv;
	double mm = unit_mm(st, id, 0);
	int len = part(st, id, "LENGTH_UNIT") != 0;

	st->nv = mark;
	if (!len && mm == 0)
		return;         /* an angle, a solid angle... */
	if (u->n++ == 0) {
		u->first = id;
		u->mm = mm;
	} else if (mm != u->mm) {
		u->differ = 1;
	}
}

/* The length units of the contexts (GLOBAL_UNIT_ASSIGNED_CONTEXT's
 * units), else every LENGTH_UNIT of the file, into *u. */
static void
find_units(struct step *st, struct units *u)
{
	memset(u, 0, sizeof *u);
	for (size_t i = 0; i < st->ne; i++) {
		size_t mark = st->nv, l, list;

		if (!mentions(st, st->e + i, "GLOBAL_UNIT_ASSIGNED_CONTEXT"))
			continue;
		l = part(st, st->e[i].id, "GLOBAL_UNIT_ASSIGNED_CONTEXT");
		list = list_arg(st, l, 0);
		for (size_t k = 0; list != 0 && k < st->v[list].n; k++)
			units_add(st, u, ref_arg(st, list, k));
		st->nv = mark;
	}
	for (size_t i = 0; u->n == 0 && i < st->ne; i++)
		if (mentions(st, st->e + i, "LENGTH_UNIT"))
			units_add(st, u, st->e[i].id);
}

/* The name of unit id for a message: a conversion's name, or the
 * words of the unit's last part (SI_UNIT's prefix and name). */
static void
unit_name(struct step *st, long id, char *buf, size_t size)
{
	size_t mark = st->nv, l = part(st, id, "CONVERSION_BASED_UNIT");
	const struct val *v = arg(st, l, 0);
	size_t at, n;

	if (v != NULL && v->kind == V_STR) {
		(void)loft__cadin_quote(buf, size, v->s, v->len);
	} else {
		const struct ent *e = find(st, id);

		at = e ? e->at : 0;
		n = e ? e->len : 0;
		(void)loft__cadin_quote(buf, size, st->buf + at, n);
	}
	st->nv = mark;
}

/* st->mm from the file's length unit; 1 with a note when there is none
 * that loft reads, or several that differ. */
static void
length_unit(struct step *st)
{
	struct units u;
	char msg[200], name[80];

	find_units(st, &u);
	st->mm = 1;
	if (u.n > 0 && !u.differ && u.mm > 0) {
		st->mm = u.mm;
		return;
	}
	if (u.n == 0)
		snprintf(msg, sizeof msg, "no length unit");
	else if (u.differ)
		snprintf(msg, sizeof msg, "%ld length units that differ (the "
		    "first #%ld)", u.n, u.first);
	else {
		unit_name(st, u.first, name, sizeof name);
		snprintf(msg, sizeof msg, "length unit #%ld '%s' is no metre "
		    "nor a conversion of one", u.first, name);
	}
	strncat(msg, ": coordinates kept as the file has them",
	    sizeof msg - strlen(msg) - 1);
	if (st->c->note != NULL)
		st->c->note(st->c->ctx, 0, msg);
}

/* Whether entity e's body begins with the type word. */
static int
begins(const struct step *st, const struct ent *e, const char *word)
{
	size_t i = skip_space(st->buf + e->at, 0, e->len), k = i;

	while (k < e->len && is_word(st->buf[e->at + k]))
		k++;
	return loft__word_is(st->buf + e->at + i, k - i, word);
}

int
loft_step_read(const char *buf, size_t len, struct loft_cadin *c)
{
	struct step st;
	long nbad = c->nbad;

	memset(&st, 0, sizeof st);
	st.buf = buf;
	st.len = len;
	st.c = c;
	st.nv = 1;
	st.mm = 1;
	if (scan(&st) != 0) {
		free(st.e);
		loft__cadin_say(c, 0, "out of memory");
		return LOFT_ENOMEM;
	}
	if (st.ne > 0)
		qsort(st.e, st.ne, sizeof *st.e, cmp_ent);
	if (st.ne == 0)
		loft__cadin_say(c, 0, "no entity instances: no STEP data");
	else
		length_unit(&st);
	for (size_t i = 0; i < st.ne && !st.oom; i++) {
		if (begins(&st, st.e + i, "ADVANCED_FACE") ||
		    begins(&st, st.e + i, "FACE_SURFACE"))
			face(&st, st.e + i);
		else if (begins(&st, st.e + i, "GEOMETRIC_SET") ||
		    begins(&st, st.e + i, "GEOMETRIC_CURVE_SET"))
			set(&st, st.e + i);
	}
	for (int k = 0; k < NSKIP && st.skip[k].n > 0; k++)
		loft__cadin_say(c, 0, "%ld %.*s %s passed over: loft reads "
		    "B-spline, Bezier and plane surfaces, B-spline, Bezier, "
		    "conic and line curves", st.skip[k].n,
		    (int)(st.skip[k].len > 60 ? 60 : st.skip[k].len),
		    st.skip[k].s, st.skip[k].n > 1 ? "items" : "item");
	if (st.oom)
		loft__cadin_say(c, 0, "out of memory");
	free(st.e);
	free(st.v);
	return st.oom ? LOFT_ENOMEM : c->nbad > nbad ? LOFT_EINPUT : 0;
}
