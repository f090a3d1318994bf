#include "tools/render/camera_rig.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "field_models/angles.h"

namespace houghloc {
namespace {

constexpr double kFallingShare = 0.1;  ///< of a fall's duration spent falling over
constexpr double kGetUpShare = 0.2;    ///< of a fall's duration spent getting up
constexpr double kLyingCameraHeight_m = 0.1;

Eigen::Matrix3d rotY(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).matrix(); }
Eigen::Matrix3d rotX(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).matrix(); }
Eigen::Matrix3d rotZ(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).matrix(); }

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

/// How far the body has tipped backwards (0 upright, 1 lying) at a fall phase.
double tipOver(double phase) {
  if (phase < kFallingShare) return smoothstep(phase / kFallingShare);
  if (phase > 1.0 - kGetUpShare) return 1.0 - smoothstep((phase - 1.0 + kGetUpShare) / kGetUpShare);
  return 1.0;
}

}  // namespace

Pose3 poseFromRotation(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  Pose3 p;
  p.x = t.x();
  p.y = t.y();
  p.z = t.z();
  p.pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  p.roll = std::atan2(r(2, 1), r(2, 2));
  p.yaw = std::atan2(r(1, 0), r(0, 0));
  return p;
}

Pose3 renderedCameraPose(const Pose3& mount, const RobotState& state, double t,
                         const Scenario& scenario) {
  // Head joints turn the camera about the neck pivot below it.
  const Eigen::Vector3d pivot(0.0, mount.y, mount.z - scenario.head.neck_height_below_camera_m);
  const Eigen::Matrix3d head = rotZ(state.pan_rad) * rotY(state.tilt_rad);
  Eigen::Matrix3d r = head * mount.rotation();
  Eigen::Vector3d p = pivot + head * (mount.translation() - pivot);
  // Gait: the torso rolls once per two steps and pitches and bobs once per step.
  const TrajectoryConfig& tc = scenario.trajectory;
  if (state.walk_speed_mps > 0.01 && tc.gait_sway_deg > 0.0) {
    const double phase = M_PI * tc.gait_frequency_hz * t;
    const double a = tc.gait_sway_deg * kDeg;
    const Eigen::Matrix3d body = rotX(a * std::sin(phase)) * rotY(0.5 * a * std::sin(2.0 * phase));
    r = body * r;
    p = body * p + Eigen::Vector3d(0.0, 0.0, 0.004 * std::sin(2.0 * phase));
  }
  if (state.fall_phase >= 0.0) {
    // Backwards about the heels; the head ends up just above the floor looking at the ceiling.
    const double tip = tipOver(state.fall_phase);
    const Eigen::Vector3d heel(-0.05, 0.0, 0.0);
    const Eigen::Matrix3d body = rotY(-tip * (0.5 * M_PI - 0.1));
    r = body * r;
    p = heel + body * (p - heel);
    p.z() = std::max(p.z(), kLyingCameraHeight_m);
  }
  return poseFromRotation(r, p);
}

Pose3 recordedCameraPose(const Pose3& rendered, const CameraPoseError& error, std::mt19937& rng) {
  Pose3 p = rendered;
  p.x += error.bias.x;
  p.y += error.bias.y;
  p.z += error.bias.z;
  p.roll += error.bias.roll;
  p.pitch += error.bias.pitch;
  p.yaw += error.bias.yaw;
  if (error.noise_deg > 0.0) {
    std::normal_distribution<double> n(0.0, error.noise_deg * kDeg);
    p.roll += n(rng);
    p.pitch += n(rng);
    p.yaw += n(rng);
  }
  return p;
}

}  // namespace houghloc
