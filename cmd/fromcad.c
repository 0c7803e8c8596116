/*
 * fromcad: read CAD documents (DXF, SVG, CSV, STEP, IGES) into loft streams: each
 * named file whole, its drawing's curves as records.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "loftprog.h"

struct opts {
	int format;             /* of loft_cadin_readers, or -1: by content */
	const char *file;       /* the document being read, for messages */
	struct loft_run *run;
};

/* The usage text, -f's words from the table of readers. */
static const char *
usage(void)
{
	static char text[512];

	return loft_usage_words(text, sizeof text, "usage: fromcad [-FHS] "
	    "[-f ", &loft_cadin_readers[0].name, sizeof loft_cadin_readers[0],
	    "] [-t tolerance] [-p digits] [file ...]\n");
}

/* The complaint of a document no reader takes, naming the readers'
 * words from their table. */
static const char *
not_read(void)
{
	static char text[256];

	return loft_usage_words(text, sizeof text, "not a document fromcad "
	    "reads (", &loft_cadin_readers[0].name,
	    sizeof loft_cadin_readers[0], "; -f names the format)");
}

/* A reader's complaint: "fromcad: FILE:LINE: what". */
static void
complain(void *ctx, long line, const char *msg)
{
	const struct opts *o = ctx;

	if (line > 0)
		fprintf(o->run->msg, "fromcad: %s:%ld: %s\n", o->file, line,
		    msg);
	else
		fprintf(o->run->msg, "fromcad: %s: %s\n", o->file, msg);
	o->run->status = 1;
}

/* A reader's note of what it passed over: said, not an error. */
static void
note(void *ctx, long line, const char *msg)
{
	const struct opts *o = ctx;

	(void)line;
	fprintf(o->run->msg, "fromcad: %s: %s\n", o->file, msg);
}

/* All of fp into *buf (malloc'd); 0, or an errno value.  A file's own
 * size is the first guess, so that a large drawing is not copied as the
 * buffer grows. */
static int
slurp(FILE *fp, char **buf, size_t *len)
{
	struct stat st;
	size_t cap = 1 << 16, n = 0, got;
	char *b, *nb;

	if (fstat(fileno(fp), &st) == 0 && S_ISREG(st.st_mode) &&
	    st.st_size > 0 && (unsigned long long)st.st_size < ((size_t)-1) / 4)
		cap = (size_t)st.st_size + 1;
	if ((b = malloc(cap)) == NULL)
		return ENOMEM;
	while ((got = fread(b + n, 1, cap - n, fp)) > 0) {
		n += got;
		if (n == cap) {
			if (cap > ((size_t)-1) / 4 ||
			    (nb = realloc(b, 2 * cap)) == NULL) {
				free(b);
				return ENOMEM;
			}
			b = nb;
			cap *= 2;
		}
	}
	if (ferror(fp)) {
		int e = errno;  /* read once: free may change it */

		free(b);
		return e != 0 ? e : EIO;
	}
	*buf = b;
	*len = n;
	return 0;
}

/* Read one document and write its records; 0, or -1 on a write error. */
static int
read_document(struct opts *o, struct loft_cadin *cad, const char *name)
{
	struct loft_run *run = o->run;
	int is_stdin = strcmp(name, "-") == 0, format, e;
	FILE *fp = is_stdin ? stdin : fopen(name, "rb");
	char *buf;
	size_t len;

	o->file = is_stdin ? "<stdin>" : name;
	if (fp == NULL) {
		complain(o, 0, strerror(errno));
		return 0;
	}
	errno = 0;
	e = slurp(fp, &buf, &len);
	if (!is_stdin)
		fclose(fp);
	if (e != 0) {
		complain(o, 0, strerror(e));
		return 0;
	}
	format = o->format >= 0 ? o->format : loft_cadin_sniff(buf, len);
	if (len == 0)
		complain(o, 0, "empty file: no drawing in it");
	else if (format < 0)
		complain(o, 0, not_read());
	else
		loft_cadin_read(format, buf, len, cad);
	free(buf);
	e = loft_run_write(run, run->w.buf, run->w.len);
	loft_writer_cut(&run->w, 0);
	return e != 0 && ferror(run->out) ? -1 : 0;
}

int
main(int argc, char *argv[])
{
	struct opts o = { -1, "", NULL };
	struct loft_run run = { .prog = "fromcad", .out = stdout, .msg = stderr,
	    .ctx = &o };
	struct loft_cadin cad = { 0, &run.w, complain, &o, 0, 0, 0, 0, note };
	struct loft_error err;
	char *stdin_only[] = { "-" };
	const char *usage_text = usage();
	int c;

	o.run = &run;
	loft_opt_long(argc, argv, usage_text);
	while ((c = getopt(argc, argv, "FHSf:t:p:h")) != -1) {
		switch (c) {
		case 'F': cad.fills = 1; break;
		case 'H': cad.hidden = 1; break;
		case 'S': cad.strict = 1; break;
		case 'f':
			if (loft_cadin_find(optarg, &o.format, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 't':
			if (loft_parse_real(optarg, 1e-300, 1e300, &cad.tol,
			    &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'p':
			if (loft_opt_digits(optarg, &run.w, &err))
				loft_usage_error(usage_text, c, err.msg);
			break;
		case 'h': loft_usage(usage_text, 0); break;
		default: loft_usage(usage_text, 2);
		}
	}
	argc -= optind;
	argv += optind;
	if (argc == 0) {
		argc = 1;
		argv = stdin_only;
	}
	for (int i = 0; i < argc; i++)
		if (read_document(&o, &cad, argv[i]) != 0) {
			loft_writer_free(&run.w);
			return 1;
		}
	loft_writer_free(&run.w);
	return run.status;
}
