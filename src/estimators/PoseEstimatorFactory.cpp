#include "featloc/estimators/PoseEstimatorFactory.h"

#include "featloc/core/ConfigError.h"
#include "featloc/estimators/EkfEstimator.h"
#include "featloc/estimators/MatcherChainEstimator.h"
#include "featloc/estimators/OdometryEstimator.h"

namespace featloc
{
std::vector<std::string> PoseEstimatorFactory::knownNames()
{
	return {"ekf", "matcher", "odometry"};
}

PoseEstimator::Ptr PoseEstimatorFactory::create(const std::string& name, const EkfOptions& ekf)
{
	if (name == "odometry") return std::make_unique<OdometryEstimator>();
	if (name == "matcher") return std::make_unique<MatcherChainEstimator>();
	if (name == "ekf") return std::make_unique<EkfEstimator>(ekf);
	std::string known;
	for (const auto& n : knownNames()) known += (known.empty() ? "" : ", ") + n;
	throw ConfigError("unknown estimator '" + name + "'; known: " + known);
}
}  // namespace featloc
