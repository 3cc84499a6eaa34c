// Moon, Miura & Shirai's Table 1 on the simulated paper scene, accuracy
// against the exact edges with and without the plane constraint, and the
// speed of the whole stereo front end next to OpenCV's block matcher alone.
// Prints Markdown (scripts/bench-stereo.sh puts it in doc/benchmarks.md).
// Usage: featloc_bench_stereo_landmarks SOURCE_DIR [SEEDS]
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "featloc/registerClasses.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/StereoRenderer.h"
#include "featloc/sim/VisibleEdges.h"
#include "featloc/stereo/StableVerticalLandmarks.h"

using namespace featloc;

namespace
{
double median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v.empty() ? 0 : v[v.size() / 2];
}

struct Truth
{
	bool found = false;
	double x = 0, y = 0, dist = 1e9;
};

Truth nearestEdge(const std::vector<VisibleEdge>& edges, const ModelledFeature& f)
{
	Truth t;
	const std::string object = f.plane.substr(0, f.plane.find('#'));
	for (const auto& e : edges)
	{
		if (e.edge.object != object) continue;
		const double d = std::hypot(e.edge.x - f.position.x(), e.edge.y - f.position.y());
		if (d < t.dist) t = {true, e.edge.x, e.edge.y, d};
	}
	// Texture inside a poster has no exact edge: only material edges count.
	t.found = t.dist < 0.1;
	return t;
}
/** Selected landmarks of `sc`'s world seen from `poses`, against the exact
 * depth beside each segment, and the outcome of every modelled feature. */
template <typename RobotAt>
void evaluateScene(const std::string& title, const SimConfiguration& sc, const std::string& mapPath,
	const std::vector<mrpt::poses::CPose2D>& poses, RobotAt robotAt)
{
	const StereoRenderer cr(sc.world, sc.stereo);
	StableVerticalLandmarks cx;
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("S", "map", mapPath);
	cx.loadParams(cfg, "S");
	const StereoHead ch = sc.stereo.head();
	size_t frames = 0, n = 0, within = 0, dropped = 0;
	double se2 = 0, ue2 = 0, sumS = 0;
	std::vector<double> times;
	std::map<std::string, size_t> reasons;
	size_t wrongRegions = 0;
	for (const auto& pose : poses)
	{
		cv::RNG rng(static_cast<uint64_t>(frames + 11));
		const auto fr = cr.render(pose, 0.2 * static_cast<double>(frames), rng);
		const auto out = cx.process(fr.left, fr.right, ch, robotAt(pose));
		times.push_back(out.seconds * 1e3);
		frames++;
		const Eigen::Vector3d X(pose.x(), pose.y(), pose.phi());
		for (const auto& f : out.features)
			reasons[f.selected                                    ? std::string("selected")
					: f.reason.rfind("length similarity", 0) == 0 ? std::string("length similarity below the threshold")
																  : f.reason.substr(0, f.reason.find(':'))]++;
		for (const auto& pl : out.planes)
			if (!pl.fitted && pl.reason.rfind("its pixels fit a line", 0) == 0) wrongRegions++;
		for (const auto& f : out.features)
		{
			if (!f.selected) continue;
			// The truth of any feature, texture edges included: where
			// its column's ray meets the world, from the exact depth a
			// pixel beside the edge on the plane's side.
			const auto& m = out.matches[f.match];
			const auto& seg = out.left[m.left];
			const int v = static_cast<int>(std::lround(0.5 * (m.vLow + m.vHigh)));
			double best = 1e300;
			Eigen::Vector2d truth;
			for (const int du : {-2, 2})
			{
				const int u = static_cast<int>(std::lround(seg.uAt(v))) + du;
				if (u < 0 || u >= fr.depth.cols) continue;
				const double z = fr.depth.at<float>(v, u);
				if (!(z > 0)) continue;
				const Eigen::Vector2d p =
					ch.toWorld(X, Eigen::Vector2d((seg.uAt(v) - ch.cx) * z / ch.fx, z));
				const double d = (p - f.position).norm();
				if (d < best) best = d, truth = p;
			}
			if (best > 1e299)
			{
				dropped++;
				continue;
			}
			const auto tr = Truth{true, truth.x(), truth.y(), best};
			n++;
			const double e = std::hypot(f.position.x() - tr.x, f.position.y() - tr.y);
			const double sAlong = std::sqrt(f.covariance.trace());
			se2 += e * e;
			sumS += sAlong;
			if (e <= 2 * sAlong) within++;
			ue2 += std::pow(f.unconstrained.x() - tr.x, 2) + std::pow(f.unconstrained.y() - tr.y, 2);
		}
	}
	std::printf("#### %s (%zu frames)\n\n", title.c_str(), frames);
	std::printf("Truth of each selected landmark: the exact depth beside its segment (texture edges included).\n\n| selected landmarks | within 2 sigma | RMS error | mean sigma | without the plane: RMS error | no exact depth | median time per frame |\n|---|---|---|---|---|---|---|\n");
	std::printf("| %zu | %.1f%% | %.1f mm | %.1f mm | %.1f mm | %zu | %.1f ms |\n\n", n, n ? 100.0 * within / n : 0.0,
		n ? std::sqrt(se2 / n) * 1e3 : 0.0, n ? sumS / n * 1e3 : 0.0, n ? std::sqrt(ue2 / n) * 1e3 : 0.0, dropped,
		median(times));
	std::printf("Modelled features by outcome (the reasons of section 4 and featloc's checks):\n\n| outcome | features |\n|---|---|\n");
	for (const auto& [r, k] : reasons)
	{
		std::printf("| %s | %zu |\n", r.c_str(), k);
	}
	std::printf("\nPlane regions whose disparity pixels fit another surface, not the map's wall: %zu.\n\n", wrongRegions);
}
/** A world of the laser benchmarks with moon-lab's [StereoCamera] (the
 * paper's camera, doc/benchmarks.md) added. */
SimConfiguration withPaperCamera(const std::string& src, const std::string& world)
{
	std::ifstream file(src + world);
	std::stringstream text;
	text << file.rdbuf();
	mrpt::config::CConfigFileMemory mem(text.str());
	// Laser worlds name some surfaces the stereo renderer has no material
	// for: the nearest look.
	const std::map<std::string, std::string> look = {
		{"hall_wall", "paint"}, {"door", "wood"}, {"shelf", "books"}, {"red", "metal"}};
	std::vector<std::string> sections;
	mem.getAllSections(sections);
	for (const auto& sec : sections)
	{
		const auto t = mem.read_string(sec, "texture", "");
		if (look.count(t)) mem.write(sec, "texture", look.at(t));
	}
	const mrpt::config::CConfigFile lab(src + "/worlds/moon-lab.ini");
	for (const auto& k : {"width", "height", "fx", "fy", "cx", "cy", "baseline", "pose", "noise_sigma", "blur_sigma",
			 "gain_change"})
		mem.write("StereoCamera", k, lab.read_string("StereoCamera", k, ""));
	return SimConfiguration::load(mem);
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 2)
	{
		std::fprintf(stderr, "usage: %s SOURCE_DIR [SEEDS]\n", argv[0]);
		return 2;
	}
	const std::string src = argv[1];
	const int seeds = argc > 2 ? std::atoi(argv[2]) : 20;
	cv::setNumThreads(1);  // one core, as the issue asks
	registerClasses();
	const auto sc = SimConfiguration::load(mrpt::config::CConfigFile(src + "/worlds/moon-lab.ini"));
	const StereoRenderer renderer(sc.world, sc.stereo);
	const VisibleEdges visible(sc.world, sc.stereo);
	StableVerticalLandmarks x;
	{
		mrpt::config::CConfigFileMemory cfg;
		cfg.write("S", "map", src + "/worlds/moon-lab.ini");
		x.loadParams(cfg, "S");
	}
	const StereoHead head = sc.stereo.head();
	const auto& c = sc.stereo;
	const double sxy = 0.02, syaw = 0.5 * M_PI / 180;
	auto robotAt = [&](const mrpt::poses::CPose2D& p) {
		mrpt::poses::CPosePDFGaussian r(p);
		r.cov.setZero();
		r.cov(0, 0) = r.cov(1, 1) = sxy * sxy;
		r.cov(2, 2) = syaw * syaw;
		return r;
	};
	auto edgesAt = [&](const mrpt::poses::CPose2D& p) {
		cv::Mat l, r, dl, dr;
		const auto cam = renderer.leftCameraPose(p);
		renderer.renderIdeal(cam, 0, l, r, dl, dr);
		return visible.visible(cam, dl, dr);
	};

	std::printf(
		"Camera simulated (the paper gives no focal length or baseline): 640x480, fx = fy = %.0f px "
		"(65 deg horizontal field), baseline %.2f m, %.1f m above the floor, level; image noise "
		"sigma %.1f grey levels, blur %.1f px. Robot pose prior: sigma %.0f mm in x and y, %.1f deg in "
		"yaw. Scene: worlds/moon-lab.ini (partition boundary at (0, 4) m, whiteboard boundary at "
		"(-0.55, 6) m).\n\n",
		c.fx, c.baseline, c.pose[2], c.noise_sigma, c.blur_sigma, sxy * 1e3, syaw * 180 / M_PI);

	// 1. Table 1 from the origin (the paper's viewpoint).
	const mrpt::poses::CPose2D origin(0, 0, M_PI / 2);
	{
		cv::RNG rng(1);
		const auto fr = renderer.render(origin, 0, rng);
		const auto out = x.process(fr.left, fr.right, head, robotAt(origin));
		const auto edges = edgesAt(origin);
		std::printf("#### Table 1, simulated (robot at the origin, seed 1) [mm]\n\n");
		std::printf(
			"| plane | index | x | y | l | sigma_x | sigma_y | l_s | selected | reason | true x | error | "
			"without the plane: x | y | sigma_x | sigma_y |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
		for (const auto& f : out.features)
		{
			if (f.plane.rfind("Wall.partition", 0) != 0 && f.plane.rfind("Wall.whiteboard", 0) != 0) continue;
			const auto t = nearestEdge(edges, f);
			char truth[64] = "(texture)", err[64] = "";
			if (t.found)
			{
				std::snprintf(truth, sizeof(truth), "%.1f", t.x * 1e3);
				std::snprintf(err, sizeof(err), "%+.1f", (f.position.x() - t.x) * 1e3);
			}
			std::printf("| %s | %d | %.1f | %.1f | %.0f | %.1f | %.1f | %.2f | %s | %s | %s | %s | %.1f | %.1f | %.1f | %.1f |\n",
				f.plane.substr(5, f.plane.find('#') - 5).c_str(), f.index, f.position.x() * 1e3,
				f.position.y() * 1e3, f.length() * 1e3, std::sqrt(f.covariance(0, 0)) * 1e3,
				std::sqrt(f.covariance(1, 1)) * 1e3, f.lengthSimilarity, f.selected ? "Yes" : "No",
				f.reason.c_str(), truth, err, f.unconstrained.x() * 1e3, f.unconstrained.y() * 1e3,
				std::sqrt(f.unconstrainedCovariance(0, 0)) * 1e3, std::sqrt(f.unconstrainedCovariance(1, 1)) * 1e3);
		}
		std::printf("\nPaper's Table 1: partition sigma_x 28.3-35.8 mm, whiteboard 46.4-54.2 mm; sigma_y 0.\n\n");
	}

	// 2. Accuracy over seeds and the paper's three viewpoints (Figs. 5, 8, 9).
	struct Acc
	{
		size_t n = 0, within2 = 0, unconstrainedWithin2 = 0, selected = 0;
		double se2 = 0, ue2 = 0, sumSigma = 0, sumUSigma = 0;
	};
	std::map<std::string, Acc> acc;
	for (const double y : {0.0, 1.0, 2.0})
		for (int s = 1; s <= seeds; s++)
		{
			cv::RNG rng(static_cast<uint64_t>(100 * s + 7));
			// The true pose varies a little around the viewpoint; the
			// estimate handed to the extractor is the truth (the prior's
			// sigma still sets the search windows and the unconstrained
			// position's uncertainty).
			const mrpt::poses::CPose2D pose(rng.gaussian(0.05), y + rng.gaussian(0.05), M_PI / 2 + rng.gaussian(0.02));
			const auto fr = renderer.render(pose, 0, rng);
			const auto out = x.process(fr.left, fr.right, head, robotAt(pose));
			const auto edges = edgesAt(pose);
			for (const auto& f : out.features)
			{
				if (!f.selected) continue;
				const auto t = nearestEdge(edges, f);
				if (!t.found) continue;
				const std::string plane = f.plane.substr(5, f.plane.find('#') - 5);
				if (plane != "partition" && plane != "whiteboard") continue;
				const std::string key = plane + " from y = " + std::to_string(static_cast<int>(y)) + " m";
				auto& a = acc[key];
				a.n++;
				const double e = f.position.x() - t.x;
				const double sx = std::sqrt(f.covariance(0, 0));
				a.se2 += e * e;
				a.sumSigma += sx;
				if (std::abs(e) <= 2 * sx) a.within2++;
				// Without the plane, in the world frame: the error and sigma
				// along the plane (x).
				const double ue = f.unconstrained.x() - t.x;
				const double usx = std::sqrt(f.unconstrainedCovariance(0, 0));
				a.ue2 += ue * ue;
				a.sumUSigma += usx;
				if (std::abs(ue) <= 2 * usx) a.unconstrainedWithin2++;
				const double uy = f.unconstrained.y() - t.y;
				a.ue2 += uy * uy;
			}
		}
	std::printf("#### Selected landmarks against the exact edges (%d seeds per viewpoint, pose jittered 5 cm / 1 deg)\n\n", seeds);
	std::printf(
		"| plane, viewpoint | landmarks | within 2 sigma | RMS error x | mean sigma_x | without the plane: RMS "
		"position error | mean sigma_x | within 2 sigma |\n|---|---|---|---|---|---|---|---|\n");
	size_t n = 0, w = 0;
	for (const auto& [k, a] : acc)
	{
		n += a.n, w += a.within2;
		std::printf("| %s | %zu | %.1f%% | %.1f mm | %.1f mm | %.1f mm | %.1f mm | %.1f%% |\n", k.c_str(), a.n,
			100.0 * a.within2 / a.n, std::sqrt(a.se2 / a.n) * 1e3, a.sumSigma / a.n * 1e3,
			std::sqrt(a.ue2 / a.n) * 1e3, a.sumUSigma / a.n * 1e3, 100.0 * a.unconstrainedWithin2 / a.n);
	}
	std::printf("\nAll: %zu of %zu selected landmarks (%.1f%%) within 2 sigma of the truth.\n\n", w, n, 100.0 * w / n);

	// 2b. Scenes other than the paper's: the stereo corridor (doors,
	// posters, people; the checks of featloc's boundary search were
	// developed on it, see doc/benchmarks.md) at the ground-truth poses of
	// its shipped run, and the office floor of the laser benchmarks, which
	// the stereo extractor was never run on before this table was made.
	{
		std::vector<mrpt::poses::CPose2D> poses;
		std::ifstream gt(src + "/rawlogs/stereo/stereo-corridor.gt.txt");
		std::string line;
		while (std::getline(gt, line))
		{
			if (line.empty() || line[0] == '#') continue;
			std::istringstream ss(line);
			double t, px, py, pz, qx, qy, qz, qw;
			ss >> t >> px >> py >> pz >> qx >> qy >> qz >> qw;
			poses.emplace_back(px, py, 2 * std::atan2(qz, qw));
		}
		evaluateScene("worlds/stereo-corridor.ini, the ground-truth poses of its shipped run (people walking); "
			"the scene featloc's boundary checks were developed on",
			SimConfiguration::load(mrpt::config::CConfigFile(src + "/worlds/stereo-corridor.ini")),
			src + "/worlds/stereo-corridor.ini", poses, robotAt);
	}
	{
		// The office floor: its own walls, doors and furniture, the
		// paper's camera (moon-lab's [StereoCamera]) at 1.0 m, poses every
		// 0.5 m along its robot path facing along it.
		const auto oc = withPaperCamera(src, "/worlds/office.ini");
		std::vector<mrpt::poses::CPose2D> poses;
		const auto& wp = oc.robot.waypoints;
		for (size_t i = 0; i + 1 < wp.size(); i++)
		{
			const double dx = wp[i + 1][0] - wp[i][0], dy = wp[i + 1][1] - wp[i][1], L = std::hypot(dx, dy);
			if (L < 0.5) continue;
			for (double t = 0; t < L; t += 0.5)
				poses.emplace_back(wp[i][0] + dx * t / L, wp[i][1] + dy * t / L, std::atan2(dy, dx));
		}
		evaluateScene("worlds/office.ini with the paper's camera, every 0.5 m of its robot path; held out until the "
			"corridor's checks were done, then used to find the textured-furniture failures (see the text)",
			oc, src + "/worlds/office.ini", poses, robotAt);
	}
	{
		// The hall with walking people, from three places, turning on the
		// spot in 30 degree steps: held out until every check above was
		// fixed, and reported as it came out.
		const auto hc = withPaperCamera(src, "/worlds/hall-people.ini");
		std::vector<mrpt::poses::CPose2D> poses;
		for (const auto& [x0, y0] : std::vector<std::pair<double, double>>{{5, 3.5}, {3, 2}, {9, 4}})
			for (int k = 0; k < 12; k++) poses.emplace_back(x0, y0, k * M_PI / 6);
		evaluateScene("worlds/hall-people.ini with the paper's camera, 3 places x 12 headings, people walking; never "
			"run during development", hc, src + "/worlds/hall-people.ini", poses, robotAt);
	}

	// 3. Speed on one core: the whole front end vs StereoBM alone.
	{
		cv::RNG rng(5);
		const auto fr = renderer.render(origin, 0, rng);
		std::vector<double> whole, bm, full;
		int sadMin = 0, sadRange = 0;
		auto ms = [](std::chrono::steady_clock::time_point t0) {
			return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
		};
		for (int i = 0; i < 40; i++)
		{
			auto t0 = std::chrono::steady_clock::now();
			const auto out = x.process(fr.left, fr.right, head, robotAt(origin));
			whole.push_back(ms(t0));
			sadMin = out.sadMin, sadRange = out.sadRange;
			t0 = std::chrono::steady_clock::now();
			const cv::Mat d = x.disparity(fr.left, fr.right, out.sadMin, out.sadRange);
			bm.push_back(ms(t0));
			t0 = std::chrono::steady_clock::now();
			const cv::Mat d64 = x.disparity(fr.left, fr.right, 0, 64);
			full.push_back(ms(t0));
		}
		std::printf("#### Speed, one 640x480 pair, one core (median of 40 runs, same run)\n\n");
		std::printf(
			"| whole stereo front end (segments, DP, SAD, planes, boundaries, features) | its StereoBM "
			"alone (15x15, left-right check, disparities %d-%d: the walls' predicted range) | StereoBM "
			"over 0-63 |\n|---|---|---|\n",
			sadMin, sadMin + sadRange - 1);
		std::printf("| %.1f ms (fastest %.1f) | %.1f ms (fastest %.1f) | %.1f ms (fastest %.1f) |\n", median(whole),
			*std::min_element(whole.begin(), whole.end()), median(bm), *std::min_element(bm.begin(), bm.end()),
			median(full), *std::min_element(full.begin(), full.end()));
	}
	return 0;
}
