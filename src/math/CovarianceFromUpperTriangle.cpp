#include "featloc/math/CovarianceFromUpperTriangle.h"

namespace featloc
{
mrpt::math::CMatrixDouble33 covarianceFromUpperTriangle(const double* c)
{
	mrpt::math::CMatrixDouble33 m;
	m(0, 0) = c[0];
	m(0, 1) = m(1, 0) = c[1];
	m(0, 2) = m(2, 0) = c[2];
	m(1, 1) = c[3];
	m(1, 2) = m(2, 1) = c[4];
	m(2, 2) = c[5];
	return m;
}
}  // namespace featloc
