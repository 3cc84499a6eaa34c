#!/usr/bin/env bash
# Reproduces "PCM hands its weak matches to IDC" in doc/benchmarks.md (issue
# 15, sixteenth session): PCM with fallback_above_sigma_xy = 0 ("PCM old":
# only failed and ambiguous matches go to IDC) and as config.ini has it
# (0.01 m: a match whose covariance leaves a translation sigma above 1 cm,
# and above a range lattice's cell, goes to IDC too), beside MRPT's ICP and
# IDC, in one featloc-bench run per data set; Borges & Aldon's protocol
# (+-0.3 m / +-10 deg uniform, seed 1), every pair counted, PCM paired with
# "PCM old" (mean |t| error difference with its 95% interval; McNemar).
#  - Calibration: the simulated office and lab at 1 cm noise and the real
#    orebro log (where the 1 cm was read off, from PCM's error against
#    IDC's by PCM's sigma), and the office and lab with MRPT's 0.16 m
#    range lattice.
#  - Held out: the corridor with people (+-0.3 m / 10 deg and
#    +-0.5 m / 15 deg), the hall with people, the room with doors and a
#    cart, the five other Radish logs; the corridor and the room with the
#    0.16 m lattice and the bundled log.
#  - Whole runs (featloc-run, PCM, matcher chain and EKF): old against new
#    on the bundled log, the corridor with people (seeds 1-3) and the
#    held-out Radish logs, step by step (featloc-eval --paired-with).
# Usage: scripts/bench-pcm-weak-handoff.sh [OUTDIR]   (about 30 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-weak-handoff "$@"

PCM=featloc::PcmFeatureMatcher
M="ICP (MRPT)=featloc::IcpMatcher,PCM old=$PCM{fallback_above_sigma_xy=0},PCM=$PCM,IDC=featloc::IdcMatcher"
HEADER=--header
bench() { # name, data, extra args...
  local name="$1" data="$2" f
  shift 2
  f="$(bench_file "$name")"
  # shellcheck disable=SC2086
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" --seed 1 -q -m "$M" --paired-with "PCM old" \
    --header --name "$name" "$@" -j "$f.json" > "$f.txt"
  main_table < "$f.txt" | if [ -n "$HEADER" ]; then cat; else tail -n +3; fi
  HEADER=
}

machine_line
bench_calibration_and_held_out
bench_calibration_lattices ", 0.16 m lattice" --perturb-xy 0.3 --perturb-yaw-deg 10
for w in corridor-people room-moving-objects; do
  sim_lattice "$w" "$w-lattice" --seed 1
  bench "$w (0.16 m lattice)" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt" \
    --perturb-xy 0.3 --perturb-yaw-deg 10
done
bench "bundled log" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" -g "$ROOT/rawlogs/mrpt-simul/simul.gt.txt" \
  --perturb-xy 0.3 --perturb-yaw-deg 10

echo
echo "### PCM against PCM old, pair by pair (mean |t| error difference [mm], 95% interval; grossly wrong only this / only the other)"
echo
echo "| data | matcher | paired with | difference | grossly wrong |"
echo "|---|---|---|---|---|"
for f in "$OUT"/*.txt; do
  awk '/paired with/ {on = 1; next} on && /^\| / && !/^\|---/ && / PCM \| PCM old \|/' "$f"
done
echo
echo "### How often IDC made PCM's match (the fallback's note per data set)"
echo
for f in "$OUT"/*.txt; do
  n="$(basename "$f" .txt)"
  grep -hE "^PCM( old)?: the fallback" "$f" | sed "s/^/- $n: /" || true
done

echo
echo "### Whole runs, PCM: ATE rmse [mm] / failed matches / the fallback's matches; new against old step by step"
echo
echo "| log | estimator | old | new | new against old |"
echo "|---|---|---|---|---|"
sim_corridor_seeds
for est in matcher ekf; do
  whole_runs_two_ways "$est" "1 2 3" old "ScanMatcher.PcmFeatureMatcher:fallback_above_sigma_xy=0" \
    new "ScanMatcher.PcmFeatureMatcher:fallback_above_sigma_xy=0.01" --set "ScanMatcher:class=$PCM"
done
echo
echo "(raw outputs in $OUT)"
