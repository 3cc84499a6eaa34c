#!/usr/bin/env bash
# Reproduces the IDC / CF-IDC figures of doc/benchmarks.md. Five matchers,
# side by side in one featloc-bench run per data set: Lu & Milios' IDC and
# Nunez et al.'s CF-IDC as published, both with featloc's additions
# (config.ini), and featloc::IcpMatcher (MRPT's ICP).
#  1. The paper's protocol (CF-IDC section IV.B): 1000 pairs of scans taken
#     by a robot standing still in the simulated hall while people walk
#     (worlds/hall-people.ini, SICK LMS200, 1 cm noise); the second scan of
#     each pair is moved by a random motion of mean 1 m and 15 deg (sd 50 mm
#     and 5 deg), every matcher starts from the mean. Control: the same hall
#     without its people.
#  2. Consecutive scans of whole logs, each matcher starting from the true
#     motion plus Gaussian errors of 50 mm and 5 deg: the simulated office,
#     lab and corridor-with-people (exact ground truth), the six real Radish
#     logs (reference poses good to 2-3 cm) if ../shared/data/laser2d (or
#     $FEATLOC_LASER2D) is there, and the Malaga 2006 log against
#     IcpMatcher's own result (consistency only).
#  3. Whole trajectories: featloc-run with each matcher on the simulated
#     corridor with people, office and lab (ATE against exact ground truth).
# Usage: scripts/bench-cfidc.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc "$@"

# As published, as far as switches go (doc/cfidc-matcher.md).
PAPER_IDC="coarse_search=false;dequantize_ranges=false;final_phase=idc;breakpoint_at_missing_returns=false;breakpoint_sigma_r_from_scan=false;guess_gate_chi2=0;max_translation_sigma=1e9;max_rotation_sigma_DEG=1e9"
PAPER_CFIDC="$PAPER_IDC;fallback_class=;pairing_gate=false;pairing_fallback=false;segment_gate=0;curvature_sampling=normalized"
MATCHERS="IDC as published=featloc::IdcMatcher{$PAPER_IDC},CF-IDC as published=featloc::CfIdcMatcher{$PAPER_CFIDC},IDC + featloc=featloc::IdcMatcher,CF-IDC + featloc=featloc::CfIdcMatcher,IcpMatcher=featloc::IcpMatcher"
ERRORS="--perturbation gaussian --perturb-xy 0.05 --perturb-yaw-deg 5 --seed 1"
HEADER=--header

bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" $ERRORS -m "$MATCHERS" $HEADER -q \
    --name "$name" "$@" -j "$OUT/$name.json"
  HEADER=
}

machine_line
echo
echo "### 1. The paper's protocol: scans from one place, people walking, a random motion applied"
echo
"$BIN/featloc-sim" "$ROOT/worlds/hall-people.ini" --out "$OUT/hall-people" -q > /dev/null
awk '/^\[/{skip = ($0 ~ /^\[Agent\./)} !skip' "$ROOT/worlds/hall-people.ini" > "$OUT/hall-empty.ini"
"$BIN/featloc-sim" "$OUT/hall-empty.ini" --out "$OUT/hall-empty" -q > /dev/null
bench "hall, people walking" "$OUT/hall-people.rawlog" -g "$OUT/hall-people.gt.txt" \
  --apply-motion 0.7071,0.7071,15
bench "hall, no people (control)" "$OUT/hall-empty.rawlog" -g "$OUT/hall-empty.gt.txt" \
  --apply-motion 0.7071,0.7071,15

echo
echo "### 2. Consecutive scans of whole logs, initial errors 50 mm / 5 deg"
echo
HEADER=--header
for scene in office lab; do
  sim_1cm "$scene"
  bench "sim $scene (1 cm)" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt"
done
"$BIN/featloc-sim" "$ROOT/worlds/corridor-people.ini" --out "$OUT/corridor-people" -q > /dev/null
bench "sim corridor-people" "$OUT/corridor-people.rawlog" -g "$OUT/corridor-people.gt.txt"
if [ -d "$LASER2D" ]; then
  for f in "$LASER2D"/*-corrected.log.gz; do
    bench "$(basename "$f" -corrected.log.gz)" "$f"
  done
else
  echo "(no real logs: $LASER2D not found)"
fi
bench "Malaga 2006 (vs ICP)" "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog" \
  --reference-matcher featloc::IcpMatcher

echo
echo "### 3. Whole trajectories (featloc-run, keyframes as in config.ini)"
echo
echo "| scene | matcher | ATE rmse [m] | ATE rot rmse [deg] | RPE trans mean [m] | failed matches | time/match mean [ms] |"
echo "|---|---|---|---|---|---|---|"
for scene in corridor-people office-1cm lab-1cm; do
  for cls in IcpMatcher IdcMatcher CfIdcMatcher; do
    "$BIN/featloc-run" "$ROOT/config.ini" "$OUT/$scene.rawlog" --out "$OUT/run-$scene-$cls" -q \
      --set ScanMatcher:class=featloc::$cls --set Evaluation:ground_truth="$OUT/$scene.gt.txt" \
      > "$OUT/run-$scene-$cls.log"
    j="$OUT/run-$scene-$cls/summary.json"
    echo "| $scene | $cls | $(fmt "$(jq -r '.evaluation.ate_m.rmse' "$j")") | $(fmt "$(jq -r '.evaluation.ate_rotation.rmse' "$j")" 2) | $(fmt "$(jq -r '.evaluation.rpe_translation_m.mean' "$j")" 4) | $(jq -r '.counts.match_failures' "$j") of $(jq -r '.counts.matches' "$j") | $(fmt "$(jq -r '.match_time_s.mean * 1000' "$j")" 2) |"
  done
done
echo
echo "(raw outputs in $OUT)"
