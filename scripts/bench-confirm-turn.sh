#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-ninth session" in doc/benchmarks.md: the
# confirmation probe along the estimate's least certain motion with its turn
# (coarse_confirm_probe_turn = true, the default) against the least certain
# translation only (false, as before), set in every featloc matcher's
# section (PCM's and CF-IDC's IDC fallback included). One featloc-bench run
# per data set and setting: PCM, IDC and CF-IDC as config.ini has them, and
# MRPT's ICP; Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed
# 1), every pair counted (a failure at its guess's error).
#  - Where it was found: the rotunda (worlds/rotunda.ini, made this session
#    and run before the change), as written and frozen.
#  - Held out from the change: the ring corridor (worlds/ring-corridor.ini,
#    written after the change and first run with it), the orchard (made
#    with the rotunda, run once before the change), the calibration scenes of the
#    earlier choices (the office and lab at 1 cm and on MRPT's 0.16 m
#    lattice, orebro), the other simulated worlds (as written, frozen at
#    1 cm against the Cramer-Rao bound, on the lattice), the bundled log and
#    the five other Radish logs (../shared/data/laser2d or $FEATLOC_LASER2D).
#  - PCM's time per office pair alone with MRPT's ICP, both ways, three
#    runs in turn (issue 15's speed target).
#  - Whole runs in the rotunda, both ways, each featloc matcher as the
#    matcher chain and in the EKF.
# Usage: scripts/bench-confirm-turn.sh [OUTDIR]   (about 30 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-confirm-turn "$@"

M="PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none --perturb-xy 0.3 --perturb-yaw-deg 10"
OFF=()
for s in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
  OFF+=(--set "ScanMatcher.$s:coarse_confirm_probe_turn=false")
done
HEADER=--header
# Both settings on one data set: "NAME" (the turn, the default) and
# "NAME, no turn"; with --world also the Cramer-Rao table of each.
bench() { # name, data, extra args...
  local name="$1" data="$2" notes="coarse search was skipped|confirmations"
  shift 2
  if [[ " $* " == *" --world "* ]]; then
    bench_run "$name" "$data" "$@" | awk -F'|' -v notes="$notes" \
      '/^\| data \| matcher \| pairs/ || NF == 14 || NF == 9 || $0 ~ notes'
    HEADER=
    bench_run "$name, no turn" "$data" "$@" "${OFF[@]}" | awk -F'|' -v notes="$notes" \
      'NF == 14 || NF == 9 || $0 ~ notes'
  else
    bench_main_table "$notes" "$name" "$data" "$@"
    bench_main_table "$notes" "$name, no turn" "$data" "$@" "${OFF[@]}"
  fi
}

machine_line
echo
echo "### Where it was found: the rotunda"
echo
sim_world_and_bench rotunda rotunda
sim_world_and_bench rotunda "rotunda frozen" --frozen
echo
echo "### Held out from the change: the ring corridor, the orchard, static scenes at 1 cm against the Cramer-Rao bound"
echo
HEADER=--header
sim_world_and_bench ring-corridor "ring corridor"
sim_world ring-corridor "ring corridor frozen" --frozen
bench "ring corridor frozen" "$OUT/ring corridor frozen.rawlog" -g "$OUT/ring corridor frozen.gt.txt" \
  --world "$ROOT/worlds/ring-corridor.ini" --frozen
sim_world_and_bench orchard orchard
sim_world orchard "orchard frozen (1 cm)" --frozen --set Laser:range_noise=0.01
bench "orchard frozen (1 cm)" "$OUT/orchard frozen (1 cm).rawlog" \
  -g "$OUT/orchard frozen (1 cm).gt.txt" --world "$ROOT/worlds/orchard.ini" --frozen
sim_world rotunda "rotunda frozen (1 cm)" --frozen --set Laser:range_noise=0.01
bench "rotunda frozen (1 cm)" "$OUT/rotunda frozen (1 cm).rawlog" \
  -g "$OUT/rotunda frozen (1 cm).gt.txt" --world "$ROOT/worlds/rotunda.ini" --frozen
# The data sets of PCM's extraction benches, the workshop, the calibration
# scenes on the lattice (bench-common.sh).
bench_extraction_scenes_and_the_rest
echo
echo "### Time per office pair, PCM with MRPT's ICP alone in the run (three runs each way)"
echo
office_time_two_ways PCM featloc::PcmFeatureMatcher turn "no turn"
# Whole runs in the rotunda (featloc-run as config.ini has it, each
# featloc matcher with estimator = matcher and then ekf), the turn against
# none in the matcher's section and in its IDC fallback's.
echo
echo "### Whole runs in the rotunda: ATE rmse [mm] / failed matches / fallback matches, no turn | turn"
echo
echo "| log | matcher | estimator | no turn | turn | turn against no turn: mean RPE difference [mm] (95%); steps off only turn / only no turn, McNemar |"
echo "|---|---|---|---|---|---|"
for log in rotunda "rotunda frozen"; do
  for est in matcher ekf; do
    for m in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
      name="whole-${log// /-}-$est-$m"
      for t in true false; do
        bench_featloc_run "$name-$t" "$OUT/$log.rawlog" "$OUT/$log.gt.txt" \
          --set "Pipeline:estimator=$est" --set "ScanMatcher:class=featloc::$m" \
          --set "ScanMatcher.$m:coarse_confirm_probe_turn=$t" \
          --set "ScanMatcher.IdcMatcher:coarse_confirm_probe_turn=$t"
      done
      echo "| $log | $m | $est | $(run_counts "$name-false") | $(run_counts "$name-true") | $(runs_paired "$OUT/$log.gt.txt" "$OUT/$name-true" "$OUT/$name-false") |"
    done
  done
done
echo
echo "(raw outputs in $OUT)"
