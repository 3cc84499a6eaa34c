#!/usr/bin/env bash
# Reproduces "Where a CARMEN log's beams point" in doc/benchmarks.md (issue
# 15, seventeenth session): the six Radish logs (../shared/data/laser2d,
# GFS-corrected reference poses) read with [Input] carmen_beam_angles = even
# (n beams evenly over -90..+90 deg, MRPT's carmen2rawlog, featloc before)
# and sick (config.ini: from -90 deg at the SICK resolution 180/n or
# 180/(n-1) deg that the count implies; 180 and 360 beams end one step short
# of +90 deg).
#  - Pairs (featloc-bench, Borges & Aldon's +-0.3 m / 10 deg, seed 1, every
#    pair counted), MRPT's ICP, PCM and IDC as config.ini has them, one run
#    per convention; then scripts/heading-bias.py --pairs: each matcher's
#    heading error against the reference's turn (the slope b: how much of a
#    turn the matcher adds) and its error across the direction of travel.
#  - Whole runs on the held-out logs (orebro's odometry misses 219 of its 237
#    scans): PCM's matcher chain and EKF, MRPT's ICP's EKF, ATE rmse.
# Usage: scripts/bench-carmen-beam-angles.sh [OUTDIR]   (about 8 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-carmen-beam-angles "$@"
if [ ! -d "$LASER2D" ]; then
  echo "(no real logs: $LASER2D not found)"
  exit 0
fi

M="ICP (MRPT)=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher"
machine_line
echo
echo "### Pairs: even -> sick"
echo
echo "| log | beams | matcher | flagged = failed + used | silent gross | \\|t\\| err mean / median / p95 [mm] |"
echo "|---|---|---|---|---|---|"
for f in "$LASER2D"/*-corrected.log.gz; do
  name="$(basename "$f" -corrected.log.gz)"
  # (awk stops reading at the first FLASER: zcat's broken pipe is expected)
  beams="$( (zcat -f "$f" || true) | awk '$1 == "FLASER" {print $2; exit}')"
  for way in even sick; do
    "$BIN/featloc-bench" "$ROOT/config.ini" "$f" --perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1 -q -m "$M" \
      --set "Input:carmen_beam_angles=$way" --pairs "$OUT/$name-$way.tsv" --header > "$OUT/$name-$way.txt"
  done
  for m in "ICP (MRPT)" PCM IDC; do
    row() { awk -F'|' -v m=" $m " 'NF > 12 && $3 == m {gsub(/^ | $/, "", $5); gsub(/^ | $/, "", $6); gsub(/^ | $/, "", $8);
      print $5 "|" $6 "|" $8; exit}' "$OUT/$name-$1.txt"; }
    IFS='|' read -r fe se te <<< "$(row even)"
    IFS='|' read -r fs ss ts <<< "$(row sick)"
    echo "| $name | $beams | $m | $fe -> $fs | $se -> $ss | $te -> $ts |"
  done
done
for f in "$LASER2D"/*-corrected.log.gz; do
  name="$(basename "$f" -corrected.log.gz)"
  for way in even sick; do
    echo
    echo "#### $name, $way"
    echo
    python3 "$ROOT/scripts/heading-bias.py" "$f" --pairs "$OUT/$name-$way.tsv" | tail -n +2
  done
done

echo
echo "### Whole runs on the held-out logs: ATE rmse [mm], even -> sick"
echo
echo "Each cell: even -> sick; then sick against even step by step (featloc-eval --paired-with: the mean"
echo "RPE translation difference [mm] with its 95% interval; steps off only in one / only in the other)."
echo
echo "| log | PCM, matcher chain | PCM, EKF | MRPT's ICP, EKF |"
echo "|---|---|---|---|"
for f in $(held_out_radish_logs); do
  name="$(basename "$f" -corrected.log.gz)"
  row="| $name |"
  for run in "matcher featloc::PcmFeatureMatcher" "ekf featloc::PcmFeatureMatcher" "ekf featloc::IcpMatcher"; do
    read -r est cls <<< "$run"
    cell=""
    run="$name-$est-${cls#featloc::}"
    for way in even sick; do
      bench_featloc_run "$run-$way" "$f" "" --set "Pipeline:estimator=$est" \
        --set "ScanMatcher:class=$cls" --set "Input:carmen_beam_angles=$way"
      cell+="${cell:+ -> }$(jq -r '(.evaluation.ate_m.rmse // -0.001) * 1000 | round' "$OUT/$run-$way/summary.json")"
    done
    [ -f "$OUT/$name.reference.txt" ] ||
      python3 "$ROOT/scripts/carmen-reference.py" "$f" "$OUT/$run-sick/poses_cov.txt" > "$OUT/$name.reference.txt"
    row+=" $cell; $(runs_paired "$OUT/$name.reference.txt" "$OUT/$run-sick" "$OUT/$run-even") |"
  done
  echo "$row"
done
echo
echo "(raw outputs in $OUT)"
