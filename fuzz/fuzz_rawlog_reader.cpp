// Fuzz target: RawlogReader, plain and gzip.
// Its body, featloc::fuzz::rawlogReader (FuzzBodies.h), also runs the
// regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::rawlogReader(data, size);
	return 0;
}
