#pragma once
#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** Chains scan-matcher motions: x_k = x_key (+) z_k, where z_k is the
 * matcher's motion from the reference (keyframe) scan to scan k, which used
 * the odometry as its initial guess; when the match fails, x_k = x_{k-1}
 * (+) u_k with the odometry increment u_k. With every scan a keyframe (the
 * default) this is the chain of scan-to-previous-scan increments.
 * Covariances compose the same way (SE(2) Jacobians). */
class MatcherChainEstimator : public PoseEstimator
{
	DEFINE_MRPT_OBJECT(MatcherChainEstimator, featloc)

   public:
	std::string name() const override { return "matcher"; }
	bool usesScanMatcher() const override { return true; }
	void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) override;
	bool process(const EstimationStep& step, const MatchResult* match) override;
	void markKeyframe() override { m_keyframePose = m_pose; }
	const mrpt::poses::CPosePDFGaussian& pose() const override { return m_pose; }

   private:
	mrpt::poses::CPosePDFGaussian m_pose;
	mrpt::poses::CPosePDFGaussian m_keyframePose;
};
}  // namespace featloc
