#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "featloc/features/CircleFit.h"
#include "featloc/scan/PointNoiseEstimator.h"
#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** The reference scan as IDC sees it (Lu & Milios): its points in bearing
 * order, consecutive points of one segment joined by straight edges, and
 * the two correspondence rules of IDC as searches that use the angular
 * order instead of scanning every point:
 *
 * - closest point (the ICP rule): the nearest point of the polyline (on an
 *   edge, interpolated, not only the nearest sample) within maxDistance of
 *   q. Everything within maxDistance of q lies within asin(maxDistance/|q|)
 *   of q's bearing, so only the edges overlapping that bearing window are
 *   tested: O(log n + window) per query, exact;
 * - matching range point (the IMRP rule): within +-window of q's bearing,
 *   the point of the polyline (range interpolated linearly in bearing
 *   along each edge, as Lu & Milios do) whose range is closest to |q|; ties
 *   (several edges reach |q| exactly) go to the smallest bearing change,
 *   so the outward walk stops once an exact match is nearer in bearing.
 *
 * Bearing windows may cross +-pi (360-degree scanners). */
class ReferencePolyline
{
   public:
	struct Hit
	{
		double x = 0, y = 0;  //!< the corresponding point
		/** The edge (a, b) it lies inside, or a == b when it is a point of
		 * the scan (a lone point, or an edge's end: a corner). */
		uint32_t a = 0, b = 0;
		double distance = 0;  //!< from the query point
	};

	/** The surface an edge lies on, for the point-to-line error: the total
	 * least squares line through the edge's two points and as many of
	 * their neighbours (up to lineHalfWindow on each side, within the
	 * segment, one at a time) as lie within 3 sigma of where the line so
	 * far predicts them, sigma the scan's robust point noise
	 * (PointNoiseEstimator::estimate, the median scatter across surfaces,
	 * at least 1 mm; build() gives the prediction's variance).
	 * Two-point edges of raw
	 * points are as noisy in direction as the points are close (1 cm
	 * noise, 2.6 cm apart at 3 m: +-20 degrees): their normals would invent
	 * constraints along walls and bias the estimate; more points along the
	 * same surface fix that without rounding corners. directionSigma() says
	 * how well a line's direction is known. */
	struct LocalLine
	{
		double cx = 0, cy = 0;	//!< centroid [m]
		/** Unit normal (-sin alpha, cos alpha), alpha the line's direction
		 * in (-pi/2, pi/2]. */
		double nx = 0, ny = 1;
		/** Difference of the scatter matrix eigenvalues (major - minor):
		 * how well the direction is determined [m^2]. */
		double gap = 0;
		uint32_t lo = 0, hi = 0;  //!< the points fitted
		/** Where the points bow away from the line (build's bowSigmas):
		 * the surface's offset along the normal at s along the line from
		 * the centroid is tilt s + bow (s^2 - meanAlong2), a local
		 * parabola; 0 and 0 on a line whose points do not bow. [1],
		 * [1/m], [m^2] */
		double tilt = 0, bow = 0, meanAlong2 = 0;
	};

	/** Keeps the points of `segments` (in order), edges inside each, and
	 * fits each edge's LocalLine. With targetDirectionSigma > 0 [rad] a
	 * line whose direction sigma (directionSigma()) is still above it after
	 * lineHalfWindow neighbours a side grows on, up to kLongestLineFactor
	 * times that, while the points fit: dense noisy scans need more points
	 * for the same direction. With bowSigmas > 0 a line whose points bow
	 * (the least-squares quadratic term of their offsets across it, h = c
	 * s + b (s^2 - mean s^2), stands more than bowSigmas of its standard
	 * error out of the points' noise across the line; kLeastBowPoints at
	 * least) keeps the parabola (LocalLine::tilt, bow). On a curved wall a
	 * line is a chord, offset from the arc by a sagitta that depends on
	 * where along it a point lies; points paired with chords biased the
	 * heading, with residuals too small to show it (doc/benchmarks.md,
	 * "Issue 15, thirtieth session"). With bowPerSegment, a segment whose
	 * lines, taken one window apart, bow one way (the median of their bows'
	 * signed t statistics, times sqrt(count) / 1.2533, the median's
	 * efficiency, beyond bowSigmas) keeps every line's bow: on a round wall
	 * each line's bow alone stays under bowSigmas, yet all bow the same way
	 * and their chords biased the motion together; on a straight wall the
	 * signs are random (doc/benchmarks.md, "Issue 15, thirty-third
	 * session").
	 *
	 * With circleSigmas > 0 a segment shorter than roundExtent (first to
	 * last point) of kLeastCirclePoints or more is a small round thing
	 * when a circle (CircleFit, radius at most roundExtent) fits its
	 * points better than a line by more than circleSigmas of the points'
	 * noise (the sums of squares differ by circleSigmas^2 rangeNoise()^2
	 * or more: the arc's curvature stands out), fits them within that
	 * noise (chi^2 of n - 3 degrees of freedom at 99.9%), and turns its
	 * convex side to the sensor (the centre beyond the points: an arc of
	 * range-lattice levels, centred on the sensor, is not one). Its edges
	 * then lie on a RoundThing (roundOf) as well as on their lines: a trunk's
	 * four to eight points leave a line's direction unknown to 8 degrees
	 * or more, and IDC left them unpaired (doc/benchmarks.md, "Issue 15,
	 * twenty-ninth session", the orchard). */
	void build(const ScanPoints& points, const std::vector<ScanSegment>& segments,
		unsigned int lineHalfWindow = 6, double targetDirectionSigma = 0, double bowSigmas = 0,
		double circleSigmas = 0, double roundExtent = 1.0, bool bowPerSegment = false);
	static constexpr unsigned int kLongestLineFactor = 8;
	/** The bow of fewer points is not fitted (a quadratic term of four
	 * points is mostly their noise). */
	static constexpr uint32_t kLeastBowPoints = 5;
	/** A round thing has this many points at least: three fix any circle,
	 * two more test it. */
	static constexpr uint32_t kLeastCirclePoints = 5;

	size_t size() const { return m_points.size(); }
	const ScanPoint& point(uint32_t i) const { return m_points[i]; }
	/** True when point i is joined to point i + 1. */
	bool joined(uint32_t i) const { return m_joined[i] != 0; }
	/** The line of edge (i, i + 1); only for joined(i). */
	const LocalLine& localLine(uint32_t i) const { return m_lines[i]; }
	/** Standard deviation of the direction of edge i's local line [rad]:
	 * the range noise over the root of its points' scatter along it
	 * (sigma / sqrt(gap)); an upper bound where beams are oblique to the
	 * line, whose points then scatter less across it. */
	double directionSigma(uint32_t i) const;
	/** The range noise estimated when building [m]
	 * (PointNoiseEstimator::rangeNoise, chords of
	 * PointNoiseEstimator::kRangeNoiseChord at least). */
	double rangeNoise() const { return m_rangeNoise; }
	/** Distance between the first and the last point of point i's segment
	 * [m]: a large structure's segment (a wall with its recesses) against
	 * a small isolated thing's (a leg, a trunk, a pole). */
	double segmentExtent(uint32_t i) const { return m_segmentExtent[i]; }
	/** A small round thing (build's circleSigmas): a segment's circle and
	 * its points lo..hi, the points fitted. */
	struct RoundThing
	{
		CircleFit circle;
		uint32_t lo = 0, hi = 0;
		/** |offset of (x, y) from the circle| [m]. */
		double distance(double x, double y) const
		{
			return std::abs(std::hypot(x - circle.ox, y - circle.oy) - circle.r);
		}
	};
	/** The round thing edge i lies on, or -1 (a line's). */
	int32_t roundOf(uint32_t i) const { return m_roundOf[i]; }
	const RoundThing& roundThing(int32_t k) const { return m_round[static_cast<size_t>(k)]; }
	size_t roundThings() const { return m_round.size(); }
	/** The variance of the direction of round thing k's normal at (qx,
	 * qy) [rad^2]: its centre's variance across the radius through q
	 * (with the range noise) over q's squared distance from the centre. */
	double roundNormalVariance(int32_t k, double qx, double qy) const;


	/** A query point with its polar coordinates (computed once, used by
	 * both rules). */
	struct Query
	{
		double x = 0, y = 0, range = 0, bearing = 0;
		Query() = default;
		Query(double qx, double qy);
	};

	/** `hint`: a point index whose edges are tried first (the last answer
	 * for this query point, as the estimate moves little between
	 * iterations); it only tightens the search's bounds, the answer is the
	 * same. kNoHint for none. */
	bool closestPoint(const Query& q, double maxDistance, Hit& hit, uint32_t hint = kNoHint) const;
	bool matchingRangePoint(const Query& q, double window, Hit& hit, uint32_t hint = kNoHint) const;
	static constexpr uint32_t kNoHint = 0xffffffffu;

   private:
	/** LocalLine::tilt and bow of L where its points bow (build's
	 * bowSigmas), against their noise across it from rangeNoise. */
	void fitBow(LocalLine& L, double rangeNoise, double bowSigmas) const;
	/** The least-squares bow of L's points and its t statistic, signed so
	 * that every line of a wall bowing one way has the same sign (its
	 * normal turned away from the sensor); false where it cannot be fitted. */
	bool bowOf(const LocalLine& L, double rangeNoise, double& bow, double& tilt, double& meanAlong2,
		double& t) const;
	/** bowPerSegment: every line of `seg` keeps its bow where its lines,
	 * one window apart, bow one way beyond bowSigmas. */
	void keepSegmentsBow(const ScanSegment& seg, double rangeNoise, double bowSigmas);
	/** The RoundThing of segment `seg` when it is one (build's
	 * circleSigmas), kept in m_round and named by its edges in m_roundOf. */
	void fitRound(const ScanSegment& seg, double rangeNoise, double circleSigmas, double roundExtent);
	/** Visits the points and edges outwards from `bearing` on both sides:
	 * visit(a, b, minDelta) for a point (a == b) or the edge (a, b), with
	 * the smallest bearing distance of that item from `bearing`; a side
	 * ends when visit returns false. */
	template <typename Visit>
	void walkOutwards(double bearing, Visit&& visit) const;
	/** Index of the first point whose bearing is >= `bearing` (size() if
	 * none), from a table of bearing buckets. */
	size_t firstAtOrAfter(double bearing) const;
	static constexpr size_t kBuckets = 1024;

	std::vector<ScanPoint> m_points;
	std::vector<double> m_bearings;	 // sorted, for the searches
	std::vector<uint32_t> m_bucketStart;
	std::vector<char> m_joined;
	/** Point i and its edge (i, i + 1), precomputed for the searches. */
	struct Edge
	{
		double ex = 0, ey = 0, invLength2 = 0;	//!< p_{i+1} - p_i, 1 / |.|^2
		double bearingSpan = 0;	 //!< bearing(i + 1) - bearing(i)
		double rangeSlope = 0;	//!< range change per radian of bearing
		bool joinedEither = false;	//!< joined to a neighbour (not lone)
	};
	std::vector<Edge> m_edges;
	std::vector<LocalLine> m_lines;
	std::vector<RoundThing> m_round;
	std::vector<int32_t> m_roundOf;	 // per point (edge), -1: none
	std::vector<ScanSegment> m_segments;  // of m_points
	std::vector<double> m_segmentExtent;  // per point, segmentExtent()
	PointNoiseEstimator m_noise;
	double m_rangeNoise = 0;
};
}  // namespace featloc
