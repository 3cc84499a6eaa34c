#include "featloc/localization/GlobalMapSearch.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <opencv2/core.hpp>

#include "featloc/math/PoseDifference.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
GlobalMapSearch::GlobalMapSearch(const LocalizationMap& map, const Options& options)
	: m_options(options)
{
	const auto& cells = map.occupiedCells();
	double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
	for (const auto& p : cells)
	{
		xmin = std::min(xmin, p.x);
		xmax = std::max(xmax, p.x);
		ymin = std::min(ymin, p.y);
		ymax = std::max(ymax, p.y);
	}
	m_cx = 0.5 * (xmin + xmax);
	m_cy = 0.5 * (ymin + ymax);
	m_nx = static_cast<int>(std::ceil(0.5 * (xmax - xmin) / m_options.resolution));
	m_ny = static_cast<int>(std::ceil(0.5 * (ymax - ymin) / m_options.resolution));
	// Every pose searched is inside the map's box; a block's bound reads up
	// to one top-level block beyond a point's cell: the table covers the
	// box, a margin of the table's width and one top-level block.
	auto build = [&](CorrelationTables& t, double res, double hitSigma, int top) {
		const double margin = 3 * hitSigma + static_cast<double>(1 << top) * res;
		// Half a table cell more: a map cell's centre then falls on a table
		// cell's centre when the two have the same size, instead of on an
		// edge, where rounding put some of a wall's cells one cell off
		// (holes, and a wall shifted by half a cell).
		const double x0 = xmin - margin - 0.5 * res, y0 = ymin - margin - 0.5 * res;
		const int width = static_cast<int>(std::ceil((xmax + margin - x0) / res)) + 1;
		const int height = static_cast<int>(std::ceil((ymax + margin - y0) / res)) + 1;
		t.build(width, height, x0, y0, res, hitSigma, top, [&](cv::Mat& surface) {
			for (const auto& p : cells)
				surface.at<uint8_t>(static_cast<int>(std::floor((p.y - y0) / res)),
					static_cast<int>(std::floor((p.x - x0) / res))) = 0;
		});
	};
	build(m_tables, m_options.resolution, m_options.hitSigma, CorrelationTables::kMaxLevel);
	// refine() searches a few cells around a hypothesis: three levels.
	build(m_sharp, m_options.refineResolution, m_options.refineHitSigma, 3);
}

void GlobalMapSearch::robotFramePoints(
	const mrpt::obs::CObservation2DRangeScan& scan, std::vector<double>& x, std::vector<double>& y) const
{
	x.clear();
	y.clear();
	const ScanPoints pts = ScanPoints::fromScan(scan);
	const mrpt::poses::CPose2D sensor(scan.sensorPose);
	const size_t n = pts.size(), m = std::min<size_t>(n, m_options.maxPoints);
	for (size_t k = 0; k < m; k++)
	{
		const auto& p = pts.points[k * n / m];
		double gx = 0, gy = 0;
		sensor.composePoint(p.x, p.y, gx, gy);
		x.push_back(gx);
		y.push_back(gy);
	}
}

GlobalMapSearch::Local GlobalMapSearch::refine(const mrpt::obs::CObservation2DRangeScan& scan,
	const mrpt::poses::CPose2D& around, double halfXY, double halfYaw) const
{
	Local out{around, 0};
	std::vector<double> x, y;
	robotFramePoints(scan, x, y);
	if (x.size() < 10) return out;
	CorrelationTables::Window w;
	w.centre = around;
	w.yawStep = CorrelationTables::rotationStep(x, y, m_sharp.resolution());
	w.nx = w.ny = static_cast<int>(std::ceil(halfXY / m_sharp.resolution()));
	w.nYaw = static_cast<int>(std::ceil(halfYaw / w.yawStep));
	const auto best = m_sharp.search(x, y, w, 1.0);
	if (best.empty()) return out;
	out.pose = best.front().pose;
	out.pose.normalizePhi();
	out.score = best.front().score;
	return out;
}

std::vector<double> GlobalMapSearch::beamHits(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& pose) const
{
	std::vector<double> out;
	const mrpt::poses::CPose2D sensor = pose + mrpt::poses::CPose2D(scan.sensorPose);
	const double k = -0.5 / (m_options.refineHitSigma * m_options.refineHitSigma);
	const size_t n = scan.getScanSize();
	for (size_t i = 0; i < n; i++)
	{
		if (!ScanPoints::hasReturn(scan, i)) continue;
		const double r = scan.getScanRange(i);
		const double bearing = scan.getScanAngle(i);
		double x = 0, y = 0;
		sensor.composePoint(r * std::cos(bearing), r * std::sin(bearing), x, y);
		const double d = m_sharp.distanceAt(x, y);
		out.push_back(d >= 0 ? std::exp(k * d * d) : 0.0);
	}
	return out;
}

GlobalMapSearch::Result GlobalMapSearch::search(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	const auto t0 = std::chrono::steady_clock::now();
	Result r;
	std::vector<double> x, y;
	robotFramePoints(scan, x, y);
	if (x.size() < 10) return r;
	CorrelationTables::Window w;
	w.centre = mrpt::poses::CPose2D(m_cx, m_cy, 0);
	w.nx = m_nx;
	w.ny = m_ny;
	w.yawStep = CorrelationTables::rotationStep(x, y, m_tables.resolution());
	w.nYaw = static_cast<int>(std::ceil(M_PI / w.yawStep));
	const auto best = m_tables.search(x, y, w, 1.0);
	if (best.empty()) return r;
	r.valid = true;
	r.best = best.front().pose;
	r.best.normalizePhi();
	r.bestScore = best.front().score;
	// Every pose away from the best that scores nearly as well, best first;
	// of those, the distinct places (a look-alike room each).
	const auto others = m_tables.search(x, y, w,
		m_options.maxContenders > 0 ? m_options.contenderRatio : 1.0,
		[&](const mrpt::poses::CPose2D& p) {
			return posesWithin(p, r.best, m_options.distinctXY, m_options.distinctYaw);
		});
	std::vector<CorrelationTables::Candidate> places;  // the rival, then the contenders
	for (const auto& c : others)
	{
		if (places.size() > m_options.maxContenders) break;
		bool distinct = true;
		for (const auto& k : places)
			distinct = distinct && !posesWithin(c.pose, k.pose, m_options.distinctXY, m_options.distinctYaw);
		if (!distinct) continue;
		places.push_back(c);
		places.back().pose.normalizePhi();
	}
	if (!places.empty())
	{
		r.rival = places.front().pose;
		r.rivalScore = places.front().score;
		r.contenders.assign(places.begin() + 1, places.end());
	}
	r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return r;
}
}  // namespace featloc
