#pragma once
#include <atomic>

namespace featloc
{
/** While alive, SIGINT (Ctrl-C) and SIGTERM ask the run to stop instead of
 * killing it: requested() becomes true, the pipeline stops reading and the
 * outputs are completed. A second signal while stopping ends the program at
 * once (the default action), for a run that does not stop. The previous
 * handlers come back at destruction. One instance at a time. */
class InterruptSignals
{
   public:
	InterruptSignals();
	~InterruptSignals();
	InterruptSignals(const InterruptSignals&) = delete;
	InterruptSignals& operator=(const InterruptSignals&) = delete;

	const std::atomic<bool>& flag() const;
	bool requested() const { return flag().load(); }
};
}  // namespace featloc
