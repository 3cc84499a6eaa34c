// Fuzz target: featloc-sim's world files, ini and YAML (the first byte
// picks), read as featloc-sim reads them, and the wall-map files of the
// stereo landmarks (WallMapFile).
#include <cstdint>
#include <string>

#include "FuzzInput.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/io/WallMapFile.h"
#include "featloc/sim/SimConfiguration.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	if (size == 0) return 0;
	const bool yaml = data[0] & 1;
	const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
	try
	{
		featloc::TrackedConfig cfg;
		if (yaml)
			cfg.loadYaml(text, "fuzz.yaml", "/nonexistent");
		else
			cfg.loadText(text, "fuzz.ini", "/nonexistent");
		featloc::SimConfiguration::load(cfg);
	}
	catch (const featloc::ConfigError&)
	{
	}
	catch (const featloc::InputError&)
	{
	}
	featloc::fuzz::FuzzFile file(data + 1, size - 1, yaml ? ".yaml" : ".ini");
	try
	{
		featloc::WallMapFile::load(file.path);
	}
	catch (const featloc::ConfigError&)
	{
	}
	catch (const featloc::InputError&)
	{
	}
	return 0;
}
