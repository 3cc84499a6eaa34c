#pragma once
#include <vector>

namespace featloc
{
/** Real roots of a polynomial c[0] + c[1] z + ... + c[n] z^n (n <= 4 here),
 * with Eigen's companion-matrix solver (unsupported/Eigen/Polynomials).
 * Leading coefficients that are zero relative to the largest one are
 * dropped (the degree falls); a root counts as real when its imaginary
 * part is below `imagTolerance` (relative to its magnitude, at least 1).
 * Roots come sorted and without near-duplicates. An identically zero
 * polynomial has no roots reported. */
class PolynomialRoots
{
   public:
	static std::vector<double> real(
		const std::vector<double>& coefficients, double imagTolerance = 1e-7);
};
}  // namespace featloc
