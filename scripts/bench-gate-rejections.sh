#!/usr/bin/env bash
# Issue 17: are the matchers' guess-gate decisions right? For each match
# the gate fired on -- a rejection that stood (matches.txt status "gate") or
# one the scans overruled (status "overruled", ScanMatcher's arbiter) -- the
# converged estimate is compared with the ground truth's relative motion
# (scripts/match-errors.py): the estimate is right when within 0.05 m and
# 1 deg of the truth. A rejection that stood with a right estimate threw a
# good match away; an overruled one with a wrong estimate let a bad one in.
# IDC and CF-IDC (the matchers with a guess gate), [Odometry]
# action_sampling_offset on (default) and off, on the logs with ground truth
# (the bundled log and the shipped simulated scenes), then the six Radish
# CARMEN logs (reference: their corrected poses; never used to choose a
# setting).
# Usage: scripts/bench-gate-rejections.sh [OUTDIR]      (about 2 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init gate-rejections "$@"
machine_line

# count SUMMARY STATUS within|outside
count() { sed -n "s/^# $2: \([0-9]*\) with the estimate $3 .*/\1/p" <<<"$1" | head -1; }
# row LOG MATCHER OFFSET DIR GT
row() {
  local s g0 g1 o0 o1
  s=$("$ROOT/scripts/match-errors.py" "$4/matches.txt" "$5" | grep '^# ' || true)
  g0=$(count "$s" gate within); g1=$(count "$s" gate outside)
  o0=$(count "$s" overruled within); o1=$(count "$s" overruled outside)
  g0=${g0:-0}; g1=${g1:-0}; o0=${o0:-0}; o1=${o1:-0}
  echo "| $1 | $2 | $3 | $((g0 + g1 + o0 + o1)) | $g0 | $g1 | $o0 | $o1 |"
}
echo
echo "| log | matcher | sampling offset | gate fired | stood, estimate right (good match lost) | stood, estimate wrong | overruled, estimate right | overruled, estimate wrong (bad match let in) |"
echo "|---|---|---|---|---|---|---|---|"
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
      row "$log" "$m" "$offset" "$dir" "$gt"
    done
  done
done
if [ -d "$LASER2D" ]; then
  for f in "$LASER2D"/*.log.gz; do
    n=$(basename "$f" .log.gz)
    for m in IdcMatcher CfIdcMatcher; do
      dir="$OUT/$n-$m"
      "$BIN/featloc-run" "$ROOT/config.ini" "$f" -q --out "$dir" \
        --set "ScanMatcher:class=featloc::$m" > /dev/null
      "$ROOT/scripts/carmen-reference.py" "$f" "$dir/poses_cov.txt" > "$OUT/$n.reference.txt"
      row "$n" "$m" "(CARMEN)" "$dir" "$OUT/$n.reference.txt"
    done
  done
fi
