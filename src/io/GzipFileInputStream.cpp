#include "featloc/io/GzipFileInputStream.h"

#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace featloc
{
namespace
{
gzFile handle(void* p) { return static_cast<gzFile>(p); }
}  // namespace

GzipFileInputStream::~GzipFileInputStream() { close(); }

bool GzipFileInputStream::open(const std::string& path, std::string& error)
{
	close();
	std::error_code ec;
	m_fileSize = std::filesystem::file_size(path, ec);
	if (ec)
	{
		error = ec.message();
		return false;
	}
	errno = 0;
	m_gz = gzopen(path.c_str(), "rb");
	if (!m_gz)
	{
		error = errno ? std::strerror(errno) : "zlib cannot open it";
		return false;
	}
	return true;
}

void GzipFileInputStream::close()
{
	if (m_gz) gzclose(handle(m_gz));
	m_gz = nullptr;
}

size_t GzipFileInputStream::Read(void* buf, size_t count)
{
	if (!m_gz) return 0;
	size_t done = 0;
	auto* out = static_cast<char*>(buf);
	while (done < count)
	{
		// gzread takes an unsigned int count.
		const auto chunk = static_cast<unsigned>(
			std::min<size_t>(count - done, std::numeric_limits<int>::max()));
		const int n = gzread(handle(m_gz), out + done, chunk);
		if (n <= 0) break;	// end of data, or a damaged stream: a short read
		done += static_cast<size_t>(n);
	}
	return done;
}

size_t GzipFileInputStream::Write(const void*, size_t)
{
	throw std::logic_error("GzipFileInputStream is read-only");
}

uint64_t GzipFileInputStream::Seek(int64_t, TSeekOrigin)
{
	throw std::logic_error("GzipFileInputStream cannot seek");
}

uint64_t GzipFileInputStream::getPosition() const
{
	return m_gz ? static_cast<uint64_t>(gztell(handle(m_gz))) : 0;
}

uint64_t GzipFileInputStream::filePosition() const
{
	return m_gz ? static_cast<uint64_t>(gzoffset(handle(m_gz))) : 0;
}

double GzipFileInputStream::fractionRead() const
{
	if (m_fileSize == 0) return 1.0;
	const double f = static_cast<double>(filePosition()) / static_cast<double>(m_fileSize);
	return f < 0 ? 0 : (f > 1 ? 1 : f);
}
}  // namespace featloc
