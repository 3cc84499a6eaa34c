#pragma once
#include <string>

#include "featloc/sim/RobotTrajectory.h"
#include "featloc/sim/SimWorld.h"

namespace featloc
{
/** A PNG top view of a simulated world: walls and obstacles, each person's
 * route (start marked), the robot's true path (start marked). featloc-sim
 * writes it next to the rawlog. */
class WorldPlot
{
   public:
	static void write(
		const std::string& pngPath, const SimWorld& world,
		const RobotTrajectory& trajectory, const std::string& title);
};
}  // namespace featloc
