#!/usr/bin/env bash
# Issue 10's figures: featloc's EKF on odometry + range-bearing landmarks
# against MRPT's own landmark EKF, in one run.
#  1. MRPT's kf-slam_demo.rawlog (mrpt-common): MRPT's kf-slam app with its
#     own config (EKF-SLAM_test_2d.ini, SAVE_LOG_FREQUENCY = 1) and
#     featloc-run --set Pipeline:estimator=ekf; ATE of both paths against
#     kf-slam_demo_ground_truth_robot_path.txt with featloc-eval (rows paired
#     in order; kf-slam's path starts at its initial pose, the origin, which
#     it does not write), landmark errors by identity as kf-slam computes
#     them, filter time per step (featloc-bench-landmarks, reading excluded).
#  2. Time per step against the number of landmarks in the state: featloc-sim
#     worlds of N = 100, 500, 2000 beacons (with identities) seen ~10 per
#     step along a lawnmower path, featloc's EKF and MRPT's
#     CRangeBearingKFSLAM2D on the same log.
#     MRPT stops after 120 s of filtering (at 2000 beacons it reaches about
#     1000 landmarks by then); its row says so.
# Usage: scripts/bench-landmarks.sh [OUTDIR]      (about 4 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init landmarks "$@"
DS=/usr/share/mrpt/datasets
GT_PATH="$DS/kf-slam_demo_ground_truth_robot_path.txt"
GT_LM="$DS/kf-slam_demo_ground_truth.txt"
MRPT_INI=/usr/share/mrpt/config_files/kf-slam/EKF-SLAM_test_2d.ini
machine_line

ate_mm() { # reference estimate
  "$BIN/featloc-eval" "$1" "$2" --json | jq -r '.ate_m.rmse * 1000 | . * 100 | round / 100'
}

echo
echo "## MRPT's kf-slam demo: featloc-run vs MRPT's kf-slam"
# MRPT's kf-slam app, as a user runs it, one pose file per step.
K="$OUT/kf-slam"
mkdir -p "$K"
sed -e 's/^SAVE_LOG_FREQUENCY.*/SAVE_LOG_FREQUENCY=1/' -e 's/^SHOW_3D_LIVE.*/SHOW_3D_LIVE = false/' \
    -e "s|^logOutput_dir.*|logOutput_dir=$K/LOG|" \
    -e "s|^ground_truth_file=.*|ground_truth_file=$GT_LM|" "$MRPT_INI" > "$K/kf.ini"
t0=$(date +%s.%N)
(cd "$K" && kf-slam kf.ini "$DS/kf-slam_demo.rawlog" > kf-slam.txt 2>&1)
t1=$(date +%s.%N)
{ echo "% x y z yaw pitch roll: kf-slam's initial pose (the origin), then robot_pose_*.txt"
  echo "0 0 0 0 0 0"
  for f in $(ls "$K"/LOG/robot_pose_*.txt | sort); do
    tr '\n' ' ' < "$f" | awk '{printf "%s %s 0 %s 0 0\n", $1, $2, $3}'
  done; } > "$K/kf-slam_path.txt"
mrpt_lm=$(sed -n 's/.*Mean Error: \([0-9.]*\) meters.*/\1/p' "$K/kf-slam.txt")
"$BIN/featloc-run" "$ROOT/config.ini" "$DS/kf-slam_demo.rawlog" -q --out "$OUT/featloc" \
  --set Pipeline:estimator=ekf --set "Evaluation:ground_truth=$GT_PATH" > "$OUT/featloc.txt"
echo "| method | poses | ATE rmse [mm] | landmark error mean [mm] (kf-slam's own printout for MRPT) | wall time of the app [s] |"
echo "|---|---|---|---|---|"
echo "| MRPT kf-slam (EKF-SLAM_test_2d.ini) | $(grep -c '^[0-9-]' "$K/kf-slam_path.txt") | $(ate_mm "$GT_PATH" "$K/kf-slam_path.txt") | $(awk -v e="$mrpt_lm" 'BEGIN{printf "%.2f", e*1000}') | $(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}') (writes 1000 log files) |"
echo "| featloc-run, estimator = ekf | $(jq .counts.steps "$OUT/featloc/summary.json") | $(ate_mm "$GT_PATH" "$OUT/featloc/poses_cov.txt") | see below | $(jq '.wall_time_s * 100 | round / 100' "$OUT/featloc/summary.json") |"
echo
echo "Filter alone, same log (featloc-bench-landmarks):"
echo
"$BIN/featloc-bench-landmarks" "$ROOT/config.ini" "$DS/kf-slam_demo.rawlog" \
  --landmarks-truth "$GT_LM" --header --name kf-slam_demo -o "$OUT/bench-demo"

echo
echo "## Time per step vs landmarks in the state (featloc-sim, ~10 observations per step)"
sed -e 's/^std_sensor_yaw_deg.*/std_sensor_yaw_deg = 1/' "$MRPT_INI" > "$OUT/mrpt-sim.ini"
first=--header
for N in 100 500 2000; do
  # A 10 m x 10 m room, beacons uniformly at random (fixed seed); range for
  # ~10 in view; lawnmower lanes 1.5 ranges apart so that every beacon is seen.
  R=$(awk -v n=$N 'BEGIN{printf "%.3f", sqrt(10*100/(3.14159265*n))}')
  # The beacons, also as a kf-slam ground-truth file (x y z - - - id).
  awk -v n=$N 'BEGIN{srand(42); for(i=0;i<n;i++) printf "%.3f %.3f 0 0 0 0 %d\n", 10*rand(), 10*rand(), i}' > "$OUT/beacons$N.truth.txt"
  PTS="[$(awk '{printf "%s%s %s", (NR>1?"; ":""), $1, $2}' "$OUT/beacons$N.truth.txt")]"
  WP=$(awk -v r="$R" 'BEGIN{d=1.5*r; y=r/2; k=0; printf "["; while (y < 10) {x1=(k%2)?9.8:0.2; x2=(k%2)?0.2:9.8; printf "%s%.3f %.3f; %.3f %.3f", (k?"; ":""), x1, y, x2, y; y+=d; k++} printf "]"}')
  cat > "$OUT/beacons$N.ini" <<EOF
[Simulation]
t0 = 1700001000
seed = 3
format = 1
[Laser]
preset = ibeo_ladar_2d30
rate = 4
[Odometry]
mode = model
model = gaussian
sigma_xy_min = 0.002
sigma_xy_per_m = 0.02
sigma_xy_per_deg = 0.0005
sigma_yaw_min_DEG = 0.05
sigma_yaw_per_m_DEG = 0.5
sigma_yaw_per_deg = 0.02
[Robot]
path = waypoints
waypoints = $WP
speed = 1
[Wall.outer]
polyline = [-0.5 -0.5; 10.5 -0.5; 10.5 10.5; -0.5 10.5]
closed = true
[Beacons]
points = $PTS
with_ids = true
occlusion = false
max_range = $R
range_noise = 0.03
bearing_noise_DEG = 1
EOF
  "$BIN/featloc-sim" "$OUT/beacons$N.ini" --out "$OUT/beacons$N" -q > /dev/null
  # Both filters start at the origin: the true beacons in the frame of the
  # robot's true first pose (first row of the TUM ground truth).
  read -r x0 y0 qz qw < <(awk '!/^#/{print $2, $3, $7, $8; exit}' "$OUT/beacons$N.gt.txt")
  awk -v x0="$x0" -v y0="$y0" -v qz="$qz" -v qw="$qw" 'BEGIN{th=2*atan2(qz,qw); c=cos(th); s=sin(th)}
    {dx=$1-x0; dy=$2-y0; printf "%.4f %.4f 0 0 0 0 %d\n", c*dx+s*dy, -s*dx+c*dy, $7}' \
    "$OUT/beacons$N.truth.txt" > "$OUT/beacons$N.truth-local.txt"
  "$BIN/featloc-bench-landmarks" "$ROOT/config.ini" "$OUT/beacons$N.rawlog" \
    --mrpt-config "$OUT/mrpt-sim.ini" --mrpt-max-seconds 120 --landmarks-truth "$OUT/beacons$N.truth-local.txt" \
    --name "$N beacons" $first -o "$OUT/bench-$N"
  first=
done
echo
echo "(results in $OUT)"
