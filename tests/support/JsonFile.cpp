#include "support/JsonFile.h"

#include <fstream>

namespace featloc::test
{
nlohmann::json readJson(const std::string& file)
{
	std::ifstream in(file);
	return nlohmann::json::parse(in);
}
}  // namespace featloc::test
