#pragma once
#include <string>
#include <vector>

#include "featloc/eval/Trajectory.h"

namespace featloc::test
{
/** A featloc-sim log of worlds/lab.ini's loop around the lab
 * (2 2 -> 12 2 -> 12 3.8 -> 9.5 3.8 -> 9.5 8.5 -> 2 8.5 -> 2 2; clear of
 * the obstacles: the loop through 12 5 drove through the slanted box and
 * took 18 scans from inside it) with `seed`,
 * config overrides ("Section:key=value") on top, written into `folder`. */
struct LabLoopLog
{
	std::string rawlog;
	Trajectory groundTruth;

	static LabLoopLog simulate(
		const std::string& folder, int seed, const std::vector<std::string>& overrides = {});
};
}  // namespace featloc::test
