#include "tools/synthetic/synthetic_ground_points.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "tools/synthetic/visible_region.h"

namespace houghloc {
namespace {

/// A sample of a map feature, field frame.
struct Sample {
  Eigen::Vector2d p;
  int feature;  ///< index into the frame's feature list
};

void sampleSegment(const Segment2& s, double spacing, double phase, int feature,
                   std::vector<Sample>& out) {
  const double len = s.length();
  for (double t = phase * spacing; t <= len; t += spacing) {
    out.push_back({s.a + s.direction() * t, feature});
  }
}

void sampleArc(const Arc2& arc, double spacing, double phase, int feature,
               std::vector<Sample>& out) {
  const double step = spacing / arc.radius;
  for (double a = phase * step; a <= arc.sweep_rad; a += step) {
    out.push_back({arc.pointAt(arc.start_rad + a), feature});
  }
}

void sampleMark(const Mark& m, double spacing, int feature, std::vector<Sample>& out) {
  const double h = 0.5 * m.size;
  if (m.shape == MarkShape::kDot) {
    out.push_back({m.center, feature});
    for (int k = 0; k < 4; ++k) {
      out.push_back(
          {m.center + 0.5 * h * Eigen::Vector2d(std::cos(k * M_PI / 2), std::sin(k * M_PI / 2)),
           feature});
    }
    return;
  }
  const double step = std::min(spacing, h);
  for (double t = -h; t <= h + 1e-9; t += step) {
    out.push_back({m.center + Eigen::Vector2d(t, 0.0), feature});
    if (std::abs(t) > 1e-9) out.push_back({m.center + Eigen::Vector2d(0.0, t), feature});
  }
}

/// All features of the map in one list: segments, arcs, marks.
std::vector<FeatureRef> featureList(const FieldModel& field) {
  std::vector<FeatureRef> out;
  for (int i = 0; i < static_cast<int>(field.segments.size()); ++i)
    out.push_back({FeatureKind::kSegment, i});
  for (int i = 0; i < static_cast<int>(field.arcs.size()); ++i)
    out.push_back({FeatureKind::kArc, i});
  for (int i = 0; i < static_cast<int>(field.marks.size()); ++i)
    out.push_back({FeatureKind::kMark, i});
  return out;
}

std::vector<Sample> sampleField(const FieldModel& field, const std::vector<FeatureRef>& features,
                                double spacing, bool marks, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> phase(0.0, 1.0);
  std::vector<Sample> out;
  for (int f = 0; f < static_cast<int>(features.size()); ++f) {
    const FeatureRef& ref = features[f];
    const double ph = rng ? phase(*rng) : 0.0;
    if (ref.kind == FeatureKind::kSegment)
      sampleSegment(field.segments[ref.index], spacing, ph, f, out);
    if (ref.kind == FeatureKind::kArc) sampleArc(field.arcs[ref.index], spacing, ph, f, out);
    if (ref.kind == FeatureKind::kMark && marks)
      sampleMark(field.marks[ref.index], spacing, f, out);
  }
  return out;
}

/// GroundPoints::field_edge: per bearing the carpet's edge (or the near side of an occluder in
/// the way, as the visible region's shadows), with the range error of a boundary row
/// field_edge_sigma_px off. Drawn last, so the line points of a seed do not depend on it.
void addFieldEdge(const FieldModel& field, const SyntheticConfig& config,
                  const std::vector<Occluder>& occluders, std::mt19937_64& rng,
                  SyntheticFrame* frame) {
  const ViewModel& view = config.view;
  std::normal_distribution<double> gauss(0.0, 1.0);
  const Pose2& pose = frame->field_T_robot;
  for (int k = 0; k < config.field_edge_samples; ++k) {
    const double phi = view.half_angle_rad * (2.0 * (k + 0.5) / config.field_edge_samples - 1.0);
    const Eigen::Vector2d direction(std::cos(phi), std::sin(phi));
    double range = rangeToRectangle(pose.translation(), pose.rotation() * direction,
                                    field.outerHalfLength(), field.outerHalfWidth());
    range = visibleRange(phi, range, occluders);  // an occluder's near side, if one is in the way
    if (range < view.min_range_m || range > view.image_far_range_m ||
        range > config.field_edge_max_range_m) {
      continue;  // not in the image, or too close to the horizon
    }
    const double h = view.camera_height_m;
    const double sigma = (range * range + h * h) / h * config.field_edge_sigma_px * view.pixel_rad;
    const double measured = std::max(view.min_range_m, range + sigma * gauss(rng));
    frame->ground.field_edge.push_back({measured * direction, sigma, 0});
  }
}

}  // namespace

std::vector<std::string> viewModelNames() {
  return {"nao-top", "nao-bottom", "kid-wide", "adult", "wide-pinhole"};
}

ViewModel viewModel(const std::string& name) {
  const double deg = M_PI / 180.0;
  if (name == "nao-top") return {name, 28.0 * deg, 0.4, 4.5, 0.50, 0.0017};
  if (name == "nao-bottom") return {name, 30.0 * deg, 0.15, 1.2, 0.45, 0.0017, 1.2};
  if (name == "kid-wide") return {name, 60.0 * deg, 0.3, 5.0, 0.90, 0.0016};
  if (name == "adult") return {name, 35.0 * deg, 0.6, 7.0, 1.40, 0.0011};
  // The camera preset's 1024x576 pinhole, f = 512 px (90 deg wide), 0.50 m high, 25 deg down.
  if (name == "wide-pinhole") return {name, 45.0 * deg, 0.45, 4.5, 0.50, 1.0 / 512.0};
  throw std::invalid_argument("unknown view model '" + name +
                              "' (known: nao-top, nao-bottom, kid-wide, adult, wide-pinhole)");
}

SyntheticFrame generateFrame(const FieldModel& field, const Pose2& field_T_robot,
                             const SyntheticConfig& config) {
  SyntheticFrame frame;
  frame.field_T_robot = field_T_robot;
  std::mt19937_64 rng(config.seed);
  const ViewModel& view = config.view;
  const Pose2 robot_T_field = field_T_robot.inverse();
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);

  std::vector<Occluder> occluders;
  for (int k = 0; k < config.occluders; ++k) {
    const double r =
        view.min_range_m + 0.3 + uniform(rng) * 0.5 * (view.max_range_m - view.min_range_m);
    const double phi = (2.0 * uniform(rng) - 1.0) * view.half_angle_rad;
    occluders.push_back(
        {r * Eigen::Vector2d(std::cos(phi), std::sin(phi)), config.occluder_radius_m});
  }
  auto visible = [&](const Eigen::Vector2d& p_robot) {
    return wedgeVisible(p_robot, view.half_angle_rad, view.min_range_m, view.max_range_m,
                        occluders);
  };

  // Ground truth of what is in view: a fine, noise-free sampling.
  const std::vector<FeatureRef> features = featureList(field);
  std::vector<double> seen_length(features.size(), 0.0);
  const double fine = 0.02;
  for (const Sample& s : sampleField(field, features, fine, true, nullptr)) {
    if (visible(robot_T_field.transform(s.p))) seen_length[s.feature] += fine;
  }
  for (std::size_t f = 0; f < features.size(); ++f) {
    if (seen_length[f] <= 0.0) continue;
    double direction = std::numeric_limits<double>::quiet_NaN();
    if (features[f].kind == FeatureKind::kSegment) {
      const Eigen::Vector2d d = field.segments[features[f].index].direction();
      direction = std::atan2(d.y(), d.x());
      if (direction < 0.0) direction += M_PI;
      if (direction >= M_PI) direction -= M_PI;
    }
    frame.visible.push_back({features[f], seen_length[f], direction});
  }

  // Line points with noise, then outliers.
  for (const Sample& s : sampleField(field, features, config.point_spacing_m, config.marks, &rng)) {
    const Eigen::Vector2d p = robot_T_field.transform(s.p);
    if (!visible(p)) continue;
    const double sigma = config.noise_sigma_m + config.noise_per_m * p.norm();
    GroundPoint g;
    g.p_robot = p + sigma * Eigen::Vector2d(gauss(rng), gauss(rng));
    frame.ground.points.push_back(g);
  }
  const int outliers =
      static_cast<int>(std::round(config.outlier_share * frame.ground.points.size()));
  for (int k = 0, tries = 0; k < outliers && tries < 100 * (outliers + 1); ++tries) {
    const double r = view.min_range_m + uniform(rng) * (view.max_range_m - view.min_range_m);
    const double phi = (2.0 * uniform(rng) - 1.0) * view.half_angle_rad;
    const Eigen::Vector2d p(r * std::cos(phi), r * std::sin(phi));
    const Eigen::Vector2d f = field_T_robot.transform(p);
    if (!visible(p) || std::abs(f.x()) > field.outerHalfLength() ||
        std::abs(f.y()) > field.outerHalfWidth()) {
      continue;
    }
    GroundPoint g;
    g.p_robot = p;
    frame.ground.points.push_back(g);
    ++k;
  }

  if (config.visible_region) {
    const double hx = field.outerHalfLength(), hy = field.outerHalfWidth();
    GroundPolygon carpet;
    for (const Eigen::Vector2d& c : {Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy),
                                     Eigen::Vector2d(hx, hy), Eigen::Vector2d(-hx, hy)}) {
      carpet.push_back(robot_T_field.transform(c));
    }
    GroundPolygon region =
        visibleRegion(view.half_angle_rad, view.min_range_m, view.max_range_m, occluders, carpet);
    if (region.size() >= 3) frame.ground.visible_regions.push_back(region);
  }
  addFieldEdge(field, config, occluders, rng, &frame);
  return frame;
}

bool hasTwoDirections(const SyntheticFrame& frame) {
  std::vector<std::pair<double, double>> lines;  // direction, length
  for (const VisibleFeature& v : frame.visible) {
    if (v.feature.kind == FeatureKind::kArc && v.feature.index == 0 && v.length_m >= 1.0)
      return true;
    if (v.feature.kind == FeatureKind::kSegment && v.length_m >= 0.5)
      lines.emplace_back(v.direction_rad, v.length_m);
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      const double d = std::abs(std::remainder(lines[i].first - lines[j].first, M_PI));
      if (d >= 30.0 * M_PI / 180.0) return true;
    }
  }
  return false;
}

bool hasOnlyParallelLines(const SyntheticFrame& frame) {
  double main_direction = std::numeric_limits<double>::quiet_NaN();
  double best = 0.0;
  for (const VisibleFeature& v : frame.visible) {
    if (v.feature.kind == FeatureKind::kSegment && v.length_m > best) {
      best = v.length_m;
      main_direction = v.direction_rad;
    }
  }
  if (best < 0.5) return false;
  for (const VisibleFeature& v : frame.visible) {
    if (v.feature.kind == FeatureKind::kMark) return false;
    if (v.feature.kind == FeatureKind::kArc && v.length_m >= 0.3) return false;
    if (v.feature.kind == FeatureKind::kSegment && v.length_m >= 0.2 &&
        std::abs(std::remainder(v.direction_rad - main_direction, M_PI)) > 0.1) {
      return false;
    }
  }
  return true;
}

Pose2 randomPose(const FieldModel& field, double margin_m, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Pose2(u(rng) * (field.halfLength() + margin_m), u(rng) * (field.halfWidth() + margin_m),
               u(rng) * M_PI);
}

}  // namespace houghloc
