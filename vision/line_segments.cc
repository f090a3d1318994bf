#include "vision/line_segments.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace houghloc {
namespace {

struct ChainPoint {
  Eigen::Vector2d p;
  const SpotRay* ray;
};

/// Links spots of one scan direction into chains: sorted along the scan axis (u for vertical
/// scanlines, v for horizontal ones), each joins the open chain that predicts it best.
std::vector<std::vector<const SpotRay*>> linkChains(const std::vector<const SpotRay*>& spots,
                                                    bool vertical, const LineSegmentConfig& cfg) {
  const auto along = [vertical](const SpotRay* s) {
    return vertical ? s->pixel.x() : s->pixel.y();
  };
  const auto across = [vertical](const SpotRay* s) {
    return vertical ? s->pixel.y() : s->pixel.x();
  };
  std::vector<const SpotRay*> sorted = spots;
  std::sort(sorted.begin(), sorted.end(),
            [&](const SpotRay* a, const SpotRay* b) { return along(a) < along(b); });
  std::vector<std::vector<const SpotRay*>> chains;
  for (const SpotRay* spot : sorted) {
    int best = -1;
    double best_error = 0.0;
    for (size_t c = 0; c < chains.size(); ++c) {
      const std::vector<const SpotRay*>& chain = chains[c];
      const double gap = along(spot) - along(chain.back());
      if (gap <= 0.0 || gap > cfg.link_gap_px) continue;
      double predicted = across(chain.back()),
             tolerance = cfg.link_slope * gap + cfg.link_tolerance_px;
      if (chain.size() >= 2) {
        const SpotRay* prev = chain[chain.size() - 2];
        const double slope = (across(chain.back()) - across(prev)) /
                             std::max(1e-3, static_cast<double>(along(chain.back()) - along(prev)));
        predicted += slope * gap;
        tolerance = cfg.link_tolerance_px + 0.3 * gap;
      }
      const double error = std::abs(across(spot) - predicted);
      if (error <= tolerance && (best < 0 || error < best_error))
        best = static_cast<int>(c), best_error = error;
    }
    if (best >= 0) {
      chains[static_cast<size_t>(best)].push_back(spot);
    } else {
      chains.push_back({spot});
    }
  }
  return chains;
}

/// Least-squares line through points[begin, end): centroid and unit direction; rms distance.
double fitLine(const std::vector<ChainPoint>& points, size_t begin, size_t end,
               Eigen::Vector2d* centroid, Eigen::Vector2d* direction) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (size_t i = begin; i < end; ++i) mean += points[i].p;
  mean /= static_cast<double>(end - begin);
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (size_t i = begin; i < end; ++i)
    cov += (points[i].p - mean) * (points[i].p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(cov);
  *centroid = mean;
  *direction = solver.eigenvectors().col(1);
  return std::sqrt(std::max(0.0, solver.eigenvalues()(0)) / static_cast<double>(end - begin));
}

/// Where the camera is and how it is turned, for turning fitted ground points back into rays.
struct CameraFrame {
  Eigen::Matrix3d camera_R_robot;
  Eigen::Vector3d position;
};

void splitAndFit(const std::vector<ChainPoint>& points, size_t begin, size_t end,
                 const LineSegmentConfig& cfg, const CameraFrame& camera,
                 std::vector<GroundSegment>* segments, int depth) {
  if (end <= begin) return;
  if (end - begin < static_cast<size_t>(cfg.min_points) || depth > 12) return;
  const Eigen::Vector2d a = points[begin].p, b = points[end - 1].p;
  const Eigen::Vector2d chord = (b - a).normalized();
  size_t worst = begin;
  double worst_distance = 0.0;
  for (size_t i = begin + 1; i + 1 < end; ++i) {
    const Eigen::Vector2d d = points[i].p - a;
    const double distance = std::abs(d.x() * chord.y() - d.y() * chord.x());
    if (distance > worst_distance) worst_distance = distance, worst = i;
  }
  if (worst_distance > cfg.split_distance_m) {
    // The split point (a corner) belongs to neither straight piece: near a corner the spots
    // of the crossing scanlines are pulled toward the other line, which would tilt both fits.
    splitAndFit(points, begin, worst, cfg, camera, segments, depth + 1);
    splitAndFit(points, worst + 1, end, cfg, camera, segments, depth + 1);
    return;
  }
  Eigen::Vector2d centroid, direction;
  const double rms = fitLine(points, begin, end, &centroid, &direction);
  GroundSegment segment;
  segment.a = centroid + direction * direction.dot(a - centroid);
  segment.b = centroid + direction * direction.dot(b - centroid);
  segment.rms_m = rms;
  segment.num_points = static_cast<int>(end - begin);
  // The fitted end points' rays (a ground line is a straight line in the undistorted image, so
  // re-projecting them with another camera tilt still gives this fit under that tilt).
  segment.ray_a_camera = camera.camera_R_robot *
                         (Eigen::Vector3d(segment.a.x(), segment.a.y(), 0.0) - camera.position);
  segment.ray_b_camera = camera.camera_R_robot *
                         (Eigen::Vector3d(segment.b.x(), segment.b.y(), 0.0) - camera.position);
  if (rms <= cfg.max_rms_m && segment.length() >= cfg.min_length_m) segments->push_back(segment);
}

/// Algebraic (Kasa) circle fit; false when degenerate.
bool fitCircle(const std::vector<ChainPoint>& points, CircleCandidate* circle) {
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd rhs(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    a.row(static_cast<long>(i)) << points[i].p.x(), points[i].p.y(), 1.0;
    rhs(static_cast<long>(i)) = -points[i].p.squaredNorm();
  }
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(rhs);
  circle->center = {-0.5 * x(0), -0.5 * x(1)};
  const double r2 = circle->center.squaredNorm() - x(2);
  if (!(r2 > 0.0)) return false;
  circle->radius_m = std::sqrt(r2);
  double sum = 0.0;
  for (const ChainPoint& p : points) {
    const double e = (p.p - circle->center).norm() - circle->radius_m;
    sum += e * e;
  }
  circle->rms_m = std::sqrt(sum / static_cast<double>(points.size()));
  circle->num_points = static_cast<int>(points.size());
  return true;
}

}  // namespace

LineFeatures fitLineFeatures(const std::vector<SpotRay>& rays, const Pose3& robot_T_camera,
                             const GroundProjectionConfig& projection,
                             const LineSegmentConfig& config) {
  LineFeatures features;
  if (!config.enabled) return features;
  const CameraFrame camera{robot_T_camera.rotation().transpose(),
                           {robot_T_camera.x, robot_T_camera.y, robot_T_camera.z}};
  const GroundProjector projector(robot_T_camera);
  for (const bool vertical : {true, false}) {
    std::vector<const SpotRay*> spots;
    for (const SpotRay& ray : rays) {
      if (ray.vertical_scan == vertical) spots.push_back(&ray);
    }
    for (const auto& chain : linkChains(spots, vertical, config)) {
      std::vector<ChainPoint> points;
      for (const SpotRay* ray : chain) {
        if (const auto p = projector.project(ray->ray_camera, projection)) {
          points.push_back({*p, ray});
        }
      }
      if (points.size() < static_cast<size_t>(config.min_points)) continue;
      const size_t before = features.segments.size();
      splitAndFit(points, 0, points.size(), config, camera, &features.segments, 0);
      const bool straight = features.segments.size() == before + 1 &&
                            features.segments.back().num_points == static_cast<int>(points.size());
      // A bent chain that a circle fits well is an arc (centre circle, corner arcs): its chords
      // are no straight field lines and would mislead the pitch/roll correction.
      CircleCandidate circle;
      if (straight || points.size() < 8 || !fitCircle(points, &circle) ||
          circle.rms_m > config.circle_max_rms_m || circle.radius_m > config.max_arc_radius_m) {
        continue;
      }
      features.segments.resize(before);
      if (config.circle_radius_m > 0.0 &&
          std::abs(circle.radius_m - config.circle_radius_m) <=
              config.circle_radius_tolerance * config.circle_radius_m) {
        const size_t n = points.size(),
                     keep = std::min(n, static_cast<size_t>(std::max(2, config.max_circle_rays)));
        for (size_t k = 0; k < keep; ++k) {
          circle.rays_camera.push_back(points[k * (n - 1) / (keep - 1)].ray->ray_camera);
        }
        features.circles.push_back(circle);
      }
    }
  }
  return features;
}

}  // namespace houghloc
