#include "featloc/stereo/SegmentStereoMatcher.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void SegmentStereoMatcher::Options::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "min_disparity", min_disparity);
	read(c, s, "max_disparity", max_disparity);
	read(c, s, "min_overlap", min_overlap);
	read(c, s, "max_angle_diff_deg", max_angle_diff_deg);
	read(c, s, "min_similarity", min_similarity);
	read(c, s, "weight_overlap", weight_overlap);
	read(c, s, "weight_orientation", weight_orientation);
	read(c, s, "weight_length", weight_length);
	require(min_disparity >= 0, c, s, "min_disparity", ">= 0");
	require(max_disparity > min_disparity, c, s, "max_disparity", "> min_disparity");
	require(min_overlap > 0 && min_overlap <= 1, c, s, "min_overlap", "in (0, 1]");
	require(max_angle_diff_deg > 0, c, s, "max_angle_diff_deg", "> 0");
	require(min_similarity >= 0 && min_similarity <= 1, c, s, "min_similarity", "in [0, 1]");
	const double w = weight_overlap + weight_orientation + weight_length;
	require(weight_overlap >= 0 && weight_orientation >= 0 && weight_length >= 0 && std::abs(w - 1) < 1e-6,
		c, s, "weight_length", "weights >= 0 that sum to 1");
}

void SegmentStereoMatcher::Options::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "min_disparity", min_disparity, "[px] nearest disparity considered (far limit)");
	write(c, s, "max_disparity", max_disparity, "[px] largest disparity considered (near limit)");
	write(c, s, "min_overlap", min_overlap, "common rows / rows of either, for a candidate pair");
	write(c, s, "max_angle_diff_deg", max_angle_diff_deg, "[deg] orientation difference scoring 0");
	write(c, s, "min_similarity", min_similarity, "weakest pair matched (similarity in [0, 1])");
	write(c, s, "weight_overlap", weight_overlap, "similarity weight of the overlap ratio");
	write(c, s, "weight_orientation", weight_orientation, "similarity weight of the orientation");
	write(c, s, "weight_length", weight_length, "similarity weight of the length ratio, eq. (18)");
}

bool SegmentStereoMatcher::score(
	const VerticalSegment& l, const VerticalSegment& r, SegmentMatch& m) const
{
	if (l.polarity != r.polarity) return false;
	const double lo = std::max(l.vTop, r.vTop), hi = std::min(l.vBottom, r.vBottom);
	if (hi < lo) return false;
	const double common = hi - lo + 1;
	const double either = std::max(l.vBottom, r.vBottom) - std::min(l.vTop, r.vTop) + 1;
	m.overlap = common / either;
	if (m.overlap < options.min_overlap) return false;
	const double vm = 0.5 * (lo + hi);
	m.disparity = l.uAt(vm) - r.uAt(vm);
	if (m.disparity < options.min_disparity || m.disparity > options.max_disparity) return false;
	const double dAngle = std::abs(std::atan(l.slope) - std::atan(r.slope)) * 180.0 / M_PI;
	m.orientation = std::max(0.0, 1.0 - dAngle / options.max_angle_diff_deg);
	m.lengthSimilarity = std::min(l.length(), r.length()) / std::max(l.length(), r.length());
	m.similarity = options.weight_overlap * m.overlap + options.weight_orientation * m.orientation +
		options.weight_length * m.lengthSimilarity;
	m.vLow = lo;
	m.vHigh = hi;
	return m.similarity >= options.min_similarity;
}

std::vector<SegmentMatch> SegmentStereoMatcher::match(
	const std::vector<VerticalSegment>& left, const std::vector<VerticalSegment>& right) const
{
	// Candidates, and the groups they connect (union-find over left and
	// right segments: right j is node left.size() + j).
	const size_t nl = left.size(), nr = right.size();
	std::vector<size_t> parent(nl + nr);
	std::iota(parent.begin(), parent.end(), 0);
	auto find = [&](size_t a) {
		while (parent[a] != a) a = parent[a] = parent[parent[a]];
		return a;
	};
	std::vector<SegmentMatch> candidates;
	for (size_t i = 0; i < nl; i++)
		for (size_t j = 0; j < nr; j++)
		{
			SegmentMatch m;
			if (!score(left[i], right[j], m)) continue;
			m.left = i;
			m.right = j;
			candidates.push_back(m);
			parent[find(i)] = find(nl + j);
		}
	std::vector<std::vector<const SegmentMatch*>> groups(nl + nr);
	for (const auto& c : candidates) groups[find(c.left)].push_back(&c);

	std::vector<SegmentMatch> out;
	for (auto& g : groups)
	{
		if (g.empty()) continue;
		// The group's left and right segments in column order.
		std::vector<size_t> ls, rs;
		for (const auto* c : g) ls.push_back(c->left), rs.push_back(c->right);
		auto byU = [](const std::vector<VerticalSegment>& s) {
			return [&s](size_t a, size_t b) { return s[a].u < s[b].u || (s[a].u == s[b].u && a < b); };
		};
		std::sort(ls.begin(), ls.end(), byU(left));
		ls.erase(std::unique(ls.begin(), ls.end()), ls.end());
		std::sort(rs.begin(), rs.end(), byU(right));
		rs.erase(std::unique(rs.begin(), rs.end()), rs.end());
		const size_t a = ls.size(), b = rs.size();
		std::vector<const SegmentMatch*> pair(a * b, nullptr);
		for (const auto* c : g)
		{
			const auto i = static_cast<size_t>(std::lower_bound(ls.begin(), ls.end(), c->left, byU(left)) - ls.begin());
			const auto j = static_cast<size_t>(std::lower_bound(rs.begin(), rs.end(), c->right, byU(right)) - rs.begin());
			pair[i * b + j] = c;
		}
		// D(i, j): best total similarity of the first i left and j right.
		std::vector<double> D((a + 1) * (b + 1), 0.0);
		auto at = [&](size_t i, size_t j) -> double& { return D[i * (b + 1) + j]; };
		for (size_t i = 1; i <= a; i++)
			for (size_t j = 1; j <= b; j++)
			{
				double best = std::max(at(i - 1, j), at(i, j - 1));
				if (const auto* c = pair[(i - 1) * b + (j - 1)]) best = std::max(best, at(i - 1, j - 1) + c->similarity);
				at(i, j) = best;
			}
		for (size_t i = a, j = b; i > 0 && j > 0;)
		{
			const auto* c = pair[(i - 1) * b + (j - 1)];
			if (c && at(i, j) == at(i - 1, j - 1) + c->similarity)
			{
				out.push_back(*c);
				i--, j--;
			}
			else if (at(i, j) == at(i - 1, j))
				i--;
			else
				j--;
		}
	}
	std::sort(out.begin(), out.end(), [&](const SegmentMatch& x, const SegmentMatch& y) {
		return left[x.left].u < left[y.left].u;
	});
	return out;
}
}  // namespace featloc
