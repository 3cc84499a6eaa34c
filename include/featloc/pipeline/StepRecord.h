#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/pipeline/ScanStep.h"

namespace featloc
{
/** What the pipeline produced for one scan, handed to every output. */
struct StepRecord
{
	const ScanStep& step;
	/** Estimated global robot pose at the scan's time, with covariance. */
	const mrpt::poses::CPosePDFGaussian& pose;
	/** The scan matcher's result for this step, or nullptr (first scan, or
	 * an estimator without matcher). */
	const MatchResult* match = nullptr;
	/** The estimator used the match (false: odometry or first scan). */
	bool usedMatch = false;
	/** The estimator's point landmarks after this step (empty for all but
	 * the EKF). */
	const std::vector<EstimatedLandmark>* landmarks = nullptr;
};
}  // namespace featloc
