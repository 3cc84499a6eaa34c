#pragma once
#include <optional>

namespace featloc
{
/** When a driver that replays a recording delivers each observation.
 *
 * MRPT's CCameraSensor with `grabber_type = rawlog` reads its file as fast
 * as it is called and keeps the recorded stamps; run as is, a live run
 * would get the whole recording at once, stamped whenever it was made.
 * This clock makes it a camera: each frame is delivered when it comes due
 * (`[Live] replay_clock`):
 *  - Now: the first frame at once, each next one at its recorded interval
 *    from it, re-stamped on this computer's clock (a recording of another
 *    day);
 *  - Recorded: at its own stamp, read as this computer's clock (the
 *    camera recording featloc-sim --serve writes); a frame already more
 *    than kSkipAfter overdue when read is skipped, as a camera opened late
 *    never sees the frames before. */
class RecordingReplayClock
{
   public:
	enum class Mode
	{
		Now,
		Recorded
	};
	/** [s] how overdue a frame may be in Recorded mode and still be sent.
	 * Frames are read well ahead of their time (the driver is called again
	 * as soon as one is delivered), so only frames from before the camera
	 * was opened are overdue; one delivered late would make every other
	 * sensor's observations wait that long in the time-order merge for
	 * the rest of the run (it bounds a sensor's delay by the largest seen). */
	static constexpr double kSkipAfter = 0.005;

	explicit RecordingReplayClock(Mode mode) : m_mode(mode) {}

	struct Due
	{
		double wait = 0;   //!< [s] from now, >= 0
		double stamp = 0;  //!< [s] the stamp to give it (MRPT clock, as a double)
	};
	/** The frame stamped `stamp`, read at `wallNow` (both MRPT clock, s):
	 * when to deliver it and with what stamp; nullopt: skip it. */
	std::optional<Due> schedule(double stamp, double wallNow);

   private:
	Mode m_mode;
	std::optional<double> m_offset;	 //!< Now: this clock - recorded clock
};
}  // namespace featloc
