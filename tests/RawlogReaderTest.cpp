#include <gtest/gtest.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>
#include <fstream>

#include "featloc/core/InputError.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/registerClasses.h"
#include "support/ErrorMessage.h"
#include "support/TempDir.h"
#include "support/TestRawlog.h"

using namespace featloc;
using featloc::test::errorMessageOf;
using featloc::test::TempDir;
using featloc::test::TestRawlog;

namespace
{
struct Counts
{
	size_t entries = 0, frames = 0, actions = 0, scans = 0, odometry = 0;
};

Counts readAll(const std::string& file)
{
	Counts c;
	RawlogReader reader(file);
	RawlogEntry e;
	while (reader.next(e))
	{
		EXPECT_EQ(e.index, c.entries);
		c.entries++;
		using namespace mrpt::obs;
		if (std::dynamic_pointer_cast<CSensoryFrame>(e.object)) c.frames++;
		if (std::dynamic_pointer_cast<CActionCollection>(e.object)) c.actions++;
		if (std::dynamic_pointer_cast<CObservation2DRangeScan>(e.object)) c.scans++;
		if (std::dynamic_pointer_cast<CObservationOdometry>(e.object))
			c.odometry++;
	}
	EXPECT_DOUBLE_EQ(reader.progress(), 1.0);
	return c;
}


/** Copies the first `bytes` bytes of a file. */
void truncateCopy(const std::string& from, const std::string& to, size_t bytes)
{
	std::ifstream in(from, std::ios::binary);
	std::string data(bytes, '\0');
	in.read(data.data(), static_cast<std::streamsize>(bytes));
	std::ofstream(to, std::ios::binary).write(data.data(), in.gcount());
}
}  // namespace

TEST(RawlogReader, ReadsFormat1CompressedAndPlain)
{
	registerClasses();
	TempDir dir;
	for (bool gz : {true, false})
	{
		TestRawlog log;
		log.scans = 6;
		log.compress = gz;
		log.write(dir.file("f1.rawlog"));
		const Counts c = readAll(dir.file("f1.rawlog"));
		EXPECT_EQ(c.frames, 6u);
		EXPECT_EQ(c.actions, 5u);
		EXPECT_EQ(c.entries, 11u);
	}
}

TEST(RawlogReader, ReadsFormat2)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 5;
	log.observationsOnly = true;
	log.odometryPerScan = 2;
	log.write(dir.file("f2.rawlog"));
	const Counts c = readAll(dir.file("f2.rawlog"));
	EXPECT_EQ(c.scans, 5u);
	EXPECT_GE(c.odometry, 10u);
	EXPECT_EQ(c.frames + c.actions, 0u);
}

TEST(RawlogReader, TruncatedFileIsAnErrorNamingTheEntry)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 20;
	log.compress = false;  // cut at a known byte of the uncompressed data
	log.write(dir.file("full.rawlog"));
	const auto size = std::filesystem::file_size(dir.file("full.rawlog"));
	truncateCopy(dir.file("full.rawlog"), dir.file("cut.rawlog"), size / 2);

	size_t readBeforeError = 0;
	const std::string msg = errorMessageOf<InputError>([&] {
		RawlogReader reader(dir.file("cut.rawlog"));
		RawlogEntry e;
		while (reader.next(e)) readBeforeError++;
	});
	ASSERT_FALSE(msg.empty()) << "a truncated rawlog must not end silently";
	EXPECT_NE(msg.find("cut.rawlog"), std::string::npos) << msg;
	EXPECT_NE(msg.find("entry #" + std::to_string(readBeforeError)),
		std::string::npos)
		<< msg;
	EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
	EXPECT_GT(readBeforeError, 5u);
}

TEST(RawlogReader, TruncatedGzipFileIsAnError)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 40;
	log.write(dir.file("full.rawlog"));
	const auto size = std::filesystem::file_size(dir.file("full.rawlog"));
	truncateCopy(dir.file("full.rawlog"), dir.file("cut.rawlog"), size * 2 / 3);
	const std::string msg = errorMessageOf<InputError>([&] { readAll(dir.file("cut.rawlog")); });
	EXPECT_NE(msg.find("entry #"), std::string::npos) << msg;
	EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
}

TEST(RawlogReader, GarbageIsCorruptNotEmpty)
{
	registerClasses();
	TempDir dir;
	std::ofstream(dir.file("text.rawlog")) << "this is not a rawlog\n";
	const std::string msg = errorMessageOf<InputError>([&] { readAll(dir.file("text.rawlog")); });
	EXPECT_NE(msg.find("entry #0"), std::string::npos) << msg;
	EXPECT_NE(msg.find("corrupt or not a rawlog"), std::string::npos) << msg;
}

TEST(RawlogReader, EmptyFileHasNoEntries)
{
	registerClasses();
	TempDir dir;
	std::ofstream(dir.file("empty.rawlog")).close();
	EXPECT_EQ(readAll(dir.file("empty.rawlog")).entries, 0u);
}

TEST(RawlogReader, MissingFileAndDirectoryAreErrors)
{
	registerClasses();
	TempDir dir;
	EXPECT_NE(errorMessageOf<InputError>([&] { RawlogReader r(dir.file("nope.rawlog")); })
				  .find("does not exist"),
		std::string::npos);
	EXPECT_NE(errorMessageOf<InputError>([&] { RawlogReader r(dir.path().string()); })
				  .find("is a directory"),
		std::string::npos);
}
