#include "featloc/sim/OdometryLineServer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace featloc
{
OdometryLineServer::OdometryLineServer(unsigned short port) : m_port(port), m_listener(port)
{
	m_thread = std::thread([this] { acceptLoop(); });
}

OdometryLineServer::~OdometryLineServer()
{
	m_stop = true;
	if (m_thread.joinable()) m_thread.join();
	for (int c : m_clients) LoopbackTcpServer::close(c);
}

void OdometryLineServer::acceptLoop()
{
	while (!m_stop)
	{
		const int client = m_listener.accept(50);
		if (client < 0) continue;
		std::lock_guard<std::mutex> lock(m_mutex);
		m_clients.push_back(client);
	}
}

size_t OdometryLineServer::publish(const OdometryLine& reading)
{
	const std::string line = reading.format();
	std::lock_guard<std::mutex> lock(m_mutex);
	size_t reached = 0;
	for (int& c : m_clients)
	{
		if (LoopbackTcpServer::sendAll(c, line, 500))
			reached++;
		else
		{
			LoopbackTcpServer::close(c);  // the client is gone
			c = -1;
		}
	}
	m_clients.erase(std::remove(m_clients.begin(), m_clients.end(), -1), m_clients.end());
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
	for (int c : m_clients) LoopbackTcpServer::close(c);
	m_clients.clear();
}
}  // namespace featloc
