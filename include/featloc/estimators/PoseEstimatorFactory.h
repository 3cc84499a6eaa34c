#pragma once
#include <string>
#include <vector>

#include "featloc/ekf/EkfOptions.h"
#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** Creates the estimator named by `[Pipeline] estimator`. */
class PoseEstimatorFactory
{
   public:
	/** Throws ConfigError listing the known names for an unknown one.
	 * `ekf`: the [Ekf] options of estimator = ekf. */
	static PoseEstimator::Ptr create(const std::string& name, const EkfOptions& ekf = {});
	static std::vector<std::string> knownNames();
};
}  // namespace featloc
