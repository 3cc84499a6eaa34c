#!/usr/bin/env bash
# Reproduces "Stable vertical landmarks on real pairs" in doc/benchmarks.md
# (issue 12, item 4): Moon, Miura & Shirai's segment stage (2.1-2.2) on the
# real pairs of ../shared/data/stereo, without a map.
#  1. RTAB-Map hall: segments found, matched by DP, supported by the SAD
#     disparity; pictures of both pairs.
#  2. EuRoC V1_01: vertical lines of pairs 0/1 and 2/3 (same place, two
#     Vicon-measured poses) placed in the world and compared within their
#     sigma, under the Vicon relative pose and under the relative pose the
#     left images give (essential matrix, Vicon's length of travel).
# Prints Markdown; the pictures go to OUTDIR and doc/images/.
# Usage: scripts/bench-stereo-real.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-stereo-real "$@"

DATA="$ROOT/../shared/data/stereo"
"$BIN/featloc-stereo-import" --rectify "$DATA/euroc-v1-pairs" \
  --times "$ROOT/rawlogs/stereo/euroc-v1-pairs.times.csv" --out "$OUT/euroc-rect.rawlog" > "$OUT/import.txt"
"$BIN/featloc-stereo-import" "$DATA/rtabmap-indoor-rect" --out "$OUT/hall.rawlog" >> "$OUT/import.txt"

machine_line
echo
"$BIN/featloc_bench_stereo_real" "$OUT/euroc-rect.rawlog" "$ROOT/rawlogs/stereo/euroc-v1-pairs.body.gt.tum" \
  "$OUT/hall.rawlog" "$OUT" | tee "$OUT/stereo-real.md"
cp "$OUT/rtabmap-pair0.png" "$ROOT/doc/images/stereo-real-hall.png"
cp "$OUT/euroc-pair2.png" "$ROOT/doc/images/stereo-real-euroc-pair2.png"
