#include "featloc/sim/ScipLaserServer.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace featloc
{
namespace
{
// SCIP 2.0: sum = (sum of the bytes & 0x3F) + 0x30.
char checksum(const std::string& bytes)
{
	unsigned sum = 0;
	for (unsigned char c : bytes) sum += c;
	return static_cast<char>((sum & 0x3F) + 0x30);
}

std::string dataLine(const std::string& data) { return data + checksum(data) + "\n"; }

// A PP / VV parameter: "NAME:value;sum", the sum over the bytes before ';'.
std::string parameterLine(const std::string& nameValue)
{
	return nameValue + ";" + checksum(nameValue) + "\n";
}

// A value in n characters of 6 bits each, most significant first.
std::string encode(uint32_t value, int n)
{
	std::string out(static_cast<size_t>(n), '0');
	for (int i = n - 1; i >= 0; i--, value >>= 6)
		out[static_cast<size_t>(i)] = static_cast<char>((value & 0x3F) + 0x30);
	return out;
}

std::string reply(const std::string& echo, const std::string& status, const std::string& data = "")
{
	return echo + "\n" + dataLine(status) + data + "\n";
}

int field(const std::string& s, size_t pos, size_t len)
{
	try
	{
		return std::stoi(s.substr(pos, len));
	}
	catch (const std::exception&)
	{
		return -1;
	}
}
}  // namespace

ScipLaserServer::Device ScipLaserServer::deviceFor(
	size_t beams, double aperture, double maxRange, int rate)
{
	if (beams < 2 || !(aperture > 0) || aperture > 2 * M_PI)
		throw std::invalid_argument("a SCIP scanner needs at least 2 beams over an aperture in (0, 360] deg");
	const double step = aperture / static_cast<double>(beams - 1);
	const double ares = 2 * M_PI / step;
	if (std::abs(ares - std::round(ares)) > 1e-3 * ares)
		throw std::invalid_argument(
			"the scan's beam step (" + std::to_string(step * 180 / M_PI) +
			" deg) is not 360 deg / an integer: SCIP cannot describe it");
	Device d;
	d.ares = static_cast<int>(std::lround(ares));
	d.amin = 0;
	d.amax = static_cast<int>(beams) - 1;
	d.afrt = d.amax / 2;
	d.dmaxMm = static_cast<int>(std::lround(maxRange * 1000));
	d.scanRpm = rate * 60;
	return d;
}

ScipLaserServer::ScipLaserServer(Device device, unsigned short port, Fault fault)
	: EmulatedLaser(port, fault == Fault::Silent), m_device(std::move(device))
{
	startServing();
}

ScipLaserServer::~ScipLaserServer() { stopServing(); }

void ScipLaserServer::onConnectionChange() { m_sessionScans = m_quitScans = 0; }

void ScipLaserServer::onBytes(std::string& pending)
{
	for (size_t lf; (lf = pending.find('\n')) != std::string::npos;)
	{
		std::string command = pending.substr(0, lf);
		pending.erase(0, lf + 1);
		if (!command.empty() && command.back() == '\r') command.pop_back();
		handleCommand(command);
	}
}

void ScipLaserServer::handleCommand(const std::string& cmd)
{
	const Device& d = m_device;
	const std::string name = cmd.substr(0, 2);
	if (cmd.empty())
		return;	 // a bare LF: SCIP ignores it
	else if (name == "QT")
	{
		if (m_streaming) m_quitScans = m_sessionScans;	// the driver sends QT twice
		m_sessionScans = 0;
		m_streaming = false;
		send(reply(cmd, "00"));
	}
	else if (cmd == "SCIP2.0" || name == "BM" || name == "HS" || name == "CR" || name == "SS" ||
		name == "RS" || name == "TM")
		send(reply(cmd, "00"));
	else if (name == "PP")
		send(reply(cmd, "00",
			parameterLine("MODL:" + d.model) + parameterLine("DMIN:" + std::to_string(d.dminMm)) +
				parameterLine("DMAX:" + std::to_string(d.dmaxMm)) +
				parameterLine("ARES:" + std::to_string(d.ares)) +
				parameterLine("AMIN:" + std::to_string(d.amin)) +
				parameterLine("AMAX:" + std::to_string(d.amax)) +
				parameterLine("AFRT:" + std::to_string(d.afrt)) +
				parameterLine("SCAN:" + std::to_string(d.scanRpm))));
	else if (name == "VV")
		send(reply(cmd, "00",
			parameterLine("VEND:Hokuyo Automatic Co.,Ltd. (featloc emulator)") +
				parameterLine("PROD:" + d.model) + parameterLine("FIRM:featloc-sim") +
				parameterLine("PROT:SCIP 2.0") + parameterLine("SERI:FEATLOC0")));
	else if (name == "MD" && cmd.size() == 15)
	{
		// MD ssss eeee cc s nn: start and end step, cluster 01, the whole
		// field of view this emulator serves.
		const int start = field(cmd, 2, 4), end = field(cmd, 6, 4), cluster = field(cmd, 10, 2);
		if (start != d.amin || end != d.amax || cluster != 1)
		{
			send(reply(cmd, "10"));	 // SCIP: invalid start/end step
			return;
		}
		m_mdEcho = cmd;
		m_scansDiscardedByReinit += m_quitScans;	// QT then MD: a re-initialisation
		m_quitScans = m_sessionScans = 0;
		if (send(reply(cmd, "00"))) m_streaming = true;
	}
	else
		send(reply(cmd, "0E"));	 // SCIP: unknown command
}

bool ScipLaserServer::publish(const std::vector<float>& ranges, uint32_t deviceTimeMs)
{
	std::lock_guard<std::mutex> lock(m_mutex);
	if (!m_streaming || m_client < 0 || m_silent) return false;
	const size_t beams = static_cast<size_t>(m_device.amax - m_device.amin + 1);
	if (ranges.size() != beams)
		throw std::invalid_argument(
			"SCIP laser emulator: a scan of " + std::to_string(ranges.size()) +
			" ranges for a device of " + std::to_string(beams) + " beams");
	std::string data;
	data.reserve(beams * 3);
	for (float r : ranges)
	{
		// Codes below 20 mm are the device's error codes: 1 = no return.
		const bool valid = std::isfinite(r) && r > 0;
		const uint32_t mm = valid ? static_cast<uint32_t>(std::lround(r * 1000.0)) : 1;
		data += encode(std::min<uint32_t>(mm, (1u << 18) - 1), 3);
	}
	std::string body = dataLine(encode(deviceTimeMs & 0xFFFFFF, 4));
	for (size_t i = 0; i < data.size(); i += 64) body += dataLine(data.substr(i, 64));
	if (!send(reply(m_mdEcho, "99", body))) return false;
	m_scansSent++;
	m_sessionScans++;
	return true;
}

bool ScipLaserServer::publishGarbage(uint32_t deviceTimeMs)
{
	std::lock_guard<std::mutex> lock(m_mutex);
	if (!m_streaming || m_client < 0) return false;
	// A frame cut short: the timestamp and 17 ranges of 1081.
	const std::string body =
		dataLine(encode(deviceTimeMs & 0xFFFFFF, 4)) + dataLine(std::string(51, '0'));
	return send(reply(m_mdEcho, "99", body));
}
}  // namespace featloc
