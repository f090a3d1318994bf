// decodeMessage on received bytes: every well-formed message decodes as the generated decode()
// does; a declared array or string length that the bytes cannot hold, a negative one, a wrong
// type, truncated or trailing bytes give false without an exception or a large allocation.
#include "tools/lcm/message_decoding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace houghloc {
namespace {

template <typename T>
std::vector<std::uint8_t> encode(const T& msg) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  EXPECT_EQ(msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return bytes;
}

/// Overwrites the big-endian int32 at `offset`.
void putInt32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
}

image_t sampleImage() {
  image_t msg;
  msg.utime = 123;
  msg.camera_id = "top";
  msg.width = 4;
  msg.height = 2;
  msg.pixel_format = image_t::PIXEL_FORMAT_YUYV;
  msg.row_stride = 8;
  msg.data.assign(16, 200);
  msg.size = 16;
  return msg;
}

// Offsets in an encoded image_t with camera_id "top": hash 8, utime 8, string 4 + 4 bytes,
// width, height 4 each, pixel_format 1, row_stride 4, then size.
constexpr std::size_t kImageCameraIdLength = 16;
constexpr std::size_t kImageSize = 16 + 8 + 4 + 4 + 1 + 4;

TEST(DecodeMessage, WellFormedMessagesDecodeExactly) {
  image_t image;
  ASSERT_TRUE(decodeMessage(encode(sampleImage()).data(), encode(sampleImage()).size(), image));
  EXPECT_EQ(image.camera_id, "top");
  EXPECT_EQ(image.data, sampleImage().data);

  localization_hint_t hint;
  hint.utime = 5;
  hint.kind = localization_hint_t::ADD;
  hint.num_poses = 2;
  hint.poses.resize(2);
  hint.poses[1].x = 1.5;
  const auto hint_bytes = encode(hint);
  localization_hint_t hint_out;
  ASSERT_TRUE(decodeMessage(hint_bytes.data(), hint_bytes.size(), hint_out));
  EXPECT_EQ(hint_out.poses.at(1).x, 1.5);

  line_points_t points;
  points.camera_id = "";
  points.num_points = 3;
  points.x = {1.f, 2.f, 3.f};
  points.y = {4.f, 5.f, 6.f};
  const auto point_bytes = encode(points);
  line_points_t points_out;
  ASSERT_TRUE(decodeMessage(point_bytes.data(), point_bytes.size(), points_out));
  EXPECT_EQ(points_out.y.at(2), 6.f);
}

TEST(DecodeMessage, ImageDataLongerThanTheBytesIsRefused) {
  for (std::uint32_t declared : {17u, 0x7fffffffu, 0xffffffffu, 0x80000000u}) {
    auto bytes = encode(sampleImage());
    putInt32(bytes, kImageSize, declared);
    image_t out;
    EXPECT_FALSE(decodeMessage(bytes.data(), bytes.size(), out)) << declared;
    EXPECT_LE(out.data.capacity(), bytes.size()) << "allocated before refusing";
  }
}

TEST(DecodeMessage, NegativeOrZeroStringLengthIsRefusedWithoutException) {
  for (std::uint32_t declared : {0u, 0xffffffffu, 0xfffffff0u}) {
    auto bytes = encode(sampleImage());
    putInt32(bytes, kImageCameraIdLength, declared);
    image_t out;
    EXPECT_FALSE(decodeMessage(bytes.data(), bytes.size(), out)) << declared;
  }
}

TEST(DecodeMessage, PoseCountsBeyondTheBytesAreRefused) {
  pose_hypotheses_t msg;
  msg.num_hypotheses = 1;
  msg.hypotheses.resize(1);
  for (std::uint32_t declared : {2u, 0x00ffffffu, 0xffffffffu}) {
    auto bytes = encode(msg);
    putInt32(bytes, 8 + 8 + 1, declared);  // hash, utime, status, then the count
    pose_hypotheses_t out;
    EXPECT_FALSE(decodeMessage(bytes.data(), bytes.size(), out)) << declared;
    EXPECT_LE(out.hypotheses.capacity(), 1u);
  }
}

TEST(DecodeMessage, WrongTypeTruncatedAndTrailingBytesAreRefused) {
  const auto bytes = encode(sampleImage());
  odometry_t odometry;
  EXPECT_FALSE(decodeMessage(bytes.data(), bytes.size(), odometry));  // type hash differs
  image_t image;
  EXPECT_FALSE(decodeMessage(bytes.data(), bytes.size() - 1, image));
  auto longer = bytes;
  longer.push_back(0);
  EXPECT_FALSE(decodeMessage(longer.data(), longer.size(), image));
  EXPECT_FALSE(decodeMessage(bytes.data(), 0, image));
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_FALSE(decodeMessage(bytes.data(), n, image));
}

}  // namespace
}  // namespace houghloc
