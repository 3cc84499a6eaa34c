#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "featloc/sim/LoopbackTcpServer.h"

namespace featloc
{
/** A laser scanner emulated over TCP on 127.0.0.1 for featloc-sim --serve:
 * the connection's life (one driver at a time, a new connection replaces
 * the old one; unplugged: connections refused; hung: link up, nothing
 * answered) is here, the device's protocol in the subclasses
 * (ScipLaserServer: Hokuyo SCIP 2.0; SickLaserServer: SICK LMS1xx CoLa-A).
 * RealTimeLogPlayer drives them all through this interface. */
class EmulatedLaser
{
   public:
	virtual ~EmulatedLaser() = default;
	EmulatedLaser(const EmulatedLaser&) = delete;
	EmulatedLaser& operator=(const EmulatedLaser&) = delete;

	/** A new scan from the device, ranges in metres in the device's beam
	 * order; a range <= 0 or not finite is "no return". deviceTimeMs: the
	 * scanner's clock. False when no driver takes scans now. */
	virtual bool publish(const std::vector<float>& ranges, uint32_t deviceTimeMs) = 0;
	/** A malformed scan in place of the next one. */
	virtual bool publishGarbage(uint32_t deviceTimeMs) = 0;
	/** The driver has set the device up and takes scans. */
	bool streaming() const { return m_streaming; }
	/** Scans that reached the driver. */
	size_t scansSent() const { return m_scansSent; }
	size_t connections() const { return m_connections; }
	unsigned short port() const { return m_port; }
	/** false: the link drops and connections are refused (the device is
	 * unplugged or off); true: it listens again on the same port. */
	void setReachable(bool reachable);
	/** true: the device hangs, link up: it sends and answers nothing. */
	void setSilent(bool silent) { m_silent = silent; }

   protected:
	/** Listens on 127.0.0.1:port; throws std::runtime_error naming the port
	 * when it cannot. */
	EmulatedLaser(unsigned short port, bool silent);
	/** The subclass starts the thread at the end of its constructor and
	 * stops it first thing in its destructor (the thread calls its
	 * overrides). */
	void startServing();
	void stopServing();

	/** Bytes received so far and not consumed: take the whole commands out
	 * and answer them (with m_mutex held). */
	virtual void onBytes(std::string& pending) = 0;
	/** A connection began or ended (with m_mutex held). */
	virtual void onConnectionChange() {}

	bool send(const std::string& bytes);  //!< with m_mutex held
	void closeClient();	 //!< with m_mutex held

	mutable std::mutex m_mutex;	 //!< guards m_client, the subclass's session and writes
	int m_client = -1;	//!< the driver's connection
	std::atomic<bool> m_streaming{false}, m_silent{false};
	std::atomic<size_t> m_scansSent{0}, m_connections{0};

   private:
	void serve();

	unsigned short m_port;
	std::atomic<bool> m_stop{false}, m_reachable{true};
	std::unique_ptr<LoopbackTcpServer> m_listener;	//!< null while unreachable
	std::thread m_thread;
};
}  // namespace featloc
