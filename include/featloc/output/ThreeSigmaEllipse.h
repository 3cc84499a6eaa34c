#pragma once
#include <mrpt/opengl/opengl_frwds.h>

#include <memory>

namespace mrpt::opengl
{
class CEllipsoid2D;
}

namespace featloc
{
/** The 3-sigma ellipse of a 2-D position (x, y) with covariance
 * [cxx cxy; cxy cyy], at height z: how map.3Dscene and featloc-viewer draw
 * robot and landmark uncertainty. The caller sets the colour. */
std::shared_ptr<mrpt::opengl::CEllipsoid2D> threeSigmaEllipse(
	double x, double y, double cxx, double cxy, double cyy, double z);
}  // namespace featloc
