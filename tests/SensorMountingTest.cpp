// ScanMatcher::match between the robot frame (the guess, the estimate) and
// the sensor frames (where the matchers work): a laser mounted off centre
// and turned on the robot. Found in the twentieth session of issue 15: with
// the sensor turned 90 deg, PCM's NEES was 8-20 where it is 3 with the
// sensor facing forward (x and y of every covariance swapped).
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>
#include <functional>

#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
/** d f(y) / d y by central differences (angles wrapped). */
Eigen::Matrix3d numericalJacobian(const std::function<CPose2D(const CPose2D&)>& f, const CPose2D& y)
{
	Eigen::Matrix3d J;
	const double h = 1e-6;
	for (int i = 0; i < 3; i++)
	{
		double plus[3] = {y.x(), y.y(), y.phi()}, minus[3] = {y.x(), y.y(), y.phi()};
		plus[i] += h;
		minus[i] -= h;
		const CPose2D a = f(CPose2D(plus[0], plus[1], plus[2]));
		const CPose2D b = f(CPose2D(minus[0], minus[1], minus[2]));
		J(0, i) = (a.x() - b.x()) / (2 * h);
		J(1, i) = (a.y() - b.y()) / (2 * h);
		J(2, i) = mrpt::math::wrapToPi(a.phi() - b.phi()) / (2 * h);
	}
	return J;
}

/** The same scan as seen with the sensor at the robot's origin. */
mrpt::obs::CObservation2DRangeScan atTheOrigin(const mrpt::obs::CObservation2DRangeScan& s)
{
	mrpt::obs::CObservation2DRangeScan c = s;
	c.sensorPose = mrpt::poses::CPose3D();
	return c;
}

/** Matching scans from a mounted sensor with a robot-frame guess must be the
 * sensor-frame problem (the same scans with the sensor at the origin, the
 * guess carried through Y = S^-1 (+) X (+) S and its Jacobian) carried
 * back: the estimate through X = S (+) Y (+) S^-1, its covariance through
 * that map's Jacobian. */
void expectTheSensorFrameProblemCarriedBack(const std::string& cls, const CPose2D& mount, bool turned = true)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	const CPose2D p0(-0.4, 0.3, 0.2);
	const CPose2D motion(0.25, -0.06, mrpt::DEG2RAD(5.0));
	const auto ref = room.scan(p0, mount, 361, M_PI);
	const auto cur = room.scan(p0 + motion, mount, 361, M_PI);
	const CPose2D inv = CPose2D() - mount;
	auto toSensor = [&](const CPose2D& x) { return inv + x + mount; };
	auto toRobot = [&](const CPose2D& y) { return mount + y + inv; };

	// A guess off the truth, far surer across the robot than along it.
	mrpt::poses::CPosePDFGaussian robotGuess(
		CPose2D(motion.x() + 0.04, motion.y() - 0.01, motion.phi() + mrpt::DEG2RAD(1.0)));
	robotGuess.cov.setZero();
	robotGuess.cov(0, 0) = 0.08 * 0.08;
	robotGuess.cov(1, 1) = 0.01 * 0.01;
	robotGuess.cov(2, 2) = mrpt::square(mrpt::DEG2RAD(2.0));
	const Eigen::Matrix3d K = numericalJacobian(toSensor, robotGuess.mean);
	const mrpt::poses::CPosePDFGaussian sensorGuess(toSensor(robotGuess.mean),
		mrpt::math::CMatrixDouble33(K * robotGuess.cov.asEigen() * K.transpose()));

	auto mounted = ScanMatcherFactory::create(cls);
	const MatchResult r = mounted->match(*ref, *cur, robotGuess);
	auto bare = ScanMatcherFactory::create(cls);
	const MatchResult s = bare->match(atTheOrigin(*ref), atTheOrigin(*cur), sensorGuess);
	ASSERT_TRUE(r.success) << r.failureReason;
	ASSERT_TRUE(s.success) << s.failureReason;

	const CPose2D back = toRobot(s.estimate.mean);
	EXPECT_NEAR(r.estimate.mean.x(), back.x(), 1e-9);
	EXPECT_NEAR(r.estimate.mean.y(), back.y(), 1e-9);
	EXPECT_NEAR(mrpt::math::wrapToPi(r.estimate.mean.phi() - back.phi()), 0, 1e-9);
	const Eigen::Matrix3d J = numericalJacobian(toRobot, s.estimate.mean);
	const Eigen::Matrix3d expected = J * s.estimate.cov.asEigen() * J.transpose();
	const double scale = expected.diagonal().maxCoeff();
	EXPECT_LT((r.estimate.cov.asEigen() - expected).cwiseAbs().maxCoeff(), 1e-5 * scale)
		<< "got\n" << r.estimate.cov.asEigen() << "\nexpected\n" << expected;
	// A turned mounting swaps what is sure and what is not: the test means
	// something only when the two frames' covariances differ.
	if (turned)
	{
		EXPECT_GT((expected - s.estimate.cov.asEigen()).cwiseAbs().maxCoeff(), 0.1 * scale);
	}
}
}  // namespace

TEST(SensorMounting, PcmsCovarianceIsCarriedFromATurnedSensorToTheRobot)
{
	expectTheSensorFrameProblemCarriedBack(
		"featloc::PcmFeatureMatcher", CPose2D(0.1, 0.05, mrpt::DEG2RAD(90)));
}

TEST(SensorMounting, IdcsCovarianceIsCarriedFromATurnedSensorToTheRobot)
{
	expectTheSensorFrameProblemCarriedBack(
		"featloc::IdcMatcher", CPose2D(0.1, 0.05, mrpt::DEG2RAD(90)));
}

// Facing forward but 0.3 m ahead of the axle: the rotation's lever arm
// couples the heading into the robot's sideways motion.
TEST(SensorMounting, TheLeverArmOfASensorAheadOfTheAxleIsInTheCovariance)
{
	expectTheSensorFrameProblemCarriedBack(
		"featloc::PcmFeatureMatcher", CPose2D(0.3, 0, 0), false);
}
