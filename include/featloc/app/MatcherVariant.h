#pragma once
#include <string>
#include <utility>
#include <vector>

#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
class TrackedConfig;

/** One matcher of a featloc-bench run, written "[LABEL=]CLASS[{key=value;
 * ...}]": the class, its parameters from [ScanMatcher.<Class>] with the
 * overrides on top, and the label its table rows show (the class name when
 * none is given). Several variants of one class can run side by side, e.g.
 * "CF-IDC as published=featloc::CfIdcMatcher{pairing_gate=false;
 * segment_gate=0}". */
struct MatcherVariant
{
	std::string label;
	std::string className;
	std::vector<std::pair<std::string, std::string>> overrides;

	/** A comma-separated list (commas inside braces belong to the
	 * overrides). Throws UsageError on a malformed item. */
	static std::vector<MatcherVariant> parseList(const std::string& text);

	/** The matcher with its parameters: from `cfg` (keys marked read there),
	 * the overrides applied to a copy of the section; an override
	 * "ScanMatcher.<Other>:key=value" sets a key of another matcher's
	 * section, for the matcher's fallback_class. Throws ConfigError for an
	 * unknown class or an override key neither the class nor its fallback
	 * reads. */
	ScanMatcher::Ptr create(TrackedConfig& cfg) const;
};
}  // namespace featloc
