#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-sixth session" in doc/benchmarks.md: PCM's
# line extraction without its two new steps ("neither", the default), each
# alone and both:
#  - line_outlier_sigmas = 3 (step 7): a line's points farther from it than
#    3 of their own sigmas (range noise at their incidence) are dropped and
#    the line refitted;
#  - collinear_fusion_chi2 = 9.21 (step 8): consecutive lines whose
#    (rho, alpha) agree within their covariances (chi-square, 2 dof, 99%)
#    become one line fitted to their points.
# Four PCM variants and MRPT's ICP in one featloc-bench run per data set,
# Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed 1), every pair
# counted:
#  - Static with 1 cm noise and the Cramer-Rao bound (--world): the office
#    and the lab (calibration), the apartment, the warehouse (where the
#    steps were looked for) and the parking garage (held out, --frozen).
#  - Held out: the corridor and the hall with people, the room with doors
#    and a cart, the three held-out worlds as written and on MRPT's 0.16 m
#    lattice, the bundled log (MRPT's simulator, 0.16 m lattice), orebro
#    (calibration) and the five other Radish logs.
#  - Whole runs (featloc-run, PCM as the matcher, estimator = matcher and
#    ekf): the bundled log, the corridor with people (seeds 1-6) and the
#    held-out Radish logs; both steps against neither, step by step.
# Usage: scripts/bench-pcm-line-outliers.sh [OUTDIR]   (about 15 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-line-outliers "$@"

PCM=featloc::PcmFeatureMatcher
OFF="line_outlier_sigmas=0;collinear_fusion_chi2=0"
M="PCM neither=$PCM{$OFF},PCM outliers=$PCM{line_outlier_sigmas=3;collinear_fusion_chi2=0}"
M="$M,PCM fusion=$PCM{line_outlier_sigmas=0;collinear_fusion_chi2=9.21}"
M="$M,PCM both=$PCM{line_outlier_sigmas=3;collinear_fusion_chi2=9.21},IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)
# The main table and, with --world, the Cramer-Rao table.
bench() { # name, data, extra args...
  bench_run "$@" "${PB[@]}" | awk -F'|' '/^\| data \| matcher \| pairs/ || NF == 14 || /CRB/ || NF == 9'
  HEADER=
}

machine_line
bench_extraction_scenes
for est in matcher ekf; do
  echo
  echo "### Whole runs, PcmFeatureMatcher, estimator = $est: ATE rmse [mm] / failed matches / fallback matches, neither | both"
  echo
  echo "| log | estimator | neither | both | both against neither: mean RPE difference [mm] (95%); steps off only both / only neither, McNemar |"
  echo "|---|---|---|---|---|"
  whole_runs_two_ways "$est" "1 2 3 4 5 6" neither \
    "ScanMatcher.PcmFeatureMatcher:line_outlier_sigmas=0 ScanMatcher.PcmFeatureMatcher:collinear_fusion_chi2=0" \
    both "ScanMatcher.PcmFeatureMatcher:line_outlier_sigmas=3 ScanMatcher.PcmFeatureMatcher:collinear_fusion_chi2=9.21" \
    --set "ScanMatcher:class=$PCM"
done
echo
echo "(raw outputs in $OUT)"
