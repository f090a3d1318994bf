#pragma once

#include <algorithm>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/field_color.h"
#include "vision/image_conversion.h"

namespace houghloc {

/// One pixel's colour as the vision stages read it: blue, green, red (0-255).
using BgrBytes = std::array<uchar, 3>;

/// A scanline's pixels read in place from a BGR8 image: pixel i at first + i * stride.
struct BgrRun {
  const uchar* first = nullptr;
  long stride = 3;  ///< bytes

  const uchar* at(int i) const { return first + stride * i; }
  int luma(int i) const { return FieldColor::luma(at(i)); }
};

/// A scanline's pixels decoded into a RunBuffer: BGR bytes, and each pixel's luma computed once
/// (a scan reads a pixel's luma several times).
struct DecodedRun {
  const uchar* bgr = nullptr;    ///< 3 bytes per pixel
  const uchar* lumas = nullptr;  ///< FieldColor::luma per pixel

  const uchar* at(int i) const { return bgr + 3 * i; }
  int luma(int i) const { return lumas[i]; }
};

/// Memory decoded runs live in, reused from scanline to scanline.
struct RunBuffer {
  std::vector<uchar> bgr, luma;
};

/// BGR8 (CV_8UC3) pixels, read in place. Reads `image`, which must outlive the reader.
class Bgr8Pixels {
 public:
  explicit Bgr8Pixels(const cv::Mat& image) : image_(image) {}

  int rows() const { return image_.rows; }
  int cols() const { return image_.cols; }

  BgrBytes at(int u, int v) const {
    const uchar* p = image_.ptr<uchar>(v) + 3 * u;
    return {p[0], p[1], p[2]};
  }
  /// Pixels (u, v) ... (u + n - 1, v), in place (the buffer is not used).
  BgrRun rowRun(int u, int v, int /*n*/, RunBuffer* /*buffer*/) const {
    return {image_.ptr<uchar>(v) + 3 * u, 3};
  }
  /// Pixels (u, v) ... (u, v + n - 1), in place (the buffer is not used).
  BgrRun columnRun(int u, int v, int /*n*/, RunBuffer* /*buffer*/) const {
    return {image_.ptr<uchar>(v) + 3 * u, static_cast<long>(image_.step[0])};
  }

 private:
  const cv::Mat& image_;
};

/// The fixed-point limited-range BT.601 coefficients of OpenCV's COLOR_YUV2BGR_YUYV (20
/// fractional bits; rounded, saturated).
namespace yuyv_fixed_point {
constexpr int kShift = 20;
constexpr int kCy = 1220542, kCub = 2116026, kCug = -409993, kCvg = -852492, kCvr = 1673527;
}  // namespace yuyv_fixed_point

/// BGR bytes of one YUYV pixel with OpenCV's arithmetic (yuyv_fixed_point), so a stage reading
/// YUYV sees exactly the bytes it would read in yuyvToBgr's output.
inline BgrBytes decodeYuyv(int y, int cb, int cr) {
  using namespace yuyv_fixed_point;
  const int y_term = std::max(0, y - 16) * kCy + (1 << (kShift - 1));  // rounds the shift
  const int du = cb - 128, dv = cr - 128;
  const auto byte = [](int value) { return static_cast<uchar>(std::clamp(value, 0, 255)); };
  return {byte((y_term + kCub * du) >> kShift), byte((y_term + kCug * du + kCvg * dv) >> kShift),
          byte((y_term + kCvr * dv) >> kShift)};
}

/// YUYV 4:2:2 (CV_8UC2: Y0 Cb Y1 Cr per pixel pair) pixels, decoded to BGR only where a stage
/// reads them (about a quarter of a frame; docs/vision.md "YUYV input"). Reads `image`, which
/// must outlive the reader.
class YuyvPixels {
 public:
  /// Throws std::invalid_argument when the image is not CV_8UC2 or its width is odd.
  explicit YuyvPixels(const cv::Mat& image);

  int rows() const { return image_.rows; }
  int cols() const { return image_.cols; }

  BgrBytes at(int u, int v) const {
    const uchar* pair = image_.ptr<uchar>(v) + 4 * (u >> 1);
    return decodeYuyv(pair[2 * (u & 1)], pair[1], pair[3]);
  }
  /// Pixels (u, v) ... (u + n - 1, v), decoded into `buffer`.
  DecodedRun rowRun(int u, int v, int n, RunBuffer* buffer) const;
  /// Pixels (u, v) ... (u, v + n - 1), decoded into `buffer`.
  DecodedRun columnRun(int u, int v, int n, RunBuffer* buffer) const;

 private:
  const cv::Mat& image_;
};

/// Throws std::invalid_argument unless the image is BGR8 or YUYV of even width.
void checkPixelLayout(const cv::Mat& image);

/// Calls visit(pixels) with the reader for the image's format and returns what it returns: a
/// stage written once against the reader interface (at, rowRun, columnRun, rows, cols) runs on
/// either format, with one branch per call rather than per pixel.
template <typename Visit>
decltype(auto) visitPixels(const cv::Mat& image, Visit&& visit) {
  if (pixelFormatOf(image) == PixelFormat::kYuyv) return visit(YuyvPixels(image));
  return visit(Bgr8Pixels(image));
}

}  // namespace houghloc
