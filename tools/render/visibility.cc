#include "tools/render/visibility.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

double directionDeg(const Eigen::Vector2d& d) {
  double deg = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
  if (deg < 0.0) deg += 180.0;
  if (deg >= 180.0) deg -= 180.0;
  return deg;
}

}  // namespace

VisibilityCounter::VisibilityCounter(const FieldModel& field, double spacing, double max_range_m)
    : max_range_m_(max_range_m) {
  auto add_line = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, int feature) {
    const double len = (b - a).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    for (int i = 0; i < n; ++i)
      samples_.push_back({a + (b - a) * ((i + 0.5) / n), len / n, feature});
  };
  for (size_t i = 0; i < field.segments.size(); ++i) {
    names_.push_back(describeFeature(FeatureRef{FeatureKind::kSegment, static_cast<int>(i)}));
    directions_deg_.push_back(directionDeg(field.segments[i].b - field.segments[i].a));
    add_line(field.segments[i].a, field.segments[i].b, static_cast<int>(names_.size()) - 1);
  }
  for (size_t i = 0; i < field.arcs.size(); ++i) {
    const Arc2& arc = field.arcs[i];
    names_.push_back(describeFeature(FeatureRef{FeatureKind::kArc, static_cast<int>(i)}));
    directions_deg_.push_back(0.0);
    const int n = std::max(1, static_cast<int>(std::ceil(arc.length() / spacing)));
    for (int k = 0; k < n; ++k) {
      samples_.push_back({arc.pointAt(arc.start_rad + arc.sweep_rad * (k + 0.5) / n),
                          arc.length() / n, static_cast<int>(names_.size()) - 1});
    }
  }
  for (size_t i = 0; i < field.marks.size(); ++i) {
    const Mark& m = field.marks[i];
    names_.push_back(describeFeature(FeatureRef{FeatureKind::kMark, static_cast<int>(i)}));
    directions_deg_.push_back(0.0);
    const int id = static_cast<int>(names_.size()) - 1;
    const Eigen::Vector2d hx(0.5 * m.size, 0.0), hy(0.0, 0.5 * m.size);
    add_line(m.center - hx, m.center + hx, id);  // a dot counts as its diameter
    if (m.shape == MarkShape::kCross) add_line(m.center - hy, m.center + hy, id);
  }
}

std::vector<VisibleRecord> VisibilityCounter::count(std::int64_t t_us, const Pose2& field_T_robot,
                                                    const CameraModel& camera,
                                                    const FrameView& view, const RayTable& rays,
                                                    const RenderBuffers& buffers) const {
  std::vector<double> length(names_.size(), 0.0);
  const Pose2 robot_T_field = field_T_robot.inverse();
  const int ss = rays.supersampling;
  for (const Sample& s : samples_) {
    if ((s.p_field - field_T_robot.translation()).norm() > max_range_m_) continue;
    const Eigen::Vector2d p_robot = robot_T_field.transform(s.p_field);
    const auto pixel = camera.project(Eigen::Vector3d(p_robot.x(), p_robot.y(), 0.0));
    if (!pixel || !camera.inImage(*pixel)) continue;
    const int col =
        std::clamp(static_cast<int>(std::lround((pixel->x() + 0.5) * ss - 0.5)), 0, rays.width - 1);
    const int row = std::clamp(static_cast<int>(std::lround((pixel->y() + 0.5) * ss - 0.5)), 0,
                               rays.height - 1);
    const int idx = rays.index(col, row);
    const Eigen::Vector3d ray = view.field_R_camera * rays.ray[idx].cast<double>();
    const Eigen::Vector3d to_point =
        Eigen::Vector3d(s.p_field.x(), s.p_field.y(), 0.0) - view.origin;
    const double dist = to_point.norm();
    // The rendered pixel must really look at the sample (guards against a lens model folding
    // far-off-axis points back into the image), and nothing opaque may stand in front of it.
    const double pixel_angle = rays.ray_du[idx].norm() * ss;
    if (!std::isfinite(ray.x()) || ray.dot(to_point / dist) < std::cos(3.0 * pixel_angle + 1e-4)) {
      continue;
    }
    if (buffers.occluder_depth(row, col) < dist - 0.02) continue;
    length[s.feature] += s.length_m;
  }
  std::vector<VisibleRecord> out;
  for (size_t i = 0; i < names_.size(); ++i) {
    if (length[i] <= 0.0) continue;
    VisibleRecord r;
    r.t_us = t_us;
    r.feature = names_[i];
    r.visible_length_m = length[i];
    r.direction_deg = directions_deg_[i];
    out.push_back(r);
  }
  return out;
}

}  // namespace houghloc
