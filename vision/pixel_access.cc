#include "vision/pixel_access.h"

#include <opencv2/core/hal/intrin.hpp>
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

/// FieldColor::luma of n BGR pixels, 16 at a time with OpenCV's portable SIMD types where the
/// target has them: a scalar pass costs about as much as OpenCV's vectorised decoding of the row.
void lumaOfBgr(const uchar* bgr, int n, uchar* luma) {
  int k = 0;
#if CV_SIMD128
  for (; k + 16 <= n; k += 16) {
    cv::v_uint8x16 b, g, r;
    cv::v_load_deinterleave(bgr + 3 * k, b, g, r);
    cv::v_uint16x8 b0, b1, g0, g1, r0, r1;
    cv::v_expand(b, b0, b1);
    cv::v_expand(g, g0, g1);
    cv::v_expand(r, r0, r1);
    // At most 4 * 255: no 16-bit lane overflows.
    const cv::v_uint16x8 low = cv::v_shr<2>(b0 + (g0 << 1) + r0);
    const cv::v_uint16x8 high = cv::v_shr<2>(b1 + (g1 << 1) + r1);
    cv::v_store(luma + k, cv::v_pack(low, high));
  }
#endif
  for (; k < n; ++k) luma[k] = static_cast<uchar>(FieldColor::luma(bgr + 3 * k));
}

}  // namespace

DecodedRun YuyvPixels::rowRun(int u, int v, int n, RunBuffer* buffer) const {
  const int first_pair = u / 2, end_pair = (u + n + 1) / 2;
  buffer->bgr.resize(6 * static_cast<size_t>(end_pair - first_pair));
  buffer->luma.resize(static_cast<size_t>(n));
  decodePairs(image_.ptr<uchar>(v) + 4 * first_pair, image_.step[0], end_pair - first_pair, 1,
              buffer->bgr.data(), buffer->bgr.size());
  const uchar* bgr = buffer->bgr.data() + 3 * (u % 2);
  uchar* luma = buffer->luma.data();
  lumaOfBgr(bgr, n, luma);
  return {bgr, luma};
}

DecodedRun YuyvPixels::columnRun(int u, int v, int n, RunBuffer* buffer) const {
  // One pair per row is too little for OpenCV's decoder (its per-row set-up dominates).
  buffer->bgr.resize(3 * static_cast<size_t>(n));
  buffer->luma.resize(static_cast<size_t>(n));
  uchar* out = buffer->bgr.data();
  const uchar* pair = image_.ptr<uchar>(v) + 4 * (u / 2);
  const int y_offset = 2 * (u % 2);
  for (int k = 0; k < n; ++k, out += 3, pair += image_.step[0]) {
    const BgrBytes bgr = decodeYuyv(pair[y_offset], pair[1], pair[3]);
    out[0] = bgr[0], out[1] = bgr[1], out[2] = bgr[2];
    buffer->luma[static_cast<size_t>(k)] = static_cast<uchar>(FieldColor::luma(out));
  }
  return {buffer->bgr.data(), buffer->luma.data()};
}

void checkPixelLayout(const cv::Mat& image) {
  if (pixelFormatOf(image) == PixelFormat::kYuyv) YuyvPixels{image};
}

}  // namespace houghloc
