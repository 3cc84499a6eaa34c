#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <memory>
#include <string>
#include <vector>

namespace featloc
{
/** The device emulator's stereo camera: the simulated log's stereo pairs
 * as a rawlog that MRPT's CCameraSensor replays (`grabber_type = rawlog`),
 * every pair stamped on this computer's clock at the moment the emulator
 * "captures" it (wall0 + log time - first log time, the clock the lasers
 * and the odometry are served on), so featloc-live can deliver each one
 * when it comes due and fuse it with the emulated lasers.
 *
 * Why a file and not a stream: CCameraSensor's rawlog grabber opens its
 * file with CFileGZInputStream, which asks the file's size first (MRPT
 * 2.5.8: std::filesystem::file_size), so a named pipe is refused. The file
 * is written whole when play starts, under a temporary name then renamed,
 * so a driver never reads half of it. Images stay in their files (absolute
 * paths, external storage); the driver loads them as it reads. */
class StereoCameraRecording
{
   public:
	/** Writes `pairs` (in time order, log time) to `path`; returns how
	 * many. Throws std::runtime_error naming the file when it cannot. */
	static size_t write(const std::string& path,
		const std::vector<std::shared_ptr<mrpt::obs::CObservationStereoImages>>& pairs,
		double firstLogTime, double wall0);
};
}  // namespace featloc
