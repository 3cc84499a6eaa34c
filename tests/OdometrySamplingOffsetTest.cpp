#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <cmath>

#include "featloc/odometry/OdometrySamplingOffset.h"

using featloc::OdometrySamplingOffset;
using mrpt::poses::CPose2D;

// The model: odometry read a fraction f ~ U[-1/2, 1/2] of the step off the
// scan's instant misplaces the pose by f D. Drawn offsets at both ends of a
// keyframe -> current motion must have the covariance the class gives.
TEST(OdometrySamplingOffset, IsTheCovarianceOfUniformReadingOffsetsAtBothEnds)
{
	const CPose2D keyframeStep(0.30, 0.02, mrpt::DEG2RAD(4.0));
	const CPose2D currentStep(0.10, -0.05, mrpt::DEG2RAD(-9.0));
	const CPose2D motion(1.2, 0.4, mrpt::DEG2RAD(60.0));
	const Eigen::Matrix3d C =
		OdometrySamplingOffset::covariance(keyframeStep, currentStep, motion).asEigen();

	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(7);
	const Eigen::Vector3d dk(keyframeStep.x(), keyframeStep.y(), keyframeStep.phi());
	const double c = std::cos(motion.phi()), s = std::sin(motion.phi());
	// The current step in the keyframe's frame.
	const Eigen::Vector3d dc(c * currentStep.x() - s * currentStep.y(),
		s * currentStep.x() + c * currentStep.y(), currentStep.phi());
	Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
	const int n = 200000;
	for (int i = 0; i < n; i++)
	{
		const Eigen::Vector3d e = rng.drawUniform(-0.5, 0.5) * dk + rng.drawUniform(-0.5, 0.5) * dc;
		sum += e * e.transpose();
	}
	const Eigen::Matrix3d sampled = sum / n;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			EXPECT_NEAR(C(i, j), sampled(i, j), 0.02 * C.diagonal().maxCoeff()) << i << "," << j;
}

TEST(OdometrySamplingOffset, IsZeroWithoutStepsAndRankOneWithOne)
{
	EXPECT_EQ(
		OdometrySamplingOffset::covariance(CPose2D(), CPose2D(), CPose2D(1, 2, 0.3)).asEigen(),
		Eigen::Matrix3d::Zero());
	const Eigen::Matrix3d C =
		OdometrySamplingOffset::covariance(CPose2D(0.5, 0, 0), CPose2D(), CPose2D()).asEigen();
	EXPECT_NEAR(C(0, 0), 0.25 / 12, 1e-12);	 // (0.5 m)^2 / 12, along the step only
	EXPECT_NEAR(C(1, 1), 0, 1e-15);
	EXPECT_NEAR(C(2, 2), 0, 1e-15);
}
