#!/usr/bin/env bash
# Reproduces the simulator figures of doc/benchmarks.md:
#  1. featloc-sim speed (Google Benchmark): ray casting one 1081-beam scan in
#     a 200-segment world, and a whole 1000-scan simulation written to disk.
#  2. The three shipped scenes, regenerated here (and compared byte for byte
#     with rawlogs/sim/), run through featloc-run in odometry and matcher
#     (IcpMatcher, config.ini) modes against their exact ground truth.
# Prints Markdown. Usage: scripts/bench-sim.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-sim "$@"

machine_line
echo
echo "### featloc-sim speed (1081 beams, 200 segments)"
echo
"$BIN/featloc_bench_sim" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json > "$OUT/bench-sim.json" 2> "$OUT/bench-sim.err"
cast=$(jq -r '.benchmarks[] | select(.name=="BM_RayCast1081Beams200Segments_median") | .real_time' "$OUT/bench-sim.json")
simu=$(jq -r '.benchmarks[] | select(.name=="BM_Simulate1000Scans_median") | .real_time' "$OUT/bench-sim.json")
echo "| what | median of 5 | per 1000 scans |"
echo "|---|---|---|"
echo "| ray casting one scan (RayCaster::cast) | $(fmt "$cast" 1) us | $(fmt "$cast" 1) ms |"
echo "| whole simulation of 1000 scans (path, casting, noise, odometry, gzip rawlog + ground truth) | $(fmt "$simu" 0) ms | $(fmt "$simu" 0) ms |"
echo
echo "### Shipped scenes: dead reckoning and ICP baseline against exact ground truth"
echo
echo "| scene | scans | laser | path [m] | same bytes as rawlogs/sim | estimator | ATE rmse [m] | ATE rot rmse [deg] | RPE trans mean [m] | RPE rot mean [deg] | time/match mean [ms] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for scene in office lab corridor-people; do
  "$BIN/featloc-sim" "$ROOT/worlds/$scene.ini" --out "$OUT/$scene" -q > "$OUT/$scene.sim.log"
  same=no
  cmp -s "$OUT/$scene.rawlog" "$ROOT/rawlogs/sim/$scene.rawlog" && cmp -s "$OUT/$scene.gt.txt" "$ROOT/rawlogs/sim/$scene.gt.txt" && same=yes
  scans=$(grep -vc '^#' "$OUT/$scene.gt.txt")
  laser=$(sed -n 's/.*laser \([a-z0-9_]*\),.*/\1/p' "$OUT/$scene.sim.log")
  path=$(sed -n 's/.*robot: \([0-9.]*\) m.*/\1/p' "$OUT/$scene.sim.log")
  for est in odometry matcher; do
    "$BIN/featloc-run" "$ROOT/config.ini" "$OUT/$scene.rawlog" --out "$OUT/$scene-$est" -q \
      --set Pipeline:estimator=$est --set Evaluation:ground_truth="$OUT/$scene.gt.txt" > "$OUT/$scene-$est.log"
    j="$OUT/$scene-$est/summary.json"
    t=$(jq -r '.match_time_s.mean * 1000' "$j")
    [ "$est" = odometry ] && t="-" || t=$(fmt "$t" 2)
    echo "| $scene | $scans | $laser | $path | $same | $est | $(fmt "$(jq -r '.evaluation.ate_m.rmse' "$j")") | $(fmt "$(jq -r '.evaluation.ate_rotation.rmse' "$j")" 2) | $(fmt "$(jq -r '.evaluation.rpe_translation_m.mean' "$j")" 4) | $(fmt "$(jq -r '.evaluation.rpe_rotation.mean' "$j")" 3) | $t |"
  done
done
# Control: the same corridor without its people ([Agent.*] sections removed).
awk '/^\[/{skip = ($0 ~ /^\[Agent\./)} !skip' "$ROOT/worlds/corridor-people.ini" > "$OUT/corridor-empty.ini"
"$BIN/featloc-sim" "$OUT/corridor-empty.ini" --out "$OUT/corridor-empty" -q > /dev/null
"$BIN/featloc-run" "$ROOT/config.ini" "$OUT/corridor-empty.rawlog" --out "$OUT/corridor-empty-matcher" -q \
  --set Evaluation:ground_truth="$OUT/corridor-empty.gt.txt" > /dev/null
echo
echo "Control: corridor-people without its people, matcher: ATE rmse $(fmt "$(jq -r '.evaluation.ate_m.rmse' "$OUT/corridor-empty-matcher/summary.json")") m."
echo
echo "(raw outputs in $OUT)"
