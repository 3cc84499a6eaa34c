#include "support/LabLoopLog.h"

#include "featloc/config/TrackedConfig.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/Simulator.h"

namespace featloc::test
{
LabLoopLog LabLoopLog::simulate(
	const std::string& folder, int seed, const std::vector<std::string>& overrides)
{
	TrackedConfig c;
	c.loadFile(std::string(FEATLOC_SOURCE_DIR) + "/worlds/lab.ini");
	c.applyOverride("Robot:path=waypoints");
	c.applyOverride("Robot:waypoints=[2 2; 12 2; 12 3.8; 9.5 3.8; 9.5 8.5; 2 8.5; 2 2]");
	c.applyOverride("Simulation:seed=" + std::to_string(seed));
	for (const auto& o : overrides) c.applyOverride(o);
	auto sc = SimConfiguration::load(c);
	Simulator sim(sc.world, sc.robot, sc.laser, sc.odometry, sc.simulation);
	LabLoopLog log;
	log.rawlog = folder + "/l.rawlog";
	const std::string gtFile = folder + "/l.gt.txt";
	sim.run(log.rawlog, gtFile);
	log.groundTruth = TrajectoryFile::read(gtFile);
	return log;
}
}  // namespace featloc::test
