#include "tools/offline/offline_context.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "tools/offline/hint_conversion.h"
#include "tools/offline/offline_config.h"
#include "tools/offline/run_field.h"

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
  if (!options.field_file.empty() || !options.standard.empty()) {
    context.field = loadRunField(options.field_file, options.standard);
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
