#pragma once
#include <fstream>
#include <string>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** poses_cov.txt: one row per processed scan,
 *   t x y yaw  c_xx c_xy c_xyaw c_yy c_yyaw c_yawyaw
 * with yaw in radians and the upper triangle of the estimate's 3x3
 * covariance (m^2, m*rad, rad^2). featloc-eval reads it (NEES). */
class PoseCovarianceWriter : public RunOutput
{
   public:
	explicit PoseCovarianceWriter(std::string path);
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	std::ofstream m_out;
};
}  // namespace featloc
