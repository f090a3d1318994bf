#include "vision/camera_pose_corrector.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "vision/circle_fit.h"

namespace houghloc {
namespace {

constexpr double kQuarterTurn = 0.5 * 3.14159265358979323846;

Pose3 withCorrection(Pose3 pose, const Eigen::Vector2d& correction) {
  pose.roll += correction.x();
  pose.pitch += correction.y();
  return pose;
}

/// Angle wrapped into [-pi/4, pi/4): the deviation from the nearest field direction.
double wrapQuarter(double angle) {
  return angle - kQuarterTurn * std::floor((angle + 0.5 * kQuarterTurn) / kQuarterTurn);
}

}  // namespace

double CameraPoseCorrector::pointSigma(double range_m) const {
  const double range_2m = 0.5 * range_m;
  return config_.min_point_sigma_m * (1.0 + range_2m * range_2m);
}

double CameraPoseCorrector::directionSigma(const GroundSegment& segment) const {
  // Least-squares line through n points spread over length L: sigma_angle ~ sigma sqrt(12 / n) / L.
  const double floor = pointSigma(0.5 * (segment.a + segment.b).norm());  // at the midpoint
  const double sigma = std::max(segment.rms_m, floor);
  return sigma * std::sqrt(12.0 / std::max(2, segment.num_points)) /
         std::max(0.1, segment.length());
}

Pose3 CameraPoseCorrector::corrected(const Pose3& recorded) const {
  return config_.enabled ? withCorrection(recorded, applied_) : recorded;
}

void CameraPoseCorrector::reset() {
  last_map_inliers_ = 0;
  line_sigma_.setConstant(std::numeric_limits<double>::infinity());
  solution_.setZero();
  runaway_frames_ = 0;
  applied_.setZero();
  sigma_.setConstant(std::numeric_limits<double>::infinity());
  frames_.clear();
}

void CameraPoseCorrector::arcResiduals(const ArcObservation& arc, const Pose3& pose,
                                       std::vector<double>* out) const {
  const GroundProjectionConfig unlimited = unlimitedProjection();
  std::vector<Eigen::Vector2d> points;
  const GroundProjector projector(pose);
  for (const Eigen::Vector3d& ray : arc.rays) {
    if (const auto p = projector.project(ray, unlimited)) points.push_back(*p);
  }
  Eigen::Vector2d center;
  const bool ok = points.size() == arc.rays.size() &&
                  fitCircleFixedRadius(points, config_.circle_radius_m, &center);
  for (size_t i = 0; i < arc.rays.size(); ++i) {
    out->push_back(ok ? (points[i] - center).norm() - config_.circle_radius_m : std::nan(""));
  }
}

void CameraPoseCorrector::frameResiduals(const Frame& frame, const Eigen::Vector2d& c,
                                         std::vector<double>* out,
                                         std::vector<double>* gates) const {
  const GroundProjectionConfig unlimited = unlimitedProjection();
  const Pose3 pose = withCorrection(frame.recorded, c);
  const GroundProjector projector(pose);
  std::vector<double> angles;
  double cos_sum = 0.0, sin_sum = 0.0;
  for (const Observation& o : frame.observations) {
    const auto a = projector.project(o.ray_a, unlimited);
    const auto b = projector.project(o.ray_b, unlimited);
    const double angle = a && b ? std::atan2(b->y() - a->y(), b->x() - a->x()) : std::nan("");
    angles.push_back(angle);
    if (!std::isfinite(angle)) continue;
    // Field directions repeat every 90 deg: average 4 x angle on the circle.
    const double w = 1.0 / (o.sigma_rad * o.sigma_rad);
    cos_sum += w * std::cos(4.0 * angle);
    sin_sum += w * std::sin(4.0 * angle);
  }
  const double heading = 0.25 * std::atan2(sin_sum, cos_sum);
  for (size_t i = 0; i < angles.size(); ++i) {
    const double sigma = frame.observations[i].sigma_rad;
    out->push_back(wrapQuarter(angles[i] - heading) / sigma);
    if (gates) gates->push_back(config_.max_residual_rad / sigma);
  }
  std::vector<double> arc_raw;
  for (const ArcObservation& arc : frame.arcs) {
    arc_raw.clear();
    arcResiduals(arc, pose, &arc_raw);
    for (double r : arc_raw) {
      out->push_back(r / arc.sigma_m);
      if (gates) gates->push_back(config_.max_circle_residual_m / arc.sigma_m);
    }
  }
  for (const MapTiltObservation& map : frame.map) map.residuals(pose, config_.map, out, gates);
}

double CameraPoseCorrector::mapRange(const Frame& frame) const {
  // A tilt error u moves a ground point at range d by about u (d^2 + h^2) / h: only points it
  // moves by less than half the gate can be matched to the right line. u is what the lines and
  // arcs alone say; the map residuals must not vouch for themselves (matched at a wrong tilt
  // and a localizer pose that absorbed it, they confirm that tilt).
  const double u = line_sigma_.maxCoeff();
  const double h = frame.recorded.z;
  if (!(u > 0.0) || !(h > 0.0)) return 0.0;
  const double d2 = 0.5 * config_.map.gate_m * h / u - h * h;
  return d2 > 0.0 ? std::min(config_.map.max_range_m, std::sqrt(d2)) : 0.0;
}

void CameraPoseCorrector::linearize(Frame* frame, const Eigen::Vector2d& c) const {
  // Map matches follow the tilt (a point at 4 m moves ~1 cm per relinearize_rad) and reach as
  // far as the tilt is known.
  frame->map_range_m = mapRange(*frame);
  for (MapTiltObservation& map : frame->map) {
    map.associate(*field_, withCorrection(frame->recorded, c), config_.map, frame->map_range_m);
  }
  frame->line_residuals = static_cast<long>(frame->observations.size());
  for (const ArcObservation& arc : frame->arcs) {
    frame->line_residuals += static_cast<long>(arc.rays.size());
  }
  std::vector<double> r0, gates;
  frameResiduals(*frame, c, &r0, &gates);
  const long n = static_cast<long>(r0.size());
  frame->r = Eigen::Map<const Eigen::VectorXd>(r0.data(), n);
  frame->gate = Eigen::Map<const Eigen::VectorXd>(gates.data(), n);
  frame->jacobian.resize(n, 2);
  constexpr double kStep = 1e-5;
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d dc = Eigen::Vector2d::Zero();
    dc(k) = kStep;
    std::vector<double> r1;
    frameResiduals(*frame, c + dc, &r1, nullptr);
    frame->jacobian.col(k) = (Eigen::Map<const Eigen::VectorXd>(r1.data(), n) - frame->r) / kStep;
  }
  frame->at = c;
  cacheQuadratic(frame);
}

void CameraPoseCorrector::cacheQuadratic(Frame* frame) const {
  frame->quadratic = true;
  frame->jtj.setZero();
  frame->line_jtj.setZero();
  frame->jtr.setZero();
  frame->rtr = 0.0;
  frame->used = 0;
  for (long i = 0; i < frame->r.size(); ++i) {
    const Eigen::RowVector2d j = frame->jacobian.row(i);
    const double r = frame->r(i);
    if (!std::isfinite(r) || !j.allFinite()) continue;                  // unusable at every c
    const double reach = config_.relinearize_rad * j.cwiseAbs().sum();  // >= |j (c - at)|
    if (std::abs(r) - reach > frame->gate(i)) continue;  // outside its gate at every c
    if (!(std::abs(r) + reach < std::min(frame->gate(i), config_.huber_sigmas))) {
      frame->quadratic = false;  // may cross a gate or the Huber threshold: per residual
      return;
    }
    frame->jtj += j.transpose() * j;
    if (i < frame->line_residuals) frame->line_jtj += j.transpose() * j;
    frame->jtr += j.transpose() * r;
    frame->rtr += r * r;
    ++frame->used;
  }
}

bool CameraPoseCorrector::solve() {
  // The prior keeps directions the lines seen so far do not constrain at 0.
  const double prior = 1.0 / (config_.prior_sigma_rad * config_.prior_sigma_rad);
  // After a runaway the solve restarts from 0 (re-linearising every frame there). A runaway
  // that persists in a larger window (a camera whose lines never constrain its tilt: the NAO's
  // bottom camera) goes on from where it ended, not applied, and restarts only every
  // runaway_restart_solves: restarting at every frame re-linearised the whole window twice per
  // frame (16 ms per image after two minutes, tests/tools/node/node_soak_test).
  const int restart_every = std::max(1, config_.runaway_restart_solves);
  const bool restart =
      runaway() && (static_cast<int>(frames_.size()) <= config_.runaway_restart_frames ||
                    runaway_frames_ % restart_every == 1);
  Eigen::Vector2d c = restart ? Eigen::Vector2d::Zero() : solution_;
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d line_information = Eigen::Matrix2d::Zero();  ///< of the lines and arcs alone
  double chi2 = 0.0;
  long residual_count = 0;
  // Re-linearise the frames the estimate moved away from, solve on the linear model, repeat
  // while the solution moves (only while converging from a large error).
  // A runaway going on is not applied, so its frames need re-linearising only when it moved by
  // a fair part of its own uncertainty (it drifts with every frame, so loosely is it held).
  const double relinearize_rad =
      runaway() && !restart
          ? std::clamp(0.1 * sigma_.maxCoeff(), config_.relinearize_rad, config_.max_correction_rad)
          : config_.relinearize_rad;
  for (int pass = 0; pass < 3; ++pass) {
    for (Frame& frame : frames_) {
      const bool moved = !((c - frame.at).cwiseAbs().maxCoeff() <= relinearize_rad);
      // Also when the tilt is now known well enough to match points 20 % farther out.
      const bool reach = !frame.map.empty() && frame.map_range_m < config_.map.max_range_m &&
                         mapRange(frame) > 1.2 * frame.map_range_m + 0.05;
      if (moved || reach) linearize(&frame, c);
    }
    const Eigen::Vector2d start = c;
    for (int it = 0; it <= config_.iterations; ++it) {
      information.setZero();
      line_information.setZero();
      Eigen::Vector2d g = Eigen::Vector2d::Zero();
      chi2 = 0.0;
      residual_count = 0;
      for (const Frame& frame : frames_) {
        const Eigen::Vector2d dc = c - frame.at;
        if (frame.quadratic && dc.cwiseAbs().maxCoeff() <= config_.relinearize_rad) {
          // Sum of (r + J dc)^2 with unit weights, from the kept sums.
          information += frame.jtj;
          line_information += frame.line_jtj;
          g += frame.jtr + frame.jtj * dc;
          chi2 += frame.rtr + 2.0 * dc.dot(frame.jtr) + dc.dot(frame.jtj * dc);
          residual_count += frame.used;
          continue;
        }
        for (long i = 0; i < frame.r.size(); ++i) {
          const Eigen::RowVector2d j = frame.jacobian.row(i);
          const double r = frame.r(i) + j.dot(dc);
          if (!std::isfinite(r) || !j.allFinite() || std::abs(r) > frame.gate(i)) continue;
          // Huber as IRLS: weight = min(1, k / |r|) on the squared residual.
          const double w = std::min(1.0, config_.huber_sigmas / std::abs(r));
          information += w * j.transpose() * j;
          if (i < frame.line_residuals) line_information += w * j.transpose() * j;
          g += w * j.transpose() * r;
          chi2 += w * r * r;
          ++residual_count;
        }
      }
      if (it == config_.iterations) break;  // the last round only measures the information
      const Eigen::Matrix2d h = information + prior * Eigen::Matrix2d::Identity();
      const Eigen::Vector2d step = -h.ldlt().solve(g + prior * c);
      if (!step.allFinite()) return false;
      c += step;
      if (step.norm() < 1e-8) it = config_.iterations - 1;  // converged: measure, then stop
    }
    if ((c - start).cwiseAbs().maxCoeff() <= relinearize_rad) break;
  }
  const double limit = config_.max_correction_rad;
  // A solution at or beyond the limit is a runaway of the linearised steps on too little data:
  // the first segments of a walk with a 2 deg error once sent it to +4 deg, then to -4 deg, and
  // it stayed there, applied, for 3 s. It is not applied, and the next solve starts from 0
  // (see the start of this function).
  runaway_frames_ = (c.cwiseAbs().array() >= limit).any() ? runaway_frames_ + 1 : 0;
  solution_ = c;
  // Covariance of the estimate; each frame's heading is a nuisance parameter, and sigmas from
  // a few spots' rms may be too small, so the residual chi^2 per degree of freedom scales it up.
  long nuisance = 2;  // roll, pitch; plus each frame's heading and each arc's centre
  for (const Frame& f : frames_) {
    nuisance += (f.observations.empty() ? 0 : 1) + 2 * static_cast<long>(f.arcs.size());
    for (const MapTiltObservation& map : f.map) nuisance += map.inliers() > 0 ? 3 : 0;
  }
  const long dof = residual_count - nuisance;
  const double scale = dof > 0 ? std::max(1.0, chi2 / static_cast<double>(dof)) : 1e6;
  const Eigen::Matrix2d covariance =
      scale * (information + prior * Eigen::Matrix2d::Identity()).inverse();
  sigma_ = covariance.diagonal().cwiseSqrt();
  line_sigma_ = (scale * (line_information + prior * Eigen::Matrix2d::Identity()).inverse())
                    .diagonal()
                    .cwiseSqrt();
  return true;
}

std::optional<MapTiltObservation> CameraPoseCorrector::mapObservation(
    const CorrectorMapInput& input, const Pose3& recorded) const {
  if (!config_.map.enabled || !field_ || !input.rays || !input.field_T_robot) return std::nullopt;
  if (!input.field_T_robot->isFinite()) return std::nullopt;
  GroundProjectionConfig in_range;
  in_range.max_range_m = config_.map.max_range_m;
  in_range.min_depression_rad = 0.0;
  const GroundProjector projector(corrected(recorded));
  std::vector<std::pair<const SpotRay*, double>> near;  // with its range, m
  for (const SpotRay& ray : *input.rays) {
    if (const auto p = projector.project(ray.ray_camera, in_range))
      near.push_back({&ray, p->norm()});
  }
  const size_t wanted = static_cast<size_t>(std::max(1, config_.map.max_points_per_frame));
  if (near.size() < static_cast<size_t>(config_.map.min_inliers)) return std::nullopt;
  std::vector<Eigen::Vector3d> rays;
  std::vector<double> sigmas;
  const double stride = std::max(1.0, static_cast<double>(near.size()) / wanted);
  for (double k = 0.0; k < static_cast<double>(near.size()); k += stride) {
    const auto& [ray, range_m] = near[static_cast<size_t>(k)];
    rays.push_back(ray->ray_camera);
    sigmas.push_back(pointSigma(range_m));
  }
  return MapTiltObservation(std::move(rays), std::move(sigmas), *input.field_T_robot);
}

bool CameraPoseCorrector::update(const std::vector<GroundSegment>& segments,
                                 const std::vector<CircleCandidate>& circles, const Pose3& recorded,
                                 const CorrectorMapInput& map_input) {
  if (!config_.enabled) return false;
  std::vector<const GroundSegment*> used;
  for (const GroundSegment& s : segments) {
    if (s.length() >= config_.min_segment_length_m && s.rms_m <= config_.max_segment_rms_m &&
        s.num_points >= config_.min_segment_points) {
      used.push_back(&s);
    }
  }
  std::sort(used.begin(), used.end(), [](const GroundSegment* a, const GroundSegment* b) {
    return a->length() > b->length();
  });
  used.resize(
      std::min(used.size(), static_cast<size_t>(std::max(0, config_.max_segments_per_frame))));
  Frame frame;
  frame.recorded = recorded;
  // A frame with one direction and one segment says nothing (its heading absorbs it).
  if (used.size() >= 2) {
    for (const GroundSegment* s : used) {
      frame.observations.push_back({s->ray_a_camera, s->ray_b_camera, directionSigma(*s)});
    }
  }
  if (config_.use_circles && config_.circle_radius_m > 0.0) {
    for (const CircleCandidate& circle : circles) {
      if (circle.rays_camera.size() < 8) continue;
      frame.arcs.push_back({circle.rays_camera, pointSigma(circle.center.norm())});
    }
  }
  if (auto map = mapObservation(map_input, recorded)) frame.map.push_back(std::move(*map));
  const bool frame_added = !frame.observations.empty() || !frame.arcs.empty() || !frame.map.empty();
  if (frame_added) frames_.push_back(std::move(frame));
  while (static_cast<int>(frames_.size()) > std::max(1, config_.window_frames)) frames_.pop_front();
  if (frames_.empty()) return false;

  const bool solved = solve();
  // The frame just added was associated in solve()'s first pass (it had never been linearised).
  last_map_inliers_ = 0;
  if (!frames_.empty() && !frames_.back().map.empty() && frame_added) {
    last_map_inliers_ = frames_.back().map.front().inliers();
  }
  if (!solved) return false;
  const bool enough = static_cast<int>(frames_.size()) >= config_.min_frames;
  const Eigen::Vector2d estimated = estimate();
  for (int k = 0; k < 2; ++k) {
    const bool significant = std::abs(estimated(k)) >= config_.significance_sigmas * sigma_(k) &&
                             std::abs(estimated(k)) >= config_.min_correction_rad;
    applied_(k) = enough && significant && !runaway() ? estimated(k) : 0.0;
  }
  return true;
}

}  // namespace houghloc
