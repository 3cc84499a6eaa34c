#!/usr/bin/env bash
# Configures (once) and builds featloc in ./build with ccache. Idempotent:
# a second call only rebuilds what changed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${FEATLOC_BUILD_DIR:-$ROOT/build}"
BUILD_TYPE="${FEATLOC_BUILD_TYPE:-Release}"
JOBS="${FEATLOC_JOBS:-$(nproc)}"

if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  # FEATLOC_CMAKE_ARGS: extra configure options (scripts/test.sh --sanitize).
  # shellcheck disable=SC2086
  cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" ${FEATLOC_CMAKE_ARGS:-}
fi
cmake --build "$BUILD_DIR" -j "$JOBS"
