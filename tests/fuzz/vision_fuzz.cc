// The vision pipeline on arbitrary image bytes and sizes. The input's first bytes choose the
// image size (1..160 x 1..120 px), the format (BGR8 or YUYV), the camera pitch and whether the
// localizer's pose is given; the rest are the pixels (repeated to fill the image). Ground points
// must be finite and the pipeline must keep working over the two frames.
#include <cmath>
#include <exception>
#include <opencv2/core.hpp>

#include "field_models/standard_fields.h"
#include "tests/fuzz/fuzz_camera.h"
#include "tests/fuzz/fuzz_support.h"
#include "vision/camera_presets.h"
#include "vision/vision_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  fuzz::ByteReader in(data, size);
  const int width = 2 * (1 + in.byte() % 80);  // even, for YUYV
  const int height = 1 + in.byte() % 120;
  const bool yuyv = in.byte() & 1;
  const std::uint8_t flags = in.byte();
  Pose3 pose = cameraPreset("nao-top").robot_T_camera;
  pose.pitch += in.smallDouble(1.0);
  const std::string pixels = in.rest();

  const CameraIntrinsics intrinsics = fuzz::scaledCamera("nao-top", width, height);
  static const auto field = std::make_shared<const FieldModel>(makeStandardField("spl"));

  cv::Mat image(height, width, yuyv ? CV_8UC2 : CV_8UC3);
  const std::size_t bytes = image.total() * image.elemSize();
  for (std::size_t i = 0; i < bytes; ++i) {
    image.data[i] = pixels.empty() ? 0 : static_cast<std::uint8_t>(pixels[i % pixels.size()]);
  }
  VisionPipeline pipeline(intrinsics);
  if (flags & 1) pipeline.setFieldModel(field);
  for (int frame = 0; frame < 2; ++frame) {
    std::optional<Pose2> field_pose;
    if (flags & 2) field_pose = Pose2(-1.0, 0.5, 0.3 * frame);
    VisionResult result;
    try {
      result = pipeline.process(image, pose, 33000 * frame, field_pose);
    } catch (const std::invalid_argument& e) {
      if (pose.isFinite()) fuzz::fail(std::string("finite pose rejected: ") + e.what());
      return 0;
    }
    for (const auto& p : result.ground.points) {
      if (!p.p_robot.allFinite() || !std::isfinite(p.weight)) fuzz::fail("non-finite point");
    }
    for (const auto& region : result.ground.visible_regions) {
      for (const auto& v : region) {
        if (!v.allFinite()) fuzz::fail("non-finite visible region");
      }
    }
    if (!result.robot_T_camera_used.isFinite()) fuzz::fail("non-finite corrected pose");
  }
  return 0;
}
