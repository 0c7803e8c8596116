/*
 * patchcut.c: libFuzzer harness of patchcut's design handler.  Byte 0
 * chooses the options, byte 1 the -P digits; the rest is the stream.
 *   bits 0-1  the plane: x = 0.5, y = 0.5, z = 0.5, x + y + z = 1
 *   bit 2     -c          bit 3  -t 0.01 (else relative)
 *   bit 4     a second plane, x = 2
 */
#include "../../cmd/patchcut.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const double n[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
	    { 1, 1, 1 } };
	static const double x2[3] = { 1, 0, 0 };
	struct opts o = { 0 };
	struct loft_run run = { .prog = "patchcut", .msg = fuzz_null(),
	    .ctx = &o };
	int k;

	if (size < 2)
		return 0;
	k = data[0] & 3;
	add_plane(&o, n[k], k == 3 ? 1 : 0.5, k == 3 ? -1 : k);
	if (data[0] & 16)
		add_plane(&o, x2, 2, 0);
	o.cubic = (data[0] & 4) != 0;
	o.tol = data[0] & 8 ? 0.01 : 0;
	run.w.digits = data[1] % 18;
	fuzz_design(&run, cut_design, data + 2, size - 2);
	free(o.pl);
	return 0;
}
