/*
 * run.c: the read-compute-write loop every program shares, and its
 * manners: one message per bad record, output whole records only, go on
 * after a bad record or an unreadable file, fail on a write error.
 * Program layer (loftprog.h): it reads and writes FILEs and prints.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "loftprog.h"
#include "internal.h"
#include "version.h"

#define STDIN_NAME "<stdin>"

/*
 * stdio's buffers are a few kilobytes: on a pipe that is several system
 * calls a record.  RUN_BUFSIZE bytes each way make about a tenth as
 * many (the insole pipeline of make bench: 2,780 writes, not 25,480).
 * A terminal keeps its own buffering, so typed records are answered at
 * once.
 */
#define RUN_BUFSIZE 65536

/* Give fp the buffer buf if fp is a file or pipe that is not a terminal
 * and has not been read or written yet (the caller's promise). */
static void
big_buffer(FILE *fp, char *buf)
{
	int fd = fileno(fp);

	if (fd >= 0 && !isatty(fd))
		(void)setvbuf(fp, buf, _IOFBF, RUN_BUFSIZE);
}

void
loft_report(struct loft_run *run, const struct loft_record *rec,
    const struct loft_error *err)
{
	long line = err->line ? err->line : loft_row_line(rec, err->row);

	fprintf(run->msg, "%s: %s:%ld: %s\n", run->prog, rec->file, line,
	    err->msg);
	run->status = 1;
}

/* Write what the handler made; 0, or -1 on a write error. */
static int
commit(struct loft_run *run)
{
	struct loft_writer *w = &run->w;

	if (w->len > 0 && fwrite(w->buf, 1, w->len, run->out) != w->len)
		return -1;
	return 0;
}

/* Handle every record of one open stream; -1 when output failed. */
static int
run_stream(struct loft_run *run, FILE *fp, const char *name)
{
	struct loft_reader *rd = loft_reader_new(fp, name);
	struct loft_record rec = { 0 };
	struct loft_error err;
	int r, out = 0;

	if (rd == NULL) {
		fprintf(run->msg, "%s: %s: out of memory\n", run->prog, name);
		run->status = 1;
		return 0;
	}
	while ((r = loft_read(rd, &rec, &err)) != 0) {
		if (r == LOFT_READ_FAIL) {
			if (err.line > 0)
				fprintf(run->msg, "%s: %s:%ld: %s\n", run->prog,
				    name, err.line, err.msg);
			else
				fprintf(run->msg, "%s: %s: %s\n", run->prog,
				    name, err.msg);
			run->status = 1;
			break;
		}
		if (r == LOFT_READ_BAD) {
			loft_report(run, &rec, &err);
			continue;
		}
		loft_writer_cut(&run->w, 0);
		run->w.bad = 0;
		err.line = 0;
		err.row = -1;
		if (run->handle(run, &rec, &err) != 0) {
			loft_report(run, &rec, &err);
		} else if (run->w.bad) {
			err.row = -1;
			snprintf(err.msg, sizeof err.msg, "%s", run->w.bad ==
			    LOFT_ENOMEM ? "out of memory" :
			    "result is not finite (the input is too extreme)");
			loft_report(run, &rec, &err);
		} else if (commit(run) != 0) {
			out = -1;
			break;
		}
	}
	loft_record_free(&rec);
	loft_reader_free(rd);
	return out;
}

/* Report a failed write, quietly for a closed pipe; returns 1. */
static int
write_failed(struct loft_run *run)
{
	if (errno != EPIPE)
		fprintf(run->msg, "%s: write error: %s\n", run->prog,
		    strerror(errno ? errno : EIO));
	return 1;
}

int
loft_opt_digits(const char *arg, struct loft_writer *w,
    struct loft_error *err)
{
	long digits;

	if (loft_parse_int(arg, 1, 17, &digits, err) != 0)
		return LOFT_EINPUT;
	w->digits = (int)digits;
	return 0;
}

int
loft_opt_fields(const char *arg, const char *const *names, int *field,
    int max, int *n, struct loft_error *err)
{
	char word[32];

	*n = 0;
	for (const char *p = arg;; p++) {
		size_t len = strcspn(p, ",");

		if (*n == max)
			return loft_fail(err, LOFT_EINPUT, -1, "more than %d "
			    "fields", max);
		if (len >= sizeof word)
			len = sizeof word - 1;
		memcpy(word, p, len);
		word[len] = '\0';
		if (loft_parse_word(word, names, &field[(*n)++], err) != 0)
			return LOFT_EINPUT;
		p += strcspn(p, ",");
		if (*p == '\0')
			return 0;
	}
}

/* The program's name in a usage text "usage: prog ...", *n bytes long. */
static const char *
usage_prog(const char *text, int *n)
{
	if (strncmp(text, "usage: ", 7) != 0) {
		*n = 4;
		return "loft";
	}
	*n = (int)strcspn(text + 7, " \n");
	return text + 7;
}

/*
 * The exit status after writing to fp (rc < 0: the write failed) for a
 * program whose usage text is usage: status, or 1 with "prog: write
 * error: reason" on standard error (none for a closed pipe) when status
 * is 0 and the write or its flush failed.
 */
static int
written(FILE *fp, int rc, const char *usage, int status)
{
	int n;
	const char *prog = usage_prog(usage, &n);

	if ((rc < 0 || fflush(fp) != 0 || ferror(fp)) && status == 0) {
		if (errno != EPIPE)
			fprintf(stderr, "%.*s: write error: %s\n", n, prog,
			    strerror(errno ? errno : EIO));
		status = 1;
	}
	return status;
}

void
loft_usage(const char *text, int status)
{
	FILE *fp = status == 0 ? stdout : stderr;

	errno = 0;
	exit(written(fp, fputs(text, fp) == EOF ? -1 : 0, text, status));
}

/* Append s to the text buf[0..len) of n bytes, cut to fit; its length. */
static size_t
append(char *buf, size_t n, size_t len, const char *s)
{
	size_t k = strlen(s);

	if (k > n - 1 - len)
		k = n - 1 - len;
	memcpy(buf + len, s, k);
	buf[len + k] = '\0';
	return len + k;
}

const char *
loft_usage_words(char *buf, size_t n, const char *head,
    const char *const *name, size_t stride, const char *tail)
{
	size_t len = append(buf, n, 0, head);

	for (size_t i = 0; *name != NULL; i++) {
		len = append(buf, n, append(buf, n, len, i > 0 ? "|" : ""),
		    *name);
		name = (const char *const *)(const void *)((const char *)name +
		    stride);
	}
	(void)append(buf, n, len, tail);
	return buf;
}

void
loft_usage_error(const char *usage, int opt, const char *msg)
{
	int n;
	const char *prog = usage_prog(usage, &n);

	if (opt != 0)
		fprintf(stderr, "%.*s: -%c %s\n", n, prog, opt, msg);
	else
		fprintf(stderr, "%.*s: %s\n", n, prog, msg);
	loft_usage(usage, 2);
}

void
loft_opt_long(int argc, char *argv[], const char *usage)
{
	int n, rc;
	const char *prog = usage_prog(usage, &n);

	if (argc < 2 || argv[1] == NULL)
		return;
	if (strcmp(argv[1], "--help") == 0)
		loft_usage(usage, 0);
	if (strcmp(argv[1], "--version") == 0) {
		errno = 0;
		rc = printf("%.*s (loft) %s\n", n, prog, LOFT_VERSION);
		exit(written(stdout, rc < 0 ? -1 : 0, usage, 0));
	}
}

/* Release the writer, flush the output, and return the exit status. */
static int
finish(struct loft_run *run)
{
	loft_writer_free(&run->w);
	errno = 0;
	if (fflush(run->out) != 0 || ferror(run->out))
		return write_failed(run);
	return run->status;
}

int
loft_run_made(struct loft_run *run)
{
	int status;

	if (run->w.bad) {
		fprintf(run->msg, "%s: %s\n", run->prog, run->w.bad ==
		    LOFT_ENOMEM ? "out of memory" : "result is not finite");
		run->status = 1;
		loft_writer_cut(&run->w, 0);
	}
	status = loft_run_write(run, run->w.buf, run->w.len);
	loft_writer_free(&run->w);
	return status;
}

int
loft_run_files(struct loft_run *run, int nfiles, char **files)
{
	static char *stdin_only[] = { "-" };

	/* one each for the output, stdin and the file open at the time;
	 * the output's and stdin's set once, before their first use */
	static char outbuf[RUN_BUFSIZE], inbuf[RUN_BUFSIZE],
	    filebuf[RUN_BUFSIZE];
	static int out_set, stdin_set;

	if (!out_set) {
		out_set = 1;
		big_buffer(run->out, outbuf);
	}
	if (nfiles == 0) {
		nfiles = 1;
		files = stdin_only;
	}
	for (int i = 0; i < nfiles; i++) {
		int is_stdin = strcmp(files[i], "-") == 0;
		FILE *fp = is_stdin ? stdin : fopen(files[i], "r");
		int rc;

		if (fp == NULL) {
			fprintf(run->msg, "%s: %s: %s\n", run->prog, files[i],
			    strerror(errno));
			run->status = 1;
			continue;
		}
		if (!is_stdin) {
			big_buffer(fp, filebuf);
		} else if (!stdin_set) {
			stdin_set = 1;
			big_buffer(fp, inbuf);
		}
		errno = 0;
		rc = run_stream(run, fp, is_stdin ? STDIN_NAME : files[i]);
		if (!is_stdin)
			fclose(fp);
		if (rc != 0) {
			loft_writer_free(&run->w);
			return write_failed(run);
		}
	}
	return finish(run);
}

/* The records loft_run_design collects before it hands them over. */
struct collected {
	struct loft_record *recs;
	size_t n, cap;
};

static int
collect(struct loft_run *run, const struct loft_record *rec,
    struct loft_error *err)
{
	struct collected *c = run->ctx;

	if (loft__grow((void **)&c->recs, &c->cap, c->n + 1,
	    sizeof *c->recs) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	memset(&c->recs[c->n], 0, sizeof c->recs[c->n]);
	if (loft_record_copy(&c->recs[c->n], rec) != 0) {
		loft_record_free(&c->recs[c->n]);
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	}
	c->n++;
	return 0;
}

int
loft_run_design(struct loft_run *run, int nfiles, char **files,
    loft_design_handler design)
{
	struct collected c = { 0 };
	void *ctx = run->ctx;
	struct loft_error err;
	int status;

	run->ctx = &c;
	run->handle = collect;
	status = loft_run_files(run, nfiles, files);
	run->ctx = ctx;
	if (status != 0) {
		if (c.n > 0)
			fprintf(run->msg, "%s: nothing written: the input "
			    "is one design, and part of it is bad\n",
			    run->prog);
	} else {
		loft_writer_cut(&run->w, 0);    /* loft_run_files freed it */
		run->w.bad = 0;
		if (design(run, c.recs, c.n) != 0) {
			run->status = 1;
		} else if (run->w.bad) {
			err.line = 0;
			err.row = -1;
			snprintf(err.msg, sizeof err.msg, "%s", run->w.bad ==
			    LOFT_ENOMEM ? "out of memory" : "result is not "
			    "finite (the input is too extreme)");
			if (c.n > 0)
				loft_report(run, &c.recs[0], &err);
			else
				fprintf(run->msg, "%s: %s\n", run->prog,
				    err.msg);
		} else {
			errno = 0;
			if (commit(run) != 0 || fflush(run->out) != 0 ||
			    ferror(run->out))
				status = write_failed(run);
		}
		loft_writer_free(&run->w);
		if (run->status != 0)
			status = 1;
	}
	for (size_t i = 0; i < c.n; i++)
		loft_record_free(&c.recs[i]);
	free(c.recs);
	return status;
}

int
loft_run_write(struct loft_run *run, const char *doc, size_t len)
{
	errno = 0;
	if ((len > 0 && fwrite(doc, 1, len, run->out) != len) ||
	    fflush(run->out) != 0 || ferror(run->out))
		return write_failed(run);
	return run->status;
}
