#pragma once
#include <mrpt/gui/CWxGLCanvasBase.h>
#include <mrpt/math/TPoint3D.h>

#include <utility>
#include <vector>
#include <mrpt/opengl/opengl_frwds.h>

namespace mrpt::opengl
{
class CEllipsoid2D;
}

#include "featloc/gui/RunResults.h"

namespace featloc
{
/** featloc-viewer's 2-D map view, on MRPT's wx OpenGL canvas: every scan at
 * its estimated pose, the estimated trajectory and the ground truth (in the
 * estimate's frame), 3-sigma ellipses of the robot (about 100 along the
 * path, and the current step's) and of the landmarks,
 * and the current step's scan (red) over its reference keyframe scan
 * (green). Seen from above with an orthographic camera; left or right drag
 * pans, the wheel zooms. */
class MapCanvas : public mrpt::gui::CWxGLCanvasBase
{
   public:
	explicit MapCanvas(wxWindow* parent);

	/** Builds the scene of a run (kept by reference: `results` must outlive
	 * the canvas or the next setResults). */
	void setResults(const RunResults& results);
	/** Highlights step `i` (its scan, reference scan, pose and ellipse). */
	void setStep(size_t i);
	/** Camera over the whole trajectory and ground truth. */
	void fitAll();

	/** Colours of what is drawn (RGB), for the legend and the tests. */
	static constexpr unsigned char kTrajectory[3] = {30, 80, 220};
	static constexpr unsigned char kGroundTruth[3] = {20, 170, 60};
	static constexpr unsigned char kCurrentScan[3] = {230, 30, 30};
	static constexpr unsigned char kReferenceScan[3] = {0, 190, 190};
	static constexpr unsigned char kScans[3] = {150, 150, 150};
	static constexpr unsigned char kKnownMap[3] = {235, 165, 205};  // pink: apart from the ellipses' tan
	static constexpr unsigned char kLandmarks[3] = {160, 60, 200};
	static constexpr unsigned char kPathEllipses[3] = {250, 200, 130};

   protected:
	void OnPreRender() override;

   private:
	void onMouseMove(wxMouseEvent& event);
	/** Appends step's scan points in the world frame at height z. */
	void placeScan(size_t step, float z, std::vector<mrpt::math::TPoint3Df>& points) const;

	const RunResults* m_results = nullptr;
	std::shared_ptr<mrpt::opengl::CPointCloud> m_current, m_reference;
	/** The map's scans at several cell sizes [m] (one drawn at a time). */
	std::vector<std::pair<double, std::shared_ptr<mrpt::opengl::CPointCloud>>> m_levels;
	std::shared_ptr<mrpt::opengl::CSetOfLines> m_robot;
	std::shared_ptr<mrpt::opengl::CEllipsoid2D> m_robotEllipse;
	double m_minX = 0, m_minY = 0, m_maxX = 1, m_maxY = 1;	//!< what fitAll shows [m]
};
}  // namespace featloc
