#include "vision/image_conversion.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace houghloc {

namespace {

// cvtColor reallocates `bgr` only when its size or type differs.
void convertYuyv(const cv::Mat& yuyv, cv::Mat& bgr) {
  if (yuyv.type() != CV_8UC2 || yuyv.cols % 2 != 0) {
    throw std::invalid_argument("YUYV image must be CV_8UC2 with an even width");
  }
  cv::cvtColor(yuyv, bgr, cv::COLOR_YUV2BGR_YUYV);
}

}  // namespace

PixelFormat pixelFormatOf(const cv::Mat& image) {
  if (image.type() == CV_8UC3) return PixelFormat::kBgr8;
  if (image.type() == CV_8UC2) return PixelFormat::kYuyv;
  throw std::invalid_argument("image type " + std::to_string(image.type()) +
                              " is neither BGR8 (CV_8UC3) nor YUYV (CV_8UC2)");
}

cv::Mat yuyvToBgr(const cv::Mat& yuyv) {
  cv::Mat bgr;
  convertYuyv(yuyv, bgr);
  return bgr;
}

cv::Mat bgrToYuyv(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3 || bgr.cols % 2 != 0) {
    throw std::invalid_argument("BGR image must be CV_8UC3 with an even width");
  }
  // OpenCV has no BGR -> YUYV conversion. Use limited-range BT.601, the inverse of what
  // COLOR_YUV2BGR_YUYV decodes, and average the chroma of each pixel pair.
  cv::Mat yuyv(bgr.rows, bgr.cols, CV_8UC2);
  const auto clamp8 = [](double value) {
    return static_cast<uchar>(std::clamp(value + 0.5, 0.0, 255.0));
  };
  for (int r = 0; r < bgr.rows; ++r) {
    const cv::Vec3b* src = bgr.ptr<cv::Vec3b>(r);
    cv::Vec2b* dst = yuyv.ptr<cv::Vec2b>(r);
    for (int c = 0; c < bgr.cols; c += 2) {
      double u_sum = 0.0, v_sum = 0.0;
      for (int k = 0; k < 2; ++k) {
        const double b = src[c + k][0], g = src[c + k][1], red = src[c + k][2];
        dst[c + k][0] = clamp8(16.0 + 0.257 * red + 0.504 * g + 0.098 * b);
        u_sum += 128.0 - 0.148 * red - 0.291 * g + 0.439 * b;
        v_sum += 128.0 + 0.439 * red - 0.368 * g - 0.071 * b;
      }
      dst[c][1] = clamp8(0.5 * u_sum);
      dst[c + 1][1] = clamp8(0.5 * v_sum);
    }
  }
  return yuyv;
}

cv::Mat toBgr(const cv::Mat& image, cv::Mat& buffer) {
  if (pixelFormatOf(image) == PixelFormat::kBgr8) return image;
  convertYuyv(image, buffer);
  return buffer;
}

}  // namespace houghloc
