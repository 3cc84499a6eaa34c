#!/usr/bin/env bash
# The correlative coarse search on by default (doc/benchmarks.md, "The
# search on by default"): whole runs (featloc-run, matcher chain, keyframes
# as in config.ini) with every matcher, coarse_search off and on, side by
# side: ATE rmse against the ground truth and the mean time per match.
#  - MRPT's 5 cm-noise simulated log (the README's default data), IcpMatcher,
#    matcher chain and EKF.
#  - The office and lab worlds, 1 cm noise, seeds 1-4 (the logs of
#    scripts/bench-robust.sh's whole-run table), every matcher.
#  - Held out: the corridor with six people walking, seeds 1-6, every
#    matcher as config.ini has it, matcher chain and EKF, and odometry
#    alone.
# The pairwise figures (every pair counted, flagged and silent failures)
# are scripts/bench-robust.sh's "+ coarse" rows; bench-robust.sh runs this
# script for its whole-run tables.
# Usage: scripts/bench-search-default.sh [OUTDIR]   (about 17 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-search-default "$@"

run() { # out, log, gt, matcher, on, extra --set args...
  local out="$1" log="$2" gt="$3" m="$4" on="$5"
  shift 5
  "$BIN/featloc-run" "$ROOT/config.ini" "$log" --out "$out" -q \
    --set "ScanMatcher:class=featloc::$m" --set "ScanMatcher.$m:coarse_search=$on" \
    --set "Evaluation:ground_truth=$gt" --set Output:write_scene=false \
    --set Output:write_rawlog=false "$@" > /dev/null
}
cell() { # out: "ATE [mm] / time [ms]"
  echo "$(fmt "$(jq -r '.evaluation.ate_m.rmse * 1000' "$1/summary.json")" 1) / $(fmt "$(jq -r '.match_time_s.mean * 1000' "$1/summary.json")" 2)"
}

machine_line
echo
echo "### MRPT's simulated log (5 cm noise, 1733 scans), IcpMatcher"
echo
echo "| estimator | coarse_search | ATE rmse [m] | failed matches | ambiguous, used inflated | time/match mean [ms] |"
echo "|---|---|---|---|---|---|"
D=/usr/share/mrpt/datasets/graphslam-engine-demos/action_observations_map
for est in matcher ekf; do
  for on in false true; do
    r="$OUT/run-simul-$est-$on"
    run "$r" "$D/simul.rawlog" "$D/simul.rawlog.GT.txt" IcpMatcher "$on" --set "Pipeline:estimator=$est"
    echo "| $est | $on | $(fmt "$(jq -r '.evaluation.ate_m.rmse' "$r/summary.json")") | $(jq -r '.counts.match_failures' "$r/summary.json") of $(jq -r '.counts.matches' "$r/summary.json") | $(jq -r '.counts.ambiguous_matches_used' "$r/summary.json") | $(fmt "$(jq -r '.match_time_s.mean * 1000' "$r/summary.json")" 2) |"
  done
done
echo
echo "### Office and lab, 1 cm noise, seeds 1-4 (matcher chain): ATE rmse [mm] / time per match [ms]"
echo
MATCHERS="IcpMatcher PcmFeatureMatcher IdcMatcher CfIdcMatcher"
header="| scene | seed"
for m in $MATCHERS; do header="$header | $m off | on"; done
echo "$header |"
echo "|---|---$(for m in $MATCHERS; do printf '|---|---'; done)|"
for scene in office lab; do
  for seed in 1 2 3 4; do
    [ -f "$OUT/$scene-seed$seed.rawlog" ] || sim_1cm "$scene" "$seed"
    row="| $scene | $seed"
    for m in $MATCHERS; do
      for on in false true; do
        r="$OUT/run-$scene-seed$seed-$m-$on"
        run "$r" "$OUT/$scene-seed$seed.rawlog" "$OUT/$scene-seed$seed.gt.txt" "$m" "$on"
        row="$row | $(cell "$r")"
      done
    done
    echo "$row |"
  done
done
echo
echo "### Held out: the corridor with people walking, seeds 1-6, every matcher as config.ini has it: ATE rmse [mm]"
echo
echo "| estimator | matcher$(for s in 1 2 3 4 5 6; do printf ' | seed %s' $s; done) | mean |"
echo "|---|---|---|---|---|---|---|---|---|"
sim_corridor_seeds
corridor_row() { # estimator, matcher[, label, extra --set args...]
  local est="$1" m="$2" label="${3:-$2}" row sum=0 a seed r
  shift 2
  [ $# -gt 0 ] && shift
  row="| $est | $label"
  for seed in 1 2 3 4 5 6; do
    r="$OUT/run-corridor-seed$seed-$est-$(echo "$label" | tr -d "()" | tr " >" "__")"
    "$BIN/featloc-run" "$ROOT/config.ini" "$OUT/corridor-people-seed$seed.rawlog" --out "$r" -q \
      --set "ScanMatcher:class=featloc::$m" --set "Pipeline:estimator=$est" \
      --set "Evaluation:ground_truth=$OUT/corridor-people-seed$seed.gt.txt" \
      --set Output:write_scene=false --set Output:write_rawlog=false "$@" > /dev/null
    a="$(jq -r '.evaluation.ate_m.rmse * 1000' "$r/summary.json")"
    sum="$(awk -v s="$sum" -v a="$a" 'BEGIN { print s + a }')"
    row="$row | $(fmt "$a" 0)"
  done
  echo "$row | $(fmt "$(awk -v s="$sum" 'BEGIN { print s / 6 }')" 0) |"
}
corridor_row odometry IcpMatcher "(odometry alone)"
for est in matcher ekf; do
  for m in $MATCHERS; do corridor_row "$est" "$m"; done
  # PCM's fallback before 2026-11-25: MRPT's ICP.
  corridor_row "$est" PcmFeatureMatcher "PcmFeatureMatcher > IcpMatcher" \
    --set ScanMatcher.PcmFeatureMatcher:fallback_class=featloc::IcpMatcher
done
echo
echo "(defaults: coarse_search on for PcmFeatureMatcher, IdcMatcher, CfIdcMatcher; off for IcpMatcher; raw outputs in $OUT)"
