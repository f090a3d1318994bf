// Shared by the in-process node tests: the rendered one-camera walk (node_render_fixtures), its
// frames as messages, and scoring hypotheses against its ground truth.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <opencv2/imgcodecs.hpp>

#include "tools/lcm/message_conversion.h"
#include "tools/node/node_core.h"
#include "tools/recording/recording.h"

namespace houghloc {

class NodeFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rec_ = std::make_unique<Recording>(readRecording(HOUGHLOC_NODE_WALK));
    for (const FrameRecord& f : rec_->frames) cameras_[f.camera_id] = rec_->intrinsicsFor(f);
  }
  static void TearDownTestSuite() { rec_.reset(); }

  std::unique_ptr<NodeCore> makeCore() const {
    return std::make_unique<NodeCore>(std::make_shared<const FieldModel>(*rec_->field),
                                      PipelineConfig{}, cameras_);
  }
  /// Frame i's image as the robot sends it (YUYV), stamped `utime`.
  static image_t image(std::size_t i, std::int64_t utime) {
    const FrameRecord& f = rec_->frames[i];
    const cv::Mat bgr = cv::imread(rec_->folder + "/" + f.image, cv::IMREAD_COLOR);
    return imageToMessage(bgr, image_t::PIXEL_FORMAT_YUYV, utime, f.camera_id);
  }
  static const FrameRecord& frame(std::size_t i) { return rec_->frames[i]; }
  static std::size_t frames() { return rec_->frames.size(); }

  /// The best hypothesis within 10 cm and 3 deg of ground truth at frame i.
  static bool correct(std::size_t i, const pose_hypotheses_t& h) {
    const std::optional<Pose2> truth = groundTruthAt(rec_->ground_truth, frame(i).t_us);
    if (!truth || h.num_hypotheses == 0) return false;
    const pose_hypothesis_t& b = h.hypotheses[0];
    return std::hypot(b.x - truth->x, b.y - truth->y) <= 0.10 &&
           std::abs(std::remainder(b.theta - truth->theta, 2 * M_PI)) <= 3.0 * M_PI / 180.0;
  }
  /// Share of correct frames among `results` (frame index -> hypotheses) from the first correct
  /// one on; `first` gets that frame's index.
  static double shareCorrect(const std::map<std::size_t, pose_hypotheses_t>& results,
                             std::size_t* first = nullptr) {
    int scored = 0, good = 0;
    bool started = false;
    for (const auto& [i, h] : results) {
      const bool ok = correct(i, h);
      if (ok && !started && first) *first = i;
      started = started || ok;
      scored += started;
      good += started && ok;
    }
    return scored > 0 ? static_cast<double>(good) / scored : 0.0;
  }

  static std::unique_ptr<Recording> rec_;
  static std::map<std::string, CameraIntrinsics> cameras_;
};

inline std::unique_ptr<Recording> NodeFixture::rec_;
inline std::map<std::string, CameraIntrinsics> NodeFixture::cameras_;

}  // namespace houghloc
