#!/usr/bin/env bash
# Issue 16: runs every libFuzzer target of fuzz/ for SECONDS each (default
# 60) and prints, per target, the executions, the corpus size and what it
# found. featloc is built with clang, ASan + UBSan and libFuzzer's coverage
# in build-fuzz/ (a first build takes a while). Corpora start from the
# shipped files (rawlogs, CARMEN logs, configs, worlds, ground truths) and
# grow in fuzz-corpus/ (not in git); crashers land in fuzz-out/TARGET/.
# An allocation over 1 GiB counts as out of memory and fuzzing goes on.
# The release build refuses a rawlog entry that much memory
# (AllocationCeiling); under ASan the ceiling is off (ASan's own mmaps
# would fail under it), so libFuzzer's malloc limit stands in for it.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SECS="${1:-60}"; shift || true
"$ROOT/scripts/setup.sh" clang libclang-rt-14-dev >/dev/null
BUILD="$ROOT/build-fuzz"
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DFEATLOC_FUZZ=ON -DBUILD_TESTING=OFF -DFEATLOC_BUILD_BENCHMARKS=OFF >/dev/null
fi
TARGETS=(fuzz_rawlog_reader fuzz_carmen_reader fuzz_config fuzz_world_file fuzz_trajectory_file fuzz_scan_matchers fuzz_stereo)
[ $# -gt 0 ] && TARGETS=("$@")
cmake --build "$BUILD" -j "$(nproc)" --target "${TARGETS[@]}" >/dev/null

CORPUS="$ROOT/fuzz-corpus"; OUTDIR="$ROOT/fuzz-out"
seed() { # target, then files to copy (trimmed to 64 kB: libFuzzer mutates small inputs fastest)
  local t="$1"; shift; mkdir -p "$CORPUS/$t"
  for f in "$@"; do [ -f "$f" ] && head -c 65536 "$f" > "$CORPUS/$t/seed-$(basename "$f")"; done; true
}
seed fuzz_rawlog_reader "$ROOT"/rawlogs/sim/*.rawlog "$ROOT"/rawlogs/mrpt-simul/simul.rawlog "$ROOT"/rawlogs/stereo/*.rawlog
for f in "$ROOT"/../shared/data/laser2d/*.log.gz; do
  [ -f "$f" ] || continue
  mkdir -p "$CORPUS/fuzz_carmen_reader"
  # head closes the pipe early: zcat's SIGPIPE is expected.
  zcat "$f" | head -c 65536 > "$CORPUS/fuzz_carmen_reader/seed-$(basename "$f" .gz)" || true
done
seed fuzz_config "$ROOT"/config.ini "$ROOT"/configs/*.ini
mkdir -p "$CORPUS/fuzz_world_file"
for f in "$ROOT"/worlds/*.ini; do { printf '\0'; cat "$f"; } > "$CORPUS/fuzz_world_file/seed-$(basename "$f")"; done
for f in "$ROOT"/worlds/*.yaml; do { printf '\1'; cat "$f"; } > "$CORPUS/fuzz_world_file/seed-$(basename "$f")"; done
seed fuzz_trajectory_file "$ROOT"/rawlogs/*/*.gt.txt "$ROOT"/rawlogs/stereo/*.tum
mkdir -p "$CORPUS/fuzz_scan_matchers" "$CORPUS/fuzz_stereo"
# Stereo: the shipped calibrations (byte 0 even, left NUL right) and a pair
# of vertical bars (byte 0 odd: 64x48 px, 6 px apart, focal 200 px).
S="$ROOT/../shared/data/stereo"
[ -f "$S/rtabmap-indoor-rect/stereo_left.yaml" ] && { printf '\0'; cat "$S/rtabmap-indoor-rect/stereo_left.yaml"; printf '\0'; cat "$S/rtabmap-indoor-rect/stereo_right.yaml"; } > "$CORPUS/fuzz_stereo/seed-rtabmap"
[ -f "$S/euroc-v1-pairs/sensorLeft.yaml" ] && { printf '\0'; cat "$S/euroc-v1-pairs/sensorLeft.yaml"; printf '\0'; cat "$S/euroc-v1-pairs/sensorRight.yaml"; } > "$CORPUS/fuzz_stereo/seed-euroc"
python3 -c "import sys; sys.stdout.buffer.write(bytes([1, 56, 40, 6, 45] + [(230 if (c // 8) % 2 else 30) for c in range(64)]))" > "$CORPUS/fuzz_stereo/seed-bars"

echo "| target | seconds | executions | corpus files | crashes | leaks | timeouts | out of memory |"
echo "|---|---|---|---|---|---|---|---|"
status=0
for t in "${TARGETS[@]}"; do
  rm -rf "${OUTDIR:?}/$t"; mkdir -p "$OUTDIR/$t"
  log="$OUTDIR/$t.log"
  set +e
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS="print_stacktrace=1:suppressions=$ROOT/tests/sanitizer/ubsan.supp" \
    "$BUILD/bin/$t" "$CORPUS/$t" -max_total_time="$SECS" -timeout=30 -rss_limit_mb=4096 \
    -malloc_limit_mb=1024 -max_len=65536 -fork=1 -ignore_ooms=1 -print_final_stats=1 \
    -artifact_prefix="$OUTDIR/$t/" > "$log" 2>&1
  set -e
  # Fork mode (one child at a time): an allocation over 1 GiB is recorded
  # as out-of-memory and fuzzing goes on; the last status line counts
  # every child's executions.
  execs=$(sed -n 's/^#\([0-9][0-9]*\).*/\1/p' "$log" | tail -1)
  count() { find "$OUTDIR/$t" -type f -name "$1-*" | wc -l; }
  crashes=$(count crash); leaks=$(count leak); timeouts=$(count timeout); ooms=$(count oom)
  echo "| $t | $SECS | ${execs:-?} | $(find "$CORPUS/$t" -type f | wc -l) | $crashes | $leaks | $timeouts | $ooms |"
  [ $((crashes + leaks + timeouts + ooms)) -gt 0 ] && status=1
done
exit $status
