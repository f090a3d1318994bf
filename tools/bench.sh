#!/usr/bin/env bash
# Builds Release (tools/setup.sh, build/) and runs every benchmark binary houghloc-bench-* found
# in build/tools/bench/, one after the other (one core each). Extra arguments go to every binary,
# e.g. tools/bench.sh --benchmark_filter=Locate
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
BUILD_DIR=${HOUGHLOC_BUILD_DIR:-build}
shopt -s nullglob
benches=("$BUILD_DIR"/tools/bench/houghloc-bench-*)
if ((${#benches[@]} == 0)); then
  echo "bench: no houghloc-bench-* in $BUILD_DIR/tools/bench/" >&2
  exit 1
fi
for bench in "${benches[@]}"; do
  [[ -x "$bench" && -f "$bench" ]] || continue
  echo "== $(basename "$bench")"
  "$bench" "$@"
done
