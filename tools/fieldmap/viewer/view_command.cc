#include "tools/fieldmap/viewer/view_command.h"

#include <QApplication>
#include <QSlider>
#include <QTimer>
#include <iostream>
#include <memory>

#include "tools/fieldmap/editor/screenshot.h"
#include "tools/fieldmap/editor_model/document_io.h"
#include "tools/fieldmap/viewer/viewer_window.h"
#include "tools/fieldmap/viewer_model/lcm_feed.h"

namespace houghloc::fieldmap {

void addViewCommand(CLI::App& app, int& exit_code) {
  struct Options {
    std::string field, standard = "spl", url, log, screenshot;
    std::vector<std::string> prefixes;
    double at_s = -1.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Live viewer (Qt): the map and, per robot, the hypotheses, line points, status and ground "
      "truth from LCM, or a replay of an lcm-logger file; see docs/editor.md");
  auto* field = cmd->add_option("--field", options->field,
                                "map to draw (.yaml, or .json for field_dimensions.json)");
  cmd->add_option("--standard", options->standard,
                  "standard field when no --field is given: spl, spl2019, kid, adult, msl")
      ->capture_default_str()
      ->excludes(field);
  cmd->add_option("--lcm-url", options->url, "LCM URL to listen on (default: LCM's default)");
  cmd->add_option("--channel-prefix", options->prefixes,
                  "channel prefix of one robot (repeat for several); default: none");
  auto* log = cmd->add_option("--log", options->log,
                              "replay this lcm-logger file with a time slider instead of listening")
                  ->check(CLI::ExistingFile);
  cmd->add_option("--at", options->at_s, "with --log: start at this time (s from the log start)")
      ->needs(log);
  cmd->add_option("--screenshot", options->screenshot,
                  "render the window to this PNG and exit (for docs and tests)");
  cmd->callback([options, &exit_code] {
    // Load before Qt starts, so a bad file fails with the file and key like the other commands.
    const EditorDocument doc =
        options->field.empty() ? standardDocument(options->standard) : loadDocument(options->field);
    std::shared_ptr<const LogIndex> log;
    if (!options->log.empty()) {
      log = std::make_shared<LogIndex>(options->log);
      std::cout << options->log << ": " << log->messages().size() << " events, "
                << (log->endUs() - log->startUs()) * 1e-6 << " s\n";
    }
    static int qt_argc = 1;
    static char qt_name[] = "houghloc-fieldmap";
    static char* qt_argv[] = {qt_name, nullptr};
    QApplication qt(qt_argc, qt_argv);
    const QString source = QString::fromStdString(
        log ? options->log : (options->url.empty() ? "the default LCM URL" : options->url));
    ViewerWindow window(doc.field(), options->prefixes, source);
    std::unique_ptr<ViewerState> live;
    std::unique_ptr<LcmFeed> feed;
    QTimer poll;
    if (log) {
      window.setLog(log);
      if (options->at_s >= 0.0)
        window.seek(log->startUs() + static_cast<std::int64_t>(options->at_s * 1e6));
    } else {
      live = std::make_unique<ViewerState>(window.state());
      feed = std::make_unique<LcmFeed>(options->url, live.get());
      // LCM runs on the GUI thread: poll without blocking every 20 ms.
      QObject::connect(&poll, &QTimer::timeout, [&] {
        if (feed->poll() > 0) window.showState(*live);
      });
      poll.start(20);
    }
    window.show();
    if (options->screenshot.empty()) {
      exit_code = qt.exec();
      return;
    }
    QApplication::processEvents();
    if (feed && feed->poll() > 0) window.showState(*live);
    exit_code = saveScreenshot(window, window.view(), options->screenshot);
  });
}

}  // namespace houghloc::fieldmap
