#include "tools/offline/lcm_log_replay.h"

#include <algorithm>
#include <cmath>

#include "tools/lcm/lcm_log_reader.h"
#include "tools/lcm/message_decoding.h"
#include "tools/node/node_core.h"

namespace houghloc {
namespace {

/// A log holds what was received: untrusted bytes, decoded as the node decodes them.
template <typename T>
bool decodeEvent(const lcm::LogEvent& event, T* msg) {
  return event.datalen >= 0 &&
         decodeMessage(event.data, static_cast<std::size_t>(event.datalen), *msg);
}

/// A logged pose_hypotheses_t as poses.csv / hypotheses.csv hold it (the doubles unchanged).
FrameEstimate estimateFromMessage(const pose_hypotheses_t& msg) {
  FrameEstimate out;
  out.t_us = msg.utime;
  const bool known =
      msg.status >= pose_hypotheses_t::INITIALIZING && msg.status <= pose_hypotheses_t::LOST;
  out.status = known ? trackerStatusName(static_cast<TrackerStatus>(msg.status)) : "LOST";
  for (const pose_hypothesis_t& h : msg.hypotheses) {
    GaussianPose pose;
    pose.mean = Pose2(h.x, h.y, h.theta);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pose.covariance(r, c) = h.covariance[3 * r + c];
    pose.weight = h.weight;
    out.hypotheses.push_back(pose);
  }
  return out;
}

/// Largest difference between two messages' hypotheses; infinity when they cannot be compared.
double difference(const pose_hypotheses_t& a, const pose_hypotheses_t& b) {
  if (a.status != b.status || a.hypotheses.size() != b.hypotheses.size()) return INFINITY;
  double d = 0.0;
  for (std::size_t i = 0; i < a.hypotheses.size(); ++i) {
    const pose_hypothesis_t& p = a.hypotheses[i];
    const pose_hypothesis_t& q = b.hypotheses[i];
    d = std::max({d, std::abs(p.x - q.x), std::abs(p.y - q.y),
                  std::abs(std::remainder(p.theta - q.theta, 2.0 * M_PI)),
                  std::abs(p.weight - q.weight)});
    for (int k = 0; k < 9; ++k) d = std::max(d, std::abs(p.covariance[k] - q.covariance[k]));
  }
  return d;
}

}  // namespace

LogReplayResult replayLcmLog(const LogReplayInput& input,
                             const std::function<void(int, int)>& progress) {
  const std::string& p = input.channel_prefix;
  LogReplayResult result;
  // First pass: which images the node processed (by utime), and ground truth.
  std::map<std::int64_t, std::vector<pose_hypotheses_t>> logged;
  {
    LcmLogReader reader(input.log_path);
    while (const lcm::LogEvent* e = reader.next()) {
      pose_hypotheses_t msg;
      if (e->channel == p + "HYPOTHESES" && decodeEvent(*e, &msg)) {
        logged[msg.utime].push_back(msg);
        ++result.logged_hypotheses;
      } else if (e->channel == p + "GROUND_TRUTH" && decodeEvent(*e, &msg) &&
                 msg.num_hypotheses == 1) {
        const pose_hypothesis_t& h = msg.hypotheses[0];
        result.ground_truth.push_back({msg.utime, Pose2(h.x, h.y, h.theta)});
      }
    }
  }
  std::stable_sort(result.ground_truth.begin(), result.ground_truth.end(),
                   [](const auto& a, const auto& b) { return a.t_us < b.t_us; });

  // Second pass: the node's inputs in log order.
  NodeCore core(input.field, input.config, input.cameras);
  core.setStaticCameraPoses(input.static_camera_poses, input.config_file);
  LcmLogReader reader(input.log_path);
  while (const lcm::LogEvent* e = reader.next()) {
    const std::string& channel = e->channel;
    if (channel == p + "ODOMETRY") {
      odometry_t msg;
      decodeEvent(*e, &msg) ? core.onOdometry(msg) : core.onUndecodable();
    } else if (channel == p + "CAMERA_POSE") {
      camera_pose_t msg;
      decodeEvent(*e, &msg) ? core.onCameraPose(msg) : core.onUndecodable();
    } else if (channel == p + "HINT") {
      localization_hint_t msg;
      decodeEvent(*e, &msg) ? core.onHint(msg) : core.onUndecodable();
    } else if (channel == p + "IMAGE") {
      ++result.images;
      image_t msg;
      if (!decodeEvent(*e, &msg)) continue;  // the node cannot have processed it either
      const auto it = logged.find(msg.utime);
      if (it == logged.end() || it->second.empty()) continue;  // the node did not process it
      const pose_hypotheses_t reference = it->second.front();
      it->second.erase(it->second.begin());
      const std::optional<NodeOutput> out = core.onImage(msg);
      if (!out) {
        if (result.refused++ == 0) result.first_refusal = core.status().message;
        continue;
      }
      const double d = difference(out->hypotheses, reference);
      if (std::isinf(d))
        ++result.mismatches;
      else
        result.max_difference = std::max(result.max_difference, d);
      result.estimates.push_back(estimateFromMessage(out->hypotheses));
      FrameRecord frame;
      frame.t_us = msg.utime;
      frame.camera_id = msg.camera_id;
      result.frames.push_back(frame);
      if (progress) progress(static_cast<int>(result.estimates.size()), result.logged_hypotheses);
    }
  }
  result.truncated_at = reader.truncatedAt();
  return result;
}

}  // namespace houghloc
