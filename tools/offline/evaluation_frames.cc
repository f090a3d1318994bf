#include "tools/offline/evaluation_frames.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace houghloc {
namespace {

/// Angle between two undirected line directions, deg in [0, 90].
double directionSeparationDeg(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 180.0);
  return std::min(d, 180.0 - d);
}

bool isCentreCircle(const std::string& feature, const FieldModel* field) {
  int index = -1;
  if (std::sscanf(feature.c_str(), "arcs[%d]", &index) != 1 || index < 0) return false;
  if (!field) return true;
  if (index >= static_cast<int>(field->arcs.size())) return false;
  const Arc2& arc = field->arcs[static_cast<size_t>(index)];
  return arc.isFullCircle() && arc.center.norm() < 0.01;
}

/// Frame index of the first frame at or after t_us (frames.size() when there is none).
int frameAtOrAfter(const std::vector<FrameRecord>& frames, std::int64_t t_us) {
  const auto it = std::lower_bound(frames.begin(), frames.end(), t_us,
                                   [](const FrameRecord& f, std::int64_t t) { return f.t_us < t; });
  return static_cast<int>(it - frames.begin());
}

}  // namespace

PoseError poseError(const Pose2& estimate, const Pose2& truth) {
  return {std::hypot(estimate.x - truth.x, estimate.y - truth.y),
          std::abs(angleDifference(estimate.theta, truth.theta))};
}

bool isCorrect(const Pose2& estimate, const Pose2& truth) {
  const PoseError e = poseError(estimate, truth);
  return e.position_m <= kCorrectPositionM && e.heading_rad <= kCorrectHeadingRad;
}

bool isCorrectUpToSymmetry(const Pose2& estimate, const Pose2& truth) {
  return isCorrect(estimate, truth) || isCorrect(estimate, mirrored(truth));
}

CorrectRank correctRankUpToSymmetry(const std::vector<Pose2>& hypotheses, const Pose2& truth) {
  std::vector<int> answer(hypotheses.size(), -1);
  int answers = 0;
  for (size_t k = 0; k < hypotheses.size(); ++k) {
    for (size_t j = 0; j < k && answer[k] < 0; ++j) {
      if (isCorrectUpToSymmetry(hypotheses[k], hypotheses[j])) answer[k] = answer[j];
    }
    if (answer[k] < 0) answer[k] = answers++;
    if (isCorrectUpToSymmetry(hypotheses[k], truth)) return {static_cast<int>(k), answer[k]};
  }
  return {};
}

PoseError symmetricPoseError(const Pose2& estimate, const Pose2& truth) {
  const PoseError direct = poseError(estimate, truth);
  const PoseError twin = poseError(estimate, mirrored(truth));
  return twin.position_m < direct.position_m ? twin : direct;
}

bool isFlip(const Pose2& estimate, const Pose2& truth) {
  const double to_truth = poseError(estimate, truth).position_m;
  const double to_twin = poseError(estimate, mirrored(truth)).position_m;
  return to_twin < to_truth && to_truth > kFlipMinDistanceM;
}

double mahalanobisDistance(const GaussianPose& hypothesis, const Pose2& truth) {
  const Eigen::Vector3d d = poseDifference(truth, hypothesis.mean);
  const Eigen::LLT<Eigen::Matrix3d> llt(hypothesis.covariance);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  return std::sqrt(std::max(0.0, d.dot(llt.solve(d))));
}

FrameView classifyView(const std::vector<VisibleRecord>& rows, const FieldModel* field) {
  if (rows.empty()) return FrameView::kUnknown;
  double circle_m = 0.0;
  std::vector<std::pair<double, double>> segments;  // direction deg, visible length m
  for (const VisibleRecord& r : rows) {
    if (r.feature.rfind("segments[", 0) == 0)
      segments.emplace_back(r.direction_deg, r.visible_length_m);
    if (isCentreCircle(r.feature, field)) circle_m += r.visible_length_m;
  }
  // Length seen along each segment's direction, summed over the segments sharing it.
  std::vector<double> along(segments.size(), 0.0);
  for (size_t i = 0; i < segments.size(); ++i) {
    for (const auto& [direction, length] : segments) {
      if (directionSeparationDeg(segments[i].first, direction) <= kSameDirectionToleranceDeg) {
        along[i] += length;
      }
    }
  }
  bool one_direction = false;
  for (size_t i = 0; i < segments.size(); ++i) {
    if (along[i] < kMinDirectionLengthM) continue;
    one_direction = true;
    for (size_t j = i + 1; j < segments.size(); ++j) {
      if (along[j] >= kMinDirectionLengthM &&
          directionSeparationDeg(segments[i].first, segments[j].first) >=
              kMinDirectionSeparationDeg) {
        return FrameView::kTwoDirections;
      }
    }
  }
  if (circle_m >= kMinCircleLengthM) return FrameView::kTwoDirections;
  return one_direction ? FrameView::kParallelOnly : FrameView::kNoLines;
}

std::vector<EvaluatedFrame> evaluatedFrames(const OfflineContext& context,
                                            const std::vector<FrameEstimate>& estimates,
                                            std::vector<PlacedEvent>* events) {
  const Recording& rec = context.recording;
  const int first = std::max(0, context.first_frame);
  const int end = std::min(static_cast<int>(rec.frames.size()), context.end_frame);
  std::map<std::int64_t, const FrameEstimate*> by_time;
  for (const FrameEstimate& e : estimates) by_time.emplace(e.t_us, &e);
  std::map<std::int64_t, std::vector<VisibleRecord>> visible;
  for (const VisibleRecord& v : rec.visible) visible[v.t_us].push_back(v);
  const FieldModel* field = context.field ? &*context.field : nullptr;

  std::vector<EvaluatedFrame> frames;
  for (int i = first; i < end; ++i) {
    EvaluatedFrame f;
    f.index = i;
    f.t_us = rec.frames[static_cast<size_t>(i)].t_us;
    f.truth = groundTruthAt(rec.ground_truth, f.t_us);
    if (const auto it = by_time.find(f.t_us); it != by_time.end()) f.estimate = it->second;
    if (const auto it = visible.find(f.t_us); it != visible.end()) {
      f.view = classifyView(it->second, field);
    }
    frames.push_back(f);
  }
  // Exclusion windows in recording frame indices: [kidnap, kidnap + 30) and
  // [fall start, fall end + 30); a fall that never ends runs to the last frame.
  auto exclude = [&](int from, int to) {
    for (EvaluatedFrame& f : frames) f.excluded |= f.index >= from && f.index < to;
  };
  int fall_start = -1;  // frame of an unfinished fall
  const int count = static_cast<int>(rec.frames.size());
  for (const EventRecord& e : rec.events) {
    const int k = frameAtOrAfter(rec.frames, e.t_us);
    if (e.event == "KIDNAP") exclude(k, k + kFramesExcludedAfterEvent);
    if (e.event == "FALL_START") fall_start = k;
    if (e.event == "FALL_END") {
      exclude(fall_start >= 0 ? fall_start : k, k + kFramesExcludedAfterEvent);
      fall_start = -1;
    }
    if (events && k >= first && k < end) events->push_back({e.event, e.t_us, k - first});
  }
  if (fall_start >= 0) exclude(fall_start, count);
  return frames;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  // The small offset keeps q n = 19.000000000000004 from rounding up to 20.
  const double rank = std::ceil(q * static_cast<double>(values.size()) - 1e-9);
  const size_t k = static_cast<size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size())));
  return values[k - 1];
}

}  // namespace houghloc
