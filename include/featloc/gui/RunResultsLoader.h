#pragma once
#include <functional>
#include <string>

#include "featloc/gui/RunResults.h"

namespace featloc
{
/** Reads a featloc-run results folder for the viewer: poses_cov.txt (the
 * steps; required), estimated.rawlog (the scans), matches.txt,
 * nees.txt, landmarks.txt, summary.json, config_used.ini and the ground
 * truth it names. A missing or damaged optional file is recorded in
 * RunResults::problems and the rest is read; a folder without a readable
 * poses_cov.txt throws InputError naming it. */
class RunResultsLoader
{
   public:
	/** progress(fraction in [0, 1]) is called while estimated.rawlog is
	 * read. */
	static RunResults load(
		const std::string& folder, const std::function<void(double)>& progress = {});
};
}  // namespace featloc
