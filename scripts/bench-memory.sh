#!/usr/bin/env bash
# Issue 16, bounded resources: featloc-run's peak resident memory (max RSS)
# against the length of the log, on featloc-sim's office world driven 1, 5
# and 25 laps with a Hokuyo UTM-30LX (1081 beams) at 40 Hz, uncompressed:
# 42 MB, 212 MB and 1.06 GB of rawlog.
#  - "streaming core": the odometry estimator with no output that keeps
#    the whole run (no map.3Dscene, map.simplemap or evaluation): what
#    reading the log and writing the row outputs and estimated.rawlog take;
#  - "all outputs": config.ini's outputs and the evaluation against the
#    ground truth, odometry estimator;
#  - EKF + ICP (config.ini's matcher), all outputs, on 1 and 5 laps (25
#    laps take 35 minutes on 2 cores).
# Usage: scripts/bench-memory.sh [OUTDIR]      (about 15 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init memory "$@"
machine_line

for n in 1 5 25; do
  [ -f "$OUT/office$n.rawlog" ] || "$BIN/featloc-sim" "$ROOT/worlds/office.ini" -q -o "$OUT/office$n" \
    --set Robot:laps=$n --set Laser:preset=hokuyo_utm30lx --set Laser:rate=40 \
    --set Simulation:compress=false >/dev/null
done

# Runs featloc-run with the given arguments; prints "seconds max_rss_MB".
measure() {
  python3 - "$BIN/featloc-run" "$@" <<'PY'
import resource, subprocess, sys, time
t = time.time()
r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
if r.returncode != 0:
    sys.exit("featloc-run failed: " + r.stderr)
print("%.1f %.0f" % (time.time() - t, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024))
PY
}

echo
echo "| log | rawlog size | scans | run | time [s] | max RSS [MB] |"
echo "|---|---|---|---|---|---|"
row() { # laps, label, args...
  local n="$1" label="$2"; shift 2
  local log="$OUT/office$n.rawlog"
  read -r secs mb < <(measure "$ROOT/config.ini" "$log" -q --out "$OUT/res-$n-${label// /_}" "$@")
  local scans; scans=$(grep -vc '^#' "$OUT/office$n.gt.txt")
  echo "| office, $n laps | $(du -mL "$log" | cut -f1) MB | $scans | $label | $secs | $mb |"
}
for n in 1 5 25; do
  row $n "streaming core" --set Pipeline:estimator=odometry --set Evaluation:ground_truth= \
    --set Output:write_scene=false --set Output:write_simplemap=false
  row $n "all outputs" --set Pipeline:estimator=odometry --set "Evaluation:ground_truth=$OUT/office$n.gt.txt"
done
for n in 1 5; do
  row $n "EKF + ICP, all outputs" --set Pipeline:estimator=ekf --set "Evaluation:ground_truth=$OUT/office$n.gt.txt"
done
