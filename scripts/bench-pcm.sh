#!/usr/bin/env bash
# Reproduces the PCM figures of doc/benchmarks.md: Borges & Aldon's protocol
# (each scan pair matched from the true motion perturbed by uniform noise in
# +-0.3 m per axis and +-10 deg; mean absolute errors in t_x, t_y, w),
# featloc::PcmFeatureMatcher as published (refinement none, no pair gate),
# PcmFeatureMatcher with featloc's additions (config.ini defaults), and
# featloc::IcpMatcher, all in one featloc-bench run per data set:
#  - the simulator's office and lab scenes regenerated with 1 cm range noise
#    (exact ground truth);
#  - the six real Radish logs (reference poses good to 2-3 cm), if
#    ../shared/data/laser2d (or $FEATLOC_LASER2D) is there;
#  - the real Malaga 2006 log, against IcpMatcher's own result from odometry
#    (no ground truth: consistency only).
# Usage: scripts/bench-pcm.sh [OUTDIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm "$@"
LASER2D="${FEATLOC_LASER2D:-$ROOT/../shared/data/laser2d}"

# Two copies of the PCM matcher's parameters: "paper" (as published) and the
# defaults. featloc-bench takes a config and a matcher list; the paper variant
# runs through its own config with the two additions switched off.
sed -e 's/^refinement .*/refinement = none/' -e 's/^pair_gate_chi2 .*/pair_gate_chi2 = 0/' \
  "$ROOT/config.ini" > "$OUT/paper.ini"
PROTOCOL="--set ScanMatcher.PcmFeatureMatcher:initial_bounds_source=config --perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1"

bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  "$BIN/featloc-bench" "$OUT/paper.ini" "$data" $PROTOCOL -m featloc::PcmFeatureMatcher \
    --name "$name" "$@" -j "$OUT/$name-paper.json" | sed 's/featloc::PcmFeatureMatcher/PCM as published/'
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" $PROTOCOL \
    -m featloc::PcmFeatureMatcher,featloc::IcpMatcher --name "$name" "$@" -j "$OUT/$name.json" \
    | sed 's/featloc::PcmFeatureMatcher/PCM + featloc additions/; s/featloc::IcpMatcher/IcpMatcher/'
}

machine_line
echo
echo "| data | matcher | pairs | failed | MAE t_x [mm] | MAE t_y [mm] | MAE w [deg] | median \\|t err\\| [mm] | time/match mean [ms] | median [ms] | iterations | mean NEES |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for scene in office lab; do
  "$BIN/featloc-sim" "$ROOT/worlds/$scene.ini" --out "$OUT/$scene-1cm" -q \
    --set Laser:range_noise=0.01 > /dev/null
  bench "sim $scene (1 cm)" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt"
done
if [ -d "$LASER2D" ]; then
  for f in "$LASER2D"/*-corrected.log.gz; do
    bench "$(basename "$f" -corrected.log.gz)" "$f"
  done
else
  echo "(no real logs: $LASER2D not found)"
fi
bench "Malaga 2006 (vs ICP)" "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog" \
  --reference-matcher featloc::IcpMatcher
echo
echo "(raw outputs in $OUT)"
