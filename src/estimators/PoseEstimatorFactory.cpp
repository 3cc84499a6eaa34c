#include "featloc/estimators/PoseEstimatorFactory.h"

#include "featloc/core/ConfigError.h"
#include "featloc/estimators/MatcherChainEstimator.h"
#include "featloc/estimators/OdometryEstimator.h"

namespace featloc
{
std::vector<std::string> PoseEstimatorFactory::knownNames()
{
	return {"matcher", "odometry"};
}

PoseEstimator::Ptr PoseEstimatorFactory::create(const std::string& name)
{
	if (name == "odometry") return std::make_unique<OdometryEstimator>();
	if (name == "matcher") return std::make_unique<MatcherChainEstimator>();
	std::string known;
	for (const auto& n : knownNames()) known += (known.empty() ? "" : ", ") + n;
	throw ConfigError("unknown estimator '" + name + "'; known: " + known);
}
}  // namespace featloc
