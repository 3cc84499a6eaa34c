#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/matchers/IcpMatcher.h"
#include "featloc/matchers/ScanMatcherAlignment.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
void expectPose(const CPose2D& got, const CPose2D& truth, double tolXY, double tolPhi)
{
	EXPECT_NEAR(got.x(), truth.x(), tolXY);
	EXPECT_NEAR(got.y(), truth.y(), tolXY);
	EXPECT_NEAR(mrpt::math::wrapToPi(got.phi() - truth.phi()), 0, tolPhi);
}
}  // namespace

TEST(IcpMatcher, RecoversAKnownMotionFromAPerturbedGuess)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	const CPose2D p0(-0.5, 0.2, 0.1);
	const CPose2D motion(0.30, -0.10, mrpt::DEG2RAD(4.0));
	const auto ref = room.scan(p0, CPose2D(), 721);
	const auto cur = room.scan(p0 + motion, CPose2D(), 721);

	auto m = ScanMatcherFactory::create("featloc::IcpMatcher");
	const CPose2D start(motion.x() + 0.08, motion.y() - 0.06,
		motion.phi() + mrpt::DEG2RAD(2.0));
	const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(start, 0.1, 0.05));
	ASSERT_TRUE(r.success) << r.failureReason;
	// Point-to-point ICP on sampled scans: sub-centimetre, not exact.
	expectPose(r.estimate.mean, motion, 0.01, mrpt::DEG2RAD(0.3));
	EXPECT_GT(r.iterations, 0u);
	EXPECT_GT(r.goodness, 0.8);
	EXPECT_EQ(r.referencePoints, 721u);
	EXPECT_GT(r.estimate.cov(0, 0), 0);
	EXPECT_GT(r.timeSeconds, 0);
}

TEST(IcpMatcher, HandlesSensorOffsetsOnTheRobot)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	const CPose2D sensor(0.35, 0.12, mrpt::DEG2RAD(12));
	const CPose2D p0(0.3, -0.4, -0.3);
	const CPose2D motion(0.25, 0.05, mrpt::DEG2RAD(-6.0));
	const auto ref = room.scan(p0, sensor, 721);
	const auto cur = room.scan(p0 + motion, sensor, 721);
	auto m = ScanMatcherFactory::create("featloc::IcpMatcher");
	const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(motion, 0.1, 0.05));
	ASSERT_TRUE(r.success) << r.failureReason;
	// The robot motion, not the sensor's (which differs by the mounting).
	expectPose(r.estimate.mean, motion, 0.01, mrpt::DEG2RAD(0.3));
	const CPose2D sensorMotion = (CPose2D() - sensor) + motion + sensor;
	EXPECT_GT(std::hypot(sensorMotion.x() - motion.x(), sensorMotion.y() - motion.y()), 0.03);
}

TEST(IcpMatcher, EmptyScanIsAReportedFailure)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	const auto ref = room.scan(CPose2D());
	auto empty = room.scan(CPose2D());
	for (size_t i = 0; i < empty->getScanSize(); i++)
		empty->setScanRangeValidity(i, false);
	auto m = ScanMatcherFactory::create("featloc::IcpMatcher");
	const MatchResult r = m->match(*ref, *empty, diagonalPoseGaussian(CPose2D(0.1, 0, 0), 0.1, 0.1));
	EXPECT_FALSE(r.success);
	EXPECT_NE(r.failureReason.find("too few valid points"), std::string::npos);
	EXPECT_EQ(r.estimate.mean, CPose2D(0.1, 0, 0));	// the guess, untouched
}

TEST(IcpMatcher, LowOverlapIsAReportedFailure)
{
	registerClasses();
	// The current scan sees a hall 15 m away: nothing within the pairing
	// distance of the office's points.
	const auto ref = SyntheticRoom::office().scan(CPose2D());
	SyntheticRoom hall;
	hall.add(-15, -15, 15, -15);
	hall.add(15, -15, 15, 15);
	hall.add(15, 15, -15, 15);
	hall.add(-15, 15, -15, -15);
	const auto cur = hall.scan(CPose2D());
	auto m = ScanMatcherFactory::create("featloc::IcpMatcher");
	const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(CPose2D(0.5, 0, 0), 0.1, 0.1));
	EXPECT_FALSE(r.success);
	EXPECT_NE(r.failureReason.find("minGoodness"), std::string::npos)
		<< r.failureReason;
}

TEST(ScanMatcherAlignment, ServesMrptAlignmentInterfaceWithTheSameResult)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	const CPose2D motion(0.2, 0.1, mrpt::DEG2RAD(3));
	const auto ref = room.scan(CPose2D(), CPose2D(), 541);
	const auto cur = room.scan(motion, CPose2D(), 541);

	mrpt::maps::CSimplePointsMap m1, m2;
	m1.insertionOptions.minDistBetweenLaserPoints = 0;
	m2.insertionOptions.minDistBetweenLaserPoints = 0;
	m1.insertObservation(*ref);
	m2.insertObservation(*cur);

	auto matcher = ScanMatcherFactory::create("featloc::IcpMatcher");
	ScanMatcherAlignment align(matcher);
	mrpt::slam::CMetricMapsAlignmentAlgorithm& mrptApi = align;
	ScanMatcherAlignment::TReturnInfo info;
	const auto pdf = mrptApi.AlignPDF(&m1, &m2, diagonalPoseGaussian(CPose2D(), 0.2, 0.1), info);
	ASSERT_TRUE(pdf);
	CPose2D mean;
	pdf->getMean(mean);
	expectPose(mean, motion, 0.01, mrpt::DEG2RAD(0.3));
	EXPECT_TRUE(info.match.success);
	EXPECT_GT(info.executionTime, 0);

	// Same matcher on the scans: equal up to the float storage of the maps.
	const MatchResult direct = matcher->match(*ref, *cur, diagonalPoseGaussian(CPose2D(), 0.2, 0.1));
	expectPose(direct.estimate.mean, mean, 1e-5, 1e-6);

	EXPECT_THROW(
		mrptApi.Align3DPDF(&m1, &m2, mrpt::poses::CPose3DPDFGaussian()),
		std::logic_error);
}
