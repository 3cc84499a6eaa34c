#!/usr/bin/env bash
# Issue 17: are the matchers' guess-gate rejections right? For each
# rejection (matches.txt status "gate"), the converged estimate is compared
# with the ground truth's relative motion (scripts/match-errors.py): a
# rejection is wrong when the estimate is within 0.05 m and 1 deg of the
# truth (the gate threw a good match away), right otherwise. IDC and CF-IDC
# (the matchers with a guess gate), [Odometry] action_sampling_offset on
# (default) and off, on the logs with ground truth: the bundled log and the
# shipped simulated scenes.
# Usage: scripts/bench-gate-rejections.sh [OUTDIR]      (about 1 minute)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init gate-rejections "$@"
machine_line
echo
echo "| log | matcher | sampling offset | rejections | wrong (estimate within 0.05 m / 1 deg of the truth) | right |"
echo "|---|---|---|---|---|---|"
for log in bundled office lab corridor-people; do
  case $log in
    bundled) in=(); gt="$ROOT/rawlogs/mrpt-simul/simul.gt.txt";;
    *) in=("$ROOT/rawlogs/sim/$log.rawlog"); gt="$ROOT/rawlogs/sim/$log.gt.txt";;
  esac
  for m in IdcMatcher CfIdcMatcher; do
    for offset in true false; do
      dir="$OUT/$log-$m-$offset"
      "$BIN/featloc-run" "$ROOT/config.ini" "${in[@]}" -q --out "$dir" \
        --set "ScanMatcher:class=featloc::$m" --set "Odometry:action_sampling_offset=$offset" \
        --set "Evaluation:ground_truth=$gt" > /dev/null
      summary=$("$ROOT/scripts/match-errors.py" "$dir/matches.txt" "$gt" | grep '^# gate' || true)
      wrong=$(sed -n 's/^# gate: \([0-9]*\) with the estimate within.*/\1/p' <<<"$summary")
      right=$(sed -n 's/^# gate: \([0-9]*\) with the estimate outside.*/\1/p' <<<"$summary")
      wrong=${wrong:-0}; right=${right:-0}
      echo "| $log | $m | $offset | $((wrong + right)) | $wrong | $right |"
    done
  done
done
