#!/usr/bin/env bash
# Reproduces "CF-IDC leaves a free direction to its IDC fallback" in
# doc/benchmarks.md (issue 15, fourteenth session): CfIdcMatcher as
# config.ini has it (free_direction_from_guess = false in its section: a
# match whose segments leave one direction free fails and IDC makes it from
# the whole scans) against the same with the key true (CF-IDC keeps the
# guess along that direction itself, as before).
#  - Whole runs (featloc-run, matcher chain and EKF) on the bundled log, the
#    corridor with people (seeds 1-6) and the five held-out Radish logs:
#    ATE rmse [mm], failed matches, the fallback's matches, for each; then
#    the two compared step by step (featloc-eval --paired-with: mean RPE
#    difference [mm] with its 95% interval; the steps only one gets off by
#    > 10 cm or 2 deg, McNemar's p).
#  - Pairs (featloc-bench, Borges & Aldon's +-0.3 m / 10 deg, every pair
#    counted, paired): the office and lab (1 cm), the corridor, room and
#    hall with things moving (seed 1), and the six Radish logs (orebro:
#    calibration).
# Usage: scripts/bench-cfidc-free-direction.sh [OUTDIR]   (about 8 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc-free-direction "$@"

sim_corridor_seeds
machine_line
echo
echo "### Whole runs: old = free_direction_from_guess true in CF-IDC's section, new = config.ini (false)"
echo
echo "| log | estimator | old: ATE [mm] / failed / fallback matches | new: the same | step by step, new - old: RPE difference [mm] (95%); steps off only new / only old, McNemar p |"
echo "|---|---|---|---|---|"
for est in matcher ekf; do
  whole_runs_two_ways "$est" "1 2 3 4 5 6" old "ScanMatcher.CfIdcMatcher:free_direction_from_guess=true" \
    new "ScanMatcher.CfIdcMatcher:free_direction_from_guess=false" --set ScanMatcher:class=featloc::CfIdcMatcher
done

M="CF-IDC old=featloc::CfIdcMatcher{free_direction_from_guess=true},CF-IDC=featloc::CfIdcMatcher"
pairs() { # name, rawlog, extra args...
  local name="$1" log="$2"
  shift 2
  "$BIN/featloc-bench" "$ROOT/config.ini" "$log" -m "$M" --paired-with "CF-IDC old" \
    --perturb-xy 0.3 --perturb-yaw-deg 10 -q --header --name "$name" "$@" > "$OUT/pairs-$name.txt"
  paired_rows "seed 1" "$OUT/pairs-$name.txt"
}
echo
echo "### Pairs, CF-IDC (config.ini) paired with CF-IDC old (+-0.3 m / 10 deg, seed 1)"
echo
echo "| data | seed | matcher | \\|t\\| err mean difference, 95% interval [mm] | grossly wrong: only this / only the other, McNemar p |"
echo "|---|---|---|---|---|"
for scene in office lab; do
  sim_1cm "$scene"
  pairs "$scene" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt"
done
for w in room-moving-objects hall-people; do
  [ -f "$OUT/$w.rawlog" ] || "$BIN/featloc-sim" "$ROOT/worlds/$w.ini" --out "$OUT/$w" --seed 1 -q > /dev/null
  pairs "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt"
done
pairs corridor-people "$OUT/corridor-people-seed1.rawlog" -g "$OUT/corridor-people-seed1.gt.txt"
for f in "$LASER2D/orebro-corrected.log.gz" $(held_out_radish_logs); do
  pairs "$(basename "$f" -corrected.log.gz)" "$f"
done
echo
echo "(raw outputs in $OUT)"
