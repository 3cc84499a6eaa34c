#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <utility>
#include <vector>

#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** Creates estimators by their registered MRPT class name, as
 * ScanMatcherFactory does for matchers: `[Pipeline] estimator =
 * featloc::EkfEstimator`, or one of the short aliases (odometry, matcher,
 * ekf). Each estimator reads its own section (EkfEstimator: [Ekf]). */
class PoseEstimatorFactory
{
   public:
	/** A new estimator of the given class or alias, with default
	 * parameters. A class name without namespace gets "featloc::". Throws
	 * ConfigError listing the aliases and classes for an unknown name. */
	static PoseEstimator::Ptr create(const std::string& nameOrClass);
	/** Every registered class derived from PoseEstimator, sorted. */
	static std::vector<std::string> knownClassNames();
	/** (alias, class name) pairs, in the order the help lists them. */
	static const std::vector<std::pair<std::string, std::string>>& aliases();
	/** The estimator named `nameOrClass` with its parameters loaded; the
	 * parameter sections of the other estimator classes present in `cfg`
	 * are loaded into throw-away instances, so that their keys are validated
	 * and counted as read (one ini can hold every estimator's settings). */
	static PoseEstimator::Ptr createFromConfig(
		const mrpt::config::CConfigFileBase& cfg, const std::string& nameOrClass);
};
}  // namespace featloc
