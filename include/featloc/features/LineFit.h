#pragma once
#include <cstddef>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** Total-least-squares line through a run of scan points, Borges & Aldon
 * eqs. (3)-(8): the line x cos(alpha) + y sin(alpha) = rho with rho >= 0.
 *
 * `sigma` is the RMS perpendicular residual, eq. (8) with its sign slip
 * corrected (the residual is rho - x cos(alpha) - y sin(alpha)). The
 * along-line spread (sumS2) and the centroid's position along the line
 * (centroidAlong) give the fit's uncertainty: with perpendicular point
 * noise s, var(alpha) = s^2 / sumS2, var(rho) = s^2 / n + centroidAlong^2
 * var(alpha), cov(rho, alpha) = centroidAlong var(alpha). */
struct LineFit
{
	double rho = 0, alpha = 0;
	double sigma = 0;  //!< [m] eq. (8)
	double length = 0;	//!< [m] extent of the points along the line
	double cx = 0, cy = 0;	//!< centroid, eq. (5)
	double sumS2 = 0;  //!< sum of squared along-line offsets from the centroid [m^2]
	double centroidAlong = 0;  //!< centroid . (-sin alpha, cos alpha) [m]
	double maxResidual = 0;	 //!< [m] largest |perpendicular residual|
	size_t n = 0;

	/** Fits points [first, first + count) (count >= 2). */
	static LineFit fit(const ScanPoint* first, size_t count);

	/** Signed perpendicular distance of (x, y) to the line. */
	double residual(double x, double y) const;
};
}  // namespace featloc
