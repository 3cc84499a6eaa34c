#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <functional>

#include "featloc/registerClasses.h"
#include "featloc/scan/RangeLattice.h"
#include "featloc/scan/ScanPoints.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
/** The office scanned from a few poses, each range passed through `f`. */
std::vector<ScanPoints> officeScans(const std::function<double(double)>& f)
{
	const SyntheticRoom office = SyntheticRoom::office();
	std::vector<ScanPoints> out;
	for (const CPose2D& at : {CPose2D(0, 0, 0), CPose2D(1.2, -0.4, 0.3), CPose2D(-1.5, 1, -2)})
	{
		auto scan = office.scan(at);
		for (size_t i = 0; i < scan->getScanSize(); i++)
			if (scan->getScanRangeValidity(i))
				scan->setScanRange(i, static_cast<float>(f(scan->getScanRange(i))));
		out.push_back(ScanPoints::fromScan(*scan));
	}
	return out;
}

double noisy(double r, double sigma)
{
	return r + sigma * mrpt::random::getRandomGenerator().drawGaussian1D_normalized();
}
}  // namespace

TEST(RangeLattice, MrptsSimulatorsStepIsFoundUnderItsNoise)
{
	// As MRPT's simulated log: on the lattice first, then 1 cm of noise.
	mrpt::random::getRandomGenerator().randomize(3);
	RangeLattice lattice;
	for (const auto& scan : officeScans([](double r) { return noisy(0.16 * std::round(r / 0.16), 0.01); }))
		EXPECT_NEAR(lattice.step(scan), 0.16, 0.002) << RangeLattice::resultant(scan, 0.16) << " " << scan.size();
}

TEST(RangeLattice, ARealSensorsRoundedRangesAreFound)
{
	// As acapulco's, edmonton's and fhw's ranges: the noisy reading rounded
	// to 5 cm.
	mrpt::random::getRandomGenerator().randomize(4);
	RangeLattice lattice;
	for (const auto& scan : officeScans([](double r) { return 0.05 * std::round(noisy(r, 0.01) / 0.05); }))
		EXPECT_NEAR(lattice.step(scan), 0.05, 0.001);
}

TEST(RangeLattice, NoLatticeInContinuousRangesOrInAFinerOne)
{
	mrpt::random::getRandomGenerator().randomize(5);
	RangeLattice lattice;
	for (const auto& scan : officeScans([](double r) { return noisy(r, 0.01); }))
		EXPECT_EQ(lattice.step(scan), 0.0);
	for (const auto& scan : officeScans([](double r) { return r; })) EXPECT_EQ(lattice.step(scan), 0.0);
	// A SICK's 1 cm readings: finer than any step that matters.
	for (const auto& scan : officeScans([](double r) { return 0.01 * std::round(noisy(r, 0.01) / 0.01); }))
		EXPECT_EQ(lattice.step(scan), 0.0);
	// A 5 cm lattice under 1 cm of noise added after it is no lattice any
	// more (a 5-sigma step: R = exp(-2 pi^2 / 25) = 0.45).
	for (const auto& scan : officeScans([](double r) { return noisy(0.05 * std::round(r / 0.05), 0.01); }))
		EXPECT_EQ(lattice.step(scan), 0.0);
}

TEST(RangeLattice, RangesInAFewNarrowClustersAreNoLattice)
{
	// Two walls seen head on, 1.5 m and 3.1 m away: every frequency that is
	// a multiple of 1 / 1.6 m puts both clusters in phase.
	ScanPoints scan;
	mrpt::random::getRandomGenerator().randomize(6);
	for (int i = 0; i < 300; i++)
	{
		ScanPoint p;
		p.range = noisy(i < 150 ? 1.5 : 3.1, 0.003);
		p.bearing = -M_PI / 2 + M_PI * i / 300;
		p.x = p.range * std::cos(p.bearing);
		p.y = p.range * std::sin(p.bearing);
		p.beam = static_cast<uint32_t>(i);
		scan.points.push_back(p);
	}
	EXPECT_EQ(RangeLattice().step(scan), 0.0);
	EXPECT_GT(RangeLattice::resultant(scan, 0.16), 0.9);  // in phase, yet no lattice
}

TEST(RangeLattice, TheBundledLogsRangesSitOnSixteenCentimetres)
{
	registerClasses();
	mrpt::io::CFileGZInputStream in(std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/mrpt-simul/simul.rawlog");
	auto ar = mrpt::serialization::archiveFrom(in);
	mrpt::obs::CActionCollection::Ptr action;
	mrpt::obs::CSensoryFrame::Ptr frame;
	mrpt::obs::CObservation::Ptr obs;
	size_t entry = 0, scans = 0, onLattice = 0;
	RangeLattice lattice;
	while (scans < 100 &&
		mrpt::obs::CRawlog::getActionObservationPairOrObservation(ar, action, frame, obs, entry))
	{
		if (!frame) continue;
		for (const auto& o : *frame)
			if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o))
			{
				scans++;
				onLattice += std::abs(lattice.step(ScanPoints::fromScan(*s)) - 0.16) < 0.003;
			}
	}
	ASSERT_EQ(scans, 100u);
	EXPECT_GE(onLattice, 95u);
}
