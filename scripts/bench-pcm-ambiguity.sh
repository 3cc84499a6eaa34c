#!/usr/bin/env bash
# Reproduces "Issue 15, seventh session" in doc/benchmarks.md: PCM as
# config.ini has it (fallback_on_ambiguity on: a match the coarse search
# finds ambiguous goes to the IDC fallback too, whose result replaces it
# when it is not ambiguous) against PCM with fallback_on_ambiguity off (the
# sixth session's PCM), beside IDC (with its search) and MRPT's ICP as MRPT
# runs it, in one featloc-bench run per data set; Borges & Aldon's protocol
# (+-0.3 m / +-10 deg uniform, seed 1), every pair counted (a failure at its
# guess's error). PCM takes the paper's fixed Delta_0, as in bench-robust.
#  - Calibration (where the rule was looked at): the simulated office and
#    lab at 1 cm noise, and the real orebro log.
#  - Held out: the corridor with people (+-0.3 m / 10 deg and +-0.5 m /
#    15 deg), the hall with people, the room with doors and a cart, and the
#    other five Radish logs (../shared/data/laser2d or $FEATLOC_LASER2D).
# Usage: scripts/bench-pcm-ambiguity.sh [OUTDIR]   (about 2 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-pcm-ambiguity "$@"

PCM=featloc::PcmFeatureMatcher
M="PCM (config.ini)=$PCM"
M="$M,PCM without fallback_on_ambiguity (before)=$PCM{fallback_on_ambiguity=false}"
M="$M,IdcMatcher=featloc::IdcMatcher"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--set ScanMatcher.PcmFeatureMatcher:initial_bounds_source=config --seed 1 -q"
HEADER=--header
bench() { bench_main_table "" "$@"; }  # name, data, extra args...

machine_line
bench_calibration_and_held_out ""
echo
echo "(raw outputs in $OUT)"
