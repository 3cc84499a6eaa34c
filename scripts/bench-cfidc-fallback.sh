#!/usr/bin/env bash
# Reproduces the whole runs of "CF-IDC's fallback is IDC" in doc/benchmarks.md
# (issue 15, thirteenth session): featloc-run with CfIdcMatcher, its IDC
# fallback off (fallback_class empty) and on (config.ini), matcher chain and
# EKF, on the bundled log, the corridor with people (seeds 1-3) and the five
# held-out Radish logs. Per run: ATE rmse [mm], failed matches, the
# fallback's matches; then the two runs compared step by step
# (featloc-eval ON --paired-with OFF: mean RPE difference on - off [mm] with
# its 95% interval, and the steps only one gets off by > 10 cm or 2 deg,
# with McNemar's p). The Radish references: scripts/carmen-reference.py.
# CF-IDC keeps the guess along a free direction itself, as it did then
# (free_direction_from_guess = true; config.ini's false since the
# fourteenth session leaves that to the fallback: bench-cfidc-free-direction.sh).
# Usage: scripts/bench-cfidc-fallback.sh [OUTDIR]   (about 3 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc-fallback "$@"

sim_corridor_seeds
machine_line
echo
echo "| log | estimator | off: ATE [mm] / failed / fallback matches | on: the same | step by step, on - off: RPE difference [mm] (95%); steps off only on / only off, McNemar p |"
echo "|---|---|---|---|---|"
for est in matcher ekf; do
  whole_runs_two_ways "$est" "1 2 3" off "ScanMatcher.CfIdcMatcher:fallback_class=" \
    on "ScanMatcher.CfIdcMatcher:fallback_class=featloc::IdcMatcher" \
    --set ScanMatcher:class=featloc::CfIdcMatcher --set ScanMatcher.CfIdcMatcher:free_direction_from_guess=true
done
echo
echo "(raw outputs in $OUT)"
