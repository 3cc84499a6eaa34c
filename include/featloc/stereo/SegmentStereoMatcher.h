#pragma once
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Segment-based stereo matching (Moon, Miura & Shirai 1999, section 2.1)
 * by dynamic programming, after Lee & Leou (1994).
 *
 * In a rectified pair a left segment can only match a right segment of the
 * same polarity that shares rows with it (overlap ratio of at least
 * min_overlap) at a disparity in [min_disparity, max_disparity]. Each such
 * candidate scores
 *     similarity = w_o * overlap + w_a * orientation + w_l * length,
 * with overlap = common rows / rows covered by either, orientation =
 * 1 - |angle difference| / max_angle_diff_deg, length = eq. (18). The
 * ordering constraint holds among segments that share epipolar lines: the
 * segments are grouped into the connected components of the candidate
 * graph and, within each group, the order-preserving one-to-one matching of
 * largest total similarity is found by dynamic programming over the left
 * and right segments in column order (the longest-common-subsequence
 * recursion with similarities as weights). Candidates below
 * min_similarity are never matched. */
class SegmentStereoMatcher
{
   public:
	struct Options
	{
		double min_disparity = 0.5;	 //!< [px]
		double max_disparity = 64;	//!< [px]
		double min_overlap = 0.5;
		double max_angle_diff_deg = 4;
		double min_similarity = 0.6;
		double weight_overlap = 1.0 / 3, weight_orientation = 1.0 / 3, weight_length = 1.0 / 3;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s);
		void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const;
	};

	SegmentStereoMatcher() = default;
	explicit SegmentStereoMatcher(const Options& o) : options(o) {}
	Options options;

	/** The candidate pair's terms, or false when it is not a candidate. */
	bool score(const VerticalSegment& l, const VerticalSegment& r, SegmentMatch& m) const;

	/** One-to-one, order-preserving matches, ordered by left column. */
	std::vector<SegmentMatch> match(
		const std::vector<VerticalSegment>& left, const std::vector<VerticalSegment>& right) const;
};
}  // namespace featloc
