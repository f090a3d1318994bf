#include "vision/camera_presets.h"

#include <stdexcept>

#include "field_models/angles.h"

namespace houghloc {
namespace {

CameraIntrinsics makeIntrinsics(int width, int height, double f, std::vector<double> distortion,
                                DistortionModel model) {
  CameraIntrinsics in;
  in.image_width = width;
  in.image_height = height;
  in.camera_matrix =
      cv::Matx33d(f, 0.0, 0.5 * (width - 1), 0.0, f, 0.5 * (height - 1), 0.0, 0.0, 1.0);
  in.distortion = std::move(distortion);
  in.model = model;
  return in;
}

Pose3 makePose(double x, double z, double pitch) {
  Pose3 pose;
  pose.x = x;
  pose.z = z;
  pose.pitch = pitch;
  return pose;
}

// NAO v6 camera (OV5640, used at 640x480): 56.3 deg horizontal / 43.7 deg vertical field of
// view for the ideal lens, so f = 320 / tan(28.15 deg) = 598 px; principal point at the image
// centre; mild barrel distortion typical of its calibrations (k1 = -0.065, k2 = 0.045, tiny
// tangential terms), which widens the view to 57.0 x 44.1 deg.
CameraIntrinsics naoIntrinsics() {
  return makeIntrinsics(640, 480, 598.0, {-0.065, 0.045, 0.0004, -0.0003, 0.0},
                        DistortionModel::kPinhole);
}

}  // namespace

std::vector<std::string> cameraPresetNames() {
  return {"nao-top", "nao-bottom", "kid-wide", "adult", "wide-pinhole"};
}

CameraPreset cameraPreset(const std::string& name) {
  CameraPreset preset;
  preset.name = name;
  if (name == "nao-top") {
    // Standing NAO in walking posture: top camera 0.50 m high, 0.06 m ahead of the robot centre,
    // pitched 20.6 deg down (1.2 deg mount + 19.4 deg head pitch). The horizon lies near row 10
    // (13 at the sides), so the view covers the ground from 0.60 m out to the far field and a
    // strip of background above it.
    preset.intrinsics = naoIntrinsics();
    preset.robot_T_camera = makePose(0.06, 0.50, 20.6 * kDeg);
  } else if (name == "nao-bottom") {
    // Same sensor, mounted 0.45 m high, 0.03 m ahead, 42.4 deg further down than the top camera
    // (39.7 deg mount tilt plus a slightly lower chin): 63 deg pitch. Its image spans the ground
    // from 0.07 m (the toes, at x ~ 0.10 m, fill the bottom ~40 rows) to 0.55 m, about where the
    // top camera's view begins.
    preset.intrinsics = naoIntrinsics();
    preset.robot_T_camera = makePose(0.03, 0.45, 63.0 * kDeg);
  } else if (name == "kid-wide") {
    // Humanoid KidSize with a wide-angle lens on a 1280x720 sensor: OpenCV fisheye model
    // (theta_d = theta (1 - 0.03 theta^2 + 0.01 theta^4 - 0.004 theta^6 + 0.0005 theta^8)),
    // f = 627 px, i.e. 120 deg horizontal and 66 deg vertical field of view, strongly curved
    // lines near the border. 0.90 m high, 0.05 m ahead, pitched 28.6 deg (0.5 rad) down: ground
    // from 0.53 m out; the horizon is a visible curve from row 42 in the middle to row 167 at
    // the sides.
    preset.intrinsics =
        makeIntrinsics(1280, 720, 627.0, {-0.03, 0.01, -0.004, 0.0005}, DistortionModel::kFisheye);
    preset.robot_T_camera = makePose(0.05, 0.90, 0.5);
  } else if (name == "adult") {
    // Humanoid AdultSize head camera: 1280x720, f = 900 px (70.8 x 43.6 deg for the ideal lens),
    // moderate barrel distortion (k1 = -0.12, k2 = 0.05, k3 = -0.008, small tangential terms)
    // that widens it to 73.8 x 44.3 deg. 1.40 m high, 0.05 m ahead, pitched 20 deg down: ground
    // from 1.60 m out, horizon from row 28 in the middle to 44 at the sides.
    preset.intrinsics = makeIntrinsics(1280, 720, 900.0, {-0.12, 0.05, 0.0008, -0.0005, -0.008},
                                       DistortionModel::kPinhole);
    preset.robot_T_camera = makePose(0.05, 1.40, 20.0 * kDeg);
  } else if (name == "wide-pinhole") {
    // A wide 16:9 pinhole camera without distortion (a webcam-class module on a small robot):
    // 1024x576, f = 512 px, i.e. 90 deg horizontal and 59 deg vertical field of view. 0.50 m
    // high, 0.05 m ahead, pitched 25 deg down: ground from 0.45 m out, horizon near row 49.
    preset.intrinsics =
        makeIntrinsics(1024, 576, 512.0, {0.0, 0.0, 0.0, 0.0, 0.0}, DistortionModel::kPinhole);
    preset.robot_T_camera = makePose(0.05, 0.50, 25.0 * kDeg);
  } else {
    std::string known;
    for (const std::string& n : cameraPresetNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown camera preset '" + name + "' (known: " + known + ")");
  }
  return preset;
}

}  // namespace houghloc
