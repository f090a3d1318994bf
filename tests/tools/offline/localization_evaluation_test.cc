#include "tools/offline/localization_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "field_models/angles.h"
#include "field_models/standard_fields.h"
#include "tools/offline/evaluation_frames.h"

namespace houghloc {
namespace {

constexpr std::int64_t kStepUs = 100000;  // 10 frames per second

/// A recording of `n` frames 100 ms apart with ground truth at each frame.
OfflineContext makeContext(int n, const std::function<Pose2(int)>& truth) {
  OfflineContext c;
  for (int i = 0; i < n; ++i) {
    FrameRecord f;
    f.t_us = 1000000 + kStepUs * i;
    c.recording.frames.push_back(f);
    c.recording.ground_truth.push_back({f.t_us, truth(i)});
  }
  c.first_frame = 0;
  c.end_frame = n;
  return c;
}

GaussianPose gaussian(const Pose2& mean, double sigma_m = 0.05) {
  GaussianPose g;
  g.mean = mean;
  g.covariance = Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, 0.01).asDiagonal();
  return g;
}

FrameEstimate estimate(std::int64_t t_us, const std::string& status,
                       const std::vector<Pose2>& poses) {
  FrameEstimate e{t_us, status, {}};
  for (const Pose2& p : poses) e.hypotheses.push_back(gaussian(p));
  return e;
}

void addVisible(OfflineContext* c, int frame, const std::string& feature, double length_m,
                double direction_deg) {
  c->recording.visible.push_back(
      {c->recording.frames[static_cast<size_t>(frame)].t_us, feature, length_m, direction_deg});
}

TEST(ClassifyView, TwoDirectionsParallelOnlyAndCircle) {
  const FieldModel field = makeStandardField("spl");
  ASSERT_TRUE(field.arcs.at(0).isFullCircle());  // the centre circle
  auto view = [&](std::vector<std::tuple<std::string, double, double>> rows, const FieldModel* f) {
    std::vector<VisibleRecord> records;
    for (const auto& [feature, length, direction] : rows) {
      records.push_back({0, feature, length, direction});
    }
    return classifyView(records, f);
  };
  EXPECT_EQ(view({}, &field), FrameView::kUnknown);
  EXPECT_EQ(view({{"segments[0]", 0.6, 0.0}, {"segments[1]", 0.5, 90.0}}, &field),
            FrameView::kTwoDirections);
  EXPECT_EQ(view({{"segments[0]", 0.6, 0.0}, {"segments[1]", 0.49, 90.0}}, &field),
            FrameView::kParallelOnly);
  EXPECT_EQ(view({{"segments[0]", 0.3, 0.0}, {"segments[1]", 0.3, 0.0}}, &field),
            FrameView::kParallelOnly);  // two parallel segments add up
  // 179 deg and 1 deg are the same undirected direction, 2 deg apart.
  EXPECT_EQ(
      view({{"segments[0]", 0.3, 179.0}, {"segments[1]", 0.3, 1.0}, {"segments[2]", 0.5, 90.0}},
           &field),
      FrameView::kTwoDirections);
  EXPECT_EQ(view({{"segments[0]", 0.6, 0.0}, {"segments[1]", 0.6, 29.0}}, &field),
            FrameView::kParallelOnly);  // less than 30 deg apart
  EXPECT_EQ(view({{"segments[0]", 0.6, 0.0}, {"segments[1]", 0.6, 31.0}}, &field),
            FrameView::kTwoDirections);
  EXPECT_EQ(view({{"segments[0]", 0.4, 0.0}, {"marks[0]", 0.2, 0.0}}, &field), FrameView::kNoLines);
  EXPECT_EQ(view({{"arcs[0]", 1.0, 0.0}}, &field), FrameView::kTwoDirections);
  EXPECT_EQ(view({{"arcs[0]", 0.9, 0.0}}, &field), FrameView::kNoLines);
  FieldModel corner_arc = field;  // an arc that is not the centre circle does not count
  corner_arc.arcs[0].center = {4.5, 3.0};
  EXPECT_EQ(view({{"arcs[0]", 1.5, 0.0}}, &corner_arc), FrameView::kNoLines);
  EXPECT_EQ(view({{"arcs[0]", 1.5, 0.0}}, nullptr), FrameView::kTwoDirections);
}

TEST(PoseChecks, CorrectFlipAndMahalanobis) {
  const Pose2 truth(1.2, 0.5, 0.0);
  EXPECT_TRUE(isCorrect(Pose2(1.29, 0.5, 2.9 * kDeg), truth));
  EXPECT_FALSE(isCorrect(Pose2(1.31, 0.5, 0.0), truth));
  EXPECT_FALSE(isCorrect(Pose2(1.2, 0.5, 3.1 * kDeg), truth));
  EXPECT_TRUE(isCorrectUpToSymmetry(Pose2(-1.2, -0.5, M_PI), truth));
  EXPECT_TRUE(isFlip(Pose2(-1.2, -0.5, M_PI), truth));
  // Near the centre the twin is close: 0.4 m away is not a flip (<= 0.5 m from the truth).
  EXPECT_FALSE(isFlip(Pose2(-0.2, 0.0, M_PI), Pose2(0.2, 0.0, 0.0)));
  GaussianPose g = gaussian(Pose2(0.0, 0.0, 0.0));
  g.covariance = Eigen::Vector3d(4.0, 0.01, 0.04).asDiagonal();  // sigma 2 m along x
  EXPECT_NEAR(mahalanobisDistance(g, Pose2(3.0, 0.0, 0.0)), 1.5, 1e-12);
  EXPECT_NEAR(mahalanobisDistance(g, Pose2(0.0, 0.1, 0.2)), std::sqrt(2.0), 1e-12);
  g.covariance.setZero();
  EXPECT_TRUE(std::isinf(mahalanobisDistance(g, Pose2(0.0, 0.0, 0.0))));
}

TEST(Statistics, MedianAndNearestRankPercentile) {
  EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(median({4.0, 1.0, 2.0, 3.0}), 2.5);
  std::vector<double> twenty;
  for (int i = 1; i <= 20; ++i) twenty.push_back(i);
  EXPECT_EQ(percentile(twenty, 0.95), 19.0);  // ceil(0.95 * 20) = 19th value
  EXPECT_EQ(percentile({5.0}, 0.95), 5.0);
  EXPECT_EQ(median({}), 0.0);
}

// 100 frames: frames 0-4 without a pose; 5-49 tracked with 2 cm / 1 deg error except frame 10
// (0.3 m off) and frame 20 (flipped); a kidnap at frame 50 (recovered at 60), a fall from 85 to
// 90 (recovered at 92, flipped). Evaluated: 5-49 and 80-84 (kidnap window 50-79, fall window
// 85-119), 50 frames.
TEST(TrackingMetrics, ErrorsRatesFlipsExclusionAndRecovery) {
  auto truth = [](int i) {
    return i < 50 ? Pose2(1.0 + 0.01 * i, 0.5, 0.0) : Pose2(-2.0 + 0.01 * i, -1.0, 0.5);
  };
  OfflineContext c = makeContext(100, truth);
  auto t = [&](int i) { return c.recording.frames[static_cast<size_t>(i)].t_us; };
  c.recording.events = {{t(50) - 10, "KIDNAP"}, {t(85), "FALL_START"}, {t(90) - 50000, "FALL_END"}};
  std::vector<FrameEstimate> estimates;
  for (int i = 0; i < 100; ++i) {
    const Pose2 g = truth(i);
    std::vector<Pose2> poses;
    if (i < 5 || i == 90 || i == 91) {
      poses = {};
    } else if (i == 10) {
      poses = {Pose2(g.x + 0.3, g.y, g.theta)};
    } else if (i == 20) {
      poses = {mirrored(g), g};  // flipped best, correct second
    } else if (i >= 50 && i < 60) {
      poses = {truth(49), g};  // best still where it was before the kidnap
    } else if (i >= 92) {
      poses = {mirrored(g)};
    } else if (i >= 80) {
      poses = {Pose2(g.x, g.y + 0.05, g.theta + 2.0 * kDeg)};
    } else {
      poses = {Pose2(g.x + 0.02, g.y, g.theta - 1.0 * kDeg)};
    }
    estimates.push_back(estimate(t(i),
                                 i < 5           ? "INITIALIZING"
                                 : poses.empty() ? "LOST"
                                                 : "TRACKING",
                                 poses));
  }
  estimates.pop_back();  // frame 99 has no row: MISSING, and outside the evaluated frames
  // Two-direction frames 5 (correct), 20 (flipped best) and 55 (wrong best, correct second).
  for (int f : {5, 20, 55}) {
    addVisible(&c, f, "segments[0]", 1.0, 0.0);
    addVisible(&c, f, "segments[1]", 1.0, 90.0);
  }

  const auto m = computeTrackingMetrics(c, estimates);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->frames_scored, 100);
  EXPECT_EQ(m->frames_evaluated, 50);
  EXPECT_EQ(m->frames_without_pose, 0);
  // Sorted position errors: 43 x 0.02, 5 x 0.05, 0.3, 2.6 (flip: twice |(1.2, 0.5)|).
  EXPECT_NEAR(m->median_position_error_m, 0.02, 1e-9);
  EXPECT_NEAR(m->p95_position_error_m, 0.05, 1e-9);  // 48th of 50
  EXPECT_NEAR(m->max_position_error_m, 2.6, 1e-9);
  // Sorted heading errors: 0 (frame 10), 43 x 1, 5 x 2, 180 deg.
  EXPECT_NEAR(m->median_heading_error_deg, 1.0, 1e-9);
  EXPECT_NEAR(m->p95_heading_error_deg, 2.0, 1e-9);
  EXPECT_NEAR(m->max_heading_error_deg, 180.0, 1e-9);
  EXPECT_NEAR(m->p95_position_error_up_to_symmetry_m, 0.05, 1e-9);
  EXPECT_DOUBLE_EQ(m->correct_rate, 48.0 / 50.0);
  EXPECT_DOUBLE_EQ(m->correct_up_to_symmetry_rate, 49.0 / 50.0);
  EXPECT_EQ(m->flips, 1);
  EXPECT_EQ(m->first_correct_frame, 5);
  EXPECT_DOUBLE_EQ(m->first_correct_s, 0.5);
  EXPECT_EQ(m->first_correct_up_to_symmetry_frame, 5);
  ASSERT_EQ(m->recovery_frames.size(), 2u);
  EXPECT_EQ(m->recovery_events[0], "KIDNAP");
  EXPECT_EQ(m->recovery_frames[0], 10);
  EXPECT_EQ(m->recovery_events[1], "FALL_END");
  EXPECT_EQ(m->recovery_frames[1], 2);
  EXPECT_EQ(m->frames_two_directions, 3);
  EXPECT_DOUBLE_EQ(m->two_direction_correct_any_rate, 1.0);
  EXPECT_DOUBLE_EQ(m->two_direction_best_correct_rate, 2.0 / 3.0);
  const std::vector<std::pair<std::string, int>> counts = {
      {"INITIALIZING", 5}, {"TRACKING", 92}, {"AMBIGUOUS", 0}, {"LOST", 2}, {"MISSING", 1}};
  EXPECT_EQ(m->status_counts, counts);

  // A range that starts inside the kidnap window: frames 70-79 stay excluded.
  c.first_frame = 70;
  c.end_frame = 85;
  const auto part = computeTrackingMetrics(c, estimates);
  EXPECT_EQ(part->frames_evaluated, 5);     // 80-84
  EXPECT_EQ(part->first_correct_frame, 0);  // frame 70 is correct, counted from the range start
  EXPECT_TRUE(part->recovery_frames.empty());

  c.recording.ground_truth.clear();
  EXPECT_FALSE(computeTrackingMetrics(c, estimates));
}

TEST(CorrectRank, ATwinOrANearCopySharesTheRankOfItsPair) {
  const Pose2 truth(1.0, 0.8, 0.3);
  const Pose2 wrong(-3.0, 2.0, 1.0);
  const Pose2 near_wrong(-3.05, 2.0, 1.0);  // within 0.10 m / 3 deg of the wrong pose
  const Pose2 other(2.5, -1.0, 0.2);
  CorrectRank r = correctRankUpToSymmetry({wrong, mirrored(wrong), truth}, truth);
  EXPECT_EQ(r.index, 2);
  EXPECT_EQ(r.answer, 1);  // in the top two
  r = correctRankUpToSymmetry({wrong, near_wrong, other, mirrored(truth)}, truth);
  EXPECT_EQ(r.index, 3);
  EXPECT_EQ(r.answer, 2);
  r = correctRankUpToSymmetry({mirrored(truth), truth}, truth);
  EXPECT_EQ(r.index, 0);
  EXPECT_EQ(r.answer, 0);
  r = correctRankUpToSymmetry({wrong, other}, truth);
  EXPECT_EQ(r.index, -1);
  EXPECT_EQ(r.answer, -1);
  EXPECT_EQ(correctRankUpToSymmetry({}, truth).index, -1);
}

// Ten frames: 0-5 with two directions, 6-7 parallel only, 8-9 without lines, 10 without ground
// truth within 20 ms.
TEST(GlobalMetrics, RatesRanksErrorsAndParallelOnly) {
  OfflineContext c = makeContext(11, [](int i) { return Pose2(1.0 + 0.1 * i, 0.8, 0.3); });
  c.recording.frames[10].t_us += 30000;  // 30 ms after its ground truth row
  c.recording.ground_truth.pop_back();
  auto truth = [&](int i) {
    return c.recording.ground_truth[static_cast<size_t>(i)].field_T_robot;
  };
  auto t = [&](int i) { return c.recording.frames[static_cast<size_t>(i)].t_us; };
  auto off = [&](int i, double dx, double dtheta_deg) {
    const Pose2 g = truth(i);
    return Pose2(g.x + dx, g.y, g.theta + dtheta_deg * kDeg);
  };
  const Pose2 far(-3.0, 2.0, 1.0);
  std::vector<FrameEstimate> e;
  e.push_back(estimate(t(0), "TRACKING", {off(0, 0.01, 0.5), far}));
  e.push_back(estimate(t(1), "AMBIGUOUS", {far, mirrored(off(1, 0.02, 1.0))}));
  // The twin of a wrong pose is the same answer: the correct pose, fourth in the list, ranks 2.
  const Pose2 other(2.5, -1.0, 0.2);
  e.push_back(estimate(t(2), "AMBIGUOUS", {far, mirrored(far), other, off(2, -0.03, -1.5)}));
  e.push_back(estimate(t(3), "AMBIGUOUS", {far, off(3, 0.2, 0.0)}));
  e.push_back(estimate(t(4), "LOST", {}));
  e.push_back(estimate(t(5), "TRACKING", {off(5, 0.05, 2.0)}));
  for (int i = 0; i <= 5; ++i) {
    addVisible(&c, i, "segments[0]", 2.0, 0.0);
    addVisible(&c, i, "segments[3]", 0.7, 90.0);
  }
  // Parallel lines along x: the hypothesis is long along x (sigma 1 m).
  GaussianPose line = gaussian(off(6, 2.0, 0.0));
  line.covariance(0, 0) = 1.0;
  e.push_back({t(6), "AMBIGUOUS", {line}});
  line.mean = off(7, 4.0, 0.0);  // 4 sigma off
  e.push_back({t(7), "AMBIGUOUS", {line}});
  for (int i : {6, 7}) addVisible(&c, i, "segments[0]", 2.0, 0.0);
  e.push_back(estimate(t(8), "TRACKING", {}));
  e.push_back(estimate(t(9), "TRACKING", {}));
  e.push_back(estimate(t(10), "TRACKING", {truth(9)}));
  addVisible(&c, 8, "segments[0]", 0.2, 0.0);

  const auto m = computeGlobalMetrics(c, e);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->frames_scored, 10);
  EXPECT_EQ(m->frames_two_directions, 6);
  EXPECT_DOUBLE_EQ(m->correct_any_rate, 4.0 / 6.0);  // frames 0, 1, 2, 5
  EXPECT_DOUBLE_EQ(m->correct_top2_rate, 3.0 / 6.0);
  EXPECT_DOUBLE_EQ(m->correct_best_rate, 2.0 / 6.0);
  EXPECT_DOUBLE_EQ(m->mean_correct_rank, 3.0 / 4.0);     // ranks 0, 1, 2, 0
  EXPECT_NEAR(m->median_position_error_m, 0.025, 1e-9);  // 0.01, 0.02, 0.03, 0.05
  EXPECT_NEAR(m->median_heading_error_deg, 1.25, 1e-9);  // 0.5, 1, 1.5, 2
  EXPECT_EQ(m->frames_parallel_only, 2);
  EXPECT_DOUBLE_EQ(m->parallel_only_within_3sigma, 0.5);
  EXPECT_DOUBLE_EQ(m->all_frames_correct_any_rate, 0.4);
  EXPECT_DOUBLE_EQ(m->all_frames_correct_best_rate, 0.2);
  EXPECT_DOUBLE_EQ(m->mean_hypotheses, 13.0 / 10.0);  // 2+2+4+2+0+1+1+1+0+0

  const nlohmann::json j = toJson(*m);
  EXPECT_EQ(j["frames_two_directions"], 6);
  EXPECT_DOUBLE_EQ(j["correct_top2_rate"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["correct_position_m"].get<double>(), 0.1);
  GlobalMetrics none;
  EXPECT_TRUE(toJson(none)["correct_any_rate"].is_null());  // no frames: undefined, not 0
}

// evaluateOutputs() reads the CSV files back, writes its section next to the others and the plot;
// running it again (what --evaluate-only does) gives a byte-identical metrics.json.
TEST(EvaluateOutputs, WritesSectionKeepsOthersAndIsDeterministic) {
  namespace fs = std::filesystem;
  OfflineContext c = makeContext(80, [](int i) { return Pose2(-1.0 + 0.02 * i, 1.0, 0.1); });
  c.field = makeStandardField("spl");
  c.out_dir = (fs::path(::testing::TempDir()) / "evaluate_outputs_test").string();
  fs::remove_all(c.out_dir);
  fs::create_directories(c.out_dir);
  {
    EstimateCsvWriter writer(c.out_dir);
    for (int i = 0; i < 80; ++i) {
      const Pose2 g = c.recording.ground_truth[static_cast<size_t>(i)].field_T_robot;
      writer.write(estimate(c.recording.frames[static_cast<size_t>(i)].t_us, "TRACKING",
                            {Pose2(g.x + 0.01 * (i % 7), g.y, g.theta), mirrored(g)}));
    }
    writer.close();
  }
  std::ofstream(fs::path(c.out_dir) / "metrics.json") << R"({"vision": {"precision": 0.9}})";
  auto slurp = [&](const std::string& name) {
    std::ifstream in(fs::path(c.out_dir) / name, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const EvaluationResult first = evaluateOutputs(c, false);
  const std::string json = slurp("metrics.json");
  ASSERT_TRUE(first.tracking);
  EXPECT_EQ(first.tracking->frames_evaluated, 80);
  EXPECT_DOUBLE_EQ(first.tracking->correct_rate, 1.0);
  EXPECT_EQ(first.trajectory_png, (fs::path(c.out_dir) / "trajectory.png").string());
  EXPECT_GT(fs::file_size(first.trajectory_png), 10000u);
  const nlohmann::json parsed = nlohmann::json::parse(json);
  EXPECT_DOUBLE_EQ(parsed["vision"]["precision"].get<double>(), 0.9);  // kept
  EXPECT_EQ(parsed["tracking"]["frames_evaluated"], 80);
  EXPECT_FALSE(parsed.contains("global"));

  evaluateOutputs(c, false);
  EXPECT_EQ(slurp("metrics.json"), json);
  const EvaluationResult global = evaluateOutputs(c, true);
  ASSERT_TRUE(global.global);
  EXPECT_EQ(nlohmann::json::parse(slurp("metrics.json"))["global"]["frames_scored"], 80);
  fs::remove_all(c.out_dir);
}

}  // namespace
}  // namespace houghloc
