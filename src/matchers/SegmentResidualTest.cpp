#include "featloc/matchers/SegmentResidualTest.h"

#include <cmath>

namespace featloc
{
SegmentResidualTest::Result SegmentResidualTest::run(const ReferencePolyline& reference,
	const ScanPoints& current, const ScanSegment& segment, const mrpt::math::TPose2D& x,
	double sigma, double maxDistance)
{
	Result out;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	const ScanPoint& first = current[segment.first];
	double sumS = 0, sumSS = 0, sumE = 0, sumSE = 0;
	for (uint32_t i = segment.first; i <= segment.last; i++)
	{
		const ScanPoint& p = current[i];
		const double qx = c * p.x - s * p.y + x.x, qy = s * p.x + c * p.y + x.y;
		ReferencePolyline::Hit hit;
		if (!reference.closestPoint(ReferencePolyline::Query(qx, qy), maxDistance, hit)) continue;
		// The local line of the edge it lies on (of an edge ending at the
		// point of the reference it is nearest to).
		uint32_t a = hit.a;
		if (!reference.joined(a))
		{
			if (hit.a != hit.b || a == 0 || !reference.joined(a - 1)) continue;
			a--;
		}
		const ReferencePolyline::LocalLine& L = reference.localLine(a);
		// A local line's normal has the sign of its direction's angle in
		// (-pi/2, pi/2]: neighbouring lines of one wall can disagree. Turned
		// towards the reference's sensor, a residual has one meaning along
		// the segment: positive, nearer the sensor than the surface.
		const double toward = L.nx * L.cx + L.ny * L.cy > 0 ? -1.0 : 1.0;
		const double e = toward * (L.nx * (qx - L.cx) + L.ny * (qy - L.cy));
		if (std::abs(e) > maxDistance) continue;
		const double along = std::hypot(p.x - first.x, p.y - first.y);
		out.points++;
		sumS += along;
		sumSS += along * along;
		sumE += e;
		sumSE += along * e;
	}
	if (out.points < 3 || !(sigma > 0)) return out;
	// Least squares e = offset + slope (s - mean s): the fitted sum of
	// squares n offset^2 + slope^2 sum (s - mean s)^2.
	const double n = static_cast<double>(out.points);
	const double meanS = sumS / n;
	out.offset = sumE / n;
	const double spread = sumSS - n * meanS * meanS;
	out.slope = spread > 1e-12 ? (sumSE - n * meanS * out.offset) / spread : 0.0;
	out.chi2 = (n * out.offset * out.offset + out.slope * out.slope * std::max(0.0, spread)) /
		(sigma * sigma);
	return out;
}
}  // namespace featloc
