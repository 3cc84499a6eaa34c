#pragma once
#include <string>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <utility>
#include <vector>

#include "featloc/features/LineFit.h"
#include "featloc/features/ScanFeature.h"
#include "featloc/scan/PointNoiseEstimator.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** Borges & Aldon's scan features: linear and ellipsoidal clusters.
 *
 * The paper extracts lines with a fuzzy-clustering split-and-merge whose
 * details it does not give. This class implements split-and-merge with a
 * clustering refinement:
 *  1. segmentation: consecutive points (in bearing order) closer than
 *     max_point_gap form a cluster; so do points farther apart that
 *     Borges & Aldon's adaptive breakpoint detector (AdaptiveBreakpoint-
 *     Segmenter, eq. (3) of Nunez et al.) with lambda = grazing_incidence
 *     keeps together (featloc's; 0 = off). Along a wall seen at grazing
 *     incidence 8 m away, 0.5 degree beams land 0.5-0.9 m apart: a fixed
 *     gap drops those points, and with them the lever arm that fixes the
 *     wall's orientation (PCM's rotation error on the office: 1.66 ->
 *     1.4x the Cramer-Rao bound, doc/benchmarks.md);
 *  2. split: a run is split at the point farthest from its end-to-end chord
 *     while that distance exceeds the cluster's threshold (iterative
 *     end-point fit). The threshold adapts to the noise:
 *     max(split_distance_min, split_sigmas * s), where s is the cluster's
 *     point noise estimated robustly from second differences (the distance
 *     of each point to the chord of its two neighbours has variance
 *     1.5 s^2; s = 1.4826 median / sqrt(1.5)). A fixed threshold either
 *     shreds noisy walls or keeps corners seen at grazing incidence as one
 *     "line" whose foot point then depends on the viewpoint;
 *  3. merge: neighbouring runs whose joint TLS line has an RMS residual
 *     below merge_sigmas times the cluster's noise estimate (and below
 *     max_line_sigma) are merged, so a single noise spike that caused a
 *     split does not keep a straight wall in pieces (pieces split at an
 *     extreme point are biased beyond their covariance); but not where
 *     merge_step_points consecutive points of the joint line lie beyond
 *     the split threshold on one side of it: that is a step or a bump in
 *     the surface (a rack's upright standing out of the pallets' face),
 *     which a spike is not, and the merged line would take it in with a
 *     weight that changes from one viewpoint to the next (not on a range
 *     lattice, rangeNoiseFloor > 0, whose readings are off in runs);
 *  4. refinement (hard c-lines clustering along the scan): each point at a
 *     boundary between two neighbouring runs goes to the line it is closer
 *     to, lines are refitted, until nothing moves (refine_iterations at
 *     most);
 *  5. end trimming: end points farther than trim_sigmas times the
 *     cluster's robust noise estimate from the run's line are dropped and
 *     the line refitted (points of an adjoining wall seen at grazing
 *     incidence would otherwise tilt it);
 *  6. selection, as in the paper: lines with sigma <= max_line_sigma, at
 *     least min_points points and min_length long; those up to
 *     ellipse_max_length long become ellipsoidal clusters (centre of
 *     gravity), longer ones linear clusters;
 *  7. outliers (featloc's, off by default; line_outlier_sigmas): a line's points
 *     farther from it than line_outlier_sigmas of their own sigma (the
 *     scan's range noise at their incidence, as the covariance takes it)
 *     are dropped and the line refitted: the end trimming of step 5 does
 *     not reach a rack's upright or its side inside a run, or a few
 *     points of it at the run's grazing end;
 *  8. collinear fusion (featloc's, off by default; collinear_fusion_chi2):
 *     consecutive lines (an ellipse between them does not part them) whose
 *     (rho, alpha) agree within their covariances (chi-square, 2 dof) are
 *     fitted as one line to their points, leaving out what lies between: a
 *     wall seen through a door, a rack's face between its uprights, which
 *     step 3 keeps apart. A direction's information grows with the square
 *     of the line's length, so the pieces of one face hold far less about
 *     the rotation than the face does. The fused line's firstPoint and
 *     lastPoint span its pieces (and what lies between).
 *
 * Feature covariances: the scan's range noise s_r is estimated once,
 * pooled over every feature's points (a point at incidence theta lies
 * s_r |cos theta| off its line), so each point's perpendicular variance is
 * s_r^2 cos^2(theta) (at least min_point_sigma^2; a feature that fits more
 * than twice worse than predicted keeps its own residual variance). The
 * unweighted TLS fit then has var(alpha) = sum s_k^2 v_k / (sum s_k^2)^2,
 * and (rho, alpha) is propagated to the foot point. An ellipse centroid gets
 * s_r^2 / n plus (ellipse_shape_sigma_ratio * length)^2 for the shift of
 * the visible part of an object between viewpoints. Estimating each line's
 * noise from its own few residuals instead would make the covariance
 * over-confident whenever that estimate comes out low by chance.
 *
 * line_fit = weighted (featloc's, the default): each line is then refitted
 * by weighted total least squares with those variances as weights (twice,
 * the incidences taken from the previous fit), which is the maximum
 * likelihood line under range noise. Along a wall seen at grazing
 * incidence the far points, which give the orientation its lever arm, lie
 * much closer to the line than the near ones; the unweighted fit of eqs.
 * (3)-(8) (line_fit = tls, as published) weighs them alike and loses that
 * (PCM's rotation error on the office: 1.76 -> 1.66 times the Cramer-Rao
 * bound, doc/pcm-matcher.md). Its covariance is then var(alpha) =
 * 1 / sum w_k s_k^2 and var of the offset at the weighted centroid
 * 1 / sum w_k, uncorrelated. */
class LineEllipseExtractor
{
   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		double max_point_gap = 0.5;	 //!< [m] segmentation
		/** [rad] segmentation: points farther apart than max_point_gap
		 * stay in one cluster if a surface seen this grazingly could
		 * space them so (eq. (3) of the adaptive breakpoint detector);
		 * 0: max_point_gap alone. */
		double grazing_incidence = mrpt::DEG2RAD(5.0);
		double split_distance_min = 0.02;  //!< [m] split/merge threshold floor
		double split_sigmas = 4;  //!< threshold in estimated noise sigmas
		double trim_sigmas = 3;	 //!< end trimming, in estimated noise sigmas
		double merge_sigmas = 3;	//!< merge test, in estimated noise sigmas
		/** Runs stay apart where this many consecutive points of their joint
		 * line lie beyond the split threshold on one side (0: the RMS test
		 * alone). */
		unsigned int merge_step_points = 3;
		/** Step 7: a line's points farther from it than this many of their
		 * sigmas (range noise at their incidence) are dropped and the line
		 * refitted; 0: off (the default: it cost on the real calibration
		 * log, doc/benchmarks.md, "Issue 15, twenty-sixth session"; 3 was
		 * measured). */
		double line_outlier_sigmas = 0;
		/** Step 8: consecutive lines whose (rho, alpha) differ by at most
		 * this chi-square (2 dof; 9.21: 99%) become one line fitted to their
		 * points; 0: off (the default, as step 7; 9.21 was measured, with
		 * step 7 at 3: alone it makes a line of pieces with outliers). */
		double collinear_fusion_chi2 = 0;
		double max_line_sigma = 0.05;  //!< [m] sigma of eq. (8)
		unsigned int min_points = 5;
		double min_length = 0.2;  //!< [m]
		double ellipse_max_length = 0.5;  //!< [m]
		unsigned int refine_iterations = 5;
		double min_point_sigma = 0.003;	 //!< [m] floor of the noise estimate
		double ellipse_shape_sigma_ratio = 0.1;
		std::string line_fit = "weighted";	//!< weighted | tls (eqs. 3-8)

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
		/** Every field equal (a new field must be added here). */
		bool operator==(const Parameters& o) const;
	};

	Parameters params;

	/** Replaces `out` with the features of `scan` (reusing its storage).
	 * The last call's scan and features are kept: a matcher of consecutive
	 * scans extracts each scan once, as the current scan, and gets the same
	 * features back when that scan is the next pair's reference (same
	 * points, bit for bit, and same parameters). */
	void extract(const ScanPoints& scan, std::vector<ScanFeature>& out);

	/** The least range noise [m] the features' covariances take for the
	 * scans that follow (0: none): a range lattice's cell, q / sqrt(12),
	 * whose errors a scan's scatter does not show once its readings are
	 * put back on their surfaces (RangeLattice). Set by the matcher. */
	double rangeNoiseFloor = 0;

   private:
	using Run = std::pair<size_t, size_t>;	//!< [first, last] point indices
	/** Step 1's test: consecutive points a, b belong to different clusters. */
	bool clusterBreak(const ScanPoint& a, const ScanPoint& b) const;
	/** The split test's distance for a cluster of point noise `noise`. */
	double splitThreshold(double noise) const;
	/** Whether merge_step_points consecutive points of first..last lie
	 * beyond `threshold` on one side of `fit`. */
	bool hasStep(const ScanPoints& s, size_t first, size_t last, const LineFit& fit,
		double threshold) const;
	void split(const ScanPoints& s, size_t first, size_t last, double noise);
	void mergeRuns(const ScanPoints& s);
	/** The scan's range noise variance, pooled over the features' points
	 * (at least rangeNoiseFloor^2). */
	double pooledRangeVariance(const ScanPoints& s, const std::vector<ScanFeature>& features) const;
	void setCovariances(
		const ScanPoints& s, std::vector<ScanFeature>& features, double pooled2) const;
	/** One feature's covariance (and, line_fit = weighted, its refit) from
	 * its n points pts[0..n). */
	void setCovariance(const ScanPoint* pts, size_t n, ScanFeature& f, double pooled2) const;
	/** line_fit = weighted: `f` refitted by weighted TLS with each point's
	 * perpendicular variance inflate * max(floor2, pooled2 cos^2 theta) as
	 * its inverse weight, and its covariances set from that fit. */
	static void weightedRefit(const ScanPoint* pts, size_t n, ScanFeature& f, double inflate,
		double pooled2, double floor2);
	/** Whether lines a and b (disjoint points) are one line: their (rho,
	 * alpha) differ by at most collinear_fusion_chi2 (step 8). */
	bool sameLine(const ScanFeature& a, const ScanFeature& b) const;
	/** Step 7 on m_linePoints, fitted as `fit`: drops the outliers and
	 * refits `fit`; whether any was dropped. */
	bool dropOutliers(LineFit& fit, double pooled2);
	/** `f` set from `fit` of m_linePoints, its covariance with them. */
	void refitLine(ScanFeature& f, const LineFit& fit, double pooled2) const;
	/** Steps 7 and 8. */
	void cleanAndFuseLines(const ScanPoints& s, std::vector<ScanFeature>& features, double pooled2);
	void refine(const ScanPoints& s);

	void extractAnew(const ScanPoints& scan, std::vector<ScanFeature>& out);

	/** The last extraction (extract()'s memo). */
	struct Memo
	{
		bool valid = false;
		Parameters params;
		double rangeNoiseFloor = 0;
		ScanPoints scan;
		std::vector<ScanFeature> features;
	} m_memo;

	std::vector<Run> m_runs;  // reused buffers: no allocation per call
	std::vector<double> m_runNoise;	 //!< per run: its cluster's noise
	std::vector<char> m_pairKept;	//!< mergeRuns(): per pair of runs, fitted and kept apart
	std::vector<std::pair<Run, LineFit>> m_runFits;	 //!< refine(): per run, its last fit
	std::vector<Run> m_stack;
	PointNoiseEstimator m_noise;  //!< robust point noise of a cluster (step 2)
	std::vector<ScanPoint> m_linePoints;	//!< steps 7, 8: the last line's kept points
};
}  // namespace featloc
