#!/usr/bin/env bash
# Builds Release (tools/setup.sh, build/) and runs every benchmark binary houghloc-bench-* found
# in build/tools/bench/, one after the other (one core each). Extra arguments go to every binary,
# e.g. tools/bench.sh --benchmark_filter=Locate
# houghloc-bench-tracking also gets two short rendered recordings (--recording=...), rendered once
# into $BUILD_DIR/bench-recordings/ and then cached.
# With HOUGHLOC_BENCH_JSON_DIR set, each binary also writes DIR/<binary>.json (Google Benchmark's
# JSON format; tools/figures.sh reads them).
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

# Tracking (issue 8): the tracker and the reference MCL on the same rendered recordings, 300
# frames of the plain walk on spl/nao-top and kid/kid-wide, seed 201. Each is rendered again only
# when the scenario, the renderer or the arguments changed (a stamp file holds their checksum).
tracking_recordings=()
render_tracking_recording() {  # NAME STANDARD CAMERA
  local scenario=tools/render/scenarios/tracking_walk.yaml
  local render="$BUILD_DIR/tools/render/houghloc-render" dir="$BUILD_DIR/bench-recordings/$1"
  local args=(--scenario "$scenario" --standard "$2" --camera "$3" --frames 300 --seed 201)
  local stamp
  stamp="$( (cat "$scenario" "$render"; echo "${args[*]}") | sha256sum | cut -d' ' -f1)"
  if [[ ! -f "$dir/.bench-stamp" || "$(cat "$dir/.bench-stamp")" != "$stamp" ]]; then
    echo "bench: rendering $dir (${args[*]}) ..." >&2
    rm -rf "$dir"
    "$render" "${args[@]}" -o "$dir" -q
    echo "$stamp" >"$dir/.bench-stamp"
  fi
  tracking_recordings+=("$dir")
}
if [[ -x "$BUILD_DIR/tools/bench/houghloc-bench-tracking" ]]; then
  render_tracking_recording walk_spl_nao-top spl nao-top
  render_tracking_recording walk_kid_kid-wide kid kid-wide
fi

for bench in "${benches[@]}"; do
  [[ -x "$bench" && -f "$bench" ]] || continue
  echo "== $(basename "$bench")"
  extra=()
  if [[ "$(basename "$bench")" == houghloc-bench-tracking ]]; then
    extra=("--recording=$(IFS=,; echo "${tracking_recordings[*]}")")
  fi
  if [[ -n "${HOUGHLOC_BENCH_JSON_DIR:-}" ]]; then
    mkdir -p "$HOUGHLOC_BENCH_JSON_DIR"
    extra+=("--benchmark_out=$HOUGHLOC_BENCH_JSON_DIR/$(basename "$bench").json"
      --benchmark_out_format=json)
  fi
  "$bench" ${extra[@]+"${extra[@]}"} "$@"
done
