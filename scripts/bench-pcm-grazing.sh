#!/usr/bin/env bash
# Reproduces "PCM keeps a grazing wall's far points" in doc/benchmarks.md
# (issue 15, item 6): PcmFeatureMatcher as config.ini has it, with
# grazing_incidence_DEG = 5 (the default) and 0 (the paper's fixed
# max_point_gap alone), each with its coarse search (the default) and
# without; Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed 1),
# every pair counted, the Cramer-Rao bound on the simulated scenes.
#  - Calibration (where 5 deg was chosen): the office and lab at 1 cm noise,
#    the real orebro log.
#  - Held out: the corridor with people (+-0.3 m / 10 deg and
#    +-0.5 m / 15 deg), the hall with people, the room with doors and a cart,
#    and the other five Radish logs (../shared/data/laser2d or
#    $FEATLOC_LASER2D).
# Usage: scripts/bench-pcm-grazing.sh [OUTDIR]   (about 8 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-grazing "$@"
LASER2D="${FEATLOC_LASER2D:-$ROOT/../shared/data/laser2d}"

PCM=featloc::PcmFeatureMatcher
M="grazing 5 (config.ini)=$PCM,grazing 0=$PCM{grazing_incidence_DEG=0}"
M="$M,grazing 5 no search=$PCM{coarse_search=false},grazing 0 no search=$PCM{grazing_incidence_DEG=0;coarse_search=false}"
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
