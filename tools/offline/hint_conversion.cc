#include "tools/offline/hint_conversion.h"

#include <algorithm>
#include <filesystem>

namespace houghloc {
namespace {

constexpr double kMinSigmaM = 0.01;
constexpr double kMinSigmaRad = 0.5 * M_PI / 180.0;

}  // namespace

std::vector<LocalizationHint> convertHints(const Recording& recording) {
  const std::string file = (std::filesystem::path(recording.folder) / "hints.csv").string();
  std::vector<LocalizationHint> hints;
  for (const HintRecord& record : recording.hints) {
    LocalizationHint hint;
    hint.t_us = record.t_us;
    const auto kind = parseHintKind(record.kind);
    if (!kind) throw RecordingError(file + ": unknown hint kind '" + record.kind + "'");
    hint.kind = *kind;
    const bool needs_pose = hint.kind == HintKind::kResetTo || hint.kind == HintKind::kAdd;
    if (needs_pose && !record.pose) {
      throw RecordingError(file + ": the " + record.kind + " hint at t_us " +
                           std::to_string(record.t_us) + " needs x, y and theta");
    }
    if (needs_pose) {
      GaussianPose pose;
      pose.mean = *record.pose;
      const Eigen::Vector3d sigma(std::max(record.sigma_x, kMinSigmaM),
                                  std::max(record.sigma_y, kMinSigmaM),
                                  std::max(record.sigma_theta, kMinSigmaRad));
      pose.covariance = sigma.cwiseProduct(sigma).asDiagonal();
      pose.weight = 1.0;
      hint.poses.push_back(pose);
    }
    hints.push_back(hint);
  }
  return hints;
}

}  // namespace houghloc
