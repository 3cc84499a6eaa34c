#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include "featloc/sim/BeaconSensorOptions.h"
#include "featloc/sim/LaserOptions.h"
#include "featloc/sim/RobotPathOptions.h"
#include "featloc/sim/SimOdometryOptions.h"
#include "featloc/sim/SimWorld.h"
#include "featloc/sim/SimulationOptions.h"
#include "featloc/sim/StereoCameraOptions.h"

namespace featloc
{
/** Everything a featloc-sim world file holds: the settings sections and
 * the world's walls, obstacles and people. */
struct SimConfiguration
{
	SimulationOptions simulation;
	RobotPathOptions robot;
	LaserOptions laser;
	SimOdometryOptions odometry;
	BeaconSensorOptions beacons;
	StereoCameraOptions stereo;
	SimWorld world;

	/** Throws ConfigError on a bad value (unknown keys are checked by the
	 * caller: TrackedConfig::requireAllKeysRead). */
	static SimConfiguration load(const mrpt::config::CConfigFileBase& cfg);

	/** Writes the settings sections with comments (not the world). */
	void saveSettings(mrpt::config::CConfigFileBase& cfg) const;
};
}  // namespace featloc
