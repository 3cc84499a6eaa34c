#include "featloc/features/CurvatureFunctionMatcher.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void CurvatureFunctionMatcher::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "U_c", U_c);
	readDegrees(c, s, "curvature_floor_DEG", curvature_floor);
	require(U_c > 0 && U_c <= 1, c, s, "U_c", "in (0, 1]");
	require(curvature_floor >= 0, c, s, "curvature_floor_DEG", ">= 0");
}

void CurvatureFunctionMatcher::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "U_c", U_c,
		"curvature matching: minimum similarity rho_ij of a pair of segments (eq. 7)");
	writeDegrees(c, s, "curvature_floor_DEG", curvature_floor,
		"[deg] curvature matching: turn per sample below which a function counts as straight");
}

namespace
{
/** Row-wise real spectra (CCS) of `functions` zero-padded to L, of their
 * squares and of their supports; |f|^2 and the support sizes. */
void spectra(
	const std::vector<std::vector<double>>& functions, int L, cv::Mat& values,
	cv::Mat& squares, cv::Mat& supports, std::vector<double>& norm2, std::vector<double>& count)
{
	const int n = static_cast<int>(functions.size());
	cv::Mat v = cv::Mat::zeros(n, L, CV_64F), q = cv::Mat::zeros(n, L, CV_64F),
			m = cv::Mat::zeros(n, L, CV_64F);
	norm2.assign(functions.size(), 0.0);
	count.assign(functions.size(), 0.0);
	for (int i = 0; i < n; i++)
	{
		const auto& f = functions[static_cast<size_t>(i)];
		for (size_t k = 0; k < f.size(); k++)
		{
			const int kk = static_cast<int>(k);
			v.at<double>(i, kk) = f[k];
			q.at<double>(i, kk) = f[k] * f[k];
			m.at<double>(i, kk) = 1;
			norm2[static_cast<size_t>(i)] += f[k] * f[k];
		}
		count[static_cast<size_t>(i)] = static_cast<double>(f.size());
	}
	if (n == 0) return;
	cv::dft(v, values, cv::DFT_ROWS);
	cv::dft(q, squares, cv::DFT_ROWS);
	cv::dft(m, supports, cv::DFT_ROWS);
}

/** corr(a, b)(s) = sum_k a[k] b[k + s] from the rows' spectra. */
void correlate(const cv::Mat& A, const cv::Mat& B, cv::Mat& product, cv::Mat& out)
{
	cv::mulSpectrums(B, A, product, 0, true);
	cv::idft(product, out, cv::DFT_REAL_OUTPUT | cv::DFT_SCALE);
}
}  // namespace

void CurvatureFunctionMatcher::match(
	const std::vector<std::vector<double>>& current,
	const std::vector<std::vector<double>>& reference, std::vector<Match>& out)
{
	bool sameLength = true;
	for (const auto* set : {&current, &reference})
		for (const auto& f : *set) sameLength = sameLength && f.size() == set->front().size();
	const size_t n = current.empty() ? 0 : current[0].size();
	const bool circular = sameLength && !reference.empty() && reference[0].size() == n &&
		n >= 2 && (n & (n - 1)) == 0;
	match(current, reference, std::vector<char>(current.size() * reference.size(), 1), circular,
		out);
}

void CurvatureFunctionMatcher::match(
	const std::vector<std::vector<double>>& current,
	const std::vector<std::vector<double>>& reference, const std::vector<char>& allowed,
	bool circular, std::vector<Match>& out)
{
	out.clear();
	const size_t nc = current.size(), nr = reference.size();
	m_rho.assign(nc * nr, 0.0);
	m_shift.assign(nc * nr, 0);
	if (nc == 0 || nr == 0) return;
	size_t longest = 0;
	for (const auto* set : {&current, &reference})
		for (const auto& f : *set)
		{
			if (circular && f.size() != current[0].size())
				throw std::invalid_argument("circular correlation of functions of different lengths");
			longest = std::max(longest, f.size());
		}
	if (circular && (longest < 2 || (longest & (longest - 1)) != 0))
		throw std::invalid_argument("circular correlation needs a power-of-two length");
	int L = 1;
	while (static_cast<size_t>(L) < (circular ? longest : 2 * longest)) L *= 2;

	cv::Mat sc, sr, qc, qr, mc, mr;
	spectra(current, L, sc, qc, mc, m_normC, m_countC);
	spectra(reference, L, sr, qr, mr, m_normR, m_countR);
	const double e2 = params.curvature_floor * params.curvature_floor;
	cv::Mat product, corr, energyC, energyR, overlap;
	std::vector<Match> candidates;
	for (size_t i = 0; i < nc; i++)
		for (size_t j = 0; j < nr; j++)
		{
			if (!allowed[i * nr + j]) continue;
			const int ri = static_cast<int>(i), rj = static_cast<int>(j);
			// corr(s) = sum_k c_i[k] r_j[k + s]: its spectrum is conj(C_i) R_j.
			correlate(sc.row(ri), sr.row(rj), product, corr);
			correlate(mc.row(ri), mr.row(rj), product, overlap);
			double best = -1e300;
			int bestShift = 0;
			if (circular)
			{
				// Every shift overlaps fully: the paper's circular correlation,
				// normalised by the whole functions.
				const double den =
					std::sqrt((m_normC[i] + e2 * m_countC[i]) * (m_normR[j] + e2 * m_countR[j]));
				for (int k = 0; k < L; k++)
				{
					const double v = den > 0
						? (corr.at<double>(0, k) + e2 * overlap.at<double>(0, k)) / den
						: 1.0;	// two all-zero functions, no floor: identical
					if (v > best) best = v, bestShift = k;
				}
			}
			else
			{
				// Linear: normalised over the overlap of each shift, which must
				// cover half the shorter function: a wall seen further along
				// from the next pose has the same shape where both see it.
				correlate(qc.row(ri), mr.row(rj), product, energyC);
				correlate(mc.row(ri), qr.row(rj), product, energyR);
				const double minOverlap =
					std::max(2.0, 0.5 * std::min(m_countC[i], m_countR[j])) - 0.5;
				for (int k = 0; k < L; k++)
				{
					const double n = overlap.at<double>(0, k);
					if (n < minOverlap) continue;
					const double den = std::sqrt(std::max(0.0, energyC.at<double>(0, k) + e2 * n) *
						std::max(0.0, energyR.at<double>(0, k) + e2 * n));
					const double v = den > 0 ? (corr.at<double>(0, k) + e2 * n) / den : 1.0;
					if (v > best) best = v, bestShift = k > L / 2 ? k - L : k;
				}
			}
			const size_t at = i * nr + j;
			m_rho[at] = std::max(0.0, best);
			m_shift[at] = bestShift;
			if (m_rho[at] >= params.U_c)
				candidates.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(j),
					m_rho[at], m_shift[at]});
		}
	// Greedy: the most similar pair first, each function paired at most
	// once. With overlap normalisation a short straight piece is as
	// similar to a long wall as the wall seen again, so among similar shapes
	// similar lengths go first: the order is rho sqrt(n_short / n_long).
	auto key = [&](const Match& m) {
		const double a = static_cast<double>(current[m.current].size()),
					 b = static_cast<double>(reference[m.reference].size());
		return circular ? m.similarity : m.similarity * std::sqrt(std::min(a, b) / std::max(a, b));
	};
	std::stable_sort(candidates.begin(), candidates.end(),
		[&](const Match& a, const Match& b) { return key(a) > key(b); });
	std::vector<char> usedC(nc, 0), usedR(nr, 0);
	for (const auto& m : candidates)
	{
		if (usedC[m.current] || usedR[m.reference]) continue;
		usedC[m.current] = usedR[m.reference] = 1;
		out.push_back(m);
	}
}
}  // namespace featloc
