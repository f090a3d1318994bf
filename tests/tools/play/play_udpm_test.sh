#!/usr/bin/env bash
# houghloc-play -> lcm-logger across processes over udpm:// inside a network namespace this
# test creates (DESIGN §7: lo only, ttl=0, nothing leaves the machine); play_log_test then checks
# that the log holds every message (no 614 KB YUYV frame lost in fragments) and Java decodes it.
#   play_udpm_test.sh PLAY_EXE FIXTURE_FOLDER WORK_DIR PLAY_LOG_TEST_EXE
set -euo pipefail
play=$1 folder=$2 work=$3 checker=$4
mkdir -p "$work"
source "$(dirname "$0")/../lcm_netns.sh"
log="$work/udpm.log"
rm -f "$log"
unshare -n bash -euo pipefail -c '
  eval "$HOUGHLOC_NETNS_SETUP"
  url=$HOUGHLOC_TEST_URL
  lcm-logger -q -f --lcm-url="$url" "$1" &
  logger=$!
  sleep 0.5
  "$2" "$3" --lcm-url "$url" --channel-prefix T_ 2>&1
  sleep 0.3
  kill -INT $logger
  wait $logger || true
' bash "$log" "$play" "$folder"
HOUGHLOC_PLAY_LOG="$log" "$checker"
