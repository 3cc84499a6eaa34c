#include "featloc/matchers/ReferencePolyline.h"

#include "featloc/features/LineFit.h"
#include "featloc/features/PointScatter.h"

#include <mrpt/math/distributions.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace featloc
{
namespace
{
/** a in (-pi, pi] for a in (-3 pi, 3 pi) (bearing differences): cheaper than
 * std::remainder, which dominated the searches. */
inline double wrapAngle(double a)
{
	if (a > M_PI) return a - 2 * M_PI;
	if (a <= -M_PI) return a + 2 * M_PI;
	return a;
}
}  // namespace

ReferencePolyline::Query::Query(double qx, double qy)
	: x(qx), y(qy), range(std::sqrt(qx * qx + qy * qy)), bearing(std::atan2(qy, qx))
{
}

void ReferencePolyline::build(const ScanPoints& s, const std::vector<ScanSegment>& segments,
	unsigned int lineHalfWindow, double targetDirectionSigma, double bowSigmas,
	double circleSigmas, double roundExtent, bool bowPerSegment)
{
	m_points.clear();
	m_joined.clear();
	m_segments.clear();
	m_segmentExtent.clear();
	for (const auto& seg : segments)
	{
		const auto first = static_cast<uint32_t>(m_points.size());
		for (uint32_t i = seg.first; i <= seg.last; i++)
		{
			m_points.push_back(s.points[i]);
			m_joined.push_back(i < seg.last ? 1 : 0);
		}
		m_segments.push_back({first, static_cast<uint32_t>(m_points.size() - 1)});
		const ScanPoint &a = s.points[seg.first], &b = s.points[seg.last];
		m_segmentExtent.insert(m_segmentExtent.end(), seg.size(), std::hypot(b.x - a.x, b.y - a.y));
	}
	m_bearings.resize(m_points.size());
	for (size_t i = 0; i < m_points.size(); i++) m_bearings[i] = m_points[i].bearing;
	// First point at or after each bearing bucket: O(1) lower bound.
	m_bucketStart.assign(kBuckets + 1, 0);
	for (size_t k = 0, i = 0; k <= kBuckets; k++)
	{
		const double from = -M_PI + 2 * M_PI * static_cast<double>(k) / kBuckets;
		while (i < m_bearings.size() && m_bearings[i] < from) i++;
		m_bucketStart[k] = static_cast<uint32_t>(i);
	}
	// Per edge, what both searches need.
	m_edges.assign(m_points.size(), Edge());
	for (size_t i = 0; i < m_points.size(); i++)
	{
		Edge& e = m_edges[i];
		e.joinedEither = m_joined[i] || (i > 0 && m_joined[i - 1]);
		if (!m_joined[i]) continue;
		const ScanPoint &p = m_points[i], &p2 = m_points[i + 1];
		e.ex = p2.x - p.x;
		e.ey = p2.y - p.y;
		const double len2 = e.ex * e.ex + e.ey * e.ey;
		e.invLength2 = len2 > 0 ? 1 / len2 : 0;
		e.bearingSpan = wrapAngle(p2.bearing - p.bearing);
		e.rangeSlope = e.bearingSpan > 0 ? (p2.range - p.range) / e.bearingSpan : 0;
	}

	// Each edge's local line, grown from the edge one point at a time on
	// either side (up to lineHalfWindow) while the next point lies within
	// 3 sigma of where the line so far predicts it: sigma^2 (1 + 1/n +
	// d^2 / gap), sigma the points' scatter across their surface, n the
	// line's points, d the next point's distance along it from their
	// centroid, gap their scatter along it. A two-point edge's direction is
	// as noisy as its points are close (1 cm noise, 1.5 cm apart: +-40
	// deg); tested against that line alone (as until 2026-11-25) the next
	// point of a straight wall often missed it and lines stopped at three
	// points with random normals, which invented constraints along walls
	// (a corridor's matches 10 cm off along it with a 5 mm sigma;
	// doc/cfidc-matcher.md, "Local lines"). (Tested against the refit
	// instead, lines were less consistent on that corridor and whole runs'
	// matches more biased along the motion; both longer-line rules carry
	// such a bias, not understood: same doc.) sigma is the median scatter
	// across surfaces; the range
	// noise, estimated on chords of 10 cm at least as dense points would
	// understate it, is what a line's direction sigma rests on: a line must
	// not claim a direction better known than it is.
	m_rangeNoise = m_noise.rangeNoise(m_points, m_segments, PointNoiseEstimator::kRangeNoiseChord);
	const double scatter2 = mrpt::square(std::max(1e-3, m_noise.estimate(m_points, m_segments)));
	m_lines.assign(m_points.size(), LocalLine());
	for (const auto& seg : m_segments)
		for (uint32_t a = seg.first; a < seg.last; a++)
		{
			PointScatter scatter;
			scatter.add(m_points[a].x, m_points[a].y);
			scatter.add(m_points[a + 1].x, m_points[a + 1].y);
			uint32_t lo = a, hi = a + 1;
			// Tries the next point on one side; `open` false once that
			// side stops.
			auto grow = [&](bool& open, bool left) {
				if (!open || (left ? lo == seg.first : hi == seg.last))
				{
					open = false;
					return;
				}
				const uint32_t next = left ? lo - 1 : hi + 1;
				const ScanPoint& p = m_points[next];
				const PointScatter::Line l = scatter.line();
				const double dx = p.x - scatter.cx(), dy = p.y - scatter.cy();
				const double across = l.nx * dx + l.ny * dy, along = l.ny * dx - l.nx * dy;
				const double n = static_cast<double>(scatter.count());
				const double predicted2 = scatter2 *
					(1 + 1 / n + (l.gap > 0 ? along * along / l.gap : 1e12));
				open = across * across <= 9 * predicted2;
				if (!open) return;
				scatter.add(p.x, p.y);
				(left ? lo : hi) = next;
			};
			// Past lineHalfWindow a line grows on while its direction is
			// known worse than targetDirectionSigma: with dense beams (0.25
			// deg) and 3 cm noise, 13 points span 10 cm and leave the
			// direction +-14 deg, and no line would pass
			// max_line_direction_sigma.
			const unsigned int most =
				targetDirectionSigma > 0 ? kLongestLineFactor * lineHalfWindow : lineHalfWindow;
			const double noise = std::max(1e-3, m_rangeNoise);
			bool left = true, right = true;
			for (unsigned int w = 0; w < most && (left || right); w++)
			{
				if (w >= lineHalfWindow)
				{
					const double gap = scatter.line().gap;
					if (gap > 0 && noise * noise <= targetDirectionSigma * targetDirectionSigma * gap)
						break;
				}
				grow(left, true);
				grow(right, false);
			}
			LocalLine& L = m_lines[a];
			L.cx = scatter.cx();
			L.cy = scatter.cy();
			const PointScatter::Line l = scatter.line();
			L.nx = l.nx;
			L.ny = l.ny;
			L.gap = l.gap;
			L.lo = lo;
			L.hi = hi;
			if (bowSigmas > 0 && hi - lo + 1 >= kLeastBowPoints) fitBow(L, noise, bowSigmas);
		}
	if (bowSigmas > 0 && bowPerSegment)
		for (const auto& seg : m_segments) keepSegmentsBow(seg, std::max(1e-3, m_rangeNoise), bowSigmas);
	m_round.clear();
	m_roundOf.assign(m_points.size(), -1);
	if (circleSigmas > 0)
		for (const auto& seg : m_segments)
			fitRound(seg, std::max(1e-3, m_rangeNoise), circleSigmas, roundExtent);
}

void ReferencePolyline::fitBow(LocalLine& L, double rangeNoise, double bowSigmas) const
{
	double bow = 0, tilt = 0, meanAlong2 = 0, t = 0;
	if (!bowOf(L, rangeNoise, bow, tilt, meanAlong2, t) || std::abs(t) <= bowSigmas) return;
	L.bow = bow;
	L.tilt = tilt;
	L.meanAlong2 = meanAlong2;
}

bool ReferencePolyline::bowOf(const LocalLine& L, double rangeNoise, double& bow, double& tilt,
	double& meanAlong2, double& t) const
{
	// Least squares of the offsets h across the line on s and on q = s^2 -
	// mean s^2 (h and s have zero mean about the centroid): h = c s + b q.
	// The linear term matters where the window is lopsided (cut by a
	// segment's end or by the growth test on one side): there s and q
	// correlate, and b alone would take part of the arc's turn. The
	// standard error of b is sigma sqrt(sum s^2 / det), sigma the points'
	// noise across the line: the range noise times |n.u|, u each beam.
	// (Not the growth test's sigma, the median scatter across surfaces: on
	// a corridor 0.6 of the range noise, it let the walls near the robot,
	// seen head on, bow by chance, and their parabolas' slopes constrained
	// the motion along them.)
	double mean = 0, across2 = 0;
	for (uint32_t j = L.lo; j <= L.hi; j++)
	{
		const ScanPoint& p = m_points[j];
		const double s = L.ny * (p.x - L.cx) - L.nx * (p.y - L.cy);
		mean += s * s;
		if (p.range > 0) across2 += mrpt::square((L.nx * p.x + L.ny * p.y) / p.range);
	}
	mean /= static_cast<double>(L.hi - L.lo + 1);
	const double noise2 = rangeNoise * rangeNoise * across2 / static_cast<double>(L.hi - L.lo + 1);
	double ss = 0, sq = 0, qq = 0, hs = 0, hq = 0;
	for (uint32_t j = L.lo; j <= L.hi; j++)
	{
		const double dx = m_points[j].x - L.cx, dy = m_points[j].y - L.cy;
		const double s = L.ny * dx - L.nx * dy, h = L.nx * dx + L.ny * dy;
		const double q = s * s - mean;
		ss += s * s;
		sq += s * q;
		qq += q * q;
		hs += h * s;
		hq += h * q;
	}
	const double det = ss * qq - sq * sq;
	if (!(det > 1e-12 * ss * qq)) return false;
	bow = (ss * hq - sq * hs) / det;
	tilt = (qq * hs - sq * hq) / det;
	meanAlong2 = mean;
	// A line's normal may point either way: the sign is taken with it
	// turned away from the sensor.
	const double away = L.nx * L.cx + L.ny * L.cy >= 0 ? 1.0 : -1.0;
	t = noise2 * ss > 0 ? away * bow * std::sqrt(det / (noise2 * ss))
						: (bow == 0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), away * bow));
	return true;
}

void ReferencePolyline::keepSegmentsBow(const ScanSegment& seg, double rangeNoise, double bowSigmas)
{
	// The lines one window apart (their points disjoint, so their bows'
	// errors are independent); the median of their t, robust to a corner's
	// few lines, has a standard error of 1.2533 / sqrt(count).
	thread_local std::vector<double> ts;
	ts.clear();
	bool any = false;
	uint32_t after = 0;
	for (uint32_t a = seg.first; a < seg.last; a++)
	{
		const LocalLine& L = m_lines[a];
		if (L.hi - L.lo + 1 < kLeastBowPoints || (any && L.lo <= after)) continue;
		double bow = 0, tilt = 0, meanAlong2 = 0, t = 0;
		if (!bowOf(L, rangeNoise, bow, tilt, meanAlong2, t)) continue;
		ts.push_back(t);
		after = L.hi;
		any = true;
	}
	if (ts.size() < 3) return;
	std::nth_element(ts.begin(), ts.begin() + static_cast<std::ptrdiff_t>(ts.size() / 2), ts.end());
	const double median = ts[ts.size() / 2];
	if (std::abs(median) * std::sqrt(static_cast<double>(ts.size())) / 1.2533 <= bowSigmas) return;
	for (uint32_t a = seg.first; a < seg.last; a++)
	{
		LocalLine& L = m_lines[a];
		if (L.hi - L.lo + 1 < kLeastBowPoints || L.bow != 0) continue;
		double t = 0;
		bowOf(L, rangeNoise, L.bow, L.tilt, L.meanAlong2, t);
	}
}

double ReferencePolyline::directionSigma(uint32_t i) const
{
	const double gap = m_lines[i].gap;
	return gap > 0 ? std::max(1e-3, m_rangeNoise) / std::sqrt(gap) : M_PI;
}

void ReferencePolyline::fitRound(
	const ScanSegment& seg, double rangeNoise, double circleSigmas, double roundExtent)
{
	const uint32_t n = seg.last - seg.first + 1;
	if (n < kLeastCirclePoints || m_segmentExtent[seg.first] >= roundExtent) return;
	const ScanPoint* p = &m_points[seg.first];
	CircleFit circle;
	if (!CircleFit::fit(p, n, roundExtent, circle)) return;
	// Convex towards the sensor: the centre lies beyond the middle point.
	const ScanPoint& mid = p[n / 2];
	if (std::hypot(circle.ox, circle.oy) <= mid.range) return;
	// The circle against the line: one parameter more (the curvature),
	// worth circleSigmas of the noise; and the circle within the noise.
	const LineFit line = LineFit::fit(p, n);
	const double noise2 = rangeNoise * rangeNoise;
	const double lineSquares = static_cast<double>(n) * line.sigma * line.sigma;
	if (lineSquares - circle.sumSquares < circleSigmas * circleSigmas * noise2) return;
	if (circle.sumSquares > noise2 * mrpt::math::chi2inv(0.999, n - 3)) return;
	const auto k = static_cast<int32_t>(m_round.size());
	m_round.push_back({circle, seg.first, seg.last});
	for (uint32_t a = seg.first; a < seg.last; a++) m_roundOf[a] = k;
}

double ReferencePolyline::roundNormalVariance(int32_t k, double qx, double qy) const
{
	const CircleFit& circle = m_round[static_cast<size_t>(k)].circle;
	const double dx = qx - circle.ox, dy = qy - circle.oy;
	const double d2 = std::max(dx * dx + dy * dy, 1e-12);
	const double d = std::sqrt(d2);
	// The normal turns with the centre's displacement across it.
	return circle.centreVariance(-dy / d, dx / d, std::max(1e-3, m_rangeNoise)) / d2;
}

size_t ReferencePolyline::firstAtOrAfter(double bearing) const
{
	const double f = (bearing + M_PI) / (2 * M_PI) * kBuckets;
	size_t i = m_bucketStart[static_cast<size_t>(std::clamp(f, 0.0, double(kBuckets)))];
	while (i < m_bearings.size() && m_bearings[i] < bearing) i++;
	return i;
}

template <typename Visit>
void ReferencePolyline::walkOutwards(double bearing, Visit&& visit) const
{
	// Points in bearing order, walked from `bearing` outwards on both sides
	// (wrapping around +-pi). On the way out each point is visited after
	// the edge that joins it to its neighbour nearer to `bearing`; the
	// bearing distance passed is the smallest of that item (an edge's
	// nearer end), never decreasing along a side, so `visit` can stop a
	// side once nothing farther can win. The edge that straddles `bearing`
	// is visited once, first.
	const size_t n = m_points.size();
	if (n == 0) return;
	const size_t c = firstAtOrAfter(bearing);
	auto delta = [&](size_t i) { return std::abs(wrapAngle(m_bearings[i] - bearing)); };
	const size_t left0 = (c + n - 1) % n, right0 = c % n;
	if (m_joined[left0] && left0 + 1 == right0) visit(left0, right0, 0.0);
	bool goRight = true, goLeft = true;
	size_t seen = 0;
	for (size_t step = 0; step < n && (goRight || goLeft); step++)
	{
		if (goRight)
		{
			// The edge from the neighbour nearer to `bearing` first: it is
			// nearer in bearing than the point.
			const size_t i = (right0 + step) % n;
			const size_t prev = (i + n - 1) % n;
			if (step > 0 && m_joined[prev] && prev + 1 == i && !visit(prev, i, delta(prev)))
				goRight = false;
			else if (!visit(i, i, delta(i)))
				goRight = false;
			seen++;
		}
		if (goLeft && seen < n)
		{
			const size_t i = (left0 + n - step) % n;
			const size_t next = (i + 1) % n;
			if (step > 0 && m_joined[i] && i + 1 == next && !visit(i, next, delta(next)))
				goLeft = false;
			else if (!visit(i, i, delta(i)))
				goLeft = false;
			seen++;
		}
		if (seen >= n) break;
	}
}

bool ReferencePolyline::closestPoint(
	const Query& q, double maxDistance, Hit& hit, uint32_t hint) const
{
	const double qx = q.x, qy = q.y, range = q.range;
	double best2 = maxDistance * maxDistance, best = maxDistance;
	// Nothing at a bearing distance D from q is nearer than range sin D (or
	// range, beyond 90 degrees): past `limit` nothing can beat `best`.
	auto limitFor = [&](double d) { return d >= range ? M_PI : std::asin(d / range); };
	double limit = limitFor(best);
	bool found = false;
	auto test = [&](size_t a, size_t b) {
		const ScanPoint& p = m_points[a];
		double cx = p.x, cy = p.y, t = 0;
		if (a != b)
		{
			const Edge& e = m_edges[a];
			t = std::clamp(((qx - p.x) * e.ex + (qy - p.y) * e.ey) * e.invLength2, 0.0, 1.0);
			cx = p.x + t * e.ex;
			cy = p.y + t * e.ey;
		}
		const double d2 = (qx - cx) * (qx - cx) + (qy - cy) * (qy - cy);
		if (d2 < best2)
		{
			best2 = d2;
			best = std::sqrt(d2);
			limit = limitFor(best);
			hit.x = cx;
			hit.y = cy;
			// An interior foot point belongs to the edge; an end point to
			// the point itself (a lone point, or a corner's vertex).
			hit.a = static_cast<uint32_t>(a);
			hit.b = static_cast<uint32_t>(a != b && t > 0 && t < 1 ? b : a);
			if (a != b && t >= 1) hit.a = hit.b = static_cast<uint32_t>(b);
			found = true;
		}
	};
	// The hint's edges first: a tight bound from the start.
	if (hint < m_points.size())
	{
		if (m_joined[hint]) test(hint, hint + 1);
		if (hint > 0 && m_joined[hint - 1]) test(hint - 1, hint);
		if (!m_edges[hint].joinedEither) test(hint, hint);
	}
	walkOutwards(q.bearing, [&](size_t a, size_t b, double minDelta) {
		if (minDelta >= limit) return false;
		// A joined point is tested with its edges.
		if (!(a == b && m_edges[a].joinedEither)) test(a, b);
		return true;
	});
	if (found) hit.distance = best;
	return found;
}

bool ReferencePolyline::matchingRangePoint(
	const Query& q, double window, Hit& hit, uint32_t hint) const
{
	const double range = q.range, bearing = q.bearing;
	double bestDr = std::numeric_limits<double>::infinity(), bestDb = bestDr;
	double bestR = 0, bestTheta = 0;
	bool found = false;
	auto consider = [&](double r, double db, double theta, size_t a, size_t b) {
		const double dr = std::abs(r - range);
		if (dr < bestDr || (dr == bestDr && db < bestDb))
		{
			bestDr = dr;
			bestDb = db;
			bestR = r;
			bestTheta = theta;
			hit.a = static_cast<uint32_t>(a);
			hit.b = static_cast<uint32_t>(b);
			found = true;
		}
	};
	auto test = [&](size_t a, size_t b) {
		const Edge& e = m_edges[a];
		const ScanPoint& p = m_points[a];
		// Bearings relative to q's, in (-pi, pi].
		const double b0 = wrapAngle(p.bearing - bearing);
		if (a == b || !(e.bearingSpan > 0))
		{
			if (std::abs(b0) <= window) consider(p.range, std::abs(b0), bearing + b0, a, a);
			return;
		}
		const double b1 = b0 + e.bearingSpan;
		const double ta = std::max(-window, b0), tb = std::min(window, b1);
		if (ta > tb) return;
		// Range linear in bearing along the edge (Lu & Milios' interpolation).
		const double ra = p.range + e.rangeSlope * (ta - b0);
		const double rb = p.range + e.rangeSlope * (tb - b0);
		if ((range - ra) * (range - rb) <= 0 && ra != rb)
		{
			const double th = ta + (tb - ta) * (range - ra) / (rb - ra);
			consider(range, std::abs(th), bearing + th, a, b);
		}
		else if (std::abs(ra - range) <= std::abs(rb - range))
			consider(ra, std::abs(ta), bearing + ta, a, b);
		else
			consider(rb, std::abs(tb), bearing + tb, a, b);
	};
	// The hint's edges first: an exact match there bounds the walk.
	if (hint < m_points.size())
	{
		if (m_joined[hint]) test(hint, hint + 1);
		if (hint > 0 && m_joined[hint - 1]) test(hint - 1, hint);
		if (!m_edges[hint].joinedEither) test(hint, hint);
	}
	walkOutwards(bearing, [&](size_t a, size_t b, double minDelta) {
		// Outside the window, or farther in bearing than an exact match.
		if (minDelta > window || (bestDr == 0 && minDelta > bestDb)) return false;
		if (!(a == b && m_edges[a].joinedEither)) test(a, b);	// joined: with its edges
		return true;
	});
	if (!found) return false;
	hit.x = bestR * std::cos(bestTheta);
	hit.y = bestR * std::sin(bestTheta);
	hit.distance = std::sqrt((hit.x - q.x) * (hit.x - q.x) + (hit.y - q.y) * (hit.y - q.y));
	return true;
}
}  // namespace featloc
