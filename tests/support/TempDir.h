#pragma once
#include <filesystem>
#include <string>

namespace featloc::test
{
/** A fresh temporary folder, removed with its contents at scope exit. */
class TempDir
{
   public:
	TempDir();
	~TempDir();
	TempDir(const TempDir&) = delete;
	TempDir& operator=(const TempDir&) = delete;

	const std::filesystem::path& path() const { return m_path; }
	/** path() / name, as a string. */
	std::string file(const std::string& name) const;

   private:
	std::filesystem::path m_path;
};
}  // namespace featloc::test
