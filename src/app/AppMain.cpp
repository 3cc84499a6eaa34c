#include "featloc/app/AppMain.h"

#include <iostream>

#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/app/UsageError.h"

namespace featloc
{
int guardedMain(const char* appName, const std::function<int()>& body)
{
	try
	{
		return body();
	}
	catch (const UsageError& e)
	{
		std::cerr << appName << ": " << e.what() << "\n(see " << appName
				  << " --help)\n";
		return 2;
	}
	catch (const ConfigError& e)
	{
		std::cerr << appName << ": configuration error: " << e.what() << "\n";
		return 2;
	}
	catch (const InputError& e)
	{
		std::cerr << appName << ": input error: " << e.what() << "\n";
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << appName << ": error: " << e.what() << "\n";
		return 1;
	}
}
}  // namespace featloc

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace featloc
{
bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv, int& exitCode)
{
	if (cmd.parse(argc, argv)) return true;
	// MRPT's TCLAP returns false both for --help/--version and for errors.
	exitCode = 2;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		if (a == "-h" || a == "--help" || a == "--version") exitCode = 0;
	}
	return false;
}
}  // namespace featloc

namespace featloc
{
void writeReferenceConfig(
	const std::string& path, const std::string& header,
	const std::function<void(mrpt::config::CConfigFileBase&)>& save)
{
	mrpt::config::CConfigFileMemory mem;
	save(mem);
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
	f << header << mem.getContent();
	if (!f) throw std::runtime_error("error writing '" + path + "'");
	std::printf("wrote %s\n", path.c_str());
}
}  // namespace featloc
