/*
 * offsets.c: libFuzzer harness of offsets.  Byte 0 chooses the mode,
 * byte 1 the -p digits; the rest is the stream.
 *   bit 0  -k: the record handler over each record (tables to
 *          stations); else the design handler with -x -1:1:0.5 -z 0,0.5
 */
#include "../../cmd/offsets.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "offsets", .msg = fuzz_null(),
	    .handle = stations, .ctx = &o };

	if (size < 2)
		return 0;
	run.w.digits = data[1] % 18;
	if (data[0] & 1) {
		fuzz_records(&run, data + 2, size - 2);
		return 0;
	}
	loft_opt_range(usage_text, 'x', "-1:1:0.5", &o.x, &o.nx, &o.xcap);
	loft_opt_range(usage_text, 'z', "0,0.5", &o.z, &o.nz, &o.zcap);
	fuzz_design(&run, tabulate, data + 2, size - 2);
	free(o.x);
	free(o.z);
	return 0;
}
