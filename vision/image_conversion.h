#pragma once

#include <opencv2/core.hpp>

namespace houghloc {

/// Pixel layouts VisionPipeline accepts (DESIGN §7 image_t): BGR8 (CV_8UC3) and YUYV 4:2:2
/// (CV_8UC2, as NAO cameras deliver it: Y0 U Y1 V for two neighbouring pixels).
enum class PixelFormat { kBgr8, kYuyv };

/// The format a cv::Mat holds judged by its type; throws std::invalid_argument for anything else.
PixelFormat pixelFormatOf(const cv::Mat& image);

/// YUYV (CV_8UC2, width even) to BGR8. Throws std::invalid_argument on a wrong type or odd width.
cv::Mat yuyvToBgr(const cv::Mat& yuyv);

/// BGR8 to YUYV (for tests and the node's simulated camera); width must be even.
cv::Mat bgrToYuyv(const cv::Mat& bgr);

/// The image as BGR8: a shallow copy for BGR8 input; for YUYV a conversion into `buffer`, whose
/// memory is reused while the size stays (a new 0.9 MB buffer per 640x480 frame costs the node
/// page faults on every frame). The result shares memory with `buffer` or `image`.
cv::Mat toBgr(const cv::Mat& image, cv::Mat& buffer);

}  // namespace houghloc
