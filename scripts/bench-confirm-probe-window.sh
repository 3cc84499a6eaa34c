#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-fourth session" in doc/benchmarks.md: the
# confirmation probe (coarse_confirm_probe) sliding the estimate only by 2
# and 4 x coarse_confirm_distance along its least certain translation
# ("near": coarse_confirm_probe_window = false, as before) against also
# every coarse_confirm_distance out to the edges of the window the search
# would cover ("window": true, the default since that session). Each
# featloc matcher both ways and MRPT's ICP in one featloc-bench run per data
# set, every pair counted (a failure at its guess's error), seed 1:
#  - Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform) and the basin
#    curve's widest level (+-0.5 m / +-20 deg), where it was found: the
#    warehouse (worlds/warehouse-aisles.ini) frozen with 1 cm noise, pair
#    369 (CF-IDC stopped one upright's bay along the aisle).
#  - Calibration scenes: the simulated office and lab at 1 cm, orebro.
#  - Held out: the apartment and the parking garage frozen at 1 cm, the
#    three worlds as written, the warehouse and the corridor with people on
#    MRPT's 0.16 m lattice, the corridor and the hall with people, the room
#    with doors and a cart, and the five other Radish logs.
#  - Whole runs (featloc-run as config.ini has it but for the matcher and
#    the key; PCM, IDC and CF-IDC, estimator = matcher and ekf): the bundled
#    log, the corridor with people (seeds 1-6) and the held-out Radish logs;
#    "window" against "near" step by step (featloc-eval --paired-with).
# Usage: scripts/bench-confirm-probe-window.sh [OUTDIR]   (about 40 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-confirm-probe-window "$@"

KEY=coarse_confirm_probe_window
M=""
for m in PCM=PcmFeatureMatcher IDC=IdcMatcher CF-IDC=CfIdcMatcher; do
  M="$M${M:+,}${m%%=*} near=featloc::${m#*=}{$KEY=false;ScanMatcher.IdcMatcher:$KEY=false}"
  M="$M,${m%%=*} window=featloc::${m#*=}"
done
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
NOTES="coarse_confirm_probe|coarse search was skipped"
bench() { bench_main_table "$NOTES" "$@"; }  # name, data, extra args...
# Both protocols on one data set.
bench2() { # name, data, extra args...
  local name="$1" data="$2"
  shift 2
  bench "$name +-0.3/10" "$data" "$@" --perturb-xy 0.3 --perturb-yaw-deg 10
  bench "$name +-0.5/20" "$data" "$@" --perturb-xy 0.5 --perturb-yaw-deg 20
}

machine_line
echo
echo "### Where it was found, and the calibration scenes"
echo
HEADER=--header
sim_world warehouse-aisles warehouse-frozen-1cm --frozen --set Laser:range_noise=0.01
bench2 "warehouse frozen (1 cm)" "$OUT/warehouse-frozen-1cm.rawlog" -g "$OUT/warehouse-frozen-1cm.gt.txt"
for w in office lab; do
  sim_1cm "$w"
  bench2 "sim $w (1 cm)" "$OUT/$w-1cm.rawlog" -g "$OUT/$w-1cm.gt.txt"
done
[ -d "$LASER2D" ] && bench2 orebro "$LASER2D/orebro-corrected.log.gz"
echo
echo "### Held out"
echo
HEADER=--header
for w in apartment parking-garage; do
  sim_world "$w" "$w-frozen-1cm" --frozen --set Laser:range_noise=0.01
  bench2 "$w frozen (1 cm)" "$OUT/$w-frozen-1cm.rawlog" -g "$OUT/$w-frozen-1cm.gt.txt"
done
for w in warehouse-aisles apartment parking-garage corridor-people hall-people room-moving-objects; do
  sim_world "$w" "$w"
  bench2 "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt"
done
for w in warehouse-aisles corridor-people; do
  sim_lattice "$w" "$w-lattice"
  bench2 "$w, lattice" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt"
done
if [ -d "$LASER2D" ]; then
  for f in $(held_out_radish_logs); do bench2 "$(basename "$f" -corrected.log.gz)" "$f"; done
fi
sim_corridor_seeds
featloc_matchers_two_ways "$KEY" false near true window "1 2 3 4 5 6" yes
echo
echo "(raw outputs in $OUT)"
