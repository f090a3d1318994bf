#include "tools/offline/estimate_csv.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include "localization/tracked_hypotheses.h"
#include "localization/tracker_config.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kPosesHeader = {
    "t_us", "x", "y", "theta", "var_x", "var_y", "var_theta", "weight", "num_hypotheses", "status"};
/// Written after kPosesHeader; not read back (twinWeight() recomputes it from hypotheses.csv,
/// so folders written without it still read).
const char* const kTwinWeightColumn = "twin_weight";
const std::vector<std::string> kHypothesesHeader = {
    "t_us",  "rank",      "x",      "y",          "theta",      "var_x",
    "var_y", "var_theta", "cov_xy", "cov_xtheta", "cov_ytheta", "weight"};
const std::vector<std::string> kStatuses = {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"};

std::string posesPath(const std::string& dir) { return (fs::path(dir) / "poses.csv").string(); }
std::string hypothesesPath(const std::string& dir) {
  return (fs::path(dir) / "hypotheses.csv").string();
}

/// Column indices of a header, looked up once (CsvTable::column() names the file on a miss).
std::vector<int> columns(const CsvTable& table, const std::vector<std::string>& names) {
  std::vector<int> out;
  for (const std::string& name : names) out.push_back(table.column(name));
  return out;
}

/// hypotheses.csv rows by t_us, in file order (ranks are checked by the caller).
std::map<std::int64_t, std::vector<std::pair<int, GaussianPose>>> readHypotheses(
    const std::string& out_dir, std::map<std::int64_t, int>* first_line) {
  const CsvTable table = CsvTable::read(hypothesesPath(out_dir));
  const std::vector<int> c = columns(table, kHypothesesHeader);
  std::map<std::int64_t, std::vector<std::pair<int, GaussianPose>>> by_time;
  for (const CsvRow& row : table.rows()) {
    const std::int64_t t_us = table.integer(row, c[0]);
    const std::int64_t rank = table.integer(row, c[1]);
    auto& list = by_time[t_us];
    if (rank != static_cast<std::int64_t>(list.size())) {
      table.fail(row, "rank " + std::to_string(rank) + " where " + std::to_string(list.size()) +
                          " was expected (ranks start at 0 and increase by one per t_us)");
    }
    GaussianPose h;
    h.mean = Pose2(table.number(row, c[2]), table.number(row, c[3]), table.number(row, c[4]));
    // Pose2 normalises theta; keep the written value so the round trip is exact.
    h.mean.theta = table.number(row, c[4]);
    Eigen::Matrix3d& cov = h.covariance;
    cov(0, 0) = table.number(row, c[5]);
    cov(1, 1) = table.number(row, c[6]);
    cov(2, 2) = table.number(row, c[7]);
    cov(0, 1) = cov(1, 0) = table.number(row, c[8]);
    cov(0, 2) = cov(2, 0) = table.number(row, c[9]);
    cov(1, 2) = cov(2, 1) = table.number(row, c[10]);
    h.weight = table.number(row, c[11]);
    if (cov(0, 0) < 0.0 || cov(1, 1) < 0.0 || cov(2, 2) < 0.0) table.fail(row, "negative variance");
    if (h.weight < 0.0) table.fail(row, "negative weight");
    first_line->emplace(t_us, row.line);
    list.emplace_back(row.line, h);
  }
  return by_time;
}

std::vector<std::string> withTwinWeight(std::vector<std::string> header) {
  header.push_back(kTwinWeightColumn);
  return header;
}

}  // namespace

double FrameEstimate::twinWeight() const {
  const TrackerConfig defaults;
  return mirrorTwinWeight(hypotheses, defaults.mirror_tolerance_m, defaults.mirror_tolerance_rad);
}

struct EstimateCsvWriter::Files {
  CsvWriter poses;
  CsvWriter hypotheses;
  Files(const std::string& dir)
      : poses(posesPath(dir), withTwinWeight(kPosesHeader)),
        hypotheses(hypothesesPath(dir), kHypothesesHeader) {}
  std::optional<FrameEstimate> held;  ///< the newest estimate, written once its time is over
};

EstimateCsvWriter::EstimateCsvWriter(const std::string& out_dir)
    : files_(std::make_shared<Files>(out_dir)) {}

void EstimateCsvWriter::write(const FrameEstimate& estimate) {
  std::optional<FrameEstimate>& held = files_->held;
  if (held && held->t_us != estimate.t_us) writeRows(*held);
  held = estimate;
}

void EstimateCsvWriter::writeRows(const FrameEstimate& estimate) {
  CsvWriter& p = files_->poses;
  CsvWriter& h = files_->hypotheses;
  const std::string t = p.format(estimate.t_us);
  const std::string count = std::to_string(estimate.hypotheses.size());
  if (estimate.hypotheses.empty()) {
    p.writeRow({t, "", "", "", "", "", "", "", count, estimate.status, "0"});
    return;
  }
  const GaussianPose& best = estimate.hypotheses.front();
  p.writeRow({t, p.format(best.mean.x), p.format(best.mean.y), p.format(best.mean.theta),
              p.format(best.covariance(0, 0)), p.format(best.covariance(1, 1)),
              p.format(best.covariance(2, 2)), p.format(best.weight), count, estimate.status,
              p.format(estimate.twinWeight())});
  for (size_t rank = 0; rank < estimate.hypotheses.size(); ++rank) {
    const GaussianPose& g = estimate.hypotheses[rank];
    const Eigen::Matrix3d& c = g.covariance;
    h.writeRow({t, std::to_string(rank), h.format(g.mean.x), h.format(g.mean.y),
                h.format(g.mean.theta), h.format(c(0, 0)), h.format(c(1, 1)), h.format(c(2, 2)),
                h.format(c(0, 1)), h.format(c(0, 2)), h.format(c(1, 2)), h.format(g.weight)});
  }
}

void EstimateCsvWriter::close() {
  if (files_->held) writeRows(*files_->held);
  files_->held.reset();
  files_->poses.close();
  files_->hypotheses.close();
}

std::vector<FrameEstimate> readFrameEstimates(const std::string& out_dir) {
  std::map<std::int64_t, int> hypothesis_line;
  auto hypotheses = readHypotheses(out_dir, &hypothesis_line);
  const CsvTable table = CsvTable::read(posesPath(out_dir));
  const std::vector<int> c = columns(table, kPosesHeader);
  std::vector<FrameEstimate> estimates;
  std::map<std::int64_t, int> seen;
  for (const CsvRow& row : table.rows()) {
    FrameEstimate e;
    e.t_us = table.integer(row, c[0]);
    if (!seen.emplace(e.t_us, row.line).second) {
      table.fail(
          row, "t_us " + std::to_string(e.t_us) + " repeats line " + std::to_string(seen[e.t_us]));
    }
    e.status = CsvTable::text(row, c[9]);
    if (std::find(kStatuses.begin(), kStatuses.end(), e.status) == kStatuses.end()) {
      table.fail(row,
                 "unknown status '" + e.status + "' (INITIALIZING, TRACKING, AMBIGUOUS or LOST)");
    }
    const std::int64_t count = table.integer(row, c[8]);
    int empty_pose_fields = 0;
    for (int k = 1; k <= 7; ++k) {
      if (!table.optionalNumber(row, c[k])) ++empty_pose_fields;
    }
    if (count < 0) table.fail(row, "negative num_hypotheses");
    if (count == 0 && empty_pose_fields != 7) {
      table.fail(row, "pose fields must be empty when num_hypotheses is 0");
    }
    if (count > 0 && empty_pose_fields != 0) table.fail(row, "empty pose field");
    const auto it = hypotheses.find(e.t_us);
    const std::int64_t found = it == hypotheses.end() ? 0 : it->second.size();
    if (found != count) {
      table.fail(row, "num_hypotheses " + std::to_string(count) + " but " +
                          hypothesesPath(out_dir) + " has " + std::to_string(found) +
                          " rows for t_us " + std::to_string(e.t_us));
    }
    if (it != hypotheses.end()) {
      for (const auto& [line, h] : it->second) e.hypotheses.push_back(h);
      hypotheses.erase(it);
    }
    estimates.push_back(std::move(e));
  }
  if (!hypotheses.empty()) {
    const std::int64_t t_us = hypotheses.begin()->first;
    throw RecordingError(hypothesesPath(out_dir) + ":" + std::to_string(hypothesis_line[t_us]) +
                         ": t_us " + std::to_string(t_us) + " has no row in " + posesPath(out_dir));
  }
  return estimates;
}

}  // namespace houghloc
