// Fuzz target: CarmenLogReader (Radish/CARMEN FLASER logs).
#include <cstdint>

#include "FuzzInput.h"
#include "featloc/core/InputError.h"
#include "featloc/io/CarmenLogReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::FuzzFile file(data, size, ".log");
	try
	{
		featloc::CarmenLogReader::read(file.path, featloc::CarmenLogReader::Options());
	}
	catch (const featloc::InputError&)
	{
	}
	return 0;
}
