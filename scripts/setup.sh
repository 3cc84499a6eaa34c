#!/usr/bin/env bash
# Installs featloc's build and run dependencies from Debian bookworm packages.
# Idempotent: packages already installed are not touched, and apt-get is only
# called when something is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake ccache pkg-config
  libmrpt-dev mrpt-apps mrpt-common
  libopencv-dev libopencv-contrib-dev libeigen3-dev libwxgtk3.2-dev
  nlohmann-json3-dev libyaml-cpp-dev zlib1g-dev jq bc python3
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri
)
# Extra packages a caller needs (scripts/fuzz.sh: clang and its libFuzzer).
PACKAGES+=("$@")

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "[setup] all dependencies already installed"
  exit 0
fi

echo "[setup] installing: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "[setup] done"
