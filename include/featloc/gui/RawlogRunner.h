#pragma once
#include <string>

namespace featloc
{
/** How featloc-viewer opens a plain rawlog: featloc-run (in this process)
 * with a configuration, or the built-in defaults (config.ini's), into a
 * fresh folder under /tmp/featloc-viewer-XXXXXX; the results folder is
 * opened from there. */
class RawlogRunner
{
   public:
	/** Returns the results folder. Throws InputError when featloc-run
	 * fails (its own messages are on stderr). */
	static std::string run(const std::string& rawlog, const std::string& config);
};
}  // namespace featloc
