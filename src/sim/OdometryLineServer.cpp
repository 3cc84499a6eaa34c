#include "featloc/sim/OdometryLineServer.h"

#include <mrpt/comms/CClientTCPSocket.h>
#include <mrpt/comms/CServerTCPSocket.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace featloc
{
OdometryLineServer::OdometryLineServer(unsigned short port) : m_port(port)
{
	m_listener = std::make_unique<mrpt::comms::CServerTCPSocket>(port, "127.0.0.1");
	// accept() with a timeout logs a warning at each timeout: only errors.
	m_listener->setMinLoggingLevel(mrpt::system::LVL_ERROR);
	if (!m_listener->isListening())
		throw std::runtime_error(
			"odometry emulator: cannot listen on 127.0.0.1:" + std::to_string(port));
	m_thread = std::thread([this] { acceptLoop(); });
}

OdometryLineServer::~OdometryLineServer()
{
	m_stop = true;
	if (m_thread.joinable()) m_thread.join();
}

void OdometryLineServer::acceptLoop()
{
	while (!m_stop)
	{
		auto client = m_listener->accept(50);
		if (!client) continue;
		client->setTCPNoDelay(1);
		std::lock_guard<std::mutex> lock(m_mutex);
		m_clients.push_back(std::move(client));
	}
}

size_t OdometryLineServer::publish(const OdometryLine& reading)
{
	const std::string line = reading.format();
	std::lock_guard<std::mutex> lock(m_mutex);
	size_t reached = 0;
	for (auto& c : m_clients)
	{
		if (c->isConnected() && c->writeAsync(line.data(), line.size(), 500) == line.size())
			reached++;
		else
			c->close();
	}
	m_clients.erase(
		std::remove_if(m_clients.begin(), m_clients.end(),
			[](const auto& c) { return !c->isConnected(); }),
		m_clients.end());
	if (reached) m_sent++;
	return reached;
}

size_t OdometryLineServer::clients() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	return m_clients.size();
}

void OdometryLineServer::dropConnections()
{
	std::lock_guard<std::mutex> lock(m_mutex);
	for (auto& c : m_clients) c->close();
	m_clients.clear();
}
}  // namespace featloc
