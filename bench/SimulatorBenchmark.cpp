// Speed of featloc-sim: ray casting and whole simulations of 1081-beam
// scans (Hokuyo UTM-30LX preset) in a 200-segment world.
// Run: scripts/bench-sim.sh (or build/bin/featloc_bench_sim).
#include <benchmark/benchmark.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "featloc/registerClasses.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/Simulator.h"

using namespace featloc;

namespace
{
/** A 20 m x 20 m room (4 walls) with 196 random segments of 0.3-1.5 m. */
SimWorld world200()
{
	SimWorld w;
	mrpt::random::CRandomGenerator rng(2024);
	auto add = [&](double x0, double y0, double x1, double y1) {
		WallSegment s;
		s.a = {x0, y0};
		s.b = {x1, y1};
		w.addSegment(s);
	};
	add(0, 0, 20, 0);
	add(20, 0, 20, 20);
	add(20, 20, 0, 20);
	add(0, 20, 0, 0);
	while (w.segments().size() < 200)
	{
		const double x = rng.drawUniform(1.0, 19.0), y = rng.drawUniform(1.0, 19.0);
		if (std::hypot(x - 10, y - 10) < 3) continue;  // keep the robot's loop free
		const double a = rng.drawUniform(-M_PI, M_PI), l = rng.drawUniform(0.3, 1.5);
		add(x, y, x + l * std::cos(a), y + l * std::sin(a));
	}
	return w;
}

LaserOptions hokuyo()
{
	LaserOptions l;
	l.applyPreset("hokuyo_utm30lx");
	l.rate = 40;
	return l;
}

void BM_RayCast1081Beams200Segments(benchmark::State& state)
{
	const SimWorld w = world200();
	const LaserOptions laser = hokuyo();
	const auto [first, step] = Simulator::beamGeometry(laser);
	std::vector<double> ranges;
	double t = 0;
	for (auto _ : state)
	{
		// Around a 2 m circle in the middle of the room.
		const mrpt::math::TPose2D s{10 + 2 * std::cos(t), 10 + 2 * std::sin(t), t + M_PI / 2};
		RayCaster::cast(s, first, step, laser.beams, laser.max_range, w.segments(),
			w.circles(), ranges);
		benchmark::DoNotOptimize(ranges.data());
		t += 0.01;
	}
	state.SetItemsProcessed(state.iterations());
	state.counters["beams"] = laser.beams;
	state.counters["segments"] = static_cast<double>(w.segments().size());
}
BENCHMARK(BM_RayCast1081Beams200Segments)->Unit(benchmark::kMicrosecond);

/** A whole featloc-sim run of 1000 scans: path, ray casting, noise,
 * odometry, writing the gzip rawlog and the ground truth. */
void BM_Simulate1000Scans(benchmark::State& state)
{
	registerClasses();
	const SimWorld w = world200();
	RobotPathOptions robot;
	robot.waypoints = {{8, 10}, {12, 10}, {12, 12}, {8, 12}, {8, 10}};
	robot.laps = 10;
	SimulationOptions sim;
	sim.max_scans = 1000;
	const auto dir = std::filesystem::temp_directory_path();
	const std::string rawlog = (dir / "featloc_bench_sim.rawlog").string();
	const std::string gt = (dir / "featloc_bench_sim.gt.txt").string();
	size_t scans = 0;
	for (auto _ : state)
	{
		Simulator s(w, robot, hokuyo(), SimOdometryOptions(), sim);
		scans = s.run(rawlog, gt).scans;
	}
	if (scans != 1000) state.SkipWithError("the path was too short for 1000 scans");
	state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * scans));
	std::remove(rawlog.c_str());
	std::remove(gt.c_str());
}
BENCHMARK(BM_Simulate1000Scans)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
