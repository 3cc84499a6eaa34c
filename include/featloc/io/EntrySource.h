#pragma once
#include <memory>
#include <string>

#include "featloc/io/RawlogEntry.h"

namespace featloc
{
struct InputOptions;

/** Where the pipeline's entries come from: a rawlog file, a CARMEN log, or
 * (later) live MRPT drivers. Entries are rawlog entries (a CSensoryFrame, a
 * CActionCollection or one CObservation) in the order the source has them.
 *
 * A source is validated when it is made: opening it reads (and keeps) its
 * first entry, so a missing, unreadable or empty input is reported before
 * any output is touched. */
class EntrySource
{
   public:
	using Ptr = std::unique_ptr<EntrySource>;
	virtual ~EntrySource() = default;

	/** The next entry; false at the end. Throws InputError on damaged
	 * input, naming the source and entry. */
	virtual bool next(RawlogEntry& entry) = 0;

	/** How much of the input has been consumed, in [0, 1] (for a file:
	 * bytes of the file on disk). */
	virtual double progress() const = 0;

	/** What the source reads, for messages and summary.json (a path). */
	virtual std::string name() const = 0;

	/** A short description for the console ("MRPT rawlog, 12.3 MB"). */
	virtual std::string description() const = 0;
	/** Where externally stored images of this source's observations are
	 * (for a rawlog: MRPT's `<name>_Images` folder beside it); "" when the
	 * source has none. */
	virtual std::string imagesDirectory() const { return {}; }

	/** The file source for `path`: a CARMEN log for .log / .log.gz names
	 * (read as `input` says: carmen_beam_angles), an MRPT rawlog otherwise.
	 * Validates it (see above). */
	static Ptr openFile(const std::string& path, const InputOptions& input);
};
}  // namespace featloc
