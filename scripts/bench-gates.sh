#!/usr/bin/env bash
# Issue 17's figures: matcher alone vs EKF, the matchers' guess gates on and
# off, [Odometry] action_sampling_offset on (default) and off (the gates
# before it), and covariance_check on and off, on the bundled log, the
# Malaga log (no ground truth: counts only), the shipped simulated scenes and
# the six Radish CARMEN logs (their corrected poses as reference, their ODOM
# messages as odometry; never used to choose any setting). "not overruled"
# sets the matchers' coarse_overrule_guess_z = 0: every guess-gate rejection
# stands, as before the arbiter. ATE in mm (rmse after SE(2) alignment).
# Usage: scripts/bench-gates.sh [OUTDIR]      (about 9 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init gates "$@"
RUN="$BIN/featloc-run"
MALAGA="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
machine_line

# run NAME INPUT GT [--set ...]: prints "ATEmm failures fallbacks"
run() {
  local name="$1" input="$2" gt="$3"; shift 3
  local args=("$ROOT/config.ini")
  [ -n "$input" ] && args+=("$input")
  [ -n "$gt" ] && args+=(--set "Evaluation:ground_truth=$gt")
  "$RUN" "${args[@]}" -q --out "$OUT/$name" "$@" >"$OUT/$name.txt" 2>&1 || { echo "error (see $OUT/$name.txt)"; return; }
  jq -r '[((.evaluation.ate_m.rmse // -0.001) * 1000 | round), .counts.match_failures, .counts.fallbacks_to_odometry] | map(tostring) | join(" ")' "$OUT/$name/summary.json"
}

echo
echo "## Guess gates and the EKF gate (ATE mm, failures, fallbacks); -1 = no ground truth"
echo "| log | matcher | matcher alone | matcher, guess gate off | matcher, gate not overruled | matcher, sampling offset off | EKF | EKF, gate off | EKF, gate not overruled | EKF, sampling offset off | EKF + covariance_check | EKF, direction offset off |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for log in bundled malaga office lab corridor-people; do
  case $log in
    bundled) in=""; gt="";;
    malaga) in="$MALAGA"; gt="";;
    *) in="$ROOT/rawlogs/sim/$log.rawlog"; gt="$ROOT/rawlogs/sim/$log.gt.txt";;
  esac
  for m in IcpMatcher PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
    c=(--set "ScanMatcher:class=featloc::$m")
    a=$(run "$log-$m-m" "$in" "$gt" "${c[@]}")
    b="(no guess gate)"; ao="(no guess gate)"; an="(no guess gate)"; en="(no guess gate)"
    case $m in IdcMatcher|CfIdcMatcher)
      b=$(run "$log-$m-m0" "$in" "$gt" "${c[@]}" --set "ScanMatcher.$m:guess_gate_chi2=0")
      an=$(run "$log-$m-mn" "$in" "$gt" "${c[@]}" --set "ScanMatcher.$m:coarse_overrule_guess_z=0")
      en=$(run "$log-$m-en" "$in" "$gt" "${c[@]}" --set "ScanMatcher.$m:coarse_overrule_guess_z=0" --set Pipeline:estimator=ekf)
      ao=$(run "$log-$m-mo" "$in" "$gt" "${c[@]}" --set Odometry:action_sampling_offset=false);; esac
    e=$(run "$log-$m-e" "$in" "$gt" "${c[@]}" --set Pipeline:estimator=ekf)
    e0=$(run "$log-$m-e0" "$in" "$gt" "${c[@]}" --set Pipeline:estimator=ekf --set Ekf:matcher_gate_chi2=1e12)
    eo=$(run "$log-$m-eo" "$in" "$gt" "${c[@]}" --set Pipeline:estimator=ekf --set Odometry:action_sampling_offset=false)
    ec=$(run "$log-$m-ec" "$in" "$gt" "${c[@]}" --set Pipeline:estimator=ekf --set Odometry:covariance_check=true)
    ed=$(run "$log-$m-ed" "$in" "$gt" "${c[@]}" --set Pipeline:estimator=ekf --set Ekf:odometry_direction_sigma_DEG=0)
    echo "| $log | $m | $a | $b | $an | $ao | $e | $e0 | $en | $eo | $ec | $ed |"
  done
done

if [ -d "$LASER2D" ]; then
  echo
  echo "## Radish CARMEN logs through featloc-run (ATE mm against the corrected poses, failures, fallbacks)"
  echo "| log | matcher | matcher alone | matcher, gate not overruled | EKF | EKF, gate not overruled | EKF + covariance_check | EKF, direction offset off |"
  echo "|---|---|---|---|---|---|---|---|"
  for f in "$LASER2D"/*.log.gz; do
    n=$(basename "$f" .log.gz)
    for m in IcpMatcher IdcMatcher CfIdcMatcher; do
      c=(--set "ScanMatcher:class=featloc::$m")
      an="(no guess gate)"; en="(no guess gate)"
      case $m in IdcMatcher|CfIdcMatcher)
        an=$(run "$n-$m-mn" "$f" "" "${c[@]}" --set "ScanMatcher.$m:coarse_overrule_guess_z=0")
        en=$(run "$n-$m-en" "$f" "" "${c[@]}" --set "ScanMatcher.$m:coarse_overrule_guess_z=0" --set Pipeline:estimator=ekf);; esac
      echo "| $n | $m | $(run "$n-$m-m" "$f" "" "${c[@]}") | $an | $(run "$n-$m-e" "$f" "" "${c[@]}" --set Pipeline:estimator=ekf) | $en | $(run "$n-$m-ec" "$f" "" "${c[@]}" --set Pipeline:estimator=ekf --set Odometry:covariance_check=true) | $(run "$n-$m-ed" "$f" "" "${c[@]}" --set Pipeline:estimator=ekf --set Ekf:odometry_direction_sigma_DEG=0) |"
    done
  done
fi
echo
echo "outputs in $OUT"
