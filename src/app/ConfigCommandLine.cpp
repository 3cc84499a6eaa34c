#include "featloc/app/ConfigCommandLine.h"

#include "featloc/app/AppMain.h"
#include "featloc/config/TrackedConfig.h"

namespace featloc
{
ConfigCommandLine::ConfigCommandLine(
	TCLAP::CmdLine& cmd, const std::string& setExample, const std::string& writtenConfig)
	: m_set("s", "set", "Override one ini key, e.g. --set " + setExample + " (repeatable)",
		  false, "SECTION:KEY=VALUE"),
	  m_writeConfig("", "write-config", "Write " + writtenConfig + " to FILE and exit", false,
		  "", "FILE"),
	  m_quiet("q", "quiet", "No progress bar")
{
	cmd.add(m_set);
	if (!writtenConfig.empty()) cmd.add(m_writeConfig);
	cmd.add(m_quiet);
}

void ConfigCommandLine::load(TrackedConfig& cfg, const std::string& path)
{
	cfg.loadFile(path);
	for (const auto& spec : m_set.getValue()) cfg.applyOverride(spec);
}

bool ConfigCommandLine::writeConfigIfAsked(
	const std::string& header,
	const std::function<void(mrpt::config::CConfigFileBase&)>& save)
{
	if (!m_writeConfig.isSet()) return false;
	writeReferenceConfig(m_writeConfig.getValue(), header, save);
	return true;
}
}  // namespace featloc
