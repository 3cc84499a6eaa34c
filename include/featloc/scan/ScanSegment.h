#pragma once
#include <cstddef>
#include <cstdint>

namespace featloc
{
/** A run of consecutive points of a ScanPoints (bearing order): indices
 * first..last, both included. */
struct ScanSegment
{
	uint32_t first = 0;
	uint32_t last = 0;

	size_t size() const { return static_cast<size_t>(last - first) + 1; }
};
}  // namespace featloc
