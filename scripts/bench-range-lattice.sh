#!/usr/bin/env bash
# Reproduces "Range lattices" in doc/benchmarks.md (issue 15, fifteenth
# session): logs whose ranges sit on multiples of a step (RangeLattice), and
# CF-IDC's segment gate widened to that step (segment_gate_from_lattice,
# config.ini: true) against the fixed 5 cm gate (false), with MRPT's ICP,
# PCM and IDC in the same runs.
#  - Which logs have a lattice (featloc_bench_range_lattice): the bundled
#    log, the six Radish logs, featloc-sim's scenes as they are and with
#    Laser:range_step = 0.16 (MRPT's simulator's lattice, then the noise).
#  - Whole runs (featloc-run; matcher chain and EKF): ATE rmse [mm] / failed
#    matches on the bundled log (where the problem was found) and on the
#    held-out corridor, hall and room with the 0.16 m lattice, seeds 1-3.
#  - Pairs (featloc-bench, Borges & Aldon's +-0.3 m / 10 deg, every pair
#    counted) on the office and lab (1 cm) and the corridor, hall and room
#    with the lattice (seed 1), and the two CF-IDCs paired.
# Usage: scripts/bench-range-lattice.sh [OUTDIR]   (about 15 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-range-lattice "$@"

HELD_OUT="corridor-people hall-people room-moving-objects"
lattice_log() { # world, seed: $OUT/WORLD-lattice-seedSEED.rawlog (+ .gt.txt)
  [ -f "$OUT/$1-lattice-seed$2.rawlog" ] ||
    "$BIN/featloc-sim" "$ROOT/worlds/$1.ini" --out "$OUT/$1-lattice-seed$2" --seed "$2" -q \
      --set Laser:range_step=0.16 > /dev/null
}
for w in office lab; do
  sim_1cm "$w"
  [ -f "$OUT/$w-1cm-lattice.rawlog" ] ||
    "$BIN/featloc-sim" "$ROOT/worlds/$w.ini" --out "$OUT/$w-1cm-lattice" -q \
      --set Laser:range_noise=0.01 --set Laser:range_step=0.16 > /dev/null
done
for w in $HELD_OUT; do
  [ -f "$OUT/$w.rawlog" ] || "$BIN/featloc-sim" "$ROOT/worlds/$w.ini" --out "$OUT/$w" -q > /dev/null
  for seed in 1 2 3; do lattice_log "$w" "$seed"; done
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

MATCHERS="ICP:featloc::IcpMatcher IDC:featloc::IdcMatcher CF-IDC-fixed:featloc::CfIdcMatcher CF-IDC:featloc::CfIdcMatcher"
echo
echo "### Whole runs: ATE rmse [mm] / failed matches (CF-IDC fixed: segment_gate_from_lattice = false)"
echo
echo "| log | estimator | ICP | IDC | CF-IDC fixed gate | CF-IDC (config.ini) |"
echo "|---|---|---|---|---|---|"
cases=("bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
for w in $HELD_OUT; do
  for seed in 1 2 3; do cases+=("$w-lattice-seed$seed:$OUT/$w-lattice-seed$seed.rawlog:$OUT/$w-lattice-seed$seed.gt.txt"); done
done
for est in matcher ekf; do
  for c in "${cases[@]}"; do
    IFS=: read -r name input gt <<< "$c"
    row="| $name | $est |"
    for m in $MATCHERS; do
      label="${m%%:*}" cls="${m#*:}"
      sets=(--set "Pipeline:estimator=$est" --set "ScanMatcher:class=$cls")
      [ "$label" = CF-IDC-fixed ] && sets+=(--set "ScanMatcher.CfIdcMatcher:segment_gate_from_lattice=false")
      bench_featloc_run "$name-$est-$label" "$input" "$gt" "${sets[@]}"
      row+=" $(jq -r '"\((.evaluation.ate_m.rmse // -0.001) * 1000 | round) / \(.counts.match_failures)"' "$OUT/$name-$est-$label/summary.json") |"
    done
    echo "$row"
  done
done

M="ICP=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC fixed=featloc::CfIdcMatcher{segment_gate_from_lattice=false},CF-IDC=featloc::CfIdcMatcher"
COMMON="--perturb-xy 0.3 --perturb-yaw-deg 10 -q"
HEADER=--header
bench() { bench_main_table "" "$@"; }
echo
echo "### Pairs with the 0.16 m lattice (+-0.3 m / 10 deg, every pair counted)"
echo
bench "office 1 cm lattice" "$OUT/office-1cm-lattice.rawlog" -g "$OUT/office-1cm-lattice.gt.txt"
bench "lab 1 cm lattice" "$OUT/lab-1cm-lattice.rawlog" -g "$OUT/lab-1cm-lattice.gt.txt"
for w in $HELD_OUT; do
  bench "$w lattice" "$OUT/$w-lattice-seed1.rawlog" -g "$OUT/$w-lattice-seed1.gt.txt"
done
echo
echo "### Pairs: CF-IDC (config.ini) paired with CF-IDC fixed gate (+-0.3 m / 10 deg)"
echo
echo "| data | seed | matcher | \\|t\\| err mean difference, 95% interval [mm] | grossly wrong: only this / only the other, McNemar p |"
echo "|---|---|---|---|---|"
for w in office-1cm lab-1cm; do
  "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt" \
    -m "CF-IDC fixed=featloc::CfIdcMatcher{segment_gate_from_lattice=false},CF-IDC=featloc::CfIdcMatcher" \
    --paired-with "CF-IDC fixed" $COMMON --header --name "$w lattice" > "$OUT/paired-$w.txt"
  paired_rows "1" "$OUT/paired-$w.txt"
done
for w in $HELD_OUT; do
  "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/$w-lattice-seed1.rawlog" -g "$OUT/$w-lattice-seed1.gt.txt" \
    -m "CF-IDC fixed=featloc::CfIdcMatcher{segment_gate_from_lattice=false},CF-IDC=featloc::CfIdcMatcher" \
    --paired-with "CF-IDC fixed" $COMMON --header --name "$w lattice" > "$OUT/paired-$w.txt"
  paired_rows "1" "$OUT/paired-$w.txt"
done
echo
echo "(raw outputs in $OUT)"
