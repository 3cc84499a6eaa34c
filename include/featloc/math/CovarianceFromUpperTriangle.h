#pragma once
#include <mrpt/math/CMatrixFixed.h>

namespace featloc
{
/** The symmetric 3x3 pose covariance from the six terms text files store
 * (poses_cov.txt, matches.txt): c_xx c_xy c_xyaw c_yy c_yyaw c_yawyaw. */
mrpt::math::CMatrixDouble33 covarianceFromUpperTriangle(const double* c);
}  // namespace featloc
