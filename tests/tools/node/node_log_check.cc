// Checks an lcm-logger log of houghloc-play + houghloc-node (node_udpm_test.sh). Exit 0 when:
// - transport: of the images in the log, <= 1 % did not reach the node, i.e. are neither
//   processed nor counted as dropped by the node's last STATUS (its final counters);
// - every processed image has its HYPOTHESES, and the images the node dropped by design (newest
//   wins when it falls behind; slow under sanitizers) are <= MAX_DROPPED_PERCENT (default 10);
// - STATUS about every second, and the best hypothesis within 10 cm and 3 deg of GROUND_TRUTH on
//   >= 95 % of the frames from the first correct one.
//   node_log_check LOG [MAX_DROPPED_PERCENT]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>

#include "houghloc/image_t.hpp"
#include "houghloc/localizer_status_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"

int main(int argc, char** argv) {
  using namespace houghloc;
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: node_log_check LOG [MAX_DROPPED_PERCENT]\n");
    return 2;
  }
  lcm::LogFile file(argv[1], "r");
  if (!file.good()) {
    std::fprintf(stderr, "node_log_check: cannot read %s\n", argv[1]);
    return 2;
  }
  std::map<std::int64_t, pose_hypotheses_t> truth, estimates;
  localizer_status_t last_status{};
  int images = 0, statuses = 0;
  std::int64_t first_ts = -1, last_ts = 0;
  while (const lcm::LogEvent* e = file.readNextEvent()) {
    if (e->channel == "IMAGE") {
      ++images;
      if (first_ts < 0) first_ts = e->timestamp;
      last_ts = e->timestamp;
    } else if (e->channel == "STATUS") {
      ++statuses;
      if (last_status.decode(e->data, 0, e->datalen) != e->datalen) return 3;
    } else if (e->channel == "HYPOTHESES" || e->channel == "GROUND_TRUTH") {
      pose_hypotheses_t msg;
      if (msg.decode(e->data, 0, e->datalen) != e->datalen) return 3;
      (e->channel == "HYPOTHESES" ? estimates : truth)[msg.utime] = msg;
    }
  }
  int scored = 0, correct = 0;
  bool started = false;
  for (const auto& [utime, est] : estimates) {
    const auto t = truth.find(utime);
    if (t == truth.end() || t->second.num_hypotheses != 1) continue;
    bool ok = false;
    if (est.num_hypotheses > 0) {
      const pose_hypothesis_t& a = est.hypotheses[0];
      const pose_hypothesis_t& b = t->second.hypotheses[0];
      const double dtheta = std::remainder(a.theta - b.theta, 2 * M_PI);
      ok = std::hypot(a.x - b.x, a.y - b.y) <= 0.10 && std::abs(dtheta) <= 3.0 * M_PI / 180.0;
    }
    started = started || ok;
    if (!started) continue;
    ++scored;
    correct += ok;
  }
  const double seconds = (last_ts - first_ts) * 1e-6;
  const std::int64_t processed = last_status.frames_processed;
  const std::int64_t dropped = last_status.dropped_old_image + last_status.dropped_no_camera_pose +
                               last_status.dropped_bad_size + last_status.dropped_queue_full;
  const auto percent = [images](double n) { return images > 0 ? 100.0 * n / images : 100.0; };
  const double transport_lost = percent(images - processed - dropped);
  const double dropped_share = percent(dropped);
  const double share = scored > 0 ? static_cast<double>(correct) / scored : 0.0;
  std::printf(
      "images %d, hypotheses %zu, processed %lld, dropped by the node %lld (%.1f %%), lost in "
      "transport %.1f %%, status %d in %.1f s, correct %.1f %% of %d\n",
      images, estimates.size(), static_cast<long long>(processed), static_cast<long long>(dropped),
      dropped_share, transport_lost, statuses, seconds, 100.0 * share, scored);
  const double max_dropped = argc == 3 ? std::atof(argv[2]) : 10.0;
  // Each bound by name, so a failure in CI says which one did not hold.
  const struct {
    bool holds;
    const char* what;
  } bounds[] = {
      {images > 0, "the log has images"},
      {transport_lost <= 1.0, "lost in transport <= 1 %"},
      {static_cast<std::int64_t>(estimates.size()) == processed,
       "one HYPOTHESES per processed image"},
      {dropped_share <= max_dropped, "dropped by the node <= MAX_DROPPED_PERCENT"},
      {statuses >= static_cast<int>(seconds) && statuses <= static_cast<int>(seconds) + 6,
       "STATUS about once a second"},
      {share >= 0.95, "correct on >= 95 % of the frames"},
  };
  bool ok = true;
  for (const auto& bound : bounds) {
    if (!bound.holds) std::printf("node_log_check: failed: %s\n", bound.what);
    ok = ok && bound.holds;
  }
  return ok ? 0 : 1;
}
