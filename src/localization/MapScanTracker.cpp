#include "featloc/localization/MapScanTracker.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <Eigen/Dense>
#include <chrono>

namespace featloc
{
namespace
{
/** R C R^T with R the rotation by `yaw` on (x, y) (yaw kept). */
mrpt::math::CMatrixDouble33 rotated(const mrpt::math::CMatrixDouble33& c, double yaw)
{
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	R.topLeftCorner<2, 2>() = Eigen::Rotation2Dd(yaw).toRotationMatrix();
	return mrpt::math::CMatrixDouble33(R * c.asEigen() * R.transpose());
}
}  // namespace

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
	const mrpt::poses::CPosePDFGaussian guess(mrpt::poses::CPose2D(), rotated(predicted.cov, -yaw));
	r.match = m_matcher->match(reference, scan, guess);
	r.match.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (!r.match.success) return r;
	r.pose.mean = predicted.mean + r.match.estimate.mean;
	r.pose.cov = rotated(r.match.estimate.cov, yaw);
	r.pose.cov *= m_options.covariance_scale;
	r.pose.cov(0, 0) += m_options.map_sigma_xy * m_options.map_sigma_xy;
	r.pose.cov(1, 1) += m_options.map_sigma_xy * m_options.map_sigma_xy;
	r.pose.cov(2, 2) += m_options.map_sigma_yaw * m_options.map_sigma_yaw;
	return r;
}
}  // namespace featloc
