#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace featloc::test
{
/** A few wall segments and circles, scanned by the simulator's exact
 * RayCaster, to make noise-free scans with known geometry for unit tests
 * (featloc-sim adds robots, people, noise and rawlogs). */
class SyntheticRoom
{
   public:
	struct Segment
	{
		double x0, y0, x1, y1;
	};

	/** An 8 m x 6 m room with a pillar, a box and a recess: enough corners
	 * to constrain all three degrees of freedom. */
	static SyntheticRoom office();
	/** Two long parallel walls (a corridor): motion along it is unobservable. */
	static SyntheticRoom corridor();
	/** A featloc-sim world file's walls and obstacles, and (withPeople) its
	 * people where they are at time t [s] (legs or body: circles). */
	static SyntheticRoom fromWorldFile(const std::string& path, double t, bool withPeople = true);

	void add(double x0, double y0, double x1, double y1);
	/** A circle (a pillar, or a person's body). */
	void addCircle(double cx, double cy, double radius);

	/** Exact scan from the robot at `robot`, sensor mounted at `sensorOnRobot`,
	 * `beams` beams over `aperture` (centred, counter-clockwise), ranges >=
	 * maxRange marked invalid. */
	mrpt::obs::CObservation2DRangeScan::Ptr scan(
		const mrpt::poses::CPose2D& robot,
		const mrpt::poses::CPose2D& sensorOnRobot = mrpt::poses::CPose2D(),
		size_t beams = 361, double aperture = M_PI, double maxRange = 30) const;

   private:
	std::vector<Segment> m_segments;
	std::vector<std::vector<double>> m_circles;	 // cx, cy, r
};
}  // namespace featloc::test
