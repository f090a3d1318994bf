// houghloc-global-dump: every hypothesis GlobalHoughLocalizer::locate() returns for a fixed set of
// synthetic frames (5 fields x 4 camera views x N frames), all fields in full double precision
// (%.17g), one line per hypothesis. Two builds that must give the same outputs are compared
// with `cmp` on their dumps.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "field_models/standard_fields.h"
#include "localization/global_hough_localizer.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc {
namespace {

const std::vector<std::string> kFields = {"spl", "spl2019", "kid", "adult", "msl"};
const std::vector<std::string> kViews = {"nao-top", "nao-bottom", "kid-wide", "adult"};

void dumpHypothesis(std::FILE* out, const PoseHypothesis& h) {
  const Pose2& p = h.field_T_robot;
  std::fprintf(out, "  %d %d %.17g %.17g %.17g w %.17g", static_cast<int>(h.kind),
               static_cast<int>(h.source), p.x, p.y, p.theta, h.weight);
  std::fprintf(out, " u %.17g %.17g s %.17g %.17g %.17g %.17g %.17g", h.line_direction.x(),
               h.line_direction.y(), h.support, h.score, h.penalty, h.inlier_share, h.rms_m);
  std::fprintf(out, " c");
  for (int k = 0; k < 9; ++k) std::fprintf(out, " %.17g", h.covariance(k / 3, k % 3));
  std::fprintf(out, "\n");
}

int run(const std::string& path, int frames, unsigned seed) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) {
    std::fprintf(stderr, "houghloc-global-dump: cannot write %s\n", path.c_str());
    return 1;
  }
  long hypotheses = 0;
  for (const std::string& name : kFields) {
    const FieldModel field = makeStandardField(name);
    const GlobalHoughLocalizer ghl(field);
    for (const std::string& view : kViews) {
      std::mt19937_64 rng(seed);
      for (int k = 0; k < frames; ++k) {
        SyntheticConfig config;
        config.view = viewModel(view);
        config.seed = seed + static_cast<unsigned>(k);
        const Pose2 truth = randomPose(field, 0.3, rng);
        const SyntheticFrame f = generateFrame(field, truth, config);
        const std::vector<PoseHypothesis> hs = ghl.locate(f.ground);
        std::fprintf(out, "%s %s %d points %zu hypotheses %zu\n", name.c_str(), view.c_str(), k,
                     f.ground.size(), hs.size());
        for (const PoseHypothesis& h : hs) dumpHypothesis(out, h);
        hypotheses += static_cast<long>(hs.size());
      }
      std::fprintf(stderr, "%s %s: %d frames\n", name.c_str(), view.c_str(), frames);
    }
  }
  std::fclose(out);
  std::fprintf(stderr, "wrote %ld hypotheses to %s\n", hypotheses, path.c_str());
  return 0;
}

}  // namespace
}  // namespace houghloc

int main(int argc, char** argv) {
  CLI::App app{
      "Writes every hypothesis of GlobalHoughLocalizer::locate() for synthetic frames of 5 fields "
      "x 4 camera views, in full double precision, to compare two builds with cmp."};
  std::string path;
  int frames = 30;
  unsigned seed = 2100;
  app.add_option("output", path, "dump file to write")->required();
  app.add_option("--frames", frames, "frames per field and view")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the random poses and the synthetic frames");
  CLI11_PARSE(app, argc, argv);
  return houghloc::run(path, frames, seed);
}
