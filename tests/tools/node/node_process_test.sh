#!/usr/bin/env bash
# houghloc-node as a process: the config file (--print-config, an unknown key), --device on a
# device that does not exist (clear error, retries every 2 s, status says so, keeps running),
# SIGTERM while processing images from houghloc-play over udpm:// in a network namespace this
# test creates (exit within 1 s), and --save-pose restored by the next process.
#   node_process_test.sh PLAY NODE FOLDER WORK
set -euo pipefail
play=$1 node=$2 folder=$3 work=$4
source "$(dirname "$0")/../lcm_netns.sh"
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Stops $1 with SIGTERM and sets ms to how long it took; fails on a non-zero exit.
term() {
  local start rc=0
  start=$(date +%s%N)
  kill -TERM "$1"
  wait "$1" || rc=$?
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  [[ $rc -eq 0 ]] || fail "houghloc-node exited with $rc after SIGTERM"
}

# 1. The config file: --print-config is a config the node accepts; an unknown key is named.
"$node" --print-config > "$work/default.yaml"
grep -q "^node:" "$work/default.yaml" || fail "--print-config has no node: section"
"$node" --config "$work/default.yaml" --field "$folder/field.yaml" \
  --camera-yaml "$folder/camera.yaml" --lcm-url memq:// 2> "$work/default.err" &
pid=$!
for _ in $(seq 100); do grep -q "running" "$work/default.err" && break; sleep 0.1; done
term $pid
grep -q "running" "$work/default.err" || fail "$(cat "$work/default.err")"
printf 'node:\n   camera_yamls: x.yaml\n' > "$work/bad.yaml"
if "$node" --config "$work/bad.yaml" --standard spl 2> "$work/bad.err"; then
  fail "an unknown key in node: was accepted"
fi
grep -q "bad.yaml: node.camera_yamls: unknown key" "$work/bad.err" || fail "$(cat "$work/bad.err")"
echo "config: the node starts with --print-config's file; an unknown key is named: $(cat "$work/bad.err")"

# 2. --device on a device that does not exist, its camera and the device in the config file.
missing=/dev/houghloc-missing-video9
printf 'node:\n   camera_yaml: top=%s\n   device: top=%s\n   log_level: debug\n' \
  "$folder/camera.yaml" "$missing" > "$work/device.yaml"
"$node" --config "$work/device.yaml" --field "$folder/field.yaml" --lcm-url memq:// \
  2> "$work/device.err" &
pid=$!
# Timed from "running" (building the map takes seconds under the sanitizers): the first
# attempt, then retries at 2 s and 4 s.
for _ in $(seq 600); do grep -q "running" "$work/device.err" && break; sleep 0.1; done
sleep 5
kill -0 $pid 2>/dev/null || fail "houghloc-node exited: $(cat "$work/device.err")"
term $pid
problem="camera 'top': $missing does not exist; retrying every 2 s"
warned=$(grep -cF "warn: $problem" "$work/device.err" || true)
retried=$(grep -cF "debug: $problem" "$work/device.err" || true)
in_status=$(grep -cF "warn: status: $problem" "$work/device.err" || true)
echo "device: warned $warned, retried $retried times in 5 s of running, status $in_status, exit ${ms} ms after SIGTERM"
[[ $warned -eq 1 && $retried -ge 2 && $in_status -ge 1 && $ms -le 1000 ]] || \
  fail "$(cat "$work/device.err")"

# 3. SIGTERM while processing, then a second node restores the saved pose.
pose="$work/pose.yaml"
rm -f "$work/run1.err"
unshare -n bash -euo pipefail -c '
  eval "$HOUGHLOC_NETNS_SETUP"
  url=$HOUGHLOC_TEST_URL
  "$2" --field "$3/field.yaml" --camera-yaml "$3/camera.yaml" --lcm-url "$url" \
    --save-pose "$4" --log-level info 2> "$1/run1.err" &
  node=$!
  houghloc_wait_running "$1/run1.err"
  "$5" "$3" --lcm-url "$url" &
  play=$!
  sleep 4
  start=$(date +%s%N)
  kill -TERM $node
  wait $node
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$1/term_ms"
  kill -TERM $play
  wait $play || true
' bash "$work" "$node" "$folder" "$pose" "$play"
ms=$(cat "$work/term_ms")
images=$(sed -nE 's/.*stopped after ([0-9]+) images.*/\1/p' "$work/run1.err")
echo "SIGTERM while processing: exit ${ms} ms after it, ${images:-0} images processed"
grep -qE "state (TRACKING|AMBIGUOUS)" "$work/run1.err" || fail "never localized: $(cat "$work/run1.err")"
[[ ${images:-0} -gt 30 && $ms -le 1000 ]] || fail "$(cat "$work/run1.err")"
[[ -s "$pose" && ! -e "$pose.tmp" ]] || fail "no pose saved in $pose"

value() { awk -v k="$1:" '$1 == k { printf "%.6f", $2 }' "$pose"; }
saved="$(value x) $(value y) $(value theta)"
"$node" --field "$folder/field.yaml" --camera-yaml "$folder/camera.yaml" --lcm-url memq:// \
  --save-pose "$pose" 2> "$work/run2.err" &
pid=$!
for _ in $(seq 100); do grep -q "restored pose" "$work/run2.err" && break; sleep 0.1; done
term $pid
restored=$(sed -nE 's/.*restored pose ([^ ]+ [^ ]+ [^ ]+) from .*/\1/p' "$work/run2.err")
echo "save-pose: saved ($saved), restored ($restored)"
[[ -n "$restored" && "$restored" == "$saved" ]] || fail "$(cat "$work/run2.err")"
