/*
 * patchnew.c: libFuzzer harness of patchnew -b, its design handler (the
 * four boundary curves).  Byte 0 is the id less 1, byte 1 the -p
 * digits; the rest is the stream.
 */
#include "../../cmd/patchnew.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { .boundary = 1 };
	struct loft_run run = { .prog = "patchnew", .msg = fuzz_null(),
	    .ctx = &o };

	if (size < 2)
		return 0;
	o.id = 1 + data[0];
	run.w.digits = data[1] % 18;
	fuzz_design(&run, from_curves, data + 2, size - 2);
	return 0;
}
