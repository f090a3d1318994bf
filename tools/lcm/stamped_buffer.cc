#include "tools/lcm/stamped_buffer.h"

#include <cmath>

namespace houghloc {
namespace {

double lerpAngle(double a, double b, double s) { return a + s * angleDifference(b, a); }
double lerp(double a, double b, double s) { return a + s * (b - a); }

}  // namespace

Pose2 interpolatePose(const Pose2& a, const Pose2& b, double s) {
  return Pose2(lerp(a.x, b.x, s), lerp(a.y, b.y, s), lerpAngle(a.theta, b.theta, s));
}

Pose3 interpolatePose(const Pose3& a, const Pose3& b, double s) {
  // Roll/pitch/yaw componentwise: head and camera motions between two samples 10-30 ms apart
  // are small, where componentwise interpolation and a rotation slerp nearly agree.
  Pose3 out;
  out.x = lerp(a.x, b.x, s);
  out.y = lerp(a.y, b.y, s);
  out.z = lerp(a.z, b.z, s);
  out.roll = lerpAngle(a.roll, b.roll, s);
  out.pitch = lerpAngle(a.pitch, b.pitch, s);
  out.yaw = lerpAngle(a.yaw, b.yaw, s);
  return out;
}

}  // namespace houghloc
