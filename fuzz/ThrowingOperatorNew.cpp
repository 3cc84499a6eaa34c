// ASan's operator new reports "out of memory" and aborts when an allocation
// is refused, where the release build's throws std::bad_alloc. featloc
// relies on that throw: a rawlog entry whose length field asks for more
// than RawlogReader::kMaxEntryBytes has its allocation refused by the
// kernel (AllocationCeiling) and is reported as corrupt. These definitions
// give the fuzz targets (and the sanitized test suite) the release behaviour: new and delete (plain and
// array, sized or not) go through ASan's malloc and free, so ASan still
// checks every use, and a refused allocation throws. The aligned forms
// stay ASan's own (they pair with each other).
#include <cstdlib>
#include <new>

void* operator new(std::size_t n)
{
	if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
	throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return std::malloc(n == 0 ? 1 : n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
	return std::malloc(n == 0 ? 1 : n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
