#!/usr/bin/env bash
# Reproduces "Issue 15, thirteenth session" in doc/benchmarks.md: the six
# Radish logs (../shared/data/laser2d or $FEATLOC_LASER2D; orebro is the
# calibration log, the other five held out), every pair against the log's
# reference poses, Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform),
# every pair counted (a failure at its guess's error). MRPT's ICP as MRPT runs
# it, PCM, IDC and CF-IDC as config.ini has them, in one featloc-bench run per
# log and seed.
#  - Table 1 (seed 1): featloc-bench's main table, with "gross used, flagged
#    or not" beside the flagged and silent rates.
#  - Table 2 (seeds 1-3): each featloc matcher paired with MRPT's ICP on the
#    same pairs and guesses (featloc-bench --paired-with): the mean |t| error
#    difference with its 95% block-bootstrap interval, and the pairs only one
#    of the two gets grossly wrong with McNemar's exact p. The reference's
#    own error, which every matcher shares, cancels in both.
# Usage: scripts/bench-real-logs.sh [OUTDIR]   (about 3 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-real-logs "$@"
[ -d "$LASER2D" ] || { echo "no real logs: $LASER2D not found" >&2; exit 1; }

M="IcpMatcher (MRPT)=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher"
M="$M,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
SEEDS="1 2 3"

logs() { echo "$LASER2D/orebro-corrected.log.gz"; held_out_radish_logs; }
run() { # log, seed -> $OUT/NAME-seedSEED.txt
  local name
  name="$(basename "$1" -corrected.log.gz)"
  "$BIN/featloc-bench" "$ROOT/config.ini" "$1" -m "$M" --paired-with "IcpMatcher (MRPT)" \
    --perturb-xy 0.3 --perturb-yaw-deg 10 --seed "$2" -q --header --name "$name" \
    -j "$OUT/$name-seed$2.json" --pairs "$OUT/$name-seed$2.tsv" > "$OUT/$name-seed$2.txt"
}

machine_line
for seed in $SEEDS; do
  for f in $(logs); do run "$f" "$seed"; done
done

echo
echo "### Table 1: every matcher on every log (seed 1; orebro: calibration)"
echo
first=1
for f in $(logs); do
  t="$OUT/$(basename "$f" -corrected.log.gz)-seed1.txt"
  if [ $first = 1 ]; then main_table < "$t"; first=0; else main_table < "$t" | tail -n +3; fi
done

echo
echo "### Table 2: paired with MRPT's ICP (each cell: |t| error mean difference [mm] and its 95% interval; grossly wrong only this / only ICP, McNemar p)"
echo
echo "| log | matcher | seed ${SEEDS// / | seed } |"
echo "|---|---|${SEEDS//[0-9]/---|}" | tr -d ' '
for f in $(logs); do
  name="$(basename "$f" -corrected.log.gz)"
  for seed in $SEEDS; do paired_rows "$seed" "$OUT/$name-seed$seed.txt"; done | paired_by_seed "$name"
done
echo
echo "(raw outputs in $OUT)"
