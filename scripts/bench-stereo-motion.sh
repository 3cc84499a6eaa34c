#!/usr/bin/env bash
# Moon, Miura & Shirai's motion experiment (Fig. 10), Monte-Carlo: the
# simulated paper scene (worlds/moon-lab.ini), the robot drives 2 m towards
# the partition with drifting odometry (3 cm/m, 2 deg/m), localized by
# featloc-run four ways on the same logs:
#   odometry         estimator = odometry
#   stereo           EKF, odometry + vertical-line landmarks selected on-line
#   laser            EKF, odometry + the laser matcher (featloc::IcpMatcher)
#   laser + stereo   EKF, both
# Per seed: final position error and ATE (RMSE of the position error, no
# alignment: the map fixes the frame) against the simulator's exact ground
# truth; over the seeds: their means and the Monte-Carlo NEES of the final
# pose (mean over seeds, 3 dof) with its 95% band.
# Prints Markdown. Usage: scripts/bench-stereo-motion.sh [OUTDIR] [SEEDS]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-stereo-motion "$@"
SEEDS="${2:-10}"
CONFIG="$ROOT/configs/stereo-moon-lab.ini"
DRIFT=(--set Odometry:sigma_xy_per_m=0.03 --set Odometry:sigma_yaw_per_m_DEG=2)

# "final_error ate nees_final" of RUN against GT (TUM rows joined on time).
metrics() { # gt.txt poses_cov.txt
  awk 'FNR==NR { if ($1 !~ /^#/) { gx[$1]=$2; gy[$1]=$3; gyaw[$1]=atan2(2*$8*$7, 1-2*$7*$7) }; next }
       $1 ~ /^#/ { next }
       ($1 in gx) { dx=$2-gx[$1]; dy=$3-gy[$1]; dth=$4-gyaw[$1];
         while (dth > 3.14159265) dth -= 6.2831853; while (dth < -3.14159265) dth += 6.2831853;
         n++; s+=dx*dx+dy*dy; last=sqrt(dx*dx+dy*dy);
         # NEES of the last pose: e^T P^-1 e with P = [xx xy xth; xy yy yth; xth yth thth]
         a=$5; b=$6; c=$7; d=$8; e=$9; f=$10;
         det=a*(d*f-e*e)-b*(b*f-c*e)+c*(b*e-c*d);
         i11=(d*f-e*e)/det; i12=-(b*f-c*e)/det; i13=(b*e-c*d)/det;
         i22=(a*f-c*c)/det; i23=-(a*e-b*c)/det; i33=(a*d-b*b)/det;
         nees=dx*(i11*dx+i12*dy+i13*dth)+dy*(i12*dx+i22*dy+i23*dth)+dth*(i13*dx+i23*dy+i33*dth) }
       END { if (n == 0) { print "nan nan nan"; exit } printf "%.5f %.5f %.3f\n", last, sqrt(s/n), nees }' "$1" "$2"
}

declare -A SETS=(
  [odometry]="--set Pipeline:estimator=odometry --set StereoLandmarks:class="
  [stereo]=""
  [laser]="--set Ekf:use_scan_matcher=true --set StereoLandmarks:class="
  [laser+stereo]="--set Ekf:use_scan_matcher=true"
)
MODES=(odometry stereo laser laser+stereo)
machine_line
echo
echo "| seed | $(printf '%s final / ATE [mm] | ' "${MODES[@]}")"
echo "|---|$(printf -- '---|%.0s' "${MODES[@]}")"
declare -A SUMF SUMA SUMN
for seed in $(seq 1 "$SEEDS"); do
  dir="$OUT/seed$seed"
  mkdir -p "$dir"
  "$BIN/featloc-sim" "$ROOT/worlds/moon-lab.ini" --out "$dir/moon-lab" -q \
    --set Simulation:seed="$seed" "${DRIFT[@]}" > "$dir/sim.log"
  row="| $seed |"
  for mode in "${MODES[@]}"; do
    # shellcheck disable=SC2086
    "$BIN/featloc-run" "$CONFIG" "$dir/moon-lab.rawlog" --out "$dir/$mode" -q \
      --set Evaluation:ground_truth="$dir/moon-lab.gt.txt" ${SETS[$mode]} > "$dir/$mode.log" 2>&1
    read -r fin ate nees < <(metrics "$dir/moon-lab.gt.txt" "$dir/$mode/poses_cov.txt")
    SUMF[$mode]=$(awk -v a="${SUMF[$mode]:-0}" -v b="$fin" 'BEGIN{print a+b}')
    SUMA[$mode]=$(awk -v a="${SUMA[$mode]:-0}" -v b="$ate" 'BEGIN{print a+b}')
    SUMN[$mode]=$(awk -v a="${SUMN[$mode]:-0}" -v b="$nees" 'BEGIN{print a+b}')
    row="$row $(awk -v f="$fin" -v a="$ate" 'BEGIN{printf "%.1f / %.1f", f*1000, a*1000}') |"
  done
  echo "$row"
done
# 95% band of the mean of SEEDS chi-square(3) draws (Wilson-Hilferty).
band=$(awk -v n="$SEEDS" 'BEGIN { k=3*n; for (z=-1.96; z<=1.97; z+=3.92) { q=k*(1-2/(9*k)+z*sqrt(2/(9*k)))^3; printf "%.2f ", q/n } }')
echo
echo "| over $SEEDS seeds | $(printf '%s | ' "${MODES[@]}")"
echo "|---|$(printf -- '---|%.0s' "${MODES[@]}")"
row="| mean final error [mm] |"; for m in "${MODES[@]}"; do row="$row $(awk -v s="${SUMF[$m]}" -v n="$SEEDS" 'BEGIN{printf "%.1f", s/n*1000}') |"; done; echo "$row"
row="| mean ATE [mm] |"; for m in "${MODES[@]}"; do row="$row $(awk -v s="${SUMA[$m]}" -v n="$SEEDS" 'BEGIN{printf "%.1f", s/n*1000}') |"; done; echo "$row"
row="| Monte-Carlo NEES, final pose (95% band ${band% }) |"; for m in "${MODES[@]}"; do row="$row $(awk -v s="${SUMN[$m]}" -v n="$SEEDS" 'BEGIN{printf "%.2f", s/n}') |"; done; echo "$row"
