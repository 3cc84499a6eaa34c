#pragma once
#include <cstdint>

namespace featloc
{
/** A geometric feature of one scan, Borges & Aldon section 2, in the
 * scan's sensor frame.
 *
 * - Linear cluster (a wall, a long side): the infinite line
 *   x cos(alpha) + y sin(alpha) = rho, represented by its foot point
 *   f = rho (cos alpha, sin alpha) (so that all features live in the same
 *   Euclidean space) and A = n n^T with n = (cos alpha, sin alpha).
 * - Ellipsoidal cluster (a short segment: a leg, a box): its centre of
 *   gravity f, and A = I.
 * Under a motion (t, w) a static feature moves to R(w)(f - A t), eq. (11).
 *
 * The covariance of f (cxx, cxy, cyy) propagates the fit's uncertainty. */
struct ScanFeature
{
	enum class Kind : uint8_t
	{
		Line,
		Ellipse
	};
	Kind kind = Kind::Line;
	double x = 0, y = 0;  //!< f [m]
	double a2 = 1, b2 = 1, c = 0;  //!< A = [a2 c; c b2], eq. (11)
	double rho = 0, alpha = 0;	//!< line parameters (lines only)
	double length = 0;	//!< [m]
	double sigma = 0;  //!< [m] RMS residual of the fit, eq. (8)
	/** Indices in the ScanPoints of its first and last point: the span of
	 * its points (a line fitted over several pieces, LineEllipseExtractor's
	 * step 8, spans what lies between them too; its outliers, step 7, are
	 * inside). */
	uint32_t firstPoint = 0, lastPoint = 0;
	double cxx = 0, cxy = 0, cyy = 0;  //!< covariance of f [m^2]
	/** Lines: covariance of (rho, alpha) from the TLS fit. */
	double varRho = 0, varAlpha = 0, covRhoAlpha = 0;
};
}  // namespace featloc
