#!/usr/bin/env bash
# Runs the README's example commands as written (every ```bash block right after a line
# `<!-- readme-examples -->`), from a scratch folder that looks like the repository root after
# tools/setup.sh: build/ is this build tree, everything else links to the sources. Each command must
# exit 0; a command ending in `# runs until stopped` is stopped after 3 s and must still be
# running then. Fails when the README has no such block, so the examples cannot drop out of
# the test unnoticed.
#   readme_examples_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
src=${1:?source dir} bin=${2:?binary dir}
readme="$src/README.md"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
ln -s "$bin" "$scratch/build"
for entry in "$src"/*; do
  [[ $(basename "$entry") == build* ]] || ln -s "$entry" "$scratch/$(basename "$entry")"
done

# The example lines, `\` continuations joined; blank and comment-only lines dropped. A trailing
# comment stays: bash ignores it.
mapfile -t commands < <(awk '
  /<!-- readme-examples -->/ { armed = 1; next }
  armed && /^```bash/ { inside = 1; armed = 0; next }
  inside && /^```/ { inside = 0; next }
  inside { print }
' "$readme" | awk '/\\$/ { sub(/\\$/, ""); line = line $0; next } { print line $0; line = "" }' |
  sed -e '/^[[:space:]]*$/d' -e '/^[[:space:]]*#/d')

if ((${#commands[@]} == 0)); then
  echo "readme-examples: $readme has no \`\`\`bash block after <!-- readme-examples -->" >&2
  exit 1
fi
failed=0
cd "$scratch"
for ((i = 0; i < ${#commands[@]}; ++i)); do
  cmd=${commands[i]}
  echo "readme-examples: \$ $cmd"
  if [[ $cmd == *"# runs until stopped"* ]]; then
    bash -c "$cmd" >"$scratch/out.log" 2>&1 &
    pid=$!
    sleep 3
    if kill -0 "$pid" 2>/dev/null; then
      kill -INT "$pid"; wait "$pid" 2>/dev/null
    else
      wait "$pid"; echo "readme-examples: ended early ($?):"; tail -n 20 "$scratch/out.log"
      failed=1
    fi
  elif ! bash -c "$cmd" >"$scratch/out.log" 2>&1; then
    echo "readme-examples: FAILED:"; tail -n 20 "$scratch/out.log"
    failed=1
  fi
done
exit $failed
