#include "TempDir.h"

#include <cstdlib>
#include <stdexcept>

namespace featloc::test
{
TempDir::TempDir()
{
	std::string tmpl =
		(std::filesystem::temp_directory_path() / "featloc-test-XXXXXX").string();
	if (!mkdtemp(tmpl.data()))
		throw std::runtime_error("cannot create a temporary folder");
	m_path = tmpl;
}

TempDir::~TempDir()
{
	std::error_code ec;
	std::filesystem::remove_all(m_path, ec);
}

std::string TempDir::file(const std::string& name) const
{
	return (m_path / name).string();
}
}  // namespace featloc::test
