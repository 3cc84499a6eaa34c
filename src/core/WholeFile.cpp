#include "featloc/core/WholeFile.h"

#include <filesystem>
#include <stdexcept>

namespace featloc
{
namespace fs = std::filesystem;

std::string partialFileName(const std::string& path)
{
	const fs::path p(path);
	return (p.parent_path() / ("." + p.stem().string() + ".partial" + p.extension().string()))
		.string();
}

void writeWholeFile(const std::string& path, const std::function<void(const std::string&)>& write)
{
	const std::string partial = partialFileName(path);
	std::error_code ec;
	try
	{
		write(partial);
	}
	catch (...)
	{
		fs::remove(partial, ec);
		throw;
	}
	fs::rename(partial, path, ec);
	if (ec)
	{
		std::error_code ignored;
		fs::remove(partial, ignored);
		throw std::runtime_error("cannot write '" + path + "': " + ec.message());
	}
}
}  // namespace featloc
