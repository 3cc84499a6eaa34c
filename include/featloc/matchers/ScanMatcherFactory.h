#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Creates scan matchers by their registered MRPT class name (the pattern of
 * mp2p_icp and MOLA): `[ScanMatcher] class = featloc::IcpMatcher`, with the
 * matcher's parameters in `[ScanMatcher.IcpMatcher]`. */
class ScanMatcherFactory
{
   public:
	/** Section holding the class name. */
	static constexpr const char* kSection = "ScanMatcher";
	/** Class used when the configuration names none. */
	static constexpr const char* kDefaultClass = "featloc::IcpMatcher";

	/** A new matcher of the given class, with default parameters. A name
	 * without namespace gets "featloc::". Throws ConfigError listing the
	 * known classes when the name is unknown. */
	static ScanMatcher::Ptr create(const std::string& className);

	/** Every registered class derived from ScanMatcher, sorted. */
	static std::vector<std::string> knownClassNames();

	/** "ScanMatcher.IcpMatcher" for "featloc::IcpMatcher". */
	static std::string paramsSection(const std::string& className);

	/** The matcher named by `[ScanMatcher] class`, with its parameters
	 * loaded. Every other `[ScanMatcher.X]` section in the configuration is
	 * loaded into a throw-away X as well, so that its keys are validated and
	 * counted as read (one ini can hold the settings of every matcher), and
	 * a section for a class that does not exist is an error. */
	static ScanMatcher::Ptr createFromConfig(
		const mrpt::config::CConfigFileBase& cfg);
};

}  // namespace featloc
