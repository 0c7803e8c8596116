/*
 * patchloft.c: libFuzzer harness of patchloft's design handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bit 0     -c          bit 1  -S 1,0[,0]     bit 2  -E 0,1[,0]
 *   bit 3     the slopes have 3 numbers (else 2)
 */
#include "../../cmd/patchloft.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o;
	struct loft_run run = { .prog = "patchloft", .msg = fuzz_null(),
	    .ctx = &o };
	int dim;

	if (size < 2)
		return 0;
	memset(&o, 0, sizeof o);
	dim = data[0] & 8 ? 3 : 2;
	o.skin.closed = data[0] & 1;
	if (!o.skin.closed) {
		o.skin.have_start = (data[0] & 2) != 0;
		o.skin.have_end = (data[0] & 4) != 0;
	}
	o.skin.start[0] = 1;
	o.skin.end[1] = 1;
	o.start_dim = o.end_dim = dim;
	run.w.digits = data[1] % 18;
	fuzz_design(&run, skin_sections, data + 2, size - 2);
	return 0;
}
