/*
 * measure.c: libFuzzer harness of measure's record handler.  Byte 0
 * chooses the fields, byte 1 the -p digits; the rest is the stream.
 *   byte 0 % 3: 0 the defaults, 1 fields of any curve, 2 every field
 *   of a plane curve
 */
#include "../../cmd/measure.c"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const char *const fields[] = {
		NULL, "length,minradius,minradius_u,extrema,energy,jump,xmax,cx",
		"length,area,cx,cy,xmin,ymin,xmax,ymax,minradius,minradius_u,"
		"inflexions,extrema,energy,jump"
	};
	struct opts o = { { 0 }, 0 };
	struct loft_run run = { .prog = "measure", .msg = fuzz_null(),
	    .handle = measure_record, .ctx = &o };
	struct loft_error err;

	if (size < 2)
		return 0;
	if (fields[data[0] % 3] != NULL &&
	    loft_opt_fields(fields[data[0] % 3], field_names, o.field,
	    MAXFIELDS, &o.nfield, &err) != 0)
		abort();
	run.w.digits = data[1] % 18;
	fuzz_records(&run, data + 2, size - 2);
	return 0;
}
