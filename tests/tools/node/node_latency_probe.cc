// Measures houghloc-node's latency over LCM (node_latency.sh): records when each IMAGE and each
// HYPOTHESES arrives (CLOCK_MONOTONIC, this process), pairs them by utime, and prints the
// latency from an image's arrival to its hypotheses' arrival (median, p99, max), the same from
// the image's utime (houghloc-play stamps CLOCK_MONOTONIC before it reads and converts the
// image, so that one also holds play's image loading), and the images lost per camera.
//   node_latency_probe [--lcm-url URL] [--channel-prefix P] [--max-lost-percent X]
// Runs until SIGINT/SIGTERM; exit 1 when no image arrived, a camera got no hypotheses at all or
// more than X % (default 100) of the images are lost.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>
#include <vector>

#include "tools/lcm/clock.h"
#include "tools/lcm/stop_signal.h"

namespace {

/// The big-endian int64 utime that follows the 8-byte fingerprint of image_t and
/// pose_hypotheses_t (their first field), read without decoding the 614 KB image.
bool readUtime(const lcm::ReceiveBuffer* buf, std::int64_t* utime) {
  if (buf->data_size < 16) return false;
  const auto* b = static_cast<const std::uint8_t*>(buf->data) + 8;
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | b[i];
  *utime = static_cast<std::int64_t>(v);
  return true;
}

/// image_t's camera_id: int32 length (with the NUL) and the bytes, after the utime.
std::string readCameraId(const lcm::ReceiveBuffer* buf) {
  if (buf->data_size < 20) return "?";
  const auto* b = static_cast<const std::uint8_t*>(buf->data) + 16;
  const std::uint32_t n = (b[0] << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
  if (n == 0 || 20 + n > buf->data_size) return "?";
  return std::string(reinterpret_cast<const char*>(b + 4), n - 1);
}

struct Image {
  std::int64_t received_us;
  std::string camera;
  bool answered = false;
};

struct Probe {
  std::map<std::int64_t, Image> images;  ///< by utime
  std::vector<double> from_arrival_ms, from_utime_ms;

  void onImage(const lcm::ReceiveBuffer* buf, const std::string&) {
    const std::int64_t now = houghloc::monotonicMicros();
    std::int64_t utime = 0;
    if (readUtime(buf, &utime)) images[utime] = {now, readCameraId(buf)};
  }
  void onHypotheses(const lcm::ReceiveBuffer* buf, const std::string&) {
    const std::int64_t now = houghloc::monotonicMicros();
    std::int64_t utime = 0;
    if (!readUtime(buf, &utime)) return;
    const auto it = images.find(utime);
    if (it == images.end() || it->second.answered) return;
    it->second.answered = true;
    from_arrival_ms.push_back(1e-3 * static_cast<double>(now - it->second.received_us));
    from_utime_ms.push_back(1e-3 * static_cast<double>(now - utime));
  }
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(k, 1, v.size()) - 1];
}

}  // namespace

int main(int argc, char** argv) {
  std::string url, prefix;
  double max_lost_percent = 100.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--lcm-url"))
      url = argv[i + 1];
    else if (!std::strcmp(argv[i], "--channel-prefix"))
      prefix = argv[i + 1];
    else if (!std::strcmp(argv[i], "--max-lost-percent"))
      max_lost_percent = std::atof(argv[i + 1]);
    else {
      std::fprintf(stderr, "node_latency_probe: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "node_latency_probe: cannot open LCM URL '%s'\n", url.c_str());
    return 2;
  }
  Probe probe;
  lcm.subscribe(prefix + "IMAGE", &Probe::onImage, &probe);
  lcm.subscribe(prefix + "HYPOTHESES", &Probe::onHypotheses, &probe);
  const std::atomic<bool>& stop = houghloc::installStopSignals();
  while (!stop) lcm.handleTimeout(100);

  std::map<std::string, std::pair<int, int>> per_camera;  // images, lost
  int lost = 0;
  bool every_camera_answered = true;
  for (const auto& [utime, image] : probe.images) {
    auto& [n, l] = per_camera[image.camera];
    ++n;
    l += !image.answered;
    lost += !image.answered;
  }
  const auto images = static_cast<int>(probe.images.size());
  std::int64_t first_us = 0, last_us = 0;
  for (const auto& [utime, image] : probe.images) {
    if (first_us == 0 || image.received_us < first_us) first_us = image.received_us;
    last_us = std::max(last_us, image.received_us);
  }
  const double span_s = 1e-6 * static_cast<double>(last_us - first_us);
  const double lost_percent = images > 0 ? 100.0 * lost / images : 100.0;
  std::printf("images %d in %.2f s (%.1f per second), answered %zu, lost %d (%.2f %%)\n", images,
              span_s, span_s > 0.0 ? (images - 1) / span_s : 0.0, probe.from_arrival_ms.size(),
              lost, lost_percent);
  for (const auto& [camera, counts] : per_camera) {
    std::printf("  camera '%s': images %d, lost %d\n", camera.c_str(), counts.first, counts.second);
    every_camera_answered = every_camera_answered && counts.second < counts.first;
  }
  const auto& a = probe.from_arrival_ms;
  const auto& u = probe.from_utime_ms;
  std::printf("latency image arrival -> hypotheses: median %.2f ms, p99 %.2f ms, max %.2f ms\n",
              quantile(a, 0.5), quantile(a, 0.99), quantile(a, 1.0));
  std::printf("latency image utime -> hypotheses:   median %.2f ms, p99 %.2f ms, max %.2f ms\n",
              quantile(u, 0.5), quantile(u, 0.99), quantile(u, 1.0));
  return images > 0 && every_camera_answered && lost_percent <= max_lost_percent ? 0 : 1;
}
