#include "featloc/core/AllocationCeiling.h"

#include <mrpt/core/aligned_allocator.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <new>

namespace featloc
{
uint64_t AllocationCeiling::dataBytesInUse()
{
	// statm: size resident shared text lib data dt, in pages; "data" is the
	// data segment, private mappings and the stack: what RLIMIT_DATA counts,
	// plus the stack, so the ceiling errs on the generous side.
	FILE* f = std::fopen("/proc/self/statm", "r");
	if (!f) return 0;
	unsigned long long size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
	const int n = std::fscanf(f, "%llu %llu %llu %llu %llu %llu", &size, &resident, &shared,
		&text, &lib, &data);
	std::fclose(f);
	if (n != 6) return 0;
	return data * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

// AddressSanitizer maps its own bookkeeping (shadow, quarantine, stack
// depot) as the program runs; under a data limit those mmaps fail and ASan
// dies ("Failed to mmap"). Sanitized builds have no ceiling: there
// libFuzzer's malloc limit flags what the ceiling would refuse.
#if defined(__SANITIZE_ADDRESS__)
#define FEATLOC_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FEATLOC_UNDER_ASAN 1
#endif
#endif

bool AllocationCeiling::available()
{
#ifdef FEATLOC_UNDER_ASAN
	return false;
#else
	return true;
#endif
}

AllocationCeiling::AllocationCeiling(uint64_t bytes)
{
	if (!available()) return;
	const uint64_t inUse = dataBytesInUse();
	if (inUse == 0 || ::getrlimit(RLIMIT_DATA, &m_saved) != 0) return;  // cannot tell: no ceiling
	const uint64_t wanted = inUse + bytes;
	if (m_saved.rlim_cur != RLIM_INFINITY && m_saved.rlim_cur <= wanted) return;
	rlimit lowered = m_saved;
	lowered.rlim_cur = static_cast<rlim_t>(wanted);
	m_lowered = ::setrlimit(RLIMIT_DATA, &lowered) == 0;
}

AllocationCeiling::~AllocationCeiling()
{
	if (m_lowered) ::setrlimit(RLIMIT_DATA, &m_saved);
}
}  // namespace featloc

// MRPT 2.5.8's aligned_allocator_cpp11::allocate returns what
// mrpt::aligned_malloc returns, null when the memory is refused, and the
// std::vector using it then writes through that null pointer (SIGSEGV in
// CObservation2DRangeScan::resizeScan). The vector's contract is a
// std::bad_alloc, which the readers catch and report. This definition, in
// the executable, takes the place of libmrpt-core's (ELF interposition: the
// executable is searched first); it is MRPT's own, plus the throw. It is
// here because it is what makes an AllocationCeiling safe: it is linked
// wherever the ceiling is.
void* mrpt::aligned_malloc(size_t size, size_t alignment)
{
	if (alignment != 0 && size % alignment != 0) size = (size / alignment + 1) * alignment;
	void* p = ::aligned_alloc(alignment, size);
	if (!p && size != 0) throw std::bad_alloc();
	return p;
}
