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

/// decodeYuyv and FieldColor::luma of n pixels of one column: pixel k's pair at
/// pair + k * step, its Y at byte y_offset of the pair. 16 pixels at a time with OpenCV's
/// portable SIMD types where the target has them, in decodeYuyv's 32-bit arithmetic (the pairs
/// are gathered row by row, the arithmetic is vectorised).
void decodeColumn(const uchar* pair, size_t step, int y_offset, int n, uchar* bgr, uchar* luma) {
  int k = 0;
#if CV_SIMD128
  using namespace yuyv_fixed_point;
  const cv::v_int32x4 zero = cv::v_setzero_s32(), offset_128 = cv::v_setall_s32(128),
                      offset_16 = cv::v_setall_s32(16), top = cv::v_setall_s32(255),
                      round = cv::v_setall_s32(1 << (kShift - 1)), cy = cv::v_setall_s32(kCy),
                      cub = cv::v_setall_s32(kCub), cug = cv::v_setall_s32(kCug),
                      cvg = cv::v_setall_s32(kCvg), cvr = cv::v_setall_s32(kCvr),
                      byte_mask = cv::v_setall_s32(255);
  const auto channel = [&](const cv::v_int32x4& sum) {
    return cv::v_min(cv::v_max(cv::v_shr<kShift>(sum), zero), top);
  };
  // The rows a column reads are a frame row apart, too far for the hardware to see a stream:
  // each gather asks for the pair kAheadRows rows further down in advance.
  constexpr int kAheadRows = 32;
  for (; k + 16 <= n; k += 16) {
    // Each pair as one 32-bit lane, Y0 in the low byte (one load per row on a little-endian
    // target; the arithmetic below needs no byte order).
    alignas(16) int pairs[16];
    const bool ahead = k + 16 + kAheadRows <= n;  // no prefetch beyond the column
    for (int i = 0; i < 16; ++i, pair += step) {
      if (ahead) __builtin_prefetch(pair + kAheadRows * step);
      pairs[i] = static_cast<int>(pair[0] | pair[1] << 8 | pair[2] << 16 |
                                  static_cast<unsigned>(pair[3]) << 24);
    }
    cv::v_int16x8 b16[2], g16[2], r16[2], l16[2];
    for (int half = 0; half < 2; ++half) {
      cv::v_int32x4 b[2], g[2], r[2], l[2];
      for (int quarter = 0; quarter < 2; ++quarter) {
        const int i = 8 * half + 4 * quarter;
        const cv::v_int32x4 lanes = cv::v_load(pairs + i);
        const cv::v_int32x4 y = (y_offset == 0 ? lanes : cv::v_shr<16>(lanes)) & byte_mask;
        const cv::v_int32x4 y_term = cv::v_max(y - offset_16, zero) * cy + round;
        const cv::v_int32x4 du = (cv::v_shr<8>(lanes) & byte_mask) - offset_128;
        const cv::v_int32x4 dv = (cv::v_shr<24>(lanes) & byte_mask) - offset_128;
        b[quarter] = channel(y_term + cub * du);
        g[quarter] = channel(y_term + cug * du + cvg * dv);
        r[quarter] = channel(y_term + cvr * dv);
        l[quarter] = cv::v_shr<2>(b[quarter] + (g[quarter] << 1) + r[quarter]);
      }
      b16[half] = cv::v_pack(b[0], b[1]);
      g16[half] = cv::v_pack(g[0], g[1]);
      r16[half] = cv::v_pack(r[0], r[1]);
      l16[half] = cv::v_pack(l[0], l[1]);
    }
    cv::v_store_interleave(bgr + 3 * k, cv::v_pack_u(b16[0], b16[1]), cv::v_pack_u(g16[0], g16[1]),
                           cv::v_pack_u(r16[0], r16[1]));
    cv::v_store(luma + k, cv::v_pack_u(l16[0], l16[1]));
  }
#endif
  for (; k < n; ++k, pair += step) {
    const BgrBytes decoded = decodeYuyv(pair[y_offset], pair[1], pair[3]);
    uchar* out = bgr + 3 * k;
    out[0] = decoded[0], out[1] = decoded[1], out[2] = decoded[2];
    luma[k] = static_cast<uchar>(FieldColor::luma(out));
  }
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
  decodeColumn(image_.ptr<uchar>(v) + 4 * (u / 2), image_.step[0], 2 * (u % 2), n,
               buffer->bgr.data(), buffer->luma.data());
  return {buffer->bgr.data(), buffer->luma.data()};
}

void checkPixelLayout(const cv::Mat& image) {
  if (pixelFormatOf(image) == PixelFormat::kYuyv) YuyvPixels{image};
}

}  // namespace houghloc
