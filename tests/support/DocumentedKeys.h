#pragma once
#include <functional>
#include <string>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace featloc::test
{
/** Checks (gtest expectations) that every section `save` writes has a
 * "## [Section]" heading in the Markdown file `doc`, and every key a
 * "| `key` |" table row. */
void expectEveryKeyDocumented(
	const std::string& doc,
	const std::function<void(mrpt::config::CConfigFileBase&)>& save);
}  // namespace featloc::test
