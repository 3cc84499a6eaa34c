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
	for (const CPose2D& at : {CPose2D(0, 0, 0), CPose2D(1.2, -0.4, 0.3), CPose2D(-2.5, 1.5, -2)})
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
	// acapulco's sit on x.x3 and x.x8 m: the lattice's offset is found too
	// (as a phase: modulo the step).
	for (const auto& scan :
		officeScans([](double r) { return 0.03 + 0.05 * std::round((noisy(r, 0.01) - 0.03) / 0.05); }))
	{
		EXPECT_NEAR(lattice.step(scan), 0.05, 0.001);
		const double phase = std::remainder(lattice.offset() - 0.03, 0.05);
		EXPECT_NEAR(phase, 0.0, 0.002) << lattice.offset();
	}
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

TEST(RangeLattice, DequantizedReadingsLieNearerTheirSurfaces)
{
	// The office scanned exactly, and on MRPT's simulator's lattice with
	// 1 cm noise on top: the readings put back on their surfaces are
	// nearer the exact ranges than the lattice left them.
	mrpt::random::getRandomGenerator().randomize(7);
	const auto exact = officeScans([](double r) { return r; });
	auto onLattice = officeScans([](double r) { return noisy(0.16 * std::round(r / 0.16), 0.01); });
	RangeLattice lattice;
	double before = 0, after = 0;
	size_t n = 0, moved = 0;
	for (size_t k = 0; k < exact.size(); k++)
	{
		ScanPoints restored = onLattice[k];
		const double q = lattice.step(restored);
		ASSERT_GT(q, 0);
		moved += lattice.dequantize(restored, q);
		ASSERT_EQ(restored.size(), exact[k].size());
		for (size_t i = 0; i < restored.size(); i++)
		{
			ASSERT_EQ(restored[i].beam, exact[k][i].beam);
			before += mrpt::square(onLattice[k][i].range - exact[k][i].range);
			after += mrpt::square(restored[i].range - exact[k][i].range);
			EXPECT_NEAR(std::hypot(restored[i].x, restored[i].y), restored[i].range, 1e-9);
			n++;
		}
	}
	const double rmsBefore = std::sqrt(before / n), rmsAfter = std::sqrt(after / n);
	// (ReadingsKeptOnTheirLevelShareOneError checks the groups.)
	std::printf("range error rms: %.1f mm on the lattice, %.1f mm restored; %zu of %zu points moved\n",
		1e3 * rmsBefore, 1e3 * rmsAfter, moved, n);
	EXPECT_GT(rmsBefore, 0.04);	 // 0.16 / sqrt(12) = 0.046
	// Not to the noise: a chord across a corner (a box's, seen head on,
	// both its anchors on one level) puts the run's points up to a step
	// off, and readings without an anchor keep theirs (46.7 -> 27.6 mm).
	EXPECT_LT(rmsAfter, 0.65 * rmsBefore);
	EXPECT_GT(moved, 7 * n / 10);

	// No lattice, nothing moved.
	ScanPoints scan = exact[0];
	EXPECT_EQ(lattice.dequantize(scan, 0.0), 0u);
	EXPECT_TRUE(scan.samePointsAs(exact[0]));
}

// The DFT's plan is made on first use and kept; a copy makes its own. A
// copy of a lattice that has searched, the original and a fresh one find
// the same step and offset, bit for bit, in any order.
TEST(RangeLattice, ACopyFindsWhatTheOriginalFinds)
{
	auto onLattice = officeScans([](double r) { return noisy(0.05 * std::round(r / 0.05), 0.003); });
	RangeLattice original;
	const double first = original.step(onLattice[0]);
	ASSERT_GT(first, 0);
	RangeLattice copy = original;
	RangeLattice assigned;
	assigned = original;
	for (const auto& scan : onLattice)
	{
		RangeLattice fresh;
		const double q = fresh.step(scan);
		EXPECT_EQ(copy.step(scan), q);
		EXPECT_EQ(copy.offset(), fresh.offset());
		EXPECT_EQ(original.step(scan), q);
		EXPECT_EQ(assigned.step(scan), q);
		EXPECT_EQ(assigned.offset(), fresh.offset());
	}
}

// A run of readings that no anchor places keeps them on their level: one
// rounding error for the whole run (on a wall seen head on, exactly one).
// They share an error group with the cell's sigma, q / sqrt(12); points
// put back on a chord have none; different runs have different groups.
TEST(RangeLattice, ReadingsKeptOnTheirLevelShareOneError)
{
	const double q = 0.16;
	mrpt::random::getRandomGenerator().randomize(3);
	auto onLattice = officeScans([&](double r) { return noisy(q * std::round(r / q), 0.01); });
	RangeLattice lattice;
	size_t kept = 0, moved = 0, groups = 0;
	for (const auto& raw : onLattice)
	{
		ScanPoints restored = raw;
		const double found = lattice.step(raw);
		ASSERT_NEAR(found, q, 1e-3);
		lattice.dequantize(restored, found, lattice.offset());
		for (size_t i = 0; i < restored.size(); i++)
		{
			const ScanPoint& p = restored[i];
			if (p.range == raw[i].range)
			{
				kept++;
				EXPECT_NE(p.sharedErrorGroup, 0u) << i;
				EXPECT_NEAR(p.sharedRangeSigma, found / std::sqrt(12.0), 1e-6);
			}
			else
			{
				moved++;
				EXPECT_EQ(p.sharedErrorGroup, 0u) << i;
			}
			if (i == 0 || p.sharedErrorGroup == 0) continue;
			const ScanPoint& before = restored[i - 1];
			const bool sameRun = before.beam + 1 == p.beam &&
				std::lround(before.range / q) == std::lround(raw[i].range / q) &&
				std::lround(raw[i - 1].range / q) == std::lround(raw[i].range / q);
			if (before.sharedErrorGroup != 0 && sameRun)
				EXPECT_EQ(before.sharedErrorGroup, p.sharedErrorGroup) << i;
			if (before.sharedErrorGroup != p.sharedErrorGroup) groups++;
		}
	}
	EXPECT_GT(kept, 20u);
	EXPECT_GT(moved, 10 * kept / 10);
	EXPECT_GT(groups, 5u);
}

// dequantize_extremum_chord: a surface's nearest run of readings on one
// level lies between two anchors on the same level boundary. On a flat wall
// seen head on the chord through them is the wall, and the anchors beyond
// lie on its line: the run goes on it either way. On a round thing (the
// simulated office's plant pot, 0.25 m, seen from 0.65 m) the anchors
// beyond are missing (its silhouette jumps to the wall behind) and the
// chord is a different line from each viewpoint: with the key the run is
// kept on its level, one shared rounding error, as a run without anchors.
TEST(RangeLattice, ARoundThingsNearestRunStaysOnItsLevelAFlatWallsGoesOnItsChord)
{
	const double q = 0.16;
	SyntheticRoom room;
	// A flat wall 0.7 m ahead, head on; a pot to the left; the rest far.
	room.add(0.7, -1.5, 0.7, 0.6);
	room.addCircle(0.5, 0.75, 0.25);
	room.add(-4, 4, 4, 4);
	room.add(-4, -4, 4, -4);
	auto scan = room.scan(CPose2D(0, 0, 0));
	for (size_t i = 0; i < scan->getScanSize(); i++)
		if (scan->getScanRangeValidity(i))
			scan->setScanRange(i, static_cast<float>(q * std::round(scan->getScanRange(i) / q)));
	const ScanPoints raw = ScanPoints::fromScan(*scan);
	auto dequantized = [&](double maxChord) {
		RangeLattice lattice;
		lattice.maxExtremumChord = maxChord;
		ScanPoints p = raw;
		lattice.dequantize(p, q);
		return p;
	};
	const ScanPoints chord = dequantized(0), kept = dequantized(0.5);
	ASSERT_EQ(chord.size(), raw.size());
	ASSERT_EQ(kept.size(), raw.size());
	// The pot's nearest run: level 4 (0.56-0.72 m) towards it, 0.56 m of
	// the pot's surface within 0.72 m; the wall's: level 4 within 13 deg
	// of straight ahead (the anchors beyond, at 0.88 m, 37 deg out).
	const double potBearing = std::atan2(0.75, 0.5);
	size_t potRun = 0, wallRun = 0;
	for (size_t i = 0; i < raw.size(); i++)
	{
		if (std::lround(raw[i].range / q) != 4) continue;
		const bool towardsPot = std::abs(raw[i].bearing - potBearing) < mrpt::DEG2RAD(15);
		const bool towardsWall = std::abs(raw[i].bearing) < mrpt::DEG2RAD(12);
		if (towardsPot)
		{
			potRun++;
			// On the chord without the key...
			EXPECT_NE(chord[i].range, raw[i].range) << i;
			EXPECT_EQ(chord[i].sharedErrorGroup, 0u) << i;
			// ...kept on its level with it, sharing one error.
			EXPECT_EQ(kept[i].range, raw[i].range) << i;
			EXPECT_NE(kept[i].sharedErrorGroup, 0u) << i;
			EXPECT_NEAR(kept[i].sharedRangeSigma, q / std::sqrt(12.0), 1e-6);
		}
		else if (towardsWall)
		{
			wallRun++;
			// The wall's run goes on its chord either way: the wall.
			EXPECT_EQ(kept[i].range, chord[i].range) << i;
			EXPECT_EQ(kept[i].sharedErrorGroup, 0u) << i;
			EXPECT_NEAR(kept[i].x, 0.7, 0.01) << i;
		}
	}
	EXPECT_GE(potRun, 5u);
	EXPECT_GE(wallRun, 5u);
	// Everything else is as without the key.
	size_t differ = 0;
	for (size_t i = 0; i < raw.size(); i++) differ += kept[i].range != chord[i].range;
	EXPECT_EQ(differ, potRun);
}
