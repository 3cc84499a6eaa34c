#include "featloc/app/MatcherVariant.h"

#include <mrpt/system/string_utils.h>

#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/matchers/ScanMatcherFactory.h"

namespace featloc
{
std::vector<MatcherVariant> MatcherVariant::parseList(const std::string& text)
{
	// Split at the commas outside braces.
	std::vector<std::string> items(1);
	int depth = 0;
	for (char ch : text)
	{
		if (ch == '{') depth++;
		if (ch == '}') depth--;
		if (depth < 0) throw UsageError("matcher list '" + text + "': unbalanced '}'");
		if (ch == ',' && depth == 0)
			items.emplace_back();
		else
			items.back() += ch;
	}
	if (depth != 0) throw UsageError("matcher list '" + text + "': unbalanced '{'");

	std::vector<MatcherVariant> out;
	for (std::string item : items)
	{
		item = mrpt::system::trim(item);
		if (item.empty()) throw UsageError("matcher list '" + text + "' has an empty item");
		MatcherVariant v;
		std::string body = item;
		const auto brace = item.find('{');
		const auto eq = item.find('=');
		if (eq != std::string::npos && (brace == std::string::npos || eq < brace))
		{
			v.label = mrpt::system::trim(item.substr(0, eq));
			body = mrpt::system::trim(item.substr(eq + 1));
		}
		const auto open = body.find('{');
		v.className = mrpt::system::trim(body.substr(0, open));
		if (open != std::string::npos)
		{
			if (body.back() != '}')
				throw UsageError("matcher '" + item + "': text after the closing '}'");
			std::vector<std::string> pairs;
			mrpt::system::tokenize(body.substr(open + 1, body.size() - open - 2), ";", pairs);
			for (const auto& p : pairs)
			{
				const auto e = p.find('=');
				if (e == std::string::npos)
					throw UsageError("matcher '" + item + "': override '" + p +
						"' is not key=value");
				v.overrides.emplace_back(
					mrpt::system::trim(p.substr(0, e)), mrpt::system::trim(p.substr(e + 1)));
			}
		}
		if (v.className.empty()) throw UsageError("matcher '" + item + "' names no class");
		if (v.label.empty()) v.label = v.className;
		out.push_back(std::move(v));
	}
	return out;
}

ScanMatcher::Ptr MatcherVariant::create(TrackedConfig& cfg) const
{
	auto m = ScanMatcherFactory::create(className);
	const std::string section = ScanMatcherFactory::paramsSection(className);
	if (overrides.empty())
	{
		m->loadParams(cfg, section);
		return m;
	}
	// The section as the ini has it, the overrides on top, in a config of its
	// own: a key the class does not read is reported as for --set. The other
	// matchers' sections come along for a fallback_class to read.
	TrackedConfig own;
	std::string text;
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& sec : sections)
	{
		if (sec.rfind(std::string(ScanMatcherFactory::kSection) + ".", 0) != 0) continue;
		text += "[" + sec + "]\n";
		std::vector<std::string> keys;
		cfg.getAllKeys(sec, keys);
		for (const auto& k : keys) text += k + " = " + cfg.read_string(sec, k, "") + "\n";
	}
	if (text.find("[" + section + "]\n") == std::string::npos) text += "[" + section + "]\n";
	own.loadText(text, cfg.sourceName());
	// "SECTION:key" sets a key of another matcher's section, the one its
	// fallback_class reads (e.g. CF-IDC's IDC fallback): a variant of a
	// matcher with a fallback is then one configuration, whatever the ini
	// has in that section.
	std::vector<std::pair<std::string, std::string>> elsewhere;
	for (const auto& [k, value] : overrides)
	{
		const auto colon = k.find(':');
		if (colon == std::string::npos)
		{
			own.applyOverride(section + ":" + k + "=" + value);
			continue;
		}
		const std::string sec = k.substr(0, colon);
		if (sec.rfind(std::string(ScanMatcherFactory::kSection) + ".", 0) != 0)
			throw UsageError("matcher '" + label + "': override '" + k +
				"' names a section that is not a matcher's ([" + ScanMatcherFactory::kSection +
				".<Class>])");
		own.applyOverride(k + "=" + value);
		elsewhere.emplace_back(sec, k.substr(colon + 1));
	}
	m->loadParams(own, section);
	// An override of another section that neither the matcher nor its
	// fallback read is as much an error as one of its own.
	const auto unread = own.unreadKeys();
	for (const auto& [sec, key] : elsewhere)
		for (const auto& [us, uk] : unread)
			if (mrpt::system::lowerCase(us) == mrpt::system::lowerCase(sec) &&
				mrpt::system::lowerCase(uk) == mrpt::system::lowerCase(key))
				throw ConfigError("matcher '" + label + "': override [" + sec + "] " + key +
					" is read neither by " + className + " nor by its fallback");
	for (const auto& sec : sections)
		if (sec != section) own.acceptSection(sec);
	own.requireAllKeysRead();
	return m;
}
}  // namespace featloc
