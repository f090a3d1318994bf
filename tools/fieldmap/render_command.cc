// `render FILE -o field.png [--scale px_per_m]`: top view with scale bar, axes and title.
#include <iostream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "field_models/field_yaml.h"
#include "tools/drawing/field_top_view.h"
#include "tools/fieldmap/commands.h"

namespace houghloc::fieldmap {

void addRenderCommand(CLI::App& app, int& exit_code) {
  struct Options {
    std::string input;
    std::string output;
    double scale_px_per_m = 100.0;
    int margin_px = 40;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "render",
      "Draw a map's top view: carpet, lines at their real width, goals, field frame axes (x "
      "toward the opponent goal), scale bar and title. Maps with validation issues are drawn "
      "anyway, with the issues listed on stderr.\n"
      "Example: houghloc-fieldmap render field.yaml -o field.png --scale 50");
  command->add_option("FILE", options->input, "Map file (.yaml)")->required();
  command->add_option("-o,--output", options->output, "Image to write (.png, .jpg)")->required();
  command->add_option("--scale", options->scale_px_per_m, "Pixels per metre")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1000.0));
  command->add_option("--margin", options->margin_px, "Frame around the carpet, px")
      ->capture_default_str()
      ->check(CLI::Range(0, 500));
  command->callback([options, &exit_code] {
    const FieldModel field = readFieldYaml(options->input);
    for (const std::string& issue : describeIssues(field, options->input)) {
      std::cerr << "warning: " << issue << "\n";
    }
    FieldTopViewConfig config;
    config.pixels_per_metre = options->scale_px_per_m;
    config.margin_px = options->margin_px;
    FieldTopView view(field, config);
    view.drawAll();
    bool written = false;
    try {
      written = cv::imwrite(options->output, view.image());
    } catch (const cv::Exception& e) {
      throw std::runtime_error(options->output + ": cannot write image (" + e.err + ")");
    }
    if (!written) throw std::runtime_error(options->output + ": cannot write image");
    std::cout << "wrote " << options->output << " (" << view.image().cols << " x "
              << view.image().rows << " px, " << options->scale_px_per_m << " px/m)\n";
    exit_code = 0;
  });
}

}  // namespace houghloc::fieldmap
