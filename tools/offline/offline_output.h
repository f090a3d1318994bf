#pragma once

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "tools/offline/offline_context.h"

namespace houghloc {

/// Sets one section ("vision", "global", "tracking") of OUT/metrics.json, keeping the others a
/// previous mode wrote. Throws std::runtime_error naming the file when it cannot be written.
void writeMetricsSection(const std::string& out_dir, const std::string& section,
                         const nlohmann::json& value);

/// The frame's image as BGR8; none (and `problem` set) when the file is missing or unreadable,
/// which the modes count and skip.
std::optional<cv::Mat> loadFrameImage(const OfflineContext& context, const FrameRecord& frame,
                                      std::string* problem);

/// Progress on stderr ("\r<what> frame i/n"), at most every `every` frames; nothing when quiet.
void reportProgress(const OfflineContext& context, const char* what, int done, int total,
                    int every = 10);

}  // namespace houghloc
