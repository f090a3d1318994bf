#!/usr/bin/env bash
# houghloc-node's latency and CPU use over udpm:// in a network namespace this script creates
# (lo only, ttl=0): houghloc-play publishes two 640x480 YUYV cameras at 30 Hz each (a rendered
# folder whose two cameras take turns at 60 frames/s), houghloc-node runs with its defaults, and
# node_latency_probe pairs each IMAGE with its HYPOTHESES by utime and times both arrivals.
# The node's CPU use is utime + stime of /proc/<pid>/stat (all its threads) over the playback,
# in per cent of one core.
#   node_latency.sh PLAY NODE PROBE FOLDER [MAX_LOST_PERCENT]
# Exit 1 when more than MAX_LOST_PERCENT (default 100: report only) of the images are lost.
set -euo pipefail
play=$1 node=$2 probe=$3 folder=$4 max_lost=${5:-100}
source "$(dirname "$0")/../lcm_netns.sh"
cameras=()
for yaml in "$folder"/cameras/*.yaml; do
  cameras+=(--camera-yaml "$(basename "$yaml" .yaml)=$yaml")
done
unshare -n bash -euo pipefail -c '
  eval "$HOUGHLOC_NETNS_SETUP"
  url=$HOUGHLOC_TEST_URL
  play=$1 node=$2 probe=$3 folder=$4 max_lost=$5
  shift 5
  "$node" --field "$folder/field.yaml" "$@" --lcm-url "$url" &
  node_pid=$!
  probe_out=$(mktemp)
  "$probe" --lcm-url "$url" --max-lost-percent "$max_lost" > "$probe_out" &
  probe_pid=$!
  sleep 2  # the node builds its map data
  ticks() { awk "{print \$14 + \$15}" /proc/$node_pid/stat; }
  t0=$(date +%s%N) c0=$(ticks)
  "$play" "$folder" --lcm-url "$url"
  sleep 0.2  # the last hypotheses
  t1=$(date +%s%N) c1=$(ticks)
  kill -TERM $probe_pid
  probe_rc=0
  wait $probe_pid || probe_rc=$?
  kill -TERM $node_pid
  wait $node_pid
  cat "$probe_out"
  answered=$(sed -nE "s/.*answered ([0-9]+).*/\1/p" "$probe_out")
  rm -f "$probe_out"
  # Per answered image too: play may publish slower than 60 images/s on a loaded machine.
  awk -v c="$((c1 - c0))" -v hz="$(getconf CLK_TCK)" -v ns="$((t1 - t0))" -v n="$answered" \
    "BEGIN { s = c / hz; printf \"houghloc-node CPU: %.1f %% of one core over the run (%.2f s \
CPU in %.2f s); %.2f ms per answered image, i.e. %.1f %% of one core at 60 images/s\\n\", \
      100 * s / (ns * 1e-9), s, ns * 1e-9, 1e3 * s / n, 100 * s / n * 60 }"
  echo "load average at the end: $(cut -d" " -f1-3 /proc/loadavg)"
  exit $probe_rc
' bash "$play" "$node" "$probe" "$folder" "$max_lost" "${cameras[@]}"
