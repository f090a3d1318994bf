#include "tests/localization/hint_walk.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "tests/localization/localizer_test_support.h"

namespace houghloc::testing {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Pose2 startPose(const FieldModel& field, StartPlace place, std::mt19937_64& rng) {
  const double heading = uniform(rng, -M_PI, M_PI);
  const double side = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  switch (place) {
    case StartPlace::kCentre: {  // uniform in the disc of 1 m around the centre mark
      const double r = std::sqrt(uniform(rng, 0.0, 1.0)), a = uniform(rng, -M_PI, M_PI);
      return Pose2(r * std::cos(a), r * std::sin(a), heading);
    }
    case StartPlace::kPenaltyMark: {  // within 0.5 m of one of the two penalty marks
      Eigen::Vector2d mark = Eigen::Vector2d::Zero();
      for (const Mark& m : field.marks) {
        if (side * m.center.x() > side * mark.x()) mark = m.center;
      }
      const double r = 0.5 * std::sqrt(uniform(rng, 0.0, 1.0)), a = uniform(rng, -M_PI, M_PI);
      return Pose2(mark.x() + r * std::cos(a), mark.y() + r * std::sin(a), heading);
    }
    case StartPlace::kCorner: {  // 0.2-0.7 m inside both lines at one of the four corners
      const double side_y = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
      return Pose2(side * (field.halfLength() - uniform(rng, 0.2, 0.7)),
                   side_y * (field.halfWidth() - uniform(rng, 0.2, 0.7)), heading);
    }
  }
  return Pose2();
}

/// The robot's motion in one frame: forward at `speed`, turning toward the centre when more than
/// 1.5 m away, with a weave.
Pose2 step(const Pose2& pose, double t, double dt, double speed, double phase) {
  double omega = 0.3 * std::sin(2.0 * M_PI * t / 3.0 + phase);
  if (pose.translation().norm() > 1.5) {
    const double bearing = std::atan2(-pose.y, -pose.x);
    omega += std::clamp(1.2 * angleDifference(bearing, pose.theta), -0.6, 0.6);
  }
  return Pose2(speed * dt, 0.0, omega * dt);
}

/// The points of a frame seen with the head panned by `pan`, expressed in the robot frame.
GroundPoints rotated(GroundPoints g, double pan) {
  const Pose2 robot_T_head(0.0, 0.0, pan);
  for (GroundPoint& p : g.points) p.p_robot = robot_T_head.transform(p.p_robot);
  for (GroundPolygon& polygon : g.visible_regions) {
    for (Eigen::Vector2d& v : polygon) v = robot_T_head.transform(v);
  }
  for (FieldEdgePoint& e : g.field_edge) e.p_robot = robot_T_head.transform(e.p_robot);
  return g;
}

}  // namespace

const char* startPlaceName(StartPlace place) {
  switch (place) {
    case StartPlace::kCentre:
      return "centre";
    case StartPlace::kPenaltyMark:
      return "penalty";
    case StartPlace::kCorner:
      return "corner";
  }
  return "?";
}

std::vector<HintWalkFrame> makeHintWalk(const FieldModel& field, const HintWalkConfig& c) {
  std::mt19937_64 rng(c.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Pose2 truth = startPose(field, c.start, rng);
  const double weave_phase = uniform(rng, -M_PI, M_PI);
  SyntheticConfig synthetic;
  synthetic.view = viewModel(c.view);
  const double dt = 1.0 / c.fps;
  Pose2 odometry(0.0, 0.0, 0.0);
  std::vector<HintWalkFrame> frames;
  for (int k = 0; k < c.frames; ++k) {
    const double t = k * dt;
    if (k > 0) {
      const Pose2 motion = step(truth, t, dt, c.walk_speed_m_per_s, weave_phase);
      truth = truth * motion;
      const double scale = (1.0 - c.odometry_slip) * (1.0 + c.odometry_noise * normal(rng));
      const double d = std::hypot(motion.x, motion.y);
      odometry = odometry * Pose2(motion.x * scale + c.odometry_noise * d * normal(rng),
                                  motion.y * scale + c.odometry_noise * d * normal(rng),
                                  motion.theta * (1.0 + c.odometry_noise * normal(rng)) +
                                      0.5 * c.odometry_noise * d * normal(rng));
    }
    if (k == c.kidnap_frame) {  // carried to the other half, odometry blind to it
      const double side = truth.x > 0.0 ? -1.0 : 1.0;
      truth = Pose2(side * field.halfLength() * uniform(rng, 0.3, 0.8),
                    field.halfWidth() * uniform(rng, -0.7, 0.7), uniform(rng, -M_PI, M_PI));
    }
    const double pan = c.head_pan_rad * std::sin(2.0 * M_PI * t / c.head_period_s);
    synthetic.seed = c.seed * 7919u + static_cast<std::uint64_t>(k);
    HintWalkFrame f;
    f.t_us = static_cast<std::int64_t>(std::llround(t * 1e6));
    f.field_T_robot = truth;
    f.odometry = odometry;
    f.points = rotated(generateFrame(field, truth * Pose2(0.0, 0.0, pan), synthetic).ground, pan);
    f.points.t_us = f.t_us;
    frames.push_back(std::move(f));
  }
  return frames;
}

LocalizationHint placementHint(const Pose2& truth, double offset_m, double offset_rad,
                               double sigma_m, double sigma_rad, std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  const double direction = uniform(rng, -M_PI, M_PI);
  const double sign = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  GaussianPose pose;
  pose.mean = Pose2(truth.x + offset_m * std::cos(direction),
                    truth.y + offset_m * std::sin(direction), truth.theta + sign * offset_rad);
  pose.covariance =
      Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
  LocalizationHint hint;
  hint.kind = HintKind::kResetTo;
  hint.poses = {pose};
  return hint;
}

void HintCellResult::add(const LocalizationEstimate& estimate, const Pose2& truth) {
  ++frames;
  const auto best = estimate.best();
  if (!best) return;
  if (first_correct_t_us < 0 && correctPose(best->mean, truth)) first_correct_t_us = estimate.t_us;
  if (first_correct_t_us >= 0) flips += isFlipped(best->mean, truth) ? 1 : 0;
  twin_max = std::max(twin_max, estimate.twin_weight);
}

std::string HintCellResult::describe() const {
  std::ostringstream s;
  s << "first correct ";
  if (first_correct_t_us < 0) {
    s << "never";
  } else {
    s << (first_correct_t_us - hint_t_us) / 1000 << " ms after the hint";
  }
  s << ", flipped frames " << flips << " of " << frames << ", twin weight max " << twin_max;
  return s.str();
}

bool isFlipped(const Pose2& best, const Pose2& truth) {
  const double to_truth = (best.translation() - truth.translation()).norm();
  const double to_twin = (best.translation() - mirrored(truth).translation()).norm();
  return to_twin < to_truth && to_truth > 0.5;
}

}  // namespace houghloc::testing
