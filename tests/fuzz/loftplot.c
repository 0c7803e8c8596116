/*
 * loftplot.c: libFuzzer harness of loftplot's record handler and its writer of
 * the picture.  Byte 0 chooses the options, byte 1 the steps; the rest
 * is the stream.  The picture of what was kept must be one SVG document
 * with no NaN or infinity in it.
 *   byte 0: bit 0  -b   bit 1  -c   bit 2  -m   bit 3  -t
 *           bits 4-5  -v xy, yz, xz, iso   bit 6  -l id   bit 7  -C 1
 *   byte 1: bits 0-2  -n 1..8   bits 3-5  -g 1..8   bit 6  -n given (else
 *           a surface's lines are as fine as they bend)
 */
#include "../../cmd/loftplot.c"
#include <strings.h>

#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The document: a whole SVG, its numbers finite (labels aside). */
static void
fuzz_check_svg(const char *buf, size_t len)
{
	static const char head[] = "<?xml version=\"1.0\"";
	static const char tail[] = "</svg>\n";
	const char *line = buf, *end = buf + len;

	FUZZ_ASSERT(len > sizeof head + sizeof tail &&
	    memcmp(buf, head, sizeof head - 1) == 0 &&
	    memcmp(end - (sizeof tail - 1), tail, sizeof tail - 1) == 0,
	    "not a whole SVG document");
	FUZZ_ASSERT(memchr(buf, '\0', len) == NULL, "NUL in the picture");
	while (line < end) {
		const char *nl = memchr(line, '\n', (size_t)(end - line));
		size_t n = (size_t)(nl - line);

		FUZZ_ASSERT(nl != NULL, "picture not ended by a newline");
		if (strncmp(line, "<text", 5) != 0)
			for (size_t i = 0; i + 3 <= n; i++)
				FUZZ_ASSERT(strncasecmp(line + i, "nan", 3) != 0 &&
				    strncasecmp(line + i, "inf", 3) != 0,
				    "NaN or infinity in the picture");
		line = nl + 1;
	}
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct pic pc = { 0 };
	struct loft_run run = { .prog = "loftplot", .msg = fuzz_null(),
	    .handle = keep_record, .ctx = &pc };
	struct loft_cad_doc d = { 0 };
	struct loft_error err;

	if (size < 2)
		return 0;
	pc.control = data[0] & 1;
	pc.comb = (data[0] & 2) != 0;
	pc.marks = (data[0] & 4) != 0;
	pc.handles = (data[0] & 8) != 0;
	pc.view = (enum view)((data[0] >> 4) & 3);
	pc.label_key = data[0] & 64 ? "id" : NULL;
	if (data[0] & 128) {
		pc.comb_scale = 1;
		pc.comb = 1;
	}
	pc.steps = 1 + (data[1] & 7);
	pc.steps_set = (data[1] & 64) != 0;
	pc.grid = 1 + ((data[1] >> 3) & 7);
	box_empty(&pc.box);
	box_empty(&pc.kbox);
	fuzz_records(&run, data + 2, size - 2);
	if (pc.nst > 0 && write_svg(&d, &pc, &err) == 0)
		fuzz_check_svg(d.out.buf, d.out.len);
	else if (pc.nst > 0)
		FUZZ_ASSERT(err.msg[0] != '\0', "a failure without a message");
	loft_cad_free(&d);
	free_pic(&pc);
	return 0;
}
