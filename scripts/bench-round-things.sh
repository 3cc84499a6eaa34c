#!/usr/bin/env bash
# Reproduces "Issue 15, thirty-second session" in doc/benchmarks.md: IDC's
# point-to-line phase pairs the points of small round things (a segment
# shorter than face_segment_extent that a circle fits better than a line by
# circle_fit_sigmas = 3, the default) with their circles, and drops the
# groups of them that may have moved (dropMovedRoundThing), against lines
# only (circle_fit_sigmas = 0, as before), set in [ScanMatcher.IdcMatcher]
# (IDC, and PCM's and CF-IDC's IDC fallback) and [ScanMatcher.CfIdcMatcher].
# One featloc-bench run per data set and setting: PCM, IDC and CF-IDC as
# config.ini has them, and MRPT's ICP; Borges & Aldon's protocol (+-0.3 m /
# +-10 deg uniform, seed 1), every pair counted (a failure at its guess's
# error).
#  - Where it was made: the orchard (its trunks) and the corridor with
#    people (their legs, which move); the rotunda and the ring corridor
#    beside them, static and as written; the static twins also against each
#    pair's Cramer-Rao bound (--pairs, --pair-bounds,
#    scripts/pair-bound-ratios.py).
#  - Held out from the change: the data sets of PCM's extraction benches
#    (bench-common.sh: the office and lab at 1 cm, the apartment, warehouse
#    and garage frozen at 1 cm against the bound and as written, the hall
#    and room with people, the lattices, the bundled log, orebro and the
#    five other Radish logs), the workshop, the office and lab on the
#    lattice.
#  - IDC's time per office pair alone with MRPT's ICP, both ways, three
#    runs in turn.
#  - Whole runs (featloc-run as config.ini has it) in the orchard, the
#    rotunda, the corridor with people (seed 1) and the bundled log, each
#    featloc matcher as the matcher chain and in the EKF.
# Usage: scripts/bench-round-things.sh [OUTDIR]   (about 16 min on 2 cores, as measured)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-round-things "$@"

switch_setup circle_fit_sigmas "lines only"

machine_line
echo
echo "### Where it was made: the orchard; the rotunda and the ring corridor beside it"
echo
switch_curved_worlds_and_the_rest orchard rotunda ring-corridor
echo
echo "### Time per office pair, IDC with MRPT's ICP alone in the run (three runs each way)"
echo
office_time_two_ways IDC featloc::IdcMatcher circles "lines only"
echo
echo "### Whole runs: ATE rmse [mm] / failed matches / fallback matches, lines only | circles"
echo
echo "| log | matcher | estimator | lines only | circles | circles against lines only: mean RPE difference [mm] (95%); steps off only with circles / only with lines only, McNemar |"
echo "|---|---|---|---|---|---|"
switch_whole_runs circles lines \
  "orchard:$OUT/orchard.rawlog:$OUT/orchard.gt.txt" \
  "rotunda:$OUT/rotunda.rawlog:$OUT/rotunda.gt.txt" \
  "corridor-people-seed1:$OUT/corridor-people-seed1.rawlog:$OUT/corridor-people-seed1.gt.txt" \
  "bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
echo
echo "(raw outputs in $OUT)"
