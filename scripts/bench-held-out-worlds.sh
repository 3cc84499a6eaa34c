#!/usr/bin/env bash
# Reproduces "Issue 15's targets on three worlds nobody tuned on" in
# doc/benchmarks.md (nineteenth session): the apartment, the warehouse and
# the parking garage (worlds/apartment.ini, warehouse-aisles.ini,
# parking-garage.ini; written before any matcher ran on them), each
# featloc matcher as config.ini has it and MRPT's ICP as MRPT runs it, in
# one featloc-bench run per log; Borges & Aldon's protocol (+-0.3 m / +-10
# deg uniform, seed 1), every pair counted (a failure at its guess's error).
#  - Static (featloc-sim --frozen) with 1 cm range noise: issue 15's static
#    targets, each matcher's mean error against the pairs' Cramer-Rao bound
#    (--world --frozen), and the basin curve (+-0.1 m / 2 deg to +-0.5 m /
#    20 deg, PNG in OUT).
#  - As written (people, a forklift, a car; each world's own laser noise):
#    the walking-people targets and the moved points each matcher kept;
#    the same world frozen with that noise (the floor of CF-IDC / IDC).
#  - As written on MRPT's 0.16 m range lattice.
# Usage: scripts/bench-held-out-worlds.sh [OUTDIR]   (about 6 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-held-out-worlds "$@"

M="IcpMatcher (MRPT)=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
COMMON="--seed 1 -q"
HEADER=--header
PB=(--perturb-xy 0.3 --perturb-yaw-deg 10)
WORLDS="apartment warehouse-aisles parking-garage"

machine_line
echo
echo "### Static (--frozen), 1 cm range noise"
echo
for w in $WORLDS; do
  sim_world "$w" "$w-frozen-1cm" --frozen --set Laser:range_noise=0.01
  bench_run "$w frozen, 1 cm" "$OUT/$w-frozen-1cm.rawlog" -g "$OUT/$w-frozen-1cm.gt.txt" "${PB[@]}" \
    --world "$ROOT/worlds/$w.ini" --frozen --basin "$OUT/basin-$w.png"
  HEADER=
done
echo
echo "### As written: people, carts, each world's laser"
echo
HEADER=--header
for w in $WORLDS; do
  sim_world "$w" "$w"
  bench_run "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt" "${PB[@]}" --world "$ROOT/worlds/$w.ini"
  HEADER=
  sim_world "$w" "$w-frozen" --frozen
  bench_main_table "" "$w frozen" "$OUT/$w-frozen.rawlog" -g "$OUT/$w-frozen.gt.txt" "${PB[@]}"
done
echo
echo "### As written, on the 0.16 m range lattice"
echo
HEADER=--header
for w in $WORLDS; do
  sim_lattice "$w" "$w-lattice"
  bench_main_table "" "$w, lattice" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt" "${PB[@]}"
done
echo
echo "(raw outputs and basin plots in $OUT)"
