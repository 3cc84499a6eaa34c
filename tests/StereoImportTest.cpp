// featloc-stereo-import on EuRoC's own folder layout (mav0/cam0|cam1 with
// data.csv and sensor.yaml), built from the real EuRoC pairs in
// ../shared/data/stereo, with a TUM ground truth beside it.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "featloc/registerClasses.h"
#include "support/CommandRunner.h"
#include "support/DataRows.h"
#include "support/TempDir.h"

using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = FEATLOC_SOURCE_DIR;
const std::string kImport = FEATLOC_STEREO_IMPORT_EXE;
const std::string kData = kSource + "/../shared/data/stereo/euroc-v1-pairs/";

// EuRoC V1_01 camera times (ns), 20 Hz.
const std::vector<std::int64_t> kTimesNs = {
	1403715273262142976, 1403715273312143104, 1403715273362142976, 1403715273412143104};

/** A mav0 folder as EuRoC ships it, holding the four real pairs. */
void makeEurocFolder(const fs::path& root)
{
	for (const std::string cam : {"cam0", "cam1"})
	{
		fs::create_directories(root / "mav0" / cam / "data");
		std::ofstream csv(root / "mav0" / cam / "data.csv");
		csv << "#timestamp [ns],filename\n";
		for (size_t i = 0; i < kTimesNs.size(); i++)
		{
			const std::string name = std::to_string(kTimesNs[i]) + ".png";
			csv << kTimesNs[i] << "," << name << "\n";
			fs::copy_file(
				kData + (cam == "cam0" ? "left_img_" : "right_img_") + std::to_string(i) + ".png",
				root / "mav0" / cam / "data" / name);
		}
		fs::copy_file(
			kData + (cam == "cam0" ? "sensorLeft.yaml" : "sensorRight.yaml"),
			root / "mav0" / cam / "sensor.yaml");
	}
}

std::vector<mrpt::obs::CObservationStereoImages::Ptr> readStereo(const std::string& rawlog)
{
	featloc::registerClasses();
	std::vector<mrpt::obs::CObservationStereoImages::Ptr> out;
	mrpt::io::CFileGZInputStream f(rawlog);
	auto arch = mrpt::serialization::archiveFrom(f);
	try
	{
		for (;;)
		{
			auto obj = arch.ReadObject();
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(obj))
				out.push_back(o);
		}
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
	}
	return out;
}

}  // namespace

TEST(StereoImport, EurocMav0LayoutTakesTimesFromDataCsvAndPicksTheGroundTruthRows)
{
	if (!fs::exists(kData)) GTEST_SKIP() << "no " << kData;
	TempDir d;
	makeEurocFolder(d.path() / "V1_01");
	// A TUM ground truth at 200 Hz (Vicon-like): only the rows at the
	// frames' times go beside the rawlog.
	{
		std::ofstream gt(d.file("gt.tum"));
		gt << "# timestamp tx ty tz qx qy qz qw\n";
		for (std::int64_t t = kTimesNs.front() - 20'000'000; t <= kTimesNs.back() + 20'000'000; t += 5'000'000)
			gt << std::fixed << static_cast<double>(t) * 1e-9 << " 0.878 2.142 0.947 -0.03 0.81 -0.06 0.58\n";
	}
	const std::string out = d.file("out/v1.rawlog");
	const auto r = runCommand(
		shellQuote(kImport) + " " + shellQuote(d.file("V1_01")) + " --rectify --ground-truth " +
		shellQuote(d.file("gt.tum")) + " --out " + shellQuote(out));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("EuRoC mav0/cam0|cam1"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("(4 ground-truth rows)"), std::string::npos) << r.output;

	const auto obs = readStereo(out);
	ASSERT_EQ(obs.size(), kTimesNs.size());
	for (size_t i = 0; i < obs.size(); i++)
	{
		// mrpt::Clock keeps 100 ns ticks.
		EXPECT_NEAR(
			mrpt::Clock::toDouble(obs[i]->timestamp), static_cast<double>(kTimesNs[i]) * 1e-9, 1e-6)
			<< "pair " << i;
		EXPECT_EQ(obs[i]->leftCamera.ncols, 752u);
		EXPECT_TRUE(fs::exists(d.file("out/v1_Images/" + obs[i]->imageLeft.getExternalStorageFile())));
	}
	// The body-to-camera extrinsics of sensor.yaml (T_BS) are the camera
	// pose on the robot.
	EXPECT_NEAR(obs[0]->cameraPose.x(), -0.0216401454975, 1e-9);
	EXPECT_NEAR(obs[0]->cameraPose.y(), -0.064676986768, 1e-9);

	const auto rows = featloc::test::dataRows(d.file("out/v1.gt.txt"));
	ASSERT_EQ(rows.size(), 4u);
	for (size_t i = 0; i < rows.size(); i++)
		EXPECT_NEAR(std::stod(rows[i]), static_cast<double>(kTimesNs[i]) * 1e-9, 0.003) << rows[i];

	// featloc-run reads the rawlog and its ground truth.
	const auto run = runCommand(
		shellQuote(FEATLOC_RUN_EXE) + " " + shellQuote(kSource + "/config.ini") + " -q --set Input:rawlog=" +
		shellQuote(out) + " --set Evaluation:ground_truth= --set Pipeline:estimator=odometry --out " +
		shellQuote(d.file("results")));
	EXPECT_EQ(run.exitCode, 0) << run.output;
}

TEST(StereoImport, BadGroundTruthRowIsAnErrorNamingTheLineAndNothingIsWritten)
{
	if (!fs::exists(kData)) GTEST_SKIP() << "no " << kData;
	TempDir d;
	makeEurocFolder(d.path() / "V1_01");
	{
		std::ofstream gt(d.file("gt.tum"));
		gt << "# timestamp tx ty tz qx qy qz qw\n"
		   << "1403715273.262143 0.878 2.142 0.947 -0.03 0.81 -0.06 0.58\n"
		   << "1403715273.312143 0.878 2.142 0.947\n";
	}
	const auto r = runCommand(
		shellQuote(kImport) + " " + shellQuote(d.file("V1_01")) + " --ground-truth " +
		shellQuote(d.file("gt.tum")) + " --out " + shellQuote(d.file("out/v1.rawlog")));
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("gt.tum:3: expected a TUM row"), std::string::npos) << r.output;
	EXPECT_FALSE(fs::exists(d.file("out/v1.rawlog")));

	// A ground truth of another recording (no row near any frame) is an
	// error too, not an empty file.
	{
		std::ofstream gt(d.file("other.tum"));
		gt << "1500000000.0 0 0 0 0 0 0 1\n";
	}
	const auto r2 = runCommand(
		shellQuote(kImport) + " " + shellQuote(d.file("V1_01")) + " --ground-truth " +
		shellQuote(d.file("other.tum")) + " --out " + shellQuote(d.file("out/v1.rawlog")));
	EXPECT_NE(r2.exitCode, 0);
	EXPECT_NE(r2.output.find("has no row within 5 ms of any stereo frame"), std::string::npos) << r2.output;
}

TEST(StereoImport, EurocCsvNamingAFileThatIsNotThereIsAnError)
{
	if (!fs::exists(kData)) GTEST_SKIP() << "no " << kData;
	TempDir d;
	makeEurocFolder(d.path() / "V1_01");
	{
		std::ofstream csv(d.path() / "V1_01/mav0/cam0/data.csv", std::ios::app);
		csv << "1403715273462142976,1403715273462142976.png\n";
	}
	{
		std::ofstream csv(d.path() / "V1_01/mav0/cam1/data.csv", std::ios::app);
		csv << "1403715273462142976,1403715273462142976.png\n";
	}
	const auto r = runCommand(
		shellQuote(kImport) + " " + shellQuote(d.file("V1_01")) + " --out " + shellQuote(d.file("v1.rawlog")));
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("1403715273462142976.png"), std::string::npos) << r.output;
}
