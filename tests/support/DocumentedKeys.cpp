#include "DocumentedKeys.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <fstream>
#include <sstream>

namespace featloc::test
{
void expectEveryKeyDocumented(
	const std::string& doc,
	const std::function<void(mrpt::config::CConfigFileBase&)>& save)
{
	std::ifstream docFile(doc);
	ASSERT_TRUE(docFile) << doc;
	std::stringstream ss;
	ss << docFile.rdbuf();
	const std::string text = ss.str();

	mrpt::config::CConfigFileMemory mem;
	save(mem);
	std::vector<std::string> sections;
	mem.getAllSections(sections);
	for (const auto& s : sections)
	{
		EXPECT_NE(text.find("## [" + s + "]"), std::string::npos) << s << " in " << doc;
		std::vector<std::string> keys;
		mem.getAllKeys(s, keys);
		for (auto k : keys)
		{
			k = mrpt::system::trim(k);	// saved names are space-padded
			EXPECT_NE(text.find("| `" + k + "` |"), std::string::npos)
				<< "[" << s << "] " << k << " is not in " << doc;
		}
	}
}
}  // namespace featloc::test
