#include "CommandRunner.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <stdexcept>

namespace featloc::test
{
CommandResult runCommand(const std::string& command)
{
	CommandResult r;
	// A command that hangs is killed (exit code 124 or 137), so the test
	// fails with its output instead of stalling until ctest's timeout.
	const std::string bounded = "timeout -k 10 " + std::to_string(kCommandTimeoutSeconds) +
		" sh -c " + shellQuote(command + " 2>&1");
	FILE* pipe = popen(bounded.c_str(), "r");
	if (!pipe) throw std::runtime_error("popen failed: " + command);
	std::array<char, 4096> buf{};
	size_t n = 0;
	while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0)
		r.output.append(buf.data(), n);
	const int status = pclose(pipe);
	r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	if (r.exitCode == 124 || r.exitCode == 137)
		r.output += "\n[timed out after " + std::to_string(kCommandTimeoutSeconds) + " s: " +
			command + "]\n";
	return r;
}

std::string shellQuote(const std::string& arg)
{
	std::string q = "'";
	for (char c : arg)
		q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}
}  // namespace featloc::test
