#!/usr/bin/env bash
# Reproduces "How much of the real logs' NEES is the reference poses'" in
# doc/benchmarks.md (issue 15, item 5): every matcher as config.ini has it
# (MRPT's ICP, PCM, IDC, CF-IDC), Borges & Aldon's protocol (+-0.3 m /
# +-10 deg uniform, seed 1) on the Radish logs (orebro: calibration; the
# rest held out) and, as a check of the method, on two simulated scenes whose
# ground truth is exact (a shared error there is the matchers' own). Each
# featloc-bench run writes every pair's outcome (--pairs), and
# scripts/reference-error-share.py splits off the error the matchers share
# (the reference poses', and whatever in the scans misleads every matcher
# alike) and gives each matcher's NEES with that share added.
# Usage: scripts/bench-reference-share.sh [OUTDIR]   (about 15 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-reference-share "$@"

M="IcpMatcher=featloc::IcpMatcher,PcmFeatureMatcher=featloc::PcmFeatureMatcher"
M="$M,IdcMatcher=featloc::IdcMatcher,CfIdcMatcher=featloc::CfIdcMatcher"
bench() { # name, data, extra args...
  local name="$1" data="$2"; shift 2
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" --seed 1 -q -m "$M" --name "$name" \
    --perturb-xy 0.3 --perturb-yaw-deg 10 --pairs "$OUT/$name.pairs.tsv" "$@" > "$OUT/$name.md"
}

machine_line
echo
files=()
if [ -d "$LASER2D" ]; then
  bench orebro "$LASER2D/orebro-corrected.log.gz"
  files+=("$OUT/orebro.pairs.tsv")
  for f in $(held_out_radish_logs); do
    name="$(basename "$f" -corrected.log.gz)"
    bench "$name" "$f"
    files+=("$OUT/$name.pairs.tsv")
  done
else
  echo "(no real logs: $LASER2D not found)"
fi
sim_1cm office
bench "sim office (1 cm)" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt"
files+=("$OUT/sim office (1 cm).pairs.tsv")
"$BIN/featloc-sim" "$ROOT/worlds/corridor-people.ini" --out "$OUT/corridor-people" -q > /dev/null
bench "corridor-people" "$OUT/corridor-people.rawlog" -g "$OUT/corridor-people.gt.txt"
files+=("$OUT/corridor-people.pairs.tsv")
python3 "$ROOT/scripts/reference-error-share.py" "${files[@]}"
