#include "featloc/math/PolynomialRoots.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <type_traits>
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
	auto keepReal = [&](const auto& all) {
		for (Eigen::Index k = 0; k < all.size(); k++)
		{
			const std::complex<double> r = all[k];
			if (std::abs(r.imag()) <= imagTolerance * std::max(1.0, std::abs(r)))
				roots.push_back(r.real());
		}
	};
	// Eigen's companion-matrix solver, of fixed size where it can be: PCM's
	// rotation quartic (PcmMotionUpdate) is solved a few times per match,
	// and the dynamic solver's allocations were a quarter of its cost. The
	// roots are the same, bit for bit.
	auto solveFixed = [&](auto degreeTag) {
		constexpr int D = decltype(degreeTag)::value;
		Eigen::Matrix<double, D + 1, 1> coeffs;
		for (int k = 0; k <= D; k++) coeffs[k] = c[static_cast<size_t>(k)] / scale;
		keepReal(Eigen::PolynomialSolver<double, D>(coeffs).roots());
	};
	if (degree == 2)
		solveFixed(std::integral_constant<int, 2>());
	else if (degree == 3)
		solveFixed(std::integral_constant<int, 3>());
	else if (degree == 4)
		solveFixed(std::integral_constant<int, 4>());
	else
	{
		Eigen::VectorXd coeffs(static_cast<Eigen::Index>(degree + 1));
		for (size_t k = 0; k <= degree; k++) coeffs[static_cast<Eigen::Index>(k)] = c[k] / scale;
		keepReal(Eigen::PolynomialSolver<double, Eigen::Dynamic>(coeffs).roots());
	}
	std::sort(roots.begin(), roots.end());
	roots.erase(
		std::unique(roots.begin(), roots.end(),
			[](double a, double b) { return std::abs(a - b) < 1e-12 * (1 + std::abs(a)); }),
		roots.end());
	return roots;
}
}  // namespace featloc
