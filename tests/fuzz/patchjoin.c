/*
 * patchjoin.c: libFuzzer harness of patchjoin's design handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bits 0-2  -P 1..8     bits 3-5  -S 1..8     bit 6  -v
 */
#include "../../cmd/patchjoin.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { .have_p = 1, .have_s = 1 };
	struct loft_run run = { .prog = "patchjoin", .msg = fuzz_null(),
	    .ctx = &o };

	if (size < 2)
		return 0;
	o.principal = 1 + (data[0] & 7);
	o.subsidiary = 1 + ((data[0] >> 3) & 7);
	o.verbose = (data[0] & 64) != 0;
	run.w.digits = data[1] % 18;
	fuzz_design(&run, join_design, data + 2, size - 2);
	return 0;
}
