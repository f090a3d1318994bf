// Compares houghloc-offline --lcm-log's outputs with the HYPOTHESES logged by houghloc-node:
// one poses.csv / hypotheses.csv frame per logged HYPOTHESES, same utime, status and number of
// hypotheses, every x, y, theta, covariance entry and weight within 1e-9. Exit 0 when they agree.
//   lcm_log_poses_check LOG OUT_DIR [CHANNEL_PREFIX]
#include <cmath>
#include <cstdio>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>

#include "houghloc/pose_hypotheses_t.hpp"
#include "localization/hypothesis_tracker.h"
#include "tools/offline/estimate_csv.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: lcm_log_poses_check LOG OUT_DIR [CHANNEL_PREFIX]\n");
    return 2;
  }
  const std::string channel = std::string(argc == 4 ? argv[3] : "") + "HYPOTHESES";
  lcm::LogFile file(argv[1], "r");
  if (!file.good()) {
    std::fprintf(stderr, "lcm_log_poses_check: cannot read %s\n", argv[1]);
    return 2;
  }
  std::map<std::int64_t, pose_hypotheses_t> logged;
  while (const lcm::LogEvent* e = file.readNextEvent()) {
    pose_hypotheses_t msg;
    if (e->channel == channel && msg.decode(e->data, 0, e->datalen) == e->datalen)
      logged[msg.utime] = msg;
  }
  const std::vector<FrameEstimate> written = readFrameEstimates(argv[2]);
  int bad = 0;
  double max_difference = 0.0;
  for (const FrameEstimate& got : written) {
    const auto it = logged.find(got.t_us);
    const pose_hypotheses_t* want = it == logged.end() ? nullptr : &it->second;
    if (!want || got.status != trackerStatusName(static_cast<TrackerStatus>(want->status)) ||
        got.hypotheses.size() != want->hypotheses.size()) {
      if (bad++ < 5) std::fprintf(stderr, "t_us %lld: no logged match\n", (long long)got.t_us);
      continue;
    }
    for (std::size_t h = 0; h < got.hypotheses.size(); ++h) {
      const GaussianPose& g = got.hypotheses[h];
      const pose_hypothesis_t& w = want->hypotheses[h];
      double d = std::max({std::abs(g.mean.x - w.x), std::abs(g.mean.y - w.y),
                           std::abs(std::remainder(g.mean.theta - w.theta, 2 * M_PI)),
                           std::abs(g.weight - w.weight)});
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j)
          d = std::max(d, std::abs(g.covariance(i, j) - w.covariance[3 * i + j]));
      max_difference = std::max(max_difference, d);
    }
  }
  std::printf("logged HYPOTHESES %zu, written frames %zu, unmatched %d, max difference %.3g\n",
              logged.size(), written.size(), bad, max_difference);
  return written.size() == logged.size() && bad == 0 && max_difference <= 1e-9 ? 0 : 1;
}
