#pragma once

#include <Eigen/Core>
#include <vector>

#include "vision/line_spots.h"  // SpotSupportConfig

namespace houghloc {

/// For each pixel, whether another of them lies within radius_px.
std::vector<char> hasNeighbourWithin(const std::vector<Eigen::Vector2f>& pixels, float radius_px);

/// Drops, in place and keeping their order, the items (anything with a `pixel` and a `width_px`:
/// LineSpot, SpotRay) at least `config.min_width_px` wide with no other item within
/// `config.radius_px`; returns how many it dropped.
template <typename Item>
int dropIsolated(std::vector<Item>* items, const SpotSupportConfig& config) {
  if (!config.enabled || !(config.radius_px > 0.0) || items->empty()) return 0;
  std::vector<Eigen::Vector2f> pixels;
  pixels.reserve(items->size());
  for (const Item& item : *items) pixels.push_back(item.pixel);
  const std::vector<char> supported =
      hasNeighbourWithin(pixels, static_cast<float>(config.radius_px));
  std::size_t kept = 0;
  for (std::size_t i = 0; i < items->size(); ++i) {
    if (supported[i] || (*items)[i].width_px < config.min_width_px) (*items)[kept++] = (*items)[i];
  }
  const int dropped = static_cast<int>(items->size() - kept);
  items->resize(kept);
  return dropped;
}

}  // namespace houghloc
