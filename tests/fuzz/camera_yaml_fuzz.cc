// camera.yaml (DESIGN §5.1): load arbitrary text; a camera that loads must project finitely.
#include <cmath>
#include <exception>

#include "tests/fuzz/fuzz_support.h"
#include "vision/camera_model.h"
#include "vision/camera_presets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  const std::string path =
      fuzz::writeScratchFile("camera.yaml", std::string(reinterpret_cast<const char*>(data), size));
  CameraIntrinsics intrinsics;
  try {
    intrinsics = loadCameraYaml(path);
  } catch (const std::exception& e) {
    fuzz::requireNamed(e.what(), "camera.yaml");
    return 0;
  }
  const CameraModel camera(intrinsics, cameraPreset("nao-top").robot_T_camera);
  for (const double fu : {0.0, 0.5, 1.0}) {
    for (const double fv : {0.5, 1.0}) {
      const auto ground = camera.pixelToGround(fu * (intrinsics.image_width - 1),
                                               fv * (intrinsics.image_height - 1));
      if (ground && !ground->allFinite()) fuzz::fail("pixelToGround gave a non-finite point");
    }
  }
  return 0;
}
