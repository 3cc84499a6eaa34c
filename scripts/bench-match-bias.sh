#!/usr/bin/env bash
# Whole runs' matches against the truth (doc/benchmarks.md, "Local lines"):
# featloc-run with MATCHER (default featloc::IdcMatcher, matcher chain,
# keyframes as in config.ini) on the office and lab, 1 cm noise, seeds 1-4
# (the logs of scripts/bench-robust.sh's whole-run table), and for each
# scene the mean signed error of every match along x, y and yaw (robot
# frame of the reference scan: x is along the motion) beside the ATE. A
# consistent non-zero mean is a bias that adds up over a run.
# Usage: scripts/bench-match-bias.sh [OUTDIR] [MATCHER] [KEY=VALUE...]
# (the KEY=VALUEs go to the matcher's section).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-match-bias "$@"
matcher_args featloc::IdcMatcher "$@"

machine_line
echo
echo "Matcher: $MATCHER ${*:3}"
echo
echo "| scene | ATE rmse seeds 1-4 [mm] | matches | mean x error [mm] | mean y error [mm] | mean yaw error [deg] |"
echo "|---|---|---|---|---|---|"
for scene in office lab; do
  ates=""
  : > "$OUT/$scene-errors.txt"
  for seed in 1 2 3 4; do
    log="$OUT/$scene-seed$seed"
    [ -f "$log.rawlog" ] || sim_1cm "$scene" "$seed"
    run="$OUT/run-$scene-seed$seed"
    "$BIN/featloc-run" "$ROOT/config.ini" "$log.rawlog" --out "$run" -q \
      --set "ScanMatcher:class=$MATCHER" "${MATCHER_SETS[@]}" --set "Evaluation:ground_truth=$log.gt.txt" \
      --set Output:write_scene=false --set Output:write_rawlog=false > /dev/null
    ates="$ates $(fmt "$(jq -r '.evaluation.ate_m.rmse * 1000' "$run/summary.json")" 1)"
    python3 "$ROOT/scripts/match-errors.py" "$run/matches.txt" "$log.gt.txt" --print-signed >> "$OUT/$scene-errors.txt"
  done
  awk -v scene="$scene" -v ates="$ates" '
    { n++; x += $1; y += $2; w += $3 }
    END { printf "| %s |%s | %d | %+.3f | %+.3f | %+.4f |\n", scene, ates, n, x / n * 1000, y / n * 1000, w / n }' \
    "$OUT/$scene-errors.txt"
done
echo
echo "(raw outputs in $OUT)"
