#pragma once

namespace featloc
{
/** featloc-bench-landmarks CONFIG RAWLOG: featloc's EKF (EkfEstimator on
 * the steps of StepAssembler: odometry + range-bearing landmarks) and
 * MRPT's own landmark EKF (mrpt::slam::CRangeBearingKFSLAM2D, the filter
 * of the kf-slam app, fed the action/observation pairs as kf-slam feeds
 * them) on the same log, side by side: time per step (the filter's work
 * only, reading excluded), landmarks in the state, landmark errors against
 * a ground-truth landmark file (MRPT's kf-slam format: x y z ... id in
 * column 7, errors by identity as kf-slam computes them). Both paths and
 * maps are written for featloc-eval. */
class LandmarkBenchApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
