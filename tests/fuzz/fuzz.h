/*
 * fuzz.h: what the libFuzzer harnesses of tests/fuzz share.  A harness
 * for a program includes the program's source built with -DLOFT_FUZZ
 * (which leaves out its main), sets its options from the input's first
 * bytes, and hands the rest to fuzz_records, which runs the program's
 * record handler over every record the way loft_run_files does and
 * checks the rules of loft.5 on what the handler leaves in the writer.
 * A broken rule aborts, and libFuzzer keeps the input that broke it.
 */
#ifndef FUZZ_H
#define FUZZ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "loftprog.h"

/* abort with a note on standard error: the fuzzer saves the input */
#define FUZZ_ASSERT(cond, what) do { \
	if (!(cond)) { \
		fprintf(stderr, "fuzz: %s:%d: %s\n", __FILE__, __LINE__, \
		    (what)); \
		abort(); \
	} \
} while (0)

/* A stream over size bytes of data (a copy: fmemopen wants it writable
 * in some libcs); NULL for no bytes.  fuzz_close frees both. */
static FILE *
fuzz_open(const uint8_t *data, size_t size, char **copy)
{
	FILE *fp;

	*copy = NULL;
	if (size == 0 || (*copy = malloc(size)) == NULL)
		return NULL;
	memcpy(*copy, data, size);
	if ((fp = fmemopen(*copy, size, "r")) == NULL) {
		free(*copy);
		*copy = NULL;
	}
	return fp;
}

static void
fuzz_close(FILE *fp, char *copy)
{
	if (fp != NULL)
		fclose(fp);
	free(copy);
}

/*
 * What a program wrote for one record: nothing, or whole records, each
 * ended by a blank line, that the reader reads back without complaint
 * (so no NaN, no infinity, no number it cannot parse, whatever -p).
 */
static void
fuzz_check_output(const char *buf, size_t len)
{
	struct loft_record rec = { 0 };
	struct loft_error err;
	struct loft_reader *rd;
	char *copy;
	FILE *fp;
	int r, n = 0;

	if (len == 0)
		return;
	FUZZ_ASSERT(len >= 2 && buf[len - 1] == '\n' && buf[len - 2] == '\n',
	    "output does not end with a blank line");
	FUZZ_ASSERT(memchr(buf, '\0', len) == NULL, "NUL in output");
	fp = fuzz_open((const uint8_t *)buf, len, &copy);
	FUZZ_ASSERT(fp != NULL, "fmemopen");
	rd = loft_reader_new(fp, "output");
	FUZZ_ASSERT(rd != NULL, "out of memory");
	while ((r = loft_read(rd, &rec, &err)) == 1) {
		FUZZ_ASSERT(rec.nrows > 0, "output record without rows");
		n++;
	}
	if (r != 0)
		fprintf(stderr, "fuzz: output line %ld: %s\n", err.line, err.msg);
	FUZZ_ASSERT(r == 0, "output does not read back");
	FUZZ_ASSERT(n > 0, "output holds no record");
	loft_record_free(&rec);
	loft_reader_free(rd);
	fuzz_close(fp, copy);
}

/* A failed record's message: some words, one line, and a line number. */
static void
fuzz_check_error(const struct loft_record *rec, const struct loft_error *err)
{
	long line = err->line ? err->line : loft_row_line(rec, err->row);

	FUZZ_ASSERT(err->msg[0] != '\0', "error without a message");
	FUZZ_ASSERT(strchr(err->msg, '\n') == NULL, "message of two lines");
	FUZZ_ASSERT(line >= 1, "message names no line");
}

/*
 * Run run->handle over every record of the bytes, as loft_run_files
 * does, and check each outcome.  Each record is handled twice: the
 * output must not depend on what the handler did before (records are
 * independent, and the output deterministic).
 */
static void
fuzz_records(struct loft_run *run, const uint8_t *data, size_t size)
{
	struct loft_record rec = { 0 };
	struct loft_error err;
	struct loft_reader *rd;
	char *copy, *first = NULL;
	size_t firstlen;
	FILE *fp = fuzz_open(data, size, &copy);
	int r;

	if (fp == NULL)
		return;
	rd = loft_reader_new(fp, "fuzz");
	FUZZ_ASSERT(rd != NULL, "out of memory");
	while ((r = loft_read(rd, &rec, &err)) != 0 && r != LOFT_READ_FAIL) {
		if (r == LOFT_READ_BAD) {
			fuzz_check_error(&rec, &err);
			continue;
		}
		for (int pass = 0; pass < 2; pass++) {
			int rc;

			run->w.len = 0;
			run->w.bad = 0;
			run->w.col = 0;
			err.line = 0;
			err.row = -1;
			rc = run->handle(run, &rec, &err);
			if (rc != 0) {
				fuzz_check_error(&rec, &err);
				run->w.len = 0;
			} else if (run->w.bad) {
				run->w.len = 0;
			}
			if (pass == 0) {
				firstlen = run->w.len;
				first = malloc(firstlen + 1);
				FUZZ_ASSERT(first != NULL, "out of memory");
				if (firstlen > 0)
					memcpy(first, run->w.buf, firstlen);
				fuzz_check_output(first, firstlen);
			} else {
				FUZZ_ASSERT(run->w.len == firstlen &&
				    (firstlen == 0 ||
				    memcmp(first, run->w.buf, firstlen) == 0),
				    "the same record gives different output");
				free(first);
				first = NULL;
			}
		}
	}
	FUZZ_ASSERT(r == 0, "read error on memory");
	loft_record_free(&rec);
	loft_reader_free(rd);
	fuzz_close(fp, copy);
	loft_writer_free(&run->w);
}

/*
 * For the programs that take the whole input as one design (loft.5,
 * Designs): read every record of the bytes as loft_run_design does; when
 * one is bad, check its message and stop (nothing would be written).
 * Otherwise hand them all to design twice: both runs must give the same
 * outcome and the same output, whole records that read back, or, on
 * failure, nothing (loft_run_design drops it).
 */
static void
fuzz_design(struct loft_run *run, loft_design_handler design,
    const uint8_t *data, size_t size)
{
	struct loft_record rec = { 0 }, *recs = NULL;
	struct loft_error err;
	struct loft_reader *rd;
	char *copy, *first = NULL;
	size_t n = 0, firstlen = 0;
	FILE *fp = fuzz_open(data, size, &copy);
	int r, bad = 0, firstrc = 0;

	if (fp == NULL)
		return;
	rd = loft_reader_new(fp, "fuzz");
	FUZZ_ASSERT(rd != NULL, "out of memory");
	while ((r = loft_read(rd, &rec, &err)) != 0 && r != LOFT_READ_FAIL) {
		if (r == LOFT_READ_BAD) {
			fuzz_check_error(&rec, &err);
			bad = 1;
			continue;
		}
		recs = realloc(recs, (n + 1) * sizeof *recs);
		FUZZ_ASSERT(recs != NULL, "out of memory");
		memset(&recs[n], 0, sizeof recs[n]);
		FUZZ_ASSERT(loft_record_copy(&recs[n], &rec) == 0,
		    "out of memory");
		n++;
	}
	FUZZ_ASSERT(r == 0, "read error on memory");
	for (int pass = 0; !bad && pass < 2; pass++) {
		int rc;

		run->w.len = 0;
		run->w.bad = 0;
		run->w.col = 0;
		rc = design(run, recs, n) != 0;
		if (rc != 0 || run->w.bad)
			run->w.len = 0;
		if (pass == 0) {
			firstrc = rc;
			firstlen = run->w.len;
			first = malloc(firstlen + 1);
			FUZZ_ASSERT(first != NULL, "out of memory");
			if (firstlen > 0)
				memcpy(first, run->w.buf, firstlen);
			fuzz_check_output(first, firstlen);
		} else {
			FUZZ_ASSERT(rc == firstrc && run->w.len == firstlen &&
			    (firstlen == 0 || memcmp(first, run->w.buf,
			    firstlen) == 0),
			    "the same design gives different output");
		}
	}
	free(first);
	for (size_t i = 0; i < n; i++)
		loft_record_free(&recs[i]);
	free(recs);
	loft_record_free(&rec);
	loft_reader_free(rd);
	fuzz_close(fp, copy);
	loft_writer_free(&run->w);
}

/* Where the programs' messages (-v) go while fuzzing. */
static FILE *
fuzz_null(void)
{
	static FILE *null;

	if (null == NULL)
		null = fopen("/dev/null", "w");
	FUZZ_ASSERT(null != NULL, "/dev/null");
	return null;
}

#endif
