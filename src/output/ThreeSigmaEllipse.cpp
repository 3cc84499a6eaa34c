#include "featloc/output/ThreeSigmaEllipse.h"

#include <mrpt/opengl/CEllipsoid2D.h>

namespace featloc
{
std::shared_ptr<mrpt::opengl::CEllipsoid2D> threeSigmaEllipse(
	double x, double y, double cxx, double cxy, double cyy, double z)
{
	auto e = mrpt::opengl::CEllipsoid2D::Create();
	mrpt::math::CMatrixDouble22 c;
	c(0, 0) = cxx;
	c(0, 1) = c(1, 0) = cxy;
	c(1, 1) = cyy;
	e->setCovMatrixAndMean(c, mrpt::math::CVectorFixedDouble<2>({x, y}));
	e->setQuantiles(3.0f);
	e->setLocation(0, 0, z);
	return e;
}
}  // namespace featloc
