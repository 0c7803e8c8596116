/*
 * patchsplit.c: libFuzzer harness of patchsplit's design handler.  Byte
 * 0 chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bit 0     -u (0) or -v (1)     bits 1-3  t, from the table below
 *   bit 4     -i, the id 1 + bits 5-7
 */
#include "../../cmd/patchsplit.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const double ts[8] = { 0.5, 0.1, 0.25, 1.0 / 3, 0.9, 1e-9,
	    0.999999999, 0.75 };
	struct opts o = { 0 };
	struct loft_run run = { .prog = "patchsplit", .msg = fuzz_null(),
	    .ctx = &o };

	if (size < 2)
		return 0;
	o.dir = data[0] & 1;
	o.t = ts[(data[0] >> 1) & 7];
	o.have_id = (data[0] & 16) != 0;
	o.id = 1 + ((data[0] >> 5) & 7);
	run.w.digits = data[1] % 18;
	fuzz_design(&run, split_design, data + 2, size - 2);
	return 0;
}
