#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-fourth session" in doc/benchmarks.md: PCM's
# line extraction merging neighbouring runs on their joint RMS residual
# alone ("RMS": merge_step_points = 0, as before) against also keeping them
# apart where 3 consecutive points of the joint line lie beyond the split
# threshold on one side ("steps": merge_step_points = 3, the default since
# that session): a rack's upright standing 5 cm out of the pallets' face,
# which the RMS test merged into one line with the face. PCM both ways and
# MRPT's ICP in one featloc-bench run per data set, Borges & Aldon's
# protocol (+-0.3 m / +-10 deg uniform, seed 1), every pair counted:
#  - Static with 1 cm noise and the Cramer-Rao bound (--world): the office
#    and the lab (calibration), the apartment, the warehouse (where it was
#    found) and the parking garage (held out, --frozen).
#  - Held out: the corridor and the hall with people, the room with doors
#    and a cart, the three held-out worlds as written and on MRPT's 0.16 m
#    lattice, the corridor with people on that lattice (since the
#    twenty-sixth session: the data sets are bench-common's
#    bench_extraction_scenes), the bundled log (MRPT's simulator, 0.16 m
#    lattice), the six Radish logs.
#  - Whole runs (featloc-run, PCM as the matcher, estimator = matcher and
#    ekf): the bundled log, the corridor with people (seeds 1-6) and the
#    held-out Radish logs; "steps" against "RMS" step by step.
# Usage: scripts/bench-pcm-merge-steps.sh [OUTDIR]   (about 15 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-merge-steps "$@"

KEY=merge_step_points
PCM=featloc::PcmFeatureMatcher
M="PCM RMS=$PCM{$KEY=0},PCM steps=$PCM{$KEY=3},IcpMatcher (MRPT)=featloc::IcpMatcher"
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
  echo "### Whole runs, PcmFeatureMatcher, estimator = $est: ATE rmse [mm] / failed matches / fallback matches, $KEY 0 | 3"
  echo
  echo "| log | estimator | RMS | steps | steps against RMS: mean RPE difference [mm] (95%); steps off only steps / only RMS, McNemar |"
  echo "|---|---|---|---|---|"
  whole_runs_two_ways "$est" "1 2 3 4 5 6" rms "ScanMatcher.PcmFeatureMatcher:$KEY=0" \
    steps "ScanMatcher.PcmFeatureMatcher:$KEY=3" --set "ScanMatcher:class=$PCM"
done
echo
echo "(raw outputs in $OUT)"
