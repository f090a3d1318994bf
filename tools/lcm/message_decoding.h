#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/line_points_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/localizer_status_t.hpp"
#include "houghloc/odometry_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"

namespace houghloc {

/// Whether the array lengths that the encoded message declares fit in its `size` bytes. Bytes
/// off the wire are untrusted, and lcm-gen's decode() (liblcm 1.3.1) resizes an array to its
/// declared length before it checks that the bytes hold it: one corrupt length field asks for
/// up to 2 GB (image data) or 16 GB (line points) of zeroed memory. Types without arrays: true.
bool declaredLengthsFit(const image_t&, const std::uint8_t* bytes, std::size_t size);
bool declaredLengthsFit(const line_points_t&, const std::uint8_t* bytes, std::size_t size);
bool declaredLengthsFit(const pose_hypotheses_t&, const std::uint8_t* bytes, std::size_t size);
bool declaredLengthsFit(const localization_hint_t&, const std::uint8_t* bytes, std::size_t size);
inline bool declaredLengthsFit(const odometry_t&, const std::uint8_t*, std::size_t) { return true; }
inline bool declaredLengthsFit(const camera_pose_t&, const std::uint8_t*, std::size_t) {
  return true;
}
inline bool declaredLengthsFit(const localizer_status_t&, const std::uint8_t*, std::size_t) {
  return true;
}

/// Decodes `size` received bytes as exactly one T (type hash, every field, no trailing bytes).
/// False, never an exception, for anything else: decode() throws std::length_error on a
/// negative string or array length, and such a message must be counted, not end the process.
template <typename T>
bool decodeMessage(const void* data, std::size_t size, T& msg) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  if (size > static_cast<std::size_t>(INT32_MAX) || !declaredLengthsFit(msg, bytes, size)) {
    return false;
  }
  try {
    return msg.decode(bytes, 0, static_cast<int>(size)) == static_cast<int>(size);
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace houghloc
