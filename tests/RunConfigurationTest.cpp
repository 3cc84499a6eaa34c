#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>


#include "featloc/app/RunConfiguration.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/localization/MapLocalizer.h"
#include "featloc/matchers/IcpMatcher.h"
#include "featloc/registerClasses.h"
#include "support/DocumentedKeys.h"

using namespace featloc;

namespace
{
std::string saved(const RunConfiguration& rc)
{
	mrpt::config::CConfigFileMemory mem;
	rc.save(mem);
	return mem.getContent();
}

RunConfiguration loadedFrom(const std::string& text)
{
	TrackedConfig c;
	c.loadText(text, "saved.ini");
	RunConfiguration rc = RunConfiguration::load(c);
	c.requireAllKeysRead();	 // everything saved is read back
	return rc;
}
}  // namespace

TEST(RunConfiguration, DefaultsRoundTripThroughSaveAndLoad)
{
	registerClasses();
	const std::string first = saved(RunConfiguration::defaults());
	const std::string second = saved(loadedFrom(first));
	EXPECT_EQ(first, second);
}

TEST(RunConfiguration, NonDefaultValuesRoundTrip)
{
	registerClasses();
	RunConfiguration rc = RunConfiguration::defaults();
	rc.input.rawlog = "a/b.rawlog";
	rc.input.laser_label = "LMS";
	rc.input.invalid_range_policy = "invalidate";
	rc.input.max_scans = 17;
	rc.input.carmen_beam_angles = "even";
	rc.odometry.covariance_source = "model";
	rc.odometry.model.sigma_xy_per_rad = 0.123;
	rc.odometry.model.sigma_yaw_min = 0.0123;
	rc.pipeline.estimator = "odometry";
	rc.pipeline.initial_pose = {1.5, -2, 0.3};
	rc.pipeline.keyframe_distance = 0.7;
	rc.pipeline.keyframe_angle = 0.2;
	rc.output.dir = "out";
	rc.output.write_scene = false;
	rc.evaluation.ground_truth = "gt.txt";
	auto& icp = dynamic_cast<IcpMatcher&>(*rc.matcher).params;
	icp.algorithm = mrpt::slam::icpLevenbergMarquardt;
	icp.thresholdAng = 0.05;
	icp.maxIterations = 33;
	icp.minGoodness = 0.25;

	const RunConfiguration back = loadedFrom(saved(rc));
	EXPECT_EQ(back.input.rawlog, "a/b.rawlog");
	EXPECT_EQ(back.input.laser_label, "LMS");
	EXPECT_EQ(back.input.invalid_range_policy, "invalidate");
	EXPECT_EQ(back.input.max_scans, 17u);
	EXPECT_EQ(back.input.carmen_beam_angles, "even");
	EXPECT_EQ(back.odometry.covariance_source, "model");
	EXPECT_NEAR(back.odometry.model.sigma_xy_per_rad, 0.123, 1e-12);
	EXPECT_NEAR(back.odometry.model.sigma_yaw_min, 0.0123, 1e-12);
	EXPECT_EQ(back.pipeline.estimator, "odometry");
	EXPECT_NEAR(back.pipeline.initial_pose[0], 1.5, 1e-12);
	EXPECT_NEAR(back.pipeline.initial_pose[1], -2, 1e-12);
	EXPECT_NEAR(back.pipeline.initial_pose[2], 0.3, 1e-12);
	EXPECT_NEAR(back.pipeline.keyframe_distance, 0.7, 1e-12);
	EXPECT_NEAR(back.pipeline.keyframe_angle, 0.2, 1e-12);
	EXPECT_EQ(back.output.dir, "out");
	EXPECT_FALSE(back.output.write_scene);
	EXPECT_EQ(back.evaluation.ground_truth, "gt.txt");
	const auto& icpBack = dynamic_cast<const IcpMatcher&>(*back.matcher).params;
	EXPECT_EQ(icpBack.algorithm, mrpt::slam::icpLevenbergMarquardt);
	EXPECT_NEAR(icpBack.thresholdAng, 0.05, 1e-12);
	EXPECT_EQ(icpBack.maxIterations, 33u);
	EXPECT_NEAR(icpBack.minGoodness, 0.25, 1e-12);
}

TEST(RunConfiguration, ShippedConfigIniHasOnlyKnownKeys)
{
	registerClasses();
	TrackedConfig c;
	c.loadFile(std::string(FEATLOC_SOURCE_DIR) + "/config.ini");
	RunConfiguration::load(c);
	EXPECT_NO_THROW(c.requireAllKeysRead());
}

TEST(RunConfiguration, BadValuesNameTheirKey)
{
	registerClasses();
	const std::pair<const char*, const char*> cases[] = {
		{"[Pipeline]\nestimator = kalman\n", "[Pipeline] estimator"},
		{"[Input]\ninvalid_range_policy = ignore\n", "invalid_range_policy"},
		{"[Input]\ncarmen_beam_angles = gmapping\n", "carmen_beam_angles"},
		{"[ScanMatcher.IcpMatcher]\nALFA = 1.5\n", "ALFA"},
		{"[ScanMatcher.IcpMatcher]\nalgorithm = icpFancy\n", "icpClassic"},
		{"[Pipeline]\ninitial_pose = [1 2]\n", "initial_pose"},
		{"[Odometry]\nsigma_xy_min = -1\n", "sigma_xy_min"},
	};
	for (const auto& [text, expected] : cases)
	{
		TrackedConfig c;
		c.loadText(text, "bad.ini");
		try
		{
			RunConfiguration::load(c);
			ADD_FAILURE() << "no error for: " << text;
		}
		catch (const ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
				<< e.what();
			EXPECT_NE(std::string(e.what()).find("bad.ini:2"), std::string::npos)
				<< e.what();
		}
	}
}

// A requirement is stated once ("must be in (0, 1]", not "must be must
// be ..."), whichever matcher's key it is.
TEST(RunConfiguration, ARequirementIsStatedOnce)
{
	registerClasses();
	const std::pair<const char*, const char*> cases[] = {
		{"featloc::CfIdcMatcher", "U_c = -1"},
		{"featloc::CfIdcMatcher", "curvature_length = 7"},
		{"featloc::CfIdcMatcher", "breakpoint_lambda_DEG = 95"},
		{"featloc::IdcMatcher", "max_pair_distance = 0.01"},
		{"featloc::PcmFeatureMatcher", "motion_window_bounds = -1"},
	};
	for (const auto& [cls, line] : cases)
	{
		const std::string name = std::string(cls).substr(9);
		TrackedConfig c;
		c.loadText(std::string("[ScanMatcher]\nclass = ") + cls + "\n[ScanMatcher." + name +
				"]\n" + line + "\n",
			"bad.ini");
		try
		{
			RunConfiguration::load(c);
			ADD_FAILURE() << "no error for: " << line;
		}
		catch (const ConfigError& e)
		{
			const std::string what = e.what();
			EXPECT_NE(what.find("bad.ini:4"), std::string::npos) << what;
			EXPECT_NE(what.find("must be "), std::string::npos) << what;
			EXPECT_EQ(what.find("must be must be"), std::string::npos) << what;
		}
	}
}

TEST(RunConfiguration, EveryKeyIsInTheConfigReferenceDoc)
{
	registerClasses();
	featloc::test::expectEveryKeyDocumented(
		std::string(FEATLOC_SOURCE_DIR) + "/doc/config-reference.md",
		[](mrpt::config::CConfigFileBase& c) { RunConfiguration::defaults().save(c); });
}

TEST(RunConfiguration, ShippedConfigIniIsTheBuiltInDefaults)
{
	// One source of truth: config.ini differs from the built-in defaults
	// (what --write-config writes) only by the bundled data it names.
	registerClasses();
	TrackedConfig c;
	c.loadFile(std::string(FEATLOC_SOURCE_DIR) + "/config.ini");
	RunConfiguration shipped = RunConfiguration::load(c);
	c.requireAllKeysRead();
	EXPECT_FALSE(shipped.input.rawlog.empty());
	EXPECT_FALSE(shipped.evaluation.ground_truth.empty());
	shipped.input.rawlog.clear();
	shipped.evaluation.ground_truth.clear();
	EXPECT_EQ(saved(shipped), saved(RunConfiguration::defaults()));
}

// The map matcher's coarse search is [Localization] map_coarse_search's
// (off by default), whatever its matcher section says for scan-to-scan
// matches (PCM's: on by default).
TEST(RunConfiguration, TheMapMatchersCoarseSearchIsTheLocalizationSections)
{
	registerClasses();
	const std::string world = std::string(FEATLOC_SOURCE_DIR) + "/worlds/office.ini";
	auto load = [&](const std::string& extra) {
		TrackedConfig c;
		c.loadText("[Pipeline]\nestimator = ekf\n[Localization]\nmap = " + world + "\n" + extra,
			"map.ini");
		return RunConfiguration::load(c);
	};
	const RunConfiguration off = load("");
	ASSERT_TRUE(off.mapLocalizer);
	EXPECT_EQ(off.mapLocalizer->mapMatcher().className(), "featloc::PcmFeatureMatcher");
	EXPECT_FALSE(off.mapLocalizer->mapMatcher().coarseSearchOptions().enabled);
	const RunConfiguration on = load("map_coarse_search = true\n");
	EXPECT_TRUE(on.mapLocalizer->mapMatcher().coarseSearchOptions().enabled);
	const RunConfiguration sectionOff =
		load("map_coarse_search = true\n[ScanMatcher.PcmFeatureMatcher]\ncoarse_search = false\n");
	EXPECT_TRUE(sectionOff.mapLocalizer->mapMatcher().coarseSearchOptions().enabled);
}

// So is its guess gate ([Localization] map_guess_gate, off by default: the
// EKF's gate_chi2 gates the map match against the same prediction).
TEST(RunConfiguration, TheMapMatchersGuessGateIsTheLocalizationSections)
{
	registerClasses();
	const std::string world = std::string(FEATLOC_SOURCE_DIR) + "/worlds/office.ini";
	auto load = [&](const std::string& extra) {
		TrackedConfig c;
		c.loadText("[Pipeline]\nestimator = ekf\n[ScanMatcher]\nclass = featloc::PcmFeatureMatcher\n[Localization]\nmap = " +
				world + "\n" + extra,
			"map.ini");
		return RunConfiguration::load(c);
	};
	const RunConfiguration off = load("");
	ASSERT_TRUE(off.mapLocalizer);
	EXPECT_FALSE(off.mapLocalizer->mapMatcher().guessGateEnabled());
	EXPECT_TRUE(off.matcher->guessGateEnabled()) << "the scan-to-scan matcher keeps its gate";
	EXPECT_TRUE(load("map_guess_gate = true\n").mapLocalizer->mapMatcher().guessGateEnabled());
}
