#include "featloc/app/BenchApp.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/MatcherVariant.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/PairedComparison.h"
#include "featloc/eval/ScanPairBenchmark.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/eval/LoopClosureRelations.h"
#include "featloc/io/CarmenLogReader.h"
#include "featloc/io/CarmenLogSource.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/pipeline/ProgressBar.h"
#include "featloc/plot/CurvePlot.h"
#include "featloc/pipeline/StepAssembler.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/MovedSurfaceBeams.h"
#include "featloc/sim/RangeScanFisherInformation.h"
#include "featloc/sim/SimConfiguration.h"

namespace featloc
{
namespace
{
struct Sequence
{
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	std::vector<double> times;
	std::vector<mrpt::poses::CPosePDFGaussian> odometry;  //!< since the previous scan
	std::vector<mrpt::poses::CPose2D> reference;  //!< poses, when known
};

Sequence loadCarmen(const std::string& path, const InputOptions& input)
{
	Sequence seq;
	mrpt::poses::CPose2D prevOdo;
	for (const auto& s : CarmenLogReader::read(path, CarmenLogReader::Options::from(input)))
	{
		seq.scans.push_back(s.scan);
		seq.times.push_back(s.time);
		seq.reference.emplace_back(s.pose);
		const mrpt::poses::CPose2D odo(s.odometry);
		seq.odometry.emplace_back(seq.scans.size() == 1 ? mrpt::poses::CPose2D() : odo - prevOdo);
		prevOdo = odo;
	}
	return seq;
}

Sequence loadRawlog(
	const std::string& path, const RunConfiguration& rc, const std::string& gtPath)
{
	Sequence seq;
	RawlogReader reader(path);
	StepAssembler assembler(rc.input, rc.odometry, path);
	std::vector<EstimationStep> steps;
	std::vector<StepSource> used;
	RawlogEntry e;
	while (!assembler.full() && reader.next(e)) assembler.push(e, used, steps);
	assembler.finish(steps);
	// Scan pairs: the odometry of steps without a scan (landmark frames)
	// composes into the next scan's.
	mrpt::poses::CPosePDFGaussian sinceScan;
	for (const auto& s : steps)
	{
		sinceScan += s.odometry;
		if (!s.scan) continue;
		seq.scans.push_back(s.scan);
		seq.times.push_back(mrpt::Clock::toDouble(s.time));
		seq.odometry.push_back(seq.scans.size() == 1 ? s.odometry : sinceScan);
		sinceScan = mrpt::poses::CPosePDFGaussian();
	}
	if (!gtPath.empty())
	{
		const Trajectory gt = TrajectoryFile::read(gtPath);
		Trajectory est;
		for (double t : seq.times)
		{
			TimedPose p;
			p.t = t;
			est.poses.push_back(p);
		}
		const auto pairs = TrajectoryEvaluator(0.001).associate(gt, est);
		if (pairs.size() != est.poses.size())
			throw InputError(
				"ground truth '" + gtPath + "' has poses for only " +
				std::to_string(pairs.size()) + " of the " + std::to_string(est.poses.size()) +
				" scans (within 1 ms)");
		seq.reference.resize(seq.scans.size());
		for (const auto& [g, s] : pairs) seq.reference[s] = mrpt::poses::CPose2D(gt.poses[g].pose);
	}
	return seq;
}
/** --world: each pair's Cramer-Rao bound from the world's true surfaces, at
 * the scans' ground-truth poses (each scan's information once; not with
 * withBounds false: Nunez et al.'s protocol moves the scans), and the
 * current scan's beams on things that moved since the reference scan. */
void attachWorld(std::vector<ScanPairSample>& pairs, const std::vector<size_t>& referenceIndex,
	const std::vector<size_t>& currentIndex, const Sequence& seq, const std::string& worldPath,
	bool withBounds, bool frozen)
{
	if (seq.reference.empty())
		throw UsageError("--world needs the scans' ground truth (--ground-truth FILE)");
	TrackedConfig wc;
	wc.loadFile(worldPath);
	SimConfiguration world = SimConfiguration::load(wc);
	wc.requireAllKeysRead();
	if (frozen) world.world = world.world.frozen();
	std::map<size_t, mrpt::math::CMatrixDouble33> info;
	auto informationOf = [&](size_t k) -> const mrpt::math::CMatrixDouble33& {
		auto it = info.find(k);
		if (it != info.end()) return it->second;
		RangeScanFisherInformation::Result r;
		try
		{
			r = RangeScanFisherInformation::of(world.world, seq.times[k] - world.simulation.t0,
				*seq.scans[k], seq.reference[k]);
		}
		catch (const std::invalid_argument& e)
		{
			throw InputError("--world '" + worldPath + "': scan " + std::to_string(k) + ": " + e.what());
		}
		// A scan of another world (or another path) would give a bound of
		// nothing: the measured ranges must be the exact ones plus noise.
		if (r.beamsOff > r.beamsValid / 10)
			throw InputError("--world '" + worldPath + "': scan " + std::to_string(k) + " does not fit it at its ground-truth pose: " +
				std::to_string(r.beamsOff) + " of its " + std::to_string(r.beamsValid) +
				" valid ranges are more than 5 sigma from the world's" +
				(frozen ? std::string() : " (a log of featloc-sim --frozen needs --frozen here too)"));
		return info[k] = r.information;
	};
	for (size_t p = 0; p < pairs.size(); p++)
	{
		const auto& ref = informationOf(referenceIndex[p]);
		const auto& cur = informationOf(currentIndex[p]);
		if (withBounds)
			pairs[p].bound = ScanPairCramerRaoBound::of(
				seq.reference[referenceIndex[p]], ref, seq.reference[currentIndex[p]], cur);
		const size_t c = currentIndex[p];
		pairs[p].movedBeams = MovedSurfaceBeams::of(world.world, seq.times[c] - world.simulation.t0,
			*seq.scans[c], seq.reference[c], seq.times[referenceIndex[p]] - world.simulation.t0);
		pairs[p].movedKnown = true;
	}
}

/** --pairs: one row per matcher and pair. The status is what featloc-bench
 * counts: used (a success), ambiguous (flagged, used with its inflated
 * covariance), failed (the guess, with the guess's covariance); the last
 * column says why a pair failed or is ambiguous (tabs and line breaks
 * turned into spaces, so that every row stays one TSV row). */
void writePairOutcomes(const std::string& path, const std::string& name,
	const std::vector<ScanPairBenchmark::Result>& results)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
	f << "# data\tmatcher\tpair\tstatus\terr_x_m\terr_y_m\terr_yaw_rad\t"
		 "cov_xx\tcov_xy\tcov_xyaw\tcov_yy\tcov_yyaw\tcov_yawyaw\treason\n";
	using Status = ScanPairBenchmark::PairOutcome::Status;
	char buf[320];
	for (const auto& r : results)
		for (size_t k = 0; k < r.outcomes.size(); k++)
		{
			const auto& o = r.outcomes[k];
			const char* status = o.status == Status::Used ? "used"
				: o.status == Status::Ambiguous			 ? "ambiguous"
														 : "failed";
			std::snprintf(buf, sizeof(buf), "\t%zu\t%s\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t",
				k, status, o.error[0], o.error[1], o.error[2], o.cov(0, 0), o.cov(0, 1),
				o.cov(0, 2), o.cov(1, 1), o.cov(1, 2), o.cov(2, 2));
			std::string reason = o.reason;
			std::replace_if(reason.begin(), reason.end(),
				[](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
			f << name << '\t' << r.matcher << buf << reason << '\n';
		}
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
}

/** --pair-bounds: one row per pair with a world (--world): the true motion
 * and the pair's Cramer-Rao bound (its covariance and the mean |t| and |w|
 * errors it allows; "nan" where the bound is not finite), in the pairs'
 * order of --pairs, so that each matcher's error can be set against the
 * bound pair by pair and direction by direction. */
void writePairBounds(const std::string& path, const std::string& name,
	const std::vector<ScanPairSample>& pairs, const std::vector<size_t>& referenceIndex,
	const std::vector<size_t>& currentIndex)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
	f << "# data\tpair\treference_scan\tcurrent_scan\ttrue_x_m\ttrue_y_m\ttrue_yaw_rad\t"
		 "crb_xx\tcrb_xy\tcrb_xyaw\tcrb_yy\tcrb_yyaw\tcrb_yawyaw\tcrb_mean_t_m\tcrb_mean_w_rad\n";
	char buf[400];
	for (size_t k = 0; k < pairs.size(); k++)
	{
		const ScanPairSample& p = pairs[k];
		std::snprintf(buf, sizeof(buf), "\t%zu\t%zu\t%zu\t%.9g\t%.9g\t%.9g", k, referenceIndex[k],
			currentIndex[k], p.truth.x(), p.truth.y(), p.truth.phi());
		f << name << buf;
		if (p.bound && p.bound->bounded)
		{
			const auto& c = p.bound->cov;
			std::snprintf(buf, sizeof(buf), "\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\n",
				c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2), p.bound->meanTrans,
				p.bound->meanYaw);
			f << buf;
		}
		else
			f << "\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n";
	}
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
}

/** --basin-levels: "XY/YAW_DEG,..." as (metres, radians). */
std::vector<std::pair<double, double>> parseBasinLevels(const std::string& text)
{
	std::vector<std::pair<double, double>> out;
	std::vector<std::string> items;
	mrpt::system::tokenize(text, ",", items);
	for (const auto& it : items)
	{
		double xy = 0, yaw = 0;
		char extra = 0;
		if (std::sscanf(it.c_str(), "%lf/%lf%c", &xy, &yaw, &extra) != 2 || !(xy >= 0) ||
			!(yaw >= 0) || !std::isfinite(xy) || !std::isfinite(yaw))
			throw UsageError("--basin-levels: '" + it + "' is not XY_M/YAW_DEG (two numbers >= 0)");
		out.emplace_back(xy, mrpt::DEG2RAD(yaw));
	}
	if (out.empty()) throw UsageError("--basin-levels names no level");
	return out;
}

/** --loop-relations: the direct matches across the loops of a trajectory,
 * written as relations (LoopClosureRelations). */
int writeLoopRelations(const Sequence& seq, const std::string& data, const std::string& trajectoryPath,
	const std::string& matcherClass, const std::string& out, const TrackedConfig& cfg)
{
	ScanMatcher::Ptr matcher = ScanMatcherFactory::create(matcherClass);
	matcher->loadParams(cfg, ScanMatcherFactory::paramsSection(matcherClass));
	const Trajectory trajectory = TrajectoryFile::read(trajectoryPath);
	const auto r = LoopClosureRelations::find(
		seq.scans, seq.times, trajectory, *matcher, LoopClosureRelations::Options());
	if (r.relations.empty())
		throw InputError("'" + trajectoryPath + "' comes back to no place of '" + data +
			"' where " + matcherClass + " matches the two scans (" + std::to_string(r.revisits) +
			" revisits, " + std::to_string(r.failed) + " failed)");
	LoopClosureRelations::write(out, r.relations,
		"loop closures of " + data + ": " + matcherClass + " across the revisits of " + trajectoryPath);
	std::printf("%zu revisits in %s: %zu relations written to %s, %zu matches failed or flagged\n",
		r.revisits, trajectoryPath.c_str(), r.relations.size(), out.c_str(), r.failed);
	for (const auto& [kind, n] : r.failuresByKind)
		std::printf("  %zu %s, e.g. %s\n", n, kind.c_str(), r.exampleByKind.at(kind).c_str());
	return 0;
}

void printHeader()
{
	std::printf(
		"| data | matcher | pairs | flagged = failed + used | silent gross | gross used, flagged or not "
		"| \\|t\\| err mean / median / p95 [mm] "
		"| \\|w\\| err mean / median / p95 [deg] | MAE t_x / t_y [mm] | time/match mean / "
		"median [ms] | iterations | NEES mean / in 95%% bound |\n");
	std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

/** n of `of` in percent (0 when of is 0). */
double share(size_t n, size_t of)
{
	return of ? 100.0 * static_cast<double>(n) / static_cast<double>(of) : 0.0;
}

std::string percent(size_t n, size_t of)
{
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.1f%%", share(n, of));
	return buf;
}

/** "8.3% = 0.6 + 7.7": the flagged pairs, split into failed matches (the
 * pipeline then uses the guess) and flagged matches that are used
 * (ambiguous, or the guess kept along a free direction, with the
 * covariance grown). MRPT's ICP has only the first kind, so its failure
 * rate compares with the first figure, not with the flagged total. */
std::string flaggedCell(const ScanPairBenchmark::Result& r)
{
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.1f%% = %.1f + %.1f", share(r.flagged(), r.pairs),
		share(r.failures, r.pairs), share(r.ambiguousUsed, r.pairs));
	return buf;
}

void printRow(const std::string& name, const ScanPairBenchmark::Result& r)
{
	std::printf(
		"| %s | %s | %zu | %s | %s | %s | %.2f / %.2f / %.1f | %.3f / %.3f / %.2f | %.2f / %.2f | "
		"%.3f / %.3f | %.1f | %.2f / %.0f%% |\n",
		name.c_str(), r.matcher.c_str(), r.pairs, flaggedCell(r).c_str(),
		percent(r.silentGross, r.pairs).c_str(), percent(r.grossUsed, r.pairs).c_str(), r.meanTrans * 1e3, r.medianTrans * 1e3,
		r.p95Trans * 1e3, mrpt::RAD2DEG(r.maeYaw), mrpt::RAD2DEG(r.medianYaw),
		mrpt::RAD2DEG(r.p95Yaw), r.maeX * 1e3, r.maeY * 1e3, r.meanTime * 1e3,
		r.medianTime * 1e3, r.meanIterations, r.meanNees, 100 * r.neesWithin95);
}

/** With --world: the matchers' mean errors against the pairs' Cramer-Rao
 * bound, and the points on things that moved that they kept. */
void printWorldTables(const std::string& name, const std::vector<ScanPairBenchmark::Result>& results)
{
	if (!results.empty() && results.front().boundedPairs > 0)
	{
		std::printf("\n| data | matcher | pairs with a bound | \\|t\\| err mean / CRB [mm] | ratio "
					"| \\|w\\| err mean / CRB [deg] | ratio |\n|---|---|---|---|---|---|---|\n");
		for (const auto& r : results)
			std::printf("| %s | %s | %zu | %.2f / %.2f | %.2f | %.4f / %.4f | %.2f |\n", name.c_str(),
				r.matcher.c_str(), r.boundedPairs, r.boundedMeanTrans * 1e3, r.boundMeanTrans * 1e3,
				r.boundMeanTrans > 0 ? r.boundedMeanTrans / r.boundMeanTrans : 0.0,
				mrpt::RAD2DEG(r.boundedMeanYaw), mrpt::RAD2DEG(r.boundMeanYaw),
				r.boundMeanYaw > 0 ? r.boundedMeanYaw / r.boundMeanYaw : 0.0);
	}
	std::printf("\n| data | matcher | current points on things that moved since the reference scan, kept "
				"| the other points, kept |\n|---|---|---|---|\n");
	for (const auto& r : results)
	{
		if (r.movedSeen + r.stillSeen == 0)
		{
			std::printf("| %s | %s | (no parts reported) | |\n", name.c_str(), r.matcher.c_str());
			continue;
		}
		const std::string moved = r.movedSeen == 0
			? "(nothing moved)"
			: percent(r.movedKept, r.movedSeen) + " of " + std::to_string(r.movedSeen);
		std::printf("| %s | %s | %s | %s of %zu |\n", name.c_str(), r.matcher.c_str(), moved.c_str(),
			percent(r.stillKept, r.stillSeen).c_str(), r.stillSeen);
	}
}

/** --paired-with: the index of the matcher labelled `label`, or by default
 * the first featloc::IcpMatcher (none without one, or with "none"). */
std::optional<size_t> pairedPeer(
	const std::vector<MatcherVariant>& variants, const std::string& label, bool given)
{
	if (given && label == "none") return std::nullopt;
	for (size_t m = 0; m < variants.size(); m++)
		if (given ? variants[m].label == label : variants[m].className == "featloc::IcpMatcher")
			return m;
	if (!given) return std::nullopt;
	std::string known;
	for (const auto& v : variants) known += (known.empty() ? "" : ", ") + v.label;
	throw UsageError("--paired-with '" + label + "' is not a matcher of -m (" + known + ")");
}

/** Every matcher against the peer, pair by pair (PairedComparison): the
 * table, and "paired" in each of their JSON results. */
void printPairedTable(const std::string& name, const std::vector<ScanPairBenchmark::Result>& results,
	size_t peer, const ScanPairBenchmark::Options& o, nlohmann::json& j)
{
	const auto column = [&](const ScanPairBenchmark::Result& r, std::vector<double>& trans,
							std::vector<bool>& gross)
	{
		for (const auto& p : r.outcomes)
		{
			const double t = std::hypot(p.error[0], p.error[1]);
			trans.push_back(t);
			gross.push_back(t > o.grossTrans || std::abs(p.error[2]) > o.grossYaw);
		}
	};
	std::vector<double> peerTrans;
	std::vector<bool> peerGross;
	column(results[peer], peerTrans, peerGross);
	bool header = false;
	for (size_t m = 0; m < results.size(); m++)
	{
		if (m == peer) continue;
		std::vector<double> trans;
		std::vector<bool> gross;
		column(results[m], trans, gross);
		const auto c = PairedComparison::of(trans, gross, peerTrans, peerGross);
		if (!header)
		{
			std::printf("\n| data | matcher | paired with | \\|t\\| err mean difference, 95%% interval "
						"[mm] | grossly wrong: only this / only the other, McNemar p |\n"
						"|---|---|---|---|---|\n");
			header = true;
		}
		std::printf("| %s | %s | %s | %+.2f (%+.2f, %+.2f) | %zu / %zu, p = %.2g |\n", name.c_str(),
			results[m].matcher.c_str(), results[peer].matcher.c_str(), c.meanDiff * 1e3,
			c.ciLow * 1e3, c.ciHigh * 1e3, c.onlyA, c.onlyB, c.mcnemarP);
		j["results"][m]["paired"] = {{"with", results[peer].matcher},
			{"mean_trans_err_diff_m", c.meanDiff}, {"ci95_m", {c.ciLow, c.ciHigh}},
			{"gross_only_this", c.onlyA}, {"gross_only_other", c.onlyB}, {"mcnemar_p", c.mcnemarP}};
	}
}

nlohmann::json toJson(const ScanPairBenchmark::Result& r)
{
	nlohmann::json j = {{"matcher", r.matcher}, {"pairs", r.pairs}, {"failures", r.failures},
		{"failures_by_kind", r.failuresByKind}, {"ambiguous_used", r.ambiguousUsed},
		{"flagged", r.flagged()}, {"silent_gross_errors", r.silentGross},
		{"gross_used", r.grossUsed},
		{"matcher_fallbacks", r.matcherFallbacks},
		{"pairs_with_segments_dropped_by_residuals", r.segmentsDroppedByResiduals},
		{"fallback_matcher_matches", r.fallbackMatches},
		{"fallback_matcher_successes", r.fallbackSuccesses},
		{"coarse_search_skipped", r.searchSkipped},
		{"coarse_confirmations_slid", r.confirmationsSlid},
		{"guess_kept_along_free_direction", r.guessKeptAlongFreeDirection},
		{"success_rate", r.successRate()}, {"mae_x_m", r.maeX}, {"mae_y_m", r.maeY},
		{"mae_yaw_deg", mrpt::RAD2DEG(r.maeYaw)}, {"mean_trans_err_m", r.meanTrans},
		{"median_trans_err_m", r.medianTrans}, {"p95_trans_err_m", r.p95Trans},
		{"median_yaw_err_deg", mrpt::RAD2DEG(r.medianYaw)},
		{"p95_yaw_err_deg", mrpt::RAD2DEG(r.p95Yaw)}, {"time_mean_s", r.meanTime},
		{"time_median_s", r.medianTime}, {"iterations_mean", r.meanIterations},
		{"nees_mean", r.meanNees}, {"nees_median", r.medianNees},
		{"nees_within_95", r.neesWithin95}, {"failure_examples", r.failureExamples},
		{"silent_gross_examples", r.silentGrossExamples}};
	if (r.movedSeen + r.stillSeen > 0)
		j["points_kept"] = {{"moved_seen", r.movedSeen}, {"moved_kept", r.movedKept},
			{"still_seen", r.stillSeen}, {"still_kept", r.stillKept}};
	if (r.boundedPairs > 0)
		j["cramer_rao"] = {{"pairs", r.boundedPairs},
			{"mean_trans_err_m", r.boundedMeanTrans}, {"bound_mean_trans_m", r.boundMeanTrans},
			{"trans_ratio", r.boundedMeanTrans / r.boundMeanTrans},
			{"mean_yaw_err_deg", mrpt::RAD2DEG(r.boundedMeanYaw)},
			{"bound_mean_yaw_deg", mrpt::RAD2DEG(r.boundMeanYaw)},
			{"yaw_ratio", r.boundedMeanYaw / r.boundMeanYaw}};
	return j;
}
}  // namespace

int BenchApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-bench: scan matchers side by side on the pairs of consecutive "
		"scans of a log, with Borges & Aldon's protocol (each matcher starts "
		"from the true motion perturbed by uniform noise: +-perturb-xy per "
		"axis, +-perturb-yaw-deg) or Nunez et al.'s (--apply-motion: the "
		"current scan is moved by a random motion, each matcher starts from "
		"its mean); reports mean absolute errors in t_x, t_y, w, failures, "
		"time and iterations per match. Ground truth: a TUM or 't x y yaw' "
		"file for rawlogs, the poses of a CARMEN log (.log, .log.gz), or a "
		"reference matcher's result from odometry.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argConfig(
		"config", "INI configuration (matcher parameters, [Input])", true, "", "CONFIG", cmd);
	TCLAP::UnlabeledValueArg<std::string> argData(
		"data", "Rawlog, or CARMEN log (.log, .log.gz)", true, "", "DATA", cmd);
	TCLAP::ValueArg<std::string> argGt("g", "ground-truth",
		"Ground truth for a rawlog (TUM or t x y yaw)", false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argMatchers("m", "matchers",
		"Comma-separated matchers, each [LABEL=]CLASS[{key=value;...}]: the class, "
		"its [ScanMatcher.<Class>] parameters with the overrides on top, and the "
		"label of its rows; a key ScanMatcher.<Other>:key sets one of another matcher's "
		"section, which the matcher's fallback_class reads",
		false,
		"featloc::PcmFeatureMatcher,featloc::IcpMatcher", "CLASSES", cmd);
	TCLAP::ValueArg<std::string> argReference("", "reference-matcher",
		"Without ground truth: the motion this matcher finds from odometry is "
		"the reference",
		false, "", "CLASS", cmd);
	TCLAP::ValueArg<double> argXY("", "perturb-xy", "[m] initial error bound per axis",
		false, 0.3, "M", cmd);
	TCLAP::ValueArg<double> argYaw("", "perturb-yaw-deg", "[deg] initial error bound",
		false, 10, "DEG", cmd);
	TCLAP::ValueArg<std::string> argKind("", "perturbation", "uniform | gaussian", false,
		"uniform", "KIND", cmd);
	TCLAP::ValueArg<std::string> argApply("", "apply-motion",
		"Nunez et al.'s protocol: move each current scan by X,Y,YAW_DEG plus the "
		"perturbation's draw (use --perturbation gaussian), start from X,Y,YAW_DEG",
		false, "", "X,Y,YAW_DEG", cmd);
	TCLAP::ValueArg<unsigned int> argStride("", "stride",
		"Pair scan k with scan k - stride", false, 1, "N", cmd);
	TCLAP::ValueArg<unsigned int> argMax("", "max-pairs", "At most this many pairs (0 = all)",
		false, 0, "N", cmd);
	TCLAP::ValueArg<unsigned int> argSeed("", "seed", "Random seed", false, 1, "N", cmd);
	TCLAP::ValueArg<std::string> argJson("j", "json", "Also write the results as JSON",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argName("", "name", "Data name in the table", false, "",
		"NAME", cmd);
	TCLAP::ValueArg<std::string> argPairs("", "pairs",
		"Also write every pair's outcome per matcher (TSV: status, error x y yaw "
		"against the reference, the covariance used), for analyses across "
		"matchers such as scripts/reference-error-share.py",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argPairBounds("", "pair-bounds",
		"With --world: also write every pair's true motion and Cramer-Rao bound (TSV: "
		"the bound's covariance of x y yaw and the mean |t| and |w| errors it allows), "
		"in the order of --pairs",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argPairedWith("", "paired-with",
		"Compare every other matcher with this one (a label of -m) pair by pair: "
		"the mean |t| error difference with its 95% block-bootstrap interval, and "
		"the pairs only one of the two gets grossly wrong with McNemar's p (the "
		"reference's own error cancels); default: the first featloc::IcpMatcher "
		"(MRPT's ICP), if any; 'none': no comparison",
		false, "", "LABEL", cmd);
	TCLAP::SwitchArg argHeader("", "header", "Print the Markdown table header", cmd);
	TCLAP::ValueArg<std::string> argBasin("", "basin",
		"Also run every matcher at each --basin-levels initial error (the "
		"--perturbation kind) and plot the success rate against it (PNG): a pair "
		"succeeds when it is neither flagged nor off by more than 10 cm or 2 deg",
		false, "", "PNG", cmd);
	TCLAP::ValueArg<std::string> argBasinLevels("", "basin-levels",
		"Initial error bounds of the basin curve, XY_M/YAW_DEG,...", false,
		"0.1/2,0.2/5,0.3/10,0.4/15,0.5/20", "LEVELS", cmd);
	TCLAP::ValueArg<std::string> argWorld("", "world",
		"The featloc-sim world file the log was simulated in: each pair's "
		"Cramer-Rao bound from the range noise against the world's true "
		"surfaces at the ground-truth poses, and each matcher's mean error "
		"against it (not with --apply-motion); and the share of the current "
		"scans' points on things that moved since the reference scan (people, "
		"carts, doors) that the matchers reporting their parts (CF-IDC's "
		"segments, PCM's features) kept",
		false, "", "FILE", cmd);
	TCLAP::SwitchArg argFrozen("", "frozen",
		"With --world: the log was simulated with featloc-sim --frozen (the world's people and "
		"carts left out, its doors held at their angle at t = 0)",
		cmd);
	TCLAP::ValueArg<std::string> argLoops("", "loop-relations",
		"Instead of benchmarking: where TRAJECTORY (of this log) comes back to a place "
		"(poses within 1 m and 30 deg, 50 or more scans apart), match the two scans "
		"directly with --reference-matcher from the trajectory's motion and write the "
		"converged matches to --write-relations: a reference for featloc-eval where the "
		"log has no ground truth",
		false, "", "TRAJECTORY", cmd);
	TCLAP::ValueArg<std::string> argRelationsOut("", "write-relations",
		"With --loop-relations: the relations file to write", false, "", "FILE", cmd);
	ConfigCommandLine config(cmd, "ScanMatcher.PcmFeatureMatcher:refinement=none", "");
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;
	if (argKind.getValue() != "uniform" && argKind.getValue() != "gaussian")
		throw UsageError("--perturbation must be uniform or gaussian");
	if (argStride.getValue() < 1) throw UsageError("--stride must be >= 1");
	if (argFrozen.getValue() && !argWorld.isSet()) throw UsageError("--frozen needs --world FILE");
	if (argPairBounds.isSet() && !argWorld.isSet())
		throw UsageError("--pair-bounds needs --world FILE");
	if (argPairBounds.isSet() && argApply.isSet())
		throw UsageError("--pair-bounds does not go with --apply-motion (the moved scan's motion has no bound)");
	const auto basinLevels = parseBasinLevels(argBasinLevels.getValue());

	TrackedConfig cfg;
	config.load(cfg, argConfig.getValue());
	const RunConfiguration rc = RunConfiguration::load(cfg);
	const auto variants = MatcherVariant::parseList(argMatchers.getValue());
	std::vector<ScanMatcher::Ptr> matchers;
	for (const auto& v : variants) matchers.push_back(v.create(cfg));
	const std::optional<size_t> peer = pairedPeer(variants, argPairedWith.getValue(),
		argPairedWith.isSet());
	cfg.requireAllKeysRead();

	const std::string data = argData.getValue();
	if (argLoops.isSet() != argRelationsOut.isSet() || (argLoops.isSet() && !argReference.isSet()))
		throw UsageError("--loop-relations needs --write-relations FILE and --reference-matcher CLASS");
	const Sequence seq = CarmenLogSource::handles(data) ? loadCarmen(data, rc.input) : loadRawlog(data, rc, argGt.getValue());
	if (argLoops.isSet())
		return writeLoopRelations(seq, data, argLoops.getValue(), argReference.getValue(),
			argRelationsOut.getValue(), cfg);
	ScanMatcher::Ptr reference;
	if (seq.reference.empty())
	{
		if (!argReference.isSet())
			throw UsageError(
				"no ground truth: give --ground-truth FILE or --reference-matcher CLASS");
		reference = ScanMatcherFactory::create(argReference.getValue());
		reference->loadParams(cfg, ScanMatcherFactory::paramsSection(argReference.getValue()));
	}

	std::vector<ScanPairSample> pairs;
	std::vector<size_t> referenceIndex, currentIndex;  //!< of each pair's scans in seq
	size_t referenceFailures = 0;
	const size_t stride = argStride.getValue();
	for (size_t k = stride; k < seq.scans.size(); k++)
	{
		if (argMax.getValue() > 0 && pairs.size() >= argMax.getValue()) break;
		ScanPairSample p;
		p.reference = seq.scans[k - stride];
		p.current = seq.scans[k];
		if (!seq.reference.empty())
			p.truth = seq.reference[k] - seq.reference[k - stride];
		else
		{
			mrpt::poses::CPosePDFGaussian odo = seq.odometry[k - stride + 1];
			for (size_t j = k - stride + 2; j <= k; j++) odo += seq.odometry[j];
			const MatchResult r = reference->match(*p.reference, *p.current, odo);
			if (!r.success)
			{
				referenceFailures++;
				continue;
			}
			p.truth = r.estimate.mean;
		}
		pairs.push_back(p);
		referenceIndex.push_back(k - stride);
		currentIndex.push_back(k);
	}
	if (pairs.empty()) throw InputError("'" + data + "' gives no scan pair to benchmark");
	if (argWorld.isSet())
		attachWorld(pairs, referenceIndex, currentIndex, seq, argWorld.getValue(), !argApply.isSet(),
			argFrozen.getValue());

	ScanPairBenchmark::Options o;
	o.perturbXY = argXY.getValue();
	o.perturbYaw = mrpt::DEG2RAD(argYaw.getValue());
	o.perturbation = argKind.getValue();
	if (argApply.isSet())
	{
		std::vector<std::string> parts;
		mrpt::system::tokenize(argApply.getValue(), ",", parts);
		std::vector<double> v;
		for (const auto& p : parts)
		{
			char* end = nullptr;
			v.push_back(std::strtod(p.c_str(), &end));
			if (end == p.c_str() || *end != '\0' || !std::isfinite(v.back()))
				throw UsageError("--apply-motion: '" + p + "' is not a number");
		}
		if (v.size() != 3) throw UsageError("--apply-motion needs X,Y,YAW_DEG (three numbers)");
		o.applyMotion = true;
		o.appliedMotion = mrpt::poses::CPose2D(v[0], v[1], mrpt::DEG2RAD(v[2]));
	}
	o.seed = argSeed.getValue();
	ProgressBar progress(std::cerr, isatty(STDERR_FILENO) != 0);
	auto results = ScanPairBenchmark::run(pairs, matchers, o, [&](size_t done) {
		if (!config.quiet())
			progress.update(static_cast<double>(done) / static_cast<double>(pairs.size()), done);
	});
	if (!config.quiet()) progress.done(pairs.size());
	for (size_t m = 0; m < results.size(); m++) results[m].matcher = variants[m].label;

	const std::string name = argName.isSet()
		? argName.getValue()
		: std::filesystem::path(data).filename().string();
	if (argHeader.getValue()) printHeader();
	nlohmann::json j;
	j["data"] = data;
	j["pairs"] = pairs.size();
	j["reference_matcher_failures"] = referenceFailures;
	j["perturbation"] = {{"kind", o.perturbation}, {"xy_m", o.perturbXY},
		{"yaw_deg", mrpt::RAD2DEG(o.perturbYaw)}, {"seed", o.seed}};
	j["gross_error"] = {{"trans_m", o.grossTrans}, {"yaw_deg", mrpt::RAD2DEG(o.grossYaw)}};
	if (o.applyMotion)
		j["applied_motion"] = {{"x_m", o.appliedMotion.x()}, {"y_m", o.appliedMotion.y()},
			{"yaw_deg", mrpt::RAD2DEG(o.appliedMotion.phi())}};
	for (const auto& r : results)
	{
		printRow(name, r);
		j["results"].push_back(toJson(r));
	}
	for (size_t m = 0; m < results.size(); m++)
		if (results[m].fallbackMatches > 0)
			std::printf("\n%s: the fallback %s made %zu of %zu pairs after the matcher failed, was "
						"ambiguous or weak (%zu of them succeeded; counted above as its results)\n",
				results[m].matcher.c_str(), matchers[m]->fallback()->className().c_str(),
				results[m].fallbackMatches, results[m].pairs, results[m].fallbackSuccesses);
	for (const auto& r : results)
		if (r.searchSkipped > 0)
			std::printf("\n%s: the coarse search was skipped on %zu of %zu pairs, where the "
						"iterations from the guess put coarse_confirm_share of the points on the "
						"reference\n",
				r.matcher.c_str(), r.searchSkipped, r.pairs);
	for (const auto& r : results)
		if (r.confirmationsSlid > 0)
			std::printf("\n%s: on %zu of %zu pairs the points confirmed the iterations from the guess "
						"but a pose slid along its least certain direction fit as well, and the "
						"coarse search ran (coarse_confirm_probe)\n",
				r.matcher.c_str(), r.confirmationsSlid, r.pairs);
	for (const auto& r : results)
		if (r.segmentsDroppedByResiduals > 0)
			std::printf("\n%s: %zu of %zu pairs dropped segments of the current scan whose residuals "
						"at the estimate said they moved (segment_residual_chi2)\n",
				r.matcher.c_str(), r.segmentsDroppedByResiduals, r.pairs);
	for (const auto& r : results)
		if (r.guessKeptAlongFreeDirection > 0)
			std::printf("\n%s: %zu of %zu pairs kept the guess along the one direction their points "
						"left free (free_direction_from_guess; counted above as flagged, at the "
						"error of what they used)\n",
				r.matcher.c_str(), r.guessKeptAlongFreeDirection, r.pairs);
	if (peer) printPairedTable(name, results, *peer, o, j);
	if (argWorld.isSet()) printWorldTables(name, results);
	if (argBasin.isSet())
	{
		// The basin curve: the same pairs and draws at each initial error.
		CurvePlot plot;
		plot.title = "Basin: " + name + " (" + o.perturbation + " initial errors, " +
			std::to_string(pairs.size()) + " pairs)";
		plot.xLabel = "initial error bound: +-xy [m] / +-yaw [deg]";
		plot.yLabel = "success [%] (not flagged, within 10 cm and 2 deg)";
		for (const auto& v : variants) plot.series.push_back({v.label, {}});
		std::printf("\n| data | matcher | initial error | success | flagged | silent gross | \\|t\\| err mean [mm] |\n|---|---|---|---|---|---|---|\n");
		for (const auto& [xy, yaw] : basinLevels)
		{
			char tick[48];
			std::snprintf(tick, sizeof(tick), "%.2g / %.3g", xy, mrpt::RAD2DEG(yaw));
			plot.xTicks.push_back(tick);
			ScanPairBenchmark::Options lo = o;
			lo.perturbXY = xy;
			lo.perturbYaw = yaw;
			const auto level = ScanPairBenchmark::run(pairs, matchers, lo);
			for (size_t m = 0; m < level.size(); m++)
			{
				plot.series[m].values.push_back(100 * level[m].successRate());
				std::printf("| %s | %s | +-%.2f m / +-%.1f deg | %.1f%% | %s | %s | %.2f |\n",
					name.c_str(), variants[m].label.c_str(), xy, mrpt::RAD2DEG(yaw),
					100 * level[m].successRate(), percent(level[m].flagged(), level[m].pairs).c_str(),
					percent(level[m].silentGross, level[m].pairs).c_str(), level[m].meanTrans * 1e3);
				auto row = toJson(level[m]);
				row["matcher"] = variants[m].label;
				row["initial_error"] = {{"xy_m", xy}, {"yaw_deg", mrpt::RAD2DEG(yaw)}};
				j["basin"].push_back(row);
			}
		}
		// The value axis from the lowest tens of percent reached, so that
		// the differences between good matchers show.
		double lowest = 100;
		for (const auto& sr : plot.series)
			for (double v : sr.values) lowest = std::min(lowest, v);
		plot.yMin = std::max(0.0, 10 * std::floor(lowest / 10) - 10);
		// "X" and "X + something" next to each other: one colour, dashed.
		plot.pairedSeries = plot.series.size() % 2 == 0;
		for (size_t m = 0; plot.pairedSeries && m + 1 < variants.size(); m += 2)
			plot.pairedSeries = variants[m + 1].className == variants[m].className;
		plot.save(argBasin.getValue());
	}
	if (argPairs.isSet()) writePairOutcomes(argPairs.getValue(), name, results);
	if (argPairBounds.isSet())
		writePairBounds(argPairBounds.getValue(), name, pairs, referenceIndex, currentIndex);
	if (argJson.isSet())
	{
		std::ofstream f(argJson.getValue());
		if (!f) throw std::runtime_error("cannot write '" + argJson.getValue() + "'");
		f << j.dump(2) << "\n";
	}
	return 0;
}
}  // namespace featloc
