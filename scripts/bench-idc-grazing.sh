#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-fourth session" in doc/benchmarks.md: IDC's
# and CF-IDC's segmentation (the adaptive breakpoint detector, eq. (3) of
# Nunez et al.) at the paper's lambda = 10 deg ("10", the default) against
# 5 deg ("5", as PCM's grazing_incidence_DEG; tried, not taken: better on
# the simulated static scenes, worse on the real logs): the
# most grazing incidence at which consecutive points still count as one
# surface. Beams that meet a wall grazingly far away carry most of a scan's
# information about rotation (their range changes fastest with it; Censi
# 2007), and eq. (3) at 10 deg cut them off their wall. Each featloc
# matcher both ways (PCM through its IDC fallback) and MRPT's ICP in one
# featloc-bench run per data set, Borges & Aldon's protocol (+-0.3 m /
# +-10 deg uniform, seed 1), every pair counted:
#  - Calibration: the simulated office and lab at 1 cm (with the
#    Cramer-Rao bound, --world) and orebro.
#  - Held out: the apartment, the warehouse and the parking garage frozen
#    at 1 cm (with the bound), as written and on MRPT's 0.16 m lattice; the
#    corridor (also +-0.5 m / 15 deg) and the hall with people, the room and
#    the workshop with moving objects; the bundled log; the other five
#    Radish logs.
#  - Whole runs (featloc-run; PCM, IDC and CF-IDC each, estimator = matcher
#    and ekf, the IDC fallback set the same way): the bundled log, the
#    corridor with people (seeds 1-6), the held-out Radish logs.
# Usage: scripts/bench-idc-grazing.sh [OUTDIR]   (about 40 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-idc-grazing "$@"

KEY=breakpoint_lambda_DEG
FB="ScanMatcher.IdcMatcher:$KEY"
M="PCM 10=featloc::PcmFeatureMatcher{$FB=10},PCM 5=featloc::PcmFeatureMatcher{$FB=5}"
M="$M,IDC 10=featloc::IdcMatcher{$KEY=10},IDC 5=featloc::IdcMatcher{$KEY=5}"
M="$M,CF-IDC 10=featloc::CfIdcMatcher{$KEY=10;$FB=10},CF-IDC 5=featloc::CfIdcMatcher{$KEY=5;$FB=5}"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)
# The main table, the fallback and search notes, and with --world the
# Cramer-Rao table.
bench() { # name, data, extra args...
  bench_run "$@" | awk -F'|' '/^\| data \| matcher \| pairs/ || NF == 14 || /CRB/ || NF == 9'
  HEADER=
}

machine_line
echo
echo "### Calibration"
echo
HEADER=--header
for w in office lab; do
  sim_1cm "$w"
  bench "sim $w (1 cm)" "$OUT/$w-1cm.rawlog" -g "$OUT/$w-1cm.gt.txt" --world "$ROOT/worlds/$w.ini" "${PB[@]}"
done
[ -d "$LASER2D" ] && bench orebro "$LASER2D/orebro-corrected.log.gz" "${PB[@]}"
echo
echo "### Held out"
echo
HEADER=--header
for w in apartment warehouse-aisles parking-garage; do
  sim_world "$w" "$w-frozen-1cm" --frozen --set Laser:range_noise=0.01
  bench "$w frozen (1 cm)" "$OUT/$w-frozen-1cm.rawlog" -g "$OUT/$w-frozen-1cm.gt.txt" \
    --world "$ROOT/worlds/$w.ini" --frozen "${PB[@]}"
done
for w in apartment warehouse-aisles parking-garage corridor-people hall-people room-moving-objects \
  workshop-moving-objects; do
  sim_world "$w" "$w"
  bench "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt" "${PB[@]}"
done
bench "corridor-people +-0.5/15" "$OUT/corridor-people.rawlog" -g "$OUT/corridor-people.gt.txt" \
  --perturb-xy 0.5 --perturb-yaw-deg 15
for w in apartment warehouse-aisles parking-garage corridor-people; do
  sim_lattice "$w" "$w-lattice"
  bench "$w, lattice" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt" "${PB[@]}"
done
bench "bundled (MRPT's simulator, lattice)" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" \
  -g "$ROOT/rawlogs/mrpt-simul/simul.gt.txt" "${PB[@]}"
if [ -d "$LASER2D" ]; then
  for f in $(held_out_radish_logs); do bench "$(basename "$f" -corrected.log.gz)" "$f" "${PB[@]}"; done
fi
sim_corridor_seeds
featloc_matchers_two_ways "$KEY" 10 "10" 5 "5" "1 2 3 4 5 6" no
echo
echo "(raw outputs in $OUT)"
