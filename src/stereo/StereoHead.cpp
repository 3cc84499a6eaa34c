#include "featloc/stereo/StereoHead.h"

#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

#include "featloc/core/InputError.h"
#include "featloc/stereo/SegmentTriangulator.h"

namespace featloc
{
StereoHead StereoHead::fromObservation(
	const mrpt::obs::CObservationStereoImages& obs, const std::string& where, double maxTiltDeg)
{
	return fromCalibration(obs.getStereoCameraParams(), mrpt::poses::CPose3D(obs.cameraPose), where, maxTiltDeg);
}

StereoHead StereoHead::fromCalibration(
	const mrpt::img::TStereoCamera& calibration, const mrpt::poses::CPose3D& cam, const std::string& where,
	double maxTiltDeg)
{
	StereoHead h;
	const SegmentTriangulator t = SegmentTriangulator::fromCalibration(calibration, where);
	h.fx = t.fx;
	h.fy = t.fy;
	h.cx = t.cx;
	h.cy = t.cy;
	h.baseline = t.baseline;
	h.width = static_cast<int>(calibration.leftCamera.ncols);
	h.height = static_cast<int>(calibration.leftCamera.nrows);
	if (!(h.width > 0 && h.height > 0))
		throw InputError(where + ": stereo observation without a usable calibration");
	const auto R = cam.getRotationMatrix();
	// Optical axes: z ahead, x right, y down. A level camera has z and x
	// horizontal and y pointing down.
	const double tilt = std::acos(std::min(1.0, std::max(-1.0, -R(2, 1)))) * 180.0 / M_PI;
	if (tilt > maxTiltDeg)
		throw InputError(
			where + ": the camera's image rows are " + std::to_string(tilt) +
			" deg from level (cameraPose); vertical-line landmarks need a level, rectified camera "
			"(at most " + std::to_string(maxTiltDeg) + " deg)");
	h.camX = cam.x();
	h.camY = cam.y();
	h.camZ = cam.z();
	h.camYaw = std::atan2(R(1, 2), R(0, 2));
	return h;
}

Eigen::Vector2d StereoHead::toCamera(
	const Eigen::Vector3d& X, const Eigen::Vector2d& p, Eigen::Matrix<double, 2, 3>* J) const
{
	const double ct = std::cos(X.z()), st = std::sin(X.z());
	const Eigen::Vector2d t(X.x() + camX * ct - camY * st, X.y() + camX * st + camY * ct);
	const double psi = X.z() + camYaw;
	const Eigen::Vector2d f(std::cos(psi), std::sin(psi)), r(std::sin(psi), -std::cos(psi));
	const Eigen::Vector2d d = p - t;
	const Eigen::Vector2d c(r.dot(d), f.dot(d));
	if (J)
	{
		// dt/dyaw, and dr/dpsi = f, df/dpsi = -r.
		const Eigen::Vector2d dt(-camX * st - camY * ct, camX * ct - camY * st);
		(*J) << -r.x(), -r.y(), c.y() - r.dot(dt),	//
			-f.x(), -f.y(), -c.x() - f.dot(dt);
	}
	return c;
}

Eigen::Vector2d StereoHead::toWorld(const Eigen::Vector3d& X, const Eigen::Vector2d& c) const
{
	const double ct = std::cos(X.z()), st = std::sin(X.z());
	const Eigen::Vector2d t(X.x() + camX * ct - camY * st, X.y() + camX * st + camY * ct);
	return t + directionToWorld(X, c);
}

Eigen::Vector2d StereoHead::directionToWorld(const Eigen::Vector3d& X, const Eigen::Vector2d& v) const
{
	const double psi = X.z() + camYaw;
	const Eigen::Vector2d f(std::cos(psi), std::sin(psi)), r(std::sin(psi), -std::cos(psi));
	return v.x() * r + v.y() * f;
}

Eigen::Vector2d StereoHead::project(const Eigen::Vector2d& c, Eigen::Matrix2d* J) const
{
	const double iy = 1.0 / c.y();
	if (J) *J << fx * iy, -fx * c.x() * iy * iy, fx * iy, -fx * (c.x() - baseline) * iy * iy;
	return {cx + fx * c.x() * iy, cx + fx * (c.x() - baseline) * iy};
}

Eigen::Vector2d StereoHead::triangulate(double xl, double xr, Eigen::Matrix2d* J) const
{
	const double d = xl - xr;
	const double depth = fx * baseline / d;
	const double lateral = (xl - cx) * baseline / d;
	if (J)
	{
		// c_x = (xl - cx) B / d, c_y = fx B / d, d = xl - xr.
		const double id2 = baseline / (d * d);
		*J << baseline / d - (xl - cx) * id2, (xl - cx) * id2,	//
			-fx * id2, fx * id2;
	}
	return {lateral, depth};
}
bool StereoHead::columnRayMeets(
	double u, const Eigen::Vector2d& p, const Eigen::Vector2d& dir, Eigen::Vector2d& c) const
{
	// ray x (p + t dir) = 0 with ray = ((u - cx) / fx, 1).
	const Eigen::Vector2d ray((u - cx) / fx, 1.0);
	const double den = ray.x() * dir.y() - ray.y() * dir.x();
	if (std::abs(den) < 1e-12) return false;
	const double t = -(ray.x() * p.y() - ray.y() * p.x()) / den;
	c = p + t * dir;
	return true;
}
}  // namespace featloc
