/*
 * hydro.c: libFuzzer harness of hydro's design handler.  Byte 0 chooses
 * the options, byte 1 the -p digits; the rest is the stream.
 *   bit 0  -w               bit 1  waterlines -0.2:0:0.1 (else 0)
 *   bit 2  -s 3             bit 3  -f volume,cb,wetted -r 1.025
 */
#include "../../cmd/hydro.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct opts o = { 0 };
	struct loft_run run = { .prog = "hydro", .msg = fuzz_null(),
	    .ctx = &o };
	struct loft_error err;

	if (size < 2)
		return 0;
	o.whole = data[0] & 1;
	loft_opt_range(usage_text, 'z', data[0] & 2 ? "-0.2:0:0.1" : "0",
	    &o.z, &o.nz, &o.zcap);
	o.stations = data[0] & 4 ? 3 : 0;
	if (data[0] & 8) {
		o.rho = 1.025;
		if (loft_opt_fields("volume,cb,wetted,displacement",
		    field_names, o.field, MAXFIELDS, &o.nfield, &err) != 0)
			abort();
	}
	run.w.digits = data[1] % 18;
	fuzz_design(&run, hydro_design, data + 2, size - 2);
	free(o.z);
	return 0;
}
