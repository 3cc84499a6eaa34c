#!/usr/bin/env bash
# Issue 15: dequantize_extremum_chord (doc/benchmarks.md, "Issue 15,
# twenty-fifth session"). On a range lattice, a surface's nearest (or
# farthest) run of readings on one level lies between two anchors on the
# same level boundary; put on the chord through them, a round thing (the
# office's plant pot) becomes a different line from each viewpoint. PCM,
# IDC and CF-IDC each with the runs on their chord ("chord",
# dequantize_extremum_chord = 0, the default) and kept on their level
# ("kept", 0.5 m; it stays off by default: see doc/benchmarks.md),
# with MRPT's ICP in one featloc-bench run per data set, Borges & Aldon's
# +-0.3 m / 10 deg:
#  - Calibration: the office and lab on the 0.16 m lattice with 1 cm noise,
#    and the orebro log.
#  - Held out: the bundled log (MRPT's simulated log, 0.16 m lattice), the
#    apartment, warehouse and garage on the lattice as written, the
#    corridor with people on the lattice and its frozen twin, and the other
#    five Radish logs (acapulco's, edmonton's and fhw's readings sit on
#    2.5-5 cm lattices).
#  - Whole runs: PCM, IDC and CF-IDC, as a chain and with the EKF, on the
#    bundled log, the corridor with people (seed 1) and the five Radish
#    logs, both ways.
# Usage: scripts/bench-lattice-extremum.sh [OUTDIR]   (about 12 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-lattice-extremum "$@"

KEY=dequantize_extremum_chord
M=""
for m in PCM=PcmFeatureMatcher IDC=IdcMatcher CF-IDC=CfIdcMatcher; do
  M="$M${M:+,}${m%%=*} chord=featloc::${m#*=}"
  M="$M,${m%%=*} kept=featloc::${m#*=}{$KEY=0.5;ScanMatcher.IdcMatcher:$KEY=0.5}"
done
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
HEADER=--header
bench() { bench_main_table "" "$@"; }  # name, data, extra args...
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)

machine_line
echo
echo "### Calibration scenes"
echo
bench_calibration_lattices ", lattice" "${PB[@]}"
[ -d "$LASER2D" ] && bench orebro "$LASER2D/orebro-corrected.log.gz" "${PB[@]}"
echo
echo "### Held out"
echo
HEADER=--header
bench "bundled log (0.16 m lattice)" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" -g "$ROOT/rawlogs/mrpt-simul/simul.gt.txt" "${PB[@]}"
for w in apartment warehouse-aisles parking-garage corridor-people; do
  sim_lattice "$w" "$w-lattice"
  bench "$w, lattice" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt" "${PB[@]}"
done
sim_lattice corridor-people corridor-people-lattice-frozen --frozen
bench "corridor-people frozen, lattice" "$OUT/corridor-people-lattice-frozen.rawlog" -g "$OUT/corridor-people-lattice-frozen.gt.txt" "${PB[@]}"
bench_held_out_radish_logs
sim_corridor_seeds
featloc_matchers_two_ways "$KEY" 0 chord 0.5 kept "1" yes
echo
echo "(raw outputs in $OUT)"
