#include "tools/play/player.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "houghloc/pose_hypotheses_t.hpp"
#include "tools/lcm/clock.h"
#include "tools/lcm/message_conversion.h"
#include "tools/offline/hint_conversion.h"

namespace houghloc {
namespace {

void sleepUntil(std::int64_t t_us) {
  const std::int64_t wait = t_us - monotonicMicros();
  if (wait > 0) std::this_thread::sleep_for(std::chrono::microseconds(wait));
}

}  // namespace

Player::Player(lcm::LCM& lcm, const Recording& recording, const PlayOptions& options)
    : lcm_(lcm), recording_(recording), options_(options), hints_(convertHints(recording)) {
  schedule_ = buildSchedule(recording, hints_.size());
  if (options_.fast) {
    lcm_.subscribeFunction(
        options_.channel_prefix + "HYPOTHESES",
        +[](const lcm::ReceiveBuffer*, const std::string&, const pose_hypotheses_t* msg,
            Player* self) {
          self->last_hypotheses_utime_ = msg->utime;
          ++self->hypotheses_received_;
        },
        this);
  }
}

int Player::playOnce(const std::atomic<bool>& stop) {
  if (schedule_.empty()) return 0;
  const std::int64_t t0 = schedule_.front().t_us;
  const std::int64_t start = std::max(monotonicMicros(), next_base_us_);
  int images = 0;
  std::int64_t utime = start;
  for (const PlayEvent& event : schedule_) {
    if (stop) break;
    utime = start + (event.t_us - t0);
    if (!options_.fast)
      sleepUntil(start + static_cast<std::int64_t>((event.t_us - t0) / options_.speed));
    publish(event, utime);
    if (event.kind == PlayEvent::Kind::kImage) {
      ++images;
      if (options_.fast) waitForHypotheses(utime, stop);
    }
  }
  next_base_us_ = utime + 33'000;  // one frame after the last stamp
  return images;
}

void Player::waitForHypotheses(std::int64_t image_utime, const std::atomic<bool>& stop) {
  const std::int64_t deadline = monotonicMicros() + 1'000'000;
  while (!stop && last_hypotheses_utime_ != image_utime) {
    const std::int64_t left_ms = (deadline - monotonicMicros()) / 1000;
    if (left_ms <= 0) return;
    lcm_.handleTimeout(static_cast<int>(left_ms));
  }
}

void Player::publish(const PlayEvent& event, std::int64_t utime) {
  const std::string& p = options_.channel_prefix;
  switch (event.kind) {
    case PlayEvent::Kind::kOdometry: {
      // buildSchedule() has no odometry event for a row without odometry.
      const odometry_t msg = odometryToMessage(utime, *recording_.frames[event.index].odometry);
      lcm_.publish(p + "ODOMETRY", &msg);
      break;
    }
    case PlayEvent::Kind::kCameraPose: {
      const FrameRecord& frame = recording_.frames[event.index];
      const camera_pose_t msg = cameraPoseToMessage(utime, frame.camera_id, frame.robot_T_camera);
      lcm_.publish(p + "CAMERA_POSE", &msg);
      break;
    }
    case PlayEvent::Kind::kImage: {
      const FrameRecord& frame = recording_.frames[event.index];
      const std::string path = recording_.folder + "/" + frame.image;
      const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
      if (bgr.empty()) throw RecordingError(path + ": cannot read image");
      const image_t msg = imageToMessage(bgr, options_.pixel_format, utime, frame.camera_id);
      lcm_.publish(p + "IMAGE", &msg);
      break;
    }
    case PlayEvent::Kind::kHint: {
      LocalizationHint hint = hints_[event.index];
      hint.t_us = utime;
      const localization_hint_t msg = hintToMessage(hint);
      lcm_.publish(p + "HINT", &msg);
      break;
    }
    case PlayEvent::Kind::kGroundTruth: {
      LocalizationEstimate truth;
      truth.status = TrackerStatus::kTracking;
      EstimateHypothesis h;
      h.pose.mean = recording_.ground_truth[event.index].field_T_robot;
      h.pose.covariance.setZero();
      truth.hypotheses.push_back(h);
      const pose_hypotheses_t msg = hypothesesToMessage(utime, truth);
      lcm_.publish(p + "GROUND_TRUTH", &msg);
      break;
    }
  }
}

}  // namespace houghloc
