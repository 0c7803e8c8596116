/*
 * splinefit.c: libFuzzer harness of splinefit's record handler.  Byte 0
 * chooses the options, byte 1 the -p digits; the rest is the stream.
 *   bit 0  -o          bit 1  -m chord      bit 2  -m ferguson
 *   (bits 1 and 2 both: -m manning; neither: the fair default)
 *   bit 3  -k turn     bit 4  -i 3          bit 5  -v
 *   bit 6  -S 1,0[,0]  bit 7  -E 0,1[,1]    (with -o)
 * Byte 1's bit 6 (digits from the other bits, as before, otherwise):
 * -e 0.1 -i 3, the approximation (issue 14).
 */
#include "../../cmd/splinefit.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { .merge = -1 };
	struct loft_run run = { .prog = "splinefit", .msg = fuzz_null(),
	    .handle = fit_record, .ctx = &o };
	int bits;

	if (size < 2)
		return 0;
	bits = data[0];
	loft_fit_defaults(&o.fit);
	o.fit.closed = !(bits & 1);
	if ((bits & 6) == 6)
		o.fit.method = LOFT_MANNING;
	else if (bits & 2)
		o.fit.method = LOFT_CHORD;
	else if (bits & 4)
		o.fit.method = LOFT_FERGUSON;
	if (bits & 8)
		o.fit.sign = LOFT_SIGN_TURN;
	if (bits & 16)
		o.fit.maxiter = 3;
	o.verbose = (bits & 32) != 0;
	if ((bits & 64) && !o.fit.closed) {
		o.fit.have_start = 1;
		o.fit.start[0] = 1;
		o.start_dim = 2 + (data[1] >> 7);
	}
	if ((bits & 128) && !o.fit.closed) {
		o.fit.have_end = 1;
		o.fit.end[1] = 1;
		o.fit.end[2] = 1;
		o.end_dim = 2 + (data[1] >> 7);
	}
	run.w.digits = (data[1] & 0x7f) % 18;
	if (data[1] & 0x40) {
		o.approx = 0.1;
		o.rounds = 3;
	}
	fuzz_records(&run, data + 2, size - 2);
	free_scratch(&o);
	return 0;
}
