#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <limits>

#include "featloc/core/InputError.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/pipeline/StepAssembler.h"
#include "featloc/registerClasses.h"
#include "support/ErrorMessage.h"
#include "support/TempDir.h"
#include "support/TestRawlog.h"

using namespace featloc;
using featloc::test::errorMessageOf;
using featloc::test::TempDir;
using featloc::test::TestRawlog;
using mrpt::poses::CPose2D;

namespace
{
std::vector<EstimationStep> stepsOf(
	const std::string& file, InputOptions in = {}, OdometryOptions odo = {},
	StepAssembler* keep = nullptr)
{
	RawlogReader reader(file);
	StepAssembler local(in, odo, file);
	StepAssembler& a = keep ? *keep : local;
	std::vector<EstimationStep> steps;
	std::vector<StepSource> sel;
	RawlogEntry e;
	while (!a.full() && reader.next(e)) a.push(e, sel, steps);
	a.finish(steps);
	return steps;
}


void expectIncrement(const EstimationStep& s, const CPose2D& truth, double tol)
{
	const CPose2D& m = s.odometry.mean;
	EXPECT_NEAR(m.x(), truth.x(), tol) << "scan " << s.scanIndex;
	EXPECT_NEAR(m.y(), truth.y(), tol) << "scan " << s.scanIndex;
	EXPECT_NEAR(mrpt::math::wrapToPi(m.phi() - truth.phi()), 0, tol)
		<< "scan " << s.scanIndex;
}
}  // namespace

TEST(StepAssembler, Format1IncrementsAreTheActions)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 8;
	const auto times = log.write(dir.file("a.rawlog"));
	const auto steps = stepsOf(dir.file("a.rawlog"));
	ASSERT_EQ(steps.size(), 8u);
	EXPECT_FALSE(steps[0].hasOdometry);
	EXPECT_EQ(steps[0].odometry.mean, CPose2D());
	for (size_t k = 1; k < steps.size(); k++)
	{
		EXPECT_TRUE(steps[k].hasOdometry);
		EXPECT_EQ(steps[k].scanIndex, k);
		EXPECT_NEAR(mrpt::Clock::toDouble(steps[k].time), times[k], 1e-6);
		const double t = log.scanPeriod * static_cast<double>(k);
		expectIncrement(steps[k], log.path(t) - log.path(t - log.scanPeriod), 1e-9);
		EXPECT_GT(steps[k].odometry.cov(0, 0), 0);	// the action's covariance
		// Read at an instant the log does not give: the gates allow for it.
		EXPECT_TRUE(steps[k].odometryFromActions);
	}
}

// Format #1 odometry read at the scan's instant has no sampling offset (the
// EKF's turn on featloc-sim's corridor went 1.5 deg wrong modelling one):
// the actions stamped with their scan's time were; unstamped ones (MRPT's
// simulated log) and ones stamped 0.1 s before their scan (Malaga) were not.
TEST(StepAssembler, ActionsStampedWithTheirScansTimeWereReadAtTheScan)
{
	registerClasses();
	TempDir dir;
	for (const double offset : {0.0, std::numeric_limits<double>::quiet_NaN(), -0.1})
	{
		TestRawlog log;
		log.scans = 4;
		log.actionTimeOffset = offset;
		log.write(dir.file("a.rawlog"));
		const auto steps = stepsOf(dir.file("a.rawlog"));
		ASSERT_EQ(steps.size(), 4u);
		for (size_t k = 1; k < steps.size(); k++)
		{
			EXPECT_TRUE(steps[k].odometryFromActions);
			EXPECT_EQ(steps[k].odometryReadAtScan, offset == 0) << "offset " << offset;
		}
	}
}

TEST(StepAssembler, Format2OdometryIsInterpolatedAtScanTimes)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 12;
	log.observationsOnly = true;
	log.odometryPerScan = 3;  // readings never at the scan times
	log.write(dir.file("b.rawlog"));
	StepAssembler a(InputOptions{}, OdometryOptions{}, "b");
	const auto steps = stepsOf(dir.file("b.rawlog"), {}, {}, &a);
	ASSERT_EQ(steps.size(), 12u);
	EXPECT_EQ(a.stepsWithoutOdometry(), 0u);
	EXPECT_GT(a.odometryReadings(), 30u);
	for (size_t k = 1; k < steps.size(); k++)
	{
		ASSERT_TRUE(steps[k].hasOdometry);
		const double t = log.scanPeriod * static_cast<double>(k);
		// Linear interpolation over 1/30 s of a smooth path: ~1e-5 error.
		expectIncrement(steps[k], log.path(t) - log.path(t - log.scanPeriod), 1e-4);
		EXPECT_FALSE(steps[k].odometryFromActions);  // at the scan's own time
	}
}

TEST(StepAssembler, Format2OdometryIsExtrapolatedWhenAskedSoAScanNeedNotWait)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 12;
	log.observationsOnly = true;
	log.odometryPerScan = 3;  // a reading 1/60 s before each scan, the next 1/60 s after
	log.write(dir.file("b.rawlog"));
	for (const double maxAhead : {0.0, 0.02})
	{
		OdometryOptions odo;
		odo.max_extrapolation = maxAhead;
		StepAssembler a(InputOptions{}, odo, "b");
		RawlogReader reader(dir.file("b.rawlog"));
		RawlogEntry e;
		std::vector<StepSource> sel;
		std::vector<EstimationStep> steps, ready;
		size_t releasedAtTheirScan = 0;
		while (reader.next(e))
		{
			ready.clear();
			a.push(e, sel, ready);
			for (const auto& s : ready)
				if (s.source == e.object.get()) releasedAtTheirScan++;
			steps.insert(steps.end(), ready.begin(), ready.end());
			sel.clear();
		}
		ready.clear();
		a.finish(ready);
		steps.insert(steps.end(), ready.begin(), ready.end());
		ASSERT_EQ(steps.size(), 12u);
		if (maxAhead == 0)
		{
			// Each scan waits for the reading after it, and is interpolated.
			EXPECT_EQ(releasedAtTheirScan, 0u);
			EXPECT_EQ(a.stepsWithExtrapolatedOdometry(), 0u);
			continue;
		}
		// Each scan is released with its own entry: the newest reading is
		// 1/60 s old, within 0.02 s.
		EXPECT_EQ(releasedAtTheirScan, 12u);
		EXPECT_EQ(a.stepsWithExtrapolatedOdometry(), 12u);
		for (size_t k = 1; k < steps.size(); k++)
		{
			ASSERT_TRUE(steps[k].hasOdometry);
			const double t = log.scanPeriod * static_cast<double>(k);
			// The last 1/30 s continued 1/60 s on a smooth path: ~1e-5 error.
			expectIncrement(steps[k], log.path(t) - log.path(t - log.scanPeriod), 1e-4);
		}
	}
}

TEST(StepAssembler, ModelCovarianceGrowsWithMotion)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 3;
	log.path = [](double t) { return CPose2D(t < 0.15 ? 0.0 : 1.0, 0, 0); };
	log.write(dir.file("c.rawlog"));
	OdometryOptions odo;
	odo.covariance_source = "model";
	const auto steps = stepsOf(dir.file("c.rawlog"), {}, odo);
	ASSERT_EQ(steps.size(), 3u);
	// Step 1: no motion -> sigma_xy_min; step 2: 1 m -> min + per_m.
	EXPECT_NEAR(std::sqrt(steps[1].odometry.cov(0, 0)), odo.model.sigma_xy_min, 1e-9);
	EXPECT_NEAR(std::sqrt(steps[2].odometry.cov(0, 0)),
		odo.model.sigma_xy_min + odo.model.sigma_xy_per_m * 1.0, 1e-9);
}

TEST(StepAssembler, SeveralLasersNeedALabel)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 6;
	log.editScan = [](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		s.sensorLabel = (k % 2) ? "REAR" : "FRONT";
	};
	log.write(dir.file("two.rawlog"));
	const std::string msg = errorMessageOf<InputError>([&] { stepsOf(dir.file("two.rawlog")); });
	EXPECT_NE(msg.find("'REAR'"), std::string::npos) << msg;
	EXPECT_NE(msg.find("'FRONT'"), std::string::npos) << msg;
	EXPECT_NE(msg.find("laser_label"), std::string::npos) << msg;

	InputOptions in;
	in.laser_label = "REAR";
	const auto steps = stepsOf(dir.file("two.rawlog"), in);
	ASSERT_EQ(steps.size(), 3u);
	for (const auto& s : steps) EXPECT_EQ(s.scan->sensorLabel, "REAR");
}

TEST(StepAssembler, ScanWithoutTimestampIsAnError)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 4;
	log.editScan = [](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		if (k == 2) s.timestamp = INVALID_TIMESTAMP;
	};
	log.write(dir.file("t.rawlog"));
	const std::string msg = errorMessageOf<InputError>([&] { stepsOf(dir.file("t.rawlog")); });
	EXPECT_NE(msg.find("entry #4"), std::string::npos) << msg;
	EXPECT_NE(msg.find("no valid timestamp"), std::string::npos) << msg;
}

TEST(StepAssembler, RepeatedTimestampsAreAnErrorWithTheCarmenHint)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 4;
	log.editScan = [](size_t, mrpt::obs::CObservation2DRangeScan& s) {
		s.timestamp = mrpt::Clock::fromDouble(5.0);
	};
	log.write(dir.file("same.rawlog"));
	const std::string msg = errorMessageOf<InputError>([&] { stepsOf(dir.file("same.rawlog")); });
	EXPECT_NE(msg.find("repeats"), std::string::npos) << msg;
	EXPECT_NE(msg.find("carmen2rawlog"), std::string::npos) << msg;
}

TEST(StepAssembler, BadRangesFailOrAreInvalidated)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 3;
	log.editScan = [](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		if (k != 1) return;
		s.setScanRange(10, std::numeric_limits<float>::quiet_NaN());
		s.setScanRange(11, -2.0f);
		s.setScanRange(12, std::numeric_limits<float>::infinity());
		for (size_t i : {10, 11, 12}) s.setScanRangeValidity(i, true);
	};
	log.write(dir.file("nan.rawlog"));
	const std::string msg = errorMessageOf<InputError>([&] { stepsOf(dir.file("nan.rawlog")); });
	EXPECT_NE(msg.find("entry #2"), std::string::npos) << msg;
	EXPECT_NE(msg.find("beam 10"), std::string::npos) << msg;
	EXPECT_NE(msg.find("invalid_range_policy"), std::string::npos) << msg;

	InputOptions in;
	in.invalid_range_policy = "invalidate";
	StepAssembler a(in, OdometryOptions{}, "nan");
	const auto steps = stepsOf(dir.file("nan.rawlog"), in, {}, &a);
	ASSERT_EQ(steps.size(), 3u);
	EXPECT_EQ(a.selector().invalidatedBeams(), 3u);
	for (size_t i : {10, 11, 12})
		EXPECT_FALSE(steps[1].scan->getScanRangeValidity(i));
	EXPECT_TRUE(steps[1].scan->getScanRangeValidity(13));
}

TEST(StepAssembler, ImpossibleScanGeometryIsAnError)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 3;
	log.editScan = [](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		if (k == 2) s.aperture = std::numeric_limits<float>::quiet_NaN();
	};
	log.write(dir.file("geo.rawlog"));
	const std::string msg =
		errorMessageOf<InputError>([&] { stepsOf(dir.file("geo.rawlog")); });
	EXPECT_NE(msg.find("entry #4"), std::string::npos) << msg;
	EXPECT_NE(msg.find("impossible geometry"), std::string::npos) << msg;
}

TEST(StepAssembler, MaxScansStopsEarly)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 10;
	log.write(dir.file("m.rawlog"));
	InputOptions in;
	in.max_scans = 4;
	EXPECT_EQ(stepsOf(dir.file("m.rawlog"), in).size(), 4u);
}

TEST(StepAssembler, LogWithoutOdometryGivesTheNoOdometryPriorAtOnce)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 5;
	log.observationsOnly = true;
	log.odometry = false;
	log.write(dir.file("o.rawlog"));
	RawlogReader reader(dir.file("o.rawlog"));
	OdometryOptions odo;
	StepAssembler a(InputOptions{}, odo, "o");
	std::vector<EstimationStep> steps, ready;
	std::vector<StepSource> sel;
	RawlogEntry e;
	size_t releasedAtTheirScan = 0;
	while (reader.next(e))
	{
		ready.clear();
		a.push(e, sel, ready);
		for (const auto& s : ready) releasedAtTheirScan += s.source == e.object.get();
		steps.insert(steps.end(), ready.begin(), ready.end());
	}
	a.finish(steps);
	ASSERT_EQ(steps.size(), 5u);
	// No odometry reading in sight: a step does not wait for one (a live
	// run with a laser alone would lag max_interpolation_gap behind).
	EXPECT_EQ(releasedAtTheirScan, 5u);
	EXPECT_EQ(a.stepsWithoutOdometry(), 4u);
	EXPECT_FALSE(steps[3].hasOdometry);
	EXPECT_EQ(steps[3].odometry.mean, CPose2D());
	EXPECT_NEAR(steps[3].odometry.cov(0, 0), odo.no_odometry_sigma_xy * odo.no_odometry_sigma_xy, 1e-12);
}
