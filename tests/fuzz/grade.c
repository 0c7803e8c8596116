/*
 * grade.c: libFuzzer harness of grade's record handler.  Byte 0 chooses
 * the options, byte 1 the -p digits and more; the rest is the stream.
 *   bits 0-2  from = -0..-7     bits 3-5  to = 0..7
 *   bit 6     -o 0,0            bit 7     -l 0 -w 1e6
 * byte 1: digits = (bits 0-4) % 18; bit 5 -m; bit 6 -s (absolute sizes
 * from the record's size=, else -b 7); bit 7 -a y
 */
#include "../../cmd/grade.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { .sys = loft_size_systems, .axis = -1, .unit = 1 };
	struct loft_run run = { .prog = "grade", .msg = fuzz_null(),
	    .handle = grade_record, .ctx = &o };

	if (size < 2)
		return 0;
	o.lstep = o.sys->length;
	o.wstep = o.sys->width;
	o.from = -(double)(data[0] & 7);
	o.to = (data[0] >> 3) & 7;
	o.have_origin = (data[0] & 64) != 0;
	if (data[0] & 128) {
		o.lstep = 0;
		o.wstep = 1e6;
	}
	run.w.digits = (data[1] & 31) % 18;
	o.mirror = (data[1] & 32) != 0;
	if (data[1] & 64) {
		o.absolute = 1;
		o.from += 8;
		o.to += 8;
		o.have_base = 1;
		o.base = 7;
	}
	if (data[1] & 128)
		o.axis = 1;
	fuzz_records(&run, data + 2, size - 2);
	free(o.q);
	return 0;
}
