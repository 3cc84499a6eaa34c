#include "featloc/sim/StereoCameraRecording.h"

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace featloc
{
size_t StereoCameraRecording::write(const std::string& path,
	const std::vector<std::shared_ptr<mrpt::obs::CObservationStereoImages>>& pairs,
	double firstLogTime, double wall0)
{
	const std::string temporary = path + ".part";
	{
		mrpt::io::CFileOutputStream file;  // plain: CFileGZInputStream reads it too
		if (!file.open(temporary))
			throw std::runtime_error("cannot write the camera recording '" + temporary + "'");
		auto archive = mrpt::serialization::archiveFrom(file);
		for (const auto& pair : pairs)
		{
			mrpt::obs::CObservationStereoImages stamped(*pair);	 // shares nothing mutable
			stamped.timestamp = mrpt::Clock::fromDouble(
				wall0 + (mrpt::Clock::toDouble(pair->timestamp) - firstLogTime));
			archive << stamped;
		}
	}
	std::error_code ec;
	std::filesystem::rename(temporary, path, ec);
	if (ec)
		throw std::runtime_error(
			"cannot rename '" + temporary + "' to '" + path + "': " + ec.message());
	return pairs.size();
}
}  // namespace featloc
