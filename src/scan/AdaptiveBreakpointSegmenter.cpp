#include "featloc/scan/AdaptiveBreakpointSegmenter.h"

#include <algorithm>
#include <cmath>

#include "featloc/config/ConfigValues.h"
#include "featloc/scan/PointNoiseEstimator.h"

namespace featloc
{
void AdaptiveBreakpointSegmenter::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readDegrees(c, s, "breakpoint_lambda_DEG", lambda);
	read(c, s, "breakpoint_sigma_r", sigma_r);
	read(c, s, "breakpoint_at_missing_returns", breakAtMissingReturns);
	read(c, s, "breakpoint_sigma_r_from_scan", sigmaFromScan);
	require(lambda > 0 && lambda < M_PI / 2, c, s, "breakpoint_lambda_DEG",
		"in (0, 90) degrees");
	require(sigma_r >= 0, c, s, "breakpoint_sigma_r", ">= 0");
}

void AdaptiveBreakpointSegmenter::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	writeDegrees(c, s, "breakpoint_lambda_DEG", lambda,
		"[deg] segmentation, eq. (3): most grazing incidence of a surface");
	write(c, s, "breakpoint_sigma_r", sigma_r,
		"[m] segmentation, eq. (3): range noise sigma_r");
	write(c, s, "breakpoint_at_missing_returns", breakAtMissingReturns,
		"segmentation: a beam without a return between two points is a breakpoint (false: the paper's eq. (3) alone)");
	write(c, s, "breakpoint_sigma_r_from_scan", sigmaFromScan,
		"segmentation: sigma_r is at least the scan's own range noise, estimated from its points (false: breakpoint_sigma_r alone, the paper)");
}

bool AdaptiveBreakpointSegmenter::isBreakpoint(const ScanPoint& a, const ScanPoint& b) const
{
	const double dphi = std::abs(b.bearing - a.bearing);
	if (dphi >= params.lambda) return true;
	if (params.breakAtMissingReturns && b.beam > a.beam + 1) return true;
	// The ratio depends on dphi only, which is the scan's angular step for
	// most neighbours: computed once for it.
	if (dphi != m_lastDphi)
	{
		m_lastDphi = dphi;
		m_lastRatio = std::sin(dphi) / std::sin(params.lambda - dphi);
	}
	const double bound = a.range * m_lastRatio + 3 * lastSigmaR();
	const double dx = b.x - a.x, dy = b.y - a.y;
	return dx * dx + dy * dy > bound * bound;
}

void AdaptiveBreakpointSegmenter::segment(
	const ScanPoints& points, std::vector<ScanSegment>& out) const
{
	m_lastDphi = -1;  // params may have changed
	out.clear();
	const size_t n = points.size();
	m_sigmaR = params.sigma_r;
	if (n == 0) return;
	if (params.sigmaFromScan && n >= 3)
	{
		const std::vector<ScanSegment> whole{{0, static_cast<uint32_t>(n - 1)}};
		m_sigmaR = std::max(m_sigmaR,
			PointNoiseEstimator().rangeNoise(points.points, whole, PointNoiseEstimator::kRangeNoiseChord));
	}
	ScanSegment cur;
	cur.first = 0;
	for (size_t i = 1; i < n; i++)
	{
		if (isBreakpoint(points[i - 1], points[i]))
		{
			cur.last = static_cast<uint32_t>(i - 1);
			out.push_back(cur);
			cur.first = static_cast<uint32_t>(i);
		}
	}
	cur.last = static_cast<uint32_t>(n - 1);
	out.push_back(cur);
}
}  // namespace featloc
