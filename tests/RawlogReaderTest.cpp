#include <gtest/gtest.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>

#include "featloc/core/AllocationCeiling.h"
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

TEST(RawlogReader, AnAbsurdBeamCountIsCorruptBeforeItIsAllocated)
{
	if (!AllocationCeiling::available()) GTEST_SKIP() << "no allocation ceiling under ASan";
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 6;
	log.compress = false;
	log.observationsOnly = true;
	// A beam count no other field of the file holds, to find it.
	constexpr uint32_t kBeams = 4321;
	log.editScan = [&](size_t, mrpt::obs::CObservation2DRangeScan& s) {
		s.resizeScanAndAssign(kBeams, 1.0f, true);
	};
	log.write(dir.file("ok.rawlog"));
	std::ifstream in(dir.file("ok.rawlog"), std::ios::binary);
	std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	// The third scan's beam count (little-endian uint32 after its class
	// name) becomes 2^29: 4.5 GB of ranges, intensities and validity flags
	// that MRPT would allocate and zero before finding the file too short.
	size_t at = 0;
	for (int i = 0; i < 3; ++i) at = bytes.find("CObservation2DRangeScan", at + 1);
	ASSERT_NE(at, std::string::npos);
	const std::string count(reinterpret_cast<const char*>(&kBeams), 4);
	at = bytes.find(count, at);
	ASSERT_NE(at, std::string::npos);
	const uint32_t absurd = uint32_t(1) << 29;
	bytes.replace(at, 4, std::string(reinterpret_cast<const char*>(&absurd), 4));
	std::ofstream(dir.file("absurd.rawlog"), std::ios::binary) << bytes;

	rusage before{};
	::getrusage(RUSAGE_SELF, &before);
	size_t read = 0;
	const std::string msg = errorMessageOf<InputError>([&] {
		RawlogReader reader(dir.file("absurd.rawlog"));
		RawlogEntry e;
		while (reader.next(e)) read++;
	});
	rusage after{};
	::getrusage(RUSAGE_SELF, &after);
	EXPECT_NE(msg.find("absurd.rawlog': entry #" + std::to_string(read)), std::string::npos) << msg;
	EXPECT_NE(msg.find("asks for more than 1024 MiB"), std::string::npos) << msg;
	EXPECT_GE(read, 2u);
	std::cout << msg << "\n";
	// The peak resident memory did not grow by the gigabytes asked for.
	EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 256L * 1024) << "kB";
	// And the ceiling is gone afterwards: a large allocation works again.
	const std::unique_ptr<char[]> big(new char[size_t(1.5 * RawlogReader::kMaxEntryBytes)]);
	EXPECT_TRUE(big);
}
