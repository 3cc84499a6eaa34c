#pragma once
#include <optional>

#include "featloc/io/EntrySource.h"
#include "featloc/io/RawlogReader.h"

namespace featloc
{
/** An MRPT rawlog file (format #1 or #2, gzip or plain) as an EntrySource.
 * The constructor reads the first entry (kept for next()), so a file that
 * does not exist, is a directory, is empty or is not a rawlog is an
 * InputError before the run starts. */
class RawlogFileSource : public EntrySource
{
   public:
	explicit RawlogFileSource(const std::string& path);

	bool next(RawlogEntry& entry) override;
	double progress() const override;
	std::string name() const override { return m_reader.path(); }
	std::string description() const override;
	std::string imagesDirectory() const override;

   private:
	RawlogReader m_reader;
	std::optional<RawlogEntry> m_first;
};
}  // namespace featloc
