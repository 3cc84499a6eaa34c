#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "featloc/io/OdometryLine.h"
#include "featloc/sim/LoopbackTcpServer.h"

namespace featloc
{
/** A robot base emulated over TCP: it sends every wheel-odometry reading,
 * in featloc's line protocol (OdometryLine), to every connected client
 * (featloc-live's TcpOdometrySensor). */
class OdometryLineServer
{
   public:
	/** Listens on 127.0.0.1:port; throws std::runtime_error naming the
	 * port when it cannot. */
	explicit OdometryLineServer(unsigned short port);
	~OdometryLineServer();
	OdometryLineServer(const OdometryLineServer&) = delete;
	OdometryLineServer& operator=(const OdometryLineServer&) = delete;

	/** Sends one reading to every client; the number of clients reached. */
	size_t publish(const OdometryLine& reading);

	unsigned short port() const { return m_port; }
	size_t readingsSent() const { return m_sent; }
	size_t clients() const;
	/** Every client's link drops; the server keeps listening. */
	void dropConnections();

   private:
	void acceptLoop();

	unsigned short m_port;
	std::atomic<bool> m_stop{false};
	std::atomic<size_t> m_sent{0};
	mutable std::mutex m_mutex;	 //!< guards m_clients
	std::vector<int> m_clients;	 //!< connection descriptors
	LoopbackTcpServer m_listener;
	std::thread m_thread;
};
}  // namespace featloc
