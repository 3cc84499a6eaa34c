#pragma once
#include <mrpt/obs/CObservationStereoImages.h>

#include <fstream>
#include <string>
#include <vector>

#include "featloc/sim/StereoCameraOptions.h"
#include "featloc/sim/StereoRenderer.h"
#include "featloc/sim/VisibleEdges.h"

namespace featloc
{
/** Writes the simulated stereo pairs as MRPT does and their ground truth.
 *
 * Images: `<rawlog folder>/<rawlog name without extension>_Images/`
 * (MRPT's convention: RawLogViewer and CRawlog::detectImagesDirectory look
 * there), named `<label>_<frame>_left.png` / `_right.png`; the
 * CObservationStereoImages stores those names (external storage) with
 * both cameras' calibration and the right camera's pose.
 *
 * Ground truth, beside the rawlog's own (`<gtPrefix>` = PREFIX):
 *   PREFIX.camera.gt.txt  the left camera (optical axes: x right, y down,
 *                         z forward) in the world per frame, TUM format
 *   PREFIX.edges.gt.txt   the visible vertical edges per frame (columns
 *                         in the file's header)
 *   PREFIX_GT/<label>_<frame>_disparity.png  exact disparity of the ideal
 *                         left image, KITTI's encoding: uint16 =
 *                         disparity * 256, 0 = none (mixed pixels too). */
class StereoOutputWriter
{
   public:
	StereoOutputWriter(
		const StereoCameraOptions& camera, const std::string& rawlogPath,
		const std::string& gtPrefix);

	/** Writes the frame's files; returns the observation to put in the
	 * rawlog (its images loaded and marked as externally stored). */
	mrpt::obs::CObservationStereoImages::Ptr write(
		size_t frame, double time, const StereoFrame& f, const std::vector<VisibleEdge>& edges);

	const std::string& imagesDir() const { return m_imagesDir; }
	/** "<label>_<frame, 6 digits>": the stem of a pair's files
	 * (`_left.png`, `_right.png`, `_disparity.png` follow). featloc-stereo-
	 * import names imported pairs the same way. */
	static std::string fileStem(const std::string& label, size_t frame);
	/** Throws when a ground-truth stream failed. */
	void finish();

   private:
	StereoCameraOptions m_cam;
	std::string m_imagesDir, m_gtDir, m_cameraPath, m_edgesPath;
	std::ofstream m_cameraGt, m_edgesGt;
};
}  // namespace featloc
