#!/usr/bin/env bash
# Reproduces the stereo camera figures of doc/benchmarks.md (issue 11):
#  1. render speed of one 640x480 stereo pair on one core (both views,
#     anti-aliasing, blur, gain, noise; no file writing), Google Benchmark,
#     in the paper's lab scene (worlds/moon-lab.ini);
#  2. geometry: OpenCV StereoBM (block 15, disp12MaxDiff 1) vs the exact
#     disparity, ground-truth edges vs the rendered intensity edges, and the
#     importer's rectification of the real EuRoC pairs (ORB |dy|): the
#     figures the StereoCamera / StereoImport tests print.
# Prints Markdown. Usage: scripts/bench-stereo.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-stereo "$@"

machine_line
echo
echo "### Stereo render speed (640x480 pair, one core)"
echo
"$BIN/featloc_bench_stereo" --benchmark_filter=Moon --benchmark_repetitions=10 \
  --benchmark_min_time=1 --benchmark_format=json > "$OUT/bench-stereo.json" 2> "$OUT/bench-stereo.err"
med=$(jq -r '.benchmarks[] | select(.name|endswith("_median")) | .real_time' "$OUT/bench-stereo.json")
mean=$(jq -r '.benchmarks[] | select(.name|endswith("_mean")) | .real_time' "$OUT/bench-stereo.json")
min=$(jq -r '[.benchmarks[] | select(.run_type=="iteration") | .real_time] | min' "$OUT/bench-stereo.json")
max=$(jq -r '[.benchmarks[] | select(.run_type=="iteration") | .real_time] | max' "$OUT/bench-stereo.json")
echo "| scene | median of 10 runs | mean | fastest run | slowest run |"
echo "|---|---|---|---|---|"
echo "| moon-lab, robot at the origin | $(fmt "$med" 2) ms | $(fmt "$mean" 2) ms | $(fmt "$min" 2) ms | $(fmt "$max" 2) ms |"
echo
echo "### Geometry and rectification"
echo
"$BIN/featloc_tests" --gtest_filter='StereoCamera.BlockMatcher*:StereoCamera.GroundTruthEdges*:StereoImport.*' \
  > "$OUT/stereo-geometry.txt" 2>&1 || { cat "$OUT/stereo-geometry.txt"; exit 1; }
grep -E '^\[          \] ' "$OUT/stereo-geometry.txt" | sed -E 's/^\[          \] /- /'
echo
echo "### Stable vertical landmarks (Moon, Miura & Shirai; issue 12)"
echo
"$BIN/featloc_bench_stereo_landmarks" "$ROOT" 20 | tee "$OUT/stereo-landmarks.md"
