#pragma once
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose3D.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/output/RunOutput.h"

namespace featloc
{
/** map.3Dscene (opens in SceneViewer3D): the scans' points placed at the
 * estimated poses, the estimated path as a line strip, the robot's 3-sigma
 * (x, y) covariance ellipse every few scans, the estimator's landmarks
 * (EKF) with their 3-sigma ellipses, a corner at the last pose, a grid on
 * the floor, and a known map's occupied cells (localization in a map) in
 * light grey under the scans. Written in finish(), also after an error,
 * with what the run produced until then. */
class ScanMapSceneWriter : public RunOutput
{
   public:
	/** \param scanDecimation place every N-th scan's points (1 = all).
	 * \param pointResolution [m] keep the first point of each cell of this
	 *   size (0: every point).
	 * \param ellipseEvery robot covariance ellipse every N-th scan (0: none). */
	ScanMapSceneWriter(std::string path, unsigned int scanDecimation, double pointResolution,
		unsigned int ellipseEvery, std::vector<mrpt::math::TPoint2D> map = {});
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	unsigned int m_decimation;
	double m_pointResolution;
	std::vector<float> m_x, m_y, m_z;
	std::unordered_set<uint64_t> m_cells;	//!< cells holding a point (pointResolution > 0)
	unsigned int m_ellipseEvery;
	std::vector<mrpt::math::TPose3D> m_path3d;
	/** Robot (x, y) means and covariances at the ellipse scans. */
	std::vector<std::pair<Eigen::Vector2d, Eigen::Matrix2d>> m_robotEllipses;
	std::vector<EstimatedLandmark> m_landmarks;  //!< after the last step
	std::vector<mrpt::math::TPoint2D> m_map;
};
}  // namespace featloc
