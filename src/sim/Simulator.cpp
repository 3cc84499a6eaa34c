#include "featloc/sim/Simulator.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Cholesky>
#include <opencv2/core.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "featloc/io/TumRow.h"
#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/StereoOutputWriter.h"

namespace featloc
{
namespace
{
mrpt::random::CRandomGenerator& rng()
{
	// MRPT's global generator: Thrun's model (drawSingleSample) draws from
	// it too, so one seeded sequence makes the whole simulation repeatable.
	return mrpt::random::getRandomGenerator();
}

}  // namespace

Simulator::Simulator(
	SimWorld world, RobotPathOptions robot, LaserOptions laser,
	SimOdometryOptions odometry, SimulationOptions simulation,
	BeaconSensorOptions beacons, StereoCameraOptions stereo)
	: m_world(std::move(world)),
	  m_robot(std::move(robot)),
	  m_laser(std::move(laser)),
	  m_odometry(std::move(odometry)),
	  m_sim(simulation),
	  m_beacons(std::move(beacons)),
	  m_stereo(std::move(stereo))
{
	// A fresh generator, not rng().randomize(seed): MRPT 2.5's randomize()
	// reseeds the Mersenne twister but keeps its std::normal_distribution,
	// which holds the second value of its last pair of Gaussians. Whatever
	// drew an odd number of them before (an earlier simulation in the same
	// process) then shifted every Gaussian of this one: the same seed gave
	// another log (a test's figures changed with the tests run before it).
	rng() = mrpt::random::CRandomGenerator(m_sim.seed);
	// Beacons draw from their own sequence: adding them to a world leaves
	// its laser and odometry exactly as they were (same seed, same draws).
	m_beaconRng.randomize(m_sim.seed + 0x9e3779b9u);
	m_trajectory = std::make_unique<RobotTrajectory>(
		RobotTrajectory::fromOptions(m_robot, m_world, rng()));
}

std::pair<double, double> Simulator::beamGeometry(const LaserOptions& laser)
{
	const double aperture = static_cast<float>(laser.aperture);
	return {-aperture / 2, aperture / static_cast<double>(laser.beams - 1)};
}

std::vector<double> Simulator::exactRanges(
	const mrpt::poses::CPose2D& sensor, double t) const
{
	std::vector<CircleShape> circles;
	m_world.circlesAt(t, circles);
	std::vector<WallSegment> moving;
	const auto& segments = m_world.segmentsAt(t, moving);
	const auto [first, step] = beamGeometry(m_laser);
	std::vector<double> ranges;
	RayCaster::cast(
		sensor.asTPose(), first, step, m_laser.beams, m_laser.max_range,
		segments, circles, ranges);
	return ranges;
}

SimulatedScan Simulator::makeScan(size_t index, double t)
{
	SimulatedScan s;
	s.index = index;
	s.time = m_sim.t0 + t;
	s.robot = m_trajectory->poseAt(t);
	const mrpt::poses::CPose2D mount(
		m_laser.sensor_pose[0], m_laser.sensor_pose[1], m_laser.sensor_pose[2]);
	s.sensor = s.robot + mount;
	s.exactRanges = exactRanges(s.sensor, t);

	auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	obs->sensorLabel = m_laser.label;
	obs->timestamp = mrpt::Clock::fromDouble(s.time);
	obs->aperture = static_cast<float>(m_laser.aperture);
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(m_laser.max_range);
	obs->stdError = static_cast<float>(m_laser.range_noise);
	obs->sensorPose = mrpt::poses::CPose3D(mount);
	obs->resizeScan(m_laser.beams);
	for (size_t i = 0; i < m_laser.beams; i++)
	{
		double r = s.exactRanges[i];
		bool valid = std::isfinite(r);
		// Always draw both numbers, so the random sequence does not depend
		// on what each beam hits.
		const double noise = rng().drawGaussian1D_normalized();
		const double u = rng().drawUniform(0.0, 1.0);
		if (valid)
		{
			// A lattice first, then the noise: MRPT's simulated log
			// (rawlogs/mrpt-simul) has its ranges on multiples of 0.16 m
			// with about 1 cm of noise on top.
			if (m_laser.range_step > 0) r = m_laser.range_step * std::round(r / m_laser.range_step);
			r += m_laser.range_bias + m_laser.range_noise * noise;
			valid = u >= m_laser.dropout_probability && r >= m_laser.min_range &&
				r < m_laser.max_range;
		}
		obs->setScanRange(
			i, static_cast<float>(valid ? r : m_laser.max_range));
		obs->setScanRangeValidity(i, valid);
	}
	s.observation = obs;
	if (m_beacons.enabled()) s.beacons = makeBeacons(s.robot, t);
	return s;
}

mrpt::obs::CObservationBearingRange::Ptr Simulator::makeBeacons(
	const mrpt::poses::CPose2D& robot, double t)
{
	const auto& b = m_beacons;
	const mrpt::poses::CPose2D mount(b.sensor_pose[0], b.sensor_pose[1], b.sensor_pose[2]);
	const mrpt::poses::CPose2D sensor = robot + mount;
	auto obs = std::make_shared<mrpt::obs::CObservationBearingRange>();
	obs->sensorLabel = b.label;
	obs->timestamp = mrpt::Clock::fromDouble(m_sim.t0 + t);
	obs->sensorLocationOnRobot = mrpt::poses::CPose3D(mount);
	obs->minSensorDistance = 0;
	obs->maxSensorDistance = static_cast<float>(b.max_range);
	obs->fieldOfView_yaw = static_cast<float>(b.field_of_view);
	obs->sensor_std_range = static_cast<float>(b.range_noise);
	obs->sensor_std_yaw = static_cast<float>(b.bearing_noise);
	obs->validCovariances = false;

	std::vector<CircleShape> circles;
	if (b.occlusion) m_world.circlesAt(t, circles);
	std::vector<WallSegment> moving;
	const auto& segments = m_world.segmentsAt(t, moving);
	for (size_t i = 0; i < b.points.size(); i++)
	{
		// Always draw both numbers (fixed random sequence, as for beams).
		const double nr = m_beaconRng.drawGaussian1D_normalized();
		const double nb = m_beaconRng.drawGaussian1D_normalized();
		const double dx = b.points[i][0] - sensor.x(), dy = b.points[i][1] - sensor.y();
		const double range = std::hypot(dx, dy);
		const double bearing = mrpt::math::wrapToPi(std::atan2(dy, dx) - sensor.phi());
		if (range > b.max_range || std::abs(bearing) > b.field_of_view / 2) continue;
		if (b.occlusion)
		{
			// One beam towards the beacon: something nearer hides it (a
			// beacon on a wall is still seen: 2 cm tolerance).
			std::vector<double> hit;
			RayCaster::cast(
				sensor.asTPose(), bearing, 1e-3, 1, range, segments, circles, hit);
			if (std::isfinite(hit[0]) && hit[0] < range - 0.02) continue;
		}
		// A beacon within a few noise sigmas could come out at a negative
		// range, which no sensor reports (and featloc-run rejects).
		const double measured = range + b.range_noise * nr;
		if (measured <= 0) continue;
		mrpt::obs::CObservationBearingRange::TMeasurement m;
		m.range = static_cast<float>(measured);
		m.yaw = static_cast<float>(mrpt::math::wrapToPi(bearing + b.bearing_noise * nb));
		m.pitch = 0;
		m.landmarkID = b.with_ids ? static_cast<int32_t>(i) : -1;
		obs->sensedData.push_back(m);
	}
	return obs;
}

mrpt::poses::CPose2D Simulator::noisyIncrement(const mrpt::poses::CPose2D& truth)
{
	double ex = 0, ey = 0, ephi = 0;
	if (m_odometry.mode == "perturbed_pairs")
	{
		const double a = m_odometry.perturbation_xy, b = m_odometry.perturbation_yaw;
		if (m_odometry.perturbation == "uniform")
		{
			ex = rng().drawUniform(-a, a);
			ey = rng().drawUniform(-a, a);
			ephi = rng().drawUniform(-b, b);
		}
		else
		{
			ex = a * rng().drawGaussian1D_normalized();
			ey = a * rng().drawGaussian1D_normalized();
			ephi = b * rng().drawGaussian1D_normalized();
		}
	}
	else if (m_odometry.model == "thrun")
	{
		// One draw of MRPT's Thrun model around the truth.
		mrpt::obs::CActionRobotMovement2D a;
		auto o = m_odometry.thrunModel();
		o.thrunModel.nParticlesCount = 1;
		a.computeFromOdometry(truth, o);
		mrpt::poses::CPose2D sample;
		a.drawSingleSample(sample);
		return sample;
	}
	else
	{
		// e ~ N(0, C(truth)), C from MRPT's Gaussian model: the reading the
		// model says the truth is N(reading, C) away from.
		const auto pdf = m_odometry.gaussian.incrementPdf(truth);
		Eigen::Matrix3d cov = pdf.cov.asEigen();
		const Eigen::Matrix3d L = cov.llt().matrixL();
		Eigen::Vector3d n;
		for (int i = 0; i < 3; i++) n[i] = rng().drawGaussian1D_normalized();
		const Eigen::Vector3d e = L * n;
		ex = e[0];
		ey = e[1];
		ephi = e[2];
	}
	return {truth.x() + ex, truth.y() + ey,
		mrpt::math::wrapToPi(truth.phi() + ephi)};
}

mrpt::serialization::CSerializable::Ptr Simulator::makeAction(
	const mrpt::poses::CPose2D& reading, double t)
{
	mrpt::obs::CActionRobotMovement2D move;
	if (m_odometry.mode == "perturbed_pairs")
	{
		// The noise's own covariance. Stored as a PDF (not as odometry,
		// which MRPT would rebuild from a motion model on loading).
		const bool uniform = m_odometry.perturbation == "uniform";
		// (A uniform draw in [-a, a] has sigma a / sqrt(3).)
		const double sigmaScale = uniform ? 1.0 / std::sqrt(3.0) : 1.0;
		move.estimationMethod = mrpt::obs::CActionRobotMovement2D::emScan2DMatching;
		move.rawOdometryIncrementReading = reading;
		move.poseChange = std::make_shared<mrpt::poses::CPosePDFGaussian>(diagonalPoseGaussian(
			reading, m_odometry.perturbation_xy * sigmaScale,
			m_odometry.perturbation_yaw * sigmaScale));
	}
	else if (m_odometry.model == "thrun")
	{
		move.computeFromOdometry(reading, m_odometry.thrunModel());
	}
	else
	{
		move.computeFromOdometry(reading, m_odometry.gaussian.motionModel());
	}
	move.timestamp = mrpt::Clock::fromDouble(t);
	auto acts = std::make_shared<mrpt::obs::CActionCollection>();
	acts->insert(move);
	return acts;
}

Simulator::Result Simulator::run(
	const std::string& rawlogPath, const std::string& groundTruthPath,
	const std::function<void(const SimulatedScan&)>& onScan,
	const std::function<void(double)>& onProgress)
{
	std::unique_ptr<mrpt::io::CStream> file;
	if (m_sim.compress)
	{
		auto gz = std::make_unique<mrpt::io::CFileGZOutputStream>();
		if (!gz->open(rawlogPath))
			throw std::runtime_error("cannot write '" + rawlogPath + "'");
		file = std::move(gz);
	}
	else
	{
		auto plain = std::make_unique<mrpt::io::CFileOutputStream>();
		if (!plain->open(rawlogPath))
			throw std::runtime_error("cannot write '" + rawlogPath + "'");
		file = std::move(plain);
	}
	std::ofstream gt(groundTruthPath);
	if (!gt) throw std::runtime_error("cannot write '" + groundTruthPath + "'");
	gt << "# featloc-sim ground truth (TUM format): t x y z qx qy qz qw of the "
		  "robot at every scan\n";
	auto arch = mrpt::serialization::archiveFrom(*file);

	Result res;
	const double end =
		m_sim.duration > 0 ? m_sim.duration : m_trajectory->duration();
	const double scanPeriod = 1.0 / m_laser.rate;
	size_t nScans = static_cast<size_t>(std::floor(end / scanPeriod + 1e-9)) + 1;
	if (m_sim.max_scans > 0 && nScans > m_sim.max_scans) nScans = m_sim.max_scans;
	const bool pairs = m_odometry.mode == "perturbed_pairs";

	// Format #2, mode = model: odometry readings at their own rate, running
	// one period past the last scan so that every scan is bracketed.
	const double odoPeriod = 1.0 / m_odometry.rate;
	double nextOdo = 0;
	mrpt::poses::CPose2D odoPose = m_trajectory->poseAt(0);
	double odoTruePrev = 0;  // [s] time of the previous reading
	bool odoStarted = false;
	auto writeOdometry = [&](double t, const mrpt::poses::CPose2D& pose) {
		mrpt::obs::CObservationOdometry o;
		o.sensorLabel = "ODOMETRY";
		o.timestamp = mrpt::Clock::fromDouble(m_sim.t0 + t);
		o.odometry = pose;
		arch << o;
		res.odometryReadings++;
	};
	auto odometryUntil = [&](double tEnd) {
		for (; nextOdo <= tEnd + 1e-12; nextOdo += odoPeriod)
		{
			if (odoStarted) odoPose = odoPose + noisyIncrement(m_trajectory->wheelMotion(odoTruePrev, nextOdo));
			odoStarted = true;
			odoTruePrev = nextOdo;
			writeOdometry(nextOdo, odoPose);
		}
	};

	// Stereo: its own renderer, writer and random generator (image noise
	// never shifts the laser's or the odometry's draws).
	std::unique_ptr<StereoRenderer> renderer;
	std::unique_ptr<VisibleEdges> edgeList;
	std::unique_ptr<StereoOutputWriter> stereoWriter;
	cv::RNG imageRng(static_cast<uint64_t>(m_sim.seed) * 2654435761ull + 12345);
	size_t nFrames = 0;
	double framePeriod = 0;
	if (m_stereo.enabled)
	{
		renderer = std::make_unique<StereoRenderer>(m_world, m_stereo);
		edgeList = std::make_unique<VisibleEdges>(m_world, m_stereo);
		std::string prefix = groundTruthPath;
		if (prefix.size() > 7 && prefix.substr(prefix.size() - 7) == ".gt.txt")
			prefix.resize(prefix.size() - 7);
		stereoWriter = std::make_unique<StereoOutputWriter>(m_stereo, rawlogPath, prefix);
		framePeriod = 1.0 / m_stereo.rate;
		const double lastScan = scanPeriod * static_cast<double>(nScans - 1);
		nFrames = static_cast<size_t>(std::floor(lastScan / framePeriod + 1e-9)) + 1;
	}

	double prevT = 0;  // [s] the previous scan or frame
	size_t k = 0, j = 0;  // next scan, next stereo frame
	size_t events = 0;
	while (k < nScans || j < nFrames)
	{
		const double tScan = k < nScans ? scanPeriod * static_cast<double>(k) : 1e300;
		const double tFrame = j < nFrames ? framePeriod * static_cast<double>(j) : 1e300;
		const double t = std::min(tScan, tFrame);
		const bool doScan = std::abs(tScan - t) < 1e-9, doFrame = std::abs(tFrame - t) < 1e-9;
		const mrpt::poses::CPose2D truth = m_trajectory->poseAt(t);
		if (m_sim.format == 1)
		{
			if (events > 0)
			{
				arch << *makeAction(noisyIncrement(m_trajectory->wheelMotion(prevT, t)), m_sim.t0 + t);
				res.actions++;
			}
		}
		else if (pairs)
		{
			if (events > 0) odoPose = odoPose + noisyIncrement(m_trajectory->wheelMotion(prevT, t));
			writeOdometry(t, odoPose);
		}
		else
		{
			odometryUntil(t);
		}
		prevT = t;
		events++;

		SimulatedScan scan;
		if (doScan)
		{
			scan = makeScan(k, t);
			if (scan.beacons) res.beaconMeasurements += scan.beacons->sensedData.size();
		}
		SimulatedStereo stereo;
		if (doFrame)
		{
			stereo.index = j;
			stereo.time = m_sim.t0 + t;
			stereo.robot = truth;
			stereo.frame = renderer->render(truth, t, imageRng);
			stereo.edges = edgeList->visible(
				stereo.frame.leftCamera, stereo.frame.depth, stereo.frame.rightDepth);
			stereo.observation = stereoWriter->write(j, stereo.time, stereo.frame, stereo.edges);
		}
		// Beacons first, at the scan's time: the pipeline makes one step of both.
		if (m_sim.format == 1)
		{
			mrpt::obs::CSensoryFrame sf;
			if (scan.beacons) sf.insert(scan.beacons);
			if (scan.observation) sf.insert(scan.observation);
			if (stereo.observation) sf.insert(stereo.observation);
			arch << sf;
		}
		else
		{
			if (scan.beacons) arch << *scan.beacons;
			if (scan.observation) arch << *scan.observation;
			if (stereo.observation) arch << *stereo.observation;
		}
		gt << tumRow(m_sim.t0 + t, truth);
		if (doScan)
		{
			if (onScan) onScan(scan);
			res.scans++;
			k++;
		}
		if (doFrame)
		{
			if (m_onStereo) m_onStereo(stereo);
			res.stereoFrames++;
			j++;
		}
		res.duration = t;
		if (onProgress)
			onProgress(static_cast<double>(k + j) / static_cast<double>(nScans + nFrames));
	}
	if (stereoWriter) stereoWriter->finish();
	if (m_sim.format == 2 && !pairs) odometryUntil(res.duration + odoPeriod);
	res.pathLength = m_trajectory->length();
	if (!gt) throw std::runtime_error("error writing '" + groundTruthPath + "'");
	return res;
}
}  // namespace featloc
