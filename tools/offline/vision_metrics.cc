#include "tools/offline/vision_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "field_models/field_distance.h"

namespace houghloc {
namespace {

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * (values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

void sampleLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double step,
                std::vector<Eigen::Vector2d>* out) {
  const int n = std::max(1, static_cast<int>(std::round((b - a).norm() / step)));
  for (int i = 0; i <= n; ++i) out->push_back(a + (b - a) * (static_cast<double>(i) / n));
}

}  // namespace

VisionMetricsAccumulator::VisionMetricsAccumulator(const FieldModel& field,
                                                   const VisionMetricsConfig& config)
    : field_(field), config_(config), bands_(config.band_edges_m.size() - 1) {}

int VisionMetricsAccumulator::bandOf(double range_m) const {
  for (size_t b = 0; b + 1 < config_.band_edges_m.size(); ++b) {
    if (range_m >= config_.band_edges_m[b] && range_m < config_.band_edges_m[b + 1]) {
      return static_cast<int>(b);
    }
  }
  return -1;
}

std::vector<Eigen::Vector2d> VisionMetricsAccumulator::featureSamples(
    const std::string& feature) const {
  std::vector<Eigen::Vector2d> samples;
  int index = -1;
  char kind[16] = {0};
  if (std::sscanf(feature.c_str(), "%15[a-z][%d]", kind, &index) != 2 || index < 0) return samples;
  const std::string k = kind;
  const double step = config_.sample_step_m;
  if (k == "segments" && index < static_cast<int>(field_.segments.size())) {
    const Segment2& s = field_.segments[static_cast<size_t>(index)];
    sampleLine(s.a, s.b, step, &samples);
  } else if (k == "arcs" && index < static_cast<int>(field_.arcs.size())) {
    const Arc2& arc = field_.arcs[static_cast<size_t>(index)];
    const int n = std::max(1, static_cast<int>(std::round(arc.length() / step)));
    const int last = arc.isFullCircle() ? n - 1 : n;
    for (int i = 0; i <= last; ++i)
      samples.push_back(arc.pointAt(arc.start_rad + arc.sweep_rad * i / n));
  } else if (k == "marks" && index < static_cast<int>(field_.marks.size())) {
    samples.push_back(field_.marks[static_cast<size_t>(index)].center);
  }
  return samples;
}

void VisionMetricsAccumulator::addFrame(const GroundPoints& points, const Pose2& field_T_robot,
                                        const std::vector<VisibleRecord>& visible,
                                        const CameraModel& camera) {
  ++frames_;
  for (const GroundPoint& p : points.points) {
    const double error = nearestFeature(field_, field_T_robot.transform(p.p_robot)).distance_m;
    const bool tp = error <= config_.precision_radius_m;
    ++points_;
    true_positives_ += tp;
    const int b = bandOf(p.p_robot.norm());
    if (b < 0) continue;
    Band& band = bands_[static_cast<size_t>(b)];
    ++band.points;
    if (tp) ++band.true_positives, band.errors.push_back(error);
  }
  // The edge samples lie on the ray from the camera: compare with the carpet's edge on it.
  const Eigen::Vector2d camera_field =
      field_T_robot.transform(Eigen::Vector2d(camera.pose().x, camera.pose().y));
  for (const FieldEdgePoint& e : points.field_edge) {
    const Eigen::Vector2d ray = field_T_robot.transform(e.p_robot) - camera_field;
    if (!(ray.norm() > 1e-6) || !(e.range_sigma_m > 0.0)) continue;
    const double edge = rangeToRectangle(camera_field, ray.normalized(), field_.outerHalfLength(),
                                         field_.outerHalfWidth());
    edge_errors_m_.push_back(ray.norm() - edge);
    edge_errors_sigmas_.push_back((ray.norm() - edge) / e.range_sigma_m);
  }
  const Pose2 robot_T_field = field_T_robot.inverse();
  const double max_range = config_.band_edges_m.back();
  const double r2 = config_.recall_radius_m * config_.recall_radius_m;
  for (const VisibleRecord& record : visible) {
    std::vector<int> in_view_band;
    std::vector<bool> found;
    for (const Eigen::Vector2d& p_field : featureSamples(record.feature)) {
      const Eigen::Vector2d p_robot = robot_T_field.transform(p_field);
      if (p_robot.norm() >= max_range) continue;
      const auto pixel = camera.project({p_robot.x(), p_robot.y(), 0.0});
      if (!pixel || !camera.inImage(*pixel)) continue;
      in_view_band.push_back(bandOf(p_robot.norm()));
      found.push_back(std::any_of(
          points.points.begin(), points.points.end(),
          [&](const GroundPoint& g) { return (g.p_robot - p_robot).squaredNorm() <= r2; }));
    }
    if (in_view_band.empty()) continue;
    // Part of the in-view length may be occluded: scale to the renderer's visible length.
    const double in_view_m = in_view_band.size() * config_.sample_step_m;
    const double scale = std::min(1.0, record.visible_length_m / in_view_m);
    for (size_t b = 0; b < bands_.size(); ++b) {
      double visible_m = 0.0, found_m = 0.0;
      for (size_t i = 0; i < in_view_band.size(); ++i) {
        if (in_view_band[i] != static_cast<int>(b)) continue;
        visible_m += config_.sample_step_m * scale;
        if (found[i]) found_m += config_.sample_step_m;
      }
      bands_[b].visible_m += visible_m;
      bands_[b].found_m += std::min(found_m, visible_m);
    }
  }
}

VisionMetrics VisionMetricsAccumulator::result() const {
  VisionMetrics m;
  m.frames_scored = frames_;
  m.points = points_;
  m.true_positives = true_positives_;
  m.precision = points_ > 0 ? static_cast<double>(true_positives_) / points_ : 0.0;
  for (size_t b = 0; b < bands_.size(); ++b) {
    const Band& band = bands_[b];
    VisionBandMetrics out;
    out.min_m = config_.band_edges_m[b];
    out.max_m = config_.band_edges_m[b + 1];
    out.points = band.points;
    out.true_positives = band.true_positives;
    out.visible_m = band.visible_m;
    out.found_m = band.found_m;
    out.precision = band.points > 0 ? static_cast<double>(band.true_positives) / band.points : 0.0;
    out.recall = band.visible_m > 0.0 ? band.found_m / band.visible_m : 0.0;
    out.median_error_m = quantile(band.errors, 0.5);
    out.p95_error_m = quantile(band.errors, 0.95);
    m.bands.push_back(out);
  }
  FieldEdgeMetrics& edge = m.field_edge;
  edge.samples = static_cast<long>(edge_errors_m_.size());
  if (edge.samples > 0) {
    std::vector<double> abs_m, abs_sigmas;
    long within = 0, nearer = 0, farther = 0;
    for (size_t i = 0; i < edge_errors_m_.size(); ++i) {
      abs_m.push_back(std::abs(edge_errors_m_[i]));
      abs_sigmas.push_back(std::abs(edge_errors_sigmas_[i]));
      within += abs_sigmas.back() <= 3.0;
      nearer += edge_errors_sigmas_[i] < -3.0;
      farther += edge_errors_sigmas_[i] > 3.0;
    }
    const double n = static_cast<double>(edge.samples);
    edge.median_abs_error_m = quantile(abs_m, 0.5);
    edge.median_abs_error_sigmas = quantile(abs_sigmas, 0.5);
    edge.within_3_sigma = within / n;
    edge.nearer_share = nearer / n;
    edge.farther_share = farther / n;
  }
  return m;
}

nlohmann::json toJson(const VisionMetrics& m) {
  nlohmann::json bands = nlohmann::json::array();
  for (const VisionBandMetrics& b : m.bands) {
    bands.push_back({{"range_m", {b.min_m, b.max_m}},
                     {"points", b.points},
                     {"precision", b.precision},
                     {"recall", b.recall},
                     {"visible_m", b.visible_m},
                     {"found_m", b.found_m},
                     {"median_error_m", b.median_error_m},
                     {"p95_error_m", b.p95_error_m}});
  }
  const FieldEdgeMetrics& e = m.field_edge;
  return {{"frames_scored", m.frames_scored},
          {"points", m.points},
          {"precision", m.precision},
          {"bands", bands},
          {"field_edge",
           {{"samples", e.samples},
            {"median_abs_error_m", e.median_abs_error_m},
            {"median_abs_error_sigmas", e.median_abs_error_sigmas},
            {"within_3_sigma", e.within_3_sigma},
            {"nearer_share", e.nearer_share},
            {"farther_share", e.farther_share}}}};
}

std::vector<VisibleRecord> visibleAt(const std::vector<VisibleRecord>& visible, std::int64_t t_us) {
  std::vector<VisibleRecord> rows;
  std::copy_if(visible.begin(), visible.end(), std::back_inserter(rows),
               [t_us](const VisibleRecord& r) { return r.t_us == t_us; });
  return rows;
}

}  // namespace houghloc
