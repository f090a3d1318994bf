#!/usr/bin/env bash
# The main job on default data it generates (README, first command):
#  1. builds houghloc (tools/setup.sh installs missing Debian packages first),
#  2. writes every standard field map and its top view,
#  3. renders a realistic 10 s SPL recording with the NAO top camera (walk with head sweeps,
#     robots in view, odometry errors, a start hint, one unannounced kidnap) - once, then cached,
#  4. runs houghloc-offline on it (vision + Hough localization + tracking) and prints the summary
#     with the metrics against ground truth, and where trajectory.png and the overlays are.
#   tools/demo.sh [OUTPUT_DIR]   (default: out/demo)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
BUILD_DIR=${HOUGHLOC_BUILD_DIR:-build}
OUT=${1:-out/demo}
mkdir -p "$OUT/fields"

FIELDMAP="$BUILD_DIR/tools/fieldmap/houghloc-fieldmap"
for name in spl spl2019 kid adult msl; do
  "$FIELDMAP" new --standard "$name" -o "$OUT/fields/$name.yaml"
  "$FIELDMAP" validate "$OUT/fields/$name.yaml" > /dev/null
  "$FIELDMAP" render "$OUT/fields/$name.yaml" -o "$OUT/fields/$name.png"
done
echo "Field maps and top views: $OUT/fields/"

# The recording is deterministic for the scenario and the renderer; it is rendered again only
# when either changed (a stamp file holds their checksums).
SCENARIO=tools/render/scenarios/demo_spl.yaml
RECORDING="$OUT/recording"
RENDER="$BUILD_DIR/tools/render/houghloc-render"
STAMP="$(cat "$SCENARIO" "$RENDER" | sha256sum | cut -d' ' -f1)"
if [[ ! -f "$RECORDING/.demo-stamp" || "$(cat "$RECORDING/.demo-stamp")" != "$STAMP" ]]; then
  echo
  echo "Rendering the demo recording ($SCENARIO, 300 frames) into $RECORDING ..."
  rm -rf "$RECORDING"
  "$RENDER" --scenario "$SCENARIO" -o "$RECORDING"
  echo "$STAMP" > "$RECORDING/.demo-stamp"
else
  echo "Using the cached demo recording in $RECORDING"
fi

echo
RESULT="$OUT/result"
"$BUILD_DIR/tools/offline/houghloc-offline" "$RECORDING" -o "$RESULT" --overlay
echo
echo "Trajectory plot (map, ground truth, estimate by status, hypotheses): $RESULT/trajectory.png"
echo "A few overlays (line points, map projected from the estimate, horizon, field boundary):"
for frame in 000030 000150 000185 000290; do
  echo "  $RESULT/overlay/$frame.png"
done
echo "Metrics: $RESULT/metrics.json   Per-frame poses: $RESULT/poses.csv"
