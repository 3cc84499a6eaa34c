#!/usr/bin/env bash
# Reproduces the foundation figures of doc/benchmarks.md:
#  1. MRPT's simulated log (simul.rawlog, exact ground truth): ATE/RPE and time
#     per match of featloc-run with IcpMatcher (keyframes as in config.ini, and
#     scan-to-previous-scan) against dead reckoning.
#  2. The real Malaga 2006 log: featloc-run (IcpMatcher) against MRPT's own
#     icp-slam, run here in the same session: wall time, and how far apart
#     the two trajectories are (no ground truth exists for this log).
# Prints Markdown tables. Usage: scripts/bench-foundation.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench "$@"
DATA=/usr/share/mrpt/datasets
SIMUL="$DATA/graphslam-engine-demos/action_observations_map/simul.rawlog"
MALAGA="$DATA/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"

run() { # name, rawlog, extra args...
  local name="$1" rawlog="$2"; shift 2
  "$BIN/featloc-run" "$ROOT/config.ini" "$rawlog" --out "$OUT/$name" -q "$@" > "$OUT/$name.log"
}
field() { jq -r "$2" "$OUT/$1/summary.json"; }

machine_line
echo
echo "### simul.rawlog (MRPT, 1733 scans, exact ground truth)"
echo
echo "| estimator | reference scan | ATE rmse [m] | RPE trans mean [m] | RPE rot mean [deg] | failed matches | time/match mean [ms] | p95 [ms] | run wall time [s] |"
echo "|---|---|---|---|---|---|---|---|---|"
GT="--set Evaluation:ground_truth=$SIMUL.GT.txt"
run simul-odometry "$SIMUL" $GT --set Pipeline:estimator=odometry
run simul-icp-keyframes "$SIMUL" $GT
run simul-icp-every-scan "$SIMUL" $GT --set Pipeline:keyframe_distance=0 --set Pipeline:keyframe_angle_DEG=0
for r in "simul-odometry|odometry|-" "simul-icp-keyframes|matcher (IcpMatcher)|1 m / 20 deg keyframes" "simul-icp-every-scan|matcher (IcpMatcher)|previous scan"; do
  IFS='|' read -r name est ref <<< "$r"
  matches=$(field "$name" '.counts.matches')
  if [ "$matches" = "0" ]; then fails="-"; tm="-"; tp="-"; else
    fails="$(field "$name" '.counts.match_failures')/$matches"
    tm=$(fmt "$(field "$name" '.match_time_s.mean * 1000')" 2)
    tp=$(fmt "$(field "$name" '.match_time_s.p95 * 1000')" 2); fi
  echo "| $est | $ref | $(fmt "$(field "$name" '.evaluation.ate_m.rmse')") | $(fmt "$(field "$name" '.evaluation.rpe_translation_m.mean')" 4) | $(fmt "$(field "$name" '.evaluation.rpe_rotation.mean')") | $fails | $tm | $tp | $(fmt "$(field "$name" '.wall_time_s')" 2) |"
done

echo
echo "### Malaga 2006 (real SICK log, 225 scans, no ground truth): featloc-run vs MRPT icp-slam"
echo
mkdir -p "$OUT/icp-slam"
sed 's/^SHOW_PROGRESS_3D_REAL_TIME=1/SHOW_PROGRESS_3D_REAL_TIME=0/' \
  /usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini > "$OUT/icp-slam/icp.ini"
t0=$(date +%s.%N)
(cd "$OUT/icp-slam" && icp-slam icp.ini "$MALAGA" < /dev/null > icp-slam.log 2>&1)
t1=$(date +%s.%N)
run malaga-icp "$MALAGA"
# icp-slam writes one pose per action/observation pair: its row k is our scan k+1.
grep -v '^#' "$OUT/malaga-icp/trajectory.tum" | tail -n +2 | paste -d' ' - "$OUT/icp-slam/LOG_ICP-SLAM/log_estimated_path.txt" \
  | awk '{d=sqrt(($2-$10)^2+($3-$11)^2); s+=d; if(d>m)m=d; n++} END {printf "%.3f %.3f %d\n", s/n, m, n}' > "$OUT/malaga-deviation.txt"
read -r devMean devMax devN < "$OUT/malaga-deviation.txt"
echo "| program | what it does | wall time [s] | time/match mean [ms] |"
echo "|---|---|---|---|"
echo "| MRPT icp-slam (demo_classic.ini) | scan-to-map ICP, matches after 0.2 m / 5 deg | $(fmt "$(echo "$t1 - $t0" | bc)" 2) | - |"
echo "| featloc-run (config.ini) | scan-to-keyframe ICP, every scan | $(fmt "$(field malaga-icp '.wall_time_s')" 2) | $(fmt "$(field malaga-icp '.match_time_s.mean * 1000')" 2) |"
echo
echo "Distance between the two trajectories over $devN common poses: mean $devMean m, max $devMax m."
echo
echo "(raw outputs in $OUT)"
