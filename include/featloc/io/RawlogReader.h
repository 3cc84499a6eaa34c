#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "featloc/io/RawlogEntry.h"

namespace featloc
{
/** Streams the entries of an MRPT rawlog file (either format, gzip-compressed
 * or plain) one at a time, without loading the file into memory.
 *
 * Unlike CRawlog::getActionObservationPairOrObservation(), which returns
 * false both at the end and on a damaged file, next() tells them apart: the
 * end of the file exactly between two entries is a clean end; running out of
 * data inside an entry is a truncated file, and anything else that fails to
 * deserialize is a corrupt file, as is an entry asking for more than
 * kMaxEntryBytes of memory. Both throw InputError naming the file, the
 * entry index and the byte offset (in the uncompressed stream). */
class RawlogReader
{
   public:
	/** The most memory one entry may take while it is read. MRPT allocates
	 * what an entry's length fields say before reading the data they
	 * announce; an entry that asks for more is reported as corrupt before
	 * any of it is allocated (AllocationCeiling). Real entries are far
	 * below it: a 1081-beam scan is 10 kB, a 12-megapixel colour image 36 MB. */
	static constexpr uint64_t kMaxEntryBytes = uint64_t(1) << 30;

	/** Opens the file. Throws InputError if it does not exist, is a
	 * directory, or cannot be opened. */
	explicit RawlogReader(const std::string& path);
	~RawlogReader();
	RawlogReader(const RawlogReader&) = delete;
	RawlogReader& operator=(const RawlogReader&) = delete;

	/** Reads the next entry. Returns false at the clean end of the file.
	 * Throws InputError on a truncated or corrupt file, or an object that is
	 * not a rawlog entry (CSensoryFrame, CActionCollection, CObservation). */
	bool next(RawlogEntry& entry);

	/** Fraction of the file on disk read so far, in [0, 1] (for a .gz
	 * file: the compressed bytes consumed over the file size; zlib reads
	 * ahead a few kB, so 1 may come a few entries before the end). */
	double progress() const;

	const std::string& path() const { return m_path; }

	/** Number of entries returned so far. */
	size_t entriesRead() const { return m_nextIndex; }

   private:
	struct Impl;
	std::unique_ptr<Impl> m_impl;
	std::string m_path;
	size_t m_nextIndex = 0;
};

}  // namespace featloc
