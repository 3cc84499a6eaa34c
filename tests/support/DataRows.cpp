#include "support/DataRows.h"

#include <fstream>

namespace featloc::test
{
std::vector<std::string> dataRows(const std::string& path)
{
	std::ifstream f(path);
	std::vector<std::string> rows;
	for (std::string line; std::getline(f, line);)
		if (!line.empty() && line[0] != '#') rows.push_back(line);
	return rows;
}
}  // namespace featloc::test
