#include "featloc/odometry/OdometryCovarianceCheck.h"

#include <mrpt/math/distributions.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "featloc/math/PoseDifference.h"

namespace featloc
{
namespace
{
/** Bisection on log(s) in [1, kMaxScale]. */
constexpr double kMaxScale = 1e6;
constexpr int kBisections = 40;
}  // namespace

OdometryCovarianceCheck::OdometryCovarianceCheck(
	size_t window, double quantile, size_t minSamples)
	: m_window(std::max<size_t>(window, 1)),
	  m_quantile(std::clamp(quantile, 0.01, 0.99)),
	  m_minSamples(minSamples)
{
}

double OdometryCovarianceCheck::quantileMahalanobis2(double s) const
{
	std::vector<double> d2;
	d2.reserve(m_recent.size());
	for (const auto& x : m_recent)
	{
		const Eigen::Matrix3d S = s * x.Q + x.R;
		d2.push_back(x.e.dot(S.ldlt().solve(x.e)));
	}
	auto mid = d2.begin() +
		static_cast<long>(std::floor(m_quantile * static_cast<double>(d2.size() - 1)));
	std::nth_element(d2.begin(), mid, d2.end());
	return *mid;
}

void OdometryCovarianceCheck::observe(
	const mrpt::poses::CPosePDFGaussian& odometry, const mrpt::poses::CPosePDFGaussian& match)
{
	Sample x;
	x.e = poseDifference(match.mean, odometry.mean);
	x.Q = odometry.cov.asEigen();
	x.R = match.cov.asEigen();
	if (!x.e.allFinite() || !x.Q.allFinite() || !x.R.allFinite()) return;
	m_recent.push_back(x);
	if (m_recent.size() > m_window) m_recent.pop_front();
	m_samples++;
	if (m_samples < m_minSamples) return;

	// A share `quantile` of consistent d^2 lie below this.
	const double target = mrpt::math::chi2inv(m_quantile, 3);
	if (quantileMahalanobis2(1.0) <= target)
	{
		m_scale = 1;
		return;
	}
	double lo = 0, hi = std::log(kMaxScale);  // log s
	for (int i = 0; i < kBisections; i++)
	{
		const double mid = 0.5 * (lo + hi);
		(quantileMahalanobis2(std::exp(mid)) > target ? lo : hi) = mid;
	}
	m_scale = std::exp(hi);
	m_maxScale = std::max(m_maxScale, m_scale);
}
}  // namespace featloc
