#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>


#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/sim/SimConfiguration.h"
#include "support/DocumentedKeys.h"
#include "support/ErrorMessage.h"

using namespace featloc;
using featloc::test::errorMessageOf;

namespace
{
const std::string kWall = "[Wall.w]\npolyline = [0 0; 5 0; 5 5]\n";

std::string savedSettings(const SimConfiguration& sc)
{
	mrpt::config::CConfigFileMemory mem;
	sc.saveSettings(mem);
	return mem.getContent();
}
}  // namespace

TEST(SimConfiguration, SettingsRoundTrip)
{
	SimConfiguration sc;
	sc.simulation.seed = 77;
	sc.simulation.format = 2;
	sc.robot.path = "explore";
	sc.robot.waypoints = {{1, 2, 0.3}, {4, 5, 0.6}};
	sc.robot.initial_yaw = "45";
	sc.laser.applyPreset("hokuyo_utm30lx");
	sc.laser.range_noise = 0.02;
	sc.laser.sensor_pose = {0.1, -0.05, 0.2};
	sc.odometry.mode = "perturbed_pairs";
	sc.odometry.model = "thrun";
	sc.odometry.thrun_alpha2_rot_trans = 0.1;
	sc.odometry.thrun_alpha4_trans_rot = 0.02;
	sc.odometry.perturbation_yaw = 0.15;
	const std::string text = savedSettings(sc);

	TrackedConfig c;
	c.loadText(text + kWall, "s.ini");
	const SimConfiguration back = SimConfiguration::load(c);
	EXPECT_NO_THROW(c.requireAllKeysRead());
	EXPECT_EQ(savedSettings(back), text);
	EXPECT_EQ(back.simulation.seed, 77u);
	EXPECT_EQ(back.laser.beams, 1081u);
	EXPECT_NEAR(back.laser.range_noise, 0.02, 1e-12);
	EXPECT_NEAR(back.laser.sensor_pose[2], 0.2, 1e-12);
	EXPECT_NEAR(back.odometry.thrun_alpha2_rot_trans, 0.1, 1e-12);
	EXPECT_NEAR(back.odometry.thrun_alpha4_trans_rot, 0.02, 1e-12);
	EXPECT_EQ(back.robot.waypoints.size(), 2u);
	EXPECT_EQ(back.robot.initial_yaw, "45");
}

TEST(SimConfiguration, PresetThenOverrides)
{
	TrackedConfig c;
	c.loadText("[Laser]\npreset = ibeo_ladar_2d30\nbeams = 271\n" + kWall, "s.ini");
	const auto sc = SimConfiguration::load(c);
	EXPECT_EQ(sc.laser.beams, 271u);  // overridden
	EXPECT_NEAR(sc.laser.aperture, 1.5 * M_PI, 1e-12);	 // from the preset
	EXPECT_NEAR(sc.laser.range_noise, 0.025, 1e-12);
}

TEST(SimConfiguration, YamlWorldIsTheSameAsIni)
{
	TrackedConfig c;
	c.loadYaml(
		"Laser:\n  preset: hokuyo_utm30lx\n"
		"Wall.w:\n  polyline: [[0, 0], [5, 0], [5, 5]]\n"
		"Agent.p:\n  waypoints: \"[1 1; 3 1]\"\n  shape: body\n"
		"Robot:\n  explore_start: [1.5, 2]\n  tipo: 3\n",
		"w.yaml");
	const auto sc = SimConfiguration::load(c);
	// The misspelt key is reported with its YAML line.
	EXPECT_NE(errorMessageOf<ConfigError>([&] { c.requireAllKeysRead(); })
				  .find("w.yaml:10: [Robot] tipo"),
		std::string::npos);
	EXPECT_EQ(sc.world.segments().size(), 2u);
	EXPECT_NEAR(sc.robot.explore_start[0], 1.5, 0);
	ASSERT_EQ(sc.world.agents().size(), 1u);
	EXPECT_EQ(sc.world.agents()[0].params().shape, WalkingAgent::Shape::Body);
	EXPECT_EQ(sc.laser.beams, 1081u);
}

TEST(SimConfiguration, BadInitialYawIsRejected)
{
	TrackedConfig c;
	c.loadText("[Robot]\ninitial_yaw_DEG = north\n" + kWall, "s.ini");
	EXPECT_NE(errorMessageOf<ConfigError>([&] { SimConfiguration::load(c); })
				  .find("initial_yaw_DEG"),
		std::string::npos);
}

TEST(SimConfiguration, EveryKeyIsInTheSimulatorDoc)
{
	featloc::test::expectEveryKeyDocumented(
		std::string(FEATLOC_SOURCE_DIR) + "/doc/simulator.md",
		[](mrpt::config::CConfigFileBase& c) { SimConfiguration().saveSettings(c); });
}

TEST(SimConfiguration, AbsurdBeamCountsAndRatesAreRejectedBeforeAnythingIsMade)
{
	for (const char* line : {"beams = 1000000000", "beams = 1", "rate = 1e9"})
	{
		TrackedConfig c;
		c.loadText(std::string("[Laser]\n") + line + "\n" + kWall, "s.ini");
		const std::string msg = errorMessageOf<ConfigError>([&] { SimConfiguration::load(c); });
		EXPECT_NE(msg.find(std::string(line).substr(0, 4)), std::string::npos) << msg;
		EXPECT_NE(msg.find("s.ini"), std::string::npos) << msg;
	}
}
