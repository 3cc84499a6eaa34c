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

/** Commands run longer than this are killed (timeout(1)). */
constexpr int kCommandTimeoutSeconds = 300;

/** Runs `command` through /bin/sh under timeout(1); a killed command
 * returns 124 (or 137) and says so at the end of its output. */
CommandResult runCommand(const std::string& command);

/** Quotes an argument for /bin/sh. */
std::string shellQuote(const std::string& arg);
}  // namespace featloc::test
