#pragma once
#include <string>

namespace featloc::test
{
/** Runs a shell command, capturing stdout and stderr together. */
struct CommandResult
{
	int exitCode = -1;
	std::string output;
};

CommandResult runCommand(const std::string& command);

/** Quotes an argument for /bin/sh. */
std::string shellQuote(const std::string& arg);
}  // namespace featloc::test
