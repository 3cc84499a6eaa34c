#include "featloc/io/EntrySource.h"

#include "featloc/io/CarmenLogSource.h"
#include "featloc/io/RawlogFileSource.h"

namespace featloc
{
EntrySource::Ptr EntrySource::openFile(const std::string& path, const InputOptions& input)
{
	if (CarmenLogSource::handles(path))
		return std::make_unique<CarmenLogSource>(path, CarmenLogReader::Options::from(input));
	return std::make_unique<RawlogFileSource>(path);
}
}  // namespace featloc
