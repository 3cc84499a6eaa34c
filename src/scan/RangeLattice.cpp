#include "featloc/scan/RangeLattice.h"

#include <opencv2/core.hpp>
#include <opencv2/core/hal/hal.hpp>

#include <algorithm>
#include <cmath>
#include <complex>

namespace featloc
{
namespace
{
/** Histogram bin [m]: the DFT reaches 1 / (2 kBin) cycles per metre, 1.25
 * times the finest step looked for. */
constexpr double kBin = 0.008;
/** Ranges up to kBins x kBin (16 m) are counted: beyond, a step's phase
 * drifts faster than the DFT's frequency grid can follow. (8 m found the
 * bundled log's lattice in 72% of its scans instead of all.) */
constexpr int kBins = 2048;
/** DFT length (the histogram zero-padded once): frequency grid
 * 1 / (kDft kBin) = 0.03 cycles per metre, refined on the exact ranges at
 * the peak. 4096 real values: 13.5 us with OpenCV on this machine, its
 * plan kept (20 us with cv::dft, which makes one per call). */
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
	m_offset = 0;
	m_ranges.clear();
	for (const auto& p : scan.points)
		if (p.range < kBins * kBin) m_ranges.push_back(p.range);
	const size_t n = m_ranges.size();
	if (n < kMinPoints) return 0;
	// The interquartile range bounds the steps that can be told from the
	// ranges' own spread.
	m_sorted = m_ranges;
	std::nth_element(m_sorted.begin(), m_sorted.begin() + static_cast<long>(n / 4), m_sorted.end());
	const double q1 = m_sorted[n / 4];
	// Everything after the first quartile is at least q1: the third is
	// among those.
	std::nth_element(m_sorted.begin() + static_cast<long>(n / 4) + 1,
		m_sorted.begin() + static_cast<long>(3 * n / 4), m_sorted.end());
	const double q3 = m_sorted[3 * n / 4];
	const double maxStep = std::min(kMaxStep, (q3 - q1) / kMinSpreadSteps);
	if (maxStep < kMinStep) return 0;

	m_histogram.assign(kDft, 0.0f);
	for (double r : m_ranges) m_histogram[static_cast<size_t>(r / kBin)] += 1.0f;
	// A real input's spectrum, packed (CCS): Re 0, Re 1, Im 1, Re 2, ...
	// (what cv::dft gives for one row, bit for bit).
	m_spectrum.resize(kDft);
	if (!m_dftPlan.plan)
		m_dftPlan.plan = std::shared_ptr<cv::hal::DFT2D>(
			cv::hal::DFT2D::create(kDft, 1, CV_32F, 1, 1, 0, 0));
	constexpr size_t kRowBytes = kDft * sizeof(float);
	static_cast<cv::hal::DFT2D*>(m_dftPlan.plan.get())
		->apply(reinterpret_cast<const uchar*>(m_histogram.data()), kRowBytes,
			reinterpret_cast<uchar*>(m_spectrum.data()), kRowBytes);

	// R on the DFT's grid, f = k / (kDft kBin). The fundamental is the
	// lowest peak about as high as the highest: its harmonics are no
	// higher (as high on a noise-free lattice), half its frequency puts
	// alternate levels in opposite phase, and a lower peak that ranges
	// bunched within a few steps make (a small room) is lower.
	const double df = 1.0 / (kDft * kBin);
	const int lowBin = static_cast<int>(std::ceil(1.0 / (maxStep * df)));
	const int highBin = std::min(kDft / 2 - 1, static_cast<int>(1.0 / (kMinStep * df)));
	// |.|^2 at bin k, and R from it by sqrt rather than glibc's slower
	// hypot (the values are far from overflow).
	auto magnitude2 = [&](int k) {
		const double re = m_spectrum[2 * static_cast<size_t>(k) - 1];
		const double im = m_spectrum[2 * static_cast<size_t>(k)];
		return re * re + im * im;
	};
	auto R = [&](int k) { return std::sqrt(magnitude2(k)) / static_cast<double>(n); };
	// The largest |.|^2, then one root: the same value as the largest R.
	double highest2 = 0;
	for (int k = lowBin; k <= highBin; k++) highest2 = std::max(highest2, magnitude2(k));
	const double highest = std::sqrt(highest2) / static_cast<double>(n);
	if (highest < kMinResultant) return 0;
	int peak = lowBin;
	while (R(peak) < highest - kPeakTolerance) peak++;
	// That frequency may be on the peak's flank: its top is the highest
	// within 20 % above it (the second harmonic is twice as far).
	for (int k = peak + 1, last = std::min(highBin, peak + peak / 5); k <= last; k++)
		if (R(k) > R(peak)) peak = k;

	// The exact resultant around the grid's peak (the grid's phase error
	// grows with the range).
	// Each range's phasor at the first frequency, turned by one refinement
	// step per frequency: two sin/cos per range instead of one per range
	// and frequency.
	constexpr int kFrequencies = 2 * kRefineSteps + 1;
	const double f0 = (peak - 1.0) * df, fStep = df / kRefineSteps;
	std::complex<double> sums[kFrequencies] = {};
	for (double r : m_ranges)
	{
		std::complex<double> phasor = std::polar(1.0, 2 * M_PI * f0 * r);
		const std::complex<double> turn = std::polar(1.0, 2 * M_PI * fStep * r);
		for (int i = 0; i < kFrequencies; i++, phasor *= turn) sums[i] += phasor;
	}
	double bestF = 0, bestR = 0, bestPhase = 0;
	for (int i = 0; i < kFrequencies; i++)
	{
		const double Rf = std::abs(sums[i]) / static_cast<double>(n);
		if (Rf > bestR) bestR = Rf, bestF = f0 + i * fStep, bestPhase = std::arg(sums[i]);
	}
	if (bestR < kMinResultant) return 0;
	// The readings' mean phase is where the levels are: offset + k q.
	const double offset = bestPhase / (2 * M_PI * bestF);
	// At least kMinLevels distinct levels (counting stops there).
	m_levels.clear();
	for (double r : m_ranges)
	{
		const long level = std::lround((r - offset) * bestF);
		if (std::find(m_levels.begin(), m_levels.end(), level) == m_levels.end())
			m_levels.push_back(level);
		if (m_levels.size() >= kMinLevels) break;
	}
	if (m_levels.size() < kMinLevels) return 0;
	m_offset = offset;
	return 1.0 / bestF;
}

size_t RangeLattice::dequantize(ScanPoints& scan, double q, double offset)
{
	auto& p = scan.points;
	const size_t n = p.size();
	if (q <= 0 || n < 3) return 0;
	m_levels.resize(n);
	for (size_t i = 0; i < n; i++) m_levels[i] = std::lround((p[i].range - offset) / q);
	auto neighbours = [&](size_t i) { return p[i + 1].beam == p[i].beam + 1; };
	// The anchor between points i and i + 1 (one level apart), as x, y.
	auto anchor = [&](size_t i, double& x, double& y) {
		const double bearing = 0.5 * (p[i].bearing + p[i + 1].bearing);
		const double range = offset + 0.5 * q * static_cast<double>(m_levels[i] + m_levels[i + 1]);
		x = range * std::cos(bearing);
		y = range * std::sin(bearing);
	};
	auto isAnchor = [&](size_t i) {
		return neighbours(i) && std::abs(m_levels[i + 1] - m_levels[i]) == 1;
	};
	// Runs of neighbouring beams on one level.
	m_runs.clear();
	for (size_t s = 0; s < n;)
	{
		size_t e = s;
		while (e + 1 < n && neighbours(e) && m_levels[e + 1] == m_levels[s]) e++;
		m_runs.emplace_back(s, e);
		s = e + 1;
	}
	// Readings kept on their level (no anchor to place them by): the run
	// is off its surface by one rounding error, uniform over the level's
	// q (on a surface seen head on, exactly one for all its beams).
	const auto cellSigma = static_cast<float>(q / std::sqrt(12.0));
	// Points first..last of the run starting at point `run` (its group
	// is named after that point's beam).
	auto keepOnLevel = [&](size_t first, size_t last, size_t run) {
		for (size_t i = first; i <= last; i++)
		{
			p[i].sharedErrorGroup = 1 + p[run].beam;
			p[i].sharedRangeSigma = cellSigma;
		}
	};
	size_t moved = 0;
	const size_t runs = m_runs.size();
	// The anchor beyond run j on its left (between run j - 1 and the run
	// before it) and on its right (between runs j + 1 and j + 2); kNone
	// where there is none.
	constexpr size_t kNone = static_cast<size_t>(-1);
	auto anchorBeyondLeft = [&](size_t j) {
		return j > 0 && m_runs[j - 1].first > 0 && isAnchor(m_runs[j - 1].first - 1)
			? m_runs[j - 1].first - 1
			: kNone;
	};
	auto anchorBeyondRight = [&](size_t j) {
		return j + 2 < runs && isAnchor(m_runs[j + 1].second) ? m_runs[j + 1].second : kNone;
	};
	// A flat surface puts the anchors beyond run j (the next level
	// boundary out, either side) on the line through its two anchors A and
	// A + (dx, dy), of that length, to within a quarter of a step.
	auto anchorsBeyondOnChord = [&](size_t j, double ax, double ay, double dx, double dy, double length) {
		const size_t outerLeft = anchorBeyondLeft(j), outerRight = anchorBeyondRight(j);
		if (outerLeft == kNone || outerRight == kNone || !(length > 0)) return false;
		auto offChord = [&](size_t i) {
			double x, y;
			anchor(i, x, y);
			return std::abs((x - ax) * dy - (y - ay) * dx) / length;
		};
		return offChord(outerLeft) <= 0.25 * q && offChord(outerRight) <= 0.25 * q;
	};
	for (size_t j = 0; j < runs; j++)
	{
		const auto [s, e] = m_runs[j];
		const bool left = j > 0 && isAnchor(s - 1), right = j + 1 < runs && isAnchor(e);
		// The line through the run's anchors; at a surface's end (an
		// anchor on one side only) the line through it and the next
		// anchor beyond it, extended.
		size_t a, b;
		if (left && right)
			a = s - 1, b = e;
		else if (left && anchorBeyondLeft(j) != kNone)
			a = anchorBeyondLeft(j), b = s - 1;
		else if (right && anchorBeyondRight(j) != kNone)
			a = e, b = anchorBeyondRight(j);
		else
		{
			keepOnLevel(s, e, s);
			continue;
		}
		double ax, ay, bx, by;
		anchor(a, ax, ay);
		anchor(b, bx, by);
		const double dx = bx - ax, dy = by - ay, chord = std::hypot(dx, dy);
		if (left && right && maxExtremumChord > 0 &&
			(m_levels[s - 1] > m_levels[s]) == (m_levels[e + 1] > m_levels[s]) &&
			chord <= maxExtremumChord && !anchorsBeyondOnChord(j, ax, ay, dx, dy, chord))
		{
			// The nearest (or farthest) stretch of a surface: both anchors
			// on one level boundary. The chord through them is the surface
			// only where it is flat; on a round thing (a plant pot, a bin,
			// a leg) it is a different line from each viewpoint. Kept.
			keepOnLevel(s, e, s);
			continue;
		}
		const double level = offset + q * static_cast<double>(m_levels[s]);
		for (size_t i = s; i <= e; i++)
		{
			// The beam u = (cos, sin) meets A + t (B - A) where
			// r (u x D) = A x D.
			const double ux = std::cos(p[i].bearing), uy = std::sin(p[i].bearing);
			const double den = ux * dy - uy * dx;
			if (std::abs(den) < 1e-12) continue;
			const double r = (ax * dy - ay * dx) / den;
			// On its own level's reach: a chord of a strongly curved
			// surface, or an anchor that was noise, may cross far off.
			if (!(std::abs(r - level) <= 0.5 * q))
			{
				keepOnLevel(i, i, s);
				continue;
			}
			p[i].range = r;
			p[i].x = r * ux;
			p[i].y = r * uy;
			moved++;
		}
	}
	return moved;
}
}  // namespace featloc
