#include "tools/fieldmap/editor/edit_command.h"

#include <QApplication>
#include <iostream>
#include <memory>

#include "tools/fieldmap/editor/editor_window.h"
#include "tools/fieldmap/editor/screenshot.h"
#include "tools/fieldmap/editor_model/document_io.h"

namespace houghloc::fieldmap {

void addEditCommand(CLI::App& app, int& exit_code) {
  struct Options {
    std::string file, standard = "spl", screenshot, check;
    int frame = 0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "edit",
      "Open the field-map editor (Qt) on FILE (YAML map or field_dimensions.json) or on a "
      "standard field; see docs/editor.md");
  cmd->add_option("file", options->file, "map to open (.yaml, or .json for field_dimensions.json)");
  cmd->add_option("--standard", options->standard,
                  "standard field when no FILE is given: spl, spl2019, kid, adult, msl")
      ->capture_default_str();
  cmd->add_option("--screenshot", options->screenshot,
                  "render the window to this PNG and exit (for docs and tests)");
  cmd->add_option("--check", options->check,
                  "recorded folder to check the map against (its line points at the frame's pose)");
  cmd->add_option("--frame", options->frame, "frame of --check to show")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->callback([options, &exit_code] {
    // Load before Qt starts, so a bad file fails with the file and key like the other commands.
    EditorDocument doc =
        options->file.empty() ? standardDocument(options->standard) : loadDocument(options->file);
    static int qt_argc = 1;
    static char qt_name[] = "houghloc-fieldmap";
    static char* qt_argv[] = {qt_name, nullptr};
    QApplication qt(qt_argc, qt_argv);
    EditorWindow window(std::move(doc), QString::fromStdString(options->file));
    if (!options->check.empty())
      window.openCheck(QString::fromStdString(options->check), options->frame);
    window.show();
    if (options->screenshot.empty()) {
      exit_code = qt.exec();
      return;
    }
    exit_code = saveScreenshot(window, window.view(), options->screenshot);
  });
}

}  // namespace houghloc::fieldmap
