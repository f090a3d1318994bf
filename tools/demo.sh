#!/usr/bin/env bash
# The main job on default data it generates: builds (tools/setup.sh), writes every standard field
# map and renders its top view. Later stages add the localizer run on a rendered recording.
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
  "$FIELDMAP" validate "$OUT/fields/$name.yaml"
  "$FIELDMAP" render "$OUT/fields/$name.yaml" -o "$OUT/fields/$name.png"
done
echo
echo "Field maps and top views:"
ls -1 "$OUT"/fields/*.png | sed 's/^/  /'
