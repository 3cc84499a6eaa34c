#!/usr/bin/env bash
# README command 1: install dependencies, build, and run the main job
# (featloc-run config.ini) on the bundled default data. Extra arguments are
# passed to featloc-run (for example --out DIR or --set Section:key=value).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh"
BUILD_DIR="${FEATLOC_BUILD_DIR:-$ROOT/build}"
cd "$ROOT"
exec "$BUILD_DIR/bin/featloc-run" config.ini "$@"
