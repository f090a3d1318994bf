// houghloc-play: publishes a recorded folder on houghloc-node's input channels (DESIGN §7).
#include <CLI/CLI.hpp>
#include <iostream>
#include <lcm/lcm-cpp.hpp>

#include "houghloc/image_t.hpp"
#include "tools/lcm/stop_signal.h"
#include "tools/play/player.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{
      "houghloc-play: publishes a recorded folder (images, odometry, camera poses, hints, ground "
      "truth on <PREFIX>GROUND_TRUTH) on houghloc-node's input channels, re-stamped to "
      "CLOCK_MONOTONIC of now plus the recorded offset"};
  std::string folder, url, format = "yuyv";
  PlayOptions options;
  app.add_option("FOLDER", folder, "recorded folder (DESIGN §5.1)")->required();
  app.add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--channel-prefix", options.channel_prefix, "channel prefix, e.g. NAO3_");
  auto* speed = app.add_option("--speed", options.speed, "playback speed factor (1 = real time)")
                    ->check(CLI::PositiveNumber);
  app.add_flag("--fast", options.fast,
               "publish the next image when the previous one's HYPOTHESES arrived (1 s timeout)")
      ->excludes(speed);
  app.add_flag("--loop", options.loop, "play the folder again and again (until SIGINT)");
  app.add_option("--format", format, "image pixel format")
      ->check(CLI::IsMember({"yuyv", "bgr8", "mjpeg"}));
  CLI11_PARSE(app, argc, argv);
  options.pixel_format = format == "bgr8"    ? image_t::PIXEL_FORMAT_BGR8
                         : format == "mjpeg" ? image_t::PIXEL_FORMAT_MJPEG
                                             : image_t::PIXEL_FORMAT_YUYV;
  const std::atomic<bool>& stop = installStopSignals();
  try {
    const Recording recording = readRecording(folder);
    lcm::LCM lcm(url);
    if (!lcm.good()) {
      std::cerr << "houghloc-play: cannot open LCM URL '" << url << "'\n";
      return 1;
    }
    Player player(lcm, recording, options);
    int pass = 0;
    do {
      const int images = player.playOnce(stop);
      std::cerr << "houghloc-play: pass " << ++pass << ": " << images << " images published\n";
    } while (options.loop && !stop);
    if (options.fast)
      std::cerr << "houghloc-play: " << player.hypothesesReceived() << " HYPOTHESES received\n";
  } catch (const std::exception& e) {
    std::cerr << "houghloc-play: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
