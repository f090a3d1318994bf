#include "tools/render/trajectory.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "field_models/angles.h"

namespace houghloc {
namespace {

constexpr double kFallingTime_s = 0.3;  ///< from upright to lying

/// First frame time at or after t (events line up with frames).
double snapToFrame(double t, double fps) { return std::ceil(t * fps - 1e-6) / fps; }

std::mt19937 rngFor(std::uint32_t seed, std::uint32_t salt) {
  std::seed_seq seq{seed, salt, 0x7261u};
  return std::mt19937(seq);
}

}  // namespace

Trajectory::Trajectory(const Scenario& scenario, const FieldModel& field)
    : scenario_(scenario), field_(field) {
  const TrajectoryConfig& c = scenario.trajectory;
  const double duration = scenario.frames / scenario.fps;
  random_poses_ = c.name == "random-poses";
  std::mt19937 rng = rngFor(scenario.seed, 1);
  Piece first;
  if (c.name == "spin") {
    path_ = makeSpin(Pose2(c.spin_x_m, c.spin_y_m, 0.0), c.spin_rate_dps * kDeg);
  } else if (c.name == "waypoints") {
    path_ = makeWaypointPath(c.waypoints, c.loop, c.turn_speed_dps * kDeg);
  } else {
    path_ = makeFigureEight(field, c.walk_speed_mps);
    first.tau0 = std::uniform_real_distribution<double>(0.0, path_->duration())(rng);
  }
  pieces_.push_back(first);
  const std::string& mode = scenario.head.mode;
  head_sweeps_ = mode == "sweep" || (mode == "auto" && c.name != "spin" && !random_poses_);

  std::vector<KidnapConfig> kidnaps = scenario.kidnaps;
  std::vector<FallConfig> falls = scenario.falls;
  if (c.name == "kidnap" && kidnaps.empty()) {
    kidnaps = {KidnapConfig{duration / 3.0, {}}, KidnapConfig{2.0 * duration / 3.0, {}}};
  }
  if (c.name == "fall" && falls.empty()) falls = {FallConfig{0.4 * duration, 3.0}};
  if (random_poses_) return;  // independent frames: nothing to disturb
  // Apply disturbances in time order; each one starts a new piece.
  struct Disturbance {
    double t;
    int kidnap, fall;
  };
  std::vector<Disturbance> all;
  for (size_t i = 0; i < kidnaps.size(); ++i) all.push_back({kidnaps[i].t_s, int(i), -1});
  for (size_t i = 0; i < falls.size(); ++i) all.push_back({falls[i].t_s, -1, int(i)});
  std::stable_sort(all.begin(), all.end(),
                   [](const Disturbance& a, const Disturbance& b) { return a.t < b.t; });
  std::uint32_t salt = 100;
  for (const Disturbance& d : all) {
    if (d.t <= pieces_.back().t0 || d.t < 0.0) continue;  // overlaps a fall: dropped
    if (d.kidnap >= 0) {
      KidnapConfig k = kidnaps[d.kidnap];
      k.t_s = snapToFrame(k.t_s, scenario.fps);
      addKidnap(k, ++salt);
    } else {
      FallConfig f = falls[d.fall];
      f.t_s = snapToFrame(f.t_s, scenario.fps);
      addFall(f, ++salt);
    }
  }
}

Pose2 Trajectory::basePose(const Piece& piece, double t) const {
  const double tau = piece.fallen ? piece.tau0 : piece.tau0 + (t - piece.t0);
  return piece.K * path_->pose(tau);
}

void Trajectory::addKidnap(const KidnapConfig& kidnap, std::uint32_t salt) {
  std::mt19937 rng = rngFor(scenario_.seed, salt);
  const Piece& prev = pieces_.back();
  Piece next = prev;
  next.t0 = kidnap.t_s;
  next.tau0 = prev.tau0 + (kidnap.t_s - prev.t0);
  next.fallen = false;
  if (kidnap.to || path_->stationary()) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Pose2 to = kidnap.to ? *kidnap.to
                               : Pose2(0.8 * field_.halfLength() * u(rng),
                                       0.8 * field_.halfWidth() * u(rng), M_PI * u(rng));
    next.K = to * path_->pose(next.tau0).inverse();
  } else {
    // Elsewhere on the same loop, so the robot keeps walking on the field.
    next.tau0 += std::uniform_real_distribution<double>(0.3, 0.7)(rng) * path_->duration();
  }
  pieces_.push_back(next);
  events_.push_back({kidnap.t_s, "KIDNAP"});
}

void Trajectory::addFall(const FallConfig& fall, std::uint32_t salt) {
  std::mt19937 rng = rngFor(scenario_.seed, salt);
  std::normal_distribution<double> n(0.0, 1.0);
  const Piece& prev = pieces_.back();
  Piece lying = prev;
  lying.t0 = fall.t_s;
  lying.tau0 = prev.tau0 + (fall.t_s - prev.t0);
  lying.fallen = true;
  lying.fall_duration = fall.duration_s;
  lying.fall_offset = Pose2(-0.15 + 0.05 * n(rng), 0.05 * n(rng), 0.3 * n(rng));
  pieces_.push_back(lying);
  // Afterwards the robot walks on from where it got up.
  Piece after = lying;
  after.t0 = fall.t_s + fall.duration_s;
  after.fallen = false;
  const Pose2 at = path_->pose(lying.tau0);
  after.K = lying.K * at * lying.fall_offset * at.inverse();
  pieces_.push_back(after);
  events_.push_back({fall.t_s, "FALL_START"});
  events_.push_back({after.t0, "FALL_END"});
}

const Trajectory::Piece& Trajectory::pieceAt(double t) const {
  const Piece* piece = &pieces_.front();
  for (const Piece& p : pieces_) {
    if (p.t0 <= t) piece = &p;
  }
  return *piece;
}

Pose2 Trajectory::walkedMotion(double t0, double t1) const {
  const Piece& piece = pieceAt(t1);
  if (random_poses_ || piece.fallen) return Pose2();
  return basePose(piece, t0).inverse() * basePose(piece, t1);
}

double Trajectory::pan(double t) const {
  const HeadConfig& h = scenario_.head;
  if (h.mode == "schedule") {
    const auto& k = h.schedule;
    if (t <= k.front().t_s) return k.front().pan_deg * kDeg;
    for (size_t i = 1; i < k.size(); ++i) {
      if (t <= k[i].t_s) {
        const double f = (t - k[i - 1].t_s) / std::max(1e-9, k[i].t_s - k[i - 1].t_s);
        return (k[i - 1].pan_deg + f * (k[i].pan_deg - k[i - 1].pan_deg)) * kDeg;
      }
    }
    return k.back().pan_deg * kDeg;
  }
  const double sweep =
      head_sweeps_ ? h.sweep_amplitude_deg * std::sin(2.0 * M_PI * t / h.sweep_period_s) : 0.0;
  return (h.pan_deg + sweep) * kDeg;
}

RobotState Trajectory::at(double t) const {
  RobotState s;
  const HeadConfig& h = scenario_.head;
  s.pan_rad = pan(t);
  s.tilt_rad = h.tilt_deg * kDeg;
  if (h.mode == "schedule") {
    const auto& k = h.schedule;
    s.tilt_rad = k.back().tilt_deg * kDeg;
    if (t <= k.front().t_s) s.tilt_rad = k.front().tilt_deg * kDeg;
    for (size_t i = 1; i < k.size() && t > k.front().t_s; ++i) {
      if (t <= k[i].t_s) {
        const double f = (t - k[i - 1].t_s) / std::max(1e-9, k[i].t_s - k[i - 1].t_s);
        s.tilt_rad = (k[i - 1].tilt_deg + f * (k[i].tilt_deg - k[i - 1].tilt_deg)) * kDeg;
        break;
      }
    }
  }
  if (random_poses_) {
    const auto frame = static_cast<std::uint32_t>(std::llround(t * scenario_.fps));
    std::mt19937 rng = rngFor(scenario_.seed, 1000000u + frame);
    const double m = scenario_.trajectory.random_margin_m;
    std::uniform_real_distribution<double> ux(-field_.halfLength() - m, field_.halfLength() + m);
    std::uniform_real_distribution<double> uy(-field_.halfWidth() - m, field_.halfWidth() + m);
    std::uniform_real_distribution<double> ut(-M_PI, M_PI);
    const double x = ux(rng), y = uy(rng);
    s.field_T_robot = Pose2(x, y, ut(rng));
    return s;
  }
  const Piece* piece = &pieceAt(t);
  s.field_T_robot = basePose(*piece, t);
  if (piece->fallen) {
    const double since = t - piece->t0;
    s.fall_phase = std::clamp(since / piece->fall_duration, 0.0, 1.0);
    // Slide into the fall displacement while falling.
    const double f = std::clamp(since / kFallingTime_s, 0.0, 1.0);
    const Pose2& o = piece->fall_offset;
    s.field_T_robot = s.field_T_robot * Pose2(f * o.x, f * o.y, f * o.theta);
    return s;
  }
  const double tau = piece->tau0 + (t - piece->t0);
  s.walk_speed_mps = path_->speed(tau);
  return s;
}

}  // namespace houghloc
