#pragma once
#include <string>
#include <vector>

#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** Creates the estimator named by `[Pipeline] estimator`. */
class PoseEstimatorFactory
{
   public:
	/** Throws ConfigError listing the known names for an unknown one. */
	static PoseEstimator::Ptr create(const std::string& name);
	static std::vector<std::string> knownNames();
};
}  // namespace featloc
