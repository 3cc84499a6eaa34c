#include "featloc/stereo/SegmentTriangulator.h"

#include <cmath>

#include "featloc/core/InputError.h"

namespace featloc
{
SegmentTriangulator SegmentTriangulator::fromCalibration(const mrpt::img::TStereoCamera& c, const std::string& where)
{
	SegmentTriangulator t;
	t.fx = c.leftCamera.fx();
	t.fy = c.leftCamera.fy();
	t.cx = c.leftCamera.cx();
	t.cy = c.leftCamera.cy();
	const auto& rp = c.rightCameraPose;
	t.baseline = std::sqrt(rp.x * rp.x + rp.y * rp.y + rp.z * rp.z);
	if (!(t.fx > 0 && t.fy > 0 && t.baseline > 0))
		throw InputError(where + ": stereo observation without a usable calibration");
	return t;
}

Eigen::Vector3d SegmentTriangulator::point(double ul, double ur, double v, Eigen::Matrix3d* J) const
{
	const double d = ul - ur;
	const double k = baseline / d;	// B / d
	const Eigen::Vector3d p((ul - cx) * k, (v - cy) * fx / fy * k, fx * k);
	if (J)
	{
		// d k / d ul = -k / d, d k / d ur = +k / d.
		const double dk = k / d;
		*J << k - (ul - cx) * dk, (ul - cx) * dk, 0,  //
			-(v - cy) * fx / fy * dk, (v - cy) * fx / fy * dk, fx / fy * k,	 //
			-fx * dk, fx * dk, 0;
	}
	return p;
}

TriangulatedSegment SegmentTriangulator::triangulate(
	const VerticalSegment& l, const VerticalSegment& r, const SegmentMatch& m) const
{
	const Eigen::Vector3d s2(sigmaColumn * sigmaColumn, sigmaColumn * sigmaColumn, sigmaRow * sigmaRow);
	auto at = [&](double v, Eigen::Vector3d& p, Eigen::Matrix3d& cov, double rowVariance)
	{
		Eigen::Matrix3d J;
		p = point(l.uAt(v), r.uAt(v), v, &J);
		Eigen::Vector3d var = s2;
		var(2) = rowVariance;
		cov = J * var.asDiagonal() * J.transpose();
	};
	TriangulatedSegment t;
	at(m.vLow, t.top, t.covTop, s2(2));
	at(m.vHigh, t.bottom, t.covBottom, s2(2));
	at(0.5 * (m.vLow + m.vHigh), t.middle, t.covMiddle, 0);	 // the middle row is chosen, not measured
	return t;
}
}  // namespace featloc
