#include "featloc/output/ResultsFolder.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "featloc/core/ConfigError.h"

namespace featloc
{
namespace fs = std::filesystem;

namespace
{
/** A folder featloc may replace: empty, or the results of an earlier run. */
bool replaceable(const fs::path& dir)
{
	std::error_code ec;
	if (fs::is_empty(dir, ec) && !ec) return true;
	return fs::is_regular_file(dir / "summary.json", ec);
}

/** The staging folders beside `d` of runs that are no longer running:
 * killed before they could publish (SIGKILL, power loss). */
std::vector<std::string> abandonedStagingFolders(const fs::path& d)
{
	std::vector<std::string> found;
	const std::string prefix = d.filename().string() + ".featloc-partial-";
	std::error_code ec;
	for (fs::directory_iterator it(d.parent_path(), ec), end; !ec && it != end; it.increment(ec))
	{
		const std::string name = it->path().filename().string();
		if (name.rfind(prefix, 0) != 0) continue;
		char* rest = nullptr;
		const long pid = std::strtol(name.c_str() + prefix.size(), &rest, 10);
		if (pid <= 0 || *rest != '\0') continue;
		if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;	// still running
		found.push_back(it->path().string());
	}
	std::sort(found.begin(), found.end());
	return found;
}

/** Absolute, normalised, without a trailing separator. */
fs::path canonicalName(const std::string& p)
{
	fs::path a = fs::absolute(p).lexically_normal();
	if (a.filename().empty()) a = a.parent_path();
	return a;
}
}  // namespace

ResultsFolder::ResultsFolder(const std::string& dir)
{
	if (dir.empty()) throw ConfigError("no results folder: set [Output] dir or give --out DIR");
	const fs::path d = canonicalName(dir);
	m_dir = d.string();
	std::error_code ec;
	if (fs::exists(d, ec))
	{
		if (!fs::is_directory(d, ec))
			throw ConfigError("results folder '" + dir + "' exists and is not a folder");
		if (!replaceable(d))
			throw ConfigError(
				"results folder '" + dir +
				"' holds other files and no featloc results (summary.json); a run "
				"replaces the whole folder: give an empty or new folder with --out DIR");
	}
	fs::create_directories(d.parent_path(), ec);
	m_abandoned = abandonedStagingFolders(d);
	m_staging = (d.parent_path() /
		(d.filename().string() + ".featloc-partial-" + std::to_string(::getpid())))
					.string();
	fs::remove_all(m_staging, ec);
	if (!fs::create_directory(m_staging, ec) || ec)
		throw ConfigError(
			"results folder '" + dir + "': cannot write beside it ('" + m_staging +
			"'): " + (ec ? ec.message() : std::string("unknown error")));
	if (::access(m_staging.c_str(), W_OK) != 0)
		throw ConfigError("results folder '" + dir + "': '" + m_staging + "' is not writable");
}

ResultsFolder::~ResultsFolder()
{
	if (m_published) return;
	std::error_code ec;
	fs::remove_all(m_staging, ec);	// a run that never started: nothing to keep
}

void ResultsFolder::requireOutside(const std::string& path, const std::string& what) const
{
	const fs::path p = canonicalName(path);
	const fs::path d(m_dir);
	auto pi = p.begin();
	for (auto di = d.begin(); di != d.end(); ++di, ++pi)
		if (pi == p.end() || *pi != *di) return;
	throw ConfigError(
		"the " + what + " '" + path + "' is inside the results folder '" + m_dir +
		"', which the run replaces: choose another --out DIR");
}

std::string ResultsFolder::stagedFile(const std::string& name) const
{
	return (fs::path(m_staging) / name).string();
}

std::string ResultsFolder::finalFile(const std::string& name) const
{
	return (fs::path(m_dir) / name).string();
}

void ResultsFolder::publish()
{
	if (m_published) return;
	const fs::path d(m_dir);
	std::error_code ec;
	if (fs::exists(d, ec))
	{
		// One atomic exchange: at every instant DIR holds either the old
		// results or the new ones, even if the process is killed here.
		// The staging name then holds the old results, removed after.
		if (::renameat2(AT_FDCWD, m_staging.c_str(), AT_FDCWD, m_dir.c_str(), RENAME_EXCHANGE) == 0)
			fs::remove_all(m_staging, ec);
		else if (errno == EINVAL || errno == ENOSYS)
			replaceInTwoSteps();  // a file system without the exchange
		else
			throw std::runtime_error(
				"cannot replace the results folder '" + m_dir + "' (" +
				std::error_code(errno, std::generic_category()).message() +
				"); this run's results are in '" + m_staging + "'");
	}
	else
	{
		fs::rename(m_staging, d, ec);
		if (ec)
			throw std::runtime_error(
				"cannot move the results into '" + m_dir + "' (" + ec.message() +
				"); they are in '" + m_staging + "'");
	}
	m_published = true;
}

void ResultsFolder::replaceInTwoSteps()
{
	// Rename first, delete after: the old results are never half gone (a
	// kill between the two renames leaves them in DIR.featloc-old-PID).
	const fs::path d(m_dir);
	const fs::path old =
		d.parent_path() / (d.filename().string() + ".featloc-old-" + std::to_string(::getpid()));
	std::error_code ec;
	fs::remove_all(old, ec);
	fs::rename(d, old, ec);
	if (ec)
		throw std::runtime_error("cannot replace the results folder '" + m_dir + "' (" +
			ec.message() + "); this run's results are in '" + m_staging + "'");
	fs::rename(m_staging, d, ec);
	if (ec)
	{
		std::error_code back;
		fs::rename(old, d, back);
		throw std::runtime_error("cannot move the results into '" + m_dir + "' (" + ec.message() +
			"); this run's results are in '" + m_staging + "'");
	}
	fs::remove_all(old, ec);
}
}  // namespace featloc
