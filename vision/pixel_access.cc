#include "vision/pixel_access.h"

#include <opencv2/imgproc/hal/hal.hpp>
#include <stdexcept>

namespace houghloc {

YuyvPixels::YuyvPixels(const cv::Mat& image) : image_(image) {
  if (image.type() != CV_8UC2 || image.cols % 2 != 0) {
    throw std::invalid_argument("YUYV image must be CV_8UC2 with an even width");
  }
}

namespace {

/// OpenCV's own YUYV decoder (the one behind COLOR_YUV2BGR_YUYV, vectorised) on a block of pixel
/// pairs: `pairs` pairs per row, `rows` rows `src_step` bytes apart, written `dst_step` apart.
void decodePairs(const uchar* src, size_t src_step, int pairs, int rows, uchar* dst,
                 size_t dst_step) {
  cv::hal::cvtOnePlaneYUVtoBGR(src, src_step, dst, dst_step, 2 * pairs, rows, 3,
                               /*swapBlue=*/false, /*uIdx=*/0, /*ycn=*/0);
}

}  // namespace

BgrRun YuyvPixels::rowRun(int u, int v, int n, std::vector<uchar>* buffer) const {
  const int first_pair = u / 2, end_pair = (u + n + 1) / 2;
  buffer->resize(6 * static_cast<size_t>(end_pair - first_pair));
  decodePairs(image_.ptr<uchar>(v) + 4 * first_pair, image_.step[0], end_pair - first_pair, 1,
              buffer->data(), buffer->size());
  return {buffer->data() + 3 * (u % 2), 3};
}

BgrRun YuyvPixels::columnRun(int u, int v, int n, std::vector<uchar>* buffer) const {
  // One pair per row is too little for OpenCV's decoder (its per-row set-up dominates).
  buffer->resize(3 * static_cast<size_t>(n));
  uchar* out = buffer->data();
  const uchar* pair = image_.ptr<uchar>(v) + 4 * (u / 2);
  const int y_offset = 2 * (u % 2);
  for (int k = 0; k < n; ++k, out += 3, pair += image_.step[0]) {
    const BgrBytes bgr = decodeYuyv(pair[y_offset], pair[1], pair[3]);
    out[0] = bgr[0], out[1] = bgr[1], out[2] = bgr[2];
  }
  return {buffer->data(), 3};
}

void checkPixelLayout(const cv::Mat& image) {
  if (pixelFormatOf(image) == PixelFormat::kYuyv) YuyvPixels{image};
}

}  // namespace houghloc
