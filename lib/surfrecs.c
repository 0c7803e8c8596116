/*
 * surfrecs.c: the surfaces of a whole input, for the programs that take
 * a hull or any other set of surface records at once (hydro, offsets).
 */
#include <stdlib.h>

#include "loftprog.h"

int
loft_surfaces_from_records(struct loft_run *run,
    const struct loft_record *recs, size_t n, struct loft_surface **out,
    size_t *ns)
{
	struct loft_surface *s;
	struct loft_error err;
	size_t k = 0;
	int rc = 0;

	*out = NULL;
	*ns = 0;
	if ((s = calloc(n + 1, sizeof *s)) == NULL) {
		fprintf(run->msg, "%s: out of memory\n", run->prog);
		run->status = 1;
		return 1;
	}
	for (size_t i = 0; i < n; i++) {
		err.line = 0;
		if (!loft_is_surface(&recs[i]))
			loft_fail(&err, LOFT_EINPUT, -1, "%s record: %s reads "
			    "surface records", recs[i].type ? recs[i].type :
			    "a point", run->prog);
		else if (loft_surface_from_record(&recs[i], &s[k], &err) != 0)
			;
		else if (s[k].dim != 3)
			loft_fail(&err, LOFT_EINPUT, -1, "a surface of %d "
			    "coordinates: %s takes surfaces in space", s[k].dim,
			    run->prog);
		else {
			k++;
			continue;
		}
		loft_report(run, &recs[i], &err);
		rc = 1;
	}
	if (rc != 0) {
		free(s);
		return rc;
	}
	*out = s;
	*ns = k;
	return 0;
}
