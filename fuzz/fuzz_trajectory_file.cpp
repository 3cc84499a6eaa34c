// Fuzz target: trajectory, relations, TUM and matches.txt readers.
// Its body, featloc::fuzz::trajectoryFile (FuzzBodies.h), also runs the
// regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::trajectoryFile(data, size);
	return 0;
}
