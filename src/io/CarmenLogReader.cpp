#include "featloc/io/CarmenLogReader.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/filesystem.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/io/InputOptions.h"

namespace featloc
{
namespace
{
std::string readAll(const std::string& path)
{
	if (!mrpt::system::fileExists(path))
		throw InputError("CARMEN log '" + path + "' does not exist");
	mrpt::io::CFileGZInputStream in;	// reads gzip and plain files alike
	if (!in.open(path)) throw InputError("CARMEN log '" + path + "' cannot be opened");
	std::string data;
	char buf[65536];
	for (size_t n; (n = in.Read(buf, sizeof(buf))) > 0;) data.append(buf, n);
	return data;
}

double number(const std::string& tok, const std::string& where)
{
	char* end = nullptr;
	const double v = std::strtod(tok.c_str(), &end);
	if (end != tok.c_str() + tok.size() || !std::isfinite(v))
		throw InputError(where + ": '" + tok + "' is not a number");
	return v;
}
}  // namespace

CarmenLogReader::Options CarmenLogReader::Options::from(const InputOptions& input)
{
	Options o;
	o.beamAngles = input.carmen_beam_angles;
	return o;
}

void CarmenLogReader::beamAngles(
	size_t n, const std::string& convention, double& step, double& first)
{
	first = -0.5 * M_PI;
	step = M_PI / static_cast<double>(n - 1);
	if (convention != "sick") return;
	// A SICK LMS scans at 1, 0.5 or 0.25 deg. A log of 180 or 360 beams
	// over its 180 deg has them one step apart from -90 deg: with 180 / (n
	// - 1) deg, every match on edmonton and fhw (180 beams) turned 0.5%
	// more than the corrected poses and went 0.6-0.8 deg to the left of
	// their direction of travel (freiburg-101, 360 beams: 0.3%, 0.3 deg);
	// 181 and 361 beams did neither.
	for (const double deg : {1.0, 0.5, 0.25})
		if (std::abs(180.0 / static_cast<double>(n) - deg) < 1e-9)
		{
			step = mrpt::DEG2RAD(deg);
			return;
		}
}

std::vector<CarmenScan> CarmenLogReader::read(const std::string& path, const Options& options)
{
	std::istringstream lines(readAll(path));
	std::vector<CarmenScan> out;
	double laserOffset = 0;
	// The ODOM chain (class comment): `chain` accumulates the increments
	// between consecutive ODOM messages, anchors excepted.
	std::optional<mrpt::poses::CPose2D> lastOdom;
	mrpt::poses::CPose2D chain;
	size_t odomSinceScan = 0;
	// The pose of the scan just read, until the next ODOM message.
	bool anchorPossible = false;
	mrpt::math::TPose2D anchorAt;
	std::string line;
	for (size_t lineNo = 1; std::getline(lines, line); lineNo++)
	{
		std::istringstream in(line);
		std::vector<std::string> tok;
		for (std::string t; in >> t;) tok.push_back(t);
		if (tok.empty()) continue;
		const std::string where = path + ":" + std::to_string(lineNo);
		if (tok[0] == "PARAM" && tok.size() >= 3 && tok[1] == "robot_frontlaser_offset")
			laserOffset = number(tok[2], where);
		if (tok[0] == "ODOM")
		{
			if (tok.size() < 4) throw InputError(where + ": ODOM needs x y theta");
			const mrpt::math::TPose2D read{
				number(tok[1], where), number(tok[2], where), number(tok[3], where)};
			const bool anchor = anchorPossible && anchorAt == read;
			const mrpt::poses::CPose2D odom(read);
			if (!anchor && lastOdom)
			{
				chain = chain + (odom - *lastOdom);
				odomSinceScan++;
			}
			else if (!anchor && out.empty())
				chain = odom;  // the stream starts before the first scan
			// else: an anchor, or a stream that starts after the first scan
			// (this message is its base: no motion known before it).
			lastOdom = odom;
			anchorPossible = false;
			continue;
		}
		if (tok[0] != "FLASER") continue;
		if (tok.size() < 2) throw InputError(where + ": FLASER without a range count");
		const double nd = number(tok[1], where);
		if (nd < 2 || nd != std::floor(nd) || nd > 100000)
			throw InputError(where + ": bad range count '" + tok[1] + "'");
		const size_t n = static_cast<size_t>(nd);
		if (tok.size() < 2 + n + 9)
			throw InputError(
				where + ": FLASER with " + std::to_string(n) + " ranges needs " +
				std::to_string(2 + n + 9) + " fields, found " + std::to_string(tok.size()));
		CarmenScan s;
		s.line = lineNo;
		auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
		scan->sensorLabel = options.label;
		// MRPT's beams span the aperture symmetrically about the sensor's
		// heading: a fan that starts at `first` is turned by its middle.
		double step = 0, first = 0;
		beamAngles(n, options.beamAngles, step, first);
		const double aperture = step * static_cast<double>(n - 1);
		scan->aperture = static_cast<float>(aperture);
		scan->rightToLeft = true;
		scan->maxRange = static_cast<float>(options.maxRange);
		scan->sensorPose = mrpt::poses::CPose3D(laserOffset, 0, 0, first + 0.5 * aperture, 0, 0);
		scan->resizeScan(n);
		for (size_t i = 0; i < n; i++)
		{
			const double r = number(tok[2 + i], where);
			const bool valid = r > 0 && r < options.maxRange;
			scan->setScanRange(i, static_cast<float>(valid ? r : options.maxRange));
			scan->setScanRangeValidity(i, valid);
		}
		const size_t p = 2 + n;
		s.pose = {number(tok[p], where), number(tok[p + 1], where), number(tok[p + 2], where)};
		s.odometry = {number(tok[p + 3], where), number(tok[p + 4], where),
			number(tok[p + 5], where)};
		s.time = number(tok[p + 8], where);
		if (odomSinceScan > 0 || out.empty()) s.odomMessages = chain.asTPose();
		odomSinceScan = 0;
		anchorAt = s.pose;
		anchorPossible = true;
		scan->timestamp = mrpt::Clock::fromDouble(s.time);
		s.scan = scan;
		out.push_back(std::move(s));
	}
	if (out.empty()) throw InputError("CARMEN log '" + path + "' has no FLASER message");
	return out;
}
}  // namespace featloc
