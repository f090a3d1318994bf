#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (the `asan` preset: clang-14, ASan + UBSan, in
# build-asan/, the tree the sanitizer tests use) and runs them, each for SECONDS (default 30) and
# HOUGHLOC_JOBS (default: the number of cores) at a time, on
# a copy of its seed corpus tests/fuzz/corpus/<target>/ (new inputs go to
# build-asan/corpus/<target>/, crashes to build-asan/crashes/<target>/). Exits non-zero when a target finds a crash, leak or timeout:
# copy the input into tests/fuzz/corpus/<target>/ so fuzz_replay_<target> keeps it as a test.
# HOUGHLOC_FUZZ_SEED fixes libFuzzer's random seed (.ci/run sets it, so that a CI run explores
# the same inputs on every run instead of failing at random on an input nobody has seen).
#   tools/fuzz.sh [TARGET|all] [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
TARGETS=(field_yaml spl_json camera_yaml recording_csv scenario_yaml vision localizer node)
WHICH=${1:-all}
SECONDS_PER_TARGET=${2:-30}
BUILD_DIR=build-asan
if [[ $WHICH != all ]]; then TARGETS=("$WHICH"); fi

if ! command -v clang++-14 >/dev/null; then
  echo "fuzz: clang++-14 missing (tools/setup.sh installs clang-14 and libfuzzer-14-dev)" >&2
  exit 1
fi
cmake --preset asan >/dev/null
names=()
for t in "${TARGETS[@]}"; do names+=("${t}_fuzz"); done
LOG="$BUILD_DIR/fuzz-build.log"
if ! cmake --build "$BUILD_DIR" -j "${HOUGHLOC_JOBS:-$(nproc)}" --target "${names[@]}" >"$LOG" 2>&1; then
  grep -E -B2 -A8 "error" "$LOG" | head -n 100 >&2
  echo "fuzz: build failed, full log in $LOG" >&2
  exit 1
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# One target per core at a time (each is single-threaded): the same SECONDS per target, in a
# fraction of the wall time. Each target's summary line is printed in the order of TARGETS.
fuzz_one() {
  local t=$1 corpus="$BUILD_DIR/corpus/$1" crashes="$BUILD_DIR/crashes/$1" start result runs
  mkdir -p "$corpus" "$crashes"
  cp -n tests/fuzz/corpus/"$t"/* "$corpus"/
  start=$(date +%s)
  local seed=()
  if [[ -n ${HOUGHLOC_FUZZ_SEED:-} ]]; then seed=(-seed="$HOUGHLOC_FUZZ_SEED"); fi
  if "$BUILD_DIR/tests/fuzz/${t}_fuzz" ${seed[@]+"${seed[@]}"} -max_total_time="$SECONDS_PER_TARGET" -timeout=10 \
      -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$crashes/" -print_final_stats=1 \
      "$corpus" >"$BUILD_DIR/fuzz-$t.log" 2>&1; then
    result=ok
  else
    result="FOUND (see $BUILD_DIR/fuzz-$t.log, inputs in $crashes/)"
  fi
  runs=$(grep -oE "stat::number_of_executed_units: *[0-9]+" "$BUILD_DIR/fuzz-$t.log" | grep -oE "[0-9]+$" || echo "?")
  echo "fuzz: $t $(( $(date +%s) - start )) s, $runs runs, corpus $(ls "$corpus" | wc -l): $result" \
    >"$BUILD_DIR/fuzz-$t.summary"
}

JOBS=${HOUGHLOC_JOBS:-$(nproc)}
rm -f "$BUILD_DIR"/fuzz-*.summary
running=0
for t in "${TARGETS[@]}"; do
  if (( running >= JOBS )); then
    wait -n || true
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
wait
status=0
for t in "${TARGETS[@]}"; do
  summary="$BUILD_DIR/fuzz-$t.summary"
  if [[ ! -f $summary ]]; then
    echo "fuzz: $t stopped before its summary (see $BUILD_DIR/fuzz-$t.log)"
    status=1
    continue
  fi
  cat "$summary"
  if grep -q FOUND "$summary"; then status=1; fi
done
exit $status
