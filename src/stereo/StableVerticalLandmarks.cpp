#include "featloc/stereo/StableVerticalLandmarks.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "featloc/config/ConfigValues.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/stereo/PlaneFit.h"
#include "featloc/stereo/SegmentBand.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(StableVerticalLandmarks, StereoLandmarkExtractor, featloc)

namespace
{
double seconds(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void StableVerticalLandmarks::loadParams(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	options.segments.loadFromConfigFile(c, s);
	options.matching.loadFromConfigFile(c, s);
	read(c, s, "map", options.map);
	read(c, s, "block_size", options.block_size);
	read(c, s, "num_disparities", options.num_disparities);
	read(c, s, "uniqueness_ratio", options.uniqueness_ratio);
	read(c, s, "texture_threshold", options.texture_threshold);
	read(c, s, "disparity_tolerance_px", options.disparity_tolerance_px);
	read(c, s, "sigma_img", options.sigma_img);
	read(c, s, "window_sigmas", options.window_sigmas);
	read(c, s, "min_plane_pixels", options.min_plane_pixels);
	read(c, s, "min_height", options.min_height);
	read(c, s, "max_height", options.max_height);
	read(c, s, "boundary_sigmas", options.boundary_sigmas);
	read(c, s, "min_boundary_angle_deg", options.min_boundary_angle_deg);
	read(c, s, "snap_to_segment", options.snap_to_segment);
	read(c, s, "sigma_end_px", options.sigma_end_px);
	read(c, s, "min_length_similarity", options.min_length_similarity);
	read(c, s, "wall_observations", options.wall_observations);
	read(c, s, "wall_min_view_angle_deg", options.wall_min_view_angle_deg);
	require(options.wall_min_view_angle_deg >= 0 && options.wall_min_view_angle_deg <= 90, c, s,
		"wall_min_view_angle_deg", "in [0, 90]");
	require(options.block_size >= 5 && options.block_size <= 255 && options.block_size % 2 == 1, c, s,
		"block_size", "odd, in [5, 255]");
	require(options.num_disparities >= 16 && options.num_disparities % 16 == 0, c, s, "num_disparities",
		"a positive multiple of 16");
	require(options.uniqueness_ratio >= 0, c, s, "uniqueness_ratio", ">= 0");
	require(options.texture_threshold >= 0, c, s, "texture_threshold", ">= 0");
	require(options.disparity_tolerance_px > 0, c, s, "disparity_tolerance_px", "> 0");
	require(options.max_height > options.min_height, c, s, "max_height", "> min_height");
	require(options.sigma_img > 0, c, s, "sigma_img", "> 0");
	require(options.window_sigmas > 0, c, s, "window_sigmas", "> 0");
	require(options.sigma_end_px > 0, c, s, "sigma_end_px", "> 0");
	require(options.boundary_sigmas >= 0, c, s, "boundary_sigmas", ">= 0");
	require(options.min_boundary_angle_deg >= 0 && options.min_boundary_angle_deg < 90, c, s,
		"min_boundary_angle_deg", "in [0, 90)");
	require(options.min_length_similarity >= 0 && options.min_length_similarity <= 1, c, s,
		"min_length_similarity", "in [0, 1]");
	walls.clear();
	m_mapPath.clear();
	if (options.map.empty()) return;  // requireComplete() says so when it is used
	std::string path = options.map;
	if (const auto* tc = dynamic_cast<const TrackedConfig*>(&c)) path = tc->resolvePath(s, "map", path);
	walls = WallMapFile::load(path);
	m_mapPath = path;
}

void StableVerticalLandmarks::requireComplete(const mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	require(!options.map.empty(), c, s, "map",
		"a map of the walls (a featloc-sim world file or lines 'x1 y1 x2 y2'): the reference planes");
}

void StableVerticalLandmarks::saveParams(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "map", options.map,
		"the known 2-D map whose walls are the reference planes: a featloc-sim world file or "
		"lines 'x1 y1 x2 y2' [m]; relative to this ini's folder");
	options.segments.saveToConfigFile(c, s);
	options.matching.saveToConfigFile(c, s);
	write(c, s, "block_size", options.block_size, "[px] SAD window (paper: 15)");
	write(c, s, "num_disparities", options.num_disparities, "[px] SAD search range, multiple of 16");
	write(c, s, "uniqueness_ratio", options.uniqueness_ratio, "[%] StereoBM: best SAD this much below the next");
	write(c, s, "texture_threshold", options.texture_threshold, "StereoBM: least texture in the window");
	write(c, s, "disparity_tolerance_px", options.disparity_tolerance_px,
		"[px] a segment match must agree with the SAD disparity image this well (2.2)");
	write(c, s, "sigma_img", options.sigma_img, "[px] image position sigma (paper: 0.5)");
	write(c, s, "window_sigmas", options.window_sigmas, "search windows are this many sigma (paper: 3)");
	write(c, s, "min_plane_pixels", options.min_plane_pixels, "disparity pixels needed to fit a plane");
	write(c, s, "min_height", options.min_height,
		"[m] wall points lower than this are left out of the plane fit (the floor)");
	write(c, s, "max_height", options.max_height,
		"[m] wall points higher than this are left out of the plane fit (the ceiling)");
	write(c, s, "boundary_sigmas", options.boundary_sigmas,
		"a feature this many sigma from the plane boundary is unstable (paper: 3)");
	write(c, s, "min_boundary_angle_deg", options.min_boundary_angle_deg,
		"[deg] a wall end seen at a smaller angle between the view ray and the wall is not searched (featloc)");
	write(c, s, "snap_to_segment", options.snap_to_segment,
		"a segment within 3 sigma outward of the SAD boundary is the boundary (featloc)");
	write(c, s, "sigma_end_px", options.sigma_end_px,
		"[px] sigma of a segment end's row (the ends' heights the EKF observes)");
	write(c, s, "min_length_similarity", options.min_length_similarity,
		"eq. (18): least min/max length of the left and right segments of a landmark");
	write(c, s, "wall_observations", options.wall_observations,
		"each fitted wall (eq. 11) also observes the robot's distance and heading to it (featloc)");
	write(c, s, "wall_min_view_angle_deg", options.wall_min_view_angle_deg,
		"[deg] a wall seen at a smaller mean angle to the view rays is not a wall observation (featloc)");
}

bool StableVerticalLandmarks::collinear(size_t w, size_t k) const
{
	if (w == k) return true;
	const auto &a = walls[w], &o = walls[k];
	const Eigen::Vector2d dir = (a.b - a.a) / a.length(), od = (o.b - o.a) / o.length();
	const Eigen::Vector2d n(-od.y(), od.x());
	return std::abs(dir.x() * od.y() - dir.y() * od.x()) <= std::sin(kCoplanarAngle) &&
		std::abs(n.dot(a.a - o.a)) <= kCoplanarDistance && std::abs(n.dot(a.b - o.a)) <= kCoplanarDistance;
}

bool StableVerticalLandmarks::continuesCoplanar(size_t w, bool atA) const
{
	const auto& wall = walls[w];
	const Eigen::Vector2d end = atA ? wall.a : wall.b, dir = (wall.b - wall.a) / wall.length();
	for (size_t k = 0; k < walls.size(); k++)
	{
		if (k == w) continue;
		if (!collinear(w, k)) continue;
		const auto& o = walls[k];
		const Eigen::Vector2d od = (o.b - o.a) / o.length();
		const double t = od.dot(end - o.a);
		// The other wall carries on past this end by kCoplanarContinuation
		// (not merely meets it, nor goes on for a stub: a recess's back
		// wall 5 cm past the ends of the bookshelf before it, then the
		// recess's side faces, made the shelf a "whiteboard on a wall",
		// whose end may be a texture edge: the books' edges were taken for
		// it).
		const double out = atA ? -1 : 1;  // along dir, leaving this wall
		const double tPast = od.dot(end + out * kCoplanarContinuation * dir - o.a);
		if (t > -kCoplanarDistance && t < o.length() + kCoplanarDistance && tPast >= 0 && tPast <= o.length())
			return true;
	}
	return false;
}

bool StableVerticalLandmarks::endStepVisible(const PlanarRegion& pl, bool atA, double depth,
	const StereoHead& head, const std::vector<double>& nearest, const BoundarySearch::Options& search) const
{
	if (depth <= 0 || static_cast<int>(nearest.size()) != head.width) return false;
	const double uE = atA ? pl.uA : pl.uB, sE = atA ? pl.sigmaUA : pl.sigmaUB;
	const int outward = (atA ? pl.uB : pl.uA) > uE ? -1 : 1;
	const double dEnd = head.fx * head.baseline / depth;
	const double reach = search.window_sigmas * sE + search.evidence_px;
	// From half a column past the end: the end's own column meets the wall.
	for (double k = 1; k <= reach; k += 1)
	{
		const long u = std::lround(uE + outward * k);
		if (u < 0 || u >= head.width) break;
		const double dn = head.fx * head.baseline / nearest[static_cast<size_t>(u)];  // 0 where nothing
		if (dn >= dEnd - kEndStepPx) return false;
	}
	return true;
}

cv::Mat StableVerticalLandmarks::disparity(
	const cv::Mat& left, const cv::Mat& right, int minDisparity, int numDisparities) const
{
	return sad().compute(left, right, minDisparity, numDisparities > 0 ? numDisparities : options.num_disparities);
}

SadDisparity StableVerticalLandmarks::sad() const
{
	SadDisparity::Options o;
	o.block_size = options.block_size;
	o.uniqueness_ratio = options.uniqueness_ratio;
	o.texture_threshold = options.texture_threshold;
	o.tolerance_px = options.disparity_tolerance_px;
	return SadDisparity(o);
}

StereoVerticalLines::Options StableVerticalLandmarks::segmentStageOptions() const
{
	StereoVerticalLines::Options o;
	o.segments = options.segments;
	o.matching = options.matching;
	o.sad = sad().options;
	o.num_disparities = options.num_disparities;
	o.sigma_img = options.sigma_img;
	return o;
}

StereoLandmarkFrame StableVerticalLandmarks::process(
	const cv::Mat& left, const cv::Mat& right, const StereoHead& head,
	const mrpt::poses::CPosePDFGaussian& robot) const
{
	const auto t0 = std::chrono::steady_clock::now();
	StereoLandmarkFrame f;
	const Eigen::Vector3d X(robot.mean.x(), robot.mean.y(), robot.mean.phi());
	Eigen::Matrix3d SX;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) SX(i, j) = robot.cov(i, j);
	const int W = left.cols, H = left.rows;
	const double s2img = options.sigma_img * options.sigma_img;

	// 1. Segments, matched by DP (2.1).
	const VerticalSegmentDetector detector(options.segments);
	f.left = detector.detect(left);
	f.right = detector.detect(right);
	const SegmentStereoMatcher matcher(options.matching);
	f.matches = matcher.match(f.left, f.right);

	// 2. The SAD disparity image (2.2) over the disparities the visible
	// walls can show (2.3.3), and the matches it supports.
	PlanarRegionExtractor::Options po;
	po.sigma_img = options.sigma_img;
	po.window_sigmas = options.window_sigmas;
	po.min_pixels = options.min_plane_pixels;
	po.block_size = options.block_size;
	po.min_height = options.min_height;
	po.max_height = options.max_height;
	const PlanarRegionExtractor planes(po);
	double dLo = 1e300, dHi = -1e300;
	for (const auto& w : walls)
	{
		double a = 0, b = 0;
		if (!planes.disparityRange(w, head, X, SX, a, b)) continue;
		dLo = std::min(dLo, a);
		dHi = std::max(dHi, b);
	}
	const auto tD = std::chrono::steady_clock::now();
	if (dHi < dLo)
		f.disparity = cv::Mat(left.size(), CV_32F, cv::Scalar(-1));	 // no wall in view
	else
	{
		// Whole pixels, rounded up to StereoBM's steps of 16, within the option.
		f.sadMin = std::max(0, static_cast<int>(std::floor(dLo)) - 1);
		const int hi = static_cast<int>(std::ceil(dHi)) + 1;
		f.sadRange = std::min(options.num_disparities, std::max(16, (hi - f.sadMin + 15) / 16 * 16));
		f.disparity = disparity(left, right, f.sadMin, f.sadRange);
	}
	f.disparitySeconds = seconds(tD);
	f.matchRejection.assign(f.matches.size(), "");
	const SadDisparity sadCheck = sad();
	for (size_t i = 0; i < f.matches.size(); i++)
	{
		const auto& m = f.matches[i];
		if (m.disparity < f.sadMin || m.disparity > f.sadMin + f.sadRange - 1)
			f.matchRejection[i] = "disparity outside every visible wall's";
		else
			f.matchRejection[i] = sadCheck.support(f.disparity, f.left[m.left], m);
	}

	// 3. Reference planes (2.3).
	const auto nearest = planes.nearestWallDepth(walls, head, X);
	for (size_t w = 0; w < walls.size(); w++)
		f.planes.push_back(planes.extract(walls[w], w, head, X, SX, f.disparity, &nearest));

	// The camera's floor plan in the robot frame: c_x to the right, c_y
	// ahead along the optical axis at camYaw.
	const double psi0 = head.camYaw;
	const Eigen::Vector2d camRight(std::sin(psi0), -std::cos(psi0)), camFwd(std::cos(psi0), std::sin(psi0));
	Eigen::Matrix2d camToRobot;
	camToRobot.col(0) = camRight;
	camToRobot.col(1) = camFwd;
	const Eigen::Vector2d camOnRobot(head.camX, head.camY);
	if (options.wall_observations)
		for (const auto& pl : f.planes)
		{
			// A fitted wall observes the pose only when
			// - it is seen from the predicted pose itself in kMinWallColumns
			//   columns, and is fitted to their pixels above the camera
			//   alone (PlanarRegion::visibleLine): the 3-sigma margin around
			//   a corner holds the wall in front's pixels (a recess's side
			//   face seen from outside put the robot 16 cm off along the
			//   stereo corridor), and below the camera a low surface's top;
			// - it is seen at wall_min_view_angle_deg or more: at a grazing
			//   angle the block matcher's window spans many disparities and
			//   the fit is biased (moon-lab's side wall at 28-32 deg: 0.9
			//   sigma the same way in all 9 frames; walls at 60-78 deg:
			//   0.1-0.4 sigma);
			// - its pixels fill half of the band just above the camera: a
			//   low surface (a table) has only the block matcher's stray
			//   matches there (lab, left camera: a third of the fits under
			//   10% were 3 sigma off the truth, none over 50%).
			const double coverage = static_cast<double>(pl.bandPixels) / std::max(1.0, pl.bandRows);
			if (!pl.fitted || !pl.visibleFitted || pl.visibleColumns < kMinWallColumns ||
				coverage < kMinWallCoverage || pl.viewAngle < options.wall_min_view_angle_deg * M_PI / 180)
				continue;
			StereoWallObservation z;
			z.wall = pl.wall;
			z.plane = walls[pl.wall].name;
			z.mapA = walls[pl.wall].a;
			z.mapB = walls[pl.wall].b;
			z.origin = camOnRobot + camToRobot * pl.fit.origin;
			z.e = camToRobot * pl.fit.e;
			z.n = camToRobot * pl.fit.n;
			z.line = pl.visibleLine;
			z.covariance = pl.visibleLineCovariance;
			z.viewAngle = pl.viewAngle;
			z.coverage = coverage;
			f.walls.push_back(z);
		}

	// 4. Matches on a plane (2.4), constrained to it (3.1).
	Eigen::Matrix2d Rw;	 // camera axes in the world
	Rw.col(0) = head.directionToWorld(X, {1, 0});
	Rw.col(1) = head.directionToWorld(X, {0, 1});
	struct OnPlane
	{
		size_t match;
		Eigen::Vector2d c;	// constrained, camera coordinates
		Eigen::Matrix2d P;
		Eigen::Vector2d cTilde;
		Eigen::Matrix2d PTilde;
		Eigen::Matrix2d dLine;	// d c / d (a, b) of the plane's fit
	};
	std::vector<std::vector<OnPlane>> byPlane(f.planes.size());
	for (size_t i = 0; i < f.matches.size(); i++)
	{
		if (!f.matchRejection[i].empty()) continue;
		const auto& m = f.matches[i];
		const auto& l = f.left[m.left];
		const auto& r = f.right[m.right];
		const double vm = 0.5 * (m.vLow + m.vHigh);
		Eigen::Matrix2d J;
		const Eigen::Vector2d cTilde = head.triangulate(l.uAt(vm), r.uAt(vm), &J);
		const Eigen::Matrix2d PTilde = J * J.transpose() * s2img;
		struct Candidate
		{
			size_t plane;
			double m2;
			OnPlane on;
		};
		std::vector<Candidate> candidates;
		for (size_t p = 0; p < f.planes.size(); p++)
		{
			const auto& pl = f.planes[p];
			if (!pl.fitted) continue;
			size_t band = 0, in = 0;
			forSegmentBand(l, m, W, H, 2, [&](int u, int v) {
				band++;
				if (pl.mask.at<uchar>(v, u)) in++;
			});
			if (2 * in < band) continue;
			OnPlane on{i, {}, {}, cTilde, PTilde, {}};
			double m2 = 0;
			on.c = pl.fit.constrain(cTilde, PTilde, on.P, &m2, &on.dLine);
			if (m2 > 9) continue;  // not on this plane
			// ... nor on this wall if it lies beyond the wall's ends (a
			// plane is the wall's line, a wall is a piece of it).
			{
				const auto& w = walls[p];
				const Eigen::Vector2d uw = (w.b - w.a) / w.length();
				const double t = uw.dot(head.toWorld(X, on.c) - w.a);
				const Eigen::Vector2d uc = Rw.transpose() * uw;	 // along the wall, camera axes
				const double s2 = uc.dot(on.P * uc) + SX(0, 0) + SX(1, 1) + on.c.squaredNorm() * SX(2, 2);
				const double margin = options.window_sigmas * std::sqrt(s2);
				if (t < -margin || t > w.length() + margin) continue;
			}
			candidates.push_back({p, m2, on});
		}
		if (candidates.empty())
		{
			f.matchRejection[i] = "not on a reference plane";
			continue;
		}
		// The plane it fits best; of walls on that plane's line that it
		// fits as well (within one unit of Mahalanobis distance), the
		// shortest (a whiteboard rather than the wall it hangs on). Two
		// faces meeting at a corner are not coplanar: the better fit wins.
		const Candidate* fit = &candidates.front();
		for (const auto& c : candidates)
			if (c.m2 < fit->m2) fit = &c;
		const Candidate* best = fit;
		for (const auto& c : candidates)
			if (c.m2 <= fit->m2 + 1 && collinear(c.plane, fit->plane) &&
				walls[c.plane].length() < walls[best->plane].length())
				best = &c;
		byPlane[best->plane].push_back(best->on);
	}

	// 5. Boundaries (3.2) and positions relative to them (3.3); 6. selection (4).
	f.boundaries.resize(f.planes.size());
	f.boundaryOffsets.resize(f.planes.size());
	BoundarySearch::Options bo;
	bo.sigma_img = options.sigma_img;
	bo.window_sigmas = options.window_sigmas;
	bo.snap_to_segment = options.snap_to_segment;
	bo.block_size = options.block_size;
	const BoundarySearch boundaries(bo);
	for (size_t p = 0; p < f.planes.size(); p++)
	{
		auto& on = byPlane[p];
		if (on.empty()) continue;
		const auto& pl = f.planes[p];
		const size_t firstObservation = f.observations.size();
		for (const auto& o : on)
		{
			const auto& m = f.matches[o.match];
			const auto& l = f.left[m.left];
			VerticalLandmarkObservation z;
			z.wall = p;
			z.polarity = l.polarity;
			z.match = o.match;
			z.position = camOnRobot + camToRobot * o.c;
			z.covariance = camToRobot * o.P * camToRobot.transpose();
			z.planeJacobian = camToRobot * o.dLine;
			z.planeCovariance = pl.fit.lineCovariance;
			const double depth = o.c.y(), sigmaH = depth / head.fy * options.sigma_end_px;
			z.lHigh = head.heightAt(l.vTop - 0.5, depth);
			z.lLow = head.heightAt(l.vBottom + 0.5, depth);
			// An end at the image border is where the view ends, not the line.
			z.sigmaHigh = l.vTop > 1 ? sigmaH : 0;
			z.sigmaLow = l.vBottom < H - 2 ? sigmaH : 0;
			f.observations.push_back(z);
		}
		std::vector<double> cols, lengths;
		for (const auto& o : on)
		{
			const auto& m = f.matches[o.match];
			cols.push_back(f.left[m.left].uAt(0.5 * (m.vLow + m.vHigh)));
			lengths.push_back(m.vHigh - m.vLow + 1);
		}
		BoundarySearch::Result best;
		for (const bool atA : {true, false})
		{
			if (!(atA ? pl.aInView : pl.bInView)) continue;
			// An end seen at a grazing angle cannot be placed: one pixel
			// is depth / (fx sin(angle)) along the wall, and the SAD
			// window spans the corner.
			const Eigen::Vector2d ca = head.toCamera(X, walls[p].a), cb = head.toCamera(X, walls[p].b);
			const Eigen::Vector2d ce = atA ? ca : cb, wd = cb - ca;
			const double sinAngle = std::abs(ce.x() * wd.y() - ce.y() * wd.x()) / (ce.norm() * wd.norm());
			if (sinAngle < std::sin(options.min_boundary_angle_deg * M_PI / 180)) continue;
			// Rows the wall's height band spans at that end.
			const double depthE = ce.y();
			double rows = 0;
			if (depthE > 0)
			{
				const auto vAt = [&](double h) {
					return std::clamp(head.cy - head.fy * (h - head.camZ) / depthE, 0.0, static_cast<double>(H));
				};
				rows = vAt(options.min_height) - vAt(options.max_height);
			}
			// The end's depth step must be there to see (featloc's check):
			// beyond it, over its window and the evidence the search looks
			// at, the map's nearest wall must lie behind the plane by more
			// than kEndStepPx of disparity. A wall meeting it at a corner or
			// standing just behind it leaves the block matcher nothing to see
			// (a bookshelf 5 cm before a recess's back wall: its end found
			// 7-9 cm out, on the recess's side face), and one in front hides
			// the end (the shelf's end behind the recess's corner: the
			// occluding edge taken for it, 24 cm off). Where the map carries
			// the plane on (a whiteboard on a wall) the segments may still
			// place it.
			const bool coplanar = continuesCoplanar(p, atA);
			if (!coplanar && !endStepVisible(pl, atA, depthE, head, nearest, boundaries.options)) continue;
			const auto b = boundaries.search(pl, f.disparity, atA, cols, lengths, rows, coplanar);
			if (b.found && (!best.found || b.sigma < best.sigma)) best = b;
		}
		f.boundaries[p] = best;
		if (!best.found)
		{
			for (const auto& o : on) f.matchRejection[o.match] = "no boundary of its plane in view";
			continue;
		}
		// The boundary: its column's ray with sigma_b, at the fitted
		// plane's depth with a loose depth, constrained to the plane (3.1).
		const Eigen::Vector2d dir = pl.fit.direction();
		Eigen::Vector2d cb0;
		if (!head.columnRayMeets(best.u, pl.fit.fromPlane({0, pl.fit.line.x()}), dir, cb0))
		{
			for (const auto& o : on) f.matchRejection[o.match] = "its plane is seen edge-on";
			continue;
		}
		const double rayX = (best.u - head.cx) / head.fx;
		const double depth = cb0.y();
		Eigen::Matrix2d Jb;	 // d(c_x, c_y) / d(u, depth)
		Jb << depth / head.fx, rayX, 0, 1;
		const Eigen::Matrix2d Pb0 =
			Jb * Eigen::Vector2d(best.sigma * best.sigma, depth * depth).asDiagonal() * Jb.transpose();
		Eigen::Matrix2d Pb;
		const Eigen::Vector2d cb = pl.fit.constrain(cb0, Pb0, Pb);

		// Eqs. (15)-(17), from the boundary end M1 towards the other M2.
		const auto& wall = walls[p];
		const Eigen::Vector2d M1 = best.atA ? wall.a : wall.b, M2 = best.atA ? wall.b : wall.a;
		const double dM = wall.length();
		// The plane's direction in the camera, from the boundary end inward.
		Eigen::Vector2d e = dir;
		const Eigen::Vector2d inward = head.toCamera(X, M2) - head.toCamera(X, M1);
		if (e.dot(inward) < 0) e = -e;
		std::vector<ModelledFeature> feats;
		for (const auto& o : on)
		{
			const auto& m = f.matches[o.match];
			const auto& l = f.left[m.left];
			const auto& r = f.right[m.right];
			ModelledFeature mf;
			mf.wall = p;
			mf.plane = wall.name;
			mf.match = o.match;
			mf.dp = e.dot(o.c - cb);
			mf.sigmaDp = std::sqrt(e.dot(o.P * e) + e.dot(Pb * e));
			const Eigen::Vector2d u = (M2 - M1) / dM;
			mf.position = M1 + mf.dp * u;  // eq. (15)
			mf.covariance = u * u.transpose() * mf.sigmaDp * mf.sigmaDp;  // eq. (17), rank 1
			mf.sharedCovariance = u * u.transpose() * e.dot(Pb * e);  // the boundary's part
			const auto& z = f.observations[firstObservation + feats.size()];	 // same order as `on`
			mf.lHigh = z.lHigh;
			mf.lLow = z.lLow;
			mf.lengthSimilarity = std::min(l.length(), r.length()) / std::max(l.length(), r.length());
			// Without the plane: stereo point and robot pose uncertainty.
			mf.unconstrained = head.toWorld(X, o.cTilde);
			Eigen::Matrix<double, 2, 3> JX;
			for (int k = 0; k < 3; k++)
			{
				Eigen::Vector3d dx = Eigen::Vector3d::Zero();
				dx(k) = 1e-6;
				JX.col(k) = (head.toWorld(X + dx, o.cTilde) - head.toWorld(X - dx, o.cTilde)) / 2e-6;
			}
			mf.unconstrainedCovariance = Rw * o.PTilde * Rw.transpose() + JX * SX * JX.transpose();
			// Section 4.
			if (std::abs(mf.dp) < options.boundary_sigmas * mf.sigmaDp)
				mf.reason = "near boundary";
			else if (mf.lengthSimilarity < options.min_length_similarity)
				mf.reason = "length similarity " + std::to_string(mf.lengthSimilarity).substr(0, 4);
			mf.selected = mf.reason.empty();
			feats.push_back(mf);
		}
		// The boundary is the map's edge only if the features placed from it
		// agree with their own stereo positions (featloc's check: the paper
		// assumes the association). Along the wall, each feature's offset
		// d_i = (P_i - U_i).u has an independent part, the plane update's
		// e'(P~ - P)e, and common parts: the boundary's e'Pb e and the robot
		// pose's. A texture-less wall end, or a door frame taken for the
		// corner, shifts every feature by the same amount.
		{
			const Eigen::Vector2d u = (M2 - M1) / dM;
			double sw = 0, swd = 0, pose2 = 0;
			for (size_t k = 0; k < feats.size(); k++)
			{
				const auto& o = on[k];
				const double indep = std::max(1e-8, e.dot((o.PTilde - o.P) * e));
				const double d = u.dot(feats[k].position - feats[k].unconstrained);
				sw += 1 / indep;
				swd += d / indep;
				const Eigen::Matrix2d Rp = feats[k].unconstrainedCovariance - Rw * o.PTilde * Rw.transpose();
				pose2 += u.dot(Rp * u) / static_cast<double>(feats.size());
			}
			const double offset = swd / sw;
			const double sigma = std::sqrt(1 / sw + e.dot(Pb * e) + pose2);
			f.boundaryOffsets[p] = {offset, sigma};
			if (std::abs(offset) > options.window_sigmas * sigma)
			{
				char why[160];
				std::snprintf(why, sizeof(why), "boundary not the map's edge: features %+.2f m from their stereo positions (%.1f sigma)",
					offset, std::abs(offset) / sigma);
				for (auto& ft : feats)
				{
					ft.selected = false;
					ft.reason = why;
				}
			}
		}
		// Selected features may start landmarks; features the paper calls
		// unstable (near the boundary, dissimilar lengths) are not observed
		// either (section 4). feats[k] is the observation firstObservation + k.
		for (size_t k = feats.size(); k-- > 0;)
		{
			const auto& ft = feats[k];
			auto& z = f.observations[firstObservation + k];
			if (ft.selected)
			{
				z.canStart = true;
				z.start = ft.position;
				z.startCovariance = ft.covariance;
				z.startSharedCovariance = ft.sharedCovariance;
			}
			if (ft.reason == "near boundary" || ft.lengthSimilarity < options.min_length_similarity)
				f.observations.erase(f.observations.begin() + static_cast<long>(firstObservation + k));
		}
		std::sort(feats.begin(), feats.end(), [](const ModelledFeature& a, const ModelledFeature& b) {
			return std::abs(a.dp) < std::abs(b.dp);
		});
		for (size_t k = 0; k < feats.size(); k++) feats[k].index = static_cast<int>(k + 1);
		f.features.insert(f.features.end(), feats.begin(), feats.end());
	}
	f.seconds = seconds(t0);
	return f;
}
}  // namespace featloc
