#!/usr/bin/env bash
# Reproduces "Issue 15, eleventh session" in doc/benchmarks.md: the
# reference (keyframe) scan after a failed match, kept
# ([Pipeline] failed_match_keeps_keyframe = true, the default: the next
# good match corrects the failed steps) or replaced by the failed match's
# scan (false, as before).
#  - Whole runs only (featloc-run, as config.ini has it but for the matcher,
#    the estimator and the switch): per-pair figures have no keyframes.
#  - Every matcher with the matcher chain and with the EKF, MRPT's ICP
#    among them: the bundled log, the shipped office and lab (calibration
#    scenes), the six Radish logs (ATE against their corrected poses;
#    orebro is a calibration log, and it has no odometry: constant-velocity
#    prior, steps up to 3 m), the held-out corridor with people, seeds 1-6.
#  - Each cell: ATE rmse [mm] / failed matches, kept | replaced.
#  - With --factor (after OUTDIR): the keyframe kept, and
#    [Pipeline] failed_match_keyframe_factor 1 | 2 instead ("Issue 15,
#    twenty-first session": each cell factor 1 | factor 2, the default).
# Usage: scripts/bench-keyframe-after-failure.sh [OUTDIR [--factor]]   (about 10 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-keyframe-after-failure "$@"
SWITCH="Pipeline:failed_match_keeps_keyframe"; VALUES=(true false); WHAT="keyframe kept | replaced after a failure"
if [ "${2:-}" = "--factor" ]; then
  SWITCH="Pipeline:failed_match_keyframe_factor"; VALUES=(1 2); WHAT="failed_match_keyframe_factor 1 | 2"
fi

MATCHERS=(IcpMatcher PcmFeatureMatcher IdcMatcher CfIdcMatcher)

# "ATE [mm]/failed matches" of one featloc-run.
run() { # name, input (empty: config.ini's), ground truth (empty: the log's), --set args...
  bench_featloc_run "$@" || { echo "error (see $OUT/$1.txt)"; return; }
  jq -r '"\((.evaluation.ate_m.rmse // -0.001) * 1000 | round)/\(.counts.match_failures)"' \
    "$OUT/$1/summary.json"
}

machine_line
sim_corridor_seeds
logs=(bundled office lab)
[ -d "$LASER2D" ] && logs+=("$LASER2D"/*-corrected.log.gz)
logs+=(seed1 seed2 seed3 seed4 seed5 seed6)
for est in matcher ekf; do
  echo
  echo "### Whole runs, estimator = $est: ATE rmse [mm] / failed matches, $WHAT"
  echo
  printf '| log |'; printf ' %s |' "${MATCHERS[@]}"; echo
  printf '|---|'; printf -- '---|%.0s' "${MATCHERS[@]}"; echo
  for log in "${logs[@]}"; do
    case $log in
      bundled) in=""; gt="";;
      seed*) in="$OUT/corridor-people-$log.rawlog"; gt="$OUT/corridor-people-$log.gt.txt"; log="corridor-people $log";;
      /*) in="$log"; gt=""; log="$(basename "$log" -corrected.log.gz)";;
      *) in="$ROOT/rawlogs/sim/$log.rawlog"; gt="$ROOT/rawlogs/sim/$log.gt.txt";;
    esac
    row="| $log |"
    for m in "${MATCHERS[@]}"; do
      cell=""
      for keep in "${VALUES[@]}"; do
        cell="$cell${cell:+ | }$(run "${log// /-}-$est-$m-$keep" "$in" "$gt" --set "ScanMatcher:class=featloc::$m" \
          --set "Pipeline:estimator=$est" --set "$SWITCH=$keep")"
      done
      row="$row ${cell/ | / \\| } |"
    done
    echo "$row"
  done
done
echo
echo "(raw outputs in $OUT)"
