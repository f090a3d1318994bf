#!/usr/bin/env bash
# Builds Release (tools/setup.sh) and runs every test: unit, accuracy and slow.
#   tools/test.sh [ctest options, e.g. -L unit]
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
BUILD_DIR=${HOUGHLOC_BUILD_DIR:-build}
cd "$BUILD_DIR"
# Qt widget tests draw offscreen (no display needed).
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
ctest --output-on-failure -j "${HOUGHLOC_JOBS:-$(nproc)}" "$@"
