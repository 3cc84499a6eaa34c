#!/usr/bin/env bash
# Reproduces "Issue 15, thirteenth session" (and the fourteenth's floor) in doc/benchmarks.md, CF-IDC
# against IDC where things move (issue 15 item 4 and its target "CF-IDC at
# most 0.6 x IDC's mean error with walking people"): CF-IDC as config.ini
# has it, the same without its curvature pairing (the paper's stage), and
# MRPT's ICP, each paired with IDC (featloc-bench --paired-with) on the same
# pairs and guesses: the mean |t| error difference with its 95%
# block-bootstrap interval, and the pairs only one of the two gets grossly
# wrong with McNemar's exact p. Three simulated scenes with things that
# move, each simulated with seeds 1-3 (other people, other paths; featloc-bench
# draws its guesses with the same seed): the corridor with people walking
# (Borges & Aldon's +-0.3 m / 10 deg and +-0.5 m / 15 deg), the room with
# doors, a cart and people who stop and start, and the hall with people
# round a standing robot (+-0.3 m / 10 deg). Every pair counts.
# The floor: each scene simulated again with nothing moving (featloc-sim
# --frozen: no people or cart, the doors held closed; the same path, seed and
# laser), IDC and CF-IDC on it with the same guesses. IDC's error there over
# its error with things moving is the least CF-IDC / IDC any rejection of
# moving things can reach, short of being more accurate than IDC on a static
# scene; the table also says which share of what the moving things cost IDC
# CF-IDC takes back.
# Usage: scripts/bench-cfidc-paired.sh [OUTDIR]   (under 2 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc-paired "$@"

M="IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
M="$M,CF-IDC - curvature pairing=featloc::CfIdcMatcher{curvature_pairing=false}"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"

# One scene, seed and initial error through featloc-bench -> $OUT/LOG-XY.txt
# (+ .json, .tsv), LOG = WORLD-seedSEED; with "frozen", LOG =
# WORLD-frozen-seedSEED, the world simulated with nothing moving
# (featloc-sim --frozen) and only IDC and CF-IDC, unpaired.
run() { # world, seed, xy, yaw[, frozen]
  local log="$OUT/$1-seed$2" m="$M" peer=IDC name="$1 +-$3/$4" sim=()
  if [ "${5:-}" = frozen ]; then
    log="$OUT/$1-frozen-seed$2" m="IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher" peer=none
    name="$1 frozen +-$3/$4" sim=(--frozen)
  fi
  [ -f "$log.rawlog" ] || "$BIN/featloc-sim" "$ROOT/worlds/$1.ini" "${sim[@]}" --out "$log" --seed "$2" -q > /dev/null
  "$BIN/featloc-bench" "$ROOT/config.ini" "$log.rawlog" -g "$log.gt.txt" -m "$m" --paired-with "$peer" \
    --perturb-xy "$3" --perturb-yaw-deg "$4" --seed "$2" -q --header --name "$name" \
    -j "$log-$3.json" --pairs "$log-$3.tsv" > "$log-$3.txt"
}
CASES="corridor-people:0.3:10 corridor-people:0.5:15 room-moving-objects:0.3:10 hall-people:0.3:10"
# "IDC CF-IDC" mean |t| errors [mm] of a featloc-bench JSON.
means() { python3 -c 'import json,sys; r={x["matcher"]: x["mean_trans_err_m"] for x in json.load(open(sys.argv[1]))["results"]}; print("%.2f %.2f" % (1e3 * r["IDC"], 1e3 * r["CF-IDC"]))' "$1"; }

machine_line
for c in $CASES; do
  IFS=: read -r world xy yaw <<< "$c"
  for seed in 1 2 3; do run "$world" "$seed" "$xy" "$yaw"; run "$world" "$seed" "$xy" "$yaw" frozen; done
done

echo
echo "### Main tables (seed 1)"
echo
first=1
for c in $CASES; do
  IFS=: read -r world xy yaw <<< "$c"
  if [ $first = 1 ]; then main_table < "$OUT/$world-seed1-$xy.txt"; first=0
  else main_table < "$OUT/$world-seed1-$xy.txt" | tail -n +3; fi
done

echo
echo "### Paired with IDC (each cell: |t| error mean difference [mm] and its 95% interval; grossly wrong only this / only IDC, McNemar p)"
echo
echo "| data | matcher | seed 1 | seed 2 | seed 3 |"
echo "|---|---|---|---|---|"
for c in $CASES; do
  IFS=: read -r world xy yaw <<< "$c"
  for seed in 1 2 3; do paired_rows "$seed" "$OUT/$world-seed$seed-$xy.txt"; done |
    paired_by_seed "$world +-$xy/$yaw"
done
echo
echo "### The floor: the same scenes with nothing moving (featloc-sim --frozen), mean |t| error [mm]"
echo
echo "| data | seed | IDC moving / frozen | CF-IDC moving / frozen | CF-IDC / IDC, moving | floor: IDC frozen / moving | share of the moving things' cost to IDC that CF-IDC takes back |"
echo "|---|---|---|---|---|---|---|"
for c in $CASES; do
  IFS=: read -r world xy yaw <<< "$c"
  for seed in 1 2 3; do
    read -r im cm <<< "$(means "$OUT/$world-seed$seed-$xy.json")"
    read -r if cf <<< "$(means "$OUT/$world-frozen-seed$seed-$xy.json")"
    awk -v d="$world +-$xy/$yaw" -v s="$seed" -v im="$im" -v cm="$cm" -v if_="$if" -v cf="$cf" 'BEGIN {
      share = (im - if_ > 0.05) ? sprintf("%.0f%%", 100 * (im - cm) / (im - if_)) : "(moving things cost IDC nothing)"
      printf "| %s | %s | %.2f / %.2f | %.2f / %.2f | %.2f | %.2f | %s |\n", d, s, im, if_, cm, cf, cm / im, if_ / im, share }'
  done
done
echo
echo "(raw outputs in $OUT)"
