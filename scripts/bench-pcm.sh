#!/usr/bin/env bash
# Reproduces the PCM figures of doc/benchmarks.md: Borges & Aldon's protocol
# (each scan pair matched from the true motion perturbed by uniform noise in
# +-0.3 m per axis and +-10 deg; mean absolute errors in t_x, t_y, w),
# featloc::PcmFeatureMatcher as published (every featloc addition off:
# doc/pcm-matcher.md),
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

# Three matchers in one featloc-bench run: PCM as published (every featloc
# addition switched off, doc/pcm-matcher.md), PCM with them (config.ini),
# IcpMatcher.
PROTOCOL="--set ScanMatcher.PcmFeatureMatcher:initial_bounds_source=config --perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1"
PAPER_PCM="coarse_search=false;dequantize_ranges=false;fallback_class=;refinement=none;pair_gate_chi2=0;guess_gate_chi2=0;dmax_corners=published;line_fit=tls;grazing_incidence_DEG=0;merge_step_points=0;line_outlier_sigmas=0;collinear_fusion_chi2=0;motion_window_bounds=0;min_matched_features=1;max_translation_sigma=1e9;max_rotation_sigma_DEG=1e9"
MATCHERS="PCM as published=featloc::PcmFeatureMatcher{$PAPER_PCM},PCM + featloc additions=featloc::PcmFeatureMatcher,IcpMatcher=featloc::IcpMatcher"
HEADER=--header

bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" $PROTOCOL -m "$MATCHERS" $HEADER \
    --name "$name" "$@" -j "$OUT/$name.json"
  HEADER=
}

machine_line
echo
for scene in office lab; do
  sim_1cm "$scene"
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
