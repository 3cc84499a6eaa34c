// Fuzz target: the text files featloc-eval and featloc-viewer read:
// trajectories in every format (TrajectoryFile, auto-detected), relations,
// TUM 3-D poses, and matches.txt.
#include <cstdint>

#include "FuzzInput.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/MatchTableFile.h"
#include "featloc/io/TumPoseFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	featloc::fuzz::FuzzFile file(data, size, ".txt");
	auto guarded = [](auto&& f) {
		try
		{
			f();
		}
		catch (const featloc::InputError&)
		{
		}
	};
	guarded([&] { featloc::TrajectoryFile::read(file.path); });
	guarded([&] { featloc::TrajectoryFile::readRelations(file.path); });
	guarded([&] { featloc::TumPoseFile::read(file.path); });
	guarded([&] { featloc::MatchTableFile::read(file.path); });
	return 0;
}
