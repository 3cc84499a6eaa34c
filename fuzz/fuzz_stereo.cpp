// Fuzz target: stereo calibration files and Moon et al.'s segment stage on
// arbitrary image pairs. Its body, featloc::fuzz::stereo (FuzzBodies.h),
// also runs the regression inputs in the normal test suite.
#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::stereo(data, size);
	return 0;
}
