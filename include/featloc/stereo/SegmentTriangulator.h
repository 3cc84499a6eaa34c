#pragma once
#include <mrpt/img/TStereoCamera.h>

#include <Eigen/Core>
#include <string>

#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/TriangulatedSegment.h"
#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Triangulates matched vertical segments of a rectified pair in 3-D,
 * whatever the camera's attitude (StereoHead is the level-camera, floor-
 * plan version the paper's method uses). A point seen at column u_l in
 * the left image and u_r in the right one, row v, lies at
 *     d = u_l - u_r,  z = fx B / d,  x = (u_l - cx) B / d,
 *     y = (v - cy) fx B / (fy d),
 * and its covariance is J diag(s_u^2, s_u^2, s_v^2) J^T with J = d(x, y, z)
 * / d(u_l, u_r, v): the columns carry the paper's image sigma (2.3.1), the
 * row the sigma of a segment's end. */
class SegmentTriangulator
{
   public:
	double fx = 0, fy = 0, cx = 0, cy = 0, baseline = 0;
	double sigmaColumn = 0.5;  //!< [px] paper, 2.3.1
	double sigmaRow = 2;  //!< [px] a segment end's row

	/** From a rectified calibration (baseline = length of rightCameraPose).
	 * Throws InputError, prefixed by `where`, without a usable one. */
	static SegmentTriangulator fromCalibration(const mrpt::img::TStereoCamera& c, const std::string& where);

	/** The point of columns (ul, ur) on row v, and optionally d p / d (ul, ur, v). */
	Eigen::Vector3d point(double ul, double ur, double v, Eigen::Matrix3d* J = nullptr) const;

	/** The match's common rows, triangulated at their ends and middle
	 * from the two segments' fitted columns. */
	TriangulatedSegment triangulate(
		const VerticalSegment& left, const VerticalSegment& right, const SegmentMatch& m) const;
};
}  // namespace featloc
