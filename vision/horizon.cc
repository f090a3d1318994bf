#include "vision/horizon.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

std::vector<int> scanStartRows(const CameraModel& camera, const HorizonConfig& config) {
  const std::vector<double>& horizon = camera.horizonRows();
  std::vector<int> rows(static_cast<size_t>(camera.width()), camera.height());
  for (size_t u = 0; u < rows.size() && u < horizon.size(); ++u) {
    // -infinity: the column sees ground throughout; +infinity (and NaN): no ground at all.
    const double row = std::ceil(horizon[u] + config.margin_px);
    if (!std::isnan(row)) {
      rows[u] = static_cast<int>(std::clamp(row, 0.0, static_cast<double>(camera.height())));
    }
  }
  return rows;
}

}  // namespace houghloc
