#pragma once
#include <functional>
#include <string>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace TCLAP
{
class CmdLine;
}

namespace featloc
{
/** Runs an app's body and turns exceptions into a message on stderr and an
 * exit code: 2 for configuration and command-line errors, 1 for input and
 * other errors. Apps catch only here. */
int guardedMain(const char* appName, const std::function<int()>& body);

/** Parses the command line with MRPT's TCLAP. Returns false when the
 * program must stop: `exitCode` is then 0 after --help/--version and 2
 * after a usage error (TCLAP has already printed the usage). */
bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv, int& exitCode);

/** The --write-config option of the apps: `save` fills a configuration
 * that is written to `path` after the '#' comment `header`. */
void writeReferenceConfig(
	const std::string& path, const std::string& header,
	const std::function<void(mrpt::config::CConfigFileBase&)>& save);
}  // namespace featloc
