// Fuzz target: ini text and --set values through RunConfiguration.
// Its body, featloc::fuzz::configText (FuzzBodies.h), also runs the
// regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::configText(data, size);
	return 0;
}
