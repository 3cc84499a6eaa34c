#!/usr/bin/env bash
# Reproduces "Issue 15, eighth session" in doc/benchmarks.md: every featloc
# matcher as config.ini has it (coarse_confirm_share = 0.85: the coarse
# search is skipped where the points confirm the iterations from the guess)
# against the same matcher with the search on every pair
# (coarse_confirm_share = 0, the seventh session's default), PCM without the
# search (its "as published" start, for the time), and MRPT's ICP as MRPT
# runs it, in one featloc-bench run per data set; Borges & Aldon's protocol
# (+-0.3 m / +-10 deg uniform, seed 1), every pair counted (a failure at its
# guess's error). PCM takes the paper's fixed Delta_0, as in bench-robust.
#  - Calibration (where 0.85 and 5 cm were chosen): the simulated office
#    and lab at 1 cm noise, and the real orebro log.
#  - Held out: the corridor with people (+-0.3 m / 10 deg and +-0.5 m /
#    15 deg), the hall with people, the room with doors and a cart, and the
#    other five Radish logs (../shared/data/laser2d or $FEATLOC_LASER2D).
# Usage: scripts/bench-search-confirm.sh [OUTDIR]   (about 4 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-search-confirm "$@"

PCM=featloc::PcmFeatureMatcher IDC=featloc::IdcMatcher CF=featloc::CfIdcMatcher
M="PCM (config.ini)=$PCM,PCM search always=$PCM{coarse_confirm_share=0}"
M="$M,PCM without the search=$PCM{coarse_search=false}"
M="$M,IDC (config.ini)=$IDC,IDC search always=$IDC{coarse_confirm_share=0}"
M="$M,CF-IDC (config.ini)=$CF,CF-IDC search always=$CF{coarse_confirm_share=0}"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--set ScanMatcher.PcmFeatureMatcher:initial_bounds_source=config --seed 1 -q"
HEADER=--header
bench() { bench_main_table "coarse search was skipped" "$@"; }  # name, data, extra args...: the main table and the skip counts

machine_line
bench_calibration_and_held_out ""
echo
echo "### Speed: PCM beside MRPT's ICP alone, the office, three runs"
echo
# In the tables above every matcher runs in turn on each pair, and the
# searches of the ones before evict the caches PCM's iterations use.
HEADER=--header
for run in 1 2 3; do
  # shellcheck disable=SC2086
  "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt" \
    $COMMON -m "PCM (config.ini)=$PCM,IcpMatcher (MRPT)=featloc::IcpMatcher" $HEADER \
    --name "sim office (1 cm), run $run" --perturb-xy 0.3 --perturb-yaw-deg 10 | main_table
  HEADER=
done
echo
echo "(raw outputs in $OUT)"
