#include <gtest/gtest.h>

#include <fstream>

#include "featloc/config/ConfigValues.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "support/ErrorMessage.h"
#include "support/TempDir.h"

using featloc::ConfigError;
using featloc::TrackedConfig;
namespace cfgv = featloc::config;
using featloc::test::errorMessageOf;

TEST(TrackedConfig, UnreadKeyIsReportedWithSectionKeyLineAndSuggestion)
{
	TrackedConfig c;
	c.loadText(
		"[Pipeline]\nestimator = matcher\n\n[ScanMatcher.IcpMatcher]\n"
		"maxIteratons = 50  // typo\n",
		"run.ini");
	std::string est;
	cfgv::read(c, "Pipeline", "estimator", est);
	unsigned int it = 80;
	cfgv::read(c, "ScanMatcher.IcpMatcher", "maxIterations", it);
	EXPECT_EQ(it, 80u);	 // the misspelt key was not taken

	const std::string msg = errorMessageOf<ConfigError>([&] { c.requireAllKeysRead(); });
	EXPECT_NE(msg.find("run.ini:5"), std::string::npos) << msg;
	EXPECT_NE(msg.find("[ScanMatcher.IcpMatcher] maxIteratons"), std::string::npos)
		<< msg;
	EXPECT_NE(msg.find("did you mean 'maxIterations'"), std::string::npos) << msg;
}

TEST(TrackedConfig, UnknownSectionIsReported)
{
	TrackedConfig c;
	c.loadText("[Pipelin]\nestimator = matcher\n", "run.ini");
	std::string est;
	cfgv::read(c, "Pipeline", "estimator", est);
	const std::string msg = errorMessageOf<ConfigError>([&] { c.requireAllKeysRead(); });
	EXPECT_NE(msg.find("unknown section [Pipelin]"), std::string::npos) << msg;
	EXPECT_NE(msg.find("did you mean [Pipeline]"), std::string::npos) << msg;
}

TEST(TrackedConfig, AllKeysReadPasses)
{
	TrackedConfig c;
	c.loadText("[A]\nx = 1\nY = 2\n", "a.ini");
	double x = 0, y = 0;
	cfgv::read(c, "a", "X", x);	 // case-insensitive, as MRPT
	cfgv::read(c, "A", "y", y);
	EXPECT_NO_THROW(c.requireAllKeysRead());
	EXPECT_DOUBLE_EQ(x, 1);
	EXPECT_DOUBLE_EQ(y, 2);
}

TEST(TrackedConfig, OverrideWinsAndNamesItsOrigin)
{
	TrackedConfig c;
	c.loadText("[A]\nx = 1\n", "a.ini");
	c.applyOverride("A:x=2.5");
	c.applyOverride("B:new = hello world");
	double x = 0;
	std::string s;
	cfgv::read(c, "A", "x", x);
	cfgv::read(c, "B", "new", s);
	EXPECT_DOUBLE_EQ(x, 2.5);
	EXPECT_EQ(s, "hello world");
	EXPECT_EQ(c.origin("A", "x"), "--set A:x=2.5");
	EXPECT_TRUE(c.origin("A", "nothere").empty());
}

TEST(TrackedConfig, MalformedOverrideIsRejected)
{
	TrackedConfig c;
	for (const char* bad : {"nocolon=1", "A:novalue", ":k=v", "A:=v"})
		EXPECT_NE(errorMessageOf<ConfigError>([&] { c.applyOverride(bad); }).find("SECTION:KEY=VALUE"),
			std::string::npos)
			<< bad;
}

TEST(TrackedConfig, OverrideOfUnknownKeyIsAnError)
{
	TrackedConfig c;
	c.loadText("[A]\nx = 1\n", "a.ini");
	c.applyOverride("A:z=3");
	double x = 0;
	cfgv::read(c, "A", "x", x);
	const std::string msg = errorMessageOf<ConfigError>([&] { c.requireAllKeysRead(); });
	EXPECT_NE(msg.find("--set A:z=3"), std::string::npos) << msg;
}

TEST(TrackedConfig, PathsResolveAgainstTheIniFolderOrTheWorkingDirectory)
{
	featloc::test::TempDir dir;
	const std::string ini = dir.file("run.ini");
	std::ofstream(ini) << "[Input]\nrawlog = data/x.rawlog\nabs = /tmp/y\n";
	TrackedConfig c;
	c.loadFile(ini);
	EXPECT_EQ(c.resolvePath("Input", "rawlog", "data/x.rawlog"),
		(dir.path() / "data/x.rawlog").string());
	EXPECT_EQ(c.resolvePath("Input", "abs", "/tmp/y"), "/tmp/y");
	c.applyOverride("Input:rawlog=other.rawlog");
	EXPECT_EQ(c.resolvePath("Input", "rawlog", "other.rawlog"), "other.rawlog");
}

TEST(TrackedConfig, MissingFileIsAConfigError)
{
	TrackedConfig c;
	EXPECT_NE(errorMessageOf<ConfigError>([&] { c.loadFile("/nonexistent/featloc.ini"); })
				  .find("does not exist"),
		std::string::npos);
}

TEST(ConfigValues, StrictNumbersRejectWhatMrptWouldSilentlyAccept)
{
	TrackedConfig c;
	c.loadText(
		"[A]\nd1 = abc\nd2 = 1.5x\ni1 = 4o\ni2 = 2.5\nu1 = -3\nb1 = maybe\n"
		"d3 = nan\nok = 1e-3  // comment\n",
		"a.ini");
	double d = 7;
	int i = 7;
	unsigned int u = 7;
	bool b = false;
	EXPECT_NE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "d1", d); }).find("a.ini:2"),
		std::string::npos);
	EXPECT_NE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "d2", d); }).find("'1.5x'"),
		std::string::npos);
	EXPECT_FALSE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "i1", i); }).empty());
	EXPECT_FALSE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "i2", i); }).empty());
	EXPECT_FALSE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "u1", u); }).empty());
	EXPECT_FALSE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "b1", b); }).empty());
	EXPECT_FALSE(errorMessageOf<ConfigError>([&] { cfgv::read(c, "A", "d3", d); }).empty());
	EXPECT_EQ(d, 7);  // unchanged by failed reads
	cfgv::read(c, "A", "ok", d);
	EXPECT_DOUBLE_EQ(d, 1e-3);
}

TEST(ConfigValues, EmptyValueWithCommentIsEmpty)
{
	TrackedConfig c;
	c.loadText("[A]\nlabel =     // empty: any\nname = x // the name\n", "a.ini");
	std::string label = "default", name;
	cfgv::read(c, "A", "label", label);
	cfgv::read(c, "A", "name", name);
	EXPECT_EQ(label, "");
	EXPECT_EQ(name, "x");
}

TEST(ConfigValues, DegreesAndChoicesAndAbsentKeys)
{
	TrackedConfig c;
	c.loadText("[A]\nang_DEG = 90\nmode = fast\n", "a.ini");
	double rad = 0, untouched = 0.25;
	cfgv::readDegrees(c, "A", "ang_DEG", rad);
	EXPECT_NEAR(rad, M_PI / 2, 1e-15);
	cfgv::read(c, "A", "absent", untouched);
	EXPECT_EQ(untouched, 0.25);
	std::string mode = "slow";
	const std::string msg =
		errorMessageOf<ConfigError>([&] { cfgv::readChoice(c, "A", "mode", mode, {"slow", "exact"}); });
	EXPECT_NE(msg.find("one of: slow, exact"), std::string::npos) << msg;
	EXPECT_EQ(mode, "slow");
}

TEST(ConfigValues, FormatNumberIsShortAndReadsBack)
{
	for (double v : {0.1, 1.0 / 3.0, 1e-6, 123456.789, -2.5e-12, 0.0})
		EXPECT_NEAR(std::stod(cfgv::formatNumber(v)), v, 1e-12 * std::abs(v));
	EXPECT_EQ(cfgv::formatNumber(0.1), "0.1");
	EXPECT_EQ(cfgv::formatNumber(0.2 * M_PI / 180 * 180 / M_PI), "0.2");
}

TEST(ConfigValues, RowsAreParsedStrictly)
{
	TrackedConfig c;
	c.loadText(
		"[A]\npts = [0 0; 1.5, 2; -3 4]\nbad = [0 0; 1 x]\nragged = [0 0; 1 2 3 4]\n",
		"a.ini");
	std::vector<std::vector<double>> rows;
	cfgv::readRows(c, "A", "pts", rows, {2, 3});
	ASSERT_EQ(rows.size(), 3u);
	EXPECT_DOUBLE_EQ(rows[1][0], 1.5);
	EXPECT_DOUBLE_EQ(rows[2][1], 4);
	EXPECT_NE(errorMessageOf<ConfigError>([&] { cfgv::readRows(c, "A", "bad", rows, {2}); })
				  .find("'x' in row 2"),
		std::string::npos);
	EXPECT_NE(errorMessageOf<ConfigError>([&] { cfgv::readRows(c, "A", "ragged", rows, {2, 3}); })
				  .find("row 2 has 4 numbers, expected 2 or 3"),
		std::string::npos);
}

// Found by fuzz/fuzz_config: MRPT's ini preprocessor threw a bare
// runtime_error on an unclosed $env{ / $eval{, without the file's name.
TEST(TrackedConfig, AnUnclosedPreprocessorExpressionIsAConfigErrorNamingTheFile)
{
	for (const char* text : {"[A]\nk = $env{ the first scan\n", "[A]\nk = $eval{1+\n"})
	{
		featloc::TrackedConfig cfg;
		try
		{
			cfg.loadText(text, "my.ini");
			ADD_FAILURE() << "no error for " << text;
		}
		catch (const featloc::ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find("my.ini: "), std::string::npos) << e.what();
		}
	}
}
