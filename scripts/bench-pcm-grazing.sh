#!/usr/bin/env bash
# Reproduces "PCM keeps a grazing wall's far points" in doc/benchmarks.md
# (issue 15, item 6): PcmFeatureMatcher as config.ini has it, with
# grazing_incidence_DEG = 5 (the default) and 0 (the paper's fixed
# max_point_gap alone), each with its coarse search (the default) and
# without; Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed 1),
# every pair counted, the Cramer-Rao bound on the simulated scenes; MRPT's
# ICP beside them (the peer, timed in the same run).
#  - Calibration (where 5 deg was chosen): the office and lab at 1 cm noise,
#    the real orebro log.
#  - Held out: the corridor with people (+-0.3 m / 10 deg and
#    +-0.5 m / 15 deg), the hall with people, the room with doors and a cart,
#    and the other five Radish logs (../shared/data/laser2d or
#    $FEATLOC_LASER2D).
#  - Whole runs (featloc-run, PCM, matcher chain and EKF, lambda 5 and 0): the
#    corridor with people, seeds 1-6, and the office at 1 cm, seeds 1-4.
# Usage: scripts/bench-pcm-grazing.sh [OUTDIR]   (about 11 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-grazing "$@"

PCM=featloc::PcmFeatureMatcher
M="grazing 5 (config.ini)=$PCM,grazing 0=$PCM{grazing_incidence_DEG=0}"
M="$M,grazing 5 no search=$PCM{coarse_search=false},grazing 0 no search=$PCM{grazing_incidence_DEG=0;coarse_search=false}"
# The peer, timed in the same run.
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" --seed 1 -q -m "$M" --name "$name" "$@" \
    -j "$OUT/$(echo "$name" | tr " /+()" "_____").json" | grep -v "^$"
  echo
}

machine_line
echo
echo "### Calibration"
echo
for scene in office lab; do
  sim_1cm "$scene"
  bench "sim $scene (1 cm)" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt" \
    --perturb-xy 0.3 --perturb-yaw-deg 10 --world "$ROOT/worlds/$scene.ini" --header
done
[ -d "$LASER2D" ] && bench orebro "$LASER2D/orebro-corrected.log.gz" --perturb-xy 0.3 --perturb-yaw-deg 10

echo "### Held out"
echo
bench_held_out_scenes

echo "### Whole runs (featloc-run, PCM as config.ini has it; ATE rmse [mm])"
echo
echo "| estimator | grazing_incidence_DEG | corridor-people seeds 1-6 (held out) | mean | office 1 cm seeds 1-4 | mean |"
echo "|---|---|---|---|---|---|"
sim_corridor_seeds
for seed in 1 2 3 4; do sim_1cm office "$seed"; done
for est in matcher ekf; do
  for g in 5 0; do
    cells=()
    for log in corridor-people-seed{1..6} office-seed{1..4}; do
      r="$OUT/run-$est-$g-$log"
      "$BIN/featloc-run" "$ROOT/config.ini" "$OUT/$log.rawlog" --out "$r" -q \
        --set ScanMatcher:class=featloc::PcmFeatureMatcher --set "Pipeline:estimator=$est" \
        --set "Evaluation:ground_truth=$OUT/$log.gt.txt" \
        --set Output:write_scene=false --set Output:write_rawlog=false \
        --set "ScanMatcher.PcmFeatureMatcher:grazing_incidence_DEG=$g" > /dev/null
      cells+=("$(jq -r '.evaluation.ate_m.rmse * 1000' "$r/summary.json")")
    done
    corridor="${cells[*]:0:6}" office="${cells[*]:6:4}"
    mean() { echo "$@" | awk '{ s = 0; for (i = 1; i <= NF; i++) s += $i; printf "%.1f", s / NF }'; }
    list() { echo "$@" | awk '{ for (i = 1; i <= NF; i++) printf "%s%.1f", (i > 1 ? ", " : ""), $i }'; }
    echo "| $est | $g | $(list $corridor) | $(mean $corridor) | $(list $office) | $(mean $office) |"
  done
done
