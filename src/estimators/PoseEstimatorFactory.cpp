#include "featloc/estimators/PoseEstimatorFactory.h"

#include <algorithm>

#include "featloc/core/ConfigError.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
std::string qualified(const std::string& name)
{
	return name.find("::") == std::string::npos ? "featloc::" + name : name;
}
}  // namespace

const std::vector<std::pair<std::string, std::string>>& PoseEstimatorFactory::aliases()
{
	static const std::vector<std::pair<std::string, std::string>> a{
		{"odometry", "featloc::OdometryEstimator"},
		{"matcher", "featloc::MatcherChainEstimator"},
		{"ekf", "featloc::EkfEstimator"}};
	return a;
}

std::vector<std::string> PoseEstimatorFactory::knownClassNames()
{
	registerClasses();
	std::vector<std::string> names;
	for (const auto* id : mrpt::rtti::getAllRegisteredClassesChildrenOf(CLASS_ID(PoseEstimator)))
		if (id->ptrCreateObject) names.emplace_back(id->className);
	std::sort(names.begin(), names.end());
	return names;
}

PoseEstimator::Ptr PoseEstimatorFactory::create(const std::string& nameOrClass)
{
	registerClasses();
	std::string name = qualified(nameOrClass);
	for (const auto& [alias, cls] : aliases())
		if (nameOrClass == alias) name = cls;
	const auto known = knownClassNames();
	if (std::find(known.begin(), known.end(), name) != known.end())
		if (auto e = std::dynamic_pointer_cast<PoseEstimator>(mrpt::rtti::classFactory(name)))
			return e;
	std::string list;
	for (const auto& [alias, cls] : aliases()) list += (list.empty() ? "" : ", ") + alias;
	for (const auto& cls : known) list += ", " + cls;
	throw ConfigError("unknown estimator '" + nameOrClass + "'; known: " + list);
}

PoseEstimator::Ptr PoseEstimatorFactory::createFromConfig(
	const mrpt::config::CConfigFileBase& cfg, const std::string& nameOrClass)
{
	PoseEstimator::Ptr estimator = create(nameOrClass);
	estimator->loadParams(cfg);
	for (const auto& cls : knownClassNames())
	{
		if (cls == estimator->className()) continue;
		const PoseEstimator::Ptr other = create(cls);
		if (!other->paramsSection().empty() && cfg.sectionExists(other->paramsSection()))
			other->loadParams(cfg);
	}
	return estimator;
}
}  // namespace featloc
