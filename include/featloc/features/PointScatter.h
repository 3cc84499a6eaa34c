#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace featloc
{
/** The total-least-squares line through 2-D points, from their running
 * first and second moments: the centroid (Borges & Aldon eq. 5) and the
 * scatter matrix's major axis (eqs. 4, 6, 7). Points are added one at a
 * time, so a line can be grown point by point (ReferencePolyline's local
 * lines) or fitted to a run at once (LineFit). A point may carry a weight
 * (the inverse of its perpendicular variance: LineEllipseExtractor's
 * weighted lines); unweighted points count 1 each, and their sums are the
 * plain ones to the bit. The sums are taken about the first point added,
 * which keeps them exact to rounding far from the origin. */
class PointScatter
{
   public:
	void add(double x, double y, double weight = 1.0)
	{
		if (m_n == 0)
		{
			m_x0 = x;
			m_y0 = y;
		}
		const double dx = x - m_x0, dy = y - m_y0;
		m_sw += weight;
		m_sx += weight * dx;
		m_sy += weight * dy;
		m_sxx += weight * dx * dx;
		m_sxy += weight * dx * dy;
		m_syy += weight * dy * dy;
		m_n++;
	}
	size_t count() const { return m_n; }
	double weight() const { return m_sw; }	//!< the weights' sum (count() if unweighted)
	double cx() const { return m_x0 + m_sx / m_sw; }  //!< the (weighted) centroid
	double cy() const { return m_y0 + m_sy / m_sw; }

	/** The line: its unit normal (nx, ny) = (-sin a, cos a), a its
	 * direction in (-pi/2, pi/2], and the difference of the scatter
	 * matrix's eigenvalues, major minus minor [m^2] (how well the direction
	 * is determined; 0 when it is not). Half-angle formulas: no
	 * trigonometry. */
	struct Line
	{
		double nx = 0, ny = 1, gap = 0;
	};
	Line line() const
	{
		const double m = m_sw;
		const double u = (m_sxx - m_sx * m_sx / m) - (m_syy - m_sy * m_sy / m);
		const double v = 2 * (m_sxy - m_sx * m_sy / m);
		// (cos 2a, sin 2a) = (u, v) / gap.
		Line l;
		l.gap = std::sqrt(u * u + v * v);
		const double c2 = l.gap > 0 ? u / l.gap : 1.0;
		const double ca = std::sqrt(std::max(0.0, 0.5 * (1 + c2)));
		const double sa = std::copysign(std::sqrt(std::max(0.0, 0.5 * (1 - c2))), v);
		l.nx = -sa;
		l.ny = ca;
		return l;
	}

   private:
	size_t m_n = 0;
	double m_x0 = 0, m_y0 = 0;
	double m_sw = 0;
	double m_sx = 0, m_sy = 0, m_sxx = 0, m_sxy = 0, m_syy = 0;
};
}  // namespace featloc
