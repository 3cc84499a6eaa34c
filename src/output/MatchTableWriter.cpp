#include "featloc/output/MatchTableWriter.h"

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <cstdio>

#include "featloc/io/MatchTableFile.h"
#include "featloc/output/StepRecord.h"

namespace featloc
{
MatchTableWriter::MatchTableWriter(std::string path)
	: TextRowWriter(std::move(path), MatchTableFile::header())
{
}

void MatchTableWriter::onStep(const StepRecord& r)
{
	if (!r.match) return;
	const MatchResult& m = *r.match;
	const bool overruled = !m.guessGateOverruled.empty();
	const char* status = m.success ? (overruled ? "overruled" : "ok")
								   : m.rejectedByGuessGate ? "gate" : "failed";
	// A failure says why. A success says what is to be known about it, in
	// this order: the guess gate the scans overruled, that the fallback
	// matcher made it and why the configured one gave up, why it is
	// flagged (ambiguous: its covariance inflated, or the guess kept along
	// a free direction), and why the estimator did not use it.
	std::string reason = m.failureReason;
	if (m.success)
	{
		reason.clear();
		auto add = [&reason](const std::string& part) {
			reason += (reason.empty() ? "" : "; ") + part;
		};
		if (overruled) add(m.guessGateOverruled);
		if (!m.primaryFailure.empty())
			add("made by the fallback matcher after " + m.primaryFailure);
		// (The coarse search's reasons already begin with "ambiguous".)
		if (m.ambiguous)
			add(m.ambiguityReason.rfind("ambiguous", 0) == 0 ? m.ambiguityReason
															 : "ambiguous: " + m.ambiguityReason);
		if (!r.fallbackReason.empty())
			add(reason.empty() ? r.fallbackReason : "not used: " + r.fallbackReason);
	}
	const auto& g = m.guess.mean;
	const auto& e = m.estimate.mean;
	std::string row(4096, '\0');
	int n = std::snprintf(row.data(), row.size(),
		"%.9f %.9f %s %d %u %.3f %.4f %zu %zu %.6f %.6f %.9f %.6f %.6f %.9f",
		mrpt::Clock::toDouble(r.step.time), mrpt::Clock::toDouble(m.referenceTime), status,
		r.usedMatch ? 1 : 0, m.iterations, m.timeSeconds * 1e3, m.goodness, m.referencePoints,
		m.currentPoints, g.x(), g.y(), g.phi(), e.x(), e.y(), e.phi());
	for (const auto* c : {&m.estimate.cov, &m.guess.cov, &m.gateAllowance})
		n += std::snprintf(row.data() + n, row.size() - n, " %.6e %.6e %.6e %.6e %.6e %.6e",
			(*c)(0, 0), (*c)(0, 1), (*c)(0, 2), (*c)(1, 1), (*c)(1, 2), (*c)(2, 2));
	n += std::snprintf(row.data() + n, row.size() - n, " %s", reason.empty() ? "-" : reason.c_str());
	row.resize(std::min<size_t>(std::max(n, 0), row.size() - 1));
	writeRow(row.c_str());
}
}  // namespace featloc
