#pragma once
#include <string>

namespace featloc
{
/** A fault the device emulator injects into a served laser, at a time of
 * the log (seconds from its first item), so that featloc-live's handling
 * of real device trouble can be tested over loopback:
 * - `outage@T:D`: the link drops at T and the device is unreachable
 *   (connections refused) for D seconds, as a cable pulled and plugged back
 *   or a scanner power-cycled; scans due meanwhile are not delivered;
 * - `stall@T:D`: the device hangs with its link up: it sends nothing and
 *   answers nothing for D seconds;
 * - `garbage@T`: the scan due at T is replaced by a malformed one (the
 *   right header, a data block of the wrong length), as a corrupted frame. */
struct DeviceFault
{
	enum class Kind
	{
		Outage,
		Stall,
		Garbage
	};
	Kind kind = Kind::Outage;
	double at = 0;	//!< [s] from the log's first item
	double duration = 0;  //!< [s] Outage and Stall

	/** Parses `outage@T:D`, `stall@T:D` or `garbage@T`; throws std::invalid_argument
	 * saying what is wrong and the accepted forms. */
	static DeviceFault parse(const std::string& spec);
	std::string describe() const;
};
}  // namespace featloc
