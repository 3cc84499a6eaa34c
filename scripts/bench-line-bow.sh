#!/usr/bin/env bash
# Reproduces "Issue 15, thirtieth session" in doc/benchmarks.md: IDC's local
# lines with their bow where their points bow (line_bow_sigmas = 3, the
# default: a local parabola) against straight lines only (line_bow_sigmas =
# 0, as before), set in [ScanMatcher.IdcMatcher] (IDC, and PCM's and
# CF-IDC's IDC fallback) and [ScanMatcher.CfIdcMatcher]. One featloc-bench
# run per data set and setting: PCM, IDC and CF-IDC as config.ini has them,
# and MRPT's ICP; Borges & Aldon's protocol (+-0.3 m / +-10 deg uniform,
# seed 1), every pair counted (a failure at its guess's error).
#  - Where it was found: the rotunda, the ring corridor and the orchard
#    (worlds written in the twenty-ninth session), static and as written;
#    their static twins also against each pair's Cramer-Rao bound
#    (--pairs, --pair-bounds, scripts/pair-bound-ratios.py: the NEES of
#    the right matches, how far from the bound and along which axis).
#  - Held out from the change: the data sets of PCM's extraction benches
#    (bench-common.sh: the office and lab at 1 cm, the apartment, warehouse
#    and garage frozen at 1 cm against the bound and as written, the
#    corridor, hall and room with people, the lattices, the bundled log,
#    orebro and the five other Radish logs), the workshop, the office and
#    lab on the lattice; the static 1 cm scenes also against the bound.
#  - IDC's time per office pair alone with MRPT's ICP, both ways, three
#    runs in turn (the bow is fitted once per line of the reference).
#  - Whole runs (featloc-run as config.ini has it) in the rotunda, the ring
#    corridor, the corridor with people (seed 1) and the bundled log, each
#    featloc matcher as the matcher chain and in the EKF.
# Usage: scripts/bench-line-bow.sh [OUTDIR]   (about 20 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-line-bow "$@"

switch_setup line_bow_sigmas "straight lines"

machine_line
echo
echo "### Where it was found: the rotunda, the ring corridor, the orchard"
echo
switch_curved_worlds_and_the_rest rotunda ring-corridor orchard
echo
echo "### Time per office pair, IDC with MRPT's ICP alone in the run (three runs each way)"
echo
office_time_two_ways IDC featloc::IdcMatcher bow straight
echo
echo "### Whole runs: ATE rmse [mm] / failed matches / fallback matches, straight lines | the bow"
echo
echo "| log | matcher | estimator | straight lines | the bow | the bow against straight lines: mean RPE difference [mm] (95%); steps off only the bow / only straight, McNemar |"
echo "|---|---|---|---|---|---|"
switch_whole_runs bow straight \
  "rotunda:$OUT/rotunda.rawlog:$OUT/rotunda.gt.txt" \
  "ring corridor:$OUT/ring corridor.rawlog:$OUT/ring corridor.gt.txt" \
  "corridor-people-seed1:$OUT/corridor-people-seed1.rawlog:$OUT/corridor-people-seed1.gt.txt" \
  "bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
echo
echo "(raw outputs in $OUT)"
