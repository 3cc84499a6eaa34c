#pragma once
#include <string>
#include <vector>

#include "featloc/sim/EmulatedLaser.h"

namespace featloc
{
/** A SICK LMS1xx laser scanner emulated over TCP in CoLa-A (ASCII
 * telegrams framed by STX 0x02 and ETX 0x03), the protocol MRPT's
 * CLMS100Eth speaks (`ip_address`, `TCP_port`), so that the real driver
 * runs unchanged against simulated scans.
 *
 * What MRPT 2.5.8's CLMS100Eth does (read in its source), and what the
 * emulator answers:
 * - initialize(): `sMN SetAccessMode 03 F4724744` (-> `sAN SetAccessMode
 *   1`), `sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000` (25 Hz, one
 *   sector, 0.25 deg, -45..225 deg; -> `sAN mLMPsetscancfg` with status 0
 *   when that is the simulated scanner, else the device's error code and
 *   its own configuration: the simulation cannot change), `sWN
 *   LMDscandatacfg ...` (-> `sWA LMDscandatacfg`), `sMN LMCstartmeas` (->
 *   `sAN LMCstartmeas 0`), then `sRN STlms` until the status is 7 (ready;
 *   answered at once). The driver reads each answer until 1 s without a
 *   byte and sleeps 10 s after each STlms: about 15 s in all.
 * - every doProcess(): `sRN LMDscandata`, answered with the newest scan
 *   (`sRA LMDscandata`, distances in hex mm in channel DIST1, SICK's angle
 *   convention: 90 deg is straight ahead, beams counter-clockwise from the
 *   start angle) or, before the first scan, as soon as there is one. The
 *   driver polls: a poll that comes before the next scan gets the same
 *   scan again, as from the real device (counted: scansResent()). A beam
 *   without return is sent as 0, as the device does.
 * Unknown commands get `sFA 1`. Faults as EmulatedLaser's. */
class SickLaserServer : public EmulatedLaser
{
   public:
	/** The scanner's configuration in the device's units. */
	struct Device
	{
		int frequency = 2500;  //!< [1/100 Hz]
		int resolution = 2500;	//!< [1/10000 deg]
		int startAngle = -450000;  //!< [1/10000 deg], SICK's frame (90 deg ahead)
		int stopAngle = 2250000;  //!< [1/10000 deg]
		int beams() const { return (stopAngle - startAngle) / resolution + 1; }
	};
	/** The LMS1xx configuration of a simulated scan (`beams` over
	 * `aperture` [rad], centred on the front) at `rate` Hz; throws
	 * std::invalid_argument when the device cannot describe it. */
	static Device deviceFor(size_t beams, double aperture, double rate);

	SickLaserServer(Device device, unsigned short port);
	~SickLaserServer() override;

	/** The device has measured a new scan (beam at the start angle first);
	 * a poll waiting for the first one is answered now. */
	bool publish(const std::vector<float>& ranges, uint32_t deviceTimeMs) override;
	/** The next poll is answered with a damaged telegram (CLMS100Eth
	 * logs "doProcessSimple failed" and reports a hardware error). */
	bool publishGarbage(uint32_t deviceTimeMs) override;
	/** Polls answered with a scan that had been sent already. */
	size_t scansResent() const { return m_scansResent; }
	/** The driver asked for a scan configuration the emulator does not have. */
	std::string configurationMismatch() const;

   private:
	void onBytes(std::string& pending) override;
	void onConnectionChange() override;
	void handleCommand(const std::string& command);	 //!< with m_mutex held
	bool sendScan();  //!< with m_mutex held
	static std::string frame(const std::string& telegram);

	Device m_device;
	std::atomic<size_t> m_scansResent{0};
	// Under m_mutex:
	std::string m_latest;  //!< the newest scan's telegram ("" before the first)
	bool m_latestSent = false;
	bool m_pollWaiting = false;	 //!< a poll came before the first scan
	bool m_measuring = false;  //!< LMCstartmeas received on this connection
	bool m_garbageNext = false;
	uint32_t m_telegrams = 0;
	std::string m_mismatch;
	uint32_t m_scans = 0;  //!< scan counter (publish()'s thread only)
};
}  // namespace featloc
