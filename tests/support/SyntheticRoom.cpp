#include "SyntheticRoom.h"

#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <limits>

#include "featloc/config/TrackedConfig.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/SimWorld.h"

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

SyntheticRoom SyntheticRoom::fromWorldFile(const std::string& path, double t, bool withPeople)
{
	TrackedConfig cfg;
	cfg.loadFile(path);
	const SimWorld world = SimWorld::fromConfig(cfg);
	SyntheticRoom r;
	for (const auto& w : world.segments()) r.add(w.a.x, w.a.y, w.b.x, w.b.y);
	std::vector<CircleShape> circles = world.circles();
	if (withPeople) world.circlesAt(t, circles);
	for (const auto& c : circles) r.addCircle(c.centre.x, c.centre.y, c.radius);
	return r;
}

void SyntheticRoom::add(double x0, double y0, double x1, double y1)
{
	m_segments.push_back({x0, y0, x1, y1});
}

void SyntheticRoom::addCircle(double cx, double cy, double radius)
{
	m_circles.push_back({cx, cy, radius});
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
	std::vector<WallSegment> walls;
	for (const auto& g : m_segments)
	{
		WallSegment w;
		w.a = {g.x0, g.y0};
		w.b = {g.x1, g.y1};
		walls.push_back(w);
	}
	std::vector<CircleShape> circles;
	for (const auto& c : m_circles)
	{
		CircleShape shape;
		shape.centre = {c[0], c[1]};
		shape.radius = c[2];
		circles.push_back(shape);
	}
	std::vector<double> ranges;
	const mrpt::poses::CPose2D sensor = robot + sensorOnRobot;
	RayCaster::cast(sensor.asTPose(), -aperture / 2, aperture / static_cast<double>(beams - 1),
		beams, maxRange, walls, circles, ranges);
	for (size_t i = 0; i < beams; i++)
	{
		const bool valid = ranges[i] < maxRange;
		s->setScanRange(i, static_cast<float>(valid ? ranges[i] : maxRange));
		s->setScanRangeValidity(i, valid);
	}
	return s;
}
}  // namespace featloc::test
