#!/usr/bin/env bash
# houghloc-play -> houghloc-node -> lcm-logger, three processes over udpm:// in a network
# namespace this test creates (lo only, ttl=0); node_log_check then checks the log, and the node
# must exit within 1 s of SIGTERM.
#   node_udpm_test.sh PLAY NODE CHECK FOLDER WORK [JAVAC JAVA CLASSPATH JAVA_SOURCE]
# With the Java arguments, DecodeHypotheses.java compiled against the jar must decode as many
# HYPOTHESES from the log as node_log_check counted.
set -euo pipefail
play=$1 node=$2 check=$3 folder=$4 work=$5
javac=${6:-} java=${7:-} cp=${8:-} java_src=${9:-}
mkdir -p "$work"
source "$(dirname "$0")/../lcm_netns.sh"
log="$work/node_udpm.log"
rm -f "$log" "$work/node_udpm.stderr"
unshare -n bash -euo pipefail -c '
  eval "$HOUGHLOC_NETNS_SETUP"
  url=$HOUGHLOC_TEST_URL
  lcm-logger -q -f --lcm-url="$url" "$1" &
  logger=$!
  "$3" --field "$4/field.yaml" --camera-yaml "$4/camera.yaml" --lcm-url "$url" \
    2> >(tee "$5" >&2) &
  node=$!
  houghloc_wait_running "$5"
  "$2" "$4" --lcm-url "$url"
  sleep 0.5
  start=$(date +%s%N)
  kill -TERM $node
  wait $node
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  echo "houghloc-node exited ${ms} ms after SIGTERM"
  kill -INT $logger
  wait $logger || true
  [ "$ms" -le 1000 ]
' bash "$log" "$play" "$node" "$folder" "$work/node_udpm.stderr"
# node_log_check asserts <= 1 % lost in transport; the images the node dropped by design when it
# fell behind (newest wins) may be up to MAX_DROPPED_PERCENT (10, more under the sanitizers).
summary=$("$check" "$log" "${HOUGHLOC_MAX_DROPPED_PERCENT:-10}") || {
  echo "$summary"
  exit 1
}
echo "$summary"
if [[ -n "$javac" ]]; then
  "$javac" -cp "$cp" -d "$work" "$java_src"
  decoded=$("$java" -cp "$cp:$work" DecodeHypotheses "$log" HYPOTHESES)
  echo "Java DecodeHypotheses: $decoded"
  expected=$(sed -E 's/.*hypotheses ([0-9]+).*/\1/' <<<"$summary")
  [[ "${decoded%% *}" == "$expected" ]]
fi
# houghloc-offline --lcm-log on this log gives the node's logged poses (HOUGHLOC_OFFLINE and
# HOUGHLOC_LOG_CHECK: houghloc-offline and lcm_log_poses_check).
if [[ -n ${HOUGHLOC_OFFLINE:-} ]]; then
  rm -rf "$work/offline_lcm_log"
  "$HOUGHLOC_OFFLINE" --lcm-log "$log" --field "$folder/field.yaml" \
    --camera-yaml "$folder/camera.yaml" -o "$work/offline_lcm_log" --quiet | grep "difference"
  "$HOUGHLOC_LOG_CHECK" "$log" "$work/offline_lcm_log"
fi
# The live viewer (houghloc-fieldmap view, built with the editor) replays this log of
# houghloc-play and houghloc-node: two points of its time slider show different states.
if [[ -n ${HOUGHLOC_VIEWER:-} ]]; then
  for at in 2 8; do
    QT_QPA_PLATFORM=offscreen "$HOUGHLOC_VIEWER" view --log "$log" --at "$at" \
      --screenshot "$work/viewer_$at.png"
    [[ -s "$work/viewer_$at.png" ]]
  done
  if cmp -s "$work/viewer_2.png" "$work/viewer_8.png"; then
    echo "the viewer shows the same state at 2 s and 8 s of the log" >&2
    exit 1
  fi
  echo "viewer: the log replayed at 2 s and 8 s gives two different views"
fi
