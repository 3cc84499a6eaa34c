#!/usr/bin/env bash
# Reproduces the "Localization in a known map" figures of doc/benchmarks.md.
# Simulated worlds (exact ground truth); ATE RMSE in the map's frame, no
# alignment ([Evaluation] align = false):
#  1. office and lab: a mapping run (the world's own path) localized in the
#     world file writes map.simplemap; a second run on another path with
#     people walking is localized in (a) the world file, (b) that
#     map.simplemap, (c) no map (EKF relative to the start, for scale), and
#     MRPT's pf-localization (CMonteCarloLocalization2D, its demo settings,
#     the same simplemap, started from the same pose) on the same log;
#  2. the office path driven 1 and 10 laps, localized in the world file:
#     the error must not grow with the run's length.
# Every featloc run starts from the ground truth's first pose known to
# 0.1 m / 3 deg ([Pipeline] initial_pose_sigma); pf-localization's particles
# start uniform over the same +-0.1 m / +-3 deg.
# Usage: scripts/bench-localization.sh [OUTDIR] [PF_PARTICLES (default 2000)]
# Takes about 3 minutes on 2 cores.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-localization "$@"
PARTICLES="${2:-2000}"
command -v pf-localization >/dev/null || { echo "pf-localization (mrpt-apps) is missing: run scripts/setup.sh"; exit 1; }

# People walking the office corridor both ways, and the lab's aisles.
OFFICE_PEOPLE=(--set Agent.a:shape=legs --set 'Agent.a:waypoints=[1 8.3; 39 8.3]' --set Agent.a:speed=1.1
  --set Agent.a:mode=pingpong --set Agent.b:shape=legs --set 'Agent.b:waypoints=[39 7.6; 1 7.6]'
  --set Agent.b:speed=0.9 --set Agent.b:mode=pingpong)
LAB_PEOPLE=(--set Agent.a:shape=legs --set 'Agent.a:waypoints=[1 5; 13 5]' --set Agent.a:speed=0.8
  --set Agent.a:mode=pingpong --set Agent.b:shape=legs --set 'Agent.b:waypoints=[7 1; 7 9]'
  --set Agent.b:speed=0.7 --set Agent.b:mode=pingpong)
OFFICE_B_PATH='Robot:waypoints=[35 8; 20 8; 20 8.3; 7.5 8; 7.5 11; 8.5 13; 6.5 13.5; 7.5 11; 7.5 8; 37 8]'

# "x y yaw_deg" of row N (0-based) of a TUM ground truth.
gt_pose() { awk -v n="$2" '!/^#/{if (k++ == n) {printf "%s %s %.4f", $2, $3, 2*atan2($7,$8)*180/3.14159265358979; exit}}' "$1"; }
# featloc-run, EKF, in MAP ("" = none), ATE without alignment. Args: prefix out map
loc() {
  local p="$1" out="$2" map="$3"
  "$BIN/featloc-run" "$ROOT/config.ini" "$p.rawlog" --out "$out" -q \
    --set Pipeline:estimator=ekf --set "Pipeline:initial_pose=[$(gt_pose "$p.gt.txt" 0)]" \
    --set 'Pipeline:initial_pose_sigma=[0.1 0.1 3]' --set Localization:map="$map" \
    --set Evaluation:ground_truth="$p.gt.txt" --set Evaluation:align=false \
    --set Output:write_rawlog=false --set Output:write_scene=false >/dev/null
}
ate() { jq -r '"\(.evaluation.ate_m.rmse*1000|floor) / \(.evaluation.ate_m.max*1000|floor)"' "$1/summary.json"; }
maptime() { jq -r '(.localization.time_per_map_match_s.median // 0)*1000 | . * 100 | floor / 100' "$1/summary.json"; }
used() { jq -r '"\(.localization.map_matches_used)/\(.counts.scans)"' "$1/summary.json"; }
perscan() { jq -r '.wall_time_s / .counts.scans * 1000 | . * 100 | floor / 100' "$1/summary.json"; }

# pf-localization on PREFIX.rawlog in MAP: its per-step mean (parsed from
# its log: "PDF estimation") as a TUM file, evaluated by featloc-eval.
# pf-localization does not run the filter on the first action/frame pair and
# reports the initial PDF there, so its particles start at the first pair's
# scan (ground-truth row 1) and estimate k belongs to row k + 1.
pf() { # prefix map out
  local p="$1" map="$2" out="$3"
  mkdir -p "$out"
  awk '!/^#/ && k++ >= 1 {printf "%s %s %s %.9f\n", $1, $2, $3, 2*atan2($7,$8)}' "$p.gt.txt" > "$out/gt4.txt"
  read -r x y yaw <<<"$(gt_pose "$p.gt.txt" 1)"
  sed -e "s#^map_file=.*#map_file=$map#" -e "s#^rawlog_file=.*#rawlog_file=$p.rawlog#" \
    -e "s#^logOutput_dir=.*#logOutput_dir=$out/LOG\nground_truth_path_file=$out/gt4.txt#" \
    -e "s#^particles_count=.*#particles_count=$PARTICLES#" -e "s#^init_PDF_mode=.*#init_PDF_mode=1#" \
    -e "s#^3DSceneFrequency=.*#3DSceneFrequency=-1#" \
    -e "s#^SHOW_PROGRESS_3D_REAL_TIME *=.*#SHOW_PROGRESS_3D_REAL_TIME=false#" \
    -e "s#^init_PDF_min_x=.*#init_PDF_min_x=$(echo "$x - 0.1" | bc -l)#" -e "s#^init_PDF_max_x=.*#init_PDF_max_x=$(echo "$x + 0.1" | bc -l)#" \
    -e "s#^init_PDF_min_y=.*#init_PDF_min_y=$(echo "$y - 0.1" | bc -l)\ninit_PDF_min_yaw_deg=$(echo "$yaw - 3" | bc -l)\ninit_PDF_max_yaw_deg=$(echo "$yaw + 3" | bc -l)#" \
    -e "s#^init_PDF_max_y=.*#init_PDF_max_y=$(echo "$y + 0.1" | bc -l)#" \
    /usr/share/mrpt/config_files/pf-localization/localization_demo.ini > "$out/pf.ini"
  (cd "$out" && pf-localization pf.ini > pf.log 2>&1)
  grep "PDF estimation" "$out/pf.log" | sed -E 's/.*PDF estimation: \(([^,]+),([^,]+),([^d]+)deg\).*/\1 \2 \3/' |
    awk 'NR==FNR{t[NR]=$1; next} {printf "%s %s %s 0 0 0 %.12f %.12f\n", t[FNR], $1, $2, sin($3*3.14159265358979/360), cos($3*3.14159265358979/360)}' \
      "$out/gt4.txt" - > "$out/trajectory.tum"
  "$BIN/featloc-eval" "$p.gt.txt" "$out/trajectory.tum" --no-align --json > "$out/eval.json"
}
pf_ate() { jq -r '"\(.ate_m.rmse*1000|floor) / \(.ate_m.max*1000|floor)"' "$1/eval.json"; }
pf_time() { awk '{s+=$1; n++} END{printf "%.2f", 1000*s/n}' "$1"/LOG_000_*/exec_times.txt; }

machine_line
echo "pf-localization: $(dpkg-query -W -f='${Version}' mrpt-apps 2>/dev/null), demo ini, $PARTICLES particles (KLD adaptive)"
echo
echo "| world | run B localized in | ATE RMSE / max [mm] | map matches used | map match [ms] (median) | whole run per scan [ms] |"
echo "|---|---|---|---|---|---|"
for world in office lab; do
  if [ "$world" = office ]; then
    A_SETS=(--seed 3); B_SETS=(--seed 7 --set "$OFFICE_B_PATH" "${OFFICE_PEOPLE[@]}")
  else
    A_SETS=(--seed 3); B_SETS=(--seed 11 "${LAB_PEOPLE[@]}")
  fi
  "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/$world-a" -q "${A_SETS[@]}" >/dev/null
  "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/$world-b" -q "${B_SETS[@]}" >/dev/null
  loc "$OUT/$world-a" "$OUT/$world-a-mapping" "$ROOT/worlds/$world.ini"
  MAP="$OUT/$world-a-mapping/map.simplemap"
  loc "$OUT/$world-b" "$OUT/$world-b-world" "$ROOT/worlds/$world.ini"
  loc "$OUT/$world-b" "$OUT/$world-b-simplemap" "$MAP"
  loc "$OUT/$world-b" "$OUT/$world-b-nomap" ""
  pf "$OUT/$world-b" "$MAP" "$OUT/$world-b-pf"
  echo "| $world | (mapping run A, in the world file) | $(ate "$OUT/$world-a-mapping") | $(used "$OUT/$world-a-mapping") | $(maptime "$OUT/$world-a-mapping") | $(perscan "$OUT/$world-a-mapping") |"
  echo "| $world | featloc, the world file | $(ate "$OUT/$world-b-world") | $(used "$OUT/$world-b-world") | $(maptime "$OUT/$world-b-world") | $(perscan "$OUT/$world-b-world") |"
  echo "| $world | featloc, run A's map.simplemap | $(ate "$OUT/$world-b-simplemap") | $(used "$OUT/$world-b-simplemap") | $(maptime "$OUT/$world-b-simplemap") | $(perscan "$OUT/$world-b-simplemap") |"
  echo "| $world | pf-localization, run A's map.simplemap | $(pf_ate "$OUT/$world-b-pf") | - | - | $(pf_time "$OUT/$world-b-pf") (filter step) |"
  echo "| $world | featloc, no map (EKF from the start) | $(ate "$OUT/$world-b-nomap") | - | - | $(perscan "$OUT/$world-b-nomap") |"
done
echo
echo "| office path | scans | ATE RMSE / max [mm], in the world file |"
echo "|---|---|---|"
for laps in 1 10; do
  "$BIN/featloc-sim" "$ROOT/worlds/office.ini" --out "$OUT/office-laps$laps" -q --seed 5 --set Robot:laps=$laps >/dev/null
  loc "$OUT/office-laps$laps" "$OUT/office-laps$laps-world" "$ROOT/worlds/office.ini"
  echo "| $laps lap(s) | $(jq -r .counts.scans "$OUT/office-laps$laps-world/summary.json") | $(ate "$OUT/office-laps$laps-world") |"
done
echo
echo "results in $OUT"
