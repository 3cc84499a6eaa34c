#!/usr/bin/env bash
# Reproduces "Issue 15, twenty-eighth session" in doc/benchmarks.md: the
# coarse search's tables with their bounds in bytes (CorrelationTables).
#  - Per pair: one featloc-bench run per data set (the simulated office at
#    1 cm and on MRPT's 0.16 m lattice; orebro, calibration; the five
#    held-out Radish logs), Borges & Aldon's protocol (+-0.3 m / 10 deg,
#    seed 1): PCM, IDC and CF-IDC as config.ini has them, MRPT's ICP in the
#    same run.
#  - With FEATLOC_BASELINE_BIN (the bin/ folder of an earlier build, for
#    example of commit 2d9a896: `git worktree add /tmp/base 2d9a896 &&
#    FEATLOC_BUILD_DIR=/tmp/base/build /tmp/base/scripts/build.sh`), the same
#    runs with its featloc-bench, taking turns with this build's, then
#    whether every pair's outcome (status, error, covariance, reason) is the
#    same both ways, byte for byte; and featloc-run with PCM on the six
#    Radish logs both ways (time per match, ATE).
# Usage: [FEATLOC_BASELINE_BIN=DIR] scripts/bench-search-tables.sh [OUTDIR]
#        (about 3 min on 2 cores, 6 with a baseline)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-search-tables "$@"
[ -d "$LASER2D" ] || { echo "no real logs: $LASER2D not found" >&2; exit 1; }
BASE="${FEATLOC_BASELINE_BIN:-}"
if [ -n "$BASE" ]; then
  for b in featloc-bench featloc-run; do
    [ -x "$BASE/$b" ] || { echo "FEATLOC_BASELINE_BIN: no $BASE/$b" >&2; exit 1; }
  done
fi

M="IcpMatcher (MRPT)=featloc::IcpMatcher,PCM=featloc::PcmFeatureMatcher"
M="$M,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
COMMON="--perturb-xy 0.3 --perturb-yaw-deg 10 --seed 1 -q --paired-with none"
# One featloc-bench run with BIN_DIR/featloc-bench, its pairs in
# $(bench_file NAME).tsv, its main table (header and rows) in
# $(bench_file NAME).table.
run_with() { # bin dir, name, data, extra args...
  local bin="$1" name="$2" data="$3"
  shift 3
  # shellcheck disable=SC2086
  "$bin/featloc-bench" "$ROOT/config.ini" "$data" $COMMON -m "$M" --header --name "$name" "$@" \
    --pairs "$(bench_file "$name").tsv" | main_table > "$(bench_file "$name").table"
}
tables=() same=()
bench() { # name, data, extra args...
  local name="$1"
  run_with "$BIN" "$name" "${@:2}"
  tables+=("$(bench_file "$name").table")
  if [ -n "$BASE" ]; then
    run_with "$BASE" "$name (baseline)" "${@:2}"
    tables+=("$(bench_file "$name (baseline)").table")
    # The data column names the build: the rest is compared.
    diff <(cut -f2- "$(bench_file "$name").tsv") <(cut -f2- "$(bench_file "$name (baseline)").tsv") \
      > "$(bench_file "$name").diff" || true
    local n
    n=$(grep -c '^<' "$(bench_file "$name").diff" || true)
    if [ "$n" = 0 ]; then
      same+=("| $name | identical |")
    else
      same+=("| $name | $n pair outcomes differ (of all four matchers; $(bench_file "$name").diff) |")
    fi
  fi
}

machine_line
sim_1cm office
sim_lattice office office-1cm-lattice --set Laser:range_noise=0.01
bench "sim office (1 cm)" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt"
bench "sim office (1 cm), lattice" "$OUT/office-1cm-lattice.rawlog" -g "$OUT/office-1cm-lattice.gt.txt"
bench orebro "$LASER2D/orebro-corrected.log.gz"
for f in $(held_out_radish_logs); do bench "$(basename "$f" -corrected.log.gz)" "$f"; done

echo
echo "### Per pair"
echo
head -2 "${tables[0]}"
for t in "${tables[@]}"; do tail -n +3 "$t"; done
if [ -n "$BASE" ]; then
  echo
  echo "| data | every pair's outcome, this build against the baseline |"
  echo "|---|---|"
  printf '%s\n' "${same[@]}"
fi

echo
echo "### Whole runs (featloc-run as config.ini has it, PCM; time per match mean / median [ms], ATE rmse [mm])"
echo
if [ -n "$BASE" ]; then
  echo "| log | this build | baseline |"
  echo "|---|---|---|"
else
  echo "| log | this build |"
  echo "|---|---|"
fi
for f in "$LASER2D/orebro-corrected.log.gz" $(held_out_radish_logs); do
  name="$(basename "$f" -corrected.log.gz)"
  bench_featloc_run "$name-pcm" "$f" "" --set "ScanMatcher:class=featloc::PcmFeatureMatcher"
  if [ -n "$BASE" ]; then
    (BIN="$BASE" bench_featloc_run "$name-pcm-baseline" "$f" "" \
      --set "ScanMatcher:class=featloc::PcmFeatureMatcher")
    echo "| $name | $(match_time_and_ate "$name-pcm") | $(match_time_and_ate "$name-pcm-baseline") |"
  else
    echo "| $name | $(match_time_and_ate "$name-pcm") |"
  fi
done
echo
echo "(raw outputs in $OUT)"
