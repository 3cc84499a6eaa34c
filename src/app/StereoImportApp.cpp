#include "featloc/app/StereoImportApp.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/vision/CStereoRectifyMap.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "featloc/app/AppMain.h"
#include "featloc/app/UsageError.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/StereoCalibrationFile.h"
#include "featloc/io/TumPoseFile.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/StereoOutputWriter.h"

namespace featloc
{
namespace fs = std::filesystem;

namespace
{
struct ImagePair
{
	fs::path left, right;
	std::string key;  //!< what pairs them (file name or suffix)
	double time = -1;  //!< [s], < 0: not known yet
};

bool isImage(const fs::path& p)
{
	std::string e = p.extension().string();
	std::transform(e.begin(), e.end(), e.begin(), ::tolower);
	return e == ".png" || e == ".jpg" || e == ".jpeg" || e == ".pgm" || e == ".bmp" || e == ".tif";
}

std::vector<fs::path> imagesIn(const fs::path& dir)
{
	std::vector<fs::path> out;
	for (const auto& e : fs::directory_iterator(dir))
		if (e.is_regular_file() && isImage(e.path())) out.push_back(e.path());
	std::sort(out.begin(), out.end());
	return out;
}

/** EuRoC's data.csv: "#timestamp [ns],filename" -> file name -> ns. */
std::map<std::string, double> readTimesCsv(const fs::path& csv)
{
	std::ifstream f(csv);
	if (!f) throw InputError("cannot read '" + csv.string() + "'");
	std::map<std::string, double> out;
	std::string line;
	for (size_t n = 1; std::getline(f, line); n++)
	{
		if (line.empty() || line[0] == '#') continue;
		const auto comma = line.find(',');
		if (comma == std::string::npos)
			throw InputError(csv.string() + ":" + std::to_string(n) + ": expected 'timestamp_ns,filename'");
		std::string name = line.substr(comma + 1);
		name.erase(name.find_last_not_of(" \r\t") + 1);
		try
		{
			out[name] = std::stod(line.substr(0, comma)) * 1e-9;
		}
		catch (const std::exception&)
		{
			throw InputError(csv.string() + ":" + std::to_string(n) + ": bad timestamp");
		}
	}
	return out;
}

/** Digits in a name (the frame number or a timestamp), -1 if none. */
double numberIn(const std::string& s)
{
	std::string digits;
	for (char c : s)
		if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
	return digits.empty() ? -1 : std::stod(digits);
}

std::vector<ImagePair> findPairs(const fs::path& dir, std::string& layout)
{
	std::vector<ImagePair> pairs;
	const fs::path euroc = dir / "mav0";
	if (fs::exists(euroc / "cam0" / "data.csv"))
	{
		layout = "EuRoC mav0/cam0|cam1";
		const auto left = readTimesCsv(euroc / "cam0" / "data.csv");
		const auto right = readTimesCsv(euroc / "cam1" / "data.csv");
		for (const auto& [name, t] : left)
		{
			if (!right.count(name)) continue;
			const fs::path l = euroc / "cam0" / "data" / name, r = euroc / "cam1" / "data" / name;
			for (const auto& [csv, image] : {std::pair{"cam0", l}, std::pair{"cam1", r}})
				if (!fs::exists(image))
					throw InputError(
						(euroc / csv / "data.csv").string() + " names '" + name + "', which is not in " +
						(euroc / csv / "data").string());
			pairs.push_back({l, r, name, t});
		}
	}
	else if (fs::is_directory(dir / "left") && fs::is_directory(dir / "right"))
	{
		layout = "left/ + right/ folders";
		for (const auto& l : imagesIn(dir / "left"))
		{
			const fs::path r = dir / "right" / l.filename();
			if (fs::exists(r)) pairs.push_back({l, r, l.filename().string()});
		}
	}
	else
	{
		layout = "left* + right* files";
		for (const auto& l : imagesIn(dir))
		{
			const std::string name = l.filename().string();
			if (name.rfind("left", 0) != 0) continue;
			const fs::path r = dir / ("right" + name.substr(4));
			if (fs::exists(r)) pairs.push_back({l, r, name});
		}
	}
	if (pairs.empty())
		throw InputError(
			"no stereo pairs in '" + dir.string() +
			"': expected left/ and right/ folders with the same file names, left*/right* files, "
			"or EuRoC's mav0/cam0|cam1/data.csv");
	return pairs;
}

std::pair<fs::path, fs::path> findCalibration(const fs::path& dir)
{
	const std::vector<std::pair<fs::path, fs::path>> candidates = {
		{dir / "stereo_left.yaml", dir / "stereo_right.yaml"},
		{dir / "sensorLeft.yaml", dir / "sensorRight.yaml"},
		{dir / "mav0" / "cam0" / "sensor.yaml", dir / "mav0" / "cam1" / "sensor.yaml"},
		{dir / "left.yaml", dir / "right.yaml"}};
	for (const auto& c : candidates)
		if (fs::exists(c.first) && fs::exists(c.second)) return c;
	throw InputError(
		"no stereo calibration in '" + dir.string() +
		"': expected stereo_left.yaml + stereo_right.yaml (OpenCV/ROS), sensorLeft.yaml + "
		"sensorRight.yaml (Kimera) or mav0/cam0|cam1/sensor.yaml (EuRoC); or give "
		"--calibration LEFT.yaml,RIGHT.yaml");
}
}  // namespace

int StereoImportApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-stereo-import: build an MRPT stereo rawlog (CObservationStereoImages, images "
		"stored in OUT_Images/) from a folder of real image pairs and their calibration. See "
		"doc/simulator.md, 'Importing real stereo pairs'.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argDir("folder", "Folder with the pairs", true, "", "FOLDER", cmd);
	TCLAP::ValueArg<std::string> argOut("o", "out", "Output rawlog (OUT.rawlog)", true, "", "OUT", cmd);
	TCLAP::ValueArg<std::string> argCalib(
		"", "calibration", "LEFT.yaml,RIGHT.yaml (default: found in FOLDER)", false, "", "FILES", cmd);
	TCLAP::SwitchArg argRectify("", "rectify", "Rectify with MRPT's CStereoRectifyMap", cmd);
	TCLAP::ValueArg<double> argRate(
		"", "rate", "Frames per second when times come from frame numbers", false, 10, "HZ", cmd);
	TCLAP::ValueArg<double> argT0(
		"", "t0", "[s] time of frame 0 when times come from frame numbers", false, 1.7e9, "T", cmd);
	TCLAP::ValueArg<std::string> argTimes(
		"", "times", "CSV 'timestamp_ns,left file name' (EuRoC data.csv form)", false, "", "CSV", cmd);
	TCLAP::ValueArg<std::string> argGt(
		"", "ground-truth", "TUM file: per frame, the nearest row within 5 ms goes to OUT.gt.txt", false, "", "TUM", cmd);
	TCLAP::ValueArg<std::string> argLabel("", "label", "Sensor label", false, "STEREO", "NAME", cmd);
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;
	if (!(argRate.getValue() > 0)) throw UsageError("--rate must be > 0");

	const fs::path dir = argDir.getValue();
	if (!fs::is_directory(dir)) throw InputError("'" + dir.string() + "' is not a folder");
	std::string layout;
	std::vector<ImagePair> pairs = findPairs(dir, layout);

	std::pair<fs::path, fs::path> calibFiles;
	if (argCalib.isSet())
	{
		const auto& v = argCalib.getValue();
		const auto comma = v.find(',');
		if (comma == std::string::npos) throw UsageError("--calibration LEFT.yaml,RIGHT.yaml");
		calibFiles = {v.substr(0, comma), v.substr(comma + 1)};
	}
	else
		calibFiles = findCalibration(dir);
	const StereoCalibrationFile calib =
		StereoCalibrationFile::load(calibFiles.first.string(), calibFiles.second.string());

	// Times: csv, else nanosecond names, else frame numbers at --rate.
	std::map<std::string, double> times;
	if (argTimes.isSet()) times = readTimesCsv(argTimes.getValue());
	for (size_t i = 0; i < pairs.size(); i++)
	{
		auto& p = pairs[i];
		if (p.time >= 0) continue;
		if (auto it = times.find(p.left.filename().string()); it != times.end())
		{
			p.time = it->second;
			continue;
		}
		if (argTimes.isSet())
			throw InputError("'" + argTimes.getValue() + "' has no time for '" + p.left.filename().string() + "'");
		const double n = numberIn(p.left.stem().string());
		p.time = n >= 1e17 ? n * 1e-9
			: n >= 0	   ? argT0.getValue() + n / argRate.getValue()
						   : argT0.getValue() + static_cast<double>(i) / argRate.getValue();
	}
	std::sort(pairs.begin(), pairs.end(), [](const ImagePair& a, const ImagePair& b) {
		return a.time < b.time;
	});
	for (size_t i = 1; i < pairs.size(); i++)
		if (pairs[i].time <= pairs[i - 1].time)
			throw InputError(
				"pairs '" + pairs[i - 1].key + "' and '" + pairs[i].key +
				"' have the same time: give --times");

	// The ground truth is read before anything is written: a bad row
	// stops the import with nothing half made.
	std::vector<std::string> gtRows;
	const fs::path outPath = argOut.getValue();
	const std::string gtPath = (outPath.parent_path() / (outPath.stem().string() + ".gt.txt")).string();
	if (argGt.isSet())
	{
		const auto gtAll = TumPoseFile::read(argGt.getValue());
		// Per frame, the nearest row within 5 ms (Vicon and motion capture
		// run at 100-200 Hz, cameras at 10-30 Hz).
		for (const auto& p : pairs)
			if (const auto* row = TumPoseFile::nearest(gtAll, p.time, 0.005)) gtRows.push_back(row->text);
		if (gtRows.empty())
			throw InputError(
				"'" + argGt.getValue() + "' has no row within 5 ms of any stereo frame's time (first frame at " +
				std::to_string(pairs.front().time) + " s)");
	}

	mrpt::img::TStereoCamera params = calib.stereo;
	mrpt::poses::CPose3D leftCameraOnBody = calib.leftCameraOnBody;
	mrpt::vision::CStereoRectifyMap rectifier;
	if (argRectify.getValue())
	{
		rectifier.setAlpha(0);	// only valid pixels
		rectifier.setFromCamParams(params);
		params = rectifier.getRectifiedImageParams();
		// MRPT 2.5.8 leaves the unrectified rotation in the rectified right
		// pose: a rectified pair is offset along x only, by the baseline.
		const auto& rp = calib.stereo.rightCameraPose;
		const double baseline = std::sqrt(rp.x * rp.x + rp.y * rp.y + rp.z * rp.z);
		params.rightCameraPose = mrpt::math::TPose3DQuat(baseline, 0, 0, 1, 0, 0, 0);
		params.leftCamera.distortion = params.rightCamera.distortion =
			mrpt::img::DistortionModel::none;
		// The rectified left camera is the raw one turned: getLeftCameraRot()
		// holds OpenCV's R1, which takes points from the raw camera's frame
		// to the rectified one's, so the rectified camera's pose on the raw
		// one has the rotation R1^T. (MRPT 2.5.8's own
		// rectify(CObservationStereoImages&) composes R1 itself, the inverse;
		// the test StereoImport.RealPairsBecomeRawlogsThatRunReads checks the
		// rays through both images.)
		leftCameraOnBody = leftCameraOnBody + (-mrpt::poses::CPose3D(rectifier.getLeftCameraRot()));
	}

	const fs::path out = argOut.getValue();
	if (out.has_parent_path()) fs::create_directories(out.parent_path());
	const fs::path imagesDir = out.parent_path() / (out.stem().string() + "_Images");
	fs::create_directories(imagesDir);
	mrpt::io::CFileGZOutputStream file;
	if (!file.open(out.string())) throw std::runtime_error("cannot write '" + out.string() + "'");
	auto arch = mrpt::serialization::archiveFrom(file);

	for (size_t i = 0; i < pairs.size(); i++)
	{
		const auto& p = pairs[i];
		cv::Mat l = cv::imread(p.left.string(), cv::IMREAD_UNCHANGED);
		cv::Mat r = cv::imread(p.right.string(), cv::IMREAD_UNCHANGED);
		if (l.empty()) throw InputError("'" + p.left.string() + "' does not decode as an image");
		if (r.empty()) throw InputError("'" + p.right.string() + "' does not decode as an image");
		if (l.size() != r.size())
			throw InputError("'" + p.left.string() + "' and '" + p.right.string() + "' differ in size");
		if (l.cols != static_cast<int>(calib.stereo.leftCamera.ncols) ||
			l.rows != static_cast<int>(calib.stereo.leftCamera.nrows))
			throw InputError(
				"'" + p.left.string() + "' is " + std::to_string(l.cols) + "x" + std::to_string(l.rows) +
				" but the calibration is for " + std::to_string(calib.stereo.leftCamera.ncols) + "x" +
				std::to_string(calib.stereo.leftCamera.nrows));
		mrpt::img::CImage left(l, mrpt::img::DEEP_COPY), right(r, mrpt::img::DEEP_COPY);
		if (argRectify.getValue())
		{
			mrpt::img::CImage rl, rr;
			rectifier.rectify(left, right, rl, rr);
			left = rl;
			right = rr;
		}
		const std::string stem = StereoOutputWriter::fileStem(argLabel.getValue(), i);
		const std::string leftName = stem + "_left.png", rightName = stem + "_right.png";
		if (!cv::imwrite((imagesDir / leftName).string(), left.asCvMatRef()) ||
			!cv::imwrite((imagesDir / rightName).string(), right.asCvMatRef()))
			throw std::runtime_error("cannot write images in '" + imagesDir.string() + "'");

		mrpt::obs::CObservationStereoImages obs;
		obs.sensorLabel = argLabel.getValue();
		obs.timestamp = mrpt::Clock::fromDouble(p.time);
		obs.setStereoCameraParams(params);
		obs.cameraPose = mrpt::poses::CPose3DQuat(leftCameraOnBody);
		obs.hasImageRight = true;
		obs.imageLeft = left;
		obs.imageRight = right;
		obs.imageLeft.setExternalStorage(leftName);
		obs.imageRight.setExternalStorage(rightName);
		arch << obs;
	}

	if (!gtRows.empty())
	{
		std::ofstream gt(gtPath);
		gt << "# featloc-stereo-import: rows of " << argGt.getValue()
		   << " at the stereo frames' times (TUM: t x y z qx qy qz qw)\n";
		for (const auto& row : gtRows) gt << row << "\n";
		if (!gt) throw std::runtime_error("cannot write '" + gtPath + "'");
	}

	std::printf(
		"featloc-stereo-import: %zu pairs (%s), calibration %s (%s)%s\n  wrote %s\n    %s/\n",
		pairs.size(), layout.c_str(), calibFiles.first.string().c_str(), calib.format.c_str(),
		argRectify.getValue() ? ", rectified" : "", out.string().c_str(), imagesDir.string().c_str());
	if (argGt.isSet()) std::printf("    %s (%zu ground-truth rows)\n", gtPath.c_str(), gtRows.size());
	return 0;
}
}  // namespace featloc
