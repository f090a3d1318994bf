#include "vision/isolated_spots.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "vision/cell_key.h"

namespace houghloc {
namespace {

/// Pixels sorted by the square cell of the search radius they lie in: a pixel's neighbours within
/// the radius lie in its own cell and the eight around it.
class PixelCells {
 public:
  PixelCells(const std::vector<Eigen::Vector2f>& pixels, float cell_px)
      : pixels_(pixels), cell_(cell_px) {
    sorted_.reserve(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) sorted_.push_back({key(cellOf(pixels[i])), i});
    std::sort(sorted_.begin(), sorted_.end());
  }

  bool hasNeighbour(std::size_t i, float radius_px) const {
    const auto [cx, cy] = cellOf(pixels_[i]);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const std::int64_t k = key({cx + dx, cy + dy});
        auto it =
            std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(k, std::size_t{0}));
        for (; it != sorted_.end() && it->first == k; ++it) {
          const std::size_t j = it->second;
          if (j != i && (pixels_[j] - pixels_[i]).norm() <= radius_px) return true;
        }
      }
    }
    return false;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cellOf(const Eigen::Vector2f& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_))};
  }
  static std::int64_t key(std::pair<std::int64_t, std::int64_t> cell) {
    return cellKey(cell.first, cell.second);
  }

  const std::vector<Eigen::Vector2f>& pixels_;
  float cell_;
  std::vector<std::pair<std::int64_t, std::size_t>> sorted_;
};

}  // namespace

std::vector<char> hasNeighbourWithin(const std::vector<Eigen::Vector2f>& pixels, float radius_px) {
  std::vector<char> out(pixels.size(), 0);
  if (!(radius_px > 0.f)) return out;
  const PixelCells cells(pixels, radius_px);
  for (std::size_t i = 0; i < pixels.size(); ++i) out[i] = cells.hasNeighbour(i, radius_px);
  return out;
}

}  // namespace houghloc
