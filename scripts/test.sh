#!/usr/bin/env bash
# README command 2: install dependencies, build, and run the whole test suite.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh"
BUILD_DIR="${FEATLOC_BUILD_DIR:-$ROOT/build}"
JOBS="${FEATLOC_JOBS:-$(nproc)}"
cd "$BUILD_DIR"
ctest --output-on-failure -j "$JOBS"
