#pragma once
#include <string>
#include <vector>

#include "featloc/io/RawlogEntry.h"
#include "featloc/output/RunStats.h"
#include "featloc/output/StepRecord.h"
#include "featloc/output/StepSource.h"

namespace featloc
{
/** A file the run writes. Outputs write as the run goes (so an error late
 * in a long run keeps what was produced) and complete their file in
 * finish(), which the pipeline calls exactly once, also after an error. */
class RunOutput
{
   public:
	virtual ~RunOutput() = default;

	/** Every rawlog entry, in file order, with the observations in it that
	 * went into steps. */
	virtual void onEntry(const RawlogEntry&, const std::vector<StepSource>&) {}
	/** Every processed step, in time order. */
	virtual void onStep(const StepRecord& record) = 0;
	/** End of the run (normal or after an error: stats.ok tells). */
	virtual void finish(const RunStats& stats) = 0;
	/** Path of the file written. */
	virtual std::string path() const = 0;
};
}  // namespace featloc
