/*
 * fromcad.c: libFuzzer harness of the CAD readers.  Byte 0 chooses the
 * format (0 DXF, 1 SVG, 2 CSV, 3 by content) and, in bit 2, an arc
 * tolerance of 1e-3 instead of the relative one; the rest is the
 * document.  The records read must be whole and read back, each
 * complaint one line, and a second reading the same bytes.
 */
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void
complain(void *ctx, long line, const char *msg)
{
	(void)ctx;
	FUZZ_ASSERT(line >= 0, "complaint with a negative line");
	FUZZ_ASSERT(msg[0] != '\0' && strchr(msg, '\n') == NULL,
	    "complaint empty or of two lines");
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct loft_writer w[2] = { { 0 }, { 0 } };
	int format, rc[2];

	if (size < 1)
		return 0;
	format = data[0] & 3;
	if (format == 3)
		format = loft_cadin_sniff((const char *)data + 1, size - 1);
	if (format < 0)
		return 0;
	for (int pass = 0; pass < 2; pass++) {
		struct loft_cadin c = { data[0] & 4 ? 1e-3 : 0, &w[pass],
		    complain, NULL, 0, data[0] & 8, data[0] & 16, 0, NULL };

		rc[pass] = loft_cadin_read(format, (const char *)data + 1,
		    size - 1, &c);
		FUZZ_ASSERT((rc[pass] == 0) == (c.nbad == 0),
		    "a failed reading without a complaint, or the other way");
		FUZZ_ASSERT(!w[pass].bad, "writer left bad");
	}
	fuzz_check_output(w[0].buf, w[0].len);
	FUZZ_ASSERT(rc[0] == rc[1] && w[0].len == w[1].len &&
	    (w[0].len == 0 || memcmp(w[0].buf, w[1].buf, w[0].len) == 0),
	    "two readings differ");
	loft_writer_free(&w[0]);
	loft_writer_free(&w[1]);
	return 0;
}
