#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "featloc/core/WholeFile.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::TempDir;

namespace
{
std::string read(const std::string& file)
{
	std::ifstream in(file);
	std::stringstream ss;
	ss << in.rdbuf();
	return ss.str();
}
}  // namespace

TEST(WholeFile, AFileAppearsWholeOrNotAtAll)
{
	TempDir dir;
	const std::string file = dir.file("summary.json");
	std::ofstream(file) << "old";
	// The temporary keeps the extension (cv::imwrite picks the format by it)
	// and is hidden beside the file.
	EXPECT_EQ(partialFileName(dir.file("trajectory.png")), dir.file(".trajectory.partial.png"));
	// A writer that fails half-way: the earlier file stays, no temporary.
	EXPECT_THROW(writeWholeFile(file,
					 [](const std::string& tmp) {
						 std::ofstream(tmp) << "half";
						 throw std::runtime_error("disk full");
					 }),
		std::runtime_error);
	EXPECT_EQ(read(file), "old");
	EXPECT_FALSE(std::filesystem::exists(partialFileName(file)));
	// Until the writer returns, the file is the earlier one.
	writeWholeFile(file, [&](const std::string& tmp) {
		std::ofstream(tmp) << "new";
		EXPECT_EQ(read(file), "old");
	});
	EXPECT_EQ(read(file), "new");
	EXPECT_FALSE(std::filesystem::exists(partialFileName(file)));
}
