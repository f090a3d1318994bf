#include "tools/render/moving_objects.h"

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace houghloc {
namespace {

/// Position bouncing between -half and +half: a triangle wave of the free motion.
double bounce(double p, double half, double* direction) {
  const double period = 4.0 * half;
  double q = std::fmod(p + half, period);
  if (q < 0.0) q += period;
  *direction = q > 2.0 * half ? -1.0 : 1.0;
  if (q > 2.0 * half) q = period - q;
  return q - half;
}

}  // namespace

double defaultRobotHeight(const FieldModel& field) {
  if (field.name.find("Adult") != std::string::npos || field.field_length > 12.0) {
    return field.field_length > 16.0 ? 0.8 : 1.4;  // MSL robots are ~0.8 m boxes on wheels
  }
  if (field.name.find("Kid") != std::string::npos) return 0.8;
  return 0.58;
}

double defaultBallDiameter(const FieldModel& field) {
  if (field.name.find("SPL") != std::string::npos) return 0.1;
  if (field.name.find("Kid") != std::string::npos) return 0.15;
  return field.field_length > 10.0 ? 0.22 : 0.1;
}

MovingObjects::MovingObjects(const Scenario& scenario, const FieldModel& field) {
  const SceneConfig& scene = scenario.scene;
  robot_height_ = scene.robot_height_m > 0.0 ? scene.robot_height_m : defaultRobotHeight(field);
  bounds_ = Eigen::Vector2d(field.outerHalfLength() - 0.2, field.outerHalfWidth() - 0.2);
  for (const RobotConfig& r : scenario.robots) {
    robots_.push_back({Eigen::Vector2d(r.x_m, r.y_m), Eigen::Vector2d(r.vx_mps, r.vy_mps),
                       r.theta_deg * M_PI / 180.0, teamColour(r.team)});
  }
  std::mt19937 rng(scenario.seed * 17u + 1u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < scene.random_robots; ++i) {
    const double heading = M_PI * u(rng), speed = 0.1 + 0.05 * u(rng);
    robots_.push_back({Eigen::Vector2d(field.halfLength() * u(rng), field.halfWidth() * u(rng)),
                       speed * Eigen::Vector2d(std::cos(heading), std::sin(heading)), heading,
                       teamColour(i % 2 ? "red" : "blue")});
  }
  const BallConfig& b = scenario.ball;
  ball_ = b.enabled;
  ball_diameter_ = b.diameter_m > 0.0 ? b.diameter_m : defaultBallDiameter(field);
  const double bx = 0.8 * field.halfLength() * u(rng), by = 0.8 * field.halfWidth() * u(rng);
  ball_mover_.start = Eigen::Vector2d(b.x_m.value_or(bx), b.y_m.value_or(by));
  ball_mover_.velocity = Eigen::Vector2d(b.vx_mps, b.vy_mps);
}

Eigen::Vector2d MovingObjects::position(const Mover& m, double t, Eigen::Vector2d* v) const {
  double dx = 1.0, dy = 1.0;
  const Eigen::Vector2d free = m.start + t * m.velocity;
  const Eigen::Vector2d p(bounce(free.x(), bounds_.x(), &dx), bounce(free.y(), bounds_.y(), &dy));
  *v = Eigen::Vector2d(dx * m.velocity.x(), dy * m.velocity.y());
  return p;
}

SceneObjects MovingObjects::at(double t, const Pose2& self) const {
  SceneObjects out;
  for (const Mover& m : robots_) {
    Eigen::Vector2d v;
    const Eigen::Vector2d p = position(m, t, &v);
    if ((p - self.translation()).norm() < 0.3) continue;
    const bool walking = v.norm() > 1e-3;
    const double theta = walking ? std::atan2(v.y(), v.x()) : m.theta;
    addRobot(Pose2(p.x(), p.y(), theta), robot_height_, m.jersey, 2.0 * M_PI * 0.9 * t, walking,
             out);
  }
  if (ball_) {
    Eigen::Vector2d v;
    const Eigen::Vector2d p = position(ball_mover_, t, &v);
    Eigen::Matrix3d spin = Eigen::Matrix3d::Identity();
    const double speed = ball_mover_.velocity.norm();
    if (speed > 1e-6) {
      // Rolling without slipping: turned by distance / radius about the axis across the motion.
      const Eigen::Vector3d axis(-v.y() / speed, v.x() / speed, 0.0);
      spin = Eigen::AngleAxisd(speed * t / (0.5 * ball_diameter_), axis).toRotationMatrix();
    }
    addBall(p, ball_diameter_, spin, out);
  }
  return out;
}

}  // namespace houghloc
