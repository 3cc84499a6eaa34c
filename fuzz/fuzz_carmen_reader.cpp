// Fuzz target: the CARMEN log reader.
// Its body, featloc::fuzz::carmenReader (FuzzBodies.h), also runs the
// regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::carmenReader(data, size);
	return 0;
}
