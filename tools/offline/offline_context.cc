#include "tools/offline/offline_context.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "field_models/field_validation.h"
#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"
#include "tools/offline/hint_conversion.h"
#include "tools/offline/offline_config.h"

namespace houghloc {

namespace fs = std::filesystem;

void prepareOutputFolder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create output folder: " + ec.message());
  const fs::path probe = fs::path(dir) / ".houghloc-write-test";
  {
    std::ofstream out(probe);
    if (!out) throw std::runtime_error(dir + ": output folder is not writable");
  }
  fs::remove(probe, ec);
}

OfflineContext loadOfflineContext(const OfflineOptions& options) {
  OfflineContext context;
  context.options = options;
  if (!fs::is_directory(options.folder)) {
    throw std::runtime_error(options.folder + ": not a folder");
  }
  context.recording = readRecording(options.folder);
  if (!options.field_file.empty()) {
    context.field = readFieldYaml(options.field_file);
    // A map that fails validation (a zero-length segment, say) localizes wrongly without a sign.
    const std::vector<FieldIssue> issues = validateField(*context.field);
    if (!issues.empty()) {
      throw std::runtime_error(options.field_file + ": " + issues.front().toString() + " (" +
                               std::to_string(issues.size()) +
                               " issue(s), houghloc-fieldmap validate lists them)");
    }
  } else if (!options.standard.empty()) {
    try {
      context.field = makeStandardField(options.standard);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("--standard: ") + e.what());
    }
  } else if (context.recording.field) {
    context.field = context.recording.field;
  }
  const OfflineConfig config = loadOfflineConfig(options.config_file);
  context.vision_config = config.vision;
  context.localizer_config = config.localizer;
  context.hints = convertHints(context.recording);
  const int frames = static_cast<int>(context.recording.frames.size());
  context.first_frame = std::min(options.start, frames);
  context.end_frame = options.end < 0 ? frames : std::min(options.end, frames);
  if (context.end_frame < context.first_frame) {
    throw std::runtime_error("--end " + std::to_string(options.end) + " is before --start " +
                             std::to_string(options.start));
  }
  context.out_dir =
      options.out_dir.empty() ? (fs::path(options.folder) / "houghloc").string() : options.out_dir;
  prepareOutputFolder(context.out_dir);
  return context;
}

}  // namespace houghloc
