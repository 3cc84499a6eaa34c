#pragma once
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>

namespace featloc
{
/** featloc's wheel-odometry line protocol: the hook a robot base plugs
 * into (served by `featloc-sim --serve`, read by the TcpOdometrySensor
 * driver of featloc-live). ASCII over TCP, one reading per line, LF (or
 * CR LF) terminated, fields separated by spaces:
 *
 *     ODOM <t> <x> <y> <phi> [<v> <w>]
 *
 * t: the reading's time [s] on the sender's clock (any epoch; it must
 * increase); x, y [m], phi [rad]: the odometry pose (the base's own
 * integration, as CObservationOdometry holds it); v [m/s], w [rad/s]: the
 * optional velocities. Lines that are empty or start with '#' carry no
 * reading. Anything else is malformed. */
struct OdometryLine
{
	double time = 0;  //!< [s] sender clock
	mrpt::poses::CPose2D pose;
	bool hasVelocities = false;
	double v = 0, w = 0;  //!< [m/s], [rad/s]

	/** The line (with its LF) for a reading. */
	std::string format() const;

	/** The reading on a line; nullopt for an empty or '#' line. Throws
	 * InputError quoting the line when it is malformed (a wrong keyword,
	 * a missing or non-finite number, extra fields). */
	static std::optional<OdometryLine> parse(const std::string& line);
};
}  // namespace featloc
