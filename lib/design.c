/*
 * design.c: designs of patches from the records of a program's input,
 * with its manners of reporting, and back into `patch` records.
 * Program layer (loftprog.h): it reports through a struct loft_run and
 * writes through a struct loft_writer, on patch.c's public interface.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "loftprog.h"
#include "internal.h"

/* Entry (i, j) of B, dim numbers. */
#define BIJ(b, i, j, dim) ((b) + (5 * (i) + (j)) * (dim))

static void
put_real_attr(struct loft_writer *w, const char *key, double x)
{
	char buf[LOFT_NUMBUF];

	loft_format_num(buf, x, 0);
	loft_put_attr(w, key, buf);
}

void
loft_design_put(struct loft_writer *w, const struct loft_design *d, size_t i)
{
	static const char *const ours[] = { "id", "su", "sv", "u0", "u1",
	    "v0", "v1", NULL };
	const struct loft_patch *p = &d->p[i];
	char buf[64 + 3 * LOFT_NUMBUF];

	loft_put_type(w, "patch");
	snprintf(buf, sizeof buf, "%ld", p->id);
	loft_put_attr(w, "id", buf);
	if (p->scale[0] != 1)
		put_real_attr(w, "su", p->scale[0]);
	if (p->scale[1] != 1)
		put_real_attr(w, "sv", p->scale[1]);
	for (int e = 0; e < 4; e++) {
		char *list = NULL;
		size_t len = 0, cap = 0;

		for (size_t k = 0; k < p->nlink[e]; k++) {
			const struct loft_link *l = &p->link[e][k];
			char a[LOFT_NUMBUF], b[LOFT_NUMBUF];
			int n;

			loft_format_num(a, l->a, 0);
			loft_format_num(b, l->b, 0);
			n = l->a == 0 && l->b == 1 ?
			    snprintf(buf, sizeof buf, ",%ld", l->id) :
			    snprintf(buf, sizeof buf, ",%ld:%s:%s", l->id, a, b);
			if (loft__grow((void **)&list, &cap, len + n + 1, 1)) {
				w->bad = LOFT_ENOMEM;
				break;
			}
			memcpy(list + len, buf, (size_t)n + 1);
			len += n;
		}
		if (len > 0 && !w->bad)
			loft_put_attr(w, loft_edge_name[e], list + 1);
		free(list);
	}
	if (p->rec != NULL)
		loft_put_attrs_except(w, p->rec, ours);
	loft_end_line(w);
	for (int r = 0; r < 5; r++)
		loft_put_row(w, BIJ(p->b, r, 0, p->dim), 5 * p->dim);
	loft_end_record(w);
}

int
loft_design_only_patches(struct loft_run *run, const struct loft_record *recs,
    size_t n)
{
	struct loft_error err;
	int rc = 0;

	for (size_t i = 0; i < n; i++)
		if (!loft_record_is(&recs[i], LOFT_KIND_MEMBER)) {
			rc = loft_fail(&err, LOFT_EINPUT, -1, "%s record: %s "
			    "reads patch records", recs[i].type ? recs[i].type :
			    "point", run->prog);
			err.line = 0;
			loft_report(run, &recs[i], &err);
		}
	return rc;
}

int
loft_design_from_records(struct loft_run *run, const struct loft_record *recs,
    size_t n, struct loft_design *d)
{
	struct loft_error err;
	size_t bad;
	int rc = 0;

	for (size_t i = 0; i < n; i++) {
		if (!loft_record_is(&recs[i], LOFT_KIND_MEMBER))
			continue;
		err.line = 0;
		if (loft_design_add(d, &recs[i], &err) != 0) {
			loft_report(run, &recs[i], &err);
			rc = LOFT_EINPUT;
		}
	}
	if (rc == 0 && loft_design_check(d, &bad, &err) != 0) {
		err.line = 0;
		err.row = -1;
		loft_report(run, d->p[bad].rec, &err);
		rc = LOFT_EINPUT;
	}
	return rc;
}
