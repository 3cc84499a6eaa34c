#include "featloc/math/PolynomialRoots.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/Polynomials>

namespace featloc
{
std::vector<double> PolynomialRoots::real(
	const std::vector<double>& c, double imagTolerance)
{
	std::vector<double> roots;
	double scale = 0;
	for (double v : c) scale = std::max(scale, std::abs(v));
	if (scale == 0) return roots;
	size_t degree = c.size() - 1;
	while (degree > 0 && std::abs(c[degree]) <= 1e-14 * scale) degree--;
	if (degree == 0) return roots;
	if (degree == 1)
	{
		roots.push_back(-c[0] / c[1]);
		return roots;
	}
	Eigen::VectorXd coeffs(static_cast<Eigen::Index>(degree + 1));
	for (size_t k = 0; k <= degree; k++) coeffs[static_cast<Eigen::Index>(k)] = c[k] / scale;
	Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
	for (const auto& r : solver.roots())
		if (std::abs(r.imag()) <= imagTolerance * std::max(1.0, std::abs(r)))
			roots.push_back(r.real());
	std::sort(roots.begin(), roots.end());
	roots.erase(
		std::unique(roots.begin(), roots.end(),
			[](double a, double b) { return std::abs(a - b) < 1e-12 * (1 + std::abs(a)); }),
		roots.end());
	return roots;
}
}  // namespace featloc
