#!/usr/bin/env bash
# featloc-viewer's responsiveness (issue 14): time to read a results folder
# and open it (map, match and plot pages built), and the time per redraw of
# the map page at the whole-map view, on
#  - the whole MRPT simul.rawlog (1733 scans; featloc-run config.ini, EKF),
#  - a 10,000-scan log: featloc-sim's office world, 6 laps at 10 Hz.
# The window runs under Xvfb, so OpenGL is Mesa's software renderer
# (llvmpipe): a machine with a GPU draws faster. Median of 3 runs each.
# Usage: scripts/bench-viewer.sh [OUTDIR]      (about 2 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init viewer "$@"
SIMUL=/usr/share/mrpt/datasets/graphslam-engine-demos/action_observations_map/simul.rawlog
machine_line

"$BIN/featloc-run" "$ROOT/config.ini" "$SIMUL" -q --out "$OUT/simul" \
  --set Pipeline:estimator=ekf --set Evaluation:ground_truth= >/dev/null
"$BIN/featloc-sim" "$ROOT/worlds/office.ini" -q --out "$OUT/office10k" \
  --set Robot:laps=6 --set Laser:rate=10 >/dev/null
"$BIN/featloc-run" "$ROOT/config.ini" "$OUT/office10k.rawlog" -q --out "$OUT/office10k-res" \
  --set Pipeline:estimator=ekf --set "Evaluation:ground_truth=$OUT/office10k.gt.txt" >/dev/null

median() { sort -g | sed -n 2p; }
echo
echo "| results | steps | scans | read and open [s] | map redraw [ms] | frames per second |"
echo "|---|---|---|---|---|---|"
for r in simul office10k-res; do
  loads=(); draws=()
  for i in 1 2 3; do
    out=$(xvfb-run -a -s "-screen 0 1600x1200x24" "$BIN/featloc-viewer" "$OUT/$r" --measure-redraws 100 2>/dev/null)
    loads+=("$(sed -n 's/.* in \([0-9.e-]*\) s (.*/\1/p' <<<"$out")")
    draws+=("$(sed -n 's/.*map redraw \([0-9.e-]*\) ms.*/\1/p' <<<"$out")")
    counts=$(sed -n 's/.* s (\([0-9]*\) steps, \([0-9]*\) scans).*/\1 | \2/p' <<<"$out")
  done
  load=$(printf '%s\n' "${loads[@]}" | median)
  draw=$(printf '%s\n' "${draws[@]}" | median)
  echo "| $r | $counts | $(fmt "$load" 2) | $(fmt "$draw" 1) | $(fmt "$(echo "1000 / $draw" | bc -l)" 0) |"
done
