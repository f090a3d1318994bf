// frames.csv, groundtruth.csv and hints.csv (DESIGN §5.1) read as a recorded folder. The input is
// up to three file texts separated by lines "%%": frames.csv [%% groundtruth.csv [%% hints.csv]];
// camera.yaml is a valid preset. Every record read must be finite.
#include <exception>
#include <filesystem>

#include "tests/fuzz/fuzz_support.h"
#include "tools/recording/recording.h"
#include "vision/camera_presets.h"

namespace {

std::vector<std::string> splitFiles(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (parts.size() < 2) {
    const std::size_t sep = text.find("%%\n", start);
    if (sep == std::string::npos) break;
    parts.push_back(text.substr(start, sep - start));
    start = sep + 3;
  }
  parts.push_back(text.substr(start));
  return parts;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  namespace fs = std::filesystem;
  const std::string folder = fuzz::scratchFolder() + "/recording";
  static const bool prepared = [&] {
    fs::create_directories(folder);
    saveCameraYaml(folder + "/camera.yaml", cameraPreset("nao-top").intrinsics);
    return true;
  }();
  (void)prepared;
  const auto parts = splitFiles(std::string(reinterpret_cast<const char*>(data), size));
  const char* names[] = {"frames.csv", "groundtruth.csv", "hints.csv"};
  for (int i = 0; i < 3; ++i) {
    const std::string path = folder + "/" + names[i];
    if (i < static_cast<int>(parts.size())) {
      fuzz::writeScratchFile(std::string("recording/") + names[i], parts[i]);
    } else {
      fs::remove(path);
    }
  }
  Recording recording;
  try {
    recording = readRecording(folder);
  } catch (const std::exception& e) {
    fuzz::requireNamed(e.what(), folder);
    return 0;
  }
  for (const auto& f : recording.frames) {
    if ((f.odometry && !f.odometry->isFinite()) || !f.robot_T_camera.isFinite())
      fuzz::fail("non-finite frame");
  }
  for (const auto& g : recording.ground_truth) {
    if (!g.field_T_robot.isFinite()) fuzz::fail("non-finite ground truth");
  }
  for (const auto& h : recording.hints) {
    if ((h.pose && !h.pose->isFinite()) || !std::isfinite(h.sigma_x + h.sigma_y + h.sigma_theta)) {
      fuzz::fail("non-finite hint");
    }
  }
  return 0;
}
