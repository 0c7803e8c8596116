/*
 * tocad: write every record of the input into one CAD document: DXF,
 * SVG at true scale, STEP, IGES or STL.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"
#include "loftcad.h"

/* The usage text, -f's words from the table of formats. */
static const char *
usage(void)
{
	static char text[512];

	return loft_usage_words(text, sizeof text, "usage: tocad -f ",
	    &loft_cad_formats[0].name, sizeof loft_cad_formats[0], " [-s] [-b] "
	    "[-t tolerance] [-n steps] [-u mm|cm|m|in] [file ...]\n");
}

static int
tocad_record(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	return loft_cad_record(run->ctx, rec, err);
}

/* The words of -f, from the table of formats. */
static int
find_format(const char *s, const struct loft_cad_format **f,
    struct loft_error *err)
{
	int i;

	if (loft_cad_format_find(s, &i, err) != 0)
		return -1;
	*f = loft_cad_formats[i].format;
	return 0;
}

/* Write the document, or say why there is none; the exit status. */
static int
finish(struct loft_run *run, struct loft_cad_doc *d)
{
	struct loft_error err;
	int status;

	if (loft_cad_finish(d, &err) != 0) {
		fprintf(run->msg, "%s: %s\n", run->prog, err.msg);
		run->status = 1;
		status = loft_run_write(run, NULL, 0);
	} else {
		/* the head, then the body; a failed write of the head shows
		 * in loft_run_write's check of the stream */
		if (d->head.len > 0)
			fwrite(d->head.buf, 1, d->head.len, run->out);
		status = loft_run_write(run, d->out.buf, d->out.len);
	}
	loft_cad_free(d);
	return status;
}

int
main(int argc, char *argv[])
{
	static const char *const unit_words[] = { "mm", "cm", "m", "in", NULL };
	static const double unit_mm[] = { 1, 10, 1000, 25.4 };
	struct loft_cad_opts o = { .unit_mm = 1, .unit_name = "mm" };
	const struct loft_cad_format *f = NULL;
	struct loft_cad_doc d;
	struct loft_run run = { .prog = "tocad", .out = stdout, .msg = stderr,
	    .handle = tocad_record, .ctx = &d };
	struct loft_error err;
	const char *usage_text = usage();
	int c, u;

	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "f:sbt:n:u:h")) != -1) {
		switch (c) {
		case 'f':
			if (find_format(optarg, &f, &err) != 0)
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 's': o.exact = 1; break;
		case 'b': o.binary = 1; break;
		case 't':
			if (loft_parse_real(optarg, 0, 1e300, &o.tol, &err))
				loft_usage_error(usage_text, c, err.msg);
			if (o.tol == 0) {
				snprintf(err.msg, sizeof err.msg, "%s: want a "
				    "tolerance above 0", optarg);
				loft_usage_error(usage_text, c, err.msg);
			}
			break;
		case 'n':
			if (loft_parse_int(optarg, 1, 1000, &o.per, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'u':
			if (loft_parse_word(optarg, unit_words, &u, &err))
				loft_usage_error(usage_text, c, err.msg);
			o.unit_name = unit_words[u];
			o.unit_mm = unit_mm[u];
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	if (f == NULL)
		loft_usage_error(usage_text, 0, "-f names the format");
	loft_cad_init(&d, f, &o);
	loft_run_files(&run, argc - optind, argv + optind);
	return finish(&run, &d);
}
