#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** The step of a range lattice: a scanner, or a simulator, that reports
 * its ranges on multiples of a step q, plus noise. MRPT's simulated log
 * (rawlogs/mrpt-simul) is one: its ranges sit on multiples of 0.16 m with
 * about 1 cm of noise on top. A surface then shows as arcs of constant
 * range centred on the sensor, which move with it: a matcher that
 * trusts them as surfaces is pulled towards "no motion", and a static
 * segment can lie up to one step off the reference at the true motion.
 *
 * Detected from one scan's own ranges: the circular resultant
 * R(f) = |mean exp(2 pi i f r_k)| is near exp(-2 pi^2 s^2 f^2) (s the
 * noise) at f = 1/q and its harmonics, and of order 1/sqrt(n) elsewhere
 * once the ranges span many steps. R is computed for every frequency at
 * once as the DFT of the ranges' histogram (OpenCV), and refined at the
 * lowest peak. */
class RangeLattice
{
   public:
	/** Steps looked for [m]: below minStep a lattice is finer than any
	 * sensor's noise that matters here (SICK's 1 cm); above maxStep it is
	 * no range finder. */
	static constexpr double kMinStep = 0.02, kMaxStep = 0.3;
	/** R at the step's frequency needed to call it a lattice: noise after
	 * the lattice of at most 0.13 steps (MRPT's simulated log: R 0.92).
	 * R is about 0.1-0.2 at the best frequency of an unquantized 361-beam
	 * scan, and 0.51-0.58 at 0.23 m on a few scans of a simulated corridor
	 * whose two walls bunch the ranges: 0.5 took those for lattices and
	 * undoing them broke a PCM chain there. Under noise of a fifth of its
	 * step (R 0.45) a lattice is not worth undoing: the noise is as large
	 * as the lattice's own error. */
	static constexpr double kMinResultant = 0.7;
	/** Fewest points, and fewest distinct lattice levels they occupy:
	 * ranges in a few narrow clusters (two walls seen head on) agree in
	 * phase at many frequencies without any lattice. */
	static constexpr size_t kMinPoints = 50, kMinLevels = 5;
	/** Only steps up to the ranges' interquartile range over this: where
	 * most ranges fall within a few steps, their own spread (a robot in a
	 * narrow corridor) puts them in phase at low frequencies. */
	static constexpr double kMinSpreadSteps = 2;

	/** q [m] of the lattice the scan's ranges sit on, or 0 when they sit
	 * on none of a step in [kMinStep, kMaxStep]. */
	double step(const ScanPoints& scan);
	/** The lattice's offset [m] found by the last step() (0 when it found
	 * none): the readings sit at offset + k q (a 5 cm lattice of acapulco
	 * sits on x.x3 and x.x8 m). */
	double offset() const { return m_offset; }
	/** The circular resultant R(f) of the scan's ranges at f = 1/q. */
	static double resultant(const ScanPoints& scan, double q);

	/** Undoes a lattice of step q where the scan says where the true range
	 * is: between two neighbouring beams whose readings are one level
	 * apart the surface crosses the level boundary, so it lies at range
	 * offset + (k + 1/2) q on the bisecting bearing (an anchor). The points of a run
	 * of beams on one level, between two anchors, are put where their
	 * beams cross the chord joining the anchors: on a wall, on the wall
	 * (to about half a beam's change of range), where the reading was up
	 * to q/2 off it. A run with an anchor on one side only (a surface's
	 * end) goes on the line through that anchor and the next one beyond
	 * it; a run without one keeps its readings, and so does a point the
	 * line would put more than q/2 off its level. Readings kept on their
	 * level share one rounding error per run: they get the run's
	 * ScanPoint::sharedErrorGroup with sharedRangeSigma q / sqrt(12), so
	 * that a covariance counts it once (PointToLineCovariance). Returns
	 * the number of points moved. */
	size_t dequantize(ScanPoints& scan, double q, double offset = 0);

	/** [m] dequantize(): a run between two anchors on the same level
	 * boundary (its neighbours both one level nearer, or both farther: the
	 * nearest or farthest stretch of a surface) whose chord is at most
	 * this long is kept on its level, as a run without anchors is, unless
	 * the anchors beyond it lie on the chord's line (a flat surface seen
	 * head on). 0: every such run goes on its chord. */
	double maxExtremumChord = 0;

   private:
	/** OpenCV's plan for the histogram's DFT (a cv::hal::DFT2D), made on
	 * first use and kept: cv::dft makes one per call, a third of its 20 us.
	 * A copy makes its own (a plan's buffers are not shared). */
	struct DftPlan
	{
		std::shared_ptr<void> plan;
		DftPlan() = default;
		DftPlan(const DftPlan&) {}
		DftPlan& operator=(const DftPlan&) { return *this; }
	} m_dftPlan;
	std::vector<float> m_histogram, m_spectrum;	 // reused buffers
	std::vector<double> m_ranges, m_sorted;
	std::vector<long> m_levels;
	double m_offset = 0;
	std::vector<std::pair<size_t, size_t>> m_runs;  // first, last point
};
}  // namespace featloc
