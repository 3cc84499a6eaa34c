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

namespace featloc
{
std::string RawlogFileSource::imagesDirectory() const
{
	// MRPT's rule (CRawlog::detectImagesDirectory, used by RawLogViewer):
	// "<name>_Images" (or _images, _IMAGES) beside the rawlog, else
	// "Images". Not called directly: in MRPT 2.5.8 it joins folder and
	// name without a separator ("/data/logImages").
	namespace fs = std::filesystem;
	const fs::path p(m_reader.path());
	std::error_code ec;
	for (const char* suffix : {"_Images", "_images", "_IMAGES"})
	{
		const fs::path d = p.parent_path() / (p.stem().string() + suffix);
		if (fs::is_directory(d, ec)) return d.string();
	}
	return (p.parent_path() / "Images").string();
}
}  // namespace featloc
