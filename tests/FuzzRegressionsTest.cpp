// Every input a fuzz target of fuzz/ found a crash with (fuzz/regressions/
// TARGET/), read again by the same readers in the normal build: each must
// end in featloc's documented errors (ConfigError, InputError) or a result.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/io/WallMapFile.h"
#include "featloc/sim/SimConfiguration.h"
#include "support/TempDir.h"

namespace fs = std::filesystem;

namespace
{
const fs::path kRegressions = fs::path(FEATLOC_SOURCE_DIR) / "fuzz" / "regressions";

std::string contents(const fs::path& p)
{
	std::ifstream in(p, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

template <typename F>
void expectOnlyDocumentedErrors(const std::string& what, F&& f)
{
	try
	{
		f();
	}
	catch (const featloc::ConfigError&)
	{
	}
	catch (const featloc::InputError&)
	{
	}
	catch (const std::exception& e)
	{
		ADD_FAILURE() << what << ": undocumented exception: " << e.what();
	}
}
}  // namespace

// fuzz/fuzz_world_file: byte 0 picks ini (even) or YAML (odd), the rest is
// the world; read as featloc-sim does, and as a wall map.
TEST(FuzzRegressions, WorldFiles)
{
	featloc::test::TempDir tmp;
	size_t n = 0;
	for (const auto& e : fs::directory_iterator(kRegressions / "world_file"))
	{
		const std::string data = contents(e.path());
		if (data.empty()) continue;
		const bool yaml = data[0] & 1;
		const std::string text = data.substr(1);
		expectOnlyDocumentedErrors(e.path().string(), [&] {
			featloc::TrackedConfig cfg;
			if (yaml)
				cfg.loadYaml(text, "fuzz.yaml", tmp.path().string());
			else
				cfg.loadText(text, "fuzz.ini", tmp.path().string());
			featloc::SimConfiguration::load(cfg);
		});
		const std::string file = tmp.file(yaml ? "w.yaml" : "w.ini");
		std::ofstream(file, std::ios::binary) << text;
		expectOnlyDocumentedErrors(e.path().string(), [&] { featloc::WallMapFile::load(file); });
		n++;
	}
	EXPECT_GE(n, 2u);
}

// fuzz/fuzz_config: ini text, then after a NUL one --set value per line.
TEST(FuzzRegressions, ConfigText)
{
	size_t n = 0;
	for (const auto& e : fs::directory_iterator(kRegressions / "config"))
	{
		const std::string data = contents(e.path());
		expectOnlyDocumentedErrors(e.path().string(), [&] {
			featloc::TrackedConfig cfg;
			cfg.loadText(data.substr(0, data.find('\0')), "fuzz.ini", "/nonexistent");
		});
		n++;
	}
	EXPECT_GE(n, 1u);
}
