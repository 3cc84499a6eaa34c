#!/usr/bin/env bash
# Reproduces "Issue 15, thirty-third session" in doc/benchmarks.md (the
# bow part): with line_bow_per_segment = true (a switch, off by default) a
# segment whose lines, one window apart, bow one way (the median of their
# bows' t statistics beyond line_bow_sigmas) keeps every line's bow; against
# the default (each line alone), set in [ScanMatcher.IdcMatcher] (IDC, and
# PCM's and CF-IDC's IDC fallback) and [ScanMatcher.CfIdcMatcher].
# One featloc-bench run per data set and setting: PCM, IDC and CF-IDC as
# config.ini has them, and MRPT's ICP; Borges & Aldon's protocol (+-0.3 m /
# +-10 deg uniform, seed 1), every pair counted (a failure at its guess's
# error).
#  - Where it was made: the rotunda (the bow's scene since the thirtieth
#    session); the ring corridor, the orchard and the mine gallery beside
#    it, static and as written; the static twins also against each pair's
#    Cramer-Rao bound (--pairs, --pair-bounds, scripts/pair-bound-ratios.py).
#  - Held out from the change: the data sets of PCM's extraction benches
#    (bench-common.sh: the office and lab at 1 cm, the apartment, warehouse
#    and garage frozen at 1 cm against the bound and as written, the hall
#    and room with people, the lattices, the bundled log, orebro and the
#    five other Radish logs), the workshop, the office and lab on the
#    lattice.
#  - IDC's time per office pair alone with MRPT's ICP, both ways, three
#    runs in turn.
#  - Whole runs (featloc-run as config.ini has it) in the rotunda, the
#    ring corridor, the corridor with people (seed 1) and the bundled log,
#    each featloc matcher as the matcher chain and in the EKF.
# Usage: scripts/bench-segment-bow.sh [OUTDIR]   (about 17 min on 2 cores, as measured)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-segment-bow "$@"

switch_setup line_bow_per_segment "per segment" true

machine_line
echo
echo "### Where it was made: the rotunda; the ring corridor, the orchard and the mine gallery beside it"
echo
switch_curved_worlds_and_the_rest rotunda ring-corridor orchard mine-gallery
echo
echo "### Time per office pair, IDC with MRPT's ICP alone in the run (three runs each way)"
echo
office_time_two_ways IDC featloc::IdcMatcher "each line alone" "per segment"
echo
echo "### Whole runs: ATE rmse [mm] / failed matches / fallback matches, per segment | each line alone (the default)"
echo
echo "| log | matcher | estimator | per segment | each line alone | each line alone against per segment: mean RPE difference [mm] (95%); steps off only each line alone / only per segment, McNemar |"
echo "|---|---|---|---|---|---|"
switch_whole_runs alone segment \
  "rotunda:$OUT/rotunda.rawlog:$OUT/rotunda.gt.txt" \
  "ring-corridor:$OUT/ring corridor.rawlog:$OUT/ring corridor.gt.txt" \
  "corridor-people-seed1:$OUT/corridor-people-seed1.rawlog:$OUT/corridor-people-seed1.gt.txt" \
  "bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
echo
echo "(raw outputs in $OUT)"
