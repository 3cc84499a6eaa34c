#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "featloc/sim/EmulatedLaser.h"

namespace featloc
{
/** A Hokuyo laser scanner emulated over TCP in SCIP 2.0, the protocol
 * MRPT's CHokuyoURG speaks in Ethernet mode (`IP_DIR`, `PORT_DIR`), so that
 * the real driver runs unchanged against simulated scans.
 *
 * Protocol (SCIP 2.0 as the UTM-30LX speaks it): every command line is
 * echoed, then a status line `SS sum LF`, data lines `data sum LF` and an
 * empty line; sum = (sum of the bytes & 0x3F) + 0x30, over a parameter
 * line's bytes before its ';'. `PP` gives DMIN DMAX ARES AMIN AMAX AFRT
 * SCAN MODL; `MD` (continuous distance data) is acknowledged with status
 * 00, then every scan repeats the MD echo with status 99, a 4-character
 * timestamp (device ms) and the ranges, 3 characters of 6 bits (+0x30,
 * mm), cut in lines of 64. `QT` stops streaming. MRPT 2.5.8 runs the whole
 * handshake twice (on connect and in initialize()), so commands are
 * accepted while streaming; the scans sent between the first MD and the
 * second handshake's QT are skipped by the driver while it looks for the
 * QT echo, so they are counted apart (scansDiscardedByReinit()).
 *
 * Faults for tests: a device that accepts connections and never answers
 * (Silent); the connection itself is EmulatedLaser's. */
class ScipLaserServer : public EmulatedLaser
{
   public:
	/** What PP reports: the scanner's geometry. Beam i (AMIN..AMAX) points
	 * at (i - AFRT) * 2 pi / ARES from the front. */
	struct Device
	{
		std::string model = "UTM-30LX";
		int dminMm = 23, dmaxMm = 30000;
		int ares = 1440, amin = 0, amax = 1080, afrt = 540;
		int scanRpm = 2400;	 //!< 40 Hz
	};
	enum class Fault
	{
		None,
		Silent	//!< accepts connections, never answers
	};

	/** Listens on 127.0.0.1:port. Throws std::runtime_error naming the
	 * port when it cannot. */
	ScipLaserServer(Device device, unsigned short port, Fault fault = Fault::None);
	~ScipLaserServer() override;

	/** A Hokuyo-like device for a scan of `beams` beams over `aperture`
	 * [rad] centred on the front (ARES = 2 pi / step, rounded; throws
	 * std::invalid_argument when the step is not 2 pi / an integer within
	 * 0.1%, since SCIP cannot describe such a scanner). */
	static Device deviceFor(size_t beams, double aperture, double maxRange, int rate);

	/** Sends one scan to the driver if it asked for data (MD); ranges in
	 * metres, beam AMIN first; a range <= 0 or not finite is sent as
	 * "no return" (error code 1, which the driver marks invalid).
	 * `deviceTimeMs`: the scanner's clock. False when no driver streams. */
	bool publish(const std::vector<float>& ranges, uint32_t deviceTimeMs) override;
	/** Sends, in place of a scan, a malformed one: the MD echo and status
	 * 99, then a data block of the wrong length (CHokuyoURG reports a
	 * hardware error). False when no driver streams. */
	bool publishGarbage(uint32_t deviceTimeMs) override;
	/** Scans sent in a streaming session that the driver then ended with
	 * QT and restarted with MD on the same connection (a re-initialisation):
	 * the driver never reads them, since it skips everything before the QT
	 * echo. */
	size_t scansDiscardedByReinit() const { return m_scansDiscardedByReinit; }

   private:
	void onBytes(std::string& pending) override;
	void onConnectionChange() override;
	void handleCommand(const std::string& command);	 //!< with m_mutex held

	Device m_device;
	std::atomic<size_t> m_scansDiscardedByReinit{0};
	size_t m_sessionScans = 0;	//!< sent since the last MD (under m_mutex)
	size_t m_quitScans = 0;	 //!< sent in the session the last QT ended (under m_mutex)
	std::string m_mdEcho;  //!< the MD command being served (under m_mutex)
};
}  // namespace featloc
