#include "featloc/localization/MapScanTracker.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <chrono>

namespace featloc
{
MapScanTracker::MapScanTracker(
	std::shared_ptr<const LocalizationMap> map, ScanMatcher::Ptr matcher, LocalizationOptions options)
	: m_map(std::move(map)), m_matcher(std::move(matcher)), m_options(std::move(options))
{
}

MapScanTracker::Result MapScanTracker::track(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPosePDFGaussian& predicted)
{
	const auto t0 = std::chrono::steady_clock::now();
	Result r;
	const mrpt::obs::CObservation2DRangeScan reference = m_map->virtualScan(scan, predicted.mean);
	for (size_t i = 0; i < reference.getScanSize(); i++)
		r.mapBeams += reference.getScanRangeValidity(i) ? 1 : 0;
	const double yaw = predicted.mean.phi();
	// The prediction's covariance in its own robot frame.
	mrpt::poses::CPosePDFGaussian guess(mrpt::poses::CPose2D(), predicted.cov);
	guess.rotateCov(-yaw);
	r.match = m_matcher->match(reference, scan, guess);
	r.match.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (!r.match.success) return r;
	r.pose.mean = predicted.mean + r.match.estimate.mean;
	r.pose.cov = r.match.estimate.cov;
	r.pose.rotateCov(yaw);	// back into the map frame
	r.pose.cov *= m_options.covariance_scale;
	r.pose.cov(0, 0) += m_options.map_sigma_xy * m_options.map_sigma_xy;
	r.pose.cov(1, 1) += m_options.map_sigma_xy * m_options.map_sigma_xy;
	r.pose.cov(2, 2) += m_options.map_sigma_yaw * m_options.map_sigma_yaw;
	return r;
}
}  // namespace featloc
