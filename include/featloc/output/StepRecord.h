#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <string>
#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/estimators/EstimationStep.h"

namespace featloc
{
struct StereoStepResult;

/** What the pipeline produced for one step, handed to every output. */
struct StepRecord
{
	const EstimationStep& step;
	/** Estimated global robot pose at the step's time, with covariance. */
	const mrpt::poses::CPosePDFGaussian& pose;
	/** The scan matcher's result for this step, or nullptr (first scan, a
	 * step without scan, or an estimator without matcher). */
	const MatchResult* match = nullptr;
	/** The estimator used the match (false: odometry or first scan). */
	bool usedMatch = false;
	/** The estimator's point landmarks after this step (empty for all but
	 * the EKF). */
	const std::vector<EstimatedLandmark>* landmarks = nullptr;
	/** What the stereo landmark extractor and the EKF made of this step's
	 * stereo pair, or nullptr. */
	const StereoStepResult* stereo = nullptr;
	/** Why the estimator did not use a match it was given (its gate), or
	 * empty. */
	std::string fallbackReason;
	/** The scan became the reference of the next matches (a keyframe). */
	bool keyframe = false;
	/** Localization in a known map: this scan matched against the map
	 * (its estimate is the correction of the predicted pose, robot
	 * frame), or nullptr; whether the estimator used it, and why not. */
	const MatchResult* mapMatch = nullptr;
	bool usedMapMatch = false;
	std::string mapReason;
};
}  // namespace featloc
