#include "tests/localization/tracking_scenario.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace houghloc::testing {
namespace {

std::vector<Eigen::Vector2d> sampleMap(const FieldModel& field, double spacing) {
  std::vector<Eigen::Vector2d> out;
  auto segment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int i = 0; i <= n; ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / n));
  };
  for (const Segment2& s : field.segments) segment(s.a, s.b);
  for (const Arc2& arc : field.arcs) {
    const int n = std::max(2, static_cast<int>(std::ceil(arc.length() / spacing)));
    for (int i = 0; i < n; ++i) out.push_back(arc.pointAt(arc.start_rad + arc.sweep_rad * i / n));
  }
  for (const Mark& m : field.marks) {
    const double h = 0.5 * m.size;
    segment(m.center - Eigen::Vector2d(h, 0.0), m.center + Eigen::Vector2d(h, 0.0));
    segment(m.center - Eigen::Vector2d(0.0, h), m.center + Eigen::Vector2d(0.0, h));
  }
  return out;
}

Pose2 figureEight(const ScenarioConfig& c, double t) {
  const double w = 2.0 * M_PI / c.period_s;
  const double x = c.half_extent_x_m * std::sin(w * t);
  const double y = c.half_extent_y_m * std::sin(2.0 * w * t);
  const double dx = c.half_extent_x_m * w * std::cos(w * t);
  const double dy = 2.0 * c.half_extent_y_m * w * std::cos(2.0 * w * t);
  return Pose2(x, y, std::atan2(dy, dx));
}

bool inWedge(const Eigen::Vector2d& p, double pan, const ScenarioConfig& c) {
  const double r = p.norm();
  if (r < c.min_range_m || r > c.max_range_m) return false;
  return std::abs(angleDifference(std::atan2(p.y(), p.x()), pan)) <= 0.5 * c.fov_rad;
}

}  // namespace

GroundPoints samplePoints(const FieldModel& field, const Pose2& field_T_robot, double pan_rad,
                          const ScenarioConfig& c, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Pose2 robot_T_field = field_T_robot.inverse();
  std::vector<Eigen::Vector2d> visible;
  for (const Eigen::Vector2d& p_field : sampleMap(field, c.sample_spacing_m)) {
    const Eigen::Vector2d p = robot_T_field.transform(p_field);
    if (inWedge(p, pan_rad, c)) visible.push_back(p);
  }
  std::shuffle(visible.begin(), visible.end(), rng);
  if (static_cast<int>(visible.size()) > c.max_points) visible.resize(c.max_points);
  GroundPoints out;
  for (const Eigen::Vector2d& p : visible) {
    const double sigma = c.point_noise_m + c.point_noise_per_m * p.norm();
    GroundPoint gp;
    gp.p_robot = p + sigma * Eigen::Vector2d(normal(rng), normal(rng));
    out.points.push_back(gp);
  }
  const int outliers = static_cast<int>(std::lround(c.outlier_fraction * visible.size()));
  for (int i = 0; i < outliers; ++i) {
    const double r = c.min_range_m + (c.max_range_m - c.min_range_m) * uniform(rng);
    const double a = pan_rad + c.fov_rad * (uniform(rng) - 0.5);
    GroundPoint gp;
    gp.p_robot = r * Eigen::Vector2d(std::cos(a), std::sin(a));
    out.points.push_back(gp);
  }
  return out;
}

std::vector<ScenarioFrame> makeScenario(const FieldModel& field, const ScenarioConfig& c) {
  std::mt19937 rng(c.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<ScenarioFrame> frames;
  Pose2 carry;  // field_T_path: identity until the kidnap
  Pose2 odometry(0.0, 0.0, 0.0);
  for (int k = 0; k < c.frames; ++k) {
    const double t = k / c.fps;
    if (k == c.kidnap_frame) carry = c.kidnap_to * figureEight(c, t).inverse();
    ScenarioFrame f;
    f.t_us = static_cast<std::int64_t>(std::llround(t * 1e6));
    f.field_T_robot = carry * figureEight(c, t);
    if (k > 0) {
      // Odometry integrates the path's own motion (a kidnap is invisible to it), with relative
      // noise on every component and a systematic slip.
      const Pose2 motion = figureEight(c, (k - 1) / c.fps).inverse() * figureEight(c, t);
      const double scale = (1.0 - c.odometry_slip) * (1.0 + c.odometry_noise * normal(rng));
      const double step = std::hypot(motion.x, motion.y);
      const Pose2 noisy(motion.x * scale + c.odometry_noise * step * normal(rng),
                        motion.y * scale + c.odometry_noise * step * normal(rng),
                        motion.theta * (1.0 + c.odometry_noise * normal(rng)) +
                            0.5 * c.odometry_noise * step * normal(rng));
      odometry = odometry * noisy;
    }
    f.odometry = odometry;
    const double pan = c.head_pan_rad * std::sin(2.0 * M_PI * t / c.head_period_s);
    f.points = samplePoints(field, f.field_T_robot, pan, c, c.seed * 7919u + k);
    f.points.t_us = f.t_us;
    frames.push_back(std::move(f));
  }
  return frames;
}

}  // namespace houghloc::testing
