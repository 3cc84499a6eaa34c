#pragma once
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <functional>
#include <string>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace featloc
{
class TrackedConfig;

/** The options every ini-driven app shares, added to its TCLAP command
 * line: -s/--set SECTION:KEY=VALUE (repeatable), --write-config FILE and
 * -q/--quiet. Included only by the apps' .cpp files (TCLAP is header-only). */
class ConfigCommandLine
{
   public:
	/** `setExample`: what --set's help shows as an example; `writtenConfig`:
	 * what --write-config writes ("" to leave --write-config out). */
	ConfigCommandLine(
		TCLAP::CmdLine& cmd, const std::string& setExample,
		const std::string& writtenConfig);

	/** Loads `path` into `cfg` and applies the --set overrides in order. */
	void load(TrackedConfig& cfg, const std::string& path);

	/** If --write-config was given: writes the configuration `save` fills,
	 * after the '#' comment `header`, and returns true (the app then exits). */
	bool writeConfigIfAsked(
		const std::string& header,
		const std::function<void(mrpt::config::CConfigFileBase&)>& save);

	bool quiet() { return m_quiet.getValue(); }

   private:
	TCLAP::MultiArg<std::string> m_set;
	TCLAP::ValueArg<std::string> m_writeConfig;
	TCLAP::SwitchArg m_quiet;
};
}  // namespace featloc
