/*
 * patchjoin: join a subsidiary patch to a principal patch along their
 * nearest edges, with continuous slopes across it (MacCallum 1970,
 * section 6).
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	long principal, subsidiary;
	int have_p, have_s;
	int verbose;
};

static const char usage_text[] =
    "usage: patchjoin -P id -S id [-v] [-p digits] [file ...]\n";

static int
join_design(struct loft_run *run, const struct loft_record *recs, size_t n)
{
	const struct opts *o = run->ctx;
	struct loft_design d = { 0 };
	struct loft_join_info info;
	struct loft_error err;
	long ip = -1, is = -1;
	int rc = 0;

	if (loft_design_only_patches(run, recs, n) != 0 ||
	    loft_design_from_records(run, recs, n, &d) != 0)
		rc = 1;
	if (rc == 0 && ((ip = loft_design_find(&d, o->principal)) < 0 ||
	    (is = loft_design_find(&d, o->subsidiary)) < 0)) {
		fprintf(run->msg, "patchjoin: no patch with id %ld in the "
		    "input\n", ip < 0 ? o->principal : o->subsidiary);
		rc = 1;
	}
	err.line = 0;
	if (rc == 0 && loft_design_join(&d, (size_t)ip, (size_t)is, &info,
	    &err) != 0) {
		loft_report(run, d.p[is].rec, &err);
		rc = 1;
	}
	if (rc == 0 && o->verbose)
		fprintf(run->msg, "patchjoin: %s:%ld: edge %s of %ld joined to "
		    "edge %s of %ld%s; they were %.3g apart (size %.3g); "
		    "now %.3g apart, largest slope mismatch %.3g\n",
		    d.p[is].rec->file, d.p[is].rec->line,
		    loft_edge_name[info.edge_s], o->subsidiary,
		    loft_edge_name[info.edge_p], o->principal, info.reversed ?
		    ", running the other way" : "", info.gap, info.size,
		    info.pos_after, info.slope_after);
	for (size_t i = 0; rc == 0 && i < d.n; i++)
		loft_design_put(&run->w, &d, i);
	loft_design_free(&d);
	return rc;
}

#ifndef LOFT_FUZZ         /* tests/fuzz/ takes the handler without main */
int
main(int argc, char *argv[])
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "patchjoin", .out = stdout,
	    .msg = stderr, .ctx = &o };
	struct loft_error err;
	int c, rc = 0;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "P:S:vp:h")) != -1) {
		switch (c) {
		case 'P': rc = loft_parse_int(optarg, 0, LONG_MAX,
		    &o.principal, &err); o.have_p = 1; break;
		case 'S': rc = loft_parse_int(optarg, 0, LONG_MAX,
		    &o.subsidiary, &err); o.have_s = 1; break;
		case 'v': o.verbose = 1; break;
		case 'p': rc = loft_opt_digits(optarg, &run.w, &err); break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
		if (rc != 0)
			loft_usage_error(usage_text, c, err.msg);
	}
	if (!o.have_p || !o.have_s)
		loft_usage_error(usage_text, 0, "give the two patches with -P "
		    "and -S");
	return loft_run_design(&run, argc - optind, argv + optind,
	    join_design);
}
#endif
