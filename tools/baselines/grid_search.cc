#include "tools/baselines/grid_search.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

constexpr int kBuckets = 4;       // kernel widths by point range
constexpr double kBucketM = 2.0;  // range covered per bucket

bool distinct(const Pose2& a, const Pose2& b, double dist, double angle) {
  return (a.translation() - b.translation()).norm() > dist ||
         std::abs(angleDifference(a.theta, b.theta)) > angle;
}

}  // namespace

GridSearchLocalizer::GridSearchLocalizer(const FieldModel& field, const GridSearchConfig& config)
    : field_(field), config_(config), grid_(field, config.grid) {
  const double hx = field.outerHalfLength() + config.max_range_m + 2 * config.step_m;
  const double hy = field.outerHalfWidth() + config.max_range_m + 2 * config.step_m;
  lattice_origin_ = Eigen::Vector2d(-hx, -hy);
  lattice_cols_ = static_cast<int>(std::ceil(2 * hx / config.step_m)) + 1;
  lattice_rows_ = static_cast<int>(std::ceil(2 * hy / config.step_m)) + 1;
  lattice_distance_.resize(static_cast<std::size_t>(lattice_cols_) * lattice_rows_);
  for (int r = 0; r < lattice_rows_; ++r) {
    for (int c = 0; c < lattice_cols_; ++c) {
      const Eigen::Vector2d p = lattice_origin_ + config.step_m * Eigen::Vector2d(c, r);
      lattice_distance_[static_cast<std::size_t>(r) * lattice_cols_ + c] =
          static_cast<float>(grid_.distance(p));
    }
  }
}

std::vector<GridSearchOptimum> GridSearchLocalizer::locate(const GroundPoints& frame) const {
  WeightedPoints all;
  for (const GroundPoint& g : frame.points) {
    if (!g.p_robot.allFinite() || !(g.weight > 0.0) || g.p_robot.norm() > config_.max_range_m) {
      continue;
    }
    all.points.push_back(g.p_robot);
    all.weights.push_back(g.weight);
  }
  if (all.size() < 3) return {};
  const WeightedPoints fine = subsamplePoints(all, config_.fine_points);
  std::vector<GridSearchOptimum> optima;
  for (const Start& s : coarseSearch(subsamplePoints(all, config_.coarse_points))) {
    optima.push_back(refine(fine, s.pose));
  }
  std::sort(optima.begin(), optima.end(),
            [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<GridSearchOptimum> out;
  for (const auto& o : optima) {
    if (static_cast<int>(out.size()) >= config_.max_optima) break;
    bool is_new = true;
    for (const auto& kept : out) {
      is_new &=
          distinct(kept.field_T_robot, o.field_T_robot, config_.distinct_m, config_.distinct_rad);
    }
    if (is_new) out.push_back(o);
  }
  return out;
}

std::vector<GridSearchLocalizer::Start> GridSearchLocalizer::coarseSearch(
    const WeightedPoints& points) const {
  const double step = config_.step_m;
  // Kernel tables per range bucket: k(d) = max(0, 1 - (d / c_b)^2).
  std::vector<std::vector<float>> tables(kBuckets);
  for (int b = 0; b < kBuckets; ++b) {
    const double c = config_.scoring.kernel_width_m + config_.coarse_extra_m +
                     (b + 1) * kBucketM * std::tan(0.5 * config_.step_rad);
    tables[b].resize(lattice_distance_.size());
    for (std::size_t i = 0; i < lattice_distance_.size(); ++i) {
      const double d = lattice_distance_[i] / c;
      tables[b][i] = static_cast<float>(std::max(0.0, 1.0 - d * d));
    }
  }
  const int nx = static_cast<int>(std::floor(field_.outerHalfLength() / step));
  const int ny = static_cast<int>(std::floor(field_.outerHalfWidth() / step));
  const int cols = 2 * nx + 1, rows = 2 * ny + 1;
  const int headings = static_cast<int>(std::lround(2 * M_PI / config_.step_rad));
  // Lattice cell of the pose translation (i - nx, j - ny) * step.
  const int base_c = static_cast<int>(std::lround(-lattice_origin_.x() / step)) - nx;
  const int base_r = static_cast<int>(std::lround(-lattice_origin_.y() / step)) - ny;
  std::vector<float> score(static_cast<std::size_t>(cols) * rows * headings, 0.0f);
  for (int h = 0; h < headings; ++h) {
    const double theta = h * 2 * M_PI / headings;
    const double c = std::cos(theta), s = std::sin(theta);
    float* out = &score[static_cast<std::size_t>(h) * cols * rows];
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector2d& p = points.points[i];
      const int ox = static_cast<int>(std::lround((c * p.x() - s * p.y()) / step));
      const int oy = static_cast<int>(std::lround((s * p.x() + c * p.y()) / step));
      const int b = std::min(kBuckets - 1, static_cast<int>(p.norm() / kBucketM));
      const float w = static_cast<float>(points.weights[i]);
      for (int r = 0; r < rows; ++r) {
        const float* src =
            &tables[b][static_cast<std::size_t>(base_r + r + oy) * lattice_cols_ + base_c + ox];
        float* dst = out + static_cast<std::size_t>(r) * cols;
        for (int col = 0; col < cols; ++col) dst[col] += w * src[col];
      }
    }
  }
  // Local maxima over (x, y, heading), best first, distinct.
  std::vector<Start> maxima;
  const float top = *std::max_element(score.begin(), score.end());
  auto at = [&](int h, int r, int col) {
    h = (h + headings) % headings;
    if (r < 0 || r >= rows || col < 0 || col >= cols) return -1.0f;
    return score[(static_cast<std::size_t>(h) * rows + r) * cols + col];
  };
  for (int h = 0; h < headings; ++h) {
    for (int r = 0; r < rows; ++r) {
      for (int col = 0; col < cols; ++col) {
        const float v = at(h, r, col);
        if (v < 0.3f * top || v <= 0.0f) continue;
        bool is_max = true;
        for (int dh = -1; dh <= 1 && is_max; ++dh) {
          for (int dr = -1; dr <= 1 && is_max; ++dr) {
            for (int dc = -1; dc <= 1 && is_max; ++dc) {
              if (dh || dr || dc) is_max = at(h + dh, r + dr, col + dc) <= v;
            }
          }
        }
        if (is_max) {
          maxima.push_back({Pose2((col - nx) * step, (r - ny) * step, h * 2 * M_PI / headings), v});
        }
      }
    }
  }
  std::sort(maxima.begin(), maxima.end(),
            [](const Start& a, const Start& b) { return a.score > b.score; });
  std::vector<Start> out;
  for (const Start& m : maxima) {
    if (static_cast<int>(out.size()) >= config_.starts) break;
    bool is_new = true;
    for (const Start& k : out) is_new &= distinct(k.pose, m.pose, 2 * step, 1.5 * config_.step_rad);
    if (is_new) out.push_back(m);
  }
  return out;
}

GridSearchOptimum GridSearchLocalizer::refine(const WeightedPoints& points,
                                              const Pose2& start) const {
  // Pattern search, first with a wide kernel (the start can be half a lattice step off), then
  // with the fine kernel, halving the steps down to 5 mm / 0.1 deg.
  Pose2 pose = start;
  for (double width :
       {config_.scoring.kernel_width_m + config_.coarse_extra_m, config_.scoring.kernel_width_m}) {
    ScoringConfig scoring = config_.scoring;
    scoring.kernel_width_m = width;
    double best = scorePose(points, pose, grid_, scoring).score;
    double dxy = 0.5 * config_.step_m, dth = 0.5 * config_.step_rad;
    while (dxy >= 0.005) {
      bool moved = false;
      for (const Eigen::Vector3d& d :
           {Eigen::Vector3d(dxy, 0, 0), Eigen::Vector3d(-dxy, 0, 0), Eigen::Vector3d(0, dxy, 0),
            Eigen::Vector3d(0, -dxy, 0), Eigen::Vector3d(0, 0, dth), Eigen::Vector3d(0, 0, -dth)}) {
        const Pose2 trial(pose.x + d.x(), pose.y + d.y(), pose.theta + d.z());
        const double s = scorePose(points, trial, grid_, scoring).score;
        if (s > best) {
          best = s;
          pose = trial;
          moved = true;
        }
      }
      if (!moved) {
        dxy *= 0.5;
        dth *= 0.5;
      }
    }
  }
  return {pose, scorePose(points, pose, grid_, config_.scoring).score};
}

}  // namespace houghloc
