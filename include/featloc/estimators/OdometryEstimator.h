#pragma once
#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** Dead reckoning: composes the odometry increments (means and covariances,
 * on SE(2)). The baseline every other estimator must beat. */
class OdometryEstimator : public PoseEstimator
{
	DEFINE_MRPT_OBJECT(OdometryEstimator, featloc)

   public:
	std::string name() const override { return "odometry"; }
	bool usesScanMatcher() const override { return false; }
	void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) override;
	bool process(const EstimationStep& step, const MatchResult* match) override;
	const mrpt::poses::CPosePDFGaussian& pose() const override { return m_pose; }

   private:
	mrpt::poses::CPosePDFGaussian m_pose;
};
}  // namespace featloc
