#include "featloc/gui/RawlogRunner.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <stdlib.h>

#include <iostream>
#include <vector>

#include "featloc/app/RunApp.h"
#include "featloc/core/InputError.h"

namespace featloc
{
namespace
{
// featloc-run in this process with these arguments; its exit code.
int featlocRun(std::vector<std::string> args)
{
	// TCLAP remembers process-wide that an optional unlabeled argument was
	// declared (the viewer's INPUT) and would refuse featloc-run's own.
	TCLAP::OptionalUnlabeledTracker<>::alreadyOptional() = false;
	args.insert(args.begin(), "featloc-run");
	std::vector<char*> argv;
	for (auto& a : args) argv.push_back(a.data());
	return RunApp().main(static_cast<int>(argv.size()), argv.data());
}
}  // namespace

std::string RawlogRunner::run(const std::string& rawlog, const std::string& configIn)
{
	char tmpl[] = "/tmp/featloc-viewer-XXXXXX";
	if (!mkdtemp(tmpl)) throw InputError("cannot create a temporary folder in /tmp");
	const std::string dir = tmpl;
	std::string config = configIn;
	if (config.empty())
	{
		// The built-in defaults, which are config.ini's.
		config = dir + "/defaults.ini";
		if (featlocRun({"--write-config", config}) != 0)
			throw InputError("cannot write the default configuration to " + config);
	}
	std::cerr << "featloc-viewer: running featloc-run " << config << " " << rawlog << " into "
			  << dir << "/results\n";
	const int code = featlocRun({config, rawlog, "--out", dir + "/results", "-q"});
	if (code != 0)
		throw InputError("featloc-run failed on '" + rawlog + "' (exit code " +
			std::to_string(code) + "): see its messages on the console");
	return dir + "/results";
}
}  // namespace featloc
