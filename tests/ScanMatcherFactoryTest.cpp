#include <gtest/gtest.h>
#include <mrpt/rtti/CObject.h>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/matchers/IcpMatcher.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"

using namespace featloc;

TEST(ScanMatcherFactory, CreatesRegisteredClassesByName)
{
	registerClasses();
	auto m = ScanMatcherFactory::create("featloc::IcpMatcher");
	ASSERT_TRUE(m);
	EXPECT_EQ(m->className(), "featloc::IcpMatcher");
	EXPECT_TRUE(std::dynamic_pointer_cast<IcpMatcher>(m));
	EXPECT_EQ(ScanMatcherFactory::create("IcpMatcher")->className(),
		"featloc::IcpMatcher");
	// MRPT's own factory knows it too (registered RTTI class).
	EXPECT_TRUE(std::dynamic_pointer_cast<IcpMatcher>(
		mrpt::rtti::classFactory("featloc::IcpMatcher")));
	const auto known = ScanMatcherFactory::knownClassNames();
	EXPECT_NE(std::find(known.begin(), known.end(), "featloc::IcpMatcher"),
		known.end());
	// The abstract base is registered but not creatable: not listed.
	EXPECT_EQ(std::find(known.begin(), known.end(), "featloc::ScanMatcher"),
		known.end());
}

TEST(ScanMatcherFactory, UnknownNameListsKnownClasses)
{
	registerClasses();
	try
	{
		ScanMatcherFactory::create("featloc::MagicMatcher");
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("featloc::MagicMatcher"), std::string::npos);
		EXPECT_NE(msg.find("known classes: featloc::CfIdcMatcher, featloc::IcpMatcher, "
						   "featloc::IdcMatcher, featloc::PcmFeatureMatcher"),
			std::string::npos)
			<< msg;
	}
	// A non-matcher MRPT class is not a matcher either.
	EXPECT_THROW(
		ScanMatcherFactory::create("mrpt::obs::CObservation2DRangeScan"),
		ConfigError);
}

TEST(ScanMatcherFactory, FromConfigLoadsTheSelectedClassParameters)
{
	registerClasses();
	TrackedConfig c;
	c.loadText(
		"[ScanMatcher]\nclass = featloc::IcpMatcher\n"
		"[ScanMatcher.IcpMatcher]\nmaxIterations = 12\n",
		"m.ini");
	auto m = ScanMatcherFactory::createFromConfig(c);
	EXPECT_EQ(dynamic_cast<IcpMatcher&>(*m).params.maxIterations, 12u);
	EXPECT_NO_THROW(c.requireAllKeysRead());
}

TEST(ScanMatcherFactory, FromConfigUnknownClassNamesFileAndKey)
{
	registerClasses();
	TrackedConfig c;
	c.loadText("[ScanMatcher]\nclass = featloc::Nope\n", "m.ini");
	try
	{
		ScanMatcherFactory::createFromConfig(c);
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("m.ini:2: [ScanMatcher] class"), std::string::npos) << msg;
		EXPECT_NE(msg.find("featloc::IcpMatcher"), std::string::npos) << msg;
	}
}

TEST(ScanMatcherFactory, SectionOfANonexistentMatcherIsAnError)
{
	registerClasses();
	TrackedConfig c;
	c.loadText("[ScanMatcher.IcpMacher]\nmaxIterations = 3\n", "m.ini");
	EXPECT_THROW(ScanMatcherFactory::createFromConfig(c), ConfigError);
}
