#pragma once
#include <functional>
#include <string>

namespace featloc
{
/** Writes a file so that it appears whole or not at all: `write` fills a
 * hidden temporary beside it (`.NAME.partial.EXT`, same folder, same
 * extension, so that writers that pick the format by extension, such as
 * cv::imwrite, still do), which is then renamed over `path` (atomic on one
 * file system). A run killed meanwhile, even by SIGKILL, leaves the earlier
 * file or none, and at most the temporary; if `write` throws, the temporary
 * is removed and the exception goes on. */
void writeWholeFile(const std::string& path, const std::function<void(const std::string&)>& write);

/** The temporary writeWholeFile() writes before renaming it to `path`. */
std::string partialFileName(const std::string& path);
}  // namespace featloc
