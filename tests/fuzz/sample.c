/*
 * sample.c: libFuzzer harness of sample's record handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bits 0-2  -n 1..8      bit 3  -u      bit 4  -d      bit 5  -k
 *   bits 6-7  0: -n, 1: -s 0.5, 2: -t 0.01, 3: -s 3
 * -s and -t make at most 100000 points a record here, so that a long
 * curve is refused quickly instead of written at length.
 */
#include "../../cmd/sample.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "sample", .msg = fuzz_null(),
	    .handle = sample_record, .ctx = &o };

	if (size < 2)
		return 0;
	o.per = 1 + (data[0] & 7);
	o.param = (data[0] & 8) != 0;
	o.tangent = (data[0] & 16) != 0;
	o.curvature = (data[0] & 32) != 0;
	o.spacing = (data[0] >> 6) == 1 ? 0.5 : (data[0] >> 6) == 3 ? 3 : 0;
	o.tol = (data[0] >> 6) == 2 ? 0.01 : 0;
	o.most = 100000;
	run.w.digits = data[1] % 18;
	fuzz_records(&run, data + 2, size - 2);
	opts_free(&o);
	return 0;
}
