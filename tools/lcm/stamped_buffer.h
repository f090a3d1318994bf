#pragma once

#include <cstdint>
#include <cstdlib>
#include <deque>
#include <optional>

#include "field_models/pose2.h"
#include "field_models/pose3.h"

namespace houghloc {

/// Linear interpolation between a and b at s in [0, 1]; angles take the short way round.
Pose2 interpolatePose(const Pose2& a, const Pose2& b, double s);
Pose3 interpolatePose(const Pose3& a, const Pose3& b, double s);

/// A short, time-ordered history of a stream (odometry, one camera's pose) for looking it up at
/// an image's utime (DESIGN §7: all utime values are the publisher's clock).
template <typename T>
class StampedBuffer {
 public:
  /// keep_us: samples older than the newest minus this are forgotten, microseconds.
  explicit StampedBuffer(std::int64_t keep_us = 2'000'000) : keep_us_(keep_us) {}

  /// Appends a sample. A sample older than the newest one means the publisher restarted (its
  /// clock went back): the history is dropped and starts again from this sample.
  void push(std::int64_t t_us, const T& value) {
    if (!samples_.empty() && t_us < samples_.back().t_us) samples_.clear();
    if (!samples_.empty() && t_us == samples_.back().t_us) samples_.pop_back();
    samples_.push_back({t_us, value});
    while (samples_.front().t_us < t_us - keep_us_) samples_.pop_front();
  }

  /// The value at t_us: interpolated between the samples around it when the nearer one lies
  /// within max_gap_us, else the nearest sample when within max_gap_us (before the first or
  /// after the last sample), else none.
  std::optional<T> at(std::int64_t t_us, std::int64_t max_gap_us) const {
    if (samples_.empty()) return std::nullopt;
    std::size_t i = 0;
    while (i < samples_.size() && samples_[i].t_us < t_us) ++i;
    if (i < samples_.size() && samples_[i].t_us == t_us) return samples_[i].value;
    if (i == 0 || i == samples_.size()) {
      const Sample& s = i == 0 ? samples_.front() : samples_.back();
      if (std::abs(s.t_us - t_us) > max_gap_us) return std::nullopt;
      return s.value;
    }
    const Sample& a = samples_[i - 1];
    const Sample& b = samples_[i];
    if (t_us - a.t_us > max_gap_us && b.t_us - t_us > max_gap_us) return std::nullopt;
    const double s = static_cast<double>(t_us - a.t_us) / static_cast<double>(b.t_us - a.t_us);
    return interpolatePose(a.value, b.value, s);
  }

  /// utime of the newest sample; none when empty.
  std::optional<std::int64_t> newest() const {
    if (samples_.empty()) return std::nullopt;
    return samples_.back().t_us;
  }
  void clear() { samples_.clear(); }

 private:
  struct Sample {
    std::int64_t t_us;
    T value;
  };
  std::int64_t keep_us_;
  std::deque<Sample> samples_;
};

}  // namespace houghloc
