#!/usr/bin/env bash
# Reproduces the CF-IDC ablation of doc/benchmarks.md ("Does CF-IDC's
# curvature stage earn its keep?", issue 15 item 4): Nunez et al.'s CF-IDC
# as published and with featloc's additions, each with its stages switched
# off one at a time, beside IDC and MRPT's ICP, on three simulated scenes
# with things that move (exact ground truth):
#  - worlds/room-moving-objects.ini: people who walk a few metres and stand,
#    two doors that swing, a cart pushed with stops (new for this ablation:
#    between two scans each moves centimetres to a decimetre);
#  - worlds/corridor-people.ini: six people walking a corridor;
#  - worlds/hall-people.ini: people walking round a standing robot.
# Two protocols: Nunez et al.'s (each current scan moved by a random motion
# of mean 1 m / 15 deg, sd 50 mm / 5 deg; every matcher starts from the
# mean) and Borges & Aldon's (+-0.3 m / +-10 deg uniform). Every pair
# counts. With --world, featloc-bench also counts the current points on
# things that moved since the reference scan (farther than 2 cm from every
# surface of the world at the reference scan's time) that each CF-IDC
# variant kept for its final IDC, against the other points kept.
# "As published" is the paper exactly as far as switches go
# (doc/cfidc-matcher.md lists what cannot be switched off); it also runs
# with U_k read as 5 cm and 1 cm instead of 1.0 m.
# Then the curvature_pairing switch alone on the static office and lab and
# the real Radish logs (if ../shared/data/laser2d or $FEATLOC_LASER2D is there).
# Usage: scripts/bench-cfidc-ablation.sh [OUTDIR]   (about 2 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-cfidc-ablation "$@"

PAPER_IDC="coarse_search=false;dequantize_ranges=false;final_phase=idc;breakpoint_at_missing_returns=false;breakpoint_sigma_r_from_scan=false;guess_gate_chi2=0;max_translation_sigma=1e9;max_rotation_sigma_DEG=1e9"
PAPER_CFIDC="$PAPER_IDC;fallback_class=;pairing_gate=false;pairing_fallback=false;segment_gate=0;curvature_sampling=normalized"
M="IDC as published=featloc::IdcMatcher{$PAPER_IDC}"
M="$M,CF-IDC as published=featloc::CfIdcMatcher{$PAPER_CFIDC}"
M="$M,CF-IDC as published - curvature pairing=featloc::CfIdcMatcher{$PAPER_CFIDC;curvature_pairing=false}"
M="$M,CF-IDC as published U_k 5 cm=featloc::CfIdcMatcher{$PAPER_CFIDC;curvature_U_k=0.05}"
M="$M,CF-IDC as published U_k 1 cm=featloc::CfIdcMatcher{$PAPER_CFIDC;curvature_U_k=0.01}"
M="$M,CF-IDC featloc=featloc::CfIdcMatcher"
M="$M,CF-IDC featloc - curvature pairing=featloc::CfIdcMatcher{curvature_pairing=false}"
M="$M,CF-IDC featloc - pairing gate=featloc::CfIdcMatcher{pairing_gate=false}"
M="$M,CF-IDC featloc - segment gate=featloc::CfIdcMatcher{segment_gate=0}"
M="$M,CF-IDC featloc - segment residuals=featloc::CfIdcMatcher{segment_residual_chi2=0}"
M="$M,CF-IDC featloc - pairing fallback=featloc::CfIdcMatcher{pairing_fallback=false}"
M="$M,IDC featloc=featloc::IdcMatcher"
M="$M,IcpMatcher=featloc::IcpMatcher"

machine_line
for world in room-moving-objects corridor-people hall-people; do
  "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/$world" -q > /dev/null
  for protocol in nunez borges; do
    if [ "$protocol" = nunez ]; then
      P="--perturbation gaussian --perturb-xy 0.05 --perturb-yaw-deg 5 --apply-motion 0.7071,0.7071,15"
      title="Nunez et al.'s protocol (1 m / 15 deg applied, 50 mm / 5 deg sd)"
    else
      P="--perturb-xy 0.3 --perturb-yaw-deg 10"
      title="Borges & Aldon's protocol (+-0.3 m / +-10 deg)"
    fi
    echo
    echo "### $world: $title"
    echo
    "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/$world.rawlog" -g "$OUT/$world.gt.txt" \
      --world "$ROOT/worlds/$world.ini" --seed 1 -q -m "$M" $P --header --name "$world" \
      -j "$OUT/$world-$protocol.json"
  done
done

# The same switch on scenes that did not decide it: the static office and
# lab (1 cm noise) and the real Radish logs, Borges & Aldon's protocol.
echo
echo "### curvature_pairing on the static scenes and the real logs (+-0.3 m / +-10 deg)"
echo
for scene in office lab; do
  sim_1cm "$scene"
done
HEADER=--header
for data in "$OUT/office-1cm.rawlog" "$OUT/lab-1cm.rawlog" "$LASER2D"/*-corrected.log.gz; do
  [ -e "$data" ] || continue
  GT=()
  case "$data" in *.rawlog) GT=(-g "${data%.rawlog}.gt.txt") ;; esac
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" "${GT[@]}" --perturb-xy 0.3 --perturb-yaw-deg 10 \
    --seed 1 -q $HEADER -m "CF-IDC featloc=featloc::CfIdcMatcher,CF-IDC featloc - curvature pairing=featloc::CfIdcMatcher{curvature_pairing=false}" \
    -j "$OUT/curvature-$(basename "$data").json"
  HEADER=
done
echo
echo "(raw outputs in $OUT)"
