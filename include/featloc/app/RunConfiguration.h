#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include "featloc/estimators/PoseEstimator.h"
#include "featloc/eval/EvaluationOptions.h"
#include "featloc/io/InputOptions.h"
#include "featloc/localization/LocalizationOptions.h"
#include "featloc/matchers/ScanMatcher.h"
#include "featloc/odometry/OdometryOptions.h"
#include "featloc/output/OutputOptions.h"
#include "featloc/pipeline/PipelineOptions.h"
#include "featloc/stereo/StereoLandmarkExtractor.h"

namespace featloc
{
class MapLocalizer;

/** Everything one featloc-run reads from its ini file: one option struct
 * per section, plus the scan matcher named in [ScanMatcher] with its
 * parameters. */
struct RunConfiguration
{
	InputOptions input;
	OdometryOptions odometry;
	PipelineOptions pipeline;
	OutputOptions output;
	EvaluationOptions evaluation;
	/** The estimator named by [Pipeline] estimator, its parameters loaded. */
	PoseEstimator::Ptr estimator;
	ScanMatcher::Ptr matcher;  //!< always created (keys are validated)
	/** [StereoLandmarks] class, its parameters loaded, handed to the
	 * estimator; null when the class is empty (the default). */
	std::shared_ptr<StereoLandmarkExtractor> stereo;
	LocalizationOptions localization;
	/** With [Localization] map: the map read and a matcher of
	 * [Localization] matcher_class (its parameters from its
	 * [ScanMatcher.<Class>] section) to match scans against it, searching
	 * first with `[Pipeline] initial_pose = global`; else null. */
	std::shared_ptr<MapLocalizer> mapLocalizer;

	/** Loads every section. Throws ConfigError on a bad value. (Unknown keys
	 * are checked by the caller: TrackedConfig::requireAllKeysRead.) */
	static RunConfiguration load(const mrpt::config::CConfigFileBase& cfg);

	/** The defaults of every section, with [ScanMatcher] class = the default
	 * matcher and a [ScanMatcher.X] section for every registered matcher. */
	static RunConfiguration defaults();

	/** Writes every section (and the parameters of every registered matcher
	 * class, at their defaults except the selected one) with comments. */
	void save(mrpt::config::CConfigFileBase& cfg) const;
};
}  // namespace featloc
