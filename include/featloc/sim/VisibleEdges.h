#pragma once
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

#include "featloc/sim/SimWorld.h"
#include "featloc/sim/StereoCameraOptions.h"

namespace featloc
{
/** A vertical edge of the world: where two surfaces meet (a wall's end or
 * corner, an obstacle's corner) or where a wall's material changes (the
 * sides of a poster, a door, a patch). Fine texture inside a material is
 * not an edge. */
struct WorldEdge
{
	double x = 0, y = 0;  //!< [m]
	double zLow = 0, zHigh = 0;	 //!< [m]
	std::string object;	 //!< world-file section, e.g. "Wall.partition"
	double s = 0;  //!< [m] along the object's polyline
};

/** One edge as a stereo frame sees it: the part of it visible in the left
 * image and where that part projects in the ideal (rectified) images. */
struct VisibleEdge
{
	WorldEdge edge;
	double zLow = 0, zHigh = 0;	 //!< [m] visible part (left image)
	double uLeftLow = 0, vLeftLow = 0, uLeftHigh = 0, vLeftHigh = 0;  //!< [px]
	double uRightLow = 0, vRightLow = 0, uRightHigh = 0, vRightHigh = 0;  //!< [px]
	bool visibleRight = false;	//!< most of that part is visible in the right image too
};

/** Lists the world's vertical edges once, then tells which are visible in
 * a rendered frame (depth test against the exact depth images). */
class VisibleEdges
{
   public:
	VisibleEdges(const SimWorld& world, const StereoCameraOptions& camera);

	const std::vector<WorldEdge>& edges() const { return m_edges; }

	/** Edges with at least 3 visible pixels in the left image, bottom and
	 * top of the visible part projected into both ideal images. */
	std::vector<VisibleEdge> visible(
		const mrpt::poses::CPose3D& leftCamera, const cv::Mat& leftDepth,
		const cv::Mat& rightDepth) const;

   private:
	StereoCameraOptions m_cam;
	std::vector<WorldEdge> m_edges;
};
}  // namespace featloc
