#!/usr/bin/env bash
# Reproduces "Issue 15, nineteenth session" in doc/benchmarks.md: the
# coarse search's skip with and without coarse_confirm_probe (where the
# estimate's largest translation sigma reaches coarse_confirm_probe_sigma,
# no pose slid by 2 or 4 x coarse_confirm_distance along that direction may
# put as large a share of the points near the reference), each featloc
# matcher both ways and MRPT's ICP in one featloc-bench run per data set;
# Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed 1), every pair
# counted (a failure at its guess's error).
#  - Where it was found: the warehouse (worlds/warehouse-aisles.ini, made
#    this session and run before the change) with MRPT's 0.16 m range
#    lattice, frozen and with its forklift and workers.
#  - The calibration scenes of the other choices: the simulated office and
#    lab at 1 cm noise, the real orebro log, and the office and lab with the
#    lattice.
#  - Held out: the corridor with people (as it is and on the lattice), the
#    hall with people, the room and the workshop with moving objects, the
#    apartment and the parking garage (made this session; as they are and on
#    the lattice), the warehouse at 1 cm noise, and the other five Radish
#    logs (../shared/data/laser2d or $FEATLOC_LASER2D).
# Usage: scripts/bench-confirm-probe.sh [OUTDIR]   (about 30 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-confirm-probe "$@"

PCM=featloc::PcmFeatureMatcher IDC=featloc::IdcMatcher CF=featloc::CfIdcMatcher
M="PCM=$PCM,PCM without the probe=$PCM{coarse_confirm_probe=false}"
M="$M,IDC=$IDC,IDC without the probe=$IDC{coarse_confirm_probe=false}"
M="$M,CF-IDC=$CF,CF-IDC without the probe=$CF{coarse_confirm_probe=false}"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
HEADER=--header
bench() { bench_main_table "coarse search was skipped" "$@"; }  # name, data, extra args...
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)
simbench() { # sim_world | sim_lattice, world, name, featloc-sim args...: simulate (once) and bench
  "$@"
  bench "$3" "$OUT/$3.rawlog" -g "$OUT/$3.gt.txt" "${PB[@]}"
}

machine_line
echo
echo "### Where it was found: the warehouse on the 0.16 m lattice"
echo
simbench sim_lattice warehouse-aisles "warehouse frozen, lattice" --frozen
simbench sim_lattice warehouse-aisles "warehouse, lattice"
echo
echo "### Calibration scenes of the other choices"
echo
HEADER=--header
bench_calibration_scenes
bench_calibration_lattices ", lattice" "${PB[@]}"
echo
echo "### Held out"
echo
HEADER=--header
for w in corridor-people hall-people room-moving-objects workshop-moving-objects apartment parking-garage; do
  simbench sim_world "$w" "$w"
done
for w in corridor-people apartment parking-garage; do
  simbench sim_lattice "$w" "$w, lattice"
done
simbench sim_world warehouse-aisles "warehouse frozen (1 cm)" --frozen --set Laser:range_noise=0.01
bench_held_out_radish_logs
# Issue 15's speed target (0.1 ms per 361-beam pair for the best featloc
# matcher, MRPT's ICP timed in the same run): in the tables above every
# matcher takes its turn on each pair, and the first of them pays for the
# caches the others find warm; here PCM with and without the probe, each
# alone with MRPT's ICP on the office, three times in turn.
echo
echo "### Time per office pair, PCM with MRPT's ICP alone in the run (three runs each)"
echo
HEADER=--header
for run in 1 2 3; do
  for probe in true false; do
    # shellcheck disable=SC2086
    "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt" \
      $COMMON -m "PCM (probe $probe)=featloc::PcmFeatureMatcher{coarse_confirm_probe=$probe},IcpMatcher (MRPT)=featloc::IcpMatcher" \
      $HEADER --name "sim office (1 cm), run $run" "${PB[@]}" | main_table
    HEADER=
  done
done
# Whole runs, probe off (A) and on (B), as config.ini has them otherwise:
# the bundled log (0.16 m lattice), the corridor with people (seeds 1-3),
# the held-out Radish logs, and the warehouse on the lattice.
echo
echo "### Whole runs: ATE rmse [mm] / failed matches / the fallback's matches, without and with the probe; with against without step by step"
echo
sim_corridor_seeds
for cls in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
  echo
  echo "#### $cls"
  echo
  echo "| log | estimator | without the probe | with it | with against without: mean RPE difference [mm] (95% interval); steps off only with / only without, McNemar p |"
  echo "|---|---|---|---|---|"
  for est in matcher ekf; do
    whole_runs_two_ways "$est" "1 2 3" "$cls-off" "ScanMatcher.$cls:coarse_confirm_probe=false" "$cls-on" \
      "ScanMatcher.$cls:coarse_confirm_probe=true" --set "ScanMatcher:class=featloc::$cls"
    name="warehouse-lattice-$cls"
    for v in off on; do
      bench_featloc_run "$name-$est-$v" "$OUT/warehouse, lattice.rawlog" "$OUT/warehouse, lattice.gt.txt" \
        --set "Pipeline:estimator=$est" --set "ScanMatcher:class=featloc::$cls" \
        --set "ScanMatcher.$cls:coarse_confirm_probe=$([ $v = on ] && echo true || echo false)"
    done
    echo "| warehouse, lattice | $est | $(run_counts "$name-$est-off") | $(run_counts "$name-$est-on") | $(runs_paired "$OUT/warehouse, lattice.gt.txt" "$OUT/$name-$est-on" "$OUT/$name-$est-off") |"
  done
done
echo
echo "(raw outputs in $OUT)"
