#include "tools/lcm/lcm_log_reader.h"

#include <cstdio>
#include <filesystem>

namespace houghloc {
namespace {

/// lcm-logger's event header: sync word, event number, timestamp, channel length, data length.
constexpr std::int64_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;

}  // namespace

LcmLogReader::LcmLogReader(const std::string& path) : path_(path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw LcmLogError(path + ": no such file (an lcm-logger log is expected)");
  size_ = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
  file_ = std::make_unique<lcm::LogFile>(path, "r");
  if (!file_->good()) throw LcmLogError(path + ": cannot open for reading");
}

LcmLogReader::~LcmLogReader() = default;

const lcm::LogEvent* LcmLogReader::next() {
  const lcm::LogEvent* event = file_->readNextEvent();
  if (event == nullptr) {
    if (end_ == size_) return nullptr;
    if (events_ == 0) throw LcmLogError(path_ + ": not an LCM log (no lcm-logger event at byte 0)");
    // liblcm reads the sync word after each event and returns nothing when it is wrong (having
    // read those 4 bytes), or when the file ends inside an event.
    const std::int64_t at = std::ftell(file_->getFilePtr());
    if (at < size_)
      throw LcmLogError(path_ + ": corrupt: no lcm-logger event at byte " + std::to_string(at - 4));
    truncated_at_ = end_;
    return nullptr;
  }
  const std::int64_t start = end_;
  end_ = std::ftell(file_->getFilePtr());
  const std::int64_t length =
      kHeaderBytes + static_cast<std::int64_t>(event->channel.size()) + event->datalen;
  if (end_ - start != length) {
    throw LcmLogError(
        path_ + (events_ == 0 ? ": not an LCM log (no lcm-logger event at byte 0)"
                              : ": corrupt: no lcm-logger event at byte " + std::to_string(start)));
  }
  ++events_;
  return event;
}

}  // namespace houghloc
