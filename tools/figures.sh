#!/usr/bin/env bash
# Re-measures the project's figures and writes docs/figures.md, so that figures are measured,
# not copied by hand: every benchmark (tools/bench.sh) and every test (ctest, with GoogleTest's
# JSON reports, which hold the figures the tests record), then houghloc-figures turns them into
# one page. Run it on an otherwise idle machine; it takes 15-25 minutes on 2 cores.
#   tools/figures.sh [--bench-only | --tests-only] [-o FILE]   (default docs/figures.md)
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; }
run_bench=1 run_tests=1 out=docs/figures.md
while (($#)); do
  case $1 in
    --bench-only) run_tests=0 ;;
    --tests-only) run_bench=0 ;;
    -o) out=${2:?-o needs a file}; shift ;;
    -h | --help) usage; exit 0 ;;
    *) echo "figures: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done

tools/setup.sh
BUILD_DIR=${HOUGHLOC_BUILD_DIR:-build}
work="$BUILD_DIR/figures"
rm -rf "$work" && mkdir -p "$work/bench" "$work/tests"

args=()
if ((run_bench)); then
  echo "figures: benchmarks (tools/bench.sh) ..." >&2
  HOUGHLOC_BENCH_JSON_DIR="$PWD/$work/bench" tools/bench.sh >"$work/bench.log" 2>&1 ||
    { tail -n 20 "$work/bench.log" >&2; echo "figures: a benchmark failed" >&2; exit 1; }
  args+=(--bench-dir "$work/bench")
fi
if ((run_tests)); then
  # One test at a time: GoogleTest picks a free report name per process, which races otherwise.
  echo "figures: tests (ctest, one at a time) ..." >&2
  status=0
  GTEST_OUTPUT="json:$PWD/$work/tests/" ctest --test-dir "$BUILD_DIR" -j 1 \
    >"$work/tests.log" 2>&1 || status=$?
  tail -n 3 "$work/tests.log" >&2
  ((status == 0)) || echo "figures: some tests failed; the page says which" >&2
  args+=(--test-dir "$work/tests")
fi

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- . ':!docs/figures.md' || commit="$commit + uncommitted changes"
machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
"$BUILD_DIR/tools/figures/houghloc-figures" "${args[@]}" --commit "$commit" \
  --date "$(date -u +%Y-%m-%d)" --machine "$machine" -o "$out"
