#include "featloc/live/RawlogRecorder.h"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace featloc
{
RawlogRecorder::RawlogRecorder(std::string path)
	: m_path(std::move(path)), m_file(m_path, std::ios::binary | std::ios::trunc)
{
	if (!m_file) throw std::runtime_error("cannot write '" + m_path + "'");
}

void RawlogRecorder::record(const mrpt::serialization::CSerializable& object)
{
	// Serialized whole in memory, then written and flushed at once: the
	// file never ends inside an entry unless the disk fills.
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << object;
	m_file.write(reinterpret_cast<const char*>(buf.getRawBufferData()),
		static_cast<std::streamsize>(buf.getTotalBytesCount()));
	m_file.flush();
	if (!m_file)
		throw std::runtime_error(
			"cannot write '" + m_path + "' (entry #" + std::to_string(m_entries) +
			"): disk full or removed?");
	m_entries++;
	m_bytes += buf.getTotalBytesCount();
}
}  // namespace featloc
