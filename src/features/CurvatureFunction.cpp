#include "featloc/features/CurvatureFunction.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void CurvatureFunction::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "curvature_U_k", U_k);
	readChoice(c, s, "curvature_sampling", sampling, {"metric", "normalized"});
	read(c, s, "curvature_length", length);
	read(c, s, "curvature_step", step);
	require(U_k > 0, c, s, "curvature_U_k", "> 0");
	require(step > 0, c, s, "curvature_step", "> 0");
	require(length >= 8 && (length & (length - 1)) == 0, c, s, "curvature_length",
		"a power of two, at least 8");
}

void CurvatureFunction::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "curvature_U_k", U_k,
		"[m] curvature, eq. (4): path minus chord length that ends the window k_i");
	write(c, s, "curvature_sampling", sampling,
		"metric (one sample per curvature_step of outline) | normalized (every segment to curvature_length samples: the paper)");
	write(c, s, "curvature_length", length,
		"normalized sampling: samples per curvature function (power of two, FFT)");
	write(c, s, "curvature_step", step, "[m] metric sampling: outline per sample");
}

double CurvatureFunction::arcLength(const ScanPoints& s, const ScanSegment& seg)
{
	double total = 0;
	for (uint32_t i = seg.first; i < seg.last; i++)
	{
		const double dx = s.points[i + 1].x - s.points[i].x, dy = s.points[i + 1].y - s.points[i].y;
		total += std::sqrt(dx * dx + dy * dy);
	}
	return total;
}

void CurvatureFunction::compute(
	const ScanPoints& s, const ScanSegment& seg, std::vector<double>& out, double step)
{
	const size_t n = seg.size();
	const bool metric = params.sampling == "metric";
	if (metric && !(step > 0)) step = params.step;
	const double total0 = metric ? arcLength(s, seg) : 0;
	const size_t L = metric ? std::max<size_t>(1, static_cast<size_t>(std::ceil(total0 / step)))
							: params.length;
	out.assign(L, 0.0);
	m_arc.resize(n);
	m_theta.resize(n);
	m_window.assign(n, 0);
	if (n < 2) return;
	auto pt = [&](size_t k) -> const ScanPoint& { return s.points[seg.first + k]; };
	auto dist = [&](size_t a, size_t b) {
		const double dx = pt(b).x - pt(a).x, dy = pt(b).y - pt(a).y;
		return std::sqrt(dx * dx + dy * dy);
	};
	m_arc[0] = 0;
	for (size_t k = 1; k < n; k++) m_arc[k] = m_arc[k - 1] + dist(k - 1, k);
	const double total = m_arc[n - 1];
	if (!(total > 0)) return;

	// eq. (4): the window end e = i + k_i. Path minus chord never decreases
	// as the window grows, so e is found by walking on from where the
	// previous point's window ended (and back where the condition fails).
	auto fits = [&](size_t i, size_t e) {
		return m_arc[e] - m_arc[i] - dist(i, e) < params.U_k;
	};
	size_t e = 1;
	for (size_t i = 0; i + 1 < n; i++)
	{
		e = std::max(e, i + 1);
		while (e > i + 1 && !fits(i, e)) e--;
		while (e + 1 < n && fits(i, e + 1)) e++;
		m_window[i] = static_cast<unsigned int>(e - i);
		// eq. (5): direction of the chord from i to i + k_i.
		m_theta[i] = std::atan2(pt(e).y - pt(i).y, pt(e).x - pt(i).x);
	}
	m_theta[n - 1] = m_theta[n - 2];  // no window to the right of the last point
	for (size_t k = 1; k < n; k++)
		m_theta[k] = m_theta[k - 1] + mrpt::math::wrapToPi(m_theta[k] - m_theta[k - 1]);

	// theta resampled at L + 1 arc positions, differenced: eq. (6).
	size_t k = 0;
	double prev = m_theta[0];
	for (size_t q = 1; q <= L; q++)
	{
		const double sq = metric ? std::min(total, step * static_cast<double>(q))
								 : total * static_cast<double>(q) / static_cast<double>(L);
		while (k + 2 < n && m_arc[k + 1] < sq) k++;
		const double span = m_arc[k + 1] - m_arc[k];
		const double f = span > 0 ? std::clamp((sq - m_arc[k]) / span, 0.0, 1.0) : 1.0;
		const double th = m_theta[k] + f * (m_theta[k + 1] - m_theta[k]);
		out[q - 1] = th - prev;
		prev = th;
	}
}
}  // namespace featloc
