/*
 * offset.c: libFuzzer harness of offset's record handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bits 0-1  -j round, miter, bevel (3: round)
 *   bits 2-4  |d| = 0.01 0.1 0.5 1 2 5 15 100
 *   bit 5     d negative      bit 6  a second distance, -2 d
 *   bit 7     -t 1e-6
 */
#include "../../cmd/offset.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const double mag[8] = { 0.01, 0.1, 0.5, 1, 2, 5, 15, 100 };
	static struct opts o;
	struct loft_run run = { .prog = "offset", .msg = fuzz_null(),
	    .handle = offset_record, .ctx = &o };

	if (size < 2)
		return 0;
	o.join = (data[0] & 3) % 3;
	o.dist[0] = mag[(data[0] >> 2) & 7] * (data[0] & 32 ? -1 : 1);
	o.dist[1] = -2 * o.dist[0];
	o.ndist = data[0] & 64 ? 2 : 1;
	o.tol = data[0] & 128 ? 1e-6 : 0;
	run.w.digits = data[1] % 18;
	fuzz_records(&run, data + 2, size - 2);
	loft_offset_free(&o.off);
	return 0;
}
