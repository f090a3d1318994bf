// The hint matrix on rendered recordings (docs/tracking.md "Hint matrix"): vision and
// localization as every tool runs them (LocalizationPipeline), one cell per value of each axis.
// The base walk (spl, nao-top, 0.65 m from the centre mark, hint 0.25 m / 6 deg off, sigma
// 0.5 m) and the walks that change one axis each; the hint at 1 s is built per cell from ground
// truth (the recording's own hint only marks its time). Same assertions as the synthetic matrix.
#include <gtest/gtest.h>

#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "field_models/angles.h"
#include "tests/localization/hint_walk.h"
#include "tools/pipeline/localization_pipeline.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

constexpr int kHintFrame = 30;    // 1.0 s
constexpr int kKidnapFrame = 75;  // the kidnap walk's 2.5 s

struct RenderCell {
  const char* walk;  ///< fixture folder (render_hint_fixtures.cmake)
  double offset_m = 0.25, offset_deg = 6.0, sigma_m = 0.5;
  bool kidnap = false;
};

void PrintTo(const RenderCell& c, std::ostream* os) {
  *os << c.walk << ", hint " << c.offset_m << " m / " << c.offset_deg << " deg off, sigma "
      << c.sigma_m << " m";
}

class HintMatrixRendered : public ::testing::TestWithParam<RenderCell> {};

TEST_P(HintMatrixRendered, CorrectWithinOneSecondNoFlipTwinBelowFloorShare) {
  const RenderCell& cell = GetParam();
  const Recording recording = readRecording(std::string(HOUGHLOC_HINT_FIXTURES) + "/" + cell.walk);
  ASSERT_TRUE(recording.field && recording.camera);
  ASSERT_EQ(recording.ground_truth.size(), recording.frames.size());
  ASSERT_GT(recording.frames.size(), static_cast<size_t>(kKidnapFrame));
  LocalizationPipeline pipeline(PipelineMode::kFull, std::make_shared<FieldModel>(*recording.field),
                                PipelineConfig{});
  pipeline.setCamera("", *recording.camera);
  const Pose2 truth_at_hint = recording.ground_truth[kHintFrame].field_T_robot;
  LocalizationHint hint = testing::placementHint(truth_at_hint, cell.offset_m,
                                                 cell.offset_deg * kDeg, cell.sigma_m, 0.3, 18);
  hint.t_us = recording.frames[kHintFrame].t_us;
  pipeline.queueHint(hint);

  testing::HintCellResult r;
  r.hint_t_us = hint.t_us;
  const int end = cell.kidnap ? kKidnapFrame : static_cast<int>(recording.frames.size());
  for (int k = 0; k < end; ++k) {
    const FrameRecord& record = recording.frames[k];
    ASSERT_EQ(recording.ground_truth[k].t_us, record.t_us);
    const cv::Mat image = cv::imread(recording.folder + "/" + record.image, cv::IMREAD_COLOR);
    ASSERT_FALSE(image.empty()) << record.image;
    PipelineFrame frame;
    frame.t_us = record.t_us;
    frame.camera_id = record.camera_id;
    frame.robot_T_camera = record.robot_T_camera;
    frame.odometry = record.odometry;
    const PipelineResult result = pipeline.process(frame, image);
    if (k >= kHintFrame) r.add(result.estimate, recording.ground_truth[k].field_T_robot);
  }
  RecordProperty("first_correct_ms_after_hint",
                 static_cast<int>(
                     r.first_correct_t_us < 0 ? -1 : (r.first_correct_t_us - r.hint_t_us) / 1000));
  RecordProperty("flips", r.flips);
  RecordProperty("twin_weight_max", std::to_string(r.twin_max));
  EXPECT_TRUE(r.passes(cell.kidnap)) << r.describe();
}

RenderCell cell(const char* walk, double offset_m = 0.25, double offset_deg = 6.0,
                double sigma_m = 0.5, bool kidnap = false) {
  return {walk, offset_m, offset_deg, sigma_m, kidnap};
}

// Every value of every axis once: the base cell, then one axis changed at a time.
INSTANTIATE_TEST_SUITE_P(
    Cells, HintMatrixRendered,
    ::testing::Values(cell("spl_nao-top_centre"), cell("spl_nao-top_centre", 0.0),
                      cell("spl_nao-top_centre", 0.5), cell("spl_nao-top_centre", 0.25, 0.0),
                      cell("spl_nao-top_centre", 0.25, 15.0),
                      cell("spl_nao-top_centre", 0.25, 6.0, 0.1),
                      cell("spl_nao-top_centre", 0.25, 6.0, 1.0), cell("spl_nao-top_penalty"),
                      cell("spl_nao-top_corner"), cell("spl_kid-wide_centre"),
                      cell("spl_wide-pinhole_centre"), cell("kid_nao-top_centre"),
                      cell("small_nao-top_centre"),
                      cell("spl_nao-top_centre_kidnap", 0.25, 6.0, 0.5, true)));

}  // namespace
}  // namespace houghloc
