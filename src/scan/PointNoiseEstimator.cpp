#include "featloc/scan/PointNoiseEstimator.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
double PointNoiseEstimator::chordDistance(const ScanPoint& a, const ScanPoint& b, const ScanPoint& p)
{
	const double ex = b.x - a.x, ey = b.y - a.y;
	// sqrt rather than hypot (no overflow at metres; glibc's hypot was
	// several percent of a PCM match, which calls this for every point).
	const double len = std::sqrt(ex * ex + ey * ey);
	if (len < 1e-12) return std::sqrt((p.x - a.x) * (p.x - a.x) + (p.y - a.y) * (p.y - a.y));
	return std::abs(ex * (p.y - a.y) - ey * (p.x - a.x)) / len;
}

double PointNoiseEstimator::fromDeviations()
{
	if (m_deviations.empty()) return 0;
	auto mid = m_deviations.begin() + static_cast<long>(m_deviations.size() / 2);
	std::nth_element(m_deviations.begin(), mid, m_deviations.end());
	return 1.4826 * *mid / std::sqrt(1.5);
}

double PointNoiseEstimator::estimate(const std::vector<ScanPoint>& p, size_t first, size_t last)
{
	m_deviations.clear();
	for (size_t k = first + 1; k < last; k++)
		m_deviations.push_back(chordDistance(p[k - 1], p[k + 1], p[k]));
	return fromDeviations();
}

double PointNoiseEstimator::estimate(
	const std::vector<ScanPoint>& p, const std::vector<ScanSegment>& segments)
{
	m_deviations.clear();
	for (const auto& seg : segments)
		for (size_t k = seg.first + 1; k < seg.last; k++)
			m_deviations.push_back(chordDistance(p[k - 1], p[k + 1], p[k]));
	return fromDeviations();
}
double PointNoiseEstimator::rangeNoise(
	const std::vector<ScanPoint>& p, const std::vector<ScanSegment>& segments, double minChord)
{
	m_deviations.clear();
	const double min2 = minChord * minChord;
	for (const auto& seg : segments)
		for (size_t k = seg.first + 1; k < seg.last; k++)
		{
			size_t m = 1;
			auto apart2 = [&] {
				const double dx = p[k + m].x - p[k - m].x, dy = p[k + m].y - p[k - m].y;
				return dx * dx + dy * dy;
			};
			while (apart2() < min2 && k - m > seg.first && k + m < seg.last) m++;
			const double chord2 = apart2();
			if (chord2 < min2 || p[k].range <= 0) continue;
			// The chord's normal against the beam of p[k].
			const double ex = p[k + m].x - p[k - m].x, ey = p[k + m].y - p[k - m].y;
			const double cosIncidence =
				std::abs(-ey * p[k].x + ex * p[k].y) / (std::sqrt(chord2) * p[k].range);
			if (cosIncidence < 0.5) continue;
			m_deviations.push_back(chordDistance(p[k - m], p[k + m], p[k]) / cosIncidence);
		}
	return fromDeviations();
}
}  // namespace featloc
