#include "featloc/sim/SimConfiguration.h"

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
	sc.world = SimWorld::fromConfig(cfg);
	return sc;
}

void SimConfiguration::saveSettings(mrpt::config::CConfigFileBase& cfg) const
{
	simulation.saveToConfigFile(cfg, SimulationOptions::kSection);
	robot.saveToConfigFile(cfg, RobotPathOptions::kSection);
	laser.saveToConfigFile(cfg, LaserOptions::kSection);
	odometry.saveToConfigFile(cfg, SimOdometryOptions::kSection);
	beacons.saveToConfigFile(cfg, BeaconSensorOptions::kSection);
}
}  // namespace featloc
