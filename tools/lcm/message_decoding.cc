#include "tools/lcm/message_decoding.h"

#include <algorithm>

namespace houghloc {
namespace {

/// Reads LCM's wire format (big-endian integers, strings as int32 length with the NUL counted)
/// far enough to find an array's declared length; any read past the end leaves it failed.
class WireCursor {
 public:
  WireCursor(const std::uint8_t* bytes, std::size_t size) : bytes_(bytes), size_(size) {}

  void skip(std::size_t n) {
    if (failed_ || n > size_ - pos_) {
      failed_ = true;
      return;
    }
    pos_ += n;
  }
  std::int32_t int32() {
    if (failed_ || size_ - pos_ < 4) {
      failed_ = true;
      return 0;
    }
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value = (value << 8) | bytes_[pos_++];
    return static_cast<std::int32_t>(value);
  }
  void string() {
    const std::int32_t length = int32();
    if (length < 1) failed_ = true;  // the NUL is part of the length
    skip(static_cast<std::size_t>(std::max(length, 0)));
  }
  /// Whether `count` elements of `bytes_each` encoded bytes can follow.
  bool fits(std::int32_t count, std::size_t bytes_each) const {
    return !failed_ && count >= 0 && static_cast<std::size_t>(count) <= (size_ - pos_) / bytes_each;
  }

 private:
  const std::uint8_t* bytes_;
  std::size_t size_;
  std::size_t pos_ = 0;
  bool failed_ = false;
};

constexpr std::size_t kHash = 8;  // type fingerprint before every top-level message
constexpr std::size_t kUtime = 8;
// pose_hypothesis_t: id, x, y, theta, covariance[9], weight, age.
constexpr std::size_t kPoseHypothesisBytes = 4 + 3 * 8 + 9 * 8 + 8 + 4;

/// pose_hypotheses_t and localization_hint_t: utime, an int8, then the pose count and poses.
bool poseArrayFits(const std::uint8_t* bytes, std::size_t size) {
  WireCursor wire(bytes, size);
  wire.skip(kHash + kUtime + 1);
  const std::int32_t count = wire.int32();
  return wire.fits(count, kPoseHypothesisBytes);
}

}  // namespace

bool declaredLengthsFit(const image_t&, const std::uint8_t* bytes, std::size_t size) {
  WireCursor wire(bytes, size);
  wire.skip(kHash + kUtime);
  wire.string();             // camera_id
  wire.skip(4 + 4 + 1 + 4);  // width, height, pixel_format, row_stride
  const std::int32_t data_bytes = wire.int32();
  return wire.fits(data_bytes, 1);
}

bool declaredLengthsFit(const line_points_t&, const std::uint8_t* bytes, std::size_t size) {
  WireCursor wire(bytes, size);
  wire.skip(kHash + kUtime);
  wire.string();  // camera_id
  const std::int32_t points = wire.int32();
  return wire.fits(points, 2 * sizeof(float));  // x[] and y[]
}

bool declaredLengthsFit(const pose_hypotheses_t&, const std::uint8_t* bytes, std::size_t size) {
  return poseArrayFits(bytes, size);
}

bool declaredLengthsFit(const localization_hint_t&, const std::uint8_t* bytes, std::size_t size) {
  return poseArrayFits(bytes, size);
}

}  // namespace houghloc
