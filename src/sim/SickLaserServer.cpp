#include "featloc/sim/SickLaserServer.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace featloc
{
namespace
{
constexpr char kStx = 0x02, kEtx = 0x03;

/** CoLa-A numbers: upper-case hex, no leading zeros; negative values as
 * their 32-bit two's complement (the start angle -45 deg is FFF92230). */
std::string hex(int64_t value)
{
	char buf[16];
	std::snprintf(buf, sizeof(buf), "%X", static_cast<uint32_t>(value));
	return buf;
}

bool startsWith(const std::string& s, const std::string& prefix)
{
	return s.compare(0, prefix.size(), prefix) == 0;
}
}  // namespace

SickLaserServer::Device SickLaserServer::deviceFor(size_t beams, double aperture, double rate)
{
	if (beams < 2 || !(aperture > 0) || aperture > 2 * M_PI || !(rate > 0))
		throw std::invalid_argument("a SICK LMS1xx needs at least 2 beams over (0, 360] deg at a rate > 0");
	const double stepUnits = aperture * 180 / M_PI / static_cast<double>(beams - 1) * 1e4;
	if (std::abs(stepUnits - std::round(stepUnits)) > 1e-3 * stepUnits)
		throw std::invalid_argument("the scan's beam step (" + std::to_string(stepUnits / 1e4) +
			" deg) is not a whole number of 1/10000 deg: CoLa-A cannot describe it");
	Device d;
	d.resolution = static_cast<int>(std::lround(stepUnits));
	d.frequency = static_cast<int>(std::lround(rate * 100));
	// SICK's frame: 90 deg straight ahead, the field centred on it.
	const int half = d.resolution * static_cast<int>(beams - 1) / 2;
	d.startAngle = 900000 - half;
	d.stopAngle = d.startAngle + d.resolution * static_cast<int>(beams - 1);
	return d;
}

SickLaserServer::SickLaserServer(Device device, unsigned short port)
	: EmulatedLaser(port, false), m_device(device)
{
	startServing();
}

SickLaserServer::~SickLaserServer() { stopServing(); }

std::string SickLaserServer::frame(const std::string& telegram)
{
	return std::string(1, kStx) + telegram + std::string(1, kEtx);
}

std::string SickLaserServer::configurationMismatch() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	return m_mismatch;
}

void SickLaserServer::onConnectionChange()
{
	m_measuring = false;
	m_pollWaiting = false;
}

void SickLaserServer::onBytes(std::string& pending)
{
	for (;;)
	{
		const size_t stx = pending.find(kStx);
		if (stx == std::string::npos)
		{
			pending.clear();  // bytes outside a frame: the device ignores them
			return;
		}
		const size_t etx = pending.find(kEtx, stx);
		if (etx == std::string::npos)
		{
			pending.erase(0, stx);	// a frame still arriving
			return;
		}
		const std::string command = pending.substr(stx + 1, etx - stx - 1);
		pending.erase(0, etx + 1);
		handleCommand(command);
	}
}

void SickLaserServer::handleCommand(const std::string& cmd)
{
	const Device& d = m_device;
	if (startsWith(cmd, "sMN SetAccessMode"))
		send(frame("sAN SetAccessMode 1"));
	else if (startsWith(cmd, "sMN mLMPsetscancfg"))
	{
		// +frequency +sectors +resolution +start +stop, decimal with signs.
		std::istringstream in(cmd.substr(18));
		long freq = 0, sectors = 0, res = 0, start = 0, stop = 0;
		in >> freq >> sectors >> res >> start >> stop;
		const bool area = start != d.startAngle || stop != d.stopAngle;
		int status = 0;	 // SICK: 1 frequency, 2 resolution, 3 both, 4 area, 5 other
		if (!in || sectors != 1)
			status = 5;
		else if (freq != d.frequency)
			status = 1;
		else if (res != d.resolution)
			status = area ? 3 : 2;
		else if (area)
			status = 4;
		if (status != 0)
			m_mismatch = "the driver asked '" + cmd.substr(4) + "'; the simulated scanner is " +
				std::to_string(d.frequency / 100.0) + " Hz, " + std::to_string(d.resolution / 1e4) +
				" deg from " + std::to_string(d.startAngle / 1e4) + " to " +
				std::to_string(d.stopAngle / 1e4) + " deg (SICK's frame)";
		send(frame("sAN mLMPsetscancfg " + std::to_string(status) + " " + hex(d.frequency) +
			" 1 " + hex(d.resolution) + " " + hex(d.startAngle) + " " + hex(d.stopAngle)));
	}
	else if (startsWith(cmd, "sWN LMDscandatacfg"))
		send(frame("sWA LMDscandatacfg"));
	else if (cmd == "sMN LMCstartmeas")
	{
		m_measuring = true;
		send(frame("sAN LMCstartmeas 0"));
	}
	else if (cmd == "sMN LMCstopmeas")
	{
		m_measuring = false;
		send(frame("sAN LMCstopmeas 0"));
	}
	else if (cmd == "sRN STlms")
		// Status 7: ready for measurement (3 while not measuring).
		send(frame(std::string("sRA STlms ") + (m_measuring ? "7" : "3") +
			" 0 8 00:00:00 8 01.01.2000 0 0 0"));
	else if (cmd == "sMN Run")
		send(frame("sAN Run 1"));
	else if (cmd == "sRN LMDscandata" && m_measuring)
	{
		m_streaming = true;
		if (m_latest.empty())
			m_pollWaiting = true;  // answered with the first scan
		else
			sendScan();
	}
	else
		send(frame("sFA 1"));  // CoLa-A: method or variable unknown / not now
}

bool SickLaserServer::sendScan()
{
	if (m_garbageNext)
	{
		m_garbageNext = false;
		// A damaged telegram: its name garbled and cut short. (Merely cut
		// short is not enough: CLMS100Eth parses a buffer it does not
		// terminate, so it reads the previous telegram's tail as a scan.)
		return send(frame("sRA LMDsc#ndata 1 1 FEA7"));
	}
	// m_latest holds everything after the telegram counter.
	const std::string telegram =
		"sRA LMDscandata 1 1 FEA7 0 0 " + hex(++m_telegrams) + " " + m_latest;
	if (!send(frame(telegram))) return false;
	if (m_latestSent)
		m_scansResent++;
	else
		m_scansSent++;
	m_latestSent = true;
	return true;
}

bool SickLaserServer::publish(const std::vector<float>& ranges, uint32_t deviceTimeMs)
{
	const Device& d = m_device;
	if (static_cast<int>(ranges.size()) != d.beams())
		throw std::invalid_argument("SICK laser emulator: a scan of " +
			std::to_string(ranges.size()) + " ranges for a device of " +
			std::to_string(d.beams()) + " beams");
	const uint32_t us = deviceTimeMs * 1000u;
	// Scan counter, time since start-up and of transmission [us], digital
	// inputs and outputs, reserved, scan and measurement frequency, no
	// encoder, one 16-bit channel: DIST1, scale 1.0, offset 0, start angle,
	// step, count, the distances [mm], then no 8-bit channel, position,
	// name, comment, time or event.
	const long measurement = std::lround(360e4 / d.resolution * d.frequency / 100.0 / 100.0);
	std::string t = hex(++m_scans) + " " + hex(us) + " " + hex(us) + " 0 0 0 0 0 " +
		hex(d.frequency) + " " + hex(measurement) + " 0 1 DIST1 3F800000 00000000 " +
		hex(d.startAngle) + " " + hex(d.resolution) + " " + hex(d.beams());
	t.reserve(t.size() + ranges.size() * 5 + 16);
	for (float r : ranges)
	{
		const bool valid = std::isfinite(r) && r > 0;
		t += " " + hex(valid ? std::min<long>(std::lround(r * 1000.0), 0xFFFF) : 0);
	}
	t += " 0 0 0 0 0 0";
	std::lock_guard<std::mutex> lock(m_mutex);
	m_latest = std::move(t);
	m_latestSent = false;
	if (m_pollWaiting && m_client >= 0 && !m_silent)
	{
		m_pollWaiting = false;
		sendScan();
	}
	return m_streaming && m_client >= 0 && !m_silent;
}

bool SickLaserServer::publishGarbage(uint32_t)
{
	std::lock_guard<std::mutex> lock(m_mutex);
	m_garbageNext = true;
	return m_streaming && m_client >= 0;
}
}  // namespace featloc
