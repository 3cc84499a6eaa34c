// Fuzz target: RawlogReader (plain and gzip rawlogs) and the pipeline's
// step assembly behind it (featloc-run's reading path). Any input must end
// in entries or an InputError, never a crash, hang or leak.
#include <cstdint>

#include "FuzzInput.h"
#include "featloc/core/InputError.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/registerClasses.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool registered = (featloc::registerClasses(), true);
	(void)registered;
	// The first byte picks plain or gzip, as a user's file name would.
	const bool gz = size > 0 && (data[0] & 1);
	featloc::fuzz::FuzzFile file(data, size, gz ? ".rawlog.gz" : ".rawlog");
	try
	{
		featloc::RawlogReader reader(file.path);
		featloc::RawlogEntry entry;
		for (int i = 0; i < 10000 && reader.next(entry); i++)
		{
		}
	}
	catch (const featloc::InputError&)
	{
	}
	return 0;
}
