#include "tools/render/base_path.h"

#include <algorithm>
#include <cmath>

#include "field_models/angles.h"

namespace houghloc {
namespace {

/// Wraps tau into [0, period).
double wrapTime(double tau, double period) {
  if (period <= 0.0) return 0.0;
  return tau - period * std::floor(tau / period);
}

/// x = a sin(phi), y = b sin(phi) cos(phi), re-parameterised by arc length so the robot walks
/// at constant speed.
class FigureEight : public BasePath {
 public:
  FigureEight(const FieldModel& field, double speed) : speed_(speed) {
    a_ = 0.7 * field.halfLength();
    b_ = 1.2 * field.halfWidth();
    constexpr int kSamples = 4096;
    arc_.resize(kSamples + 1, 0.0);
    for (int i = 1; i <= kSamples; ++i) {
      arc_[i] = arc_[i - 1] + (point(phiOf(i)) - point(phiOf(i - 1))).norm();
    }
  }
  Pose2 pose(double tau) const override {
    const double s = wrapTime(tau, duration()) * speed_;
    const auto it = std::upper_bound(arc_.begin(), arc_.end(), s);
    const int i =
        std::clamp(static_cast<int>(it - arc_.begin()) - 1, 0, static_cast<int>(arc_.size()) - 2);
    const double f = (s - arc_[i]) / std::max(1e-12, arc_[i + 1] - arc_[i]);
    const double phi = phiOf(i) + f * (phiOf(i + 1) - phiOf(i));
    const Eigen::Vector2d p = point(phi);
    const Eigen::Vector2d d(a_ * std::cos(phi), b_ * std::cos(2.0 * phi));
    return Pose2(p.x(), p.y(), std::atan2(d.y(), d.x()));
  }
  double speed(double) const override { return speed_; }
  double duration() const override { return arc_.back() / speed_; }

 private:
  double phiOf(int i) const { return 2.0 * M_PI * i / (static_cast<double>(arc_.size()) - 1.0); }
  Eigen::Vector2d point(double phi) const {
    return {a_ * std::sin(phi), b_ * std::sin(phi) * std::cos(phi)};
  }
  double speed_, a_, b_;
  std::vector<double> arc_;  ///< arc length (m) at each sample of phi
};

class Spin : public BasePath {
 public:
  Spin(const Pose2& where, double rate) : where_(where), rate_(rate) {}
  Pose2 pose(double tau) const override {
    return Pose2(where_.x, where_.y, where_.theta + rate_ * tau);
  }
  double speed(double) const override { return 0.0; }
  double duration() const override { return 2.0 * M_PI / std::max(1e-6, std::abs(rate_)); }
  bool stationary() const override { return true; }

 private:
  Pose2 where_;
  double rate_;
};

class WaypointPath : public BasePath {
 public:
  WaypointPath(const std::vector<Waypoint>& w, bool loop, double turn_rate) : loop_(loop) {
    for (const Waypoint& p : w) poses_.emplace_back(p.x_m, p.y_m, p.theta_deg * kDeg);
    if (loop && poses_.size() > 1) poses_.push_back(poses_.front());
    times_.push_back(0.0);
    for (size_t i = 1; i < poses_.size(); ++i) {
      const double dist = (poses_[i].translation() - poses_[i - 1].translation()).norm();
      const double turn = std::abs(angleDifference(poses_[i].theta, poses_[i - 1].theta));
      const double speed = w[i % w.size()].speed_mps;
      speeds_.push_back(dist / std::max(1e-6, std::max(dist / speed, turn / turn_rate)));
      times_.push_back(times_.back() + std::max({dist / speed, turn / turn_rate, 1e-3}));
    }
  }
  Pose2 pose(double tau) const override {
    if (poses_.size() == 1) return poses_.front();
    const double t = loop_ ? wrapTime(tau, duration()) : std::clamp(tau, 0.0, duration());
    const size_t i = segment(t);
    const double f = (t - times_[i]) / (times_[i + 1] - times_[i]);
    const Pose2& a = poses_[i];
    const Pose2& b = poses_[i + 1];
    return Pose2(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y),
                 a.theta + f * angleDifference(b.theta, a.theta));
  }
  double speed(double tau) const override {
    if (poses_.size() == 1 || (!loop_ && tau >= duration())) return 0.0;
    return speeds_[segment(loop_ ? wrapTime(tau, duration()) : std::max(0.0, tau))];
  }
  double duration() const override { return times_.back(); }

 private:
  size_t segment(double t) const {
    const auto it = std::upper_bound(times_.begin(), times_.end(), t);
    return std::clamp<size_t>(static_cast<size_t>(it - times_.begin()), 1, times_.size() - 1) - 1;
  }
  bool loop_;
  std::vector<Pose2> poses_;
  std::vector<double> times_;   ///< arrival time at each pose (s)
  std::vector<double> speeds_;  ///< walking speed on each segment (m/s)
};

}  // namespace

std::unique_ptr<BasePath> makeFigureEight(const FieldModel& field, double speed_mps) {
  return std::make_unique<FigureEight>(field, speed_mps);
}

std::unique_ptr<BasePath> makeSpin(const Pose2& where, double rate_rad_s) {
  return std::make_unique<Spin>(where, rate_rad_s);
}

std::unique_ptr<BasePath> makeWaypointPath(const std::vector<Waypoint>& waypoints, bool loop,
                                           double turn_speed_rad_s) {
  return std::make_unique<WaypointPath>(waypoints, loop, turn_speed_rad_s);
}

}  // namespace houghloc
