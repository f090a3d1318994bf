// Fault injection (docs/reliability.md "Fault injection"): houghloc-offline on rendered
// recordings that each carry one fault (truth/faults.csv gives its windows), against the clean
// run of the same walk. Bounds for every fault: the best pose correct (up to symmetry) again
// within 1 s of each fault window's end, the run's median position error at most 2x the clean
// run's, and no flip; the median over the fault's frames (first start to 1 s after the last
// end) within 2x the clean run's where kFaultCases says so (below). Prints the table of
// docs/reliability.md and writes it to HOUGHLOC_FAULT_WORK/fault_table.md.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tools/offline/estimate_csv.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

constexpr double kMaxRecovery_s = 1.0;
constexpr double kMaxMedianRatio = 2.0;
constexpr double kCorrectPosition_m = 0.10;  // DESIGN §5.3
constexpr double kCorrectHeading_rad = 3.0 * M_PI / 180.0;
constexpr double kAfterFault_s = 1.0;  // the fault's frames run on to 1 s after its end

const fs::path kFixtures = HOUGHLOC_FAULT_FIXTURES;
const fs::path kWork = HOUGHLOC_FAULT_WORK;

struct Window {
  double start_s = 0.0, end_s = 0.0;
};

/// One run's per-frame errors and the figures of the table.
struct RunFigures {
  std::vector<double> t_s, position_error_m, heading_error_deg;
  std::vector<bool> correct_up_to_symmetry;
  std::vector<Window> faults;
  int flips = -1;
  double first_correct_s = NAN;
  double median_m = NAN, p95_m = NAN;  // whole run, metrics.json
  double window_median_m = NAN, window_p95_m = NAN, window_median_deg = NAN;
  double recovery_s = NAN;  // worst over the windows; NAN: not recovered
};

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double p95(std::vector<double> v) {  // nearest rank, like metrics.json
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * v.size()));
  return v[std::max<size_t>(rank, 1) - 1];
}

std::string runOffline(const fs::path& folder, const fs::path& out) {
  const std::string command = std::string(HOUGHLOC_OFFLINE_EXE) + " " + folder.string() +
                              " --quiet -o " + out.string() + " 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return "failed: " + output;
  return "";
}

std::vector<Window> readFaultWindows(const fs::path& folder) {
  std::vector<Window> windows;
  const fs::path path = folder / "truth" / "faults.csv";
  if (!fs::exists(path)) return windows;
  const CsvTable table = CsvTable::read(path.string());
  const int start = table.column("t_start_us"), end = table.column("t_end_us");
  for (const CsvRow& row : table.rows()) {
    windows.push_back({1e-6 * table.integer(row, start), 1e-6 * table.integer(row, end)});
  }
  return windows;
}

/// Runs houghloc-offline (default configuration) on fixture `name` and scores its best poses
/// against ground truth.
RunFigures evaluate(const std::string& name) {
  const fs::path folder = kFixtures / name, out = kWork / name;
  fs::remove_all(out);
  RunFigures r;
  const std::string failure = runOffline(folder, out);
  EXPECT_EQ(failure, "") << name;
  if (!failure.empty()) return r;
  std::ifstream metrics_file(out / "metrics.json");
  const nlohmann::json tracking = nlohmann::json::parse(metrics_file)["tracking"];
  r.flips = tracking["flips"].get<int>();
  r.median_m = tracking["median_position_error_m"].get<double>();
  r.p95_m = tracking["p95_position_error_m"].get<double>();
  if (!tracking["first_correct_s"].is_null()) r.first_correct_s = tracking["first_correct_s"];

  const Recording rec = readRecording(folder.string());
  r.faults = readFaultWindows(folder);
  const double t0 = 1e-6 * rec.frames.front().t_us;
  for (const FrameEstimate& e : readFrameEstimates(out.string())) {
    const auto truth = groundTruthAt(rec.ground_truth, e.t_us);
    if (!truth || e.hypotheses.empty()) continue;
    const Pose2& best = e.hypotheses.front().mean;
    const Pose2 twin(-truth->x, -truth->y, truth->theta + M_PI);
    auto correct = [&](const Pose2& p) {
      return std::hypot(best.x - p.x, best.y - p.y) <= kCorrectPosition_m &&
             std::abs(angleDifference(best.theta, p.theta)) <= kCorrectHeading_rad;
    };
    r.t_s.push_back(1e-6 * e.t_us - t0);
    r.position_error_m.push_back(std::hypot(best.x - truth->x, best.y - truth->y));
    r.heading_error_deg.push_back(std::abs(angleDifference(best.theta, truth->theta)) * 180 / M_PI);
    r.correct_up_to_symmetry.push_back(correct(*truth) || correct(twin));
  }
  return r;
}

/// The fault's frames: first window start to kAfterFault_s after the last window end.
void scoreWindow(const std::vector<Window>& faults, RunFigures& r) {
  const double from = faults.front().start_s, to = faults.back().end_s + kAfterFault_s;
  std::vector<double> pos, head;
  for (size_t i = 0; i < r.t_s.size(); ++i) {
    if (r.t_s[i] < from - 1e-9 || r.t_s[i] >= to - 1e-9) continue;
    pos.push_back(r.position_error_m[i]);
    head.push_back(r.heading_error_deg[i]);
  }
  r.window_median_m = median(pos);
  r.window_p95_m = p95(pos);
  r.window_median_deg = median(head);
}

/// Worst over the windows of the time from a window's end to the first frame at or after it
/// whose best pose is correct up to symmetry (NAN when one never recovers).
double recovery(const RunFigures& r) {
  double worst = 0.0;
  for (const Window& w : r.faults) {
    double found = NAN;
    for (size_t i = 0; i < r.t_s.size(); ++i) {
      if (r.t_s[i] >= w.end_s - 1e-9 && r.correct_up_to_symmetry[i]) {
        found = r.t_s[i] - w.end_s;
        break;
      }
    }
    if (std::isnan(found)) return NAN;
    worst = std::max(worst, found);
  }
  return worst;
}

std::string tableRow(const std::string& name, const RunFigures& r) {
  char line[400];
  const std::string rec = std::isnan(r.recovery_s) ? (r.faults.empty() ? "-" : "never")
                                                   : std::to_string(r.recovery_s).substr(0, 4);
  std::snprintf(line, sizeof(line), "| %s | %.1f | %.1f | %.1f | %.1f | %.2f | %d | %s |",
                name.c_str(), 100 * r.median_m, 100 * r.p95_m, 100 * r.window_median_m,
                100 * r.window_p95_m, r.window_median_deg, r.flips, rec.c_str());
  return line;
}

/// A fault recording and whether its fault frames' median is held to 2x the clean run's,
/// beyond the bounds every fault is held to (no flipped frame, recovery within 1 s of each
/// window's end, the whole run's median within 2x the clean run's).
struct FaultCase {
  const char* name;
  bool bound_fault_frames;
};

// Reported, not asserted, where a fault removes what the localizer would need during this
// walk's one-direction stretch (4.1-7.6 s) or corrupts the geometry of the points themselves
// (docs/reliability.md, figures in the table):
// - odometry_dropout, odometry_scale: the motion along the lines is seen by nothing but
//   odometry until the second direction returns;
// - camera_pose_delay: the recorded camera yaw is wrong by up to 3 deg while the head sweeps,
//   and a frame's points cannot tell that from a robot heading error;
// - camera_pitch_error: the point update fits the frame's camera pitch with the pose (docs/
//   tracking.md "Camera tilt"), so the track stays (no flip), but with one line direction in
//   view pitch and position across the line are hard to tell apart: it drifts by one or two
//   decimetres.
const FaultCase kFaultCases[] = {
    {"odometry_dropout", false},   {"robots_in_view", true},     {"motion_blur", true},
    {"light_change", true},        {"camera_pose_delay", false}, {"odometry_scale", false},
    {"camera_pitch_error", false}, {"frame_drop", true},
};

TEST(FaultInjection, EachFaultStaysWithinTheBounds) {
  fs::create_directories(kWork);
  RunFigures clean = evaluate("clean");
  ASSERT_GE(clean.flips, 0);
  ASSERT_FALSE(std::isnan(clean.first_correct_s)) << "the clean run never localized";
  std::vector<std::string> table = {
      "| run | median (cm) | p95 (cm) | fault median (cm) | fault p95 (cm) | fault median "
      "(deg) | flips | recovery (s) |",
      "|---|---|---|---|---|---|---|---|"};
  std::vector<std::pair<FaultCase, RunFigures>> faults;
  for (const FaultCase& fault : kFaultCases) {
    RunFigures r = evaluate(fault.name);
    ASSERT_FALSE(r.faults.empty()) << fault.name << ": no truth/faults.csv rows";
    scoreWindow(r.faults, r);
    r.recovery_s = recovery(r);
    faults.emplace_back(fault, r);
  }
  // The clean run over the same frames as each fault's (all faults share the windows' span
  // only by convention, so score the clean run per fault).
  const std::vector<Window> first_window = faults.front().second.faults;
  scoreWindow(first_window, clean);
  table.push_back(tableRow("clean", clean));
  for (auto& [fault, r] : faults) {
    const std::string name = fault.name;
    RunFigures clean_here = clean;
    scoreWindow(r.faults, clean_here);
    table.push_back(tableRow(name, r));
    EXPECT_LE(r.recovery_s, kMaxRecovery_s) << name << " (NAN: never correct again)";
    EXPECT_LE(r.median_m, kMaxMedianRatio * clean.median_m) << name << ": whole run";
    EXPECT_EQ(r.flips, 0) << name;
    if (fault.bound_fault_frames) {
      EXPECT_LE(r.window_median_m, kMaxMedianRatio * clean_here.window_median_m)
          << name << ": fault frames (clean run " << clean_here.window_median_m << " m)";
    }
  }
  EXPECT_EQ(clean.flips, 0);
  std::ofstream md(kWork / "fault_table.md");
  for (const std::string& line : table) {
    std::printf("%s\n", line.c_str());
    md << line << "\n";
  }
}

}  // namespace
}  // namespace houghloc
