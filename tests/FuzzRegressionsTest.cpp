// Every input a fuzz target of fuzz/ found a crash with (fuzz/regressions/
// TARGET/), run again in the normal build through the target's own body
// (fuzz/FuzzBodies.h): only featloc's documented errors (ConfigError,
// InputError) may end a read, so anything else thrown fails the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>

#include "FuzzBodies.h"

namespace fs = std::filesystem;

namespace
{
const fs::path kRegressions = fs::path(FEATLOC_SOURCE_DIR) / "fuzz" / "regressions";

// Folder under fuzz/regressions -> the body of its fuzz target.
const std::map<std::string, std::function<void(const uint8_t*, size_t)>> kBodies = {
	{"rawlog_reader", featloc::fuzz::rawlogReader},
	{"carmen_reader", featloc::fuzz::carmenReader},
	{"config", featloc::fuzz::configText},
	{"world_file", featloc::fuzz::worldFile},
	{"trajectory_file", featloc::fuzz::trajectoryFile},
	{"stereo", featloc::fuzz::stereo},
};
}  // namespace

TEST(FuzzRegressions, EveryFoundInputEndsInADocumentedErrorOrAResult)
{
	size_t n = 0;
	for (const auto& dir : fs::directory_iterator(kRegressions))
	{
		const auto body = kBodies.find(dir.path().filename().string());
		ASSERT_NE(body, kBodies.end()) << dir.path() << " names no fuzz target of FuzzBodies.h";
		for (const auto& e : fs::directory_iterator(dir.path()))
		{
			std::ifstream in(e.path(), std::ios::binary);
			const std::string data((std::istreambuf_iterator<char>(in)), {});
			try
			{
				body->second(reinterpret_cast<const uint8_t*>(data.data()), data.size());
			}
			catch (const std::exception& ex)
			{
				ADD_FAILURE() << e.path() << ": undocumented exception: " << ex.what();
			}
			n++;
		}
	}
	EXPECT_GE(n, 4u) << "the four inputs found on 2026-11-24";
}
