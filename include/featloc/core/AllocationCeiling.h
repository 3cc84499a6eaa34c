#pragma once
#include <sys/resource.h>

#include <cstdint>

namespace featloc
{
/** While it lives, the process may map at most `bytes` more data memory
 * (heap and private mappings) than it had when it was made: a larger
 * allocation fails at once with std::bad_alloc, before any page of it is
 * touched. Made around code that sizes memory from untrusted input that
 * featloc cannot check first, such as MRPT's deserialization, which resizes
 * a scan to the beam count a (possibly corrupt) file says before reading
 * the beams (CObservation2DRangeScan::serializeFrom), or OpenCV's decoders.
 *
 * It lowers the soft RLIMIT_DATA (enforced for mmap too since Linux 4.7)
 * and restores the previous limit when it goes; never raises it. The limit
 * is the process's, so other threads share the headroom meanwhile: keep
 * the scope short. Off under AddressSanitizer (available()). */
class AllocationCeiling
{
   public:
	explicit AllocationCeiling(uint64_t bytes);
	~AllocationCeiling();
	AllocationCeiling(const AllocationCeiling&) = delete;
	AllocationCeiling& operator=(const AllocationCeiling&) = delete;

	/** False in AddressSanitizer builds, where the ceiling is off (ASan's
	 * own mappings would fail under it). */
	static bool available();

	/** The process's data memory now, in bytes (/proc/self/statm). */
	static uint64_t dataBytesInUse();

   private:
	rlimit m_saved{};
	bool m_lowered = false;
};
}  // namespace featloc
