/*
 * grade.c: libFuzzer harness of grade's record handler.  Byte 0 chooses
 * the options, byte 1 the -p digits; the rest is the stream.
 *   bits 0-2  from = -0..-7     bits 3-5  to = 0..7
 *   bit 6     -o 0,0            bit 7     -l 0 -w 1e6
 */
#include "../../cmd/grade.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { .lstep = LENGTH_STEP, .wstep = WIDTH_STEP };
	struct loft_run run = { .prog = "grade", .msg = fuzz_null(),
	    .handle = grade_record, .ctx = &o };

	if (size < 2)
		return 0;
	o.from = -(long)(data[0] & 7);
	o.to = (data[0] >> 3) & 7;
	o.have_origin = (data[0] & 64) != 0;
	if (data[0] & 128) {
		o.lstep = 0;
		o.wstep = 1e6;
	}
	run.w.digits = data[1] % 18;
	fuzz_records(&run, data + 2, size - 2);
	return 0;
}
