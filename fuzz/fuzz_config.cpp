// Fuzz target: the configuration layer. The input is ini text, then, after
// a NUL byte, one "--set" value per line; the run configuration is read
// from it as featloc-run reads it (every section, every matcher). Any input
// must end in a configuration or a ConfigError.
#include <cstdint>
#include <sstream>
#include <string>

#include "featloc/app/RunConfiguration.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/registerClasses.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool registered = (featloc::registerClasses(), true);
	(void)registered;
	const std::string all(reinterpret_cast<const char*>(data), size);
	const auto nul = all.find('\0');
	try
	{
		featloc::TrackedConfig cfg;
		cfg.loadText(all.substr(0, nul), "fuzz.ini", "/nonexistent");
		if (nul != std::string::npos)
		{
			std::istringstream sets(all.substr(nul + 1));
			for (std::string line; std::getline(sets, line);) cfg.applyOverride(line);
		}
		featloc::RunConfiguration::load(cfg);
		cfg.requireAllKeysRead();
	}
	catch (const featloc::ConfigError&)
	{
	}
	catch (const featloc::InputError&)
	{
		// a file the configuration names (a map, a ground truth) is missing
	}
	return 0;
}
