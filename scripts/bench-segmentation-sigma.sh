#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-second session" in doc/benchmarks.md: IDC's
# and CF-IDC's segmentation (eq. (3)) with the fixed breakpoint_sigma_r
# (5 mm, the paper's; "off": breakpoint_sigma_r_from_scan = false) against
# sigma_r at least the scan's own range noise ("on": true, the default
# since that session).
#  - Per pair (featloc-bench, Borges & Aldon's protocol +-0.3 m / +-10 deg,
#    seed 1, every pair counted, off and on side by side in one run with
#    MRPT's ICP as the peer; PCM's off | on are its IDC fallback's): the
#    calibration scenes (office, lab at 1 cm; orebro), the held-out worlds
#    with movers (corridor and hall with people, room and workshop with
#    doors and carts), the three
#    held-out static worlds (apartment, warehouse, garage; frozen) at 1 cm
#    and at 3 cm noise, the office at 3 cm, the corridor with people and the
#    warehouse on MRPT's 0.16 m range lattice, and the five held-out Radish
#    logs.
#  - Whole runs (featloc-run as config.ini has it, PCM, IDC and CF-IDC each as
#    the matcher, estimator = matcher and ekf, off | on): the bundled log,
#    the corridor with people seeds 1-3, the held-out Radish logs.
#  - PCM's and CF-IDC's IDC fallback is set as IDC is, in both.
#  - With --probe (after OUTDIR): the same logs, IDC and CF-IDC with
#    coarse_confirm_probe_sigma = 0.004 ("off": the probe only where the
#    estimate's largest translation sigma reaches 4 mm) against 0 ("on":
#    wherever the share confirms the guess), both with
#    breakpoint_sigma_r_from_scan = true.
# Usage: scripts/bench-segmentation-sigma.sh [OUTDIR [--probe]]   (about 16 min on 2 cores each)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-segmentation-sigma "$@"

IDC=featloc::IdcMatcher CF=featloc::CfIdcMatcher
KEY=breakpoint_sigma_r_from_scan OFF=false ON=true
if [ "${2:-}" = "--probe" ]; then
  KEY=coarse_confirm_probe_sigma OFF=0.004 ON=0
fi
# CF-IDC's and PCM's IDC fallback ([ScanMatcher.IdcMatcher]) set the same
# way as IDC itself: each variant is one configuration (PCM's own matching
# has no such key; its off | on differ in the fallback alone).
FB="ScanMatcher.IdcMatcher:$KEY"
M="IcpMatcher (MRPT)=featloc::IcpMatcher"
M="$M,PCM off=featloc::PcmFeatureMatcher{$FB=$OFF},PCM on=featloc::PcmFeatureMatcher{$FB=$ON}"
M="$M,IDC off=$IDC{$KEY=$OFF},IDC on=$IDC{$KEY=$ON}"
M="$M,CF-IDC off=$CF{$KEY=$OFF;$FB=$OFF},CF-IDC on=$CF{$KEY=$ON;$FB=$ON}"
COMMON="--seed 1 -q --paired-with none"
HEADER=--header
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)
bench() { bench_main_table "" "$@"; }

machine_line
echo
echo "### Per pair, +-0.3 m / +-10 deg"
echo
bench_calibration_scenes
for w in corridor-people hall-people room-moving-objects workshop-moving-objects; do
  sim_world "$w" "$w"
  bench "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt" "${PB[@]}" --world "$ROOT/worlds/$w.ini"
done
for w in apartment warehouse-aisles parking-garage; do
  sim_world "$w" "$w-1cm" --frozen --set Laser:range_noise=0.01
  bench "$w, 1 cm" "$OUT/$w-1cm.rawlog" -g "$OUT/$w-1cm.gt.txt" "${PB[@]}"
done
for w in office apartment warehouse-aisles parking-garage; do
  sim_world "$w" "$w-3cm" --frozen --set Laser:range_noise=0.03
  bench "$w, 3 cm" "$OUT/$w-3cm.rawlog" -g "$OUT/$w-3cm.gt.txt" "${PB[@]}"
done
sim_lattice corridor-people corridor-people-lattice
bench "corridor-people, lattice" "$OUT/corridor-people-lattice.rawlog" -g "$OUT/corridor-people-lattice.gt.txt" "${PB[@]}"
sim_lattice warehouse-aisles warehouse-lattice --frozen
bench "warehouse, lattice" "$OUT/warehouse-lattice.rawlog" -g "$OUT/warehouse-lattice.gt.txt" "${PB[@]}"
bench_held_out_radish_logs

sim_corridor_seeds
featloc_matchers_two_ways "$KEY" "$OFF" off "$ON" on "1 2 3" no
echo
echo "(raw outputs in $OUT)"
