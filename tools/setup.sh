#!/usr/bin/env bash
# Installs the Debian 12 packages houghloc needs (only those missing; quiet otherwise), then
# configures and builds the Release tree in build/. Idempotent; run as root on a fresh machine.
#   tools/setup.sh [extra cmake -D options]
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config
  libeigen3-dev libopencv-dev libopencv-contrib-dev nlohmann-json3-dev libcli11-dev
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev openjdk-17-jdk-headless
  googletest libgtest-dev libbenchmark-dev
  libyaml-dev iproute2 util-linux
  qtbase5-dev xvfb
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_DIR=${HOUGHLOC_BUILD_DIR:-build}
JOBS=${HOUGHLOC_JOBS:-$(nproc)}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DHOUGHLOC_BUILD_EDITOR=ON "$@" >/dev/null
LOG="$BUILD_DIR/build.log"
if ! cmake --build "$BUILD_DIR" -j "$JOBS" >"$LOG" 2>&1; then
  grep -E -B2 -A8 "error|Error" "$LOG" | head -n 200 >&2
  echo "setup: build failed, full log in $LOG" >&2
  exit 1
fi
echo "setup: built $BUILD_DIR/" >&2
