#!/usr/bin/env bash
# Reproduces "Range lattices" in doc/benchmarks.md (issue 15, fifteenth
# session): logs whose readings sit on multiples of a step (RangeLattice),
# and what the featloc matchers do with it, with MRPT's ICP in the same runs.
# "old": dequantize_ranges = false in every featloc matcher's section and
# CF-IDC's segment_gate_from_lattice = false (as before this session);
# "gate": CF-IDC with its segment gate widened to the step only; "new":
# config.ini (readings put back on their surfaces before matching, and the
# widened gate).
#  - Which logs have a lattice (featloc_bench_range_lattice): the bundled
#    log, the six Radish logs, featloc-sim's scenes as they are and with
#    Laser:range_step = 0.16 (MRPT's simulator's lattice, then the noise).
#  - Whole runs (featloc-run; matcher chain and EKF): ATE rmse [mm] / failed
#    matches on the bundled log (where the problem was found) and on the
#    held-out corridor, hall and room with the 0.16 m lattice, seeds 1-3.
#  - Pairs (featloc-bench, Borges & Aldon's +-0.3 m / 10 deg, every pair
#    counted): the office and lab (1 cm noise) with the lattice, on which
#    the detector's constants were set, then held out: the corridor, hall
#    and room with it (seed 1) and the bundled log; old, then new.
# The Radish logs with a lattice (acapulco, edmonton, fhw): bench-real-logs.sh.
# Usage: scripts/bench-range-lattice.sh [OUTDIR]   (about 25 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-range-lattice "$@"

HELD_OUT="corridor-people hall-people room-moving-objects"
for w in office lab; do sim_1cm "$w"; done
sim_calibration_lattices
for w in $HELD_OUT; do
  [ -f "$OUT/$w.rawlog" ] || "$BIN/featloc-sim" "$ROOT/worlds/$w.ini" --out "$OUT/$w" -q > /dev/null
  for seed in 1 2 3; do sim_lattice "$w" "$w-lattice-seed$seed" --seed "$seed"; done
done

machine_line
echo
echo "### Which logs have their ranges on a lattice"
echo
radish=()
[ -d "$LASER2D" ] && radish=("$LASER2D"/*-corrected.log.gz)
"$BIN/featloc_bench_range_lattice" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" "${radish[@]}" \
  "$OUT/office-1cm.rawlog" "$OUT/lab-1cm.rawlog" $(for w in $HELD_OUT; do echo "$OUT/$w.rawlog"; done) \
  "$OUT/office-1cm-lattice.rawlog" "$OUT/lab-1cm-lattice.rawlog" \
  $(for w in $HELD_OUT; do echo "$OUT/$w-lattice-seed1.rawlog"; done)

OLD=(--set ScanMatcher.PcmFeatureMatcher:dequantize_ranges=false --set ScanMatcher.IdcMatcher:dequantize_ranges=false
  --set ScanMatcher.CfIdcMatcher:dequantize_ranges=false --set ScanMatcher.CfIdcMatcher:segment_gate_from_lattice=false)
GATE=(--set ScanMatcher.PcmFeatureMatcher:dequantize_ranges=false --set ScanMatcher.IdcMatcher:dequantize_ranges=false
  --set ScanMatcher.CfIdcMatcher:dequantize_ranges=false)
RUNS="ICP:featloc::IcpMatcher:new PCM:featloc::PcmFeatureMatcher:old PCM:featloc::PcmFeatureMatcher:new"
RUNS="$RUNS IDC:featloc::IdcMatcher:old IDC:featloc::IdcMatcher:new CF-IDC:featloc::CfIdcMatcher:old"
RUNS="$RUNS CF-IDC:featloc::CfIdcMatcher:gate CF-IDC:featloc::CfIdcMatcher:new"
echo
echo "### Whole runs: ATE rmse [mm] / failed matches"
echo
echo "| log | estimator | ICP | PCM old | PCM new | IDC old | IDC new | CF-IDC old | CF-IDC gate | CF-IDC new |"
echo "|---|---|---|---|---|---|---|---|---|---|"
cases=("bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
for w in $HELD_OUT; do
  for seed in 1 2 3; do cases+=("$w-lattice-seed$seed:$OUT/$w-lattice-seed$seed.rawlog:$OUT/$w-lattice-seed$seed.gt.txt"); done
done
for est in matcher ekf; do
  for c in "${cases[@]}"; do
    IFS=: read -r name input gt <<< "$c"
    row="| $name | $est |"
    for r in $RUNS; do
      IFS=: read -r label cls way <<< "${r/featloc::/featloc__}"
      cls="${cls/featloc__/featloc::}"
      sets=(--set "Pipeline:estimator=$est" --set "ScanMatcher:class=$cls")
      [ "$way" = old ] && sets+=("${OLD[@]}")
      [ "$way" = gate ] && sets+=("${GATE[@]}")
      bench_featloc_run "$name-$est-$label-$way" "$input" "$gt" "${sets[@]}"
      row+=" $(jq -r '"\((.evaluation.ate_m.rmse // -0.001) * 1000 | round) / \(.counts.match_failures)"' "$OUT/$name-$est-$label-$way/summary.json") |"
    done
    echo "$row"
  done
done

M="ICP=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
COMMON="--perturb-xy 0.3 --perturb-yaw-deg 10 -q"
HEADER=--header
bench() { bench_main_table "" "$@"; }
pairs_old_new() { # name, rawlog, gt
  bench "$1 old" "$2" -g "$3" "${OLD[@]}"
  bench "$1 new" "$2" -g "$3"
}
echo
echo "### Pairs with the 0.16 m lattice (+-0.3 m / 10 deg, every pair counted): calibration"
echo
for w in office lab; do pairs_old_new "$w 1 cm lattice" "$OUT/$w-1cm-lattice.rawlog" "$OUT/$w-1cm-lattice.gt.txt"; done
echo
echo "### Held out"
echo
HEADER=--header
for w in $HELD_OUT; do pairs_old_new "$w lattice" "$OUT/$w-lattice-seed1.rawlog" "$OUT/$w-lattice-seed1.gt.txt"; done
pairs_old_new "bundled log" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" "$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
echo
echo "(raw outputs in $OUT)"
