#pragma once
#include <string>

#include "featloc/sim/RobotTrajectory.h"
#include "featloc/sim/SimWorld.h"

namespace featloc
{
/** The simulated world as an MRPT 3-D scene (opens in SceneViewer3D): walls
 * and polygonal obstacles as 1 m high panels coloured by texture name,
 * circular obstacles as cylinders, each person's route as a line with the
 * person at the start, the robot's true path in blue. */
class WorldSceneWriter
{
   public:
	/** Throws std::runtime_error if the file cannot be written. */
	static void write(
		const std::string& path, const SimWorld& world,
		const RobotTrajectory& trajectory);
};
}  // namespace featloc
