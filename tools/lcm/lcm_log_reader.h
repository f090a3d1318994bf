#pragma once

#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <stdexcept>
#include <string>

namespace houghloc {

/// An lcm-logger file that cannot be read; what() names the file and the byte at fault.
class LcmLogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads an lcm-logger file event by event with liblcm's lcm::LogFile and tells apart what
/// LogFile reports alike as "no more events": the end of the log, a file that is not an LCM log,
/// bytes that are not an event between events, and a last event cut short. Every event must
/// start where the previous one ended (the first at byte 0).
class LcmLogReader {
 public:
  /// Throws LcmLogError when the file cannot be opened.
  explicit LcmLogReader(const std::string& path);
  ~LcmLogReader();

  /// The next event (valid until the next call), or null at the end. Throws LcmLogError when the
  /// file is not an LCM log or the bytes after an event are not an event (liblcm then drops that
  /// event too). A last event cut short (a logger killed while writing) ends the log:
  /// truncatedAt() tells where.
  const lcm::LogEvent* next();

  /// Byte offset of a last event that was cut short; -1 when the log ended cleanly.
  std::int64_t truncatedAt() const { return truncated_at_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<lcm::LogFile> file_;
  std::int64_t size_ = 0;    ///< bytes in the file
  std::int64_t end_ = 0;     ///< where the last event read ended
  std::int64_t events_ = 0;  ///< read so far
  std::int64_t truncated_at_ = -1;
};

}  // namespace houghloc
