#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-seventh session" in doc/benchmarks.md: a
# matcher and its fallback (PCM's and CF-IDC's is IDC) sharing the coarse
# search's tables and last branch and bound (fallback_shares_tables = true,
# the default) against each building and searching its own (false).
#  - Per pair: one featloc-bench run per data set (orebro, calibration; the
#    five held-out Radish logs; the simulated office at 1 cm), Borges &
#    Aldon's protocol (+-0.3 m / 10 deg, seed 1), MRPT's ICP in the same run;
#    then whether every pair's outcome (status, error, covariance, reason)
#    is the same both ways, byte for byte.
#  - Whole runs: featloc-run with PCM and CF-IDC as config.ini has them on
#    the six Radish logs, both ways: time per match and the same ATE.
# Usage: scripts/bench-fallback-tables.sh [OUTDIR]   (about 3 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-fallback-tables "$@"
[ -d "$LASER2D" ] || { echo "no real logs: $LASER2D not found" >&2; exit 1; }

M="IcpMatcher (MRPT)=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher"
M="$M,PCM own tables=featloc::PcmFeatureMatcher{fallback_shares_tables=false}"
M="$M,CF-IDC=featloc::CfIdcMatcher,CF-IDC own tables=featloc::CfIdcMatcher{fallback_shares_tables=false}"
COMMON="--perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1 -q --paired-with none"
HEADER=--header
# The outcomes of matcher A's pairs against B's, matcher column left out.
same_pairs() { # pairs tsv, A, B
  if cmp -s <(awk -F'\t' -v m="$2" '$2 == m {$2 = ""; print}' "$1") \
            <(awk -F'\t' -v m="$3" '$2 == m {$2 = ""; print}' "$1"); then
    echo "identical"
  else
    echo "DIFFERENT"
  fi
}
rows=()
bench() { # name, data, extra args...
  local name="$1"
  bench_run "$@" --pairs "$(bench_file "$name").tsv" | main_table
  HEADER=
  rows+=("| $name | $(same_pairs "$(bench_file "$name").tsv" PCM "PCM own tables") | $(same_pairs "$(bench_file "$name").tsv" CF-IDC "CF-IDC own tables") |")
}

machine_line
echo
echo "### Per pair (time/match: shared against own tables)"
echo
sim_1cm office
bench "sim office (1 cm)" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt"
bench orebro "$LASER2D/orebro-corrected.log.gz"
for f in $(held_out_radish_logs); do bench "$(basename "$f" -corrected.log.gz)" "$f"; done
echo
echo "| data | PCM's pairs, shared against own | CF-IDC's pairs |"
echo "|---|---|---|"
printf '%s\n' "${rows[@]}"

echo
echo "### Whole runs (featloc-run as config.ini has it but the matcher; time per match mean / median [ms], ATE rmse [mm])"
echo
echo "| log | matcher | shared | own tables |"
echo "|---|---|---|---|"
for f in "$LASER2D/orebro-corrected.log.gz" $(held_out_radish_logs); do
  name="$(basename "$f" -corrected.log.gz)"
  for m in PcmFeatureMatcher CfIdcMatcher; do
    bench_featloc_run "$name-$m-shared" "$f" "" --set "ScanMatcher:class=featloc::$m"
    bench_featloc_run "$name-$m-own" "$f" "" --set "ScanMatcher:class=featloc::$m" \
      --set "ScanMatcher.$m:fallback_shares_tables=false"
    echo "| $name | $m | $(match_time_and_ate "$name-$m-shared") | $(match_time_and_ate "$name-$m-own") |"
  done
done
echo
echo "(raw outputs in $OUT)"
