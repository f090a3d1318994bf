# Sourced by the udpm:// tests: exits 77 (ctest SKIP_RETURN_CODE) with a clear message when
# `unshare -n` is not permitted, and defines the URL and the namespace set-up (DESIGN §7: lo
# only, multicast route on lo, ttl=0; a 4 MB receive buffer, capped by net.core.rmem_max, for
# 614 KB YUYV frames).
if ! unshare -n true 2>/dev/null; then
  echo "SKIPPED: unshare -n is not permitted here (needs root or CAP_SYS_ADMIN)"
  exit 77
fi
# houghloc_wait_running LOG: waits (up to 60 s) until houghloc-node wrote "running" to LOG, i.e.
# has subscribed; building the map takes seconds under the sanitizers, so a fixed sleep before
# publishing would lose the first images. Exported for the namespace's inner bash.
houghloc_wait_running() {
  local _
  for _ in $(seq 600); do
    grep -q "running" "$1" 2>/dev/null && return 0
    sleep 0.1
  done
  echo "houghloc-node did not say 'running' within 60 s: $(cat "$1")" >&2
  return 1
}
export -f houghloc_wait_running
export HOUGHLOC_TEST_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
export HOUGHLOC_NETNS_SETUP="ip link set lo up; ip route add 224.0.0.0/4 dev lo"
