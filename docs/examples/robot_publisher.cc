// Minimal robot-side publisher of houghloc's inputs (docs/lcm.md): what a team's own code sends
// for each camera frame. Built and run by the tests (tests/lcm_types), so it stays correct.
//   robot_publisher [LCM_URL]
#include <time.h>

#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <vector>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/odometry_t.hpp"

// One clock for every utime: CLOCK_MONOTONIC in microseconds, as the camera driver stamps images.
static int64_t nowMicros() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return int64_t{ts.tv_sec} * 1000000 + ts.tv_nsec / 1000;
}

int main(int argc, char** argv) {
  lcm::LCM lcm(argc > 1 ? argv[1] : "");  // "" = LCM_DEFAULT_URL
  if (!lcm.good()) return 1;
  const int64_t t = nowMicros();

  // Cumulative odometry from the walking engine (x, y in m, theta in rad since start).
  houghloc::odometry_t odometry{};
  odometry.utime = t;
  odometry.x = 1.25;
  odometry.y = -0.10;
  odometry.theta = 0.05;  // covariance left all zero: unknown
  lcm.publish("ODOMETRY", &odometry);

  // robot_T_camera from the kinematic chain (head joints) and the IMU, at the image's time.
  houghloc::camera_pose_t camera{};
  camera.utime = t;
  camera.camera_id = "top";
  camera.x = 0.05;
  camera.z = 0.52;
  camera.pitch = 0.02 + 0.35;  // body pitch from the IMU + head pitch, rad (positive looks down)
  lcm.publish("CAMERA_POSE", &camera);

  // The camera frame as the driver delivers it: YUYV, 2 bytes per pixel.
  houghloc::image_t image{};
  image.utime = t;
  image.camera_id = "top";
  image.width = 640;
  image.height = 480;
  image.pixel_format = houghloc::image_t::PIXEL_FORMAT_YUYV;
  image.row_stride = 2 * image.width;
  image.data.assign(static_cast<size_t>(image.row_stride) * image.height, 128);
  image.size = static_cast<int32_t>(image.data.size());
  lcm.publish("IMAGE", &image);

  // Re-entry after a penalty: the robot stands at one of two touch-line spots of its own half.
  houghloc::localization_hint_t hint{};
  hint.utime = t;
  hint.kind = houghloc::localization_hint_t::ADD;
  for (double y : {-3.0, 3.0}) {
    houghloc::pose_hypothesis_t pose{};
    pose.x = -1.5;
    pose.y = y;
    pose.theta = y < 0 ? 1.5708 : -1.5708;                // facing the field
    pose.covariance[0] = pose.covariance[4] = 0.2 * 0.2;  // m^2
    pose.covariance[8] = 0.1 * 0.1;                       // rad^2
    pose.weight = 0.5;
    hint.poses.push_back(pose);
  }
  hint.num_poses = static_cast<int32_t>(hint.poses.size());
  lcm.publish("HINT", &hint);
  return 0;
}
