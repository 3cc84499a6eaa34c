#pragma once
#include <mrpt/io/CStream.h>

#include <cstdint>
#include <string>

namespace featloc
{
/** A read-only MRPT stream over a gzip-compressed or plain file (zlib reads
 * both), which also knows how far into the *file on disk* it has read.
 *
 * MRPT's CFileGZInputStream reports the uncompressed position against the
 * compressed file size, so a progress bar built on it reaches 100% long
 * before the end of a .gz log; zlib's gzoffset() gives the compressed
 * position, which is what can be compared with the file size. */
class GzipFileInputStream : public mrpt::io::CStream
{
   public:
	GzipFileInputStream() = default;
	~GzipFileInputStream() override;
	GzipFileInputStream(const GzipFileInputStream&) = delete;
	GzipFileInputStream& operator=(const GzipFileInputStream&) = delete;

	/** Returns false (and sets `error`) when the file cannot be opened. */
	bool open(const std::string& path, std::string& error);
	void close();

	size_t Read(void* buf, size_t count) override;
	size_t Write(const void*, size_t) override;
	uint64_t Seek(int64_t, TSeekOrigin) override;
	/** Size of the file on disk [bytes]. */
	uint64_t getTotalBytesCount() const override { return m_fileSize; }
	/** Position in the uncompressed data [bytes]. */
	uint64_t getPosition() const override;

	/** Bytes of the file on disk consumed so far (compressed position). */
	uint64_t filePosition() const;
	/** Fraction of the file on disk read so far, in [0, 1]. */
	double fractionRead() const;

   private:
	void* m_gz = nullptr;  //!< gzFile (zlib.h stays out of this header)
	uint64_t m_fileSize = 0;
};
}  // namespace featloc
