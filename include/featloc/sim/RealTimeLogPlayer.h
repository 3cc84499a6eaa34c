#pragma once
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPose2D.h>

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "featloc/io/OdometryLine.h"
#include "featloc/sim/DeviceFault.h"
#include "featloc/sim/OdometryLineServer.h"
#include "featloc/sim/EmulatedLaser.h"

namespace featloc
{
/** The device emulator's clock: plays a simulated log (format #2: laser
 * scans and odometry readings) in real time through the emulated devices,
 * so that MRPT's drivers receive it as they would from a robot, and writes
 * the true robot pose of every scan as it is sent, stamped on this
 * computer's clock (the clock the drivers stamp observations with).
 *
 * Log time t maps to wall time W0 + (t - t_first), W0 being the moment
 * every driver is connected and the laser streams; the scanner's own
 * millisecond clock is the log time. */
class RealTimeLogPlayer
{
   public:
	struct Item
	{
		double t = 0;  //!< [s] log time
		bool isScan = false;
		std::vector<float> ranges;	//!< scan: metres, 0 = no return
		mrpt::poses::CPose2D truth;	 //!< scan: the true robot pose
		OdometryLine odometry;	//!< odometry reading (time = log time)
		/** A stereo pair (neither scan nor odometry): not played by the
		 * devices; its images' paths are absolute. */
		std::shared_ptr<mrpt::obs::CObservationStereoImages> stereo;
	};
	struct Result
	{
		size_t scans = 0;  //!< served (each laser counts what reached its driver)
		size_t readings = 0, readingsDelivered = 0;
		size_t faultsInjected = 0;	//!< laser faults that came due
		size_t stereoPairs = 0;	 //!< written to the camera recording
		double seconds = 0;	 //!< wall time played
		bool stopped = false;  //!< `stop` ended it early
	};

	/** The scans, odometry readings and stereo pairs of a format-#2 rawlog
	 * in time order; `truths` is the robot's true pose at each scan, in
	 * order. Throws InputError when the log holds something else or the
	 * counts differ. */
	static std::vector<Item> load(
		const std::string& rawlogPath, const std::vector<mrpt::poses::CPose2D>& truths);

	/** Every scan goes to each of `lasers` (the same simulated scanner in
	 * several protocols); `odometry` may be null (a robot without
	 * odometry). `groundTruthPath` is written as the scans go (TUM rows,
	 * flushed per row). */
	RealTimeLogPlayer(std::vector<EmulatedLaser*> lasers, OdometryLineServer* odometry,
		std::string groundTruthPath);

	/** Writes the log's stereo pairs to `path` when play starts
	 * (StereoCameraRecording), stamped on this computer's clock. */
	void setCameraRecording(std::string path) { m_cameraPath = std::move(path); }

	/** Faults to inject into the lasers as the log plays (DeviceFault). */
	void setLaserFaults(std::vector<DeviceFault> faults) { m_faults = std::move(faults); }

	/** Waits until the drivers are connected and the laser streams, then
	 * plays `items`; `onProgress(fraction)` now and then. Ends at the end
	 * of the log or when `stop` becomes true. */
	Result play(
		const std::vector<Item>& items, const std::atomic<bool>* stop,
		const std::function<void(double)>& onProgress = {});

   private:
	std::vector<EmulatedLaser*> m_lasers;
	OdometryLineServer* m_odometry;
	std::string m_gtPath;
	std::string m_cameraPath;
	std::vector<DeviceFault> m_faults;
};
}  // namespace featloc
