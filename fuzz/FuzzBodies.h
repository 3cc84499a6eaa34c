#pragma once
// What the file-reading fuzz targets do with one input, shared by their
// libFuzzer entry points (fuzz_*.cpp) and by the normal test suite, which
// runs every input of fuzz/regressions/TARGET/ through the same body
// (tests/FuzzRegressionsTest.cpp). Each body lets only featloc's documented
// errors (ConfigError, InputError) end a read; anything else escapes.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "FuzzInput.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/CarmenLogReader.h"
#include "featloc/io/MatchTableFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/io/StereoCalibrationFile.h"
#include "featloc/io/TumPoseFile.h"
#include "featloc/io/WallMapFile.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/stereo/StereoVerticalLines.h"

#include <opencv2/core.hpp>

namespace featloc::fuzz
{
/** Runs f, letting only featloc's documented errors end it. */
template <typename F>
void documentedErrorsOnly(F&& f)
{
	try
	{
		f();
	}
	catch (const ConfigError&)
	{
	}
	catch (const InputError&)
	{
	}
}

inline void registerOnce()
{
	static const bool registered = (registerClasses(), true);
	(void)registered;
}

/** fuzz_rawlog_reader: RawlogReader, plain or gzip (byte 0 picks, as a
 * user's file name would), every entry. */
inline void rawlogReader(const uint8_t* data, size_t size)
{
	registerOnce();
	const bool gz = size > 0 && (data[0] & 1);
	FuzzFile file(data, size, gz ? ".rawlog.gz" : ".rawlog");
	documentedErrorsOnly([&] {
		RawlogReader reader(file.path);
		RawlogEntry entry;
		for (int i = 0; i < 10000 && reader.next(entry); i++)
		{
		}
	});
}

/** fuzz_carmen_reader: CarmenLogReader (Radish/CARMEN FLASER logs). */
inline void carmenReader(const uint8_t* data, size_t size)
{
	FuzzFile file(data, size, ".log");
	documentedErrorsOnly([&] { CarmenLogReader::read(file.path, CarmenLogReader::Options()); });
}

/** fuzz_config: ini text, then, after a NUL byte, one --set value per line;
 * the run configuration read from it as featloc-run reads it (every
 * section, every matcher, no key left unread). A file the configuration
 * names (a map, a ground truth) that is missing is an InputError. */
inline void configText(const uint8_t* data, size_t size)
{
	registerOnce();
	const std::string all(reinterpret_cast<const char*>(data), size);
	const auto nul = all.find('\0');
	documentedErrorsOnly([&] {
		TrackedConfig cfg;
		cfg.loadText(all.substr(0, nul), "fuzz.ini", "/nonexistent");
		if (nul != std::string::npos)
		{
			std::istringstream sets(all.substr(nul + 1));
			for (std::string line; std::getline(sets, line);) cfg.applyOverride(line);
		}
		RunConfiguration::load(cfg);
		cfg.requireAllKeysRead();
	});
}

/** fuzz_world_file: byte 0 picks ini (even) or YAML (odd); the rest is
 * read as featloc-sim reads a world, and as a wall map (WallMapFile). */
inline void worldFile(const uint8_t* data, size_t size)
{
	if (size == 0) return;
	const bool yaml = data[0] & 1;
	const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
	documentedErrorsOnly([&] {
		TrackedConfig cfg;
		if (yaml)
			cfg.loadYaml(text, "fuzz.yaml", "/nonexistent");
		else
			cfg.loadText(text, "fuzz.ini", "/nonexistent");
		SimConfiguration::load(cfg);
	});
	FuzzFile file(data + 1, size - 1, yaml ? ".yaml" : ".ini");
	documentedErrorsOnly([&] { WallMapFile::load(file.path); });
}

/** fuzz_trajectory_file: the text files featloc-eval and featloc-viewer
 * read: trajectories in every format (auto-detected), relations, TUM 3-D
 * poses, matches.txt. */
inline void trajectoryFile(const uint8_t* data, size_t size)
{
	FuzzFile file(data, size, ".txt");
	documentedErrorsOnly([&] { TrajectoryFile::read(file.path); });
	documentedErrorsOnly([&] { TrajectoryFile::readRelations(file.path); });
	documentedErrorsOnly([&] { TumPoseFile::read(file.path); });
	documentedErrorsOnly([&] { MatchTableFile::read(file.path); });
}
/** fuzz_stereo: byte 0 even: a stereo calibration, the rest split at its
 * first NUL into the left and right camera files (OpenCV camera_info or
 * EuRoC sensor.yaml), read by StereoCalibrationFile (featloc-stereo-import).
 * Byte 0 odd: a grey stereo pair made of the bytes through the segment
 * stage of Moon et al. (StereoVerticalLines: detection, dynamic-programming
 * matching, SAD disparity, triangulation): bytes 1-2 give the width and
 * height (8 to 263 px), byte 3 the right image's shift (disparity), byte 4
 * the focal length; the pixels repeat the bytes that follow. */
inline void stereo(const uint8_t* data, size_t size)
{
	if (size == 0) return;
	if ((data[0] & 1) == 0)
	{
		const uint8_t* rest = data + 1;
		const size_t n = size - 1;
		size_t cut = 0;
		while (cut < n && rest[cut] != 0) cut++;
		FuzzFile left(rest, cut, "-left.yaml");
		FuzzFile right(rest + std::min(cut + 1, n), n - std::min(cut + 1, n), "-right.yaml");
		documentedErrorsOnly([&] { StereoCalibrationFile::load(left.path, right.path); });
		return;
	}
	if (size < 6) return;
	const int w = 8 + data[1], h = 8 + data[2], shift = data[3] % w;
	const uint8_t* pixels = data + 5;
	const size_t n = size - 5;
	cv::Mat left(h, w, CV_8UC1), right(h, w, CV_8UC1);
	for (int r = 0; r < h; r++)
		for (int c = 0; c < w; c++)
		{
			left.at<uint8_t>(r, c) = pixels[(size_t(r) * w + c) % n];
			right.at<uint8_t>(r, c) = pixels[(size_t(r) * w + (c + shift) % w) % n];
		}
	mrpt::img::TStereoCamera camera;
	for (auto* c : {&camera.leftCamera, &camera.rightCamera})
	{
		c->ncols = w;
		c->nrows = h;
		c->setIntrinsicParamsFromValues(20.0 + data[4] * 4, 20.0 + data[4] * 4, w / 2.0, h / 2.0);
	}
	camera.rightCameraPose = mrpt::math::TPose3DQuat(0.12, 0, 0, 1, 0, 0, 0);
	documentedErrorsOnly([&] {
		StereoVerticalLines().extract(left, right, camera, mrpt::poses::CPose3D(), "fuzz pair");
	});
}
}  // namespace featloc::fuzz
