#pragma once
#include <Eigen/Core>
#include <cstddef>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** The circle through a run of scan points, by least squares of their
 * geometric distances f_j = |p_j - o| - r: Kasa's algebraic fit (linear in
 * x^2 + y^2 + D x + E y + F) for a start, then Gauss-Newton steps on f
 * (Chernov, "Circular and linear regression", 2010, ch. 4-5). A small
 * round thing (a trunk, a pole, a leg) gives a laser scan a few points on
 * an arc, whose local lines know their direction badly; the circle knows
 * its normals (radial) as well as it knows its centre.
 *
 * normalInverse, (A^T A)^-1 with A's rows df_j/d(ox, oy, r) = (-n_j, -1)
 * (n_j the unit radial direction of p_j), gives the fit's covariance,
 * s^2 normalInverse for independent distance errors of standard
 * deviation s, and its sensitivity to each point (implicit function
 * theorem at the minimum): d(ox, oy, r)/dp_j = -normalInverse a_j n_j^T
 * to first order (PointToLineCovariance takes each range's effect
 * through it). */
struct CircleFit
{
	double ox = 0, oy = 0, r = 0;  //!< centre and radius [m]
	double sumSquares = 0;	//!< sum of f_j^2 at the solution [m^2]
	Eigen::Matrix3d normalInverse = Eigen::Matrix3d::Zero();
	size_t n = 0;

	/** Fits points [first, first + count); false when they do not fix a
	 * circle (fewer than 3, collinear, or a radius above maxRadius: a
	 * nearly straight run). */
	static bool fit(const ScanPoint* first, size_t count, double maxRadius, CircleFit& out);

	/** The centre's variance along unit direction (tx, ty) for distance
	 * noise s [m^2]. */
	double centreVariance(double tx, double ty, double s) const;
};
}  // namespace featloc
