#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <Eigen/Dense>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <sstream>

#include "featloc/config/TrackedConfig.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/Simulator.h"
#include "support/CommandRunner.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
using mrpt::poses::CPose2D;

namespace
{
const std::string kSim = FEATLOC_SIM_EXE;
const std::string kWorlds = std::string(FEATLOC_SOURCE_DIR) + "/worlds/";

SimConfiguration loadWorld(const std::string& name, const std::vector<std::string>& sets)
{
	TrackedConfig c;
	c.loadFile(kWorlds + name);
	for (const auto& s : sets) c.applyOverride(s);
	auto sc = SimConfiguration::load(c);
	c.requireAllKeysRead();
	return sc;
}

Simulator makeSimulator(const SimConfiguration& sc)
{
	return Simulator(sc.world, sc.robot, sc.laser, sc.odometry, sc.simulation);
}

std::string fileBytes(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	std::stringstream ss;
	ss << in.rdbuf();
	return ss.str();
}

/** Odometry readings (format #1 actions) with their covariances. */
std::vector<mrpt::poses::CPosePDFGaussian> actionsOf(const std::string& rawlog)
{
	std::vector<mrpt::poses::CPosePDFGaussian> out;
	RawlogReader reader(rawlog);
	RawlogEntry e;
	while (reader.next(e))
		if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(e.object))
		{
			auto move = acts->getActionByClass<mrpt::obs::CActionRobotMovement2D>();
			mrpt::poses::CPosePDFGaussian g;
			g.copyFrom(*move->poseChange);
			out.push_back(g);
		}
	return out;
}

/** Mean NEES of odometry readings against the true increments. */
double meanNees(
	const std::vector<mrpt::poses::CPosePDFGaussian>& readings, const Trajectory& gt)
{
	double sum = 0;
	for (size_t k = 1; k < gt.poses.size(); k++)
	{
		const CPose2D truth = CPose2D(gt.poses[k].pose) - CPose2D(gt.poses[k - 1].pose);
		const auto& r = readings.at(k - 1);
		Eigen::Vector3d e(r.mean.x() - truth.x(), r.mean.y() - truth.y(),
			mrpt::math::wrapToPi(r.mean.phi() - truth.phi()));
		sum += e.dot(r.cov.asEigen().inverse() * e);
	}
	return sum / static_cast<double>(gt.poses.size() - 1);
}
}  // namespace

TEST(Simulator, GroundTruthIsExactlyConsistentWithTheScans)
{
	registerClasses();
	TempDir dir;
	// People walking, no range noise: re-casting from the written ground
	// truth must give the same ranges.
	const auto sc = loadWorld(
		"corridor-people.ini", {"Laser:range_noise=0", "Simulation:max_scans=120"});
	Simulator sim = makeSimulator(sc);
	std::vector<SimulatedScan> scans;
	sim.run(dir.file("c.rawlog"), dir.file("c.gt.txt"),
		[&](const SimulatedScan& s) { scans.push_back(s); });
	ASSERT_EQ(scans.size(), 120u);

	const Trajectory gt = TrajectoryFile::read(dir.file("c.gt.txt"));
	ASSERT_EQ(gt.poses.size(), 120u);
	const CPose2D mount(sc.laser.sensor_pose[0], sc.laser.sensor_pose[1], sc.laser.sensor_pose[2]);
	size_t hits = 0, legHits = 0;
	for (size_t k = 0; k < scans.size(); k++)
	{
		EXPECT_NEAR(gt.poses[k].t, scans[k].time, 1e-6);
		const double t = static_cast<double>(k) / sc.laser.rate;
		const auto recast = sim.exactRanges(CPose2D(gt.poses[k].pose) + mount, t);
		for (size_t i = 0; i < recast.size(); i++)
		{
			if (std::isinf(scans[k].exactRanges[i]))
			{
				EXPECT_TRUE(std::isinf(recast[i]));
				continue;
			}
			EXPECT_NEAR(recast[i], scans[k].exactRanges[i], 1e-9) << k << "/" << i;
			hits++;
		}
		// People are in the scans.
		std::vector<CircleShape> legs;
		for (const auto& a : sim.world().agents()) a.shapesAt(t, legs);
		std::vector<double> withoutPeople;
		RayCaster::cast((CPose2D(gt.poses[k].pose) + mount).asTPose(),
			Simulator::beamGeometry(sc.laser).first,
			Simulator::beamGeometry(sc.laser).second, sc.laser.beams,
			sc.laser.max_range, sim.world().segments(), sim.world().circles(),
			withoutPeople);
		for (size_t i = 0; i < recast.size(); i++)
			legHits += recast[i] < withoutPeople[i] - 0.05;
	}
	EXPECT_GT(hits, 120u * 300);
	EXPECT_GT(legHits, 200u);

	// The rawlog holds the same ranges (as floats) and the same beam
	// geometry as MRPT reads it back.
	RawlogReader reader(dir.file("c.rawlog"));
	RawlogEntry e;
	size_t k = 0;
	while (reader.next(e))
	{
		auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(e.object);
		if (!sf) continue;
		auto obs = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
		ASSERT_TRUE(obs);
		for (size_t i = 0; i < obs->getScanSize(); i++)
		{
			const double exact = scans[k].exactRanges[i];
			EXPECT_EQ(obs->getScanRangeValidity(i),
				std::isfinite(exact) && exact >= sc.laser.min_range);
			if (obs->getScanRangeValidity(i))
			{
				EXPECT_NEAR(obs->getScanRange(i), exact, 2e-6 * exact);
			}
			const auto [first, step] = Simulator::beamGeometry(sc.laser);
			EXPECT_NEAR(obs->getScanAngle(i), first + step * static_cast<double>(i), 1e-6);
		}
		k++;
	}
	EXPECT_EQ(k, 120u);
}

TEST(Simulator, SameSeedSameBytesOtherSeedOtherBytes)
{
	registerClasses();
	TempDir dir;
	auto run = [&](const std::string& prefix, const std::string& seed) {
		const auto r = runCommand(
			shellQuote(kSim) + " " + shellQuote(kWorlds + "lab.ini") + " --out " +
			shellQuote(dir.file(prefix)) + " --seed " + seed +
			" --set Simulation:max_scans=60 -q");
		EXPECT_EQ(r.exitCode, 0) << r.output;
	};
	run("a", "11");
	run("b", "11");
	run("c", "12");
	EXPECT_EQ(fileBytes(dir.file("a.rawlog")), fileBytes(dir.file("b.rawlog")));
	EXPECT_EQ(fileBytes(dir.file("a.gt.txt")), fileBytes(dir.file("b.gt.txt")));
	EXPECT_NE(fileBytes(dir.file("a.rawlog")), fileBytes(dir.file("c.rawlog")));
	// The lab explores random goals: another seed, another path.
	EXPECT_NE(fileBytes(dir.file("a.gt.txt")), fileBytes(dir.file("c.gt.txt")));
	// MRPT's own tool reads it.
	const auto info = runCommand("rawlog-edit --info -i " + shellQuote(dir.file("a.rawlog")));
	EXPECT_EQ(info.exitCode, 0) << info.output;
	EXPECT_NE(info.output.find("LASER"), std::string::npos) << info.output;
}

// In one process too: MRPT's randomize(seed) keeps the normal
// distribution's spare Gaussian, so a simulation after anything that drew
// an odd number of them (here one draw) came out another log with the same
// seed; PipelineKeyframe's four seeds in one test saw it.
TEST(Simulator, SameSeedSameLogWhateverRanBeforeInTheProcess)
{
	registerClasses();
	TempDir dir;
	const auto sc = loadWorld("lab.ini", {"Simulation:max_scans=40", "Simulation:seed=7"});
	auto run = [&](const std::string& prefix) {
		Simulator sim = makeSimulator(sc);
		sim.run(dir.file(prefix + ".rawlog"), dir.file(prefix + ".gt.txt"));
	};
	run("a");
	mrpt::random::getRandomGenerator().drawGaussian1D_normalized();
	run("b");
	EXPECT_EQ(fileBytes(dir.file("a.gt.txt")), fileBytes(dir.file("b.gt.txt")));
	// Not EXPECT_EQ: a failure would print both compressed rawlogs.
	EXPECT_TRUE(fileBytes(dir.file("a.rawlog")) == fileBytes(dir.file("b.rawlog")));
}

TEST(Simulator, OdometryCovarianceIsHonest)
{
	registerClasses();
	TempDir dir;
	// Average NEES of the odometry readings against the true increments,
	// within the 95% band for the mean of N chi-square(3) values.
	const auto sc = loadWorld("office.ini", {});
	makeSimulator(sc).run(dir.file("o.rawlog"), dir.file("o.gt.txt"));
	const Trajectory gt = TrajectoryFile::read(dir.file("o.gt.txt"));
	const auto readings = actionsOf(dir.file("o.rawlog"));
	ASSERT_EQ(readings.size() + 1, gt.poses.size());
	const double n = static_cast<double>(readings.size());
	const double nees = meanNees(readings, gt);
	EXPECT_GT(nees, 3 - 1.96 * std::sqrt(6 / n)) << nees;
	EXPECT_LT(nees, 3 + 1.96 * std::sqrt(6 / n)) << nees;
}

TEST(Simulator, PerturbedPairsAreIndependentUniformTrials)
{
	registerClasses();
	TempDir dir;
	const auto sc = loadWorld("office.ini",
		{"Odometry:mode=perturbed_pairs", "Odometry:perturbation=uniform",
		 "Odometry:perturbation_xy=0.3", "Odometry:perturbation_yaw_DEG=10",
		 "Simulation:max_scans=400"});
	makeSimulator(sc).run(dir.file("p.rawlog"), dir.file("p.gt.txt"));
	const Trajectory gt = TrajectoryFile::read(dir.file("p.gt.txt"));
	const auto readings = actionsOf(dir.file("p.rawlog"));
	ASSERT_EQ(readings.size(), 399u);
	double maxErrXY = 0, maxErrYaw = 0;
	for (size_t k = 1; k < gt.poses.size(); k++)
	{
		const CPose2D truth = CPose2D(gt.poses[k].pose) - CPose2D(gt.poses[k - 1].pose);
		const auto& r = readings[k - 1];
		maxErrXY = std::max({maxErrXY, std::abs(r.mean.x() - truth.x()),
			std::abs(r.mean.y() - truth.y())});
		maxErrYaw = std::max(maxErrYaw, std::abs(mrpt::math::wrapToPi(r.mean.phi() - truth.phi())));
		EXPECT_NEAR(r.cov(0, 0), 0.3 * 0.3 / 3, 1e-12);
		EXPECT_EQ(r.cov(0, 1), 0);
	}
	EXPECT_LE(maxErrXY, 0.3 + 1e-9);
	EXPECT_GT(maxErrXY, 0.25);	// the whole interval is used
	EXPECT_LE(maxErrYaw, mrpt::DEG2RAD(10.0) + 1e-9);
	const double nees = meanNees(readings, gt);
	EXPECT_NEAR(nees, 3.0, 1.96 * std::sqrt(2 * 3 * 0.4 / 399.0) + 0.1) << nees;
}

TEST(Simulator, Format2InterleavesOdometryInTimeOrder)
{
	registerClasses();
	TempDir dir;
	const auto sc = loadWorld("office.ini",
		{"Simulation:format=2", "Simulation:max_scans=50", "Laser:rate=5", "Odometry:rate=50"});
	const auto res = makeSimulator(sc).run(dir.file("f2.rawlog"), dir.file("f2.gt.txt"));
	EXPECT_EQ(res.scans, 50u);
	// Every 20 ms from 0 s to one period past the last scan (9.8 s).
	EXPECT_EQ(res.odometryReadings, 492u);
	RawlogReader reader(dir.file("f2.rawlog"));
	RawlogEntry e;
	double last = 0;
	size_t scans = 0, odo = 0;
	while (reader.next(e))
	{
		auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(e.object);
		ASSERT_TRUE(obs) << "format #2 holds only observations";
		const double t = mrpt::Clock::toDouble(obs->timestamp);
		EXPECT_GE(t, last);
		last = t;
		scans += static_cast<bool>(std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs));
		odo += static_cast<bool>(std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs));
	}
	EXPECT_EQ(scans, 50u);
	EXPECT_EQ(odo, res.odometryReadings);
}

TEST(FeatlocSim, WritesAllOutputsAndRejectsBadWorlds)
{
	TempDir dir;
	const auto ok = runCommand(
		shellQuote(kSim) + " " + shellQuote(kWorlds + "office.ini") + " --out " +
		shellQuote(dir.file("out/office")) + " --set Simulation:max_scans=20 -q");
	ASSERT_EQ(ok.exitCode, 0) << ok.output;
	for (const char* ext : {".rawlog", ".gt.txt", ".3Dscene", ".png"})
		EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("out/office") + ext))) << ext;
	const auto yaml = runCommand(
		shellQuote(kSim) + " " + shellQuote(kWorlds + "two-rooms.yaml") + " --out " +
		shellQuote(dir.file("out/two-rooms")) + " -q");
	ASSERT_EQ(yaml.exitCode, 0) << yaml.output;
	EXPECT_NE(yaml.output.find("1 people"), std::string::npos) << yaml.output;

	std::ofstream(dir.file("typo.ini"))
		<< "[Wall.w]\npolyline = [0 0; 1 0]\n[Robot]\nwaypoints = [0 0; 1 1]\nsped = 2\n";
	std::ofstream(dir.file("empty.ini")) << "[Robot]\nspeed = 1\n";
	std::ofstream(dir.file("badrow.ini")) << "[Wall.w]\npolyline = [0 0; 1]\n";
	std::ofstream(dir.file("obst.ini"))
		<< "[Wall.w]\npolyline = [0 0; 1 0]\n[Obstacle.o]\ntexture = x\n";
	struct Case
	{
		std::string args, expected;
	};
	const std::vector<Case> cases = {
		{shellQuote(dir.file("typo.ini")) + " --out x", "typo.ini:5: [Robot] sped"},
		{shellQuote(dir.file("empty.ini")) + " --out x", "no walls or obstacles"},
		{shellQuote(dir.file("badrow.ini")) + " --out x", "row 2 has 1 numbers"},
		{shellQuote(dir.file("obst.ini")) + " --out x", "either 'polygon"},
		{shellQuote(kWorlds + "office.ini") + " --out x --set Laser:preset=velodyne",
			"sick_lms200_181"},
		{shellQuote(kWorlds + "office.ini"), "missing --out"},
	};
	for (const auto& c : cases)
	{
		const auto r = runCommand("cd " + shellQuote(dir.path().string()) + " && " +
			shellQuote(kSim) + " " + c.args + " -q");
		EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
		EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
	}
}

// --frozen: the same world with nothing moving (no agents, every door held
// at its angle at t = 0) along the same path: what the moving things cost a
// matcher is its error on the world's log against this one's.
TEST(FeatlocSim, FrozenWorldHoldsDoorsDropsAgentsKeepsThePath)
{
	const SimWorld world = loadWorld("room-moving-objects.ini", {}).world;
	ASSERT_FALSE(world.agents().empty());
	ASSERT_EQ(world.doors().size(), 2u);
	const SimWorld still = world.frozen();
	EXPECT_TRUE(still.agents().empty());
	EXPECT_EQ(still.segments().size(), world.segments().size());
	EXPECT_EQ(still.circles().size(), world.circles().size());
	ASSERT_EQ(still.doors().size(), world.doors().size());
	for (size_t k = 0; k < world.doors().size(); k++)
		for (double t : {0.0, 10.0, 60.0})
		{
			const WallSegment held = still.doors()[k].segmentAt(t),
							  first = world.doors()[k].segmentAt(0);
			EXPECT_NEAR(held.b.x, first.b.x, 1e-12) << k << " " << t;
			EXPECT_NEAR(held.b.y, first.b.y, 1e-12) << k << " " << t;
		}
	// The doors do swing in the world itself (10 s: both are open).
	EXPECT_GT(std::abs(world.doors()[0].angleAt(10) - world.doors()[0].angleAt(0)), 1.0);
	EXPECT_GT(std::abs(world.doors()[1].angleAt(10) - world.doors()[1].angleAt(0)), 1.0);

	TempDir dir;
	const std::string common = shellQuote(kSim) + " " + shellQuote(kWorlds + "room-moving-objects.ini") +
		" --set Simulation:max_scans=60 -q --seed 2 --out ";
	const auto moving = runCommand(common + shellQuote(dir.file("moving")));
	const auto frozen = runCommand(common + shellQuote(dir.file("frozen")) + " --frozen");
	ASSERT_EQ(moving.exitCode, 0) << moving.output;
	ASSERT_EQ(frozen.exitCode, 0) << frozen.output;
	EXPECT_EQ(fileBytes(dir.file("moving.gt.txt")), fileBytes(dir.file("frozen.gt.txt")));
	EXPECT_NE(fileBytes(dir.file("moving.rawlog")), fileBytes(dir.file("frozen.rawlog")));
	const auto verbose = runCommand(shellQuote(kSim) + " " + shellQuote(kWorlds + "room-moving-objects.ini") +
		" --set Simulation:max_scans=5 --frozen --out " + shellQuote(dir.file("v")));
	EXPECT_NE(verbose.output.find("0 people, 0 carts, 2 doors"), std::string::npos) << verbose.output;
}
