#pragma once
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

#include "featloc/eval/Trajectory.h"

namespace featloc
{
/** A PNG picture of a reference trajectory and an estimate (after the
 * evaluation's alignment) on a metric grid, with a legend and a title. An
 * empty reference draws the estimate alone (a run without ground truth).
 * A known map's occupied cells, if given, are drawn under both (grey). */
class TrajectoryPlot
{
   public:
	/** Throws std::runtime_error if the file cannot be written. */
	static void write(
		const std::string& pngPath, const Trajectory& reference,
		const Trajectory& estimate, const mrpt::math::TPose2D& alignment,
		const std::string& title, const std::vector<mrpt::math::TPoint2D>& map = {});
};
}  // namespace featloc
