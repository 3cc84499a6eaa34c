#include "featloc/scan/RangeLattice.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <set>

namespace featloc
{
namespace
{
/** Histogram bin [m]: the DFT reaches 1 / (2 kBin) cycles per metre, 1.25
 * times the finest step looked for. */
constexpr double kBin = 0.008;
/** Ranges up to kBins x kBin (16 m) are counted: beyond, a step's phase
 * drifts faster than the DFT's frequency grid can follow. */
constexpr int kBins = 2048;
/** DFT length (the histogram zero-padded once): frequency grid
 * 1 / (kDft kBin) = 0.03 cycles per metre, refined on the exact ranges at
 * the peak. */
constexpr int kDft = 2 * kBins;
/** Refinement: the exact resultant at this many frequencies across one
 * grid step either side of the DFT's peak. */
constexpr int kRefineSteps = 4;
/** A peak within this of the highest counts as as high (a harmonic of a
 * noise-free lattice is exactly as high as the fundamental). */
constexpr double kPeakTolerance = 0.1;
}  // namespace

double RangeLattice::resultant(const ScanPoints& scan, double q)
{
	if (scan.empty() || q <= 0) return 0;
	std::complex<double> sum = 0;
	for (const auto& p : scan.points) sum += std::polar(1.0, 2 * M_PI * p.range / q);
	return std::abs(sum) / static_cast<double>(scan.size());
}

double RangeLattice::step(const ScanPoints& scan)
{
	m_ranges.clear();
	for (const auto& p : scan.points)
		if (p.range < kBins * kBin) m_ranges.push_back(p.range);
	const size_t n = m_ranges.size();
	if (n < kMinPoints) return 0;
	// The interquartile range bounds the steps that can be told from the
	// ranges' own spread.
	std::vector<double> sorted = m_ranges;
	std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(n / 4), sorted.end());
	const double q1 = sorted[n / 4];
	std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(3 * n / 4), sorted.end());
	const double q3 = sorted[3 * n / 4];
	const double maxStep = std::min(kMaxStep, (q3 - q1) / kMinSpreadSteps);
	if (maxStep < kMinStep) return 0;

	m_histogram.assign(kDft, 0.0f);
	for (double r : m_ranges) m_histogram[static_cast<size_t>(r / kBin)] += 1.0f;
	const cv::Mat histogram(1, kDft, CV_32F, m_histogram.data());
	m_spectrum.resize(2 * kDft);
	cv::Mat spectrum(1, kDft, CV_32FC2, m_spectrum.data());
	cv::dft(histogram, spectrum, cv::DFT_COMPLEX_OUTPUT);

	// R on the DFT's grid, f = k / (kDft kBin). The fundamental is the
	// lowest peak about as high as the highest: its harmonics are no
	// higher (as high on a noise-free lattice), half its frequency puts
	// alternate levels in opposite phase, and a lower peak that ranges
	// bunched within a few steps make (a small room) is lower.
	const double df = 1.0 / (kDft * kBin);
	const int kLow = static_cast<int>(std::ceil(1.0 / (maxStep * df)));
	const int kHigh = std::min(kDft / 2 - 1, static_cast<int>(1.0 / (kMinStep * df)));
	auto R = [&](int k) {
		return std::hypot(m_spectrum[2 * static_cast<size_t>(k)],
				   m_spectrum[2 * static_cast<size_t>(k) + 1]) /
			static_cast<double>(n);
	};
	double highest = 0;
	for (int k = kLow; k <= kHigh; k++) highest = std::max(highest, R(k));
	if (highest < kMinResultant) return 0;
	int peak = kLow;
	while (R(peak) < highest - kPeakTolerance) peak++;
	// That frequency may be on the peak's flank: its top is the highest
	// within 20 % above it (the second harmonic is twice as far).
	for (int k = peak + 1, last = std::min(kHigh, peak + peak / 5); k <= last; k++)
		if (R(k) > R(peak)) peak = k;

	// The exact resultant around the grid's peak (the grid's phase error
	// grows with the range).
	double bestF = 0, bestR = 0;
	for (int i = -kRefineSteps; i <= kRefineSteps; i++)
	{
		const double f = (peak + static_cast<double>(i) / kRefineSteps) * df;
		std::complex<double> sum = 0;
		for (double r : m_ranges) sum += std::polar(1.0, 2 * M_PI * f * r);
		const double Rf = std::abs(sum) / static_cast<double>(n);
		if (Rf > bestR) bestR = Rf, bestF = f;
	}
	if (bestR < kMinResultant) return 0;
	std::set<long> levels;
	for (double r : m_ranges) levels.insert(std::lround(r * bestF));
	return levels.size() >= kMinLevels ? 1.0 / bestF : 0.0;
}
}  // namespace featloc
