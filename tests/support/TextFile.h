#pragma once
#include <string>

namespace featloc::test
{
/** The whole of `file` as text ("" when it cannot be read). */
std::string readText(const std::string& file);
}  // namespace featloc::test
