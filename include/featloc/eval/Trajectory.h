#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace featloc
{
/** A planar pose at a time, optionally with its 3x3 covariance. */
struct TimedPose
{
	double t = 0;  //!< [s]
	mrpt::math::TPose2D pose;  //!< x [m], y [m], phi [rad]
	bool hasCovariance = false;
	mrpt::math::CMatrixDouble33 cov;
};

/** A trajectory read from a file, in time order. */
struct Trajectory
{
	std::string source;	 //!< file it came from
	std::vector<TimedPose> poses;
	/** False for formats without times (MRPT robot paths, KITTI): `t` is
	 * then the row index, and evaluation pairs rows in order. */
	bool timed = true;
	/** Some consecutive rows share a time (a format #1 log whose frames
	 * all carry one timestamp, as MRPT's kf-slam_demo.rawlog): the rows
	 * can only be paired in order, with an untimed reference. */
	bool repeatedTimes = false;
};

/** A relative pose between two times (Kummerle et al. 2009 relations). */
struct PoseRelation
{
	double t1 = 0, t2 = 0;	//!< [s]
	mrpt::math::TPose2D delta;	//!< pose at t2 in the frame of the pose at t1
};
}  // namespace featloc
