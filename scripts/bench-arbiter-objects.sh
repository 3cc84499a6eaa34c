#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-third session" in doc/benchmarks.md: the
# guess-gate arbiter's evidence (ScanMatcher::arbitrateGuessGate) counted
# object by object ("objects": coarse_overrule_object_span = 0.3, the
# default since that session) against point by point ("points": 0, as
# before).
#  - Whole runs (featloc-run as config.ini has it but for the matcher: PCM,
#    IDC and CF-IDC each, estimator = matcher and ekf; the IDC fallback of
#    PCM and CF-IDC set the same way): the bundled log and the corridor with
#    people, seed 3 (where the span was chosen), the corridor's seeds 1, 2
#    and 4-6 and the five held-out Radish logs. ATE, and "objects" against
#    "points" step by step (featloc-eval --paired-with).
#  - The overruled matches of every run against the ground truth (the
#    Radish logs: their corrected poses): how many, how many within
#    5 cm / 1 deg, how many off by more than 10 cm or 2 deg where the
#    odometry's guess was not (scripts/match-errors.py --all).
# Usage: scripts/bench-arbiter-objects.sh [OUTDIR]   (about 5 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-arbiter-objects "$@"

KEY=coarse_overrule_object_span OFF=0 ON=0.3
SEEDS="1 2 3 4 5 6"
machine_line
sim_corridor_seeds
featloc_matchers_two_ways "$KEY" "$OFF" points "$ON" objects "$SEEDS" yes

# "overruled / within 5 cm and 1 deg / gross where the guess was not" of
# the run $OUT/NAME against the ground truth GT.
overrule_counts() { # name, gt
  python3 "$ROOT/scripts/match-errors.py" "$OUT/$1/matches.txt" "$2" --all |
    awk -F' [|] ' 'NF >= 3 && $1 ~ / overruled / { n++; split($2, e, " "); split($3, g, " ");
        em = e[1]; ed = e[2] < 0 ? -e[2] : e[2]; gm = g[1]; gd = g[2] < 0 ? -g[2] : g[2]
        if (em <= 0.05 && ed <= 1) right++
        if ((em > 0.1 || ed > 2) && !(gm > 0.1 || gd > 2)) harm++ }
      END { printf "%d / %d / %d", n, right, harm }'
}
echo
echo "### Overruled matches (every matcher and estimator above): overruled / within 5 cm and 1 deg of the truth / off by > 10 cm or 2 deg where the guess was not"
echo
echo "| log | PCM points | PCM objects | IDC points | IDC objects | CF-IDC points | CF-IDC objects |"
echo "|---|---|---|---|---|---|---|"
logs=("bundled:$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
for s in $SEEDS; do logs+=("corridor-seed$s:$OUT/corridor-people-seed$s.gt.txt"); done
for f in $(held_out_radish_logs); do
  n="$(basename "$f" -corrected.log.gz)"
  logs+=("$n:$OUT/$n.reference.txt")
done
for c in "${logs[@]}"; do
  IFS=: read -r name gt <<< "$c"
  row="| $name"
  for m in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
    for side in points objects; do
      cell=""
      for est in matcher ekf; do
        cell="$cell${cell:+, }$(overrule_counts "$name-$est-$m-$side" "$gt")"
      done
      row="$row | $cell"
    done
  done
  echo "$row |"
done
echo
echo "(each cell: estimator = matcher, then ekf; raw outputs in $OUT)"
