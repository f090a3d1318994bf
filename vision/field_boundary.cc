#include "vision/field_boundary.h"

#include <algorithm>
#include <cmath>

#include "vision/pixel_access.h"

namespace houghloc {
namespace {

/// Top of the first run of min_green_run green samples in column u, refined to the pixel;
/// negative when the column has no such run.
template <typename Pixels>
float greenTop(const Pixels& pixels, const FieldColor& color, int u, int start_row,
               const FieldBoundaryConfig& config) {
  int run = 0;
  int run_start = -1;
  for (int v = std::max(0, start_row); v < pixels.rows(); v += config.row_step_px) {
    if (color.isField(pixels.at(u, v).data())) {
      if (run++ == 0) run_start = v;
      if (run >= config.min_green_run) break;
    } else {
      run = 0;
    }
  }
  if (run < config.min_green_run) return -1.f;
  int top = run_start;
  while (top > std::max(0, start_row) && top > run_start - config.row_step_px + 1 &&
         color.isField(pixels.at(u, top - 1).data())) {
    --top;
  }
  return static_cast<float>(top);
}

double cross(const Eigen::Vector2f& o, const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
  return static_cast<double>(a.x() - o.x()) * (b.y() - o.y()) -
         static_cast<double>(a.y() - o.y()) * (b.x() - o.x());
}

/// Andrew's monotone chain: the chain that every point lies on or below (larger v) in image
/// coordinates. Points are sorted by u.
std::vector<Eigen::Vector2f> upperHull(const std::vector<Eigen::Vector2f>& points) {
  std::vector<Eigen::Vector2f> hull;
  for (const Eigen::Vector2f& p : points) {
    while (hull.size() >= 2 && cross(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
    hull.push_back(p);
  }
  return hull;
}

/// Drops tops that stick out far above both neighbours; returns whether any was dropped.
bool dropSpikes(const std::vector<Eigen::Vector2f>& hull, std::vector<Eigen::Vector2f>* tops,
                double max_spike_px) {
  bool dropped = false;
  for (const Eigen::Vector2f& vertex : hull) {
    auto it = std::find_if(tops->begin(), tops->end(),
                           [&](const Eigen::Vector2f& t) { return t.x() == vertex.x(); });
    if (it == tops->end()) continue;
    const bool has_left = it != tops->begin(), has_right = it + 1 != tops->end();
    if (!has_left && !has_right) continue;
    const float left = has_left ? (it - 1)->y() : (it + 1)->y();
    const float right = has_right ? (it + 1)->y() : (it - 1)->y();
    if (std::min(left, right) - it->y() > max_spike_px) {
      tops->erase(it);
      dropped = true;
    }
  }
  return dropped;
}

/// Rows at the image bottom without turf (the robot's feet), per sampled column, spread to every
/// column with the smaller (higher) value of the two neighbouring samples: conservative at the
/// body's edges. A field line running into the feet joins their non-turf run along the bottom
/// row but reaches much higher: each run's columns are capped at its median height (plus a
/// margin), so the line above the feet is still scanned.
template <typename Pixels>
std::vector<float> bodyRows(const Pixels& pixels, const FieldColor& color,
                            const FieldBoundaryConfig& config) {
  const int step = std::max(1, config.column_step_px);
  const int rows = pixels.rows(), cols = pixels.cols();
  // Per column the id of the wide non-turf run of the bottom row it lies in (-1: none).
  std::vector<int> run_of(static_cast<size_t>(cols), -1);
  RunBuffer buffer;
  const auto bottom = pixels.rowRun(0, rows - 1, cols, &buffer);
  const int min_width = static_cast<int>(config.min_body_width_share * cols);
  int runs = 0;
  for (int u = 0; u < cols;) {
    const int begin = u;
    while (u < cols && !color.isField(bottom.at(u))) ++u;
    if (u - begin >= std::max(1, min_width))
      std::fill(run_of.begin() + begin, run_of.begin() + u, runs++);
    if (u == begin) ++u;
  }
  std::vector<int> extents, sample_run;
  std::vector<std::vector<int>> run_extents(static_cast<size_t>(runs));
  for (int u = 0; u < cols; u += step) {
    const int run = run_of[static_cast<size_t>(u)];
    int extent = 0;
    if (run >= 0) {
      int v = rows - 1;
      while (v >= 0 && !color.isField(pixels.at(u, v).data())) --v;
      extent = rows - 1 - v;
      run_extents[static_cast<size_t>(run)].push_back(extent);
    }
    extents.push_back(extent);
    sample_run.push_back(run);
  }
  std::vector<float> sampled;
  for (size_t i = 0; i < extents.size(); ++i) {
    int extent = extents[i];
    if (sample_run[i] >= 0) {
      std::vector<int>& e = run_extents[static_cast<size_t>(sample_run[i])];
      std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
      const double cap = config.body_height_tolerance * e[e.size() / 2] + config.row_step_px;
      extent = std::min(extent, static_cast<int>(cap));
    }
    sampled.push_back(extent >= config.min_body_px ? static_cast<float>(rows - extent)
                                                   : static_cast<float>(rows));
  }
  std::vector<float> body_rows(static_cast<size_t>(cols));
  for (int u = 0; u < cols; ++u) {
    const size_t left = static_cast<size_t>(u / step);
    const size_t right = std::min(sampled.size() - 1, left + 1);
    body_rows[static_cast<size_t>(u)] = std::min(sampled[left], sampled[right]);
  }
  return body_rows;
}

/// The sampled green tops: every column_step_px-th column and the last one.
template <typename Pixels>
std::vector<Eigen::Vector2f> greenTops(const Pixels& pixels, const FieldColor& color,
                                       const std::vector<int>& start_rows,
                                       const FieldBoundaryConfig& config) {
  std::vector<Eigen::Vector2f> tops;
  const int cols = pixels.cols();
  const int step = std::max(1, config.column_step_px);
  for (int u = 0; u < cols; u += step) {
    const int col = std::min(u, cols - 1);
    const float top = greenTop(pixels, color, col, start_rows[static_cast<size_t>(col)], config);
    if (top >= 0.f) tops.emplace_back(static_cast<float>(col), top);
  }
  if (cols - 1 > (cols - 1) / step * step) {
    const int col = cols - 1;
    const float top = greenTop(pixels, color, col, start_rows[static_cast<size_t>(col)], config);
    if (top >= 0.f) tops.emplace_back(static_cast<float>(col), top);
  }
  return tops;
}

}  // namespace

FieldBoundary detectFieldBoundary(const cv::Mat& image, const FieldColor& color,
                                  const std::vector<int>& start_rows,
                                  const FieldBoundaryConfig& config) {
  FieldBoundary boundary;
  boundary.rows.assign(static_cast<size_t>(image.cols), static_cast<float>(image.rows));
  boundary.body_rows = boundary.rows;
  if (!color.valid) return boundary;
  visitPixels(image, [&](const auto& pixels) {
    boundary.body_rows = bodyRows(pixels, color, config);
    boundary.green_tops = greenTops(pixels, color, start_rows, config);
  });
  std::vector<Eigen::Vector2f> tops = boundary.green_tops;
  if (tops.size() < 2) return boundary;
  boundary.hull = upperHull(tops);
  for (int pass = 0; pass < config.max_spike_passes; ++pass) {
    if (!dropSpikes(boundary.hull, &tops, config.max_spike_px) || tops.size() < 2) break;
    boundary.hull = upperHull(tops);
  }
  // Interpolate between hull vertices; extend the outer edges to the image border.
  const std::vector<Eigen::Vector2f>& hull = boundary.hull;
  for (int u = 0; u < image.cols; ++u) {
    size_t i = 1;
    while (i + 1 < hull.size() && hull[i].x() < u) ++i;
    const Eigen::Vector2f& a = hull[i - 1];
    const Eigen::Vector2f& b = hull[i];
    float v = a.y();
    if (hull.size() >= 2 && b.x() != a.x())
      v = a.y() + (b.y() - a.y()) * (u - a.x()) / (b.x() - a.x());
    // Outside the sampled range keep it flat: the extrapolated slope can shoot off.
    if (u < hull.front().x()) v = hull.front().y();
    if (u > hull.back().x()) v = hull.back().y();
    boundary.rows[static_cast<size_t>(u)] =
        std::clamp(std::max(v, static_cast<float>(start_rows[static_cast<size_t>(u)])), 0.f,
                   static_cast<float>(image.rows));
  }
  boundary.found = true;
  return boundary;
}

}  // namespace houghloc
