#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include "featloc/sim/BeaconSensorOptions.h"
#include "featloc/sim/LaserOptions.h"
#include "featloc/sim/RobotPathOptions.h"
#include "featloc/sim/RobotTrajectory.h"
#include "featloc/sim/SimOdometryOptions.h"
#include "featloc/sim/SimWorld.h"
#include "featloc/sim/SimulationOptions.h"
#include "featloc/sim/StereoCameraOptions.h"
#include "featloc/sim/StereoRenderer.h"
#include "featloc/sim/VisibleEdges.h"

namespace featloc
{
/** One simulated scan, with what the test suite needs to check it. */
struct SimulatedScan
{
	size_t index = 0;
	double time = 0;  //!< [s] absolute (t0 + k / rate)
	mrpt::poses::CPose2D robot;	 //!< true robot pose
	mrpt::poses::CPose2D sensor;  //!< true sensor pose in the world
	/** Exact ranges before noise (double precision); +inf: no return. */
	std::vector<double> exactRanges;
	mrpt::obs::CObservation2DRangeScan::Ptr observation;  //!< as written
	/** The beacons seen with the scan (nullptr without [Beacons]). */
	mrpt::obs::CObservationBearingRange::Ptr beacons;
};

/** One simulated stereo pair, with its exact geometry. */
struct SimulatedStereo
{
	size_t index = 0;
	double time = 0;  //!< [s] absolute
	mrpt::poses::CPose2D robot;	 //!< true robot pose
	StereoFrame frame;
	std::vector<VisibleEdge> edges;
	mrpt::obs::CObservationStereoImages::Ptr observation;  //!< as written
};

/** featloc-sim's engine: drives the robot along its path, casts the laser
 * (walls, obstacles and the people at each scan's time), draws odometry
 * errors, and writes an ordinary MRPT rawlog (format #1 or #2) and the true
 * robot pose at every scan (TUM format).
 *
 * Deterministic: every random draw (odometry errors, range noise,
 * dropouts, exploration goals, MRPT's Thrun model) comes from MRPT's global
 * random generator seeded with [Simulation] seed, in a fixed order, and the
 * gzip stream carries no time stamp, so the same seed gives a
 * byte-identical rawlog. */
class Simulator
{
   public:
	struct Result
	{
		size_t scans = 0;
		size_t odometryReadings = 0;  //!< format #2
		size_t actions = 0;	 //!< format #1
		size_t beaconMeasurements = 0;	//!< range-bearing measurements
		size_t stereoFrames = 0;
		double duration = 0;  //!< [s] from the first to the last scan
		double pathLength = 0;	//!< [m] driven by the robot
	};

	Simulator(
		SimWorld world, RobotPathOptions robot, LaserOptions laser,
		SimOdometryOptions odometry, SimulationOptions simulation,
		BeaconSensorOptions beacons = {}, StereoCameraOptions stereo = {});

	/** Called with every stereo pair (after its files are written). */
	void onStereo(std::function<void(const SimulatedStereo&)> f) { m_onStereo = std::move(f); }

	/** Writes `rawlogPath` and `groundTruthPath` (the robot at every scan
	 * and stereo frame); `onScan` (optional) sees every scan. With a
	 * stereo camera, also the images and the stereo ground truth
	 * (StereoOutputWriter; its prefix is groundTruthPath without
	 * ".gt.txt"). Scans and stereo frames at the same time share one
	 * sensory frame (format #1). */
	Result run(
		const std::string& rawlogPath, const std::string& groundTruthPath,
		const std::function<void(const SimulatedScan&)>& onScan = {},
		const std::function<void(double)>& onProgress = {});

	const RobotTrajectory& trajectory() const { return *m_trajectory; }
	const SimWorld& world() const { return m_world; }
	const LaserOptions& laser() const { return m_laser; }

	/** Angle of the first beam relative to the sensor heading and the step
	 * between beams [rad], exactly as MRPT will read them back (the rawlog
	 * stores the aperture as a float). */
	static std::pair<double, double> beamGeometry(const LaserOptions& laser);

	/** A scan of the world from a sensor pose at time t (relative to t0),
	 * without noise: the exact ranges (+inf: no return). */
	std::vector<double> exactRanges(
		const mrpt::poses::CPose2D& sensor, double t) const;

   private:
	SimulatedScan makeScan(size_t index, double t);
	mrpt::obs::CObservationBearingRange::Ptr makeBeacons(
		const mrpt::poses::CPose2D& robot, double t);
	mrpt::poses::CPose2D noisyIncrement(const mrpt::poses::CPose2D& truth);
	mrpt::serialization::CSerializable::Ptr makeAction(
		const mrpt::poses::CPose2D& reading, double t);

	SimWorld m_world;
	RobotPathOptions m_robot;
	LaserOptions m_laser;
	SimOdometryOptions m_odometry;
	SimulationOptions m_sim;
	BeaconSensorOptions m_beacons;
	StereoCameraOptions m_stereo;
	std::function<void(const SimulatedStereo&)> m_onStereo;
	mrpt::random::CRandomGenerator m_beaconRng;
	std::unique_ptr<RobotTrajectory> m_trajectory;
};
}  // namespace featloc
