#include "featloc/stereo/StereoLandmarkExtractorFactory.h"

#include <mrpt/rtti/CObject.h>

#include <algorithm>

#include "featloc/config/ConfigValues.h"
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

std::vector<std::string> StereoLandmarkExtractorFactory::knownClassNames()
{
	registerClasses();
	std::vector<std::string> names;
	for (const auto* id : mrpt::rtti::getAllRegisteredClassesChildrenOf(CLASS_ID(StereoLandmarkExtractor)))
		if (id->ptrCreateObject) names.emplace_back(id->className);
	std::sort(names.begin(), names.end());
	return names;
}

std::shared_ptr<StereoLandmarkExtractor> StereoLandmarkExtractorFactory::create(const std::string& className)
{
	registerClasses();
	const std::string name = qualified(className);
	const auto known = knownClassNames();
	if (std::find(known.begin(), known.end(), name) != known.end())
		if (auto e = std::dynamic_pointer_cast<StereoLandmarkExtractor>(mrpt::rtti::classFactory(name)))
			return e;
	std::string list;
	for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
	throw ConfigError("unknown stereo landmark extractor class '" + className + "'; known classes: " + list);
}

std::string StereoLandmarkExtractorFactory::paramsSection(const std::string& className)
{
	const std::string name = qualified(className);
	return std::string(kSection) + "." + name.substr(name.rfind("::") + 2);
}

std::shared_ptr<StereoLandmarkExtractor> StereoLandmarkExtractorFactory::createFromConfig(
	const mrpt::config::CConfigFileBase& cfg)
{
	std::string className;
	config::read(cfg, kSection, "class", className);
	std::shared_ptr<StereoLandmarkExtractor> selected;
	std::string mySection;
	if (!className.empty())
	{
		try
		{
			selected = create(className);
		}
		catch (const ConfigError& e)
		{
			config::fail(cfg, kSection, "class", e.what());
		}
		mySection = paramsSection(className);
		selected->loadParams(cfg, mySection);
		selected->requireComplete(cfg, mySection);
	}
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	const std::string prefix = std::string(kSection) + ".";
	for (const auto& s : sections)
	{
		if (s.rfind(prefix, 0) != 0 || s.size() == prefix.size() || s == mySection) continue;
		std::shared_ptr<StereoLandmarkExtractor> other;
		try
		{
			other = create(s.substr(prefix.size()));
		}
		catch (const ConfigError& e)
		{
			throw ConfigError("section [" + s + "] names no stereo landmark extractor class: " + e.what());
		}
		other->loadParams(cfg, s);
	}
	return selected;
}
}  // namespace featloc
