#include "featloc/odometry/OdometrySamplingOffset.h"

#include <cmath>

namespace featloc
{
namespace
{
void addStep(double dx, double dy, double dyaw, mrpt::math::CMatrixDouble33& cov)
{
	const double d[3] = {dx, dy, dyaw};
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) cov(i, j) += d[i] * d[j] / 12.0;
}
}  // namespace

mrpt::math::CMatrixDouble33 OdometrySamplingOffset::ofReading(const mrpt::poses::CPose2D& step)
{
	mrpt::math::CMatrixDouble33 cov;
	cov.setZero();
	addStep(step.x(), step.y(), step.phi(), cov);
	return cov;
}

mrpt::math::CMatrixDouble33 OdometrySamplingOffset::covariance(
	const mrpt::poses::CPose2D& keyframeStep, const mrpt::poses::CPose2D& currentStep,
	const mrpt::poses::CPose2D& motion)
{
	// One reading's error at each end; the current one's into the
	// keyframe's frame.
	const double c = std::cos(motion.phi()), s = std::sin(motion.phi());
	mrpt::math::CMatrixDouble33 cov = ofReading(keyframeStep);
	addStep(c * currentStep.x() - s * currentStep.y(), s * currentStep.x() + c * currentStep.y(),
		currentStep.phi(), cov);
	return cov;
}
}  // namespace featloc
