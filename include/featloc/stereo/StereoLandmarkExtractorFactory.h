#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>
#include <vector>

#include "featloc/stereo/StereoLandmarkExtractor.h"

namespace featloc
{
/** Creates stereo landmark extractors by registered class name, like the
 * scan matchers: `[StereoLandmarks] class = featloc::StableVerticalLandmarks`
 * with the parameters in `[StereoLandmarks.StableVerticalLandmarks]`. An
 * empty class (the default) means no stereo landmarks: stereo pairs in the
 * log are checked and passed through to the outputs only. */
class StereoLandmarkExtractorFactory
{
   public:
	static constexpr const char* kSection = "StereoLandmarks";

	/** Throws ConfigError listing the known classes for an unknown name. */
	static std::shared_ptr<StereoLandmarkExtractor> create(const std::string& className);
	static std::vector<std::string> knownClassNames();
	/** "StereoLandmarks.StableVerticalLandmarks" for its class. */
	static std::string paramsSection(const std::string& className);

	/** The extractor named by `[StereoLandmarks] class` with its parameters
	 * loaded, or null when the key is empty or absent. Every other
	 * `[StereoLandmarks.X]` section is loaded into a throw-away X (its keys
	 * validated, one ini may hold several). */
	static std::shared_ptr<StereoLandmarkExtractor> createFromConfig(const mrpt::config::CConfigFileBase& cfg);
};
}  // namespace featloc
