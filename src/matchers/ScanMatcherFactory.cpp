#include "featloc/matchers/ScanMatcherFactory.h"

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

std::string joined(const std::vector<std::string>& v)
{
	std::string out;
	for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
	return out;
}

bool startsWithNoCase(const std::string& s, const std::string& prefix)
{
	if (s.size() < prefix.size()) return false;
	for (size_t i = 0; i < prefix.size(); i++)
		if (std::tolower(static_cast<unsigned char>(s[i])) !=
			std::tolower(static_cast<unsigned char>(prefix[i])))
			return false;
	return true;
}
}  // namespace

std::vector<std::string> ScanMatcherFactory::knownClassNames()
{
	registerClasses();
	std::vector<std::string> names;
	for (const auto* id :
		 mrpt::rtti::getAllRegisteredClassesChildrenOf(CLASS_ID(ScanMatcher)))
		if (id->ptrCreateObject) names.emplace_back(id->className);
	std::sort(names.begin(), names.end());
	return names;
}

ScanMatcher::Ptr ScanMatcherFactory::create(const std::string& className)
{
	registerClasses();
	const std::string name = qualified(className);
	const auto known = knownClassNames();
	if (std::find(known.begin(), known.end(), name) != known.end())
	{
		auto obj = mrpt::rtti::classFactory(name);
		if (auto m = std::dynamic_pointer_cast<ScanMatcher>(obj)) return m;
	}
	throw ConfigError(
		"unknown scan matcher class '" + className +
		"'; known classes: " + joined(known));
}

std::string ScanMatcherFactory::paramsSection(const std::string& className)
{
	const std::string name = qualified(className);
	const auto pos = name.rfind("::");
	return std::string(kSection) + "." + name.substr(pos + 2);
}

ScanMatcher::Ptr ScanMatcherFactory::createFromConfig(
	const mrpt::config::CConfigFileBase& cfg)
{
	std::string className = kDefaultClass;
	config::read(cfg, kSection, "class", className);
	ScanMatcher::Ptr matcher;
	try
	{
		matcher = create(className);
	}
	catch (const ConfigError& e)
	{
		config::fail(cfg, kSection, "class", e.what());
	}
	const std::string mySection = paramsSection(className);
	matcher->loadParams(cfg, mySection);

	// Validate the other matchers' sections too.
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	const std::string prefix = std::string(kSection) + ".";
	for (const auto& s : sections)
	{
		if (!startsWithNoCase(s, prefix) || s.size() == prefix.size()) continue;
		if (paramsSection(s.substr(prefix.size())) == mySection) continue;
		ScanMatcher::Ptr other;
		try
		{
			other = create(s.substr(prefix.size()));
		}
		catch (const ConfigError& e)
		{
			throw ConfigError(
				"section [" + s + "] names no scan matcher class: " + e.what());
		}
		other->loadParams(cfg, s);
	}
	return matcher;
}

}  // namespace featloc
