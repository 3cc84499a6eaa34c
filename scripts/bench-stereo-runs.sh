#!/usr/bin/env bash
# Stereo landmarks on longer runs (issue 12, "a longer corridor run"):
# featloc-run on simulated logs whose stereo camera looks sideways at the
# walls (the paper's robot turns to face its planes), five ways on the same
# log:
#   odometry         estimator = odometry
#   stereo (paper)   EKF, odometry + the vertical-line landmarks alone
#                    (wall_observations = false)
#   stereo           EKF, odometry + landmarks + featloc's wall observations
#   laser            EKF, odometry + the laser matcher (MATCHER)
#   laser + stereo   EKF, odometry + laser + landmarks + wall observations
#   walls, laser + walls   the same without the landmarks
#                    (Ekf:stereo_landmarks_per_frame = 0)
# Scenes (the map given to the stereo is the world file itself):
#   worlds/stereo-corridor.ini, camera turned to the north wall, 4 m laser,
#     seeds 1-3: where the wall observations' checks were developed;
#   worlds/lab.ini with the camera on the robot's left: where the coverage
#     check (a table is not a wall) was found;
#   worlds/office.ini with the camera on the robot's left: held out (run
#     once before the coverage check, then only for this table).
# Errors against the simulator's exact ground truth, not aligned (the map
# fixes the frame; every run starts at the true pose): ATE RMSE and max,
# and the mean NEES of the poses (3 dof, consistent: 3).
# Prints Markdown. Usage: scripts/bench-stereo-runs.sh [OUTDIR] [MATCHER] [KEY=VALUE...]
# (the KEY=VALUEs go to the matcher's section, e.g. coarse_search=true).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-stereo-runs "$@"
matcher_args featloc::IcpMatcher "$@"
CONFIG="$ROOT/configs/stereo-moon-lab.ini"

# The laser worlds' surfaces the stereo renderer has no material for get
# the nearest look (as bench/StereoLandmarksBenchmark.cpp does), and a
# stereo camera on the robot's left, the paper's camera (moon-lab.ini).
stereo_world() { # world.ini out.ini
  sed -E -e 's/texture( *)= *(lab_wall|hall_wall)$/texture = paint/' \
    -e 's/texture( *)= *(bench|table|door)$/texture = wood/' \
    -e 's/texture( *)= *(chair|plastic|red)$/texture = metal/' \
    -e 's/texture( *)= *shelf$/texture = books/' "$1" > "$2"
  cat >> "$2" <<'EOF'

[StereoCamera]
width     = 640
height    = 480
fx        = 500
fy        = 500
cx        = 319.5
cy        = 239.5
baseline  = 0.12
pose      = [0.1 0 1.1 90 0 0]
rate      = 4
noise_sigma = 2.0
blur_sigma  = 0.5
gain_change = 0.02
EOF
}

# "x y yaw_deg" of the first ground-truth row (TUM).
first_pose() {
  awk '$1 !~ /^#/ { printf "%s %s %.6f", $2, $3, 2 * atan2($7, $8) * 180 / 3.14159265358979; exit }' "$1"
}

declare -A SETS=(
  [odometry]="--set Pipeline:estimator=odometry --set StereoLandmarks:class="
  [stereo-paper]="--set StereoLandmarks.StableVerticalLandmarks:wall_observations=false"
  [stereo]=""
  [laser]="--set Ekf:use_scan_matcher=true --set StereoLandmarks:class="
  [laser+stereo]="--set Ekf:use_scan_matcher=true"
  [walls]="--set Ekf:stereo_landmarks_per_frame=0"
  [laser+walls]="--set Ekf:use_scan_matcher=true --set Ekf:stereo_landmarks_per_frame=0"
)
MODES=(odometry stereo-paper stereo laser laser+stereo walls laser+walls)

run_scene() { # label dir world.ini(map) log-prefix
  local label="$1" dir="$2" map="$3" log="$4" row mode pose
  pose=$(first_pose "$log.gt.txt")
  row="| $label |"
  for mode in "${MODES[@]}"; do
    # shellcheck disable=SC2086
    "$BIN/featloc-run" "$CONFIG" "$log.rawlog" --out "$dir/$mode" -q \
      --set StereoLandmarks.StableVerticalLandmarks:map="$map" --set "Pipeline:initial_pose=[$pose]" \
      --set ScanMatcher:class="$MATCHER" "${MATCHER_SETS[@]}" --set Output:stereo_debug_every=0 \
      --set Evaluation:ground_truth="$log.gt.txt" --set Evaluation:align=false ${SETS[$mode]} > "$dir/$mode.log" 2>&1
    row="$row $(jq -r '[.evaluation.ate_m.rmse * 1000, .evaluation.ate_m.max * 1000, .evaluation.nees.mean] | "\(.[0] | . * 10 | round / 10) / \(.[1] | round) / \(.[2] | . * 10 | round / 10)"' "$dir/$mode/summary.json") |"
  done
  echo "$row"
  # Wall observations of the stereo run: fitted, used.
  WALLS="$WALLS| $label | $(jq -r '.stereo_landmarks | "\(.wall_observations) | \(.wall_observations_used) | \(.wall_observations_failed_gate) | \(.observations_used) | \(.time_per_pair_s.median * 1000 | . * 10 | round / 10)"' "$dir/stereo/summary.json") |
"
}

machine_line
echo
echo "Laser matcher: $MATCHER ${*:3}. Each cell: ATE RMSE / max [mm] / mean NEES."
echo
echo "| scene | $(printf '%s | ' "${MODES[@]}")"
echo "|---|$(printf -- '---|%.0s' "${MODES[@]}")"
WALLS=""
for seed in 1 2 3; do
  dir="$OUT/corridor-seed$seed"
  mkdir -p "$dir"
  "$BIN/featloc-sim" "$ROOT/worlds/stereo-corridor.ini" --out "$dir/c" -q --set Simulation:seed="$seed" \
    --set "StereoCamera:pose=[0.1 0 1.1 90 0 0]" --set Laser:max_range=4 > "$dir/sim.log"
  run_scene "stereo-corridor, seed $seed (development)" "$dir" "$ROOT/worlds/stereo-corridor.ini" "$dir/c"
done
for scene in lab office; do
  dir="$OUT/$scene"
  mkdir -p "$dir"
  stereo_world "$ROOT/worlds/$scene.ini" "$dir/$scene-stereo.ini"
  "$BIN/featloc-sim" "$dir/$scene-stereo.ini" --out "$dir/s" -q > "$dir/sim.log"
  if [ "$scene" = lab ]; then label="lab, camera left (coverage check found here)"; else label="office, camera left (held out)"; fi
  run_scene "$label" "$dir" "$dir/$scene-stereo.ini" "$dir/s"
done
echo
echo "Wall observations in the stereo runs: walls fitted and passing the checks, used by the EKF, failed their gate; landmark observations used; extractor median ms per pair."
echo
echo "| scene | walls observed | used | failed gate | landmark observations used | ms per pair |"
echo "|---|---|---|---|---|---|"
printf "%s" "$WALLS"
