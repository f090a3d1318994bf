#include "tools/realframes/groundtruth_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "field_models/field_distance.h"

namespace houghloc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void sampleSegment(const Segment2& s, double step, std::vector<Eigen::Vector2d>* out) {
  const int n = std::max(1, static_cast<int>(std::round(s.length() / step)));
  for (int i = 0; i <= n; ++i) out->push_back(s.a + (s.b - s.a) * (static_cast<double>(i) / n));
}

void sampleArc(const Arc2& arc, double step, std::vector<Eigen::Vector2d>* out) {
  const int n = std::max(1, static_cast<int>(std::round(arc.length() / step)));
  const int last = arc.isFullCircle() ? n - 1 : n;  // a full circle's end is its start
  for (int i = 0; i <= last; ++i)
    out->push_back(arc.pointAt(arc.start_rad + arc.sweep_rad * i / n));
}

/// Below the horizon in the pixel's column (the ground side); columns outside the image have none.
bool belowHorizon(const CameraModel& camera, const Eigen::Vector2d& pixel) {
  const std::vector<double>& rows = camera.horizonRows();
  const long column = std::lround(pixel.x());
  if (column < 0 || column >= static_cast<long>(rows.size())) return false;
  return pixel.y() > rows[static_cast<size_t>(column)];
}

}  // namespace

double medianMapDistance(const FieldModel& field, const Pose2& field_T_robot,
                         const std::vector<Eigen::Vector2d>& points_robot) {
  if (points_robot.empty()) return kNaN;
  std::vector<double> d;
  d.reserve(points_robot.size());
  for (const Eigen::Vector2d& p : points_robot) {
    d.push_back(nearestFeature(field, field_T_robot.transform(p)).distance_m);
  }
  const size_t mid = d.size() / 2;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(mid), d.end());
  if (d.size() % 2 == 1) return d[mid];
  const double upper = d[mid];
  return 0.5 * (upper + *std::max_element(d.begin(), d.begin() + static_cast<long>(mid)));
}

int countBeyondGoalLine(const FieldModel& field, const Pose2& field_T_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double margin_m) {
  const double limit = field.halfLength() + margin_m;
  return static_cast<int>(std::count_if(
      points_robot.begin(), points_robot.end(),
      [&](const Eigen::Vector2d& p) { return std::abs(field_T_robot.transform(p).x()) > limit; }));
}

std::vector<Eigen::Vector2d> visibleLineSamples(const FieldModel& field, const Pose2& field_T_robot,
                                                const CameraModel& camera,
                                                const GroundTruthMetricsConfig& config) {
  std::vector<Eigen::Vector2d> samples_field;
  for (const Segment2& s : field.segments) sampleSegment(s, config.sample_step_m, &samples_field);
  for (const Arc2& a : field.arcs) sampleArc(a, config.sample_step_m, &samples_field);
  const Pose2 robot_T_field = field_T_robot.inverse();
  std::vector<Eigen::Vector2d> visible;
  for (const Eigen::Vector2d& p_field : samples_field) {
    const Eigen::Vector2d p_robot = robot_T_field.transform(p_field);
    if (p_robot.norm() > config.max_range_m) continue;
    const auto pixel = camera.project({p_robot.x(), p_robot.y(), 0.0});
    if (!pixel || !camera.inImage(*pixel) || !belowHorizon(camera, *pixel)) continue;
    visible.push_back(p_robot);
  }
  return visible;
}

int countCoveredSamples(const std::vector<Eigen::Vector2d>& samples_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double radius_m) {
  const double r2 = radius_m * radius_m;
  return static_cast<int>(
      std::count_if(samples_robot.begin(), samples_robot.end(), [&](const Eigen::Vector2d& s) {
        return std::any_of(points_robot.begin(), points_robot.end(),
                           [&](const Eigen::Vector2d& p) { return (p - s).squaredNorm() <= r2; });
      }));
}

GroundTruthMetrics groundTruthMetrics(const FieldModel& field, const Pose2& field_T_robot,
                                      const CameraModel& camera,
                                      const std::vector<Eigen::Vector2d>& points_robot,
                                      const GroundTruthMetricsConfig& config) {
  GroundTruthMetrics m;
  m.points = static_cast<int>(points_robot.size());
  m.median_distance_m = medianMapDistance(field, field_T_robot, points_robot);
  m.beyond_goal =
      countBeyondGoalLine(field, field_T_robot, points_robot, config.beyond_goal_margin_m);
  m.beyond_goal_share = m.points > 0 ? static_cast<double>(m.beyond_goal) / m.points : 0.0;
  const std::vector<Eigen::Vector2d> samples =
      visibleLineSamples(field, field_T_robot, camera, config);
  m.visible_samples = static_cast<int>(samples.size());
  m.covered_samples = countCoveredSamples(samples, points_robot, config.found_radius_m);
  m.coverage =
      m.visible_samples > 0 ? static_cast<double>(m.covered_samples) / m.visible_samples : kNaN;
  return m;
}

}  // namespace houghloc
