// houghloc-node: the onboard LCM process (DESIGN §1, §7).
#include <CLI/CLI.hpp>
#include <iostream>
#include <lcm/lcm-cpp.hpp>

#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"
#include "tools/lcm/stop_signal.h"
#include "tools/node/node_runner.h"
#include "tools/offline/offline_config.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{
      "houghloc-node: subscribes to <PREFIX>IMAGE, ODOMETRY, CAMERA_POSE, HINT and publishes "
      "<PREFIX>HYPOTHESES (one per processed image), STATUS (1 Hz and on state change), "
      "LINE_POINTS (docs/lcm.md)"};
  std::string config_path, field_path, standard, url, prefix, line_points = "on";
  std::vector<std::string> camera_yamls;
  app.add_option("--config", config_path, "config file (vision:, global:, tracker:, ...)");
  auto* field_opt = app.add_option("--field", field_path, "field map YAML");
  app.add_option("--standard", standard, "standard field (spl, spl2019, kid, adult, msl)")
      ->excludes(field_opt);
  app.add_option("--camera-yaml", camera_yamls, "[ID=]camera.yaml, one per camera (no ID: '')")
      ->required();
  app.add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL)");
  app.add_option("--channel-prefix", prefix, "channel prefix, e.g. NAO3_");
  app.add_option("--publish-line-points", line_points, "publish LINE_POINTS")
      ->check(CLI::IsMember({"on", "off"}));
  CLI11_PARSE(app, argc, argv);
  try {
    if (field_path.empty() == standard.empty())
      throw std::runtime_error("give --field FILE or --standard NAME");
    const FieldModel field =
        field_path.empty() ? makeStandardField(standard) : readFieldYaml(field_path);
    std::map<std::string, CameraIntrinsics> cameras;
    for (const std::string& arg : camera_yamls) {
      const auto eq = arg.find('=');
      const std::string id = eq == std::string::npos ? "" : arg.substr(0, eq);
      cameras[id] = loadCameraYaml(eq == std::string::npos ? arg : arg.substr(eq + 1));
    }
    const OfflineConfig loaded = loadOfflineConfig(config_path);
    PipelineConfig config;
    config.vision = loaded.vision;
    config.localizer = loaded.localizer;
    lcm::LCM lcm(url);
    if (!lcm.good()) throw std::runtime_error("cannot open LCM URL '" + url + "'");
    NodeCore core(std::make_shared<const FieldModel>(field), config, cameras);
    NodeRunner runner(lcm, core, prefix, line_points == "on");
    const std::atomic<bool>& stop = installStopSignals();
    std::cerr << "houghloc-node: running, " << cameras.size() << " camera(s)\n";
    runner.run(stop);
    const localizer_status_t status = core.status();
    std::cerr << "houghloc-node: stopped after " << status.frames_processed << " images, dropped "
              << core.drops().total() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "houghloc-node: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
