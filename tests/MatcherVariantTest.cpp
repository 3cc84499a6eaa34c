// featloc-bench's matcher variants, "[LABEL=]CLASS[{key=value;...}]": the
// overrides of another matcher's section, which a fallback_class reads.
#include <gtest/gtest.h>

#include "featloc/app/MatcherVariant.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/matchers/CfIdcMatcher.h"
#include "featloc/matchers/IdcMatcher.h"
#include "featloc/registerClasses.h"

using namespace featloc;

namespace
{
TrackedConfig shippedConfig()
{
	TrackedConfig c;
	c.loadFile(std::string(FEATLOC_SOURCE_DIR) + "/config.ini");
	return c;
}

bool fallbackSigmaFromScan(const ScanMatcher& m)
{
	const auto idc = std::dynamic_pointer_cast<IdcMatcher>(m.fallback());
	EXPECT_TRUE(idc);
	return idc && idc->params.segmentation.sigmaFromScan;
}
}  // namespace

// A CF-IDC variant without the override has its IDC fallback as the ini's
// [ScanMatcher.IdcMatcher]; "ScanMatcher.IdcMatcher:key=value" sets the
// fallback's key and leaves CF-IDC's own.
TEST(MatcherVariant, AnOverrideOfAnotherSectionReachesTheFallback)
{
	registerClasses();
	TrackedConfig cfg = shippedConfig();
	const auto variants = MatcherVariant::parseList(
		"own=featloc::CfIdcMatcher{breakpoint_sigma_r_from_scan=false},"
		"both=featloc::CfIdcMatcher{breakpoint_sigma_r_from_scan=false;"
		"ScanMatcher.IdcMatcher:breakpoint_sigma_r_from_scan=false}");
	ASSERT_EQ(variants.size(), 2u);
	const auto own = variants[0].create(cfg);
	const auto both = variants[1].create(cfg);
	for (const auto& m : {own, both})
		EXPECT_FALSE(std::dynamic_pointer_cast<CfIdcMatcher>(m)->params.segmentation.sigmaFromScan);
	EXPECT_TRUE(fallbackSigmaFromScan(*own));  // config.ini's IdcMatcher section
	EXPECT_FALSE(fallbackSigmaFromScan(*both));
}

// Read by nobody, or of a section that is no matcher's: an error naming it.
TEST(MatcherVariant, AnOverrideOfAnotherSectionNobodyReadsIsAnError)
{
	registerClasses();
	TrackedConfig cfg = shippedConfig();
	// PCM has an IDC fallback, but IDC has no key of that name; MRPT's ICP
	// has no fallback to read IDC's section.
	for (const std::string item :
		{"featloc::PcmFeatureMatcher{ScanMatcher.IdcMatcher:breakpoint_sigma=0.01}",
			"featloc::IcpMatcher{ScanMatcher.IdcMatcher:breakpoint_sigma_r=0.01}"})
	{
		try
		{
			MatcherVariant::parseList(item)[0].create(cfg);
			ADD_FAILURE() << item << " was accepted";
		}
		catch (const ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find("[ScanMatcher.IdcMatcher]"), std::string::npos)
				<< e.what();
		}
	}
	EXPECT_THROW(MatcherVariant::parseList("featloc::IdcMatcher{Pipeline:keyframe_distance=2}")[0]
					 .create(cfg),
		UsageError);
}
