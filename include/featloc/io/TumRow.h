#pragma once
#include <mrpt/poses/CPose2D.h>

#include <string>

namespace featloc
{
/** A planar pose as a row of a TUM trajectory file, "t x y z qx qy qz qw"
 * (z = 0, a rotation about Z), with its LF; full precision (ground-truth
 * files of the simulator and the device emulator). */
std::string tumRow(double t, const mrpt::poses::CPose2D& pose);
}  // namespace featloc
