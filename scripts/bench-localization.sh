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
#     then the map matcher's own guess gate ([Localization] map_guess_gate)
#     on and off for the PCM scan-to-scan rows;
#  2. the office path driven 1 and 10 laps, localized in the world file:
#     the error must not grow with the run's length;
#  3. global localization ([Pipeline] initial_pose = global) from N random
#     starts in the office and the lab (a random free pose, then random
#     goals; 30 scans), featloc and pf-localization (particles uniform over
#     the free cells, the demo's 40000) in the same gridmap of the world
#     (featloc-sim --gridmap 0.05): found within 10 scans and right
#     (0.2 m / 5 deg), found later, never found, and false confirmations (a
#     "found" that is wrong; pf-localization: its first step with
#     sqrt(trace(cov)) < 0.2 counts as its "found"). The starts are seeds
#     101.. by default: seeds 1-100 of the office are where
#     global_min_evidence was chosen. Then the kidnapped robot (carried
#     across the office, odometry blind): lost and found again.
# Every featloc run starts from the ground truth's first pose known to
# 0.1 m / 3 deg ([Pipeline] initial_pose_sigma); pf-localization's particles
# start uniform over the same +-0.1 m / +-3 deg.
# Usage: scripts/bench-localization.sh [OUTDIR] [PF_PARTICLES (default 2000)] [STARTS (default 100)]
#   [FIRST_START_SEED (default 101)]
# Takes about 8 minutes on 2 cores.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-localization "$@"
PARTICLES="${2:-2000}"
STARTS="${3:-100}"
FIRST="${4:-101}"
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
# featloc-run, EKF, in MAP ("" = none), ATE without alignment. Args: prefix out map [--set ...]
loc() {
  local p="$1" out="$2" map="$3"; shift 3
  "$BIN/featloc-run" "$ROOT/config.ini" "$p.rawlog" --out "$out" -q "$@" \
    --set Pipeline:estimator=ekf --set "Pipeline:initial_pose=[$(gt_pose "$p.gt.txt" 0)]" \
    --set 'Pipeline:initial_pose_sigma=[0.1 0.1 3]' --set Localization:map="$map" \
    --set Evaluation:ground_truth="$p.gt.txt" --set Evaluation:align=false \
    --set Output:write_rawlog=false --set Output:write_scene=false >/dev/null
}
ate() { jq -r '"\(.evaluation.ate_m.rmse*1000|floor) / \(.evaluation.ate_m.max*1000|floor)"' "$1/summary.json"; }
maptime() { jq -r '(.localization.time_per_map_match_s.median // 0)*1000 | . * 100 | floor / 100' "$1/summary.json"; }
used() { jq -r '"\(.localization.map_matches_used)/\(.counts.scans)"' "$1/summary.json"; }
perscan() { jq -r '.wall_time_s / .counts.scans * 1000 | . * 100 | floor / 100' "$1/summary.json"; }
# The per-scan processing, like pf-localization's filter step (no log
# reading, start-up or output writing): the scan-to-scan match, the map
# match and the estimator's step, mean times summed.
processing() { jq -r '((.match_time_s.mean // 0) + (.localization.time_per_map_match_s.mean // 0) + (.estimator_time_s.mean // 0)) * 1000 | . * 100 | floor / 100' "$1/summary.json"; }

# pf-localization on PREFIX.rawlog in MAP: its per-step mean (parsed from
# its log: "PDF estimation") as a TUM file, evaluated by featloc-eval.
# pf-localization does not run the filter on the first action/frame pair and
# reports the initial PDF there, so its particles start at the first pair's
# scan (ground-truth row 1) and estimate k belongs to row k + 1.
pf() { # prefix map out [global]
  local p="$1" map="$2" out="$3" mode="${4:-tracking}"
  mkdir -p "$out"
  awk '!/^#/ && k++ >= 1 {printf "%s %s %s %.9f\n", $1, $2, $3, 2*atan2($7,$8)}' "$p.gt.txt" > "$out/gt4.txt"
  local init
  if [ "$mode" = global ]; then
    # Uniform over the free cells of the whole map, the demo's 40000 particles.
    init=(-e "s#^particles_count=.*#particles_count=40000#" -e "s#^init_PDF_mode=.*#init_PDF_mode=0#"
      -e "s#^init_PDF_min_x=.*#init_PDF_min_x=-5#" -e "s#^init_PDF_max_x=.*#init_PDF_max_x=45#"
      -e "s#^init_PDF_min_y=.*#init_PDF_min_y=-5#" -e "s#^init_PDF_max_y=.*#init_PDF_max_y=25#")
  else
    read -r x y yaw <<<"$(gt_pose "$p.gt.txt" 1)"
    init=(-e "s#^particles_count=.*#particles_count=$PARTICLES#" -e "s#^init_PDF_mode=.*#init_PDF_mode=1#"
      -e "s#^init_PDF_min_x=.*#init_PDF_min_x=$(echo "$x - 0.1" | bc -l)#" -e "s#^init_PDF_max_x=.*#init_PDF_max_x=$(echo "$x + 0.1" | bc -l)#"
      -e "s#^init_PDF_min_y=.*#init_PDF_min_y=$(echo "$y - 0.1" | bc -l)\ninit_PDF_min_yaw_deg=$(echo "$yaw - 3" | bc -l)\ninit_PDF_max_yaw_deg=$(echo "$yaw + 3" | bc -l)#"
      -e "s#^init_PDF_max_y=.*#init_PDF_max_y=$(echo "$y + 0.1" | bc -l)#")
  fi
  sed -e "s#^map_file=.*#map_file=$map#" -e "s#^rawlog_file=.*#rawlog_file=$p.rawlog#" \
    -e "s#^logOutput_dir=.*#logOutput_dir=$out/LOG\nground_truth_path_file=$out/gt4.txt#" \
    -e "s#^3DSceneFrequency=.*#3DSceneFrequency=-1#" \
    -e "s#^SHOW_PROGRESS_3D_REAL_TIME *=.*#SHOW_PROGRESS_3D_REAL_TIME=false#" "${init[@]}" \
    /usr/share/mrpt/config_files/pf-localization/localization_demo.ini > "$out/pf.ini"
  (cd "$out" && pf-localization pf.ini > pf.log 2>&1)
  grep "PDF estimation" "$out/pf.log" | sed -E 's/.*PDF estimation: \(([^,]+),([^,]+),([^d]+)deg\).*tr\(cov\): ([-0-9.e]+).*/\1 \2 \3 \4/' > "$out/means.txt"
  awk 'NR==FNR{t[NR]=$1; next} {printf "%s %s %s 0 0 0 %.12f %.12f\n", t[FNR], $1, $2, sin($3*3.14159265358979/360), cos($3*3.14159265358979/360)}' \
    "$out/gt4.txt" "$out/means.txt" > "$out/trajectory.tum"
  [ "$mode" = global ] || "$BIN/featloc-eval" "$p.gt.txt" "$out/trajectory.tum" --no-align --json > "$out/eval.json"
}
# pf-localization's first step whose particles have converged (sqrt of the
# covariance's trace under 0.2) and whether its mean is right there (0.2 m,
# 5 deg), and whether its mean is right at its last step: "STEP RIGHT
# LAST_RIGHT" (STEP -1: never). Step k is ground-truth row k + 1.
# Whether the last pose of a TUM trajectory is within 0.2 m / 5 deg of the
# ground truth's last row: 1 or 0.
last_right() { # trajectory.tum gt
  python3 - "$1" "$2" <<'PY'
import math, sys
rows = lambda f: [l.split() for l in open(f) if not l.startswith("#") and l.strip()]
e, g = rows(sys.argv[1])[-1], rows(sys.argv[2])[-1]
yaw = lambda r: math.degrees(2 * math.atan2(float(r[6]), float(r[7])))
a = (yaw(e) - yaw(g) + 180) % 360 - 180
print(int(math.hypot(float(e[1]) - float(g[1]), float(e[2]) - float(g[2])) < 0.2 and abs(a) < 5))
PY
}
pf_converged() { # out gt
  python3 - "$1/means.txt" "$2" <<'PY'
import math, sys
gt = [l.split() for l in open(sys.argv[2]) if not l.startswith("#") and l.strip()]
means = [list(map(float, l.split())) for l in open(sys.argv[1])]
def right(k):
    x, y, w, tr = means[k]
    g = gt[min(k + 1, len(gt) - 1)]
    a = (w - math.degrees(2 * math.atan2(float(g[6]), float(g[7]))) + 180) % 360 - 180
    return int(math.hypot(x - float(g[1]), y - float(g[2])) < 0.2 and abs(a) < 5)
first = next((k for k in range(1, len(means)) if means[k][3] < 0.2 and k + 1 < len(gt)), None)
print(-1 if first is None else first + 1, 0 if first is None else right(first), right(len(means) - 1) if means else 0)
PY
}
pf_ate() { jq -r '"\(.ate_m.rmse*1000|floor) / \(.ate_m.max*1000|floor)"' "$1/eval.json"; }
pf_time() { awk '{s+=$1; n++} END{printf "%.2f", 1000*s/n}' "$1"/LOG_000_*/exec_times.txt; }

machine_line
echo "pf-localization: $(dpkg-query -W -f='${Version}' mrpt-apps 2>/dev/null), demo ini, $PARTICLES particles (KLD adaptive)"
echo
echo "| world | run B localized in | ATE RMSE / max [mm] | map matches used | map match [ms] (median) | whole run per scan [ms] | processing per scan [ms] (matches + estimator, means) |"
echo "|---|---|---|---|---|---|---|"
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
  loc "$OUT/$world-b" "$OUT/$world-b-pcm" "$MAP" --set ScanMatcher:class=featloc::PcmFeatureMatcher
  loc "$OUT/$world-b" "$OUT/$world-b-pcm-nosearch" "$MAP" --set ScanMatcher:class=featloc::PcmFeatureMatcher \
    --set ScanMatcher.PcmFeatureMatcher:coarse_search=false --set ScanMatcher.IdcMatcher:coarse_search=false
  pf "$OUT/$world-b" "$MAP" "$OUT/$world-b-pf"
  echo "| $world | (mapping run A, in the world file) | $(ate "$OUT/$world-a-mapping") | $(used "$OUT/$world-a-mapping") | $(maptime "$OUT/$world-a-mapping") | $(perscan "$OUT/$world-a-mapping") | $(processing "$OUT/$world-a-mapping") |"
  echo "| $world | featloc, the world file | $(ate "$OUT/$world-b-world") | $(used "$OUT/$world-b-world") | $(maptime "$OUT/$world-b-world") | $(perscan "$OUT/$world-b-world") | $(processing "$OUT/$world-b-world") |"
  echo "| $world | featloc, run A's map.simplemap | $(ate "$OUT/$world-b-simplemap") | $(used "$OUT/$world-b-simplemap") | $(maptime "$OUT/$world-b-simplemap") | $(perscan "$OUT/$world-b-simplemap") | $(processing "$OUT/$world-b-simplemap") |"
  echo "| $world | featloc, run A's map.simplemap, PCM scan-to-scan too | $(ate "$OUT/$world-b-pcm") | $(used "$OUT/$world-b-pcm") | $(maptime "$OUT/$world-b-pcm") | $(perscan "$OUT/$world-b-pcm") | $(processing "$OUT/$world-b-pcm") |"
  echo "| $world | featloc, run A's map.simplemap, PCM scan-to-scan without coarse searches (its own and its IDC fallback's) | $(ate "$OUT/$world-b-pcm-nosearch") | $(used "$OUT/$world-b-pcm-nosearch") | $(maptime "$OUT/$world-b-pcm-nosearch") | $(perscan "$OUT/$world-b-pcm-nosearch") | $(processing "$OUT/$world-b-pcm-nosearch") |"
  echo "| $world | pf-localization, run A's map.simplemap | $(pf_ate "$OUT/$world-b-pf") | - | - | - | $(pf_time "$OUT/$world-b-pf") (filter step) |"
  echo "| $world | featloc, no map (EKF from the start) | $(ate "$OUT/$world-b-nomap") | - | - | $(perscan "$OUT/$world-b-nomap") | $(processing "$OUT/$world-b-nomap") |"
done
echo
echo "| office run B in the world file: [Localization] matcher_class (config.ini: PcmFeatureMatcher) | ATE RMSE / max [mm] | map matches used / failed / rejected | map match [ms] (median) |"
echo "|---|---|---|---|"
for m in IcpMatcher IdcMatcher CfIdcMatcher PcmFeatureMatcher; do
  loc "$OUT/office-b" "$OUT/office-b-world-$m" "$ROOT/worlds/office.ini" --set Localization:matcher_class=featloc::$m
  echo "| $m | $(ate "$OUT/office-b-world-$m") | $(jq -r '"\(.localization.map_matches_used) / \(.localization.map_match_failures) / \(.localization.map_matches_rejected_by_gate)"' "$OUT/office-b-world-$m/summary.json") | $(maptime "$OUT/office-b-world-$m") |"
done
echo
echo "| run B in run A's map.simplemap, PCM scan-to-scan | [Localization] map_guess_gate | ATE RMSE / max [mm] | map matches used / failed / rejected | lost | global searches | map match [ms] (median) | processing per scan [ms] |"
echo "|---|---|---|---|---|---|---|---|"
for world in office lab; do
  # false: config.ini's (the first table's PCM scan-to-scan rows); true: the matcher's own
  # guess gate on the map matches as well as gate_chi2's.
  loc "$OUT/$world-b" "$OUT/$world-b-pcm-mapgate" "$OUT/$world-a-mapping/map.simplemap" \
    --set ScanMatcher:class=featloc::PcmFeatureMatcher --set Localization:map_guess_gate=true
  for run in "$world-b-pcm false" "$world-b-pcm-mapgate true"; do
    read -r d gate <<<"$run"
    echo "| $world | $gate | $(ate "$OUT/$d") | $(jq -r '"\(.localization.map_matches_used) / \(.localization.map_match_failures) / \(.localization.map_matches_rejected_by_gate) | \([.localization.events[]? | select(startswith("lost"))] | length) | \(.localization.global_searches)"' "$OUT/$d/summary.json") | $(maptime "$OUT/$d") | $(processing "$OUT/$d") |"
  done
done
echo
echo "| office path | scans | ATE RMSE / max [mm], in the world file |"
echo "|---|---|---|"
for laps in 1 10; do
  "$BIN/featloc-sim" "$ROOT/worlds/office.ini" --out "$OUT/office-laps$laps" -q --seed 5 --set Robot:laps=$laps >/dev/null
  loc "$OUT/office-laps$laps" "$OUT/office-laps$laps-world" "$ROOT/worlds/office.ini"
  echo "| $laps lap(s) | $(jq -r .counts.scans "$OUT/office-laps$laps-world/summary.json") | $(ate "$OUT/office-laps$laps-world") |"
done

# Global localization: the first "found" event's scan and whether it is
# within 0.2 m / 5 deg of the ground truth there; every found event judged.
# Prints "FIRST_SCAN FIRST_RIGHT WRONG_FOUNDS" (FIRST_SCAN -1: never found).
judge_found() { # out gt
  python3 - "$1/summary.json" "$2" <<'PY'
import json, math, re, sys
events = json.load(open(sys.argv[1])).get("localization", {}).get("events", [])
gt = [l.split() for l in open(sys.argv[2]) if not l.startswith("#") and l.strip()]
first, first_right, wrong = -1, 0, 0
for e in events:
    m = re.match(r"found at scan (\d+) .*?: at \(([-0-9.]+) m, ([-0-9.]+) m, ([-0-9.]+) deg\)", e)
    if not m:
        continue
    k, x, y, w = int(m.group(1)), float(m.group(2)), float(m.group(3)), float(m.group(4))
    g = gt[k]
    gw = math.degrees(2 * math.atan2(float(g[6]), float(g[7])))
    a = (w - gw + 180) % 360 - 180
    right = math.hypot(x - float(g[1]), y - float(g[2])) < 0.2 and abs(a) < 5
    if first < 0:
        first, first_right = k, int(right)
    wrong += 0 if right else 1
print(first, first_right, wrong)
PY
}
echo
echo "| world | random starts (seeds) | localizer | found within 10 scans, right | found later, right | never found (30 scans) | false confirmations | estimate right at the last scan | time per scan [s] (mean) |"
echo "|---|---|---|---|---|---|---|---|---|"
for world in office lab; do
  "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/$world-map" -q --gridmap 0.05 --set Simulation:max_scans=1 >/dev/null
  GRID="$OUT/$world-map.gridmap.gz"
  within=0; later=0; never=0; wrong=0; last=0; searchTime=0
  pwithin=0; plater=0; pnever=0; pwrong=0; plast=0; pfTime=0
  for i in $(seq "$FIRST" $((FIRST + STARTS - 1))); do
    # A random start in free space: candidates drawn until the simulator
    # accepts one (explore_start needs its clearance).
    for attempt in $(seq 0 50); do
      read -r sx sy <<<"$(awk -v s=$((i * 100 + attempt)) -v w="$world" 'BEGIN{srand(s);
        if (w=="office") printf "%.2f %.2f", 0.5+rand()*39, 0.5+rand()*15; else printf "%.2f %.2f", 0.5+rand()*13, 0.5+rand()*9}')"
      if "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/global-$world-$i" -q --seed "$i" \
          --set Robot:path=explore --set "Robot:explore_start=[$sx $sy]" --set Robot:explore_goals=3 \
          --set Robot:explore_clearance=0.4 --set Simulation:max_scans=30 >/dev/null 2>&1; then break; fi
    done
    "$BIN/featloc-run" "$ROOT/config.ini" "$OUT/global-$world-$i.rawlog" --out "$OUT/global-$world-$i-run" -q \
      --set Pipeline:estimator=ekf --set Pipeline:initial_pose=global --set Localization:map="$GRID" \
      --set Output:write_rawlog=false --set Output:write_scene=false >/dev/null
    read -r first right bad <<<"$(judge_found "$OUT/global-$world-$i-run" "$OUT/global-$world-$i.gt.txt")"
    wrong=$((wrong + bad))
    last=$((last + $(last_right "$OUT/global-$world-$i-run/trajectory.tum" "$OUT/global-$world-$i.gt.txt")))
    if [ "$first" -ge 0 ] && [ "$right" = 1 ] && [ "$first" -lt 10 ]; then within=$((within + 1));
    elif [ "$first" -ge 0 ] && [ "$right" = 1 ]; then later=$((later + 1));
    elif [ "$first" -lt 0 ]; then never=$((never + 1)); fi
    searchTime=$(echo "$searchTime + $(jq -r '.wall_time_s / .counts.scans' "$OUT/global-$world-$i-run/summary.json")" | bc -l)
    pf "$OUT/global-$world-$i" "$GRID" "$OUT/global-$world-$i-pf" global
    read -r step ok pfLast <<<"$(pf_converged "$OUT/global-$world-$i-pf" "$OUT/global-$world-$i.gt.txt")"
    plast=$((plast + pfLast))
    if [ "$step" -lt 0 ]; then pnever=$((pnever + 1));
    elif [ "$ok" = 0 ]; then pwrong=$((pwrong + 1));
    elif [ "$step" -lt 10 ]; then pwithin=$((pwithin + 1)); else plater=$((plater + 1)); fi
    pfTime=$(echo "$pfTime + $(awk '{s+=$1; n++} END{print (n ? s/n : 0)}' "$OUT"/global-$world-$i-pf/LOG_000_*/exec_times.txt)" | bc -l)
  done
  seeds="$FIRST-$((FIRST + STARTS - 1))"
  echo "| $world | $STARTS ($seeds) | featloc | $within | $later | $never | $wrong | $last | $(fmt "$(echo "$searchTime / $STARTS" | bc -l)" 3) (whole run) |"
  echo "| $world | $STARTS ($seeds) | pf-localization | $pwithin | $plater | $pnever | $pwrong | $plast | $(fmt "$(echo "$pfTime / $STARTS" | bc -l)" 3) (filter step) |"
done

echo
echo "| kidnapped robot (office) | events |"
echo "|---|---|"
"$BIN/featloc-sim" "$ROOT/worlds/office.ini" --out "$OUT/kidnap" -q --seed 9 \
  --set 'Robot:waypoints=[3 8; 15 8; 17.6 8; 17.6 11; 18.5 13.5]' \
  --set 'Robot:kidnap_waypoints=[30 8; 22 8; 21 8; 21 8.5; 27.5 8; 27.5 5.5; 29.5 3]' >/dev/null
"$BIN/featloc-run" "$ROOT/config.ini" "$OUT/kidnap.rawlog" --out "$OUT/kidnap-run" -q \
  --set Pipeline:estimator=ekf --set Pipeline:initial_pose=global --set Localization:map="$ROOT/worlds/office.ini" \
  --set Evaluation:ground_truth="$OUT/kidnap.gt.txt" --set Evaluation:align=false >/dev/null
jq -r '.localization.events[]' "$OUT/kidnap-run/summary.json" | sed 's/^/| | /; s/$/ |/'
read -r first right bad <<<"$(judge_found "$OUT/kidnap-run" "$OUT/kidnap.gt.txt")"
echo "| | wrong founds: $bad; ATE median after the first found $(jq -r '.evaluation.ate_m.median * 1000 | floor' "$OUT/kidnap-run/summary.json") mm |"

# Real data: MRPT's localization demo (a real log and its simplemap, no
# ground truth): featloc from a global start and pf-localization with its
# own demo settings (its initial region, 40000 particles), side by side.
echo
D=/usr/share/mrpt/datasets
"$BIN/featloc-run" "$ROOT/config.ini" "$D/localization_demo.rawlog" --out "$OUT/demo-featloc" -q \
  --set Pipeline:estimator=ekf --set Pipeline:initial_pose=global --set Localization:map="$D/localization_demo.simplemap.gz" \
  --set Evaluation:ground_truth= --set Output:write_rawlog=false >/dev/null
mkdir -p "$OUT/demo-pf"
sed -e "s#^map_file=.*#map_file=$D/localization_demo.simplemap.gz#" -e "s#^rawlog_file=.*#rawlog_file=$D/localization_demo.rawlog#" \
  -e "s#^logOutput_dir=.*#logOutput_dir=$OUT/demo-pf/LOG#" -e "s#^SHOW_PROGRESS_3D_REAL_TIME *=.*#SHOW_PROGRESS_3D_REAL_TIME=false#" \
  -e "s#^3DSceneFrequency=.*#3DSceneFrequency=-1#" /usr/share/mrpt/config_files/pf-localization/localization_demo.ini > "$OUT/demo-pf/pf.ini"
(cd "$OUT/demo-pf" && pf-localization pf.ini > pf.log 2>&1)
echo "MRPT localization_demo (real, no ground truth): featloc (global start) against pf-localization (demo ini), step by step"
python3 - "$OUT/demo-featloc/trajectory.tum" "$OUT/demo-pf/pf.log" "$OUT/demo-featloc/summary.json" <<'PY'
import json, math, re, sys
est = [l.split() for l in open(sys.argv[1]) if not l.startswith("#") and l.strip()]
pf = [tuple(map(float, m.groups())) for m in (re.search(r"PDF estimation: \(([-0-9.]+),([-0-9.]+),([-0-9.]+)deg.*tr\(cov\): ([-0-9.e]+)", l) for l in open(sys.argv[2])) if m]
s = json.load(open(sys.argv[3]))["localization"]
found = next((int(re.match(r"found at scan (\d+)", e).group(1)) for e in s["events"] if e.startswith("found")), None)
# This log starts with an action: pf-localization's step k is frame k,
# featloc's row k. Compared where both have converged (pf: sqrt(trace) < 0.2).
pfFound = next((k for k, p in enumerate(pf) if k > 0 and p[3] < 0.2), None)
start = max(found or 0, pfFound or 0)
d = [math.hypot(float(est[k][1]) - pf[k][0], float(est[k][2]) - pf[k][1]) for k in range(start, min(len(pf), len(est)))]
print("| featloc found at scan | pf-localization converged at step | map matches used / rejected / scans matched | events | featloc vs pf-localization from then on: mean / max [m] |")
print("|---|---|---|---|---|")
print("| %s | %s | %d / %d / %d | %s | %.3f / %.3f |" % (found, pfFound, s["map_matches_used"], s["map_matches_rejected_by_gate"], s["map_matches"], "; ".join(e.split(" (")[0] for e in s["events"]), sum(d) / len(d), max(d)))
PY
echo
echo "results in $OUT"
