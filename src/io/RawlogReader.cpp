#include "featloc/io/RawlogReader.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <sstream>

#include "featloc/core/AllocationCeiling.h"
#include "featloc/core/ExceptionText.h"
#include "featloc/core/InputError.h"
#include "featloc/io/GzipFileInputStream.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
/** Forwards reads to another stream and counts the bytes delivered, so that
 * a failed read can be placed: no byte consumed means a clean end of file,
 * a short read means the file ends inside an object. */
class CountingInputStream : public mrpt::io::CStream
{
   public:
	explicit CountingInputStream(mrpt::io::CStream& in) : m_in(in) {}

	size_t Read(void* buf, size_t count) override
	{
		const size_t n = m_in.Read(buf, count);
		m_delivered += n;
		if (n < count) m_shortRead = true;
		return n;
	}
	size_t Write(const void*, size_t) override
	{
		throw std::logic_error("CountingInputStream is read-only");
	}
	uint64_t Seek(int64_t, TSeekOrigin) override
	{
		throw std::logic_error("CountingInputStream cannot seek");
	}
	uint64_t getTotalBytesCount() const override
	{
		return m_in.getTotalBytesCount();
	}
	uint64_t getPosition() const override { return m_in.getPosition(); }

	uint64_t delivered() const { return m_delivered; }
	bool shortRead() const { return m_shortRead; }

   private:
	mrpt::io::CStream& m_in;
	uint64_t m_delivered = 0;
	bool m_shortRead = false;
};

}  // namespace

struct RawlogReader::Impl
{
	GzipFileInputStream file;
	std::unique_ptr<CountingInputStream> counter;
};

RawlogReader::RawlogReader(const std::string& path)
	: m_impl(std::make_unique<Impl>()), m_path(path)
{
	registerClasses();
	if (path.empty()) throw InputError("no rawlog file given");
	if (mrpt::system::directoryExists(path))
		throw InputError("rawlog '" + path + "' is a directory, not a file");
	if (!mrpt::system::fileExists(path))
		throw InputError("rawlog '" + path + "' does not exist");
	std::string err;
	if (!m_impl->file.open(path, err))
		throw InputError("rawlog '" + path + "' cannot be opened: " + err);
	m_impl->counter = std::make_unique<CountingInputStream>(m_impl->file);
}

RawlogReader::~RawlogReader() = default;

bool RawlogReader::next(RawlogEntry& entry)
{
	auto& in = *m_impl->counter;
	const uint64_t before = in.delivered();
	// "rawlog 'F': entry #N (byte B of the uncompressed stream) WHAT; the N
	// entries before it were read correctly".
	auto entryError = [&](const std::string& what) {
		std::ostringstream msg;
		msg << "rawlog '" << m_path << "': entry #" << m_nextIndex << " (byte " << before
			<< " of the uncompressed stream) " << what;
		if (m_nextIndex > 0)
			msg << "; the " << m_nextIndex << " entries before it were read correctly";
		return msg.str();
	};
	mrpt::serialization::CSerializable::Ptr obj;
	try
	{
		// MRPT sizes arrays and strings from the length fields it reads,
		// before reading their contents: a corrupt length must fail here,
		// not fill gigabytes of memory with zeros.
		const AllocationCeiling ceiling(kMaxEntryBytes);
		auto arch = mrpt::serialization::archiveFrom(in);
		obj = arch.ReadObject();
	}
	catch (const std::bad_alloc&)
	{
		throw InputError(entryError(
			"is corrupt: a length field in it asks for more than " +
				std::to_string(kMaxEntryBytes >> 20) + " MiB of memory"));
	}
	catch (const std::exception& e)
	{
		const bool nothingConsumed = in.delivered() == before;
		if (nothingConsumed && in.shortRead()) return false;  // clean end
		throw InputError(entryError(
			in.shortRead()
				? "is cut short: the file is truncated (" + exceptionText(e) + ")"
				: "cannot be read: the file is corrupt or not a rawlog (" + exceptionText(e) +
					")"));
	}

	if (!obj)
		throw InputError(
			"rawlog '" + m_path + "': entry #" + std::to_string(m_nextIndex) +
			" is a null object");
	using namespace mrpt::obs;
	if (!std::dynamic_pointer_cast<CSensoryFrame>(obj) &&
		!std::dynamic_pointer_cast<CActionCollection>(obj) &&
		!std::dynamic_pointer_cast<CObservation>(obj))
		throw InputError(
			"rawlog '" + m_path + "': entry #" + std::to_string(m_nextIndex) +
			" is a " + obj->GetRuntimeClass()->className +
			", not a rawlog entry (CSensoryFrame, CActionCollection or a "
			"CObservation)");
	entry.index = m_nextIndex++;
	entry.object = std::move(obj);
	return true;
}

double RawlogReader::progress() const
{
	// The position in the file on disk (compressed for .gz) against its
	// size: both count the same bytes.
	return m_impl->file.fractionRead();
}

}  // namespace featloc
