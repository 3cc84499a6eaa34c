#include "featloc/sim/SimConfiguration.h"

#include "featloc/sim/StereoRenderer.h"

namespace featloc
{
SimConfiguration SimConfiguration::load(const mrpt::config::CConfigFileBase& cfg)
{
	SimConfiguration sc;
	sc.simulation.loadFromConfigFile(cfg, SimulationOptions::kSection);
	sc.robot.loadFromConfigFile(cfg, RobotPathOptions::kSection);
	sc.laser.loadFromConfigFile(cfg, LaserOptions::kSection);
	sc.odometry.loadFromConfigFile(cfg, SimOdometryOptions::kSection);
	sc.beacons.loadFromConfigFile(cfg, BeaconSensorOptions::kSection);
	sc.stereo.loadFromConfigFile(cfg, StereoCameraOptions::kSection);
	sc.world = SimWorld::fromConfig(cfg);
	// Every surface the camera may see must be a material it can render
	// (the laser does not care: worlds without a camera may name anything).
	if (sc.stereo.enabled) StereoRenderer(sc.world, sc.stereo);
	return sc;
}

void SimConfiguration::saveSettings(mrpt::config::CConfigFileBase& cfg) const
{
	simulation.saveToConfigFile(cfg, SimulationOptions::kSection);
	robot.saveToConfigFile(cfg, RobotPathOptions::kSection);
	laser.saveToConfigFile(cfg, LaserOptions::kSection);
	odometry.saveToConfigFile(cfg, SimOdometryOptions::kSection);
	beacons.saveToConfigFile(cfg, BeaconSensorOptions::kSection);
	stereo.saveToConfigFile(cfg, StereoCameraOptions::kSection);
}
}  // namespace featloc
