// Speed of featloc-sim's stereo camera: one 640x480 pair (both views,
// anti-aliasing, blur, gain and noise; file writing excluded) on one core,
// in the paper's lab scene and in the office corridor with people.
// Run: scripts/bench-stereo.sh (or build/bin/featloc_bench_stereo).
#include <benchmark/benchmark.h>
#include <mrpt/config/CConfigFile.h>
#include <opencv2/core.hpp>

#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/StereoRenderer.h"

using namespace featloc;

namespace
{
void renderPair(benchmark::State& state, const char* worldFile, double x, double y, double yaw)
{
	cv::setNumThreads(1);  // one core, as the requirement says
	const mrpt::config::CConfigFile cfg(std::string(FEATLOC_SOURCE_DIR) + "/worlds/" + worldFile);
	SimConfiguration sc = SimConfiguration::load(cfg);
	const StereoRenderer r(sc.world, sc.stereo);
	cv::RNG rng(1);
	double t = 0;
	StereoFrame f;	// buffers reused, as featloc-sim does
	for (auto _ : state)
	{
		r.render(mrpt::poses::CPose2D(x, y, yaw), t, rng, f);
		benchmark::DoNotOptimize(f.left.data);
		t += 0.2;
	}
	state.counters["pairs/s"] = benchmark::Counter(
		static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_StereoPairMoonLab(benchmark::State& s) { renderPair(s, "moon-lab.ini", 0, 0, M_PI / 2); }
void BM_StereoPairOfficeCorridor(benchmark::State& s)
{
	renderPair(s, "office-corridor.ini", 3, 1.5, 0);
}
}  // namespace

BENCHMARK(BM_StereoPairMoonLab)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StereoPairOfficeCorridor)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_MAIN();
