#include "featloc/io/EntrySource.h"

#include "featloc/io/CarmenLogSource.h"
#include "featloc/io/InputOptions.h"
#include "featloc/io/RawlogFileSource.h"

namespace featloc
{
EntrySource::Ptr EntrySource::openFile(const std::string& path, const InputOptions& input)
{
	if (CarmenLogSource::handles(path))
	{
		CarmenLogReader::Options carmen;
		carmen.beamAngles = input.carmen_beam_angles;
		return std::make_unique<CarmenLogSource>(path, carmen);
	}
	return std::make_unique<RawlogFileSource>(path);
}
}  // namespace featloc
