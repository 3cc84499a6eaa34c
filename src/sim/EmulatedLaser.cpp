#include "featloc/sim/EmulatedLaser.h"

#include <chrono>

namespace featloc
{
EmulatedLaser::EmulatedLaser(unsigned short port, bool silent)
	: m_silent(silent), m_port(port), m_listener(std::make_unique<LoopbackTcpServer>(port))
{
}

void EmulatedLaser::startServing()
{
	m_thread = std::thread([this] { serve(); });
}

void EmulatedLaser::stopServing()
{
	m_stop = true;
	if (m_thread.joinable()) m_thread.join();
}

void EmulatedLaser::setReachable(bool reachable)
{
	m_reachable = reachable;
	if (reachable) return;
	std::lock_guard<std::mutex> lock(m_mutex);
	closeClient();	// now: nothing more is delivered (the listener follows)
}

void EmulatedLaser::closeClient()
{
	if (m_client >= 0) LoopbackTcpServer::close(m_client);
	m_client = -1;
	m_streaming = false;
	onConnectionChange();
}

bool EmulatedLaser::send(const std::string& bytes)
{
	if (m_client < 0) return false;
	if (LoopbackTcpServer::sendAll(m_client, bytes, 1000)) return true;
	closeClient();	// a driver that is gone or does not read
	return false;
}

void EmulatedLaser::serve()
{
	std::string pending;
	while (!m_stop)
	{
		bool connected = false;
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			connected = m_client >= 0;
		}
		if (!m_reachable)
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			closeClient();
			m_listener.reset();	 // connections are refused
		}
		if (!m_listener)
		{
			if (m_reachable)
			{
				try
				{
					m_listener = std::make_unique<LoopbackTcpServer>(m_port);
				}
				catch (const std::runtime_error&)
				{
					// the port is not free again yet: retry
				}
			}
			std::this_thread::sleep_for(std::chrono::milliseconds(10));
			continue;
		}
		if (!connected)
		{
			const int client = m_listener->accept(50);
			if (client < 0) continue;
			std::lock_guard<std::mutex> lock(m_mutex);
			m_client = client;
			m_streaming = false;
			m_connections++;
			onConnectionChange();
			pending.clear();
		}
		char buf[512];
		long n = 0;
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			if (m_client >= 0) n = LoopbackTcpServer::receive(m_client, buf, sizeof(buf));
			if (n < 0)
			{
				closeClient();	// the driver hung up
				continue;
			}
			pending.append(buf, static_cast<size_t>(n));
			if (m_silent)
				pending.clear();  // a hung device reads and never answers
			else
				onBytes(pending);
		}
		if (n == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	std::lock_guard<std::mutex> lock(m_mutex);
	closeClient();
}
}  // namespace featloc
