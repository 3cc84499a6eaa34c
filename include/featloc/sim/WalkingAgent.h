#pragma once
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <vector>

#include "featloc/sim/CircleShape.h"
#include "featloc/sim/WallSegment.h"

namespace featloc
{
/** A person walking along waypoints at a constant speed, pausing at each
 * waypoint, seen by a laser as two legs (two small circles swinging with
 * the gait) or as one body circle; or a cart pushed along them, seen as a
 * rectangle lengthwise along its heading. Positions are analytic functions
 * of time, so a scan at any time sees the person exactly where it is. The
 * simulated camera sees people, not carts. */
class WalkingAgent
{
   public:
	enum class Shape
	{
		Legs,
		Body,
		Cart
	};
	enum class Mode
	{
		Loop,  //!< w0 -> ... -> w_last -> w0 -> ...
		PingPong,  //!< w0 -> ... -> w_last -> ... -> w0 -> ...
		Once  //!< w0 -> ... -> w_last, then stands there
	};
	struct Params
	{
		std::string name;
		Shape shape = Shape::Legs;
		std::vector<mrpt::math::TPoint2D> waypoints;
		double speed = 1.2;	 //!< [m/s]
		double pause = 0;  //!< [s] at each waypoint
		Mode mode = Mode::Loop;
		double startTime = 0;  //!< [s] stands at w0 before this
		double bodyRadius = 0.22;  //!< [m] Body shape
		double legRadius = 0.06;  //!< [m] Legs shape
		double legSeparation = 0.25;  //!< [m] between leg centres, across
		double strideLength = 1.4;	//!< [m] walked per gait cycle
		double stepAmplitude = 0.15;  //!< [m] leg swing, along the heading
		double cartLength = 1.0, cartWidth = 0.6;  //!< [m] Cart shape
		std::string texture = "clothes";
	};
	struct State
	{
		mrpt::math::TPoint2D position;
		double heading = 0;	 //!< [rad]
		bool walking = false;
		double distance = 0;  //!< walked since the start [m] (gait phase)
	};

	explicit WalkingAgent(Params params);

	const Params& params() const { return m_params; }
	State stateAt(double t) const;
	/** Appends the circles the laser sees at time t (none for a cart). */
	void shapesAt(double t, std::vector<CircleShape>& out) const;
	/** Appends the segments the laser sees at time t: a cart's four sides
	 * (nothing for a person). */
	void segmentsAt(double t, std::vector<WallSegment>& out) const;
	/** Appends the cylinders a camera sees at time t: the laser's circles
	 * (legs up to the hip, or the whole body) plus, for legs, a torso and a
	 * head above them. */
	void cameraShapesAt(double t, std::vector<CircleShape>& out) const;

   private:
	struct Phase
	{
		double start;  //!< since startTime [s]
		double duration;
		mrpt::math::TPoint2D from, to;
		bool walking;
		double distanceAtStart;
	};
	Params m_params;
	std::vector<Phase> m_phases;
	double m_routeDuration = 0;	 //!< one pass of the route [s]
	double m_routeDistance = 0;	 //!< [m]
};
}  // namespace featloc
