#include "SyntheticRoom.h"

#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <limits>

namespace featloc::test
{
SyntheticRoom SyntheticRoom::office()
{
	SyntheticRoom r;
	// Outer walls with a recess in the top wall.
	r.add(-4, -3, 4, -3);
	r.add(4, -3, 4, 3);
	r.add(4, 3, 1, 3);
	r.add(1, 3, 1, 3.8);
	r.add(1, 3.8, -1, 3.8);
	r.add(-1, 3.8, -1, 3);
	r.add(-1, 3, -4, 3);
	r.add(-4, 3, -4, -3);
	// A square pillar and a slanted box.
	r.add(1.5, -1, 2, -1);
	r.add(2, -1, 2, -0.5);
	r.add(2, -0.5, 1.5, -0.5);
	r.add(1.5, -0.5, 1.5, -1);
	r.add(-2.5, 1, -2, 1.6);
	r.add(-2, 1.6, -1.4, 1.1);
	r.add(-1.4, 1.1, -1.9, 0.5);
	r.add(-1.9, 0.5, -2.5, 1);
	return r;
}

SyntheticRoom SyntheticRoom::corridor()
{
	SyntheticRoom r;
	r.add(-50, -1, 50, -1);
	r.add(-50, 1, 50, 1);
	return r;
}

void SyntheticRoom::add(double x0, double y0, double x1, double y1)
{
	m_segments.push_back({x0, y0, x1, y1});
}

mrpt::obs::CObservation2DRangeScan::Ptr SyntheticRoom::scan(
	const mrpt::poses::CPose2D& robot, const mrpt::poses::CPose2D& sensorOnRobot,
	size_t beams, double aperture, double maxRange) const
{
	auto s = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	s->aperture = static_cast<float>(aperture);
	s->rightToLeft = true;
	s->maxRange = static_cast<float>(maxRange);
	s->sensorPose = mrpt::poses::CPose3D(sensorOnRobot);
	s->resizeScan(beams);
	const mrpt::poses::CPose2D sensor = robot + sensorOnRobot;
	for (size_t i = 0; i < beams; i++)
	{
		const double a = sensor.phi() - aperture / 2 +
			aperture * static_cast<double>(i) / static_cast<double>(beams - 1);
		const double dx = std::cos(a), dy = std::sin(a);
		double best = std::numeric_limits<double>::infinity();
		for (const auto& g : m_segments)
		{
			// sensor + t (dx,dy) = p0 + u (p1 - p0), t > 0, u in [0,1]
			const double ex = g.x1 - g.x0, ey = g.y1 - g.y0;
			const double den = dx * ey - dy * ex;
			if (std::abs(den) < 1e-12) continue;
			const double wx = g.x0 - sensor.x(), wy = g.y0 - sensor.y();
			const double t = (wx * ey - wy * ex) / den;
			const double u = (wx * dy - wy * dx) / den;
			if (t > 0 && u >= 0 && u <= 1 && t < best) best = t;
		}
		const bool valid = best < maxRange;
		s->setScanRange(i, static_cast<float>(valid ? best : maxRange));
		s->setScanRangeValidity(i, valid);
	}
	return s;
}
}  // namespace featloc::test
