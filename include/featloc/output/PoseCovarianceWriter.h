#pragma once
#include "featloc/output/TextRowWriter.h"

namespace featloc
{
/** poses_cov.txt: one row per processed scan,
 *   t x y yaw  c_xx c_xy c_xyaw c_yy c_yyaw c_yawyaw
 * with yaw in radians and the upper triangle of the estimate's 3x3
 * covariance (m^2, m*rad, rad^2). featloc-eval reads it. */
class PoseCovarianceWriter : public TextRowWriter
{
   public:
	explicit PoseCovarianceWriter(std::string path);
	void onStep(const StepRecord& record) override;
};
}  // namespace featloc
