#include "support/TextFile.h"

#include <fstream>
#include <iterator>

namespace featloc::test
{
std::string readText(const std::string& file)
{
	std::ifstream f(file);
	return std::string(std::istreambuf_iterator<char>(f), {});
}
}  // namespace featloc::test
