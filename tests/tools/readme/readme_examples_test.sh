#!/usr/bin/env bash
# Runs the example commands of markdown pages as written (every ```bash block right after a line
# `<!-- readme-examples -->`), from a scratch folder that looks like the repository root after
# tools/setup.sh: build/ is this build tree, everything else links to the sources. Each command must
# exit 0; a command ending in `# runs until stopped` is stopped after 3 s and must still be
# running then. Fails when the pages together have no such block, so the examples cannot drop out
# of the test unnoticed.
#   readme_examples_test.sh SOURCE_DIR BINARY_DIR [PAGE...]
# PAGE: a markdown file relative to SOURCE_DIR, or a glob such as 'docs/*.md' (quoted; expanded
# in SOURCE_DIR); default README.md. Pages run in the order given, blocks in page order.
set -uo pipefail
src=${1:?source dir} bin=${2:?binary dir}
shift 2
patterns=("$@")
((${#patterns[@]})) || patterns=(README.md)

pages=()
for pattern in "${patterns[@]}"; do
  matched=0
  for page in "$src"/$pattern; do
    [[ -f $page ]] || continue
    pages+=("$page")
    matched=1
  done
  if ((!matched)); then
    echo "readme-examples: no page matches $pattern in $src" >&2
    exit 1
  fi
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
ln -s "$bin" "$scratch/build"
for entry in "$src"/*; do
  [[ $(basename "$entry") == build* ]] || ln -s "$entry" "$scratch/$(basename "$entry")"
done

# The example lines of one page, `\` continuations joined; blank and comment-only lines dropped.
# A trailing comment stays: bash ignores it.
examples() {
  awk '
    /<!-- readme-examples -->/ { armed = 1; next }
    armed && /^```bash/ { inside = 1; armed = 0; next }
    inside && /^```/ { inside = 0; next }
    inside { print }
  ' "$1" | awk '/\\$/ { sub(/\\$/, ""); line = line $0; next } { print line $0; line = "" }' |
    sed -e '/^[[:space:]]*$/d' -e '/^[[:space:]]*#/d'
}

commands=()
for page in "${pages[@]}"; do
  mapfile -t page_commands < <(examples "$page")
  ((${#page_commands[@]})) || continue
  echo "readme-examples: ${page#"$src"/}: ${#page_commands[@]} command(s)"
  commands+=("${page_commands[@]}")
done

if ((${#commands[@]} == 0)); then
  echo "readme-examples: no \`\`\`bash block after <!-- readme-examples --> in ${patterns[*]}" >&2
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
