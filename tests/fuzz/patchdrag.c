/*
 * patchdrag.c: libFuzzer harness of patchdrag's design handler.  Bytes
 * 0 and 1 choose the options; the rest is the stream.
 *   byte 0: bits 0-1  -u 0.5, 0.1, 0.95, 1.5   bits 2-3  -v likewise
 *           bit 4     -t (else -b)   bit 5  -w 0,0,1 (0,1 with bit 0
 *           of byte 1)   bit 6  -i 1 + bits 1-3 of byte 1   bit 7  -V
 *   byte 1: bit 0     2 coordinates (else 3)   bits 4-5  -e 0.25, 0,
 *           0.5, 0.1   bits 6-7  -p 0, 3, 9, 17
 */
#include "../../cmd/patchdrag.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const double us[4] = { 0.5, 0.1, 0.95, 1.5 };
	static const double edges[4] = { 0.25, 0, 0.5, 0.1 };
	static const int digits[4] = { 0, 3, 9, 17 };
	struct opts o = { .have_u = 1, .have_v = 1 };
	struct loft_run run = { .prog = "patchdrag", .msg = fuzz_null(),
	    .ctx = &o };
	int dim;

	if (size < 2)
		return 0;
	dim = data[1] & 1 ? 2 : 3;
	o.u = us[data[0] & 3];
	o.v = us[(data[0] >> 2) & 3];
	o.target = (data[0] & 16) != 0;
	o.nmove = dim;
	o.move[0] = 0.25;
	o.move[1] = -0.5;
	o.move[2] = 1;
	if (data[0] & 32) {
		o.nview = dim;
		o.view[dim - 1] = 1;
	}
	o.have_id = (data[0] & 64) != 0;
	o.id = 1 + ((data[1] >> 1) & 7);
	o.verbose = (data[0] & 128) != 0;
	o.edge = edges[(data[1] >> 4) & 3];
	run.w.digits = digits[(data[1] >> 6) & 3];
	fuzz_design(&run, drag_design, data + 2, size - 2);
	return 0;
}
