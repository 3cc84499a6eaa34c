#include "featloc/io/RawlogFileSource.h"

#include <cstdio>
#include <filesystem>

#include "featloc/core/InputError.h"

namespace featloc
{
RawlogFileSource::RawlogFileSource(const std::string& path) : m_reader(path)
{
	RawlogEntry first;
	if (!m_reader.next(first))
		throw InputError("rawlog '" + path + "' is empty: it holds no entry");
	m_first = std::move(first);
}

bool RawlogFileSource::next(RawlogEntry& entry)
{
	if (m_first)
	{
		entry = std::move(*m_first);
		m_first.reset();
		return true;
	}
	return m_reader.next(entry);
}

double RawlogFileSource::progress() const { return m_reader.progress(); }

std::string RawlogFileSource::description() const
{
	std::error_code ec;
	const auto bytes = std::filesystem::file_size(m_reader.path(), ec);
	char buf[64];
	std::snprintf(buf, sizeof(buf), "MRPT rawlog, %.1f MB", ec ? 0.0 : static_cast<double>(bytes) / 1e6);
	return buf;
}
}  // namespace featloc
