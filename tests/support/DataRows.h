#pragma once
#include <string>
#include <vector>

namespace featloc::test
{
/** The lines of a text file that are neither empty nor comments ('#'):
 * a TUM trajectory's poses, a ground truth's rows. */
std::vector<std::string> dataRows(const std::string& path);
}  // namespace featloc::test
