// houghloc-render: writes a synthetic recorded folder with ground truth (DESIGN §5.4).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"
#include "tools/render/recording_renderer.h"
#include "tools/render/scenario.h"
#include "vision/camera_presets.h"

namespace {

using namespace houghloc;
namespace fs = std::filesystem;

bool isStandardField(const std::string& name) {
  for (const std::string& n : standardFieldNames()) {
    if (n == name) return true;
  }
  return false;
}

bool isPreset(const std::string& name) {
  for (const std::string& n : cameraPresetNames()) {
    if (n == name) return true;
  }
  return false;
}

/// A path from the scenario file is relative to the scenario's folder.
std::string besideScenario(const std::string& path, const std::string& scenario_file) {
  if (scenario_file.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(scenario_file).parent_path() / path).string();
}

FieldModel resolveField(const std::string& field_file, const std::string& standard,
                        const Scenario& s, const std::string& scenario_file) {
  if (!field_file.empty()) return readFieldYaml(field_file);
  if (!standard.empty()) return makeStandardField(standard);
  if (s.field.empty()) throw std::runtime_error("no field: give --field FILE or --standard NAME");
  if (isStandardField(s.field)) return makeStandardField(s.field);
  return readFieldYaml(besideScenario(s.field, scenario_file));
}

void resolveCamera(const std::string& camera_arg, const Scenario& s,
                   const std::string& scenario_file, RenderJob& job) {
  const std::string name = !camera_arg.empty() ? camera_arg : s.camera;
  if (name.empty()) throw std::runtime_error("no camera: give --camera PRESET|camera.yaml");
  if (name == kNaoCameraRig) {
    // A NAO reads its top and bottom camera in turn; the camera column tells them apart.
    useNaoCameraRig(&job);
    if (s.camera_mount)
      throw std::runtime_error("camera_mount cannot be combined with --camera nao");
    return;
  }
  if (isPreset(name)) {
    const CameraPreset preset = cameraPreset(name);
    job.intrinsics = preset.intrinsics;
    job.mount = preset.robot_T_camera;
  } else {
    const std::string path = camera_arg.empty() ? besideScenario(name, scenario_file) : name;
    if (!fs::exists(path)) {
      std::string known;
      for (const std::string& n : cameraPresetNames()) known += " " + n;
      throw std::runtime_error("--camera: '" + name + "' is neither a preset nor a file (presets:" +
                               known + ", " + kNaoCameraRig + ")");
    }
    job.intrinsics = loadCameraYaml(path);
    job.mount = cameraPreset("nao-top").robot_T_camera;  // unless the scenario says otherwise
    if (!s.camera_mount) {
      std::cerr << "houghloc-render: " << path
                << " has no mount; using nao-top's (set camera_mount in a scenario)\n";
    }
  }
  if (s.camera_mount) job.mount = *s.camera_mount;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "houghloc-render: renders a synthetic recorded folder with ground truth "
      "(DESIGN 5.4; scenario format in docs/render.md)"};
  std::string field_file, standard, camera, trajectory, scenario_file, out_dir;
  int frames = -1;
  long long seed = -1;
  bool quiet = false;
  auto* field_opt = app.add_option("--field", field_file, "field map YAML");
  auto* standard_opt =
      app.add_option("--standard", standard, "standard field: spl, spl2019, kid, adult, msl");
  field_opt->excludes(standard_opt);
  app.add_option("--camera", camera,
                 "preset (nao-top, nao-bottom, kid-wide, adult, wide-pinhole), nao (top and bottom taking turns, "
                 "as on the robot) or camera.yaml");
  auto* traj_opt = app.add_option("--trajectory", trajectory,
                                  "built-in: walk, spin, kidnap, fall, random-poses");
  auto* scen_opt =
      app.add_option("--scenario", scenario_file, "scenario YAML")->check(CLI::ExistingFile);
  traj_opt->excludes(scen_opt);
  app.add_option("--frames", frames, "number of frames (default: scenario, else 300)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--seed", seed, "random seed (default: scenario, else 1)")
      ->check(CLI::Range(0LL, 4294967295LL));
  app.add_option("-o,--out", out_dir, "output folder")->required();
  app.add_flag("-q,--quiet", quiet, "no progress output");
  CLI11_PARSE(app, argc, argv);

  try {
    Scenario s = scenario_file.empty() ? Scenario{} : loadScenario(scenario_file);
    if (!trajectory.empty()) s.trajectory.name = trajectory;
    if (frames >= 0) s.frames = frames;
    if (seed >= 0) s.seed = static_cast<std::uint32_t>(seed);
    validateScenario(s);
    RenderJob job;
    job.field = resolveField(field_file, standard, s, scenario_file);
    resolveCamera(camera, s, scenario_file, job);
    job.scenario = s;
    job.out_dir = out_dir;
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // A terminal gets one line redrawn in place; a log file gets a line every 10 %.
    const bool terminal = isatty(fileno(stderr)) != 0;
    renderRecording(job, [&](int done, int total) {
      if (quiet) return;
      const int log_every = std::max(1, total / 10);
      if (terminal && (done % 10 == 0 || done == total)) {
        std::fprintf(stderr, "\rhoughloc-render: frame %d/%d (%.1f frames/s)", done, total,
                     done / std::max(1e-9, seconds()));
      } else if (!terminal && (done % log_every == 0 || done == total)) {
        std::fprintf(stderr, "houghloc-render: frame %d/%d (%.1f frames/s)\n", done, total,
                     done / std::max(1e-9, seconds()));
      }
    });
    if (!quiet) {
      std::fprintf(stderr, "%shoughloc-render: wrote %d frames to %s in %.1f s (%.1f frames/s)\n",
                   terminal ? "\n" : "", s.frames, out_dir.c_str(), seconds(),
                   s.frames / std::max(1e-9, seconds()));
    }
  } catch (const std::exception& e) {
    std::cerr << "houghloc-render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
