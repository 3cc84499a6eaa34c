// Which logs have their ranges on a lattice (RangeLattice), of what step,
// and what finding it costs per scan: one Markdown row per log given on
// the command line (MRPT rawlogs or CARMEN logs, as featloc-run reads them).
// Run: scripts/bench-range-lattice.sh.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "featloc/core/ExceptionText.h"
#include "featloc/io/EntrySource.h"
#include "featloc/io/InputOptions.h"
#include "featloc/registerClasses.h"
#include "featloc/scan/RangeLattice.h"
#include "featloc/scan/ScanPoints.h"

using namespace featloc;

namespace
{
void scansOf(const mrpt::serialization::CSerializable::Ptr& object,
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& out)
{
	if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(object))
		out.push_back(s);
	else if (auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object))
		for (const auto& o : *frame) scansOf(o, out);
}

double quantile(std::vector<double> v, double p)
{
	if (v.empty()) return 0;
	const auto at = v.begin() + static_cast<long>(p * static_cast<double>(v.size() - 1));
	std::nth_element(v.begin(), at, v.end());
	return *at;
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 2)
	{
		std::fprintf(stderr, "usage: %s LOG [LOG...]  (MRPT rawlogs or CARMEN .log[.gz])\n", argv[0]);
		return 2;
	}
	registerClasses();
	std::printf("| log | scans | on a lattice | step: median (5-95%%) [mm] | time per scan [us] |\n");
	std::printf("|---|---|---|---|---|\n");
	for (int a = 1; a < argc; a++)
	{
		std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
		try
		{
			auto source = EntrySource::openFile(argv[a], InputOptions());  // ranges only
			RawlogEntry entry;
			while (source->next(entry)) scansOf(entry.object, scans);
		}
		catch (const std::exception& e)
		{
			std::fprintf(stderr, "%s: %s\n", argv[a], exceptionText(e).c_str());
			return 1;
		}
		RangeLattice lattice;
		std::vector<double> steps;
		double seconds = 0;
		for (const auto& scan : scans)
		{
			const ScanPoints points = ScanPoints::fromScan(*scan);
			const auto t0 = std::chrono::steady_clock::now();
			const double q = lattice.step(points);
			seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
			if (q > 0) steps.push_back(q);
		}
		const double n = static_cast<double>(std::max<size_t>(1, scans.size()));
		std::printf("| %s | %zu | %.1f%% | ", std::filesystem::path(argv[a]).filename().c_str(),
			scans.size(), 100.0 * static_cast<double>(steps.size()) / n);
		if (steps.empty())
			std::printf("- | ");
		else
			std::printf("%.0f (%.0f-%.0f) | ", 1e3 * quantile(steps, 0.5), 1e3 * quantile(steps, 0.05),
				1e3 * quantile(steps, 0.95));
		std::printf("%.0f |\n", 1e6 * seconds / n);
	}
	return 0;
}
