#include "localization/localizer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "localization/global_hough_localizer.h"
#include "localization/tracked_hypotheses.h"

namespace houghloc {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

/// The tracker's unit from a global hypothesis. Heading-only hypotheses carry no position and
/// are left out: the tracker could not tell them from a confident pose at the field centre.
std::vector<GaussianPose> toGaussianPoses(const std::vector<PoseHypothesis>& hypotheses,
                                          int max_count) {
  std::vector<GaussianPose> out;
  for (const PoseHypothesis& h : hypotheses) {
    if (static_cast<int>(out.size()) >= max_count) break;
    if (h.kind == HypothesisKind::kHeadingOnly) continue;
    GaussianPose pose;
    pose.mean = h.field_T_robot;
    pose.covariance = h.covariance;
    pose.weight = h.weight;
    if (pose.isFinite()) out.push_back(pose);
  }
  return out;
}

/// Every line, arc and mark has a twin at (-x, -y) (within 1 cm): the map is point-symmetric.
bool pointSymmetric(const FieldModel& field) {
  const auto near = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - b).norm() < 0.01;
  };
  const bool segments = std::all_of(field.segments.begin(), field.segments.end(), [&](auto& s) {
    return std::any_of(field.segments.begin(), field.segments.end(), [&](auto& t) {
      return (near(-s.a, t.a) && near(-s.b, t.b)) || (near(-s.a, t.b) && near(-s.b, t.a));
    });
  });
  const bool arcs = std::all_of(field.arcs.begin(), field.arcs.end(), [&](auto& a) {
    return std::any_of(field.arcs.begin(), field.arcs.end(), [&](auto& b) {
      return near(-a.center, b.center) && std::abs(a.radius - b.radius) < 0.01;
    });
  });
  const bool marks = std::all_of(field.marks.begin(), field.marks.end(), [&](auto& m) {
    return std::any_of(field.marks.begin(), field.marks.end(),
                       [&](auto& n) { return near(-m.center, n.center); });
  });
  return segments && arcs && marks;
}

/// On a point-symmetric map both twins of a hypothesis explain the frame equally well, but the
/// global localizer's list need not hold both: it lists each twin pair once when it has more
/// candidates than slots, and a 1-D hypothesis may stem from a candidate whose twin was pruned.
/// Each missing twin is added with the same weight and kind, so both halves of the field carry
/// the same likelihood and the tracker's belief alone decides between them. The kind counts: a
/// full pose next to a 1-D hypothesis does not stand for the 1-D one (it would leave one half
/// with two hypotheses and the other with one).
void addMissingTwins(const TrackerConfig& config, std::vector<PoseHypothesis>* hypotheses) {
  const size_t found = hypotheses->size();
  for (size_t k = 0; k < found; ++k) {
    const PoseHypothesis& original = (*hypotheses)[k];
    const bool listed = std::any_of(hypotheses->begin(), hypotheses->end(), [&](const auto& h) {
      return h.kind == original.kind &&
             areMirrors(original.field_T_robot, h.field_T_robot, config.mirror_tolerance_m,
                        config.mirror_tolerance_rad);
    });
    if (!listed) hypotheses->push_back(mirrored(original));
  }
}

/// The `count` poses with the largest belief x likelihood: the product the tracker weighs them
/// by, so a cut by the likelihood alone cannot drop the pose the belief favours.
void keepMostProbable(const HypothesisTracker& tracker, int count,
                      std::vector<GaussianPose>* poses) {
  if (static_cast<int>(poses->size()) <= count) return;
  std::vector<std::pair<double, GaussianPose>> scored;
  for (const GaussianPose& p : *poses) scored.emplace_back(tracker.belief(p) * p.weight, p);
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  poses->clear();
  for (int k = 0; k < std::max(0, count); ++k) poses->push_back(scored[k].second);
}

/// A camera close to the ground or tilted far from its upright pose: the robot has fallen.
bool cameraSaysFallen(const std::vector<Pose3>& robot_T_cameras, const LocalizerConfig& config) {
  for (const Pose3& camera : robot_T_cameras) {
    if (!camera.isFinite()) continue;
    // robot_T_camera comes from the joint angles and the body's inertial tilt, so a robot lying
    // on the ground reports its camera near the ground, rolled far to the side or facing up.
    const bool low = camera.z < config.fallen_camera_height_m;
    const bool rolled = std::abs(camera.roll) > config.fallen_tilt_rad;
    const bool facing_up = camera.pitch < -config.fallen_tilt_rad;  // pitch > 0 looks down
    if (low || rolled || facing_up) return true;
  }
  return false;
}

/// Points with a finite position and a finite positive weight, and visible regions whose
/// vertices are all finite; `points` itself when it is clean (the usual case, no copy).
const GroundPoints& cleanPoints(const GroundPoints& points, GroundPoints* storage) {
  auto good_point = [](const GroundPoint& p) {
    return p.p_robot.allFinite() && std::isfinite(p.weight) && p.weight > 0.0;
  };
  auto good_region = [](const GroundPolygon& polygon) {
    return std::all_of(polygon.begin(), polygon.end(),
                       [](const Eigen::Vector2d& v) { return v.allFinite(); });
  };
  if (std::all_of(points.points.begin(), points.points.end(), good_point) &&
      std::all_of(points.visible_regions.begin(), points.visible_regions.end(), good_region)) {
    return points;
  }
  storage->t_us = points.t_us;
  storage->points.clear();
  storage->visible_regions.clear();
  storage->field_edge = points.field_edge;  // FieldEdgeEvidence skips bad samples itself
  std::copy_if(points.points.begin(), points.points.end(), std::back_inserter(storage->points),
               good_point);
  std::copy_if(points.visible_regions.begin(), points.visible_regions.end(),
               std::back_inserter(storage->visible_regions), good_region);
  return *storage;
}

}  // namespace

Localizer::Localizer(const FieldModel& field, const LocalizerConfig& config)
    : config_(config),
      field_(std::make_shared<const FieldModel>(field)),
      global_(std::make_shared<const GlobalHoughLocalizer>(field, config.global)),
      tracker_(field, config.tracker),
      point_symmetric_(pointSymmetric(field)) {}

Localizer::~Localizer() = default;
Localizer::Localizer(const Localizer&) = default;
Localizer& Localizer::operator=(const Localizer&) = default;

LocalizationEstimate Localizer::process(std::int64_t t_us, const std::optional<Pose2>& odometry,
                                        const std::vector<Pose3>& robot_T_cameras,
                                        const GroundPoints& points) {
  last_t_us_ = t_us;
  const bool was_fallen = fallen_;
  fallen_ = cameraSaysFallen(robot_T_cameras, config_);
  // Getting up turns and shifts the robot in ways its odometry does not follow, and the first
  // views may be ambiguous: ask the global localizer until it has seen enough.
  if (was_fallen && !fallen_) {
    global_frames_pending_ = config_.global_frames_after_fall;
  }
  const auto tracker_start = std::chrono::steady_clock::now();
  // A fallen robot's odometry is meaningless and its camera sees the sky or its own body: the
  // tracker is told that motion is unknown (its covariance grows) and gets no points.
  const std::optional<Pose2> usable_odometry = fallen_ ? std::nullopt : odometry;
  GroundPoints cleaned;
  const GroundPoints no_points;
  const GroundPoints& usable_points = fallen_ ? no_points : cleanPoints(points, &cleaned);
  tracker_.update(t_us, usable_odometry, usable_points);
  double tracker_ms = millisecondsSince(tracker_start);

  bool global_ran = false;
  double global_ms = 0.0;
  if (!fallen_ && (global_frames_pending_ > 0 || tracker_.needsGlobalHypotheses())) {
    const auto global_start = std::chrono::steady_clock::now();
    std::vector<PoseHypothesis> found = global_->locate(usable_points);
    global_ms = millisecondsSince(global_start);
    global_ran = true;
    // The tracker weighs them by its belief (the pre-fall pose inflated by the fall's unknown
    // motion after getting up): that tells the field's mirror twins apart.
    if (point_symmetric_) addMissingTwins(config_.tracker, &found);
    std::vector<GaussianPose> poses = toGaussianPoses(found, static_cast<int>(found.size()));
    keepMostProbable(tracker_, config_.max_injected_hypotheses, &poses);
    if (!poses.empty()) {
      const auto inject_start = std::chrono::steady_clock::now();
      tracker_.injectHypotheses(poses);
      tracker_ms += millisecondsSince(inject_start);
    }
    if (!found.empty() && global_frames_pending_ > 0) --global_frames_pending_;
  }

  LocalizationEstimate out = estimate();
  out.global_ran = global_ran;
  out.global_ms = global_ms;
  out.tracker_ms = tracker_ms;
  return out;
}

void Localizer::applyHint(const LocalizationHint& hint) { tracker_.applyHint(hint); }

LocalizationEstimate Localizer::estimate() const {
  LocalizationEstimate out;
  out.t_us = last_t_us_;
  out.status = tracker_.status();
  // Lying on the ground the robot neither moves as odometry says nor sees lines: whatever it
  // believed before is not to be acted on until it stands and looks again.
  if (fallen_ && out.status != TrackerStatus::kInitializing) out.status = TrackerStatus::kLost;
  out.fallen = fallen_;
  out.points_in = tracker_.lastStats().points_in;
  out.points_used = tracker_.lastStats().points_used;
  std::vector<GaussianPose> poses;
  for (const TrackedHypothesis& h : tracker_.hypotheses()) {
    out.hypotheses.push_back({h.pose, h.id, h.age_frames});
    poses.push_back(h.pose);
  }
  out.twin_weight = mirrorTwinWeight(poses, config_.tracker.mirror_tolerance_m,
                                     config_.tracker.mirror_tolerance_rad);
  return out;
}

}  // namespace houghloc
