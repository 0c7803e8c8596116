/*
 * unroll.c: libFuzzer harness of unroll's design handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bits 0-1  -n 1..4     bit 2  -a   bit 3  -e   bit 4  -m
 *   bit 5     -x 0.5      bit 6  -t 0.01 (else relative)
 */
#include "../../cmd/unroll.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static struct opts o;
	struct loft_run run = { .prog = "unroll", .msg = fuzz_null(),
	    .ctx = &o };

	if (size < 2)
		return 0;
	memset(&o, 0, sizeof o);
	o.u.steps = 1 + (data[0] & 3);
	o.u.arap = (data[0] & 4) != 0;
	o.edges = (data[0] & 8) != 0;
	o.map = (data[0] & 16) != 0;
	if (data[0] & 32) {
		o.cut[0].axis = 0;
		o.cut[0].at = 0.5;
		o.ncut = 1;
	}
	o.u.tol = data[0] & 64 ? 0.01 : 0;
	run.w.digits = data[1] % 18;
	fuzz_design(&run, unroll_design, data + 2, size - 2);
	return 0;
}
