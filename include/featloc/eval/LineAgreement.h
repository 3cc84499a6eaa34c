#pragma once
#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "featloc/stereo/WorldVerticalLine.h"

namespace featloc
{
/** Do two sets of vertical lines, seen from two poses, put the same lines
 * in the same places? Lines pair up as mutual nearest neighbours on the
 * floor plan, among lines of the same polarity whose height ranges
 * overlap; no distance gate, so a line that is wrong shows as a pair that
 * disagrees, not as a pair left out. Each pair's difference is judged by
 * its Mahalanobis distance under the sum of the two covariances (the two
 * pairs' images are independent). */
class LineAgreement
{
   public:
	struct Pair
	{
		size_t a = 0, b = 0;
		Eigen::Vector2d difference = Eigen::Vector2d::Zero();  //!< b - a [m]
		double mahalanobis2 = 0;
	};

	static std::vector<Pair> pair(const std::vector<WorldVerticalLine>& a, const std::vector<WorldVerticalLine>& b);
};
}  // namespace featloc
