#!/usr/bin/env bash
# Reproduces "What the Radish logs' whole-run ATE can tell apart" in
# doc/benchmarks.md (issue 15, seventeenth session): on the held-out Radish
# logs (../shared/data/laser2d, GFS-corrected reference poses), whole runs of
# PCM before the sixteenth session's hand-off ("PCM old":
# fallback_above_sigma_xy = 0) and as config.ini has it, in the matcher
# chain and the EKF, with MRPT's ICP, IDC and the odometry alone beside
# them; then scripts/heading-bias.py: every run's heading error per step
# against the reference, and each run against another step by step (the
# reference cancels), which says whether the difference between two runs'
# ATE comes from a systematic difference per step or from the sum of
# independent ones; and the pairs of featloc-bench (+-0.3 m / 10 deg),
# each matcher's heading error against the reference's turn.
# Usage: scripts/bench-heading-bias.sh [OUTDIR]   (about 6 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-heading-bias "$@"
if [ ! -d "$LASER2D" ]; then
  echo "(no real logs: $LASER2D not found)"
  exit 0
fi

PCM=featloc::PcmFeatureMatcher
OLD="ScanMatcher.PcmFeatureMatcher:fallback_above_sigma_xy=0"
# The logs as the sixteenth session read them (its question): their beams
# evenly over 180 deg. config.ini's reading since, and what it changes:
# scripts/bench-carmen-beam-angles.sh.
READ=(--set Input:carmen_beam_angles=even)
machine_line
# The held-out logs: orebro's ODOM messages miss 219 of its 237 scans and
# its times do not increase (featloc-run says so), so its odometry and EKF
# runs measure nothing.
for f in $(held_out_radish_logs); do
  name="$(basename "$f" -corrected.log.gz)"
  bench_featloc_run "$name-odometry" "$f" "" "${READ[@]}" --set Pipeline:estimator=odometry
  for est in matcher ekf; do
    bench_featloc_run "$name-$est-pcm-old" "$f" "" "${READ[@]}" --set "Pipeline:estimator=$est" \
      --set "ScanMatcher:class=$PCM" --set "$OLD"
    bench_featloc_run "$name-$est-pcm" "$f" "" "${READ[@]}" --set "Pipeline:estimator=$est" \
      --set "ScanMatcher:class=$PCM"
  done
  bench_featloc_run "$name-ekf-icp" "$f" "" "${READ[@]}" --set Pipeline:estimator=ekf \
    --set ScanMatcher:class=featloc::IcpMatcher
  bench_featloc_run "$name-ekf-idc" "$f" "" "${READ[@]}" --set Pipeline:estimator=ekf \
    --set ScanMatcher:class=featloc::IdcMatcher
  "$BIN/featloc-bench" "$ROOT/config.ini" "$f" "${READ[@]}" --perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1 -q \
    -m "ICP (MRPT)=featloc::IcpMatcher,PCM=$PCM,IDC=featloc::IdcMatcher" --pairs "$OUT/$name-pairs.tsv" \
    > "$OUT/$name-pairs.txt"
  echo
  echo "### $name"
  echo
  echo "ATE rmse [mm]: $(for r in odometry matcher-pcm-old matcher-pcm ekf-pcm-old ekf-pcm ekf-icp ekf-idc; do
    printf "%s %s; " "$r" "$(jq -r '(.evaluation.ate_m.rmse // -0.001) * 1000 | round' "$OUT/$name-$r/summary.json")"
  done)"
  echo
  python3 "$ROOT/scripts/heading-bias.py" "$f" "$OUT/$name-ekf-pcm-old" "$OUT/$name-ekf-pcm" \
    "$OUT/$name-ekf-icp" "$OUT/$name-ekf-idc" "$OUT/$name-odometry"
  echo
  python3 "$ROOT/scripts/heading-bias.py" "$f" "$OUT/$name-matcher-pcm-old" "$OUT/$name-matcher-pcm" | tail -n 3
  echo
  python3 "$ROOT/scripts/heading-bias.py" "$f" --pairs "$OUT/$name-pairs.tsv"
done
echo
echo "(raw outputs in $OUT)"
