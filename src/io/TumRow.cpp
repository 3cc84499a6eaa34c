#include "featloc/io/TumRow.h"

#include <cmath>
#include <cstdio>

namespace featloc
{
std::string tumRow(double t, const mrpt::poses::CPose2D& p)
{
	char row[256];
	std::snprintf(
		row, sizeof(row), "%.9f %.12f %.12f 0 0 0 %.15f %.15f\n", t, p.x(), p.y(),
		std::sin(p.phi() / 2), std::cos(p.phi() / 2));
	return row;
}
}  // namespace featloc
