// Fuzz target: world files (ini, YAML) and wall maps.
// Its body, featloc::fuzz::worldFile (FuzzBodies.h), also runs the
// regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::worldFile(data, size);
	return 0;
}
