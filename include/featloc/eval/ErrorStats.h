#pragma once
#include <cstddef>
#include <vector>

namespace featloc
{
/** Summary statistics of a set of (non-negative) errors or timings. */
struct ErrorStats
{
	size_t count = 0;
	double mean = 0;
	double median = 0;
	double p95 = 0;	 //!< 95th percentile, linear interpolation
	double rmse = 0;  //!< sqrt(mean of squares)
	double stddev = 0;	//!< population standard deviation
	double max = 0;

	/** All zero for an empty set. */
	static ErrorStats of(std::vector<double> values);
};
}  // namespace featloc
