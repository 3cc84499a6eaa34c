#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace featloc::test
{
/** The JSON document in `file` (summary.json, featloc-eval --json...);
 * throws nlohmann's parse error when it is not JSON. */
nlohmann::json readJson(const std::string& file);
}  // namespace featloc::test
