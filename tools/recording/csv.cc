#include "tools/recording/csv.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tools/recording/recording.h"

namespace houghloc {
namespace {

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw RecordingError(path + ": cannot open file");
  CsvTable table;
  table.path_ = path;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // files written on Windows
    const std::string trimmed = trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    CsvRow row{number, split(line)};
    if (table.header_.empty()) {
      table.header_line_ = number;
      table.header_ = row.fields;
      for (std::size_t i = 0; i < table.header_.size(); ++i) {
        if (table.header_[i].empty()) table.fail(row, "empty column name in the header");
        for (std::size_t j = 0; j < i; ++j) {
          if (table.header_[j] == table.header_[i]) {
            table.fail(row, "column '" + table.header_[i] + "' appears twice in the header");
          }
        }
      }
      continue;
    }
    if (row.fields.size() != table.header_.size()) {
      table.fail(row, "malformed row: " + std::to_string(row.fields.size()) +
                          " fields, the header has " + std::to_string(table.header_.size()));
    }
    table.rows_.push_back(std::move(row));
  }
  if (table.header_.empty()) throw RecordingError(path + ":1: missing header line");
  return table;
}

void CsvTable::fail(const CsvRow& row, const std::string& what) const {
  throw RecordingError(path_ + ":" + std::to_string(row.line) + ": " + what);
}

std::optional<int> CsvTable::optionalColumn(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

int CsvTable::column(const std::string& name) const {
  if (const auto index = optionalColumn(name)) return *index;
  throw RecordingError(path_ + ":" + std::to_string(header_line_) + ": missing column '" + name +
                       "' in the header");
}

const std::string& CsvTable::text(const CsvRow& row, int column) { return row.fields.at(column); }

double CsvTable::number(const CsvRow& row, int column) const {
  const std::string& field = text(row, column);
  const char* begin = field.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (field.empty() || end != begin + field.size() || errno == ERANGE || !std::isfinite(value)) {
    fail(row, "column '" + header_[column] + "': '" + field + "' is not a finite number");
  }
  return value;
}

std::optional<double> CsvTable::optionalNumber(const CsvRow& row, int column) const {
  if (text(row, column).empty()) return std::nullopt;
  return number(row, column);
}

std::int64_t CsvTable::integer(const CsvRow& row, int column) const {
  const std::string& field = text(row, column);
  const char* begin = field.c_str();
  char* end = nullptr;
  errno = 0;
  const std::int64_t value = std::strtoll(begin, &end, 10);
  if (field.empty() || end != begin + field.size() || errno == ERANGE) {
    fail(row, "column '" + header_[column] + "': '" + field + "' is not an integer");
  }
  return value;
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path), columns_(header.size()), out_(path) {
  if (!out_) throw RecordingError(path + ": cannot create file");
  writeRow(header);
}

std::string CsvWriter::format(double value) const {
  if (!std::isfinite(value)) throw RecordingError(path_ + ": cannot write a non-finite number");
  // The shortest of 15, 16 or 17 significant digits that reads back to the same double: exact
  // round trips without the noise digits of a plain %.17g (0.059999999999999998).
  char buffer[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

void CsvWriter::writeRow(const std::vector<std::string>& fields) {
  if (fields.size() != columns_) throw RecordingError(path_ + ": row with wrong field count");
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string& f = fields[i];
    if (f.find_first_of(",\r\n") != std::string::npos || trim(f) != f ||
        (i == 0 && !f.empty() && f[0] == '#')) {
      throw RecordingError(path_ + ": cannot write field '" + f +
                           "' (commas, line breaks, surrounding spaces or a leading #)");
    }
    out_ << (i ? "," : "") << f;
  }
  out_ << '\n';
}

void CsvWriter::close() {
  out_.close();
  if (!out_) throw RecordingError(path_ + ": write failed");
}

}  // namespace houghloc
