#!/usr/bin/env bash
# Reproduces "Issue 15, thirty-first session" in doc/benchmarks.md: IDC's
# point-to-line pairs with the local lines of a large structure's short
# faces (max_face_direction_sigma_DEG = 8 on segments of at least
# face_segment_extent = 1 m, the default) against the one 5-degree gate for
# every line (max_face_direction_sigma_DEG = 0, as before), set in
# [ScanMatcher.IdcMatcher] (IDC, and PCM's and CF-IDC's IDC fallback) and
# [ScanMatcher.CfIdcMatcher]. One featloc-bench run per data set and
# setting: PCM, IDC and CF-IDC as config.ini has them, and MRPT's ICP;
# Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform, seed 1), every pair
# counted (a failure at its guess's error).
#  - Where it was found: the ring corridor (its door recesses' jambs);
#    the rotunda and the orchard beside it, static and as written; their
#    static twins also against each pair's Cramer-Rao bound (--pairs,
#    --pair-bounds, scripts/pair-bound-ratios.py).
#  - Held out from the change: the data sets of PCM's extraction benches
#    (bench-common.sh: the office and lab at 1 cm, the apartment, warehouse
#    and garage frozen at 1 cm against the bound and as written, the
#    corridor, hall and room with people, the lattices, the bundled log,
#    orebro and the five other Radish logs), the workshop, the office and
#    lab on the lattice.
#  - IDC's time per office pair alone with MRPT's ICP, both ways, three
#    runs in turn.
#  - Whole runs (featloc-run as config.ini has it) in the ring corridor, the
#    rotunda, the corridor with people (seed 1) and the bundled log, each
#    featloc matcher as the matcher chain and in the EKF.
# Usage: scripts/bench-face-lines.sh [OUTDIR]   (about 20 min on 2 cores, as measured)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-face-lines "$@"

switch_setup max_face_direction_sigma_DEG "one gate"

machine_line
echo
echo "### Where it was found: the ring corridor; the rotunda and the orchard beside it"
echo
switch_curved_worlds_and_the_rest ring-corridor rotunda orchard
echo
echo "### Time per office pair, IDC with MRPT's ICP alone in the run (three runs each way)"
echo
office_time_two_ways IDC featloc::IdcMatcher faces "one gate"
echo
echo "### Whole runs: ATE rmse [mm] / failed matches / fallback matches, one gate | faces"
echo
echo "| log | matcher | estimator | one gate | faces | faces against one gate: mean RPE difference [mm] (95%); steps off only with faces / only with one gate, McNemar |"
echo "|---|---|---|---|---|---|"
switch_whole_runs faces gate \
  "ring corridor:$OUT/ring corridor.rawlog:$OUT/ring corridor.gt.txt" \
  "rotunda:$OUT/rotunda.rawlog:$OUT/rotunda.gt.txt" \
  "corridor-people-seed1:$OUT/corridor-people-seed1.rawlog:$OUT/corridor-people-seed1.gt.txt" \
  "bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
echo
echo "(raw outputs in $OUT)"
