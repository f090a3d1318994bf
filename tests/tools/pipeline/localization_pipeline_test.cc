// LocalizationPipeline against its parts run by hand, on drawn views of an SPL field
// (tests/vision/synthetic_field_image: every pixel from the camera model and the map).
#include "tools/pipeline/localization_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "field_models/standard_fields.h"
#include "tests/vision/synthetic_field_image.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

/// A robot walking along x near the centre circle, 10 frames per second, as a test drive.
struct Walk {
  std::shared_ptr<const FieldModel> field =
      std::make_shared<const FieldModel>(makeStandardField("spl"));
  CameraPreset camera = cameraPreset("nao-top");
  std::vector<Pose2> truth;
  std::vector<cv::Mat> images;

  explicit Walk(int frames) {
    for (int i = 0; i < frames; ++i) {
      truth.emplace_back(-1.2 + 0.05 * i, 0.4, 0.1);
      const CameraModel model(camera.intrinsics, camera.robot_T_camera);
      images.push_back(testing::drawFieldView(model, *field, truth.back()));
    }
  }
  PipelineFrame frame(int i, const std::string& camera_id = "") const {
    // Odometry: the true poses themselves (a cumulative pose in the odometry frame).
    return {100000LL * i, camera_id, camera.robot_T_camera, truth[static_cast<size_t>(i)]};
  }
};

LocalizationHint resetTo(const Pose2& pose, std::int64_t t_us) {
  LocalizationHint hint;
  hint.kind = HintKind::kResetTo;
  hint.t_us = t_us;
  GaussianPose g;
  g.mean = pose;
  g.covariance = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal();
  hint.poses.push_back(g);
  return hint;
}

PipelineConfig withoutCorrection() {
  PipelineConfig config;
  config.vision.pose_correction.enabled = false;
  return config;
}

TEST(LocalizationPipeline, FullModeEqualsVisionAndLocalizerRunByHand) {
  const Walk walk(12);
  const PipelineConfig config =
      withoutCorrection();  // no feedback: the parts alone are the reference
  LocalizationPipeline pipeline(PipelineMode::kFull, walk.field, config);
  pipeline.setCamera("", walk.camera.intrinsics);
  pipeline.queueHint(resetTo(walk.truth[0], 0));

  VisionPipeline vision(walk.camera.intrinsics, config.vision);
  Localizer localizer(*walk.field, config.localizer);
  localizer.applyHint(resetTo(walk.truth[0], 0));
  for (int i = 0; i < 12; ++i) {
    const PipelineResult got = pipeline.process(walk.frame(i), walk.images[i]);
    const VisionResult seen =
        vision.process(walk.images[i], walk.camera.robot_T_camera, 100000LL * i);
    const LocalizationEstimate want =
        localizer.process(100000LL * i, walk.truth[i], {walk.camera.robot_T_camera}, seen.ground);
    ASSERT_EQ(got.estimate.hypotheses.size(), want.hypotheses.size()) << "frame " << i;
    for (size_t k = 0; k < want.hypotheses.size(); ++k) {
      EXPECT_EQ(got.estimate.hypotheses[k].pose.mean.x, want.hypotheses[k].pose.mean.x);
      EXPECT_EQ(got.estimate.hypotheses[k].pose.mean.y, want.hypotheses[k].pose.mean.y);
      EXPECT_EQ(got.estimate.hypotheses[k].pose.mean.theta, want.hypotheses[k].pose.mean.theta);
    }
  }
  // And the track is where the robot is.
  const auto best = pipeline.estimate().best();
  ASSERT_TRUE(best);
  EXPECT_LT((best->mean.translation() - walk.truth.back().translation()).norm(), 0.05);
}

TEST(LocalizationPipeline, TheTrackReachesTheCorrectorOnlyInFullMode) {
  const Walk walk(10);
  for (const PipelineMode mode : {PipelineMode::kFull, PipelineMode::kVisionOnly}) {
    LocalizationPipeline pipeline(mode, walk.field, PipelineConfig{});
    pipeline.setCamera("", walk.camera.intrinsics);
    pipeline.queueHint(resetTo(walk.truth[0], 0));
    int matched_frames = 0;
    for (int i = 0; i < 10; ++i) {
      const SeenFrame seen = pipeline.see(walk.frame(i), walk.images[i]);
      pipeline.locate(seen);
      matched_frames += seen.vision.diagnostics.pose_correction_map_inliers > 0;
    }
    // Frames 0-2 have no lagged estimate yet (track_feedback_lag_frames = 3).
    if (mode == PipelineMode::kFull) {
      EXPECT_GE(matched_frames, 5);
    } else {
      EXPECT_EQ(matched_frames, 0);
    }
  }
}

TEST(LocalizationPipeline, CamerasShareOneCorrectorWhenConfigured) {
  const Walk walk(2);
  for (const bool shared : {false, true}) {
    PipelineConfig config;
    config.vision.pose_correction.shared_between_cameras = shared;
    LocalizationPipeline pipeline(PipelineMode::kVisionOnly, nullptr, config);
    pipeline.setCamera("top", walk.camera.intrinsics);
    pipeline.setCamera("bottom", walk.camera.intrinsics);
    EXPECT_EQ(pipeline.camera("top"), nullptr);  // created at the camera's first frame
    pipeline.process(walk.frame(0, "top"), walk.images[0]);
    pipeline.process(walk.frame(1, "bottom"), walk.images[1]);
    ASSERT_NE(pipeline.camera("top"), nullptr);
    ASSERT_NE(pipeline.camera("bottom"), nullptr);
    EXPECT_EQ(
        &pipeline.camera("top")->poseCorrector() == &pipeline.camera("bottom")->poseCorrector(),
        shared);
  }
}

TEST(LocalizationPipeline, HintsTakeEffectAtTheirTime) {
  const Walk walk(4);
  LocalizationPipeline pipeline(PipelineMode::kFull, walk.field, withoutCorrection());
  pipeline.setCamera("", walk.camera.intrinsics);
  const Pose2 elsewhere(2.5, -1.5, 2.0);
  pipeline.queueHint(resetTo(walk.truth[0], 0));
  pipeline.queueHint(resetTo(elsewhere, 300000));  // due at frame 3
  for (int i = 0; i < 3; ++i) pipeline.process(walk.frame(i), walk.images[i]);
  EXPECT_LT((pipeline.estimate().best()->mean.translation() - walk.truth[2].translation()).norm(),
            0.05);
  // Frame 3 is seen without an image, so only the hint (and a 5 cm odometry step) moves it.
  const PipelineResult at_hint = pipeline.locate(pipeline.seeNothing(walk.frame(3)));
  ASSERT_TRUE(at_hint.estimate.best());
  EXPECT_LT((at_hint.estimate.best()->mean.translation() - elsewhere.translation()).norm(), 0.1);
}

TEST(LocalizationPipeline, AFrameWithoutAnImageOnlyPredicts) {
  const Walk walk(2);
  LocalizationPipeline pipeline(PipelineMode::kFull, walk.field, withoutCorrection());
  pipeline.setCamera("", walk.camera.intrinsics);
  pipeline.queueHint(resetTo(walk.truth[0], 0));
  pipeline.process(walk.frame(0), walk.images[0]);
  const SeenFrame nothing = pipeline.seeNothing(walk.frame(1));  // odometry moved 5 cm
  EXPECT_EQ(nothing.vision.ground.size(), 0u);
  const PipelineResult result = pipeline.locate(nothing);
  ASSERT_TRUE(result.estimate.best());
  const Eigen::Vector2d at = result.estimate.best()->mean.translation();
  EXPECT_LT((at - walk.truth[1].translation()).norm(), 0.01);
  EXPECT_GT((at - walk.truth[0].translation()).norm(), 0.04);
  EXPECT_EQ(result.estimate.points_in, 0);
}

TEST(LocalizationPipeline, TwoThreadsGiveTheResultsOfOne) {
  const Walk walk(12);
  std::vector<PipelineResult> one, two;
  {
    LocalizationPipeline pipeline(PipelineMode::kFull, walk.field, PipelineConfig{});
    pipeline.setCamera("", walk.camera.intrinsics);
    pipeline.queueHint(resetTo(walk.truth[0], 0));
    for (int i = 0; i < 12; ++i) one.push_back(pipeline.process(walk.frame(i), walk.images[i]));
  }
  {
    LocalizationPipeline pipeline(PipelineMode::kFull, walk.field, PipelineConfig{});
    pipeline.setCamera("", walk.camera.intrinsics);
    pipeline.queueHint(resetTo(walk.truth[0], 0));
    std::vector<SeenFrame> seen(12);
    std::mutex mutex;
    std::condition_variable ready;
    int seen_count = 0;
    // Vision in its own thread, ahead of localization as far as the lag lets it.
    std::thread vision([&] {
      for (int i = 0; i < 12; ++i) {
        SeenFrame s = pipeline.see(walk.frame(i), walk.images[i]);
        std::lock_guard<std::mutex> lock(mutex);
        seen[i] = std::move(s);
        ++seen_count;
        ready.notify_one();
      }
    });
    for (int i = 0; i < 12; ++i) {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait(lock, [&] { return seen_count > i; });
      const SeenFrame s = seen[i];
      lock.unlock();
      two.push_back(pipeline.locate(s));
    }
    vision.join();
  }
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_TRUE(one[i].estimate.best() && two[i].estimate.best());
    EXPECT_EQ(one[i].estimate.best()->mean.x, two[i].estimate.best()->mean.x) << i;
  }
}

TEST(LocalizationPipeline, LearningTheTiltFirstCorrectsTheFirstFrames) {
  // The images are drawn at the preset's pose; the recorded pose has the camera pitched 2 deg
  // too little, constant over the walk (a head joint offset).
  const Walk walk(12);
  const double error_rad = 2.0 * M_PI / 180.0;
  const auto recorded = [&](int i) {
    PipelineFrame frame = walk.frame(i);
    frame.robot_T_camera.pitch -= error_rad;
    return frame;
  };
  const double true_pitch = walk.camera.robot_T_camera.pitch;
  LocalizationPipeline plain(PipelineMode::kVisionOnly, walk.field, {});
  LocalizationPipeline learned(PipelineMode::kVisionOnly, walk.field, {});
  for (LocalizationPipeline* p : {&plain, &learned}) p->setCamera("", walk.camera.intrinsics);
  for (int i = 0; i < 12; ++i) learned.learnCameraTilt(recorded(i), walk.images[i]);
  for (int i = 0; i < 3; ++i) {
    const SeenFrame a = plain.see(recorded(i), walk.images[i]);
    const SeenFrame b = learned.see(recorded(i), walk.images[i]);
    EXPECT_EQ(b.sequence, i);  // learning is no step of the run
    // Before its min_frames-th frame (3) the corrector applies nothing; after the learning
    // pass the whole walk's estimate applies from the first frame on.
    if (i < 2) {
      EXPECT_DOUBLE_EQ(a.vision.robot_T_camera_used.pitch, true_pitch - error_rad) << i;
    }
    EXPECT_NEAR(b.vision.robot_T_camera_used.pitch, true_pitch, 0.1 * M_PI / 180.0) << i;
  }
  EXPECT_THROW(learned.learnCameraTilt(walk.frame(0, "other"), walk.images[0]),
               std::invalid_argument);
}

TEST(LocalizationPipeline, RejectsWhatItCannotRun) {
  const Walk walk(1);
  EXPECT_THROW(LocalizationPipeline(PipelineMode::kFull, nullptr, PipelineConfig{}),
               std::invalid_argument);
  LocalizationPipeline pipeline(PipelineMode::kVisionOnly, nullptr, PipelineConfig{});
  EXPECT_THROW(pipeline.see(walk.frame(0, "left"), walk.images[0]), std::invalid_argument);
  pipeline.setCamera("left", walk.camera.intrinsics);
  EXPECT_THROW(pipeline.see(walk.frame(0, "left"), cv::Mat(10, 10, CV_8UC3)),
               std::invalid_argument);
}

}  // namespace
}  // namespace houghloc
