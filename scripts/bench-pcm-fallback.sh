#!/usr/bin/env bash
# Reproduces "PCM with a fallback" in doc/benchmarks.md (issue 15): Borges &
# Aldon's PCM alone, and with `fallback_class` (another matcher makes the
# match when PCM fails), beside MRPT's ICP and IDC with the coarse search,
# in one featloc-bench run per data set; Borges & Aldon's protocol
# (+-0.3 m / +-10 deg uniform, seed 1), every pair counted (a failure at its
# guess's error).
#  - Calibration (where merge_sigmas = 3 and the ICP fallback were chosen):
#    the simulated office and lab at 1 cm noise, with each pair's
#    Cramer-Rao bound (--world), and the real orebro log.
#  - Held out: the corridor with people walking (+-0.3 m / 10 deg and
#    +-0.5 m / 15 deg), the hall with people, the room with doors and a cart,
#    and the other five Radish logs (../shared/data/laser2d or
#    $FEATLOC_LASER2D).
#  - Whole runs (featloc-run, matcher chain): the office and lab with four
#    seeds each, and MRPT's 5 cm-noise simulated log with both estimators.
#  - PCM's signed errors over the office's consecutive matches against the
#    spread its covariance predicts (scripts/match-errors.py --all).
# Usage: scripts/bench-pcm-fallback.sh [OUTDIR]   (about 3 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-fallback "$@"

PCM=featloc::PcmFeatureMatcher
M="PCM alone with merge_sigmas 1.5 (before)=$PCM{fallback_class=;merge_sigmas=1.5}"
M="$M,PCM alone=$PCM{fallback_class=}"
M="$M,PCM > ICP (config.ini)=$PCM"
M="$M,PCM > IDC + search=$PCM{fallback_class=featloc::IdcMatcher}"
M="$M,IcpMatcher=featloc::IcpMatcher"
M="$M,IdcMatcher + search=featloc::IdcMatcher"
# The IDC fallback and the IDC row run with the coarse search.
COMMON="--set ScanMatcher.PcmFeatureMatcher:initial_bounds_source=config
  --set ScanMatcher.IdcMatcher:coarse_search=true --seed 1 -q"
bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  # shellcheck disable=SC2086
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" $COMMON -m "$M" --header \
    --name "$name" "$@" -j "$OUT/$(echo "$name" | tr " /+()" "_____").json"
  echo
}

machine_line
echo
echo "### Calibration scenes"
echo
for scene in office lab; do
  sim_1cm "$scene"
  bench "sim $scene (1 cm)" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt" \
    --perturb-xy 0.3 --perturb-yaw-deg 10 --world "$ROOT/worlds/$scene.ini"
done
[ -d "$LASER2D" ] && bench "orebro" "$LASER2D/orebro-corrected.log.gz" --perturb-xy 0.3 --perturb-yaw-deg 10

echo "### Held out"
echo
bench_held_out_scenes

echo "### Whole runs (matcher chain unless said; ATE rmse [mm]; failed matches / made by the fallback)"
echo
echo "| log | PCM alone | PCM > ICP (config.ini) | PCM > IDC + search |"
echo "|---|---|---|---|"
cell() { # run folder
  jq -r '"\(.evaluation.ate_m.rmse * 1000 | . * 10 | round / 10) (\(.counts.match_failures) / \(.counts.fallback_matcher_matches))"' "$1/summary.json"
}
run() { # label, rawlog, ground truth, extra args...
  local label="$1" log="$2" gt="$3"; shift 3
  local row="| $label" i=0
  for fb in "" featloc::IcpMatcher featloc::IdcMatcher; do
    local r="$OUT/run-$(echo "$label" | tr " /+(),'" "________")-$i"
    "$BIN/featloc-run" "$ROOT/config.ini" "$log" --out "$r" -q \
      --set ScanMatcher:class=$PCM --set "ScanMatcher.PcmFeatureMatcher:fallback_class=$fb" \
      --set ScanMatcher.IdcMatcher:coarse_search=true \
      --set "Evaluation:ground_truth=$gt" --set Output:write_scene=false \
      --set Output:write_rawlog=false "$@" > /dev/null
    row="$row | $(cell "$r")"
    i=$((i + 1))
  done
  echo "$row |"
}
for scene in office lab; do
  for seed in 1 2 3 4; do
    "$BIN/featloc-sim" "$ROOT/worlds/$scene.ini" --out "$OUT/$scene-seed$seed" --seed "$seed" -q \
      --set Laser:range_noise=0.01 > /dev/null
    run "$scene, seed $seed, 1 cm" "$OUT/$scene-seed$seed.rawlog" "$OUT/$scene-seed$seed.gt.txt"
  done
done
D=/usr/share/mrpt/datasets/graphslam-engine-demos/action_observations_map
for est in matcher ekf; do
  run "MRPT's simul.rawlog (5 cm), $est" "$D/simul.rawlog" "$D/simul.rawlog.GT.txt" \
    --set "Pipeline:estimator=$est"
done
echo
echo "### PCM's errors on the office's consecutive matches (featloc-run, every scan a keyframe): bias or variance"
echo
"$BIN/featloc-run" "$ROOT/config.ini" "$OUT/office-1cm.rawlog" --out "$OUT/run-office-consecutive" -q \
  --set ScanMatcher:class=$PCM --set Pipeline:keyframe_distance=0 --set Pipeline:keyframe_angle_DEG=0 \
  --set Output:write_scene=false --set Output:write_rawlog=false > /dev/null
python3 "$ROOT/scripts/match-errors.py" "$OUT/run-office-consecutive/matches.txt" "$OUT/office-1cm.gt.txt" --all \
  | grep '^# successful'
echo
echo "(raw outputs in $OUT)"
