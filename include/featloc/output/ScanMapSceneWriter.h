#pragma once
#include <mrpt/math/TPose3D.h>

#include <string>
#include <vector>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** map.3Dscene (opens in SceneViewer3D): the scans' points placed at the
 * estimated poses, the estimated path as a line strip, a corner at each
 * scan pose, a grid on the floor. Written in finish(), also after an error,
 * with what the run produced until then. */
class ScanMapSceneWriter : public RunOutput
{
   public:
	/** \param scanDecimation place every N-th scan's points (1 = all). */
	ScanMapSceneWriter(std::string path, unsigned int scanDecimation);
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	unsigned int m_decimation;
	std::vector<float> m_x, m_y, m_z;
	std::vector<mrpt::math::TPose3D> m_path3d;
};
}  // namespace featloc
