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
# Usage: scripts/bench-cfidc-fallback.sh [OUTDIR]   (about 3 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc-fallback "$@"

sim_corridor_seeds
summary() { jq -r '"\((.evaluation.ate_m.rmse // -0.001) * 1000 | round) / \(.counts.match_failures) / \(.counts.fallback_matcher_matches)"' "$OUT/$1/summary.json"; }
paired() { # reference, name
  "$BIN/featloc-eval" "$1" "$OUT/$2-on/poses_cov.txt" --paired-with "$OUT/$2-off/poses_cov.txt" -j |
    jq -r '.paired | "\(.rpe_trans_mean_diff_m * 1e5 | round / 100) (\(.ci95_m[0] * 1e5 | round / 100), \(.ci95_m[1] * 1e5 | round / 100)); \(.off_only_this) / \(.off_only_other), p = \(.mcnemar_p * 1000 | round / 1000)"'
}

machine_line
echo
echo "| log | estimator | off: ATE [mm] / failed / fallback matches | on: the same | step by step, on - off: RPE difference [mm] (95%); steps off only on / only off, McNemar p |"
echo "|---|---|---|---|---|"
for est in matcher ekf; do
  cases=("bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
  for s in 1 2 3; do cases+=("corridor-seed$s:$OUT/corridor-people-seed$s.rawlog:$OUT/corridor-people-seed$s.gt.txt"); done
  for f in $(held_out_radish_logs); do cases+=("$(basename "$f" -corrected.log.gz):$f:"); done
  for c in "${cases[@]}"; do
    IFS=: read -r name input gt <<< "$c"
    for fb in off on; do
      [ $fb = on ] && class=featloc::IdcMatcher || class=
      bench_featloc_run "$name-$est-$fb" "$input" "$gt" --set ScanMatcher:class=featloc::CfIdcMatcher \
        --set "Pipeline:estimator=$est" --set "ScanMatcher.CfIdcMatcher:fallback_class=$class"
    done
    ref="$gt"
    if [ -z "$ref" ]; then
      ref="$OUT/$name.reference.txt"
      python3 "$ROOT/scripts/carmen-reference.py" "$input" "$OUT/$name-$est-on/poses_cov.txt" > "$ref"
    fi
    echo "| $name | $est | $(summary "$name-$est-off") | $(summary "$name-$est-on") | $(paired "$ref" "$name-$est") |"
  done
done
echo
echo "(raw outputs in $OUT)"
