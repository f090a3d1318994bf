#pragma once

// Shared by the libFuzzer targets (tests/fuzz/*_fuzz.cc) and their Release replay (replay_main.cc).
// A target must never crash, hang or give non-finite output; the exceptions the readers document
// are fine but must name their source (the file or key), so the message check is part of the
// target: a message without it aborts like a crash.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace houghloc::fuzz {

/// Aborts (a finding) with the message on stderr.
[[noreturn]] inline void fail(const std::string& what) {
  std::cerr << "fuzz finding: " << what << "\n";
  std::abort();
}

/// An error message must mention `source` (a file name); aborts otherwise.
inline void requireNamed(const std::string& message, const std::string& source) {
  if (message.find(source) == std::string::npos) {
    fail("error message does not name '" + source + "': " + message);
  }
}

/// Reads fixed-size values from the front of the fuzz input; past the end it yields zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t remaining() const { return size_ - pos_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  template <typename T>
  T value() {
    T out{};
    const std::size_t n = std::min(sizeof(T), remaining());
    std::memcpy(&out, data_ + pos_, n);
    pos_ += n;
    return out;
  }
  /// A double from 8 raw bytes: any value, NaN and infinities included.
  double rawDouble() { return value<double>(); }
  /// A double in [-range, range] from 2 bytes, or (1 in 16) a raw double.
  double smallDouble(double range) {
    if ((byte() & 15) == 0) return rawDouble();
    return range * (static_cast<double>(value<std::int16_t>()) / 32768.0);
  }
  /// The rest of the input.
  std::string rest() {
    std::string out(reinterpret_cast<const char*>(data_ + pos_), remaining());
    pos_ = size_;
    return out;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// A scratch folder of this process (fuzz targets run single-threaded), created on first use.
std::string scratchFolder();

/// Writes `text` to scratchFolder()/name and returns its path.
std::string writeScratchFile(const std::string& name, const std::string& text);

}  // namespace houghloc::fuzz
