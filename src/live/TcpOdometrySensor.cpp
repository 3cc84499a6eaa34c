#include "featloc/live/TcpOdometrySensor.h"

#include <mrpt/comms/CClientTCPSocket.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "featloc/core/InputError.h"
#include "featloc/io/OdometryLine.h"

IMPLEMENTS_GENERIC_SENSOR(TcpOdometrySensor, featloc)

namespace featloc
{
TcpOdometrySensor::TcpOdometrySensor() { m_sensorLabel = "ODOMETRY"; }

TcpOdometrySensor::~TcpOdometrySensor() = default;

void TcpOdometrySensor::loadConfig_sensorSpecific(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	m_host = cfg.read_string(section, "host", m_host);
	m_port = cfg.read_int(section, "port", m_port);
	if (m_host.empty() || m_port <= 0 || m_port > 65535)
		throw std::invalid_argument(
			"[" + section + "] TcpOdometrySensor needs host and port (1-65535), got '" +
			m_host + "':" + std::to_string(m_port));
}

void TcpOdometrySensor::connect()
{
	m_lastAttempt = std::chrono::steady_clock::now();
	auto s = std::make_unique<mrpt::comms::CClientTCPSocket>();
	s->connect(m_host, static_cast<unsigned short>(m_port), 2000);
	m_socket = std::move(s);
	m_pending.clear();
	m_state = ssWorking;
}

void TcpOdometrySensor::initialize()
{
	try
	{
		connect();
	}
	catch (const std::exception& e)
	{
		m_state = ssError;
		throw std::runtime_error(
			"TcpOdometrySensor: cannot connect to the robot base at " + m_host + ":" +
			std::to_string(m_port) + ": " + mrpt::exception_to_str(e));
	}
}

void TcpOdometrySensor::doProcess()
{
	if (!m_socket || !m_socket->isConnected())
	{
		m_state = ssError;
		if (std::chrono::steady_clock::now() - m_lastAttempt < std::chrono::milliseconds(500))
		{
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
			return;
		}
		try
		{
			connect();
			m_reconnections++;
			std::fprintf(stderr, "[%s] TcpOdometrySensor: reconnected to %s:%d\n",
				m_sensorLabel.c_str(), m_host.c_str(), m_port);
		}
		catch (const std::exception&)
		{
			return;	 // not yet: try again in half a second
		}
	}
	char buf[4096];
	const size_t n = m_socket->readAsync(buf, sizeof(buf), 50, 1);
	m_pending.append(buf, n);
	for (size_t lf; (lf = m_pending.find('\n')) != std::string::npos;)
	{
		const std::string line = m_pending.substr(0, lf);
		m_pending.erase(0, lf + 1);
		onLine(line);
	}
	if (m_pending.size() > 4096)
	{
		// No line end in 4 kB: not the protocol.
		m_malformed++;
		std::fprintf(stderr, "[%s] TcpOdometrySensor: no line end in 4096 bytes from %s:%d\n",
			m_sensorLabel.c_str(), m_host.c_str(), m_port);
		m_pending.clear();
	}
}

void TcpOdometrySensor::onLine(const std::string& text)
{
	std::optional<OdometryLine> line;
	try
	{
		line = OdometryLine::parse(text);
	}
	catch (const InputError& e)
	{
		m_malformed++;
		std::fprintf(stderr, "[%s] TcpOdometrySensor: %s (skipped)\n", m_sensorLabel.c_str(), e.what());
		return;
	}
	if (!line) return;
	const double arrival = mrpt::Clock::toDouble(mrpt::Clock::now());
	const double offset = arrival - line->time;
	m_clockOffset = m_clockOffset ? std::min(*m_clockOffset, offset) : offset;
	// Strictly increasing stamps, even if the offset estimate improves.
	const double stamp = std::max(line->time + *m_clockOffset, m_lastStamp + 1e-6);
	m_lastStamp = stamp;

	auto obs = mrpt::obs::CObservationOdometry::Create();
	obs->sensorLabel = m_sensorLabel;
	obs->timestamp = mrpt::Clock::fromDouble(stamp);
	obs->odometry = line->pose;
	obs->hasVelocities = line->hasVelocities;
	obs->velocityLocal.vx = line->v;
	obs->velocityLocal.omega = line->w;
	appendObservation(obs);
}
}  // namespace featloc
