/*
 * bezapprox.c: libFuzzer harness of bezapprox's record handler and of
 * its expressions.  Byte 0 chooses the options, byte 1 the -p digits
 * and the mode; the rest is the stream, or in expression mode the
 * expressions -x, -y [, -z], one a line.
 *   byte 0: bits 0-2  -n 1..8 (3..8 with -c)   bit 3  -c
 *           bit 4     -n m,n, m from bits 5-6 (1..4)   bit 7  -v
 *   byte 1: bits 0-4  -p (0: lossless)   bit 5  expressions   bit 6  -z
 */
#include "../../cmd/bezapprox.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Compile the expressions of lines in text; 0, or -1 when one fails
 * (which must say where). */
static int
fuzz_compile(struct opts *o, char *text)
{
	const char *vars = o->m > 0 ? "uv" : "t";
	struct loft_error err;
	char *line = text;
	int col;

	for (int k = 0; k < o->dim; k++) {
		char *nl = line != NULL ? strchr(line, '\n') : NULL;

		if (nl != NULL)
			*nl = '\0';
		o->src[k] = line != NULL ? line : "";
		o->e[k] = loft_expr_parse(o->src[k], vars, &col, &err);
		if (o->e[k] == NULL) {
			FUZZ_ASSERT(err.msg[0] != '\0' && col >= 1 &&
			    (size_t)col <= strlen(o->src[k]) + 1,
			    "a syntax error without a message or a column");
			return -1;
		}
		line = nl != NULL ? nl + 1 : NULL;
	}
	return 0;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "bezapprox", .msg = fuzz_null(),
	    .handle = approx_record, .ctx = &o };
	struct loft_error err;
	char *text;

	if (size < 2)
		return 0;
	o.clamp = (data[0] & 8) != 0;
	o.n = 1 + (data[0] & 7);
	if (o.clamp && o.n < 3)
		o.n += 2;
	o.m = data[0] & 16 ? 1 + ((data[0] >> 5) & 3) : 0;
	if (o.clamp && o.m > 0 && o.m < 3)
		o.m += 2;
	o.verbose = (data[0] & 128) != 0;
	run.w.digits = (data[1] & 31) % 18;
	if (!(data[1] & 32)) {
		fuzz_records(&run, data + 2, size - 2);
		return 0;
	}
	/* expressions: at most 200 bytes, so that each run stays short */
	if (size - 2 > 200)
		return 0;
	o.dim = data[1] & 64 || o.m > 0 ? 3 : 2;
	text = malloc(size - 1);
	FUZZ_ASSERT(text != NULL, "out of memory");
	memcpy(text, data + 2, size - 2);
	text[size - 2] = '\0';
	if (fuzz_compile(&o, text) == 0) {
		for (int pass = 0; pass < 2; pass++) {
			run.w.len = 0;
			run.w.bad = 0;
			run.w.col = 0;
			if (approx_expr(&run, &o, &err) != 0) {
				FUZZ_ASSERT(err.msg[0] != '\0' &&
				    strchr(err.msg, '\n') == NULL,
				    "a failure without a one-line message");
				run.w.len = 0;
			} else if (run.w.bad)
				run.w.len = 0;
			fuzz_check_output(run.w.buf, run.w.len);
		}
	}
	for (int k = 0; k < 3; k++)
		loft_expr_free(o.e[k]);
	loft_writer_free(&run.w);
	free(text);
	return 0;
}
