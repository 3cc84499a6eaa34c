#pragma once
// What every featloc fuzz target shares: the input as a file (featloc's
// readers take paths, as users give them), and the rule that only
// featloc's documented errors may escape a reader.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace featloc::fuzz
{
/** Writes the input to a file of this process in /dev/shm (or /tmp) with
 * the given suffix (readers pick formats by name, e.g. ".gz"); removed by
 * the destructor. */
class FuzzFile
{
   public:
	FuzzFile(const uint8_t* data, size_t size, const std::string& suffix)
	{
		const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
		path = std::string(dir) + "/featloc-fuzz-" + std::to_string(getpid()) + suffix;
		if (FILE* f = std::fopen(path.c_str(), "wb"))
		{
			if (size) std::fwrite(data, 1, size, f);
			std::fclose(f);
		}
	}
	~FuzzFile() { std::remove(path.c_str()); }
	std::string path;
};
}  // namespace featloc::fuzz
