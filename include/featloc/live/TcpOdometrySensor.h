#pragma once
#include <mrpt/hwdrivers/CGenericSensor.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace mrpt::comms
{
class CClientTCPSocket;
}

namespace featloc
{
/** Wheel odometry from a robot base over TCP, in featloc's line protocol
 * (OdometryLine: `ODOM t x y phi [v w]`): the hook a user's own base plugs
 * into featloc-live. An MRPT sensor plugin, registered with MRPT's sensor
 * registry under the driver name `TcpOdometrySensor`, so it is configured
 * like any MRPT driver:
 *
 *     [ODOMETRY]
 *     driver      = TcpOdometrySensor
 *     sensorLabel = ODOMETRY
 *     host        = 127.0.0.1   // the base's address
 *     port        = 10950       // the base's TCP port
 *
 * Each line becomes a CObservationOdometry. Its time is the sender's time
 * mapped to this computer's clock by the smallest offset seen so far
 * (arrival - sent: the transport delay can only add), so the base's clock
 * may have any epoch. A malformed line is counted, logged and skipped; a
 * dropped link is reconnected every half second. */
class TcpOdometrySensor : public mrpt::hwdrivers::CGenericSensor
{
	DEFINE_GENERIC_SENSOR(TcpOdometrySensor)

   public:
	TcpOdometrySensor();
	~TcpOdometrySensor() override;

	/** Connects; throws naming host:port when the base cannot be reached. */
	void initialize() override;
	/** Reads what has arrived (waits up to 50 ms for it). */
	void doProcess() override;

	size_t malformedLines() const { return m_malformed; }
	size_t reconnections() const { return m_reconnections; }

   protected:
	void loadConfig_sensorSpecific(
		const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;

   private:
	void connect();
	void onLine(const std::string& line);

	std::string m_host = "127.0.0.1";
	int m_port = 10950;
	std::unique_ptr<mrpt::comms::CClientTCPSocket> m_socket;
	std::string m_pending;
	std::optional<double> m_clockOffset;  //!< [s] local - sender, smallest seen
	double m_lastStamp = 0;
	size_t m_malformed = 0, m_reconnections = 0;
	std::chrono::steady_clock::time_point m_lastAttempt;
};
}  // namespace featloc
