#!/usr/bin/env bash
# README command 2: install dependencies, build, and run the whole test suite.
# With --sanitize: the same suite built with AddressSanitizer +
# UndefinedBehaviorSanitizer in build-sanitize/ (a first build takes about
# 13 minutes with the run); any sanitizer report fails its test.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "${1:-}" = "--sanitize" ]; then
  export FEATLOC_BUILD_DIR="${FEATLOC_BUILD_DIR:-$ROOT/build-sanitize}"
  export FEATLOC_BUILD_TYPE=RelWithDebInfo
  export FEATLOC_CMAKE_ARGS="-DFEATLOC_SANITIZE=ON -DFEATLOC_BUILD_BENCHMARKS=OFF"
  # The flags live in the cache: reconfigure (cheap) in case they changed.
  [ -f "$FEATLOC_BUILD_DIR/CMakeCache.txt" ] && cmake "$FEATLOC_BUILD_DIR" $FEATLOC_CMAKE_ARGS > /dev/null
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$ROOT/tests/sanitizer/ubsan.supp}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$ROOT/tests/sanitizer/lsan.supp:print_suppressions=0}"
elif [ -n "${1:-}" ]; then
  echo "usage: scripts/test.sh [--sanitize]" >&2
  exit 2
fi
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh"
BUILD_DIR="${FEATLOC_BUILD_DIR:-$ROOT/build}"
JOBS="${FEATLOC_JOBS:-$(nproc)}"
cd "$BUILD_DIR"
ctest --output-on-failure -j "$JOBS"
