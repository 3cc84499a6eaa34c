#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <vector>

#include "featloc/matchers/IterativeDualCorrespondence.h"
#include "featloc/matchers/ReferencePolyline.h"
#include "featloc/matchers/ScanMatcher.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"

namespace featloc
{
/** Lu & Milios' Iterative Dual Correspondence on whole scans: the
 * classic IDC that Nunez et al. compare CF-IDC with. The reference scan
 * becomes a polyline whose edges join consecutive points of one segment of
 * the adaptive breakpoint detector (so IDC does not interpolate across
 * depth jumps); every valid current point takes part. The iteration, the
 * covariance and the failures are IterativeDualCorrespondence's. */
class IdcMatcher : public ScanMatcher
{
	DEFINE_MRPT_OBJECT(IdcMatcher, featloc)

   public:
	// The confirmation probe wherever the share confirms the guess
	// (coarse_confirm_probe_sigma = 0): the 4 mm gate saves PCM's 0.1 ms
	// pairs a seventh of their time, nothing measurable on IDC's 1-9 ms;
	// ungated it found a 0.2 m slide along an aisle with a 3.4 mm sigma
	// (doc/benchmarks.md, "Issue 15, twenty-second session").
	IdcMatcher() { coarseSearchOptions().confirmProbeSigma = 0; }

	struct Parameters : public mrpt::config::CLoadableOptions
	{
		// featloc: eq. (3)'s sigma_r at least the scan's own range noise
		// (breakpoint_sigma_r_from_scan; doc/benchmarks.md, "Issue 15,
		// twenty-second session"). The paper's fixed sigma_r: false.
		Parameters() { segmentation.sigmaFromScan = true; }

		AdaptiveBreakpointSegmenter::Parameters segmentation;
		IterativeDualCorrespondence::Parameters idc;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	Parameters params;

   protected:
	void loadOwnParams(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveOwnParams(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
	double guessGateChi2() const override { return params.idc.guess_gate_chi2; }
	void matchPoints(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		MatchResult& result) override;

   private:
	/** Segments and polyline of `reference`, unless they are already of
	 * these points with these parameters. */
	void buildReference(const ScanPoints& reference);

	std::vector<ScanSegment> m_segments;
	ReferencePolyline m_polyline;
	IterativeDualCorrespondence m_idc;
	/** What m_segments and m_polyline were built from. */
	bool m_built = false;
	ScanPoints m_builtReference;
	AdaptiveBreakpointSegmenter::Parameters m_builtSegmentation;
	unsigned int m_builtLineHalfWindow = 0;
	double m_builtLineTarget = -1;
	double m_builtBowSigmas = -1;
	bool m_builtBowPerSegment = false;
	double m_builtCircleSigmas = -1, m_builtRoundExtent = -1;
};
}  // namespace featloc
