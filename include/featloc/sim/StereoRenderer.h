#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core/mat.hpp>

#include <memory>
#include <vector>

#include "featloc/sim/StereoCameraOptions.h"
#include "featloc/sim/SimWorld.h"

namespace featloc
{
class SurfaceMaterial;

/** One rendered stereo pair with its exact geometry. */
struct StereoFrame
{
	mrpt::poses::CPose3D leftCamera;  //!< in the world, optical axes
	cv::Mat left, right;  //!< CV_8U, with the image effects (and the lens)
	/** Exact depth Z [m] of every pixel of the ideal left image (the
	 * rectified pinhole image, no lens distortion); 0 where the pixel
	 * straddles two surfaces at different depths. CV_32F. */
	cv::Mat depth;
	cv::Mat rightDepth;	 //!< the same for the ideal right image
	/** fx * baseline / depth [px] (0 where depth is 0). CV_32F. */
	cv::Mat disparity;
};

/** Renders the simulated world as a rectified stereo camera sees it:
 * walls of finite height with their materials and patches, obstacles with
 * their tops, the floor and the ceiling, and the people as cylinders.
 *
 * How: the robot moves in the plane, so every image is a fixed rotation
 * (the camera's pitch and roll on the robot) of a level camera at the same
 * centre. A level camera sees vertical walls as vertical strips: each
 * image column is one 2-D ray, cast once against the walls, and each
 * surface it hits fills a run of rows whose height on the wall is linear
 * in the row. Two rays per column (at -1/4 and +1/4 pixel) are averaged,
 * so vertical edges are anti-aliased to sub-pixel accuracy. The floor and
 * ceiling are a per-row pass. When the camera is pitched, rolled or has a
 * lens, one precomputed remap (cv::remap) turns the level image into the
 * real one. Deterministic: only the image effects draw random numbers,
 * from the generator passed in. */
class StereoRenderer
{
   public:
	/** Throws ConfigError when a texture of the world is not a
	 * SurfaceMaterial (naming the world-file section). */
	StereoRenderer(const SimWorld& world, const StereoCameraOptions& camera);
	~StereoRenderer();

	/** Left camera pose in the world for a robot pose. */
	mrpt::poses::CPose3D leftCameraPose(const mrpt::poses::CPose2D& robot) const;

	/** The pair seen from `robot` at time t [s since the run's start]
	 * (people move); image effects draw from `rng`. Writes into `f`,
	 * reusing its buffers when they have the right size. */
	void render(const mrpt::poses::CPose2D& robot, double t, cv::RNG& rng, StereoFrame& f) const;
	StereoFrame render(const mrpt::poses::CPose2D& robot, double t, cv::RNG& rng) const
	{
		StereoFrame f;
		render(robot, t, rng, f);
		return f;
	}

	/** The left and right images without effects (grey levels as float,
	 * through the lens if there is one) and the ideal depths: what
	 * render() starts from. */
	void renderIdeal(
		const mrpt::poses::CPose3D& leftCamera, double t, cv::Mat& left, cv::Mat& right,
		cv::Mat& leftDepth, cv::Mat& rightDepth) const;

	const StereoCameraOptions& camera() const { return m_cam; }

   private:
	void renderLevel(
		const mrpt::poses::CPose3D& cameraPose, double t, cv::Mat& intensity,
		cv::Mat& depth) const;
	void toCamera(
		const cv::Mat& levelIntensity, const cv::Mat& levelDepth, cv::Mat* intensity,
		cv::Mat* idealDepth) const;

	const SimWorld& m_world;
	StereoCameraOptions m_cam;
	/** Level (virtual) camera: intrinsics and canvas. */
	double m_cxLevel = 0, m_cyLevel = 0;
	int m_wLevel = 0, m_hLevel = 0;
	/** Rotation from the level camera to the real one is not identity, or
	 * there is a lens: the level image is remapped. */
	bool m_warp = false;
	cv::Mat m_mapX, m_mapY;	 //!< real (distorted) pixel -> level pixel
	cv::Mat m_idealX, m_idealY, m_idealDepthScale;	//!< ideal pixel -> level pixel, 1/d.z
	/** Per wall segment: its material and its patches' materials. */
	std::vector<std::shared_ptr<const SurfaceMaterial>> m_segmentMaterials;
	std::vector<std::vector<std::shared_ptr<const SurfaceMaterial>>> m_patchMaterials;
	/** Buffers reused from frame to frame (fresh megabyte-sized buffers
	 * every frame cost more in page faults than the rendering itself), so
	 * one renderer must not render in two threads at once. */
	struct Workspace
	{
		cv::Mat background, backgroundT, colI, colD;
		cv::Mat levelI[2], levelD[2], ideal[2];
	};
	mutable Workspace m_ws;
	std::shared_ptr<const SurfaceMaterial> m_floor, m_ceiling;
};
}  // namespace featloc
