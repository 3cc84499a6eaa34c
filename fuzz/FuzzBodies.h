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
#include "featloc/io/TumPoseFile.h"
#include "featloc/io/WallMapFile.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/SimConfiguration.h"

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
}  // namespace featloc::fuzz
