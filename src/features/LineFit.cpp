#include "featloc/features/LineFit.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
LineFit LineFit::fit(const ScanPoint* p, size_t count)
{
	LineFit f;
	f.n = count;
	for (size_t k = 0; k < count; k++)
	{
		f.cx += p[k].x;
		f.cy += p[k].y;
	}
	f.cx /= static_cast<double>(count);	 // eq. (5)
	f.cy /= static_cast<double>(count);
	double sxx = 0, syy = 0, sxy = 0;  // eqs. (6), (7)
	for (size_t k = 0; k < count; k++)
	{
		const double dx = p[k].x - f.cx, dy = p[k].y - f.cy;
		sxx += dx * dx;
		syy += dy * dy;
		sxy += dx * dy;
	}
	// Eq. (4) with atan2: the normal direction, where the perpendicular
	// spread is smallest.
	f.alpha = 0.5 * std::atan2(-2 * sxy, syy - sxx);
	f.rho = f.cx * std::cos(f.alpha) + f.cy * std::sin(f.alpha);  // eq. (3)
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
