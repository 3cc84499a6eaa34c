#include "featloc/features/LineFit.h"

#include "featloc/features/PointScatter.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
LineFit LineFit::fit(const ScanPoint* p, size_t count)
{
	LineFit f;
	f.n = count;
	PointScatter scatter;
	for (size_t k = 0; k < count; k++) scatter.add(p[k].x, p[k].y);
	f.cx = scatter.cx();  // eq. (5)
	f.cy = scatter.cy();
	// Eq. (4): the normal direction, where the perpendicular spread
	// (eqs. 6, 7) is smallest.
	const PointScatter::Line line = scatter.line();
	f.alpha = std::atan2(line.ny, line.nx);
	f.rho = f.cx * line.nx + f.cy * line.ny;  // eq. (3)
	if (f.rho < 0)
	{
		f.rho = -f.rho;
		f.alpha += M_PI;
	}
	if (f.alpha > M_PI) f.alpha -= 2 * M_PI;
	const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
	double ss = 0, sMin = 0, sMax = 0;
	for (size_t k = 0; k < count; k++)
	{
		const double r = f.rho - p[k].x * ca - p[k].y * sa;	// eq. (8), corrected
		ss += r * r;
		f.maxResidual = std::max(f.maxResidual, std::abs(r));
		const double s = -(p[k].x - f.cx) * sa + (p[k].y - f.cy) * ca;
		f.sumS2 += s * s;
		sMin = std::min(sMin, s);
		sMax = std::max(sMax, s);
	}
	f.sigma = std::sqrt(ss / static_cast<double>(count));
	f.length = sMax - sMin;
	f.centroidAlong = -f.cx * sa + f.cy * ca;
	return f;
}

double LineFit::residual(double x, double y) const
{
	return rho - x * std::cos(alpha) - y * std::sin(alpha);
}
}  // namespace featloc
