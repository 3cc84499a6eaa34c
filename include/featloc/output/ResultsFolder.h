#pragma once
#include <string>
#include <vector>

namespace featloc
{
/** The results folder of a run, written through a staging folder so that
 * no run ever mixes its files with an earlier run's, and a run that fails
 * to start leaves the earlier results as they were.
 *
 * The constructor checks the folder before anything is written: it must
 * not exist yet, be empty, or hold an earlier featloc run (a summary.json);
 * any other folder is refused, since publishing replaces all of it. The
 * files of the run go to a staging folder beside it
 * (`DIR.featloc-partial-PID`); publish() swaps that in place of DIR at the
 * end of the run (finished, failed part-way, or interrupted), and a run
 * abandoned before it started removes its staging folder. A run killed
 * outright (SIGKILL) leaves DIR as it was and its partial files in the
 * staging folder: every file there whole (rows are written a line at a
 * time, files written at the end appear whole through writeWholeFile) and
 * estimated.rawlog readable up to its last whole entry. The next run into
 * DIR finds such folders (abandoned()) and says so; it does not delete
 * them. */
class ResultsFolder
{
   public:
	/** Throws ConfigError when `dir` cannot take the results, naming it and
	 * why (not a folder, a folder of other files, not writable). */
	explicit ResultsFolder(const std::string& dir);
	~ResultsFolder();
	ResultsFolder(const ResultsFolder&) = delete;
	ResultsFolder& operator=(const ResultsFolder&) = delete;

	/** Throws ConfigError if `path` (an input of the run) lies inside the
	 * results folder, which publish() replaces. `what`: "rawlog", ... */
	void requireOutside(const std::string& path, const std::string& what) const;

	/** Where the run writes `name` now (in the staging folder). */
	std::string stagedFile(const std::string& name) const;
	/** Where `name` will be once published. */
	std::string finalFile(const std::string& name) const;

	/** Replaces the results folder with the staging folder. Idempotent. */
	void publish();

	const std::string& dir() const { return m_dir; }

	/** Staging folders beside DIR left by runs killed before they
	 * published (their process is gone), found when this one was made. */
	const std::vector<std::string>& abandoned() const { return m_abandoned; }

   private:
	/** publish() where the file system cannot exchange two folders
	 * atomically: DIR aside, the staging folder in, the old one deleted. */
	void replaceInTwoSteps();

	std::string m_dir, m_staging;
	std::vector<std::string> m_abandoned;
	bool m_published = false;
};
}  // namespace featloc
